// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The linear part of a feed axis as one continuous state-space model, discretized exactly (zero-order
// hold over one current-loop period) with the matrix exponential:
//   q-axis circuit   L(i) di/dt = v - R i - K_e ω_m
//   motor side       J_m dω_m/dt = K_t i - K(θ_m - θ_L) - C(ω_m - ω_L) - b_m ω_m + τ_m
//   load side        J_L dω_L/dt = K(θ_m - θ_L) + C(ω_m - ω_L) - b_L ω_L + τ_L
//   higher modes     q̈_k + 2ζ_k ω_k q̇_k + ω_k² q_k = K_t i / J_k   (collocated, seen by the motor encoder)
// With K = 0 the coupling is rigid and one inertia J_m + J_L remains. τ_m, τ_L are external torques
// (friction, disturbance) held over the step. L(i) = L0 (1 - δ |i|/I_max): the discretization is
// cached per 1/256 of I_max so a current-dependent inductance costs no exponential per step.
// A ball screw (ScrewStiffness) makes K a function of the table position (docs/simulator.md "Long axis"): the
// nut's distance from the fixed bearing sets the screw's axial stiffness; the discretization is cached per
// 1/256 of the screw length as well, so the position costs no exponential per step either.

#include <Eigen/Dense>

#include <map>
#include <vector>

namespace axistune::sim {

struct ResonanceMode {
    double frequencyHz = 0.0;
    double damping = 0.0;
    double modalInertiaKgm2 = 0.0;  ///< 1/residue: the mode adds s / (J_k (s² + 2ζωs + ω²)) to torque → velocity
};

/// Axial stiffness of a ball screw mounted fixed–free or fixed–supported (THK/NSK catalogue formula): the screw
/// between the fixed bearing and the nut, k_s = π d_r² E / (4 L_n), in series with the support bearing, the nut and
/// (on the motor side) the torsional stiffness of coupling and screw:
///   1/K(x) = 1/K_t + 1/(R² k_a(x)),   1/k_a(x) = 1/k_b + 1/k_n + 4 L_n / (π d_r² E),   L_n = L_0 + x,
/// with R the lead [m/rad] and x the table position [m]. Off (rootDiameterM = 0) for every other axis.
struct ScrewStiffness {
    double rootDiameterM = 0.0;              ///< d_r
    double youngsModulusPa = 0.0;            ///< E
    double nutDistanceAtZeroM = 0.0;         ///< L_0: the nut's distance from the fixed bearing at x = 0
    double lengthM = 0.0;                    ///< screw length between the bearings; L_n is held within [0, length]
    double bearingStiffnessNPerM = 0.0;      ///< k_b (axial, of the fixed support bearing)
    double nutStiffnessNPerM = 0.0;          ///< k_n (axial, of the preloaded nut)
    double torsionalStiffnessNmPerRad = 0.0; ///< K_t (coupling and screw torsion)
    bool enabled() const { return rootDiameterM > 0.0; }
};
/// K(x) [N·m/rad] of the formula above for lead R [m/rad] and table position x [m].
double screwCouplingStiffness(const ScrewStiffness& s, double leadMPerRad, double positionM);

struct PlantConfig {
    double resistanceOhm = 0.0;
    double inductanceH = 0.0;
    double inductanceDropAtMax = 0.0;  ///< δ
    double maxCurrentA = 1.0;
    double torqueConstantNmPerA = 1.0;
    double backEmfVsPerRad = 0.0;
    double inertiaMotorKgm2 = 0.0;
    double inertiaLoadKgm2 = 0.0;
    double stiffnessNmPerRad = 0.0;  ///< 0 = rigid coupling
    double dampingNmsPerRad = 0.0;
    double viscousMotorNmsPerRad = 0.0;
    double viscousLoadNmsPerRad = 0.0;
    std::vector<ResonanceMode> modes;
    ScrewStiffness screw;          ///< enabled: K follows the table position (stiffnessNmPerRad is not used)
    double screwLeadMPerRad = 0.0; ///< R, with a screw
};

class PlantModel {
public:
    PlantModel(PlantConfig config, double periodS);

    int stateSize() const { return m_n; }
    bool rigid() const { return m_rigid; }
    const PlantConfig& config() const { return m_cfg; }

    /// Advances x by one period with voltage v and external torques held (τ_m on the motor, τ_L on the load).
    /// `currentDependentInductance` false keeps L = L0 (the linear part).
    void step(Eigen::VectorXd& x, double voltageV, double torqueMotorNm, double torqueLoadNm,
              bool currentDependentInductance);

    // State accessors.
    static double current(const Eigen::VectorXd& x) { return x[0]; }
    static double motorAngle(const Eigen::VectorXd& x) { return x[1]; }
    static double motorVelocity(const Eigen::VectorXd& x) { return x[2]; }
    double loadAngle(const Eigen::VectorXd& x) const { return m_rigid ? x[1] : x[3]; }
    double loadVelocity(const Eigen::VectorXd& x) const { return m_rigid ? x[2] : x[4]; }
    /// Angle the motor encoder sees: rigid-body angle plus the higher modes.
    double encoderAngle(const Eigen::VectorXd& x) const;

    /// Continuous matrices for inductance L (inputs: v, τ_m, τ_L), coupling stiffness as configured.
    void continuousModel(double inductanceH, Eigen::MatrixXd& a, Eigen::MatrixXd& b) const;
    /// The same with the coupling stiffness K [N·m/rad] given.
    void continuousModel(double inductanceH, double stiffnessNmPerRad, Eigen::MatrixXd& a, Eigen::MatrixXd& b) const;
    /// Coupling stiffness the step uses at load angle θ_L [rad] (the screw's bucket value; else the configured K).
    double stiffnessAt(double loadAngleRad) const;
    /// Number of discretizations computed so far (each is one matrix exponential).
    std::size_t discretizations() const { return m_cache.size(); }

private:
    struct Discrete {
        Eigen::MatrixXd phi;
        Eigen::MatrixXd gamma;
    };
    const Discrete& discreteFor(int level, int bucket);
    int bucketOf(double loadAngleRad) const;
    double bucketStiffness(int bucket) const;

    PlantConfig m_cfg;
    double m_h;
    bool m_rigid;
    int m_n;
    int m_modeOffset;
    std::map<int, Discrete> m_cache;
    Eigen::VectorXd m_tmp;
    Eigen::Vector3d m_u;
};

}  // namespace axistune::sim

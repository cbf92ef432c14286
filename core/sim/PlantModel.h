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

#include <Eigen/Dense>

#include <map>
#include <vector>

namespace axistune::sim {

struct ResonanceMode {
    double frequencyHz = 0.0;
    double damping = 0.0;
    double modalInertiaKgm2 = 0.0;  ///< 1/residue: the mode adds s / (J_k (s² + 2ζωs + ω²)) to torque → velocity
};

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

    /// Continuous matrices for inductance L (inputs: v, τ_m, τ_L).
    void continuousModel(double inductanceH, Eigen::MatrixXd& a, Eigen::MatrixXd& b) const;

private:
    struct Discrete {
        Eigen::MatrixXd phi;
        Eigen::MatrixXd gamma;
    };
    const Discrete& discreteFor(int level);

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

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tool and cutting data for milling stability (spec/chatter-stability-and-spindle-speed.md §1.3, §1.6, §1.7).
// The tool is described per direction by independent modes (mass, damping, stiffness) whose
// displacements add: G_xx(jω) = Σ_i 1/(k_i − m_i ω² + j c_i ω). x is the feed direction.

#include "core/model/Result.h"

#include <Eigen/Core>
#include <complex>
#include <vector>

namespace axistune::machining {

struct ModalParameters {
    double massKg = 0.0;
    double dampingNsPerM = 0.0;
    double stiffnessNPerM = 0.0;
};

struct ToolModes {
    std::vector<ModalParameters> modesX;
    std::vector<ModalParameters> modesY;
};

enum class MillingDirection { Down, Up };

struct CuttingConditions {
    int teeth = 0;
    double ktNPerM2 = 0.0;        ///< tangential specific cutting force
    double krNPerM2 = 0.0;        ///< radial specific cutting force
    double radialImmersion = 0.0; ///< a_e / D, 0 < r ≤ 1
    MillingDirection milling = MillingDirection::Down;
    /// Spindle speed loop of a simulated cut (cut.json optional "spindle" object, docs/chatter-avoidance.md):
    /// first-order time constant (2 ms ≈ the seed's 80 Hz speed loop, spec §4.3) and the speed limits.
    double spindleTimeConstantS = 0.002;
    double spindleMinRpm = 100.0;
    double spindleMaxRpm = 20000.0;
};

/// Checks every mode (mass > 0, damping ≥ 0, stiffness > 0, all finite). A direction without modes is rigid
/// (e.g. the one-direction milling benchmark: flexible in x only); at least one mode in all is required.
Status validateTool(const ToolModes& tool);
/// Checks teeth ≥ 1, K_t > 0, K_r ≥ 0, 0 < immersion ≤ 1.
Status validateCut(const CuttingConditions& cut);

double naturalFrequencyHz(const ModalParameters& m);
double dampingRatio(const ModalParameters& m);
/// Direct compliance Σ 1/(k − m ω² + j c ω) of a list of modes at ω [rad/s], in m/N.
std::complex<double> compliance(const std::vector<ModalParameters>& modes, double omegaRadS);

/// Entry and exit angles [rad] of a tooth (eq. (1-9)): up [0, acos(1−2r)], down [acos(2r−1), π].
std::pair<double, double> engagementAngles(const CuttingConditions& cut);

/// Integral over tooth angle φ ∈ [a, b] (a ≤ b, any length) of the single-tooth cutting matrix of
/// eq. (1-6), restricted to the engagement window (repeated every 2π). Exact (closed form).
Eigen::Matrix2d integrateToothMatrix(const CuttingConditions& cut, double a, double b);

/// Mean over spindle angle [θa, θb] of the specific cutting force matrix K_f summed over all teeth
/// (tooth j at θ + 2πj/N_t). Units N/m².
Eigen::Matrix2d averageCuttingMatrix(const CuttingConditions& cut, double thetaA, double thetaB);

} // namespace axistune::machining

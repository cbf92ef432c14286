// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Sensorless chatter detection on a captured full-closed trace, seed 004 (spec/cutting-force-observer-and-
// chatter-detection.md §2.5–§2.6, §3.6 CD-1…CD-3): the three inputs (motor force K_t I_ref / R, motor
// position R θ_m, table position x_t) pass a 4th-order Butterworth high-pass (20 Hz) and low-pass
// (2000 Hz); then the vibration-mode position and force of the modally decomposed two-mass stage
//   x_vib = α/(1+α) (R θ_m − x_t)                                   (3)
//   F_vib = α (K_t I_ref / R − w M_vib a_vib − C_vib v_vib − K_vib x_vib)   (4)
// with v, a by central differences (time-aligned, spec §2.6), and the moving-window correlations of
// CorrelationChatterDetector; chatter ⇔ r_Fx < r_Fa. F_vib is the force of the process on the table along
// +x; it drives the vibration mode as −F_vib/α, so the correlations use the load F_load = −F_vib (the sign
// of seed 003 eq. (1)), for which a 1-DOF response gives r_Fx = cos φ as in spec §2.4.

#include "core/dsp/DigitalFilter.h"
#include "core/model/Result.h"

#include <cstdint>
#include <vector>

namespace axistune::machining {

/// Two-mass stage in linear units: M_m = J_M/R², M_t = J_L/R², K = K_rot/R², C = C_rot/R².
struct TwoMassStage {
    double motorMassKg = 0.0;
    double tableMassKg = 0.0;
    double stiffnessNPerM = 0.0;
    double dampingNsPerM = 0.0;
};

/// The vibration mode of spec §2.5: α = M_t/M_m, M_vib = M_m (1+α)/α, K_vib = K ((1+α)/α)², C_vib likewise.
struct VibrationMode {
    double alpha = 0.0;
    double massKg = 0.0;
    double stiffnessNPerM = 0.0;
    double dampingNsPerM = 0.0;
    double frequencyHz() const;
};

Result<VibrationMode> vibrationModeOf(const TwoMassStage& stage);

/// Butterworth filter of even order (cascade of order/2 biquads), Tustin pre-warped at fc.
Result<dsp::FilterCascade> butterworthLowPass(int order, double cutoffHz, double periodS);
Result<dsp::FilterCascade> butterworthHighPass(int order, double cutoffHz, double periodS);

struct ChatterDetectOptions {
    double lowPassHz = 2000.0;  ///< G_LPF (4th order); skipped when ≥ Nyquist (reported)
    double highPassHz = 20.0;   ///< G_HPF (4th order)
    double windowS = 0.1;       ///< T (spec §2.7: the printed 100 µs read as 100 ms)
    double inertialScale = 1.0; ///< w of eq. (4)
    double energyFloor = 0.0;   ///< minimum mean square of each correlated signal (CD-2 guard)
    double minDurationS = 0.0;  ///< debounce: shorter flagged runs are dropped (not in the paper)
    double mergeGapS = 0.0;     ///< flagged runs closer than this are merged (not in the paper)
    /// Validity gate of spec §3.6 CD-2 from an air-cut baseline: when > 0, the windows that end within
    /// [T, baselineS] (the tool not yet cutting) give the floor = baselineFactor × their largest mean square of
    /// the force; windows with less force energy are invalid (idle, air cut). 0: no gate.
    double baselineS = 0.0;
    double baselineFactor = 4.0;
};

struct ChatterInterval {
    double startS = 0.0;
    double endS = 0.0;
    double frequencyHz = 0.0; ///< peak of Re{F_load A*} in the interval (the line that makes r_Fa > r_Fx)
    double score = 0.0;       ///< mean of r_Fa − r_Fx over the interval, in (0, 2]
};

struct ChatterAnalysis {
    std::vector<double> timeS, rFx, rFa, forceVibN;
    std::vector<std::uint8_t> valid, chatter;
    std::vector<ChatterInterval> intervals;
    bool lowPassApplied = false;
    double vibrationModeHz = 0.0;
    double flaggedFraction = 0.0; ///< chatter samples / valid samples
    double forceFloorN2 = 0.0;    ///< the force mean-square floor of the baseline gate (0: none)
};

/// Runs CD-1…CD-3 over equal-length signals sampled at fs. Errors: lengths differ, too short for one
/// window, non-finite values (index named), bad options.
Result<ChatterAnalysis> detectChatter(const std::vector<double>& timeS, const std::vector<double>& motorForceN,
                                      const std::vector<double>& motorPositionM,
                                      const std::vector<double>& tablePositionM, double sampleRateHz,
                                      const VibrationMode& mode, const ChatterDetectOptions& options);

} // namespace axistune::machining

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Adaptive multisine FRF (issue 18 item 2; docs/multisine.md "Adaptive measurement"): after a first multisine,
// the lines that are not yet valid are excited again, each with the amplitude its own noise asks for (the
// spectrum follows 1/|H|·noise: A_i²·P ∝ (σ_i/|H_i|)² of what was measured so far), within the drive's torque
// limit (Drive::limits) and the voltage the current loop has left, with as many periods as that leaves
// necessary, until every line is valid or the motion-time budget is spent. The passes are combined per line by
// inverse-variance weighting; a line whose passes disagree beyond their noise is non-linear.
//
// Works through the seam on every backend (device::runTest, FrfRequestPlan): each pass is an ordinary multisine
// request (at most 4 bands, the Modbus register map's limit); a drive that refuses a shaped spectrum gets flat
// bands. Voltage: each pass's voltage_V trace gives the voltage per injected torque Z_i of its lines; the next pass's
// phases are designed for the voltage's crest factor through them (dsp::MultisineDesignOptions::crestThrough) and its
// peak voltage is predicted from that design; a pass that still reaches the limit is discarded and the excitation
// lowered.

#include "core/device/Drive.h"
#include "core/device/TestRunner.h"
#include "core/model/Result.h"

#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace axistune::device {

struct AdaptiveFrfOptions {
    double timeBudgetS = 5.0;         ///< motion time of all passes together, the first included [s]
    int maxPasses = 8;                ///< at most this many passes
    double noiseTargetFraction = 0.8; ///< a re-excited line aims at this fraction of the validity limit
    double voltageHeadroom = 0.85;    ///< predicted peak voltage at most this fraction of drive.max_voltage
    /// Passes after the first: phases that keep the crest factor of the current loop's voltage low (designed through
    /// the lines' measured voltage per torque, dsp::MultisineDesignOptions::crestThrough) when the drive traces its
    /// voltage and takes a spectrum; false: phases for the torque's crest factor, as the first pass.
    bool phasesForVoltage = true;
};

/// Why a line is left invalid.
enum class InvalidReason {
    Noise,        ///< σ_H/|H| above the limit when the budget was spent
    TorqueLimit,  ///< noisy, and the drive's FRF amplitude limit held the excitation
    VoltageLimit, ///< noisy, and the current loop's voltage held the excitation (or every pass reached it)
    Nonlinear,    ///< the passes disagree beyond their noise
};
const char* invalidReasonName(InvalidReason r);
inline constexpr std::size_t kInvalidReasonCount = 4;

struct AdaptiveFrfPass {
    std::size_t lines = 0; ///< lines excited
    std::size_t bands = 0;
    double peakPct = 0.0; ///< multisine peak [% of rated torque]
    int periods = 0;
    double motionTimeS = 0.0;
    bool shaped = false;         ///< per-line amplitudes (else flat bands)
    bool voltageReached = false; ///< discarded: the current loop reached its voltage limit
    std::size_t validAfter = 0;  ///< lines valid after combining this pass
    std::string limitedBy;       ///< "", "torque limit", "voltage limit", "time budget"
    /// Peak voltage of the current loop over the record, from the trace [V] (NaN: the drive traces no voltage).
    double voltagePeakV = std::numeric_limits<double>::quiet_NaN();
    /// The peak voltage this pass was designed for, from the lines' voltage per torque measured before [V] (NaN: the
    /// pass has phases designed for the torque: the first pass, a drive that takes no spectrum or traces no voltage).
    double voltagePredictedV = std::numeric_limits<double>::quiet_NaN();
};

struct InvalidLine {
    double freqHz = 0.0;
    InvalidReason reason = InvalidReason::Noise;
    double relativeNoise = 0.0; ///< combined σ_H/|H| (NaN when never measured below the voltage limit)
};

struct AdaptiveFrfResult {
    FrfMeasurement measurement; ///< lines of the first pass; h, coherence, valid and relativeNoise combined
    std::vector<AdaptiveFrfPass> passes;
    std::vector<InvalidLine> invalid;
    double motionTimeS = 0.0; ///< all passes
    std::size_t validLines = 0;
};

/// How many lines are left invalid for each reason, indexed by InvalidReason.
std::array<std::size_t, kInvalidReasonCount> invalidByReason(const AdaptiveFrfResult& result);

/// Runs the adaptive measurement of `first` (TestType::Frf, FrfMethod::Multisine; its amplitude, bands and
/// periods are the first pass). Errors: another method, a first pass longer than the budget, the drive's
/// refusals and errors (runTest's), an abort.
Result<AdaptiveFrfResult> runAdaptiveFrf(Drive& drive, const TestRequest& first, const AdaptiveFrfOptions& options,
                                         const RunOptions& runOptions = {});

} // namespace axistune::device

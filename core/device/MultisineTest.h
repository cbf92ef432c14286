// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The three-phase multisine FRF test of a drive (docs/multisine.md, issue 11): the multisine of
// dsp::designMultisine is injected as the torque disturbance d at the current-loop rate (as the
// sine streams of FrfTest.h), uninterrupted; after a settle time the record of P whole periods
// (three windows of 1/Δf each, the phases 0°, +120°, −120° of every line) is analysed at once.
// Settle and periods come from the velocity loop's own dynamics (loopTimingFromParameters).
// The FRF is T = −T_c/d divided by the injection-hold factor G (dsp/InjectionHold.h), as the
// sine-stream FRF of the same drive.

#include "core/device/Drive.h"
#include "core/device/FrfTest.h"
#include "core/dsp/Multisine.h"
#include "core/model/Capture.h"
#include "core/model/Result.h"

#include <cstdint>
#include <vector>

namespace axistune::device {

/// At least this many periods are averaged (so that every line carries a noise estimate).
inline constexpr int kMinMultisinePeriods = 2;
inline constexpr int kMaxMultisinePeriods = 1000;

struct MultisinePlanOptions {
    double fsHz = 4000.0;        ///< trace rate
    int ticksPerSample = 1;      ///< current-loop ticks per trace sample
    double currentPeriodS = 0.0; ///< h, for the injection-hold correction (0: no correction)
    int ticksPerVelocity = 1;    ///< N current ticks per velocity tick
    std::vector<dsp::MultisineBand> bands;
    std::vector<std::pair<double, double>> shape;
    std::vector<std::pair<double, std::complex<double>>> crestThrough; ///< dsp::MultisineDesignOptions::crestThrough
    dsp::MultisinePhases phases = dsp::MultisinePhases::Clipping;
    double peakNm = 0.0; ///< peak of the injected torque
    LoopTiming timing;
    int periods = 0;                ///< 0: max(kMinMultisinePeriods, ⌈minMeasureS / period⌉)
    double voltageLimitV = 0.0;     ///< a record that reaches it is not a linear measurement (0: no check)
    double maxRelativeNoise = 0.03; ///< lines noisier than this (σ_H/|H|, ≈ 0.26 dB / 1.7°) are invalid
};

struct MultisinePlan {
    dsp::MultisineDesign design;
    std::size_t settleSamples = 0;
    std::size_t periods = 0;
    std::size_t totalSamples = 0; ///< settle + periods·3M
    LoopTiming timing;
    double currentPeriodS = 0.0;
    int ticksPerVelocity = 1;
    double voltageLimitV = 0.0;
    double maxRelativeNoise = 0.03;
    double durationS() const { return static_cast<double>(totalSamples) / design.fsHz; }
};

/// The request's bands, or the one band fminHz..fmaxHz with multisineSpacingHz (0: fminHz/2).
std::vector<dsp::MultisineBand> multisineBandsOf(const FrfTest& request);

/// Settle = max(timing.settleS, min(settlePeriods / lowest line, maxSettleS)) (the rule of the sine
/// streams, for lightly damped modes), rounded up to whole trace samples. Errors: those of
/// designMultisine, periods outside [1, kMaxMultisinePeriods], a peak that is not positive.
Result<MultisinePlan> planMultisineTest(const MultisinePlanOptions& options);

/// The injected torque at current tick n counted from trace sample 0 (zero outside the plan).
double multisineExcitation(const MultisinePlan& plan, std::int64_t tick);

/// The FRF of a completed trace (channels injection_Nm, torque_cmd_Nm; voltage_V when present):
/// T = −T_c/d per line by the three-phase FFT analysis, corrected by G; every line invalid when the
/// traced voltage reached the limit during the record.
Result<FrfMeasurement> evaluateMultisineTrace(const MultisinePlan& plan, const model::Capture& trace);

/// Whether a multisine FRF's metadata say the current loop reached its voltage limit (voltage_clamped_samples > 0, as
/// evaluateMultisineTrace writes it). A count that is not a whole number (a foreign drive's text) counts as reached:
/// such a run is left out, never trusted. No count at all: false.
bool voltageLimitReached(const model::Metadata& frfMetadata);

} // namespace axistune::device

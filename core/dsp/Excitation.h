// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Excitation signals for frequency-response tests: stepped sine stream (settle, then an integer
// number of periods per frequency, optionally repeated at several phase offsets for the multi-sweep
// method), maximal-length PRBS and chirps (linear, exponential). An amplitude above its limit is an
// error, never clamped.

#include "core/model/Result.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace axistune::dsp {

/// Phase offsets of the three-phase multi-sweep (spec §3.5): 0, +120°, -120°.
inline const std::vector<double> kMultiSweepOffsetsDeg{0.0, 120.0, -120.0};

struct SineStreamOptions {
    std::vector<double> freqHz;             ///< frequencies, each > 0 and < fsHz
    double fsHz = 4000.0;                   ///< rate of the recorded samples (the measurement grid)
    double amplitude = 0.0;                 ///< excitation amplitude (e.g. N·m)
    double amplitudeLimit = 0.0;            ///< amplitude must not exceed it
    double settleTimeS = 0.0;               ///< settle at least this long ...
    double settlePeriods = 0.0;             ///< ... and at least this many periods
    std::size_t periods = 10;               ///< measurement window: this many whole periods ...
    double minMeasureTimeS = 0.0;           ///< ... raised to whole periods covering at least this time
    std::vector<double> phaseOffsetsDeg{0.0};  ///< one (conventional) or kMultiSweepOffsetsDeg
};

/// One frequency at one phase offset. Sample index k counts from the start of the measurement
/// window (settle samples have k < 0); the excitation is amplitude·sin(2π f k/fs + ψ).
struct SineStreamSegment {
    double freqHz = 0.0;
    double phaseOffsetDeg = 0.0;
    std::size_t settleSamples = 0;
    std::size_t measureSamples = 0;  ///< ≥ 1
    std::size_t periods = 0;         ///< whole periods in the window (rounded to the sample grid)
};

/// Segments in order: for each frequency, each phase offset. Errors: empty list, f ≤ 0 or f ≥ fs,
/// amplitude ≤ 0 or above the limit, periods = 0, negative times.
Result<std::vector<SineStreamSegment>> planSineStream(const SineStreamOptions& options);
/// The excitation value at sample index k (k < 0: settling) of a segment.
double sineStreamValue(const SineStreamSegment& segment, double amplitude, std::int64_t k, double fsHz);
/// Total number of samples (settle + measure) of a plan.
std::size_t sineStreamLength(const std::vector<SineStreamSegment>& plan);

struct PrbsOptions {
    unsigned order = 10;            ///< register length n, 2..24: period 2^n - 1 bits
    std::size_t holdSamples = 1;    ///< samples per bit (≥ 1)
    std::size_t periods = 1;        ///< whole sequence repetitions (≥ 1)
    double amplitude = 0.0;         ///< output ±amplitude
    double amplitudeLimit = 0.0;
};
/// Maximal-length sequence from a Fibonacci LFSR (all-ones start), +amplitude for bit 1.
Result<std::vector<double>> makePrbs(const PrbsOptions& options);

enum class ChirpKind { Linear, Exponential };
struct ChirpOptions {
    ChirpKind kind = ChirpKind::Linear;
    double f0Hz = 0.0;        ///< start frequency (> 0 for exponential)
    double f1Hz = 0.0;        ///< end frequency, < fsHz/2
    double durationS = 0.0;
    double fsHz = 0.0;
    double amplitude = 0.0;
    double amplitudeLimit = 0.0;
};
/// amplitude·sin(φ(t)), φ(0) = 0, instantaneous frequency f0 → f1 (linear or exponential in t),
/// samples t = k/fs for k = 0 .. round(duration·fs) - 1.
Result<std::vector<double>> makeChirp(const ChirpOptions& options);

}  // namespace axistune::dsp

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Three-phase multisine (docs/multisine.md; the multi-sweep method of
// spec/current-loop-and-multisweep-frf.md §3.5 applied to every line of a multisine at once).
//
// Lines sit at f_i = (m_i + 1/3)·Δf with Δf = fs/M (M trace samples per window). The signal
// x(t) = Σ A_i sin(2π f_i t + φ_i) is periodic with 3/Δf, and the window n (length 1/Δf) shows every
// line shifted by the same ψ_n = n·120° (2π f_i n/Δf = 2π m_i n + n·120°): one uninterrupted
// multisine is the three-phase excitation of the issue, with no settling between the phases.
// Demodulating line j with the three-phase formula removes the sum-frequency terms of every line
// (Σ_n e^{−2jψ_n} = 0), the difference terms sum to zero over a window (f_i − f_j a nonzero
// multiple of Δf below fs), so every line below the trace rate fs is measured exactly for a
// linear, fs-periodic system. All lines are demodulated at once by one complex FFT of length M.

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Result.h"

#include <complex>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace axistune::dsp {

/// Lines every spacingHz (rounded to a multiple of the finest band's spacing) in [fminHz, fmaxHz].
struct MultisineBand {
    double fminHz = 0.0;
    double fmaxHz = 0.0;
    double spacingHz = 0.0;
};

/// Phases that keep the crest factor low.
enum class MultisinePhases {
    Clipping,  ///< Schroeder start, then iterative clipping on the generation grid (lower crest factor)
    Schroeder, ///< φ_i = −π·i·(i−1)/L (flat spectrum; weighted by the power for a shaped one)
};

const char* multisinePhasesName(MultisinePhases p);

struct MultisineDesignOptions {
    double fsHz = 4000.0;   ///< trace (observation) rate
    int ticksPerSample = 1; ///< generation ticks per trace sample (current-loop rate = fs·ticksPerSample)
    std::vector<MultisineBand> bands;
    /// Relative amplitude over frequency as (f [Hz], weight > 0) points, interpolated linearly in
    /// log f (held beyond the ends); empty: flat.
    std::vector<std::pair<double, double>> shape;
    MultisinePhases phases = MultisinePhases::Clipping;
    /// Keep the crest factor low as seen through this response instead of the excitation's own: (f [Hz], gain)
    /// points, the gain interpolated linearly in log f between them (held beyond the ends), e.g. the current loop's
    /// voltage per injected torque when the voltage, not the torque, limits the excitation. The phases are designed
    /// for the spectrum |G_i|·A_i and turned back by arg G_i; amplitudes and the excitation's peak are as without it.
    /// Empty: the excitation's own crest factor.
    std::vector<std::pair<double, std::complex<double>>> crestThrough;
    int clippingIterations = 300; ///< at most; fewer (≥ 10) when one period exceeds 50000 generation ticks
    double peak = 1.0; ///< peak of the generated samples (e.g. N·m): never exceeded
};

struct MultisineDesign {
    double fsHz = 0.0;
    int ticksPerSample = 1;
    std::size_t windowSamples = 0; ///< M: trace samples per window (one phase)
    double spacingHz = 0.0;        ///< Δf = fs/M
    std::vector<std::size_t> bins; ///< m_i: f_i = (m_i + 1/3)·Δf, increasing
    std::vector<double> freqHz;
    std::vector<double> amplitude; ///< A_i
    std::vector<double> phaseRad;  ///< φ_i
    std::vector<double> table;     ///< one period (3·M·ticksPerSample generation ticks)
    double peak = 0.0;             ///< max |x| over the generation grid (= options.peak)
    double rms = 0.0;              ///< over one period
    double crestFactor = 0.0;      ///< peak / rms
    MultisinePhases phases = MultisinePhases::Clipping;

    std::size_t periodTicks() const { return table.size(); }
    std::size_t periodSamples() const { return 3 * windowSamples; }
    /// The excitation at generation tick n (n ≥ 0; periodic).
    double valueAtTick(std::int64_t tick) const;
    /// The exact multisine at time t [s] from the origin (for tests; t on the grid gives valueAtTick).
    double valueAt(double tS) const;
};

/// Designs the multisine. Errors (OutOfRange, naming the option): no band, fmin ≤ 0, fmax < fmin,
/// fmax ≥ fs, spacing ≤ 0 or a window longer than 2²⁰ samples, a band without a line, more than
/// 20000 lines, shape weights not positive, peak not positive, ticksPerSample < 1.
Result<MultisineDesign> designMultisine(const MultisineDesignOptions& options);

/// Peak over the generation grid of the design's excitation seen through the gains G_i of its lines
/// (max_t |Σ |G_i| A_i sin(2π f_i t + φ_i + arg G_i)|), e.g. the voltage a multisine of torque asks of the current
/// loop. gains.size() must equal the design's lines (else NaN).
double multisinePeakThrough(const MultisineDesign& design, std::span<const std::complex<double>> gains);

/// Crest factor max|x|/rms of samples.
double crestFactor(std::span<const double> x);

/// Options of the analysis of a record.
struct MultisineAnalysisOptions {
    /// Three-phase (the method) or single-phase (a conventional analysis of the first window of each
    /// period, for comparison: valid only below fs/2 and only when no excited line folds off the grid).
    bool threePhase = true;
    /// A line whose relative standard error of the mean (σ_H/|H|) exceeds this is marked invalid
    /// (needs ≥ 2 periods; 0 disables the check).
    double maxRelativeNoise = 0.03;
};

/// Per-line result besides the FRF.
struct MultisineLineStats {
    std::vector<double> relativeNoise;    ///< σ_H/|H| of the mean over the periods (NaN for one period)
    std::vector<double> excitationPhasor; ///< |X| of the mean excitation phasor
    std::size_t periods = 0;
    std::size_t invalidNoise = 0; ///< lines invalid by maxRelativeNoise
};

struct MultisineAnalysis {
    FrequencyResponse frf; ///< H = ΣY/ΣX per line; coherence = |ΣX*Y|²/(Σ|X|²Σ|Y|²) over the periods (NaN for one)
    MultisineLineStats stats;
};

/// Phasors P = B·e^{jφ} (y = B sin(ω k/fs + φ) from the start of the first window) of every line
/// from three windows of M samples (window n at phase n·120°), by one complex FFT of length M.
std::vector<std::complex<double>> demodulateThreePhase(const MultisineDesign& design, std::span<const double> w0,
                                                       std::span<const double> w1, std::span<const double> w2);
/// Conventional (single-phase) phasors of every line from one window of M samples.
std::vector<std::complex<double>> demodulateSinglePhase(const MultisineDesign& design, std::span<const double> w0);

/// The FRF response/excitation of a record of whole periods (3·M samples each, `periods` ≥ 1) that
/// starts at any trace sample after settling. Errors: records shorter than the periods, unequal
/// lengths, periods < 1.
Result<MultisineAnalysis> analyzeMultisine(const MultisineDesign& design, std::span<const double> excitation,
                                           std::span<const double> response, std::size_t periods,
                                           const MultisineAnalysisOptions& options = {});

} // namespace axistune::dsp

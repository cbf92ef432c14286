// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Sine-stream demodulation (spec/current-loop-and-multisweep-frf.md §3.3–3.6):
//   conventional (one sweep, phase offset ψ):
//     a = 2/M Σ_k y[k] cos(ω kΔt + ψ),  b = 2/M Σ_k y[k] sin(ω kΔt + ψ)   valid for f < fs/2
//   three-phase multi-sweep (sweeps at ψ = 0, +120°, -120°, same sample indices k):
//     a = 2/(3M) Σ_k Σ_n y_n[k] cos(ω kΔt + ψ_n),  b = 2/(3M) Σ_k Σ_n y_n[k] sin(ω kΔt + ψ_n)
//     exact for any M ≥ 1, valid for f < fs.
// For y = B sin(ω t + φ + ψ): a = B sin φ, b = B cos φ, so B = |b + j a| and φ = atan2(a, b)
// (DESIGN.md; the thesis prints the inverse ratio). k is the sample index counted from the start
// of the measurement window, t = k/fs.
// A sine-stream recording (the sine-stream CSV of DESIGN.md) is turned into an FRF by demodulating
// the response and the recorded excitation of each frequency and taking their ratio.

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Result.h"

#include <array>
#include <complex>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace axistune::dsp {

/// One sweep at one frequency: samples y[i] at sample indices firstSample + i.
struct SweepSamples {
    double phaseOffsetDeg = 0.0;
    std::int64_t firstSample = 0;
    std::span<const double> y;
};

struct Demodulated {
    double a = 0.0;  ///< B sin φ
    double b = 0.0;  ///< B cos φ
    bool valid = false;
    bool multiSweep = false;
    std::complex<double> phasor() const { return {b, a}; }  ///< B·e^{jφ}
    double amplitude() const { return std::hypot(a, b); }
    double phaseRad() const { return std::atan2(a, b); }
};

/// One sweep → conventional; three sweeps with offsets {0, +120, -120}° (any order, within 1e-6°)
/// on the same sample indices → multi-sweep. Errors: other sweep counts or offsets, empty or
/// unequal sample windows, f ≤ 0, fs ≤ 0. f beyond the method's alias-free range → valid = false.
Result<Demodulated> demodulate(std::span<const SweepSamples> sweeps, double freqHz, double fsHz);

/// Park transform of (D.1)–(D.2): [d; q] = R(θ)ᵀ Sᵀ [u; v; w] (spec Appendix D, check C-C4).
std::array<double, 2> parkTransform(double u, double v, double w, double thetaRad);

/// A sine-stream recording: blocks of rows with one frequency and phase offset each.
struct SweepBlock {
    double freqHz = 0.0;
    double phaseOffsetDeg = 0.0;
    std::vector<std::int64_t> sample;   ///< k from the measurement-window start; k < 0 while settling
    std::vector<double> excitation;
    std::vector<double> response;
};
struct SweepRecording {
    double fsHz = 0.0;
    double amplitude = 0.0;                          ///< nominal excitation amplitude (metadata)
    model::Metadata metadata;                        ///< all "# key=value" lines, fs_Hz and amplitude included
    std::vector<SweepBlock> blocks;
};

/// FRF response/excitation per frequency (frequencies in order of first appearance, sorted):
/// three offsets → multi-sweep, one → conventional. Only samples with k ≥ 0 are used, and k must
/// increase by one within a block. Coherence is undefined (NaN). Errors name the frequency.
Result<FrequencyResponse> sineStreamFrf(const SweepRecording& recording);

}  // namespace axistune::dsp

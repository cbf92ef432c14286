// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tool modes fitted to a measured tool-tip receptance FRF (issue 10 item 1, issue 19 item 1; the model of
// spec/chatter-stability-and-spindle-speed.md §1.3): H(ω) = Σ_i 1/(k_i − m_i ω² + j c_i ω) in m/N, plus
// residual terms for the modes outside the band (a complex constant for those above, −L/ω² for those
// below). docs/machining.md "Tool modes from a measured FRF" describes the method and the quality gate.
//  1. Resonance peaks: interior maxima of the smoothed −Im H whose half-power points of |H| lie inside the
//     data; peaks not separated by a dip below 1/√2 of the smaller one are one resonance.
//  2. Band: given, or automatic from the chosen peaks (three half-power half-widths beyond the outer ones).
//  3. Levenberg–Marquardt on the absolute complex error weighted by √|H| (compliance-based: the noise floor
//     and the anti-resonances, where |H| is small, weigh little), in bounded parameters: f_n > 0,
//     ζ = 0.5/(1 + e^−q) ∈ (0, 0.5), k > 0.
//  4. Quality gate: a fit whose residual or parameters are implausible is refused with the reason.

#include "core/dsp/FrequencyResponse.h"
#include "core/machining/ToolModel.h"
#include "core/model/Result.h"

#include <complex>
#include <limits>
#include <vector>

namespace axistune::machining {

struct ToolModeFitOptions {
    int modes = 0; ///< modes to fit; 0 = one per significant resonance peak (≥ 25 % of the largest −Im H)
    double minHz = std::numeric_limits<double>::quiet_NaN(); ///< band lower edge; NaN (both) = automatic
    double maxHz = std::numeric_limits<double>::quiet_NaN(); ///< band upper edge; NaN = automatic / data end
    int maxIterations = 200;                                 ///< Levenberg–Marquardt iterations
    bool residualTerms = true;                               ///< fit the residual terms of the out-of-band modes
    double maxResidual = 0.30; ///< quality gate: largest accepted weighted residual ratio (see result)
};

/// A resonance peak found in the FRF.
struct ResonancePeak {
    double hz = 0.0;          ///< frequency of the −Im H maximum
    double lowHz = 0.0;       ///< lower half-power point of |H| (of the merged peak group)
    double highHz = 0.0;      ///< upper half-power point of |H| (of the merged peak group)
    double negIm = 0.0;       ///< −Im H at the peak [m/N]
    double halfWidthHz = 0.0; ///< half the own half-power bandwidth (before merging)
};

struct ToolModeFitResult {
    std::vector<ModalParameters> modes;      ///< sorted by natural frequency
    std::vector<ModalParameters> startModes; ///< the peak-picking start values, same order as modes
    std::vector<ResonancePeak> peaks;        ///< the peaks the modes started from, same order as modes
    double bandMinHz = 0.0, bandMaxHz = 0.0; ///< the band that was fitted
    bool automaticBand = false;
    std::complex<double> upperResidual = 0.0; ///< constant compliance of the modes above the band [m/N]
    double lowerResidual = 0.0;               ///< L of −L/ω² for the modes below the band [m/N·(rad/s)²]
    double rmsRelativeError = 0.0;            ///< sqrt(mean |H_model/H − 1|²) over the fitted points (diagnostic)
    double residualRatio = 0.0; ///< ‖√|H|·(H_model − H)‖ / ‖√|H|·H‖ over the band (the gated quantity)
    int iterations = 0;
    std::size_t points = 0; ///< valid points inside the band that were fitted
};

/// Resonance peaks of the receptance in [minHz, maxHz] (NaN = data edge), strongest first, each at least
/// 5 % of the strongest −Im H. Points with valid = false, f ≤ 0 or non-finite h are ignored.
std::vector<ResonancePeak> findResonancePeaks(const dsp::FrequencyResponse& frf, double minHz, double maxHz);

/// Fits tool modes to the receptance `frf` (h in m/N). Errors (BadInput) name the reason: too few points,
/// no resonance peak (for mode N), or a fit refused by the quality gate (residual ratio above
/// options.maxResidual; a damping ratio outside [1e-4, 0.25] (at a bound); a natural frequency outside the
/// band; two modes on one resonance; a mode whose peak is below 5 % of the largest |H| in the band; a mode
/// that misses its measured peak by more than 35 % locally). OutOfRange for modes < 0 or an empty band.
Result<ToolModeFitResult> fitToolModes(const dsp::FrequencyResponse& frf, const ToolModeFitOptions& options = {});

/// Model of a fit (modes and residual terms) at ω [rad/s], in m/N.
std::complex<double> fittedCompliance(const ToolModeFitResult& fit, double omegaRadS);

} // namespace axistune::machining

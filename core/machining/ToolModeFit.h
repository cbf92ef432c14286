// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tool modes fitted to a measured tool-tip receptance FRF (issue 10 item 1; the model of
// spec/chatter-stability-and-spindle-speed.md §1.3): H(ω) = Σ_i 1/(k_i − m_i ω² + j c_i ω) in m/N.
// Start values by peak picking (peaks of −Im H, half-power bandwidth of |H|), one mode at a time
// with the modes found so far subtracted; then Levenberg–Marquardt on the relative complex residuals
// (H_model − H)/H over the chosen band, in log-parameters so every result stays positive.

#include "core/dsp/FrequencyResponse.h"
#include "core/machining/ToolModel.h"
#include "core/model/Result.h"

#include <limits>
#include <vector>

namespace axistune::machining {

struct ToolModeFitOptions {
    int modes = 1;                 ///< number of modes to fit (≥ 1)
    double minHz = 0.0;            ///< band lower edge (inclusive)
    double maxHz = std::numeric_limits<double>::infinity();  ///< band upper edge (inclusive)
    int maxIterations = 200;       ///< Levenberg–Marquardt iterations
};

struct ToolModeFitResult {
    std::vector<ModalParameters> modes;  ///< sorted by natural frequency
    std::vector<ModalParameters> startModes;  ///< the peak-picking start values, same order as found
    double rmsRelativeError = 0.0;       ///< sqrt(mean |H_model/H − 1|²) over the fitted points
    int iterations = 0;
    std::size_t points = 0;              ///< valid points inside the band that were fitted
};

/// Fits `options.modes` modes to the receptance `frf` (h in m/N; only points with valid = true and
/// minHz ≤ f ≤ maxHz, f > 0, finite nonzero h). Errors: BadInput for fewer points than 3·modes + 1,
/// no resonance peak for a mode (the first: no interior local maximum of −Im H; a further one: none above
/// 5 % of the first peak outside ±5ζω_n of the modes already found), or a non-finite / non-positive
/// result; OutOfRange for modes < 1.
Result<ToolModeFitResult> fitToolModes(const dsp::FrequencyResponse& frf, const ToolModeFitOptions& options = {});

}  // namespace axistune::machining

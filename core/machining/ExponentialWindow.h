// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The damping an exponential window adds, removed from fitted modes (docs/machining.md "Tap test").
// A tap test windowed by exp(−σt) on force and response measures H(s + σ) instead of H(s): the mode
// 1/(m s² + c s + k) becomes 1/(m s² + (c + 2mσ) s + (k + cσ + mσ²)). A mode fitted to that FRF is mapped
// back exactly by m = m_w, c = c_w − 2mσ, k = k_w − cσ − mσ² (its pole moves right by σ).

#include "core/dsp/FrequencyResponse.h"
#include "core/machining/ToolModel.h"
#include "core/model/Result.h"

#include <vector>

namespace axistune::machining {

/// The mode without the window's decay σ [1/s]. OutOfRange when the window's damping is larger than the
/// fitted damping (c_w < 2mσ: the fit cannot be trusted) or the stiffness would not stay positive.
Result<ModalParameters> removeExponentialWindow(const ModalParameters& fitted, double sigmaPerS);

/// σ from an FRF's metadata exp_window_decay_1_s (0 when absent); BadInput when it is not a number ≥ 0.
Result<double> exponentialWindowDecay(const dsp::FrequencyResponse& frf);

/// Applies removeExponentialWindow to every mode with the FRF's σ (nothing when σ = 0).
Status removeExponentialWindow(std::vector<ModalParameters>& modes, const dsp::FrequencyResponse& frf);

} // namespace axistune::machining

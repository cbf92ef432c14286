// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Loop margins as result JSON (`axistune-cli notch`, `frf --margins`, the notch and velocity-loop
// wizards): a margin that is not defined is left out and named with its reason in "undefined"
// (docs/formats.md "Undefined values"), never null.

#include "core/dsp/LoopAnalysis.h"

#include <nlohmann/json_fwd.hpp>

namespace axistune::dsp {

/// Why a margin is not defined.
inline constexpr const char* kNoGainCrossover =
    "no gain crossover: |L| does not cross 0 dB in the measured band, so there is no phase margin";
inline constexpr const char* kNoPhaseCrossover =
    "no phase crossover: the phase of L does not reach -180 deg in the measured band, so the gain margin is "
    "unbounded";
inline constexpr const char* kNoValidPoint = "no valid point in the FRF";

/// gain_margin_dB/_Hz, phase_margin_deg/_Hz, peak_sensitivity_dB/_Hz of `notch` and the notch wizard.
nlohmann::json loopMarginsJson(const LoopMargins& m);

} // namespace axistune::dsp

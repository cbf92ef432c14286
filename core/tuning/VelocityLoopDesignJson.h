// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A velocity-loop design as result JSON: `axistune-cli velocity-loop` and the velocity-loop wizard's session
// ("proposal"). A margin or limit that is not defined is left out and named in "undefined" (docs/formats.md
// "Undefined values"), never null.

#include "core/tuning/VelocityLoopDesign.h"

#include <nlohmann/json_fwd.hpp>

namespace axistune::tuning {

/// crossover_Hz, phase_margin_deg, gain_margin_dB, phase_crossover_Hz, peak_sensitivity_dB.
nlohmann::json velocityLoopMarginsJson(const LoopMargins& m);

/// velocity_kp_Nms_per_rad, velocity_ki_Nm_per_rad, rule, margins_before, margins, position_gain_limit_Hz,
/// position_gain_limit_per_s, position_gain_per_s.
nlohmann::json velocityLoopProposalJson(const VelocityLoopDesign& d);

} // namespace axistune::tuning

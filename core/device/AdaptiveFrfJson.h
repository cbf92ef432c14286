// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The adaptive FRF's passes and the lines it left invalid as JSON: the CLI's `capture --adaptive` output
// (docs/cli.md) and the FRF wizard's session result "adaptive" (docs/wizards/frf.md) write the same object.

#include <nlohmann/json_fwd.hpp>

namespace axistune::device {

struct AdaptiveFrfResult;

/// {time_budget_s, motion_time_s, valid_lines, passes[] {lines, bands, peak_pct, periods, motion_time_s, shaped,
/// voltage_limit_reached, valid_after, limited_by, voltage_peak_V, voltage_predicted_V}, invalid_lines[] {f_Hz,
/// reason, relative_noise}, invalid_by_reason {noise, torque limit, voltage limit, nonlinearity}}; a number that is
/// not known is null with its reason beside it (model::putNumber).
nlohmann::json adaptiveFrfJson(const AdaptiveFrfResult& result, double timeBudgetS);

} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Units: SI inside core, display units only at the edge (DESIGN.md "Units and conventions").
// A unit is named by an ASCII token ("mH", "um", "min^-1"); each token has a UTF-8 label for people
// ("mH", "µm", "min⁻¹"), the SI token it converts to, and the factor to SI.

#include "core/model/Number.h" // formatNumber, long declared here
#include "core/model/Result.h"

#include <string>
#include <string_view>
#include <vector>

namespace axistune::model {

struct UnitInfo {
    std::string_view token; ///< ASCII name used in files and metadata
    std::string_view label; ///< UTF-8 label shown to people
    std::string_view si;    ///< token of the SI unit of the same quantity
    double toSi;            ///< value_si = value * toSi
};

/// The unit with this token, or NotFound.
Result<UnitInfo> findUnit(std::string_view token);
/// Converts between two units of the same quantity; BadInput when the quantities differ.
Result<double> convertUnit(double value, std::string_view from, std::string_view to);
Result<double> toSi(double value, std::string_view from);
/// The UTF-8 label of a unit token (the token itself when unknown).
std::string unitLabel(std::string_view token);
/// All known unit tokens (for documentation and tests).
std::vector<UnitInfo> allUnits();

} // namespace axistune::model

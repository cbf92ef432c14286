// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Parameter metadata: every drive parameter has a key, an SI unit, a display unit, limits in SI and
// whether it may be written while a test runs. Range violations are errors, never clamps.

#include "core/model/Result.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace axistune::model {

struct ParameterMeta {
    std::string key;           ///< e.g. "velocity.kp"
    std::string label;         ///< short English name for people
    std::string siUnit;        ///< unit token (core/model/Units.h) of the stored value
    std::string displayUnit;   ///< unit token shown to people
    double minSi = 0.0;
    double maxSi = 0.0;
    bool writable = true;              ///< false: read-only (motor data, identity)
    bool writableDuringTest = false;   ///< most parameters are frozen while a test moves the axis
    bool integer = false;              ///< an integer-valued setting (mode, count)
    std::string group;                 ///< "current", "velocity", "position", "filter", ...
    std::string description;
};

using ParameterValues = std::map<std::string, double>;

/// Checks a value against its metadata: finite, integer where required, inside [minSi, maxSi].
/// The error names the key, the value and the limits in the display unit.
Status checkParameterValue(const ParameterMeta& meta, double valueSi);

/// A lookup over a list of metadata.
const ParameterMeta* findParameter(const std::vector<ParameterMeta>& metas, const std::string& key);

/// Formats a value in the parameter's display unit, e.g. "2.19 mH".
std::string formatDisplay(const ParameterMeta& meta, double valueSi);

}  // namespace axistune::model

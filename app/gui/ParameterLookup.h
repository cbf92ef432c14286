// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A value of a drive's parameter reply, or the caller's fallback when the drive did not send that key
// (the wizard pages keep what they had).

#include "core/model/Parameter.h"

#include <string>

namespace axistune::gui {

inline double parameterOr(const model::ParameterValues& values, const std::string& key, double fallback)
{
    const auto it = values.find(key);
    return it == values.end() ? fallback : it->second;
}

} // namespace axistune::gui

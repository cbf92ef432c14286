// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The names a circle's travel direction has in files, metadata, the register map and on the command line ("ccw",
// "cw"): written and read here only.

#include "core/model/BallBarTrace.h"

#include <optional>
#include <string_view>

namespace axistune::model {

inline const char* circleDirectionName(CircleDirection d) { return d == CircleDirection::Cw ? "cw" : "ccw"; }

/// "ccw" or "cw" (exactly, lower case); nullopt for anything else.
inline std::optional<CircleDirection> circleDirectionFromName(std::string_view name)
{
    if (name == "ccw")
        return CircleDirection::Ccw;
    if (name == "cw")
        return CircleDirection::Cw;
    return std::nullopt;
}

} // namespace axistune::model

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A capture: named channels of equal length sampled at one rate, in SI units, with metadata.
// Channel names carry their unit (DESIGN.md "File formats"): "t_s", "torque_cmd_Nm", "motor_vel_rad_s".
// Captures are immutable once made; share them as std::shared_ptr<const Capture>.

#include "core/model/Metadata.h"

#include <string>
#include <vector>

namespace axistune::model {

struct Channel {
    std::string name;          ///< column name with unit suffix, e.g. "motor_vel_rad_s"
    std::vector<double> data;  ///< SI values
};

struct Capture {
    Metadata metadata; ///< "# key=value" lines, e.g. fs_Hz=4000 (numbers as numbers)
    std::vector<Channel> channels;

    std::size_t size() const { return channels.empty() ? 0 : channels.front().data.size(); }
    const Channel* channel(const std::string& name) const
    {
        for (const auto& c : channels) {
            if (c.name == name)
                return &c;
        }
        return nullptr;
    }
};

}  // namespace axistune::model

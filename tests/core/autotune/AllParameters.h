// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Every parameter of an axis as the drive holds it (the tuner's tests compare them before and after a run).

#include "core/device/Drive.h"
#include "core/model/Parameter.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace axistune::autotunetest {

inline model::ParameterValues allParameters(device::Drive& d, const std::string& axis)
{
    std::vector<std::string> keys;
    auto metas = d.parameterMetadata(axis);
    EXPECT_TRUE(metas.ok());
    if (!metas.ok())
        return {};
    for (const auto& m : *metas)
        keys.push_back(m.key);
    auto v = d.readParameters(axis, keys);
    EXPECT_TRUE(v.ok());
    return v.ok() ? *v : model::ParameterValues{};
}

} // namespace axistune::autotunetest

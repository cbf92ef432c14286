// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Test requests shared by the GUI's drive-link tests (tst_drivecontroller, tst_drivereplies).

#include "core/device/Drive.h"

#include <string>

namespace axistune::testing {

/// An FRF test that takes several seconds of wall time on the simulator (many slow low frequencies).
inline device::TestRequest longFrf(const std::string& axis)
{
    device::TestRequest t;
    t.axis = axis;
    auto& f = t.test.emplace<device::FrfTest>();
    f.method = device::FrfMethod::MultiSweep;
    f.fminHz = 2.0;
    f.fmaxHz = 1000.0;
    f.points = 300;
    f.amplitudePct = 3.0;
    f.settleS = 0.5;
    f.minMeasureS = 1.0;
    return t;
}

} // namespace axistune::testing

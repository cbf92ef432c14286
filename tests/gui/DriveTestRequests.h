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
    t.type = device::TestType::Frf;
    t.frfMethod = device::FrfMethod::MultiSweep;
    t.fminHz = 2.0;
    t.fmaxHz = 1000.0;
    t.points = 300;
    t.amplitudePct = 3.0;
    t.settleS = 0.5;
    t.minMeasureS = 1.0;
    return t;
}

} // namespace axistune::testing

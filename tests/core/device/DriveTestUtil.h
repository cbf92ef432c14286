// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shared by the simulated drive's FRF tests: a drive on a preset, and an FRF test run to its end.

#include "core/device/SimulatedDrive.h"
#include "core/sim/MachineDefinition.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace axistune::devtest {

inline std::unique_ptr<device::SimulatedDrive> makeDrive(const std::string& preset, std::uint64_t seed = 3)
{
    auto def = sim::loadPreset(preset);
    EXPECT_TRUE(def.ok());
    auto d = device::SimulatedDrive::create(*def, seed);
    EXPECT_TRUE(d.ok());
    return std::move(d).value();
}

/// Starts the test, polls it to its end (progress never falls; it must complete) and returns the FRF.
inline device::FrfMeasurement runFrf(device::SimulatedDrive& drive, const device::TestRequest& r)
{
    auto st = drive.startTest(r);
    EXPECT_TRUE(st.ok()) << (st.ok() ? "" : st.error().detail);
    double progress = 0.0;
    while (true) {
        auto s = drive.pollTest();
        EXPECT_TRUE(s.ok());
        EXPECT_GE(s->progress, progress);
        progress = s->progress;
        if (s->state != device::TestState::Running) {
            EXPECT_EQ(s->state, device::TestState::Completed) << s->detail;
            break;
        }
    }
    auto m = drive.readFrequencyResponse();
    EXPECT_TRUE(m.ok()) << (m.ok() ? "" : m.error().detail);
    return std::move(m).value();
}

}  // namespace axistune::devtest

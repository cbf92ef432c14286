// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shared by the simulated drive's FRF tests: a drive on a preset, and an FRF test run to its end.

#include "core/device/SimulatedDrive.h"
#include "core/device/TestRunner.h"
#include "core/sim/MachineDefinition.h"

#include <gtest/gtest.h>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace axistune::devtest {

inline std::unique_ptr<device::SimulatedDrive> makeDrive(const std::string& preset, std::uint64_t seed = 3)
{
    auto def = sim::loadPreset(preset);
    EXPECT_TRUE(def.ok());
    auto d = device::SimulatedDrive::create(*def, seed);
    EXPECT_TRUE(d.ok());
    return std::move(d).value();
}

/// Forwards every call of the seam to another drive; a test derives from it and overrides what it changes.
class ForwardingDrive : public device::Drive {
public:
    explicit ForwardingDrive(device::Drive& inner) : m_inner(inner) {}
    Result<device::DriveIdentity> identify() override { return m_inner.identify(); }
    Result<std::vector<model::ParameterMeta>> parameterMetadata(const std::string& a) override
    {
        return m_inner.parameterMetadata(a);
    }
    Result<model::ParameterValues> readParameters(const std::string& a, std::span<const std::string> k) override
    {
        return m_inner.readParameters(a, k);
    }
    Status writeParameters(const std::string& a, const model::ParameterValues& v) override
    {
        return m_inner.writeParameters(a, v);
    }
    Status startTest(const device::TestRequest& r) override { return m_inner.startTest(r); }
    Result<device::TestStatus> pollTest() override { return m_inner.pollTest(); }
    Result<model::Capture> readTrace() override { return m_inner.readTrace(); }
    Status abortTest() override { return m_inner.abortTest(); }
    Result<device::FrfMeasurement> readFrequencyResponse() override { return m_inner.readFrequencyResponse(); }
    Result<device::DriveCapabilities> capabilities(const std::string& a) override { return m_inner.capabilities(a); }
    Result<device::DriveLimits> limits(const std::string& a) override { return m_inner.limits(a); }
    Result<device::TestPlan> planTest(const device::TestRequest& r) override { return m_inner.planTest(r); }

protected:
    device::Drive& m_inner;
};

/// Runs the test to its end with device::runTest (progress never falls; it must complete) and returns the
/// FRF the drive evaluated.
inline device::FrfMeasurement runFrf(device::Drive& drive, const device::TestRequest& r)
{
    double progress = 0.0;
    device::RunOptions o;
    o.readTrace = false;
    o.progress = [&progress](double f, const std::string&) {
        EXPECT_GE(f, progress);
        progress = f;
    };
    auto run = device::runTest(drive, r, o);
    EXPECT_TRUE(run.ok()) << (run.ok() ? "" : run.error().detail);
    if (!run.ok() || !run->frf)
        return {};
    EXPECT_FALSE(run->frfEvaluatedOnHost);
    EXPECT_EQ(progress, 1.0);
    return *run->frf;
}

/// Runs the request to its end on each drive (device::runTest) and returns their traces (nullopt, reported as
/// a failure, when a run fails).
inline std::vector<std::optional<model::Capture>> tracesOfEach(std::initializer_list<device::Drive*> drives,
                                                               const device::TestRequest& r)
{
    std::vector<std::optional<model::Capture>> out;
    for (device::Drive* d : drives) {
        auto run = device::runTest(*d, r);
        EXPECT_TRUE(run.ok()) << (run.ok() ? "" : run.error().detail);
        out.push_back(run.ok() ? run->trace : std::nullopt);
    }
    return out;
}

} // namespace axistune::devtest

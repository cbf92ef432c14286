// SPDX-License-Identifier: GPL-3.0-or-later
// The drive conformance suite (DriveConformance.h) for sim:, modbus:// and replay:; hal: runs in
// tests/linuxcnc/test_hal_conformance.cpp, where the HAL tests run one at a time. A new backend adds one
// INSTANTIATE line (here or next to its own tests) and its scheme to the coverage list below.
#include "tests/conformance/DriveConformance.h"

namespace axistune::device {
namespace {

INSTANTIATE_TEST_SUITE_P(Backends, DriveConformance, ::testing::Values("sim", "modbus", "replay"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

// Every registered backend is in the suite: a new registration without an instantiation above fails.
TEST(DriveConformanceCoverage, EveryRegisteredBackendIsInstantiated)
{
    // hal: and linuxcnc: are instantiated in tests/linuxcnc/test_hal_conformance.cpp.
    const std::vector<std::string> covered{"sim:", "modbus://", "replay:", "hal:", "linuxcnc:"};
    for (const auto& b : registeredBackends()) {
        EXPECT_NE(std::find(covered.begin(), covered.end(), b.scheme), covered.end())
            << b.scheme << " is registered but not run by the conformance suite";
    }
}

// The same FRF from sim: and modbus:// on the same simulated machine and seed. Both run the same
// deterministic simulator (seed 7, same request as the first test after connecting) and the trace and
// the FRF travel as float64 (docs/modbus.md): they agree to rounding, 1e-9 relative (as
// tests/core/device/test_multisine_test.cpp); the noise of the simulator is the same sequence in both.
TEST(DriveConformanceCross, SameFrfFromSimAndModbus)
{
    testing::SimDrive server("--preset vmc --seed 7");
    ASSERT_GT(server.port(), 0);
    auto remote = connect({server.uri("timeout_ms=2000"), kSeed});
    auto local = connect({"sim:vmc", kSeed});
    ASSERT_TRUE(remote.ok() && local.ok());
    for (const auto method : {FrfMethod::MultiSweep, FrfMethod::Multisine}) {
        SCOPED_TRACE(frfMethodName(method));
        TestRequest r;
        r.axis = "X";
        auto& frf = r.test.emplace<FrfTest>();
        frf.method = method;
        frf.fminHz = 50.0;
        frf.fmaxHz = 400.0;
        frf.points = 6;
        frf.amplitudePct = 5.0;
        std::vector<FrfMeasurement> m;
        for (Drive* d : {remote->get(), local->get()}) {
            ASSERT_TRUE(d->startTest(r).ok());
            const auto out = runToEnd(*d);
            ASSERT_EQ(out.last.state, TestState::Completed) << out.error << out.last.detail;
            auto f = d->readFrequencyResponse();
            ASSERT_TRUE(f.ok()) << errorText(f.error());
            m.push_back(std::move(f).value());
        }
        const auto& a = m[0].frf;
        const auto& b = m[1].frf;
        ASSERT_GT(b.size(), 0u);
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t i = 0; i < b.size(); ++i) {
            EXPECT_EQ(a.freqHz[i], b.freqHz[i]);
            EXPECT_LE(std::abs(a.h[i] - b.h[i]), 1e-9 * std::abs(b.h[i])) << b.freqHz[i];
            EXPECT_EQ(a.valid[i], b.valid[i]);
        }
        EXPECT_EQ(m[0].motionTimeS, m[1].motionTimeS);
    }
}

} // namespace
} // namespace axistune::device

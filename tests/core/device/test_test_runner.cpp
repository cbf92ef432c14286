// SPDX-License-Identifier: GPL-3.0-or-later
// device::runTest (TestRunner.h, issue 16 item 3): one run-to-completion helper. Host-side evaluation:
// a drive that only streams samples (readFrequencyResponse() left at the seam's NotFound) gets the same
// multisine, multi-sweep and PRBS FRF from the host as the simulated drive computes itself, from the
// same samples (two drives on the same preset and seed); progress never falls and ends at 1; an abort
// before the start runs nothing, an abort while running restores the parameters; a lost connection,
// a stalled drive and a fault are reported with their codes.
#include "core/device/FrfRequestPlan.h"
#include "core/device/SimulatedDrive.h"
#include "core/device/TestRunner.h"
#include "core/model/MetadataKeys.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <complex>
#include <gtest/gtest.h>

#include "tests/core/device/DriveTestUtil.h"

using namespace axistune;
using namespace axistune::device;

namespace {

/// Forwards everything to a drive but keeps the seam's default readFrequencyResponse (NotFound):
/// a backend that hands raw samples to the host.
class SamplesOnlyDrive : public devtest::ForwardingDrive {
public:
    explicit SamplesOnlyDrive(Drive& inner) : ForwardingDrive(inner) {}
    // The seam's defaults, not the inner drive's: no FRF, no description of itself.
    Result<FrfMeasurement> readFrequencyResponse() override { return Drive::readFrequencyResponse(); }
    Result<DriveCapabilities> capabilities(const std::string& a) override { return Drive::capabilities(a); }
    Result<DriveLimits> limits(const std::string& a) override { return Drive::limits(a); }
    Result<TestPlan> planTest(const TestRequest& r) override { return Drive::planTest(r); }
    Status startTest(const TestRequest& r) override
    {
        ++starts;
        return m_inner.startTest(r);
    }
    Result<TestStatus> pollTest() override
    {
        ++polls;
        if (failAfterPolls >= 0 && polls > failAfterPolls)
            return makeError(ErrorCode::Device, "connection reset by peer (test)");
        if (stallAfterPolls >= 0 && polls > stallAfterPolls)
            return TestStatus{TestState::Running, 0.25, {}};
        if (faultAfterPolls >= 0 && polls > faultAfterPolls)
            return TestStatus{TestState::Faulted, 0.25, "following error too large (test)"};
        return m_inner.pollTest();
    }
    Status abortTest() override
    {
        ++aborts;
        return m_inner.abortTest();
    }
    int starts = 0, polls = 0, aborts = 0;
    int failAfterPolls = -1, stallAfterPolls = -1, faultAfterPolls = -1;
};

TestRequest frfRequest(FrfMethod method)
{
    TestRequest r;
    r.axis = "A";
    auto& frf = r.test.emplace<FrfTest>();
    frf.method = method;
    frf.fminHz = 20.0;
    frf.fmaxHz = 600.0;
    frf.points = 12;
    frf.multisineSpacingHz = 10.0;
    frf.amplitudePct = 5.0;
    return r;
}

/// The same request on two drives of the same preset and seed (the same samples): once evaluated by the
/// drive, once on the host. Tolerance 1e-9 relative (+1e-15 absolute): the same arithmetic on the same
/// samples; only the order of floating-point operations could differ.
void expectHostEqualsDrive(FrfMethod method)
{
    auto a = devtest::makeDrive("two-inertia", 11);
    auto b = devtest::makeDrive("two-inertia", 11);
    const TestRequest r = frfRequest(method);
    auto byDrive = runTest(*a, r);
    ASSERT_TRUE(byDrive.ok()) << byDrive.error().detail;
    SamplesOnlyDrive samples(*b);
    auto byHost = runTest(samples, r);
    ASSERT_TRUE(byHost.ok()) << byHost.error().detail;
    ASSERT_TRUE(byDrive->frf && byHost->frf);
    EXPECT_FALSE(byDrive->frfEvaluatedOnHost);
    EXPECT_TRUE(byHost->frfEvaluatedOnHost);
    EXPECT_EQ(byHost->frf->frf.metadata.text("evaluated_by"), "host");
    const auto& d = byDrive->frf->frf;
    const auto& h = byHost->frf->frf;
    ASSERT_GE(d.size(), 6u);
    ASSERT_EQ(d.size(), h.size());
    std::size_t valid = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
        EXPECT_NEAR(h.freqHz[i], d.freqHz[i], 1e-9 * d.freqHz[i]);
        EXPECT_LE(std::abs(h.h[i] - d.h[i]), 1e-9 * std::abs(d.h[i]) + 1e-15) << d.freqHz[i] << " Hz";
        if (std::isnan(d.coherence[i])) // sine streams carry no coherence
            EXPECT_TRUE(std::isnan(h.coherence[i])) << d.freqHz[i] << " Hz";
        else
            EXPECT_NEAR(h.coherence[i], d.coherence[i], 1e-9) << d.freqHz[i] << " Hz";
        EXPECT_EQ(h.valid[i], d.valid[i]) << d.freqHz[i] << " Hz";
        valid += d.valid[i] ? 1 : 0;
    }
    EXPECT_GE(valid, d.size() / 2); // a measurement, not an empty shell
    EXPECT_NEAR(byHost->frf->motionTimeS, byDrive->frf->motionTimeS, 1e-12);
    EXPECT_EQ(byHost->frf->sweep.blocks.size(), byDrive->frf->sweep.blocks.size());
    EXPECT_EQ(byHost->frf->relativeNoise.size(), byDrive->frf->relativeNoise.size());
    for (std::size_t i = 0; i < byDrive->frf->relativeNoise.size(); ++i)
        EXPECT_NEAR(byHost->frf->relativeNoise[i], byDrive->frf->relativeNoise[i],
                    1e-9 * std::abs(byDrive->frf->relativeNoise[i]) + 1e-15);
}

} // namespace

TEST(TestRunnerHostFrf, MultisineFromSamplesEqualsTheDrivesOwn)
{
    expectHostEqualsDrive(FrfMethod::Multisine);
}
TEST(TestRunnerHostFrf, MultiSweepFromSamplesEqualsTheDrivesOwn)
{
    expectHostEqualsDrive(FrfMethod::MultiSweep);
}
TEST(TestRunnerHostFrf, PrbsFromSamplesEqualsTheDrivesOwn)
{
    expectHostEqualsDrive(FrfMethod::Prbs);
}

// The host plans from the parameters the drive runs with: a trace divider of the request counts.
TEST(TestRunnerHostFrf, RequestTraceDividerIsPartOfTheHostPlan)
{
    auto a = devtest::makeDrive("two-inertia", 5);
    auto b = devtest::makeDrive("two-inertia", 5);
    TestRequest r = frfRequest(FrfMethod::MultiSweep);
    r.traceDivider = 2;
    r.frf().fmaxHz = 400.0;
    auto byDrive = runTest(*a, r);
    SamplesOnlyDrive samples(*b);
    auto byHost = runTest(samples, r);
    ASSERT_TRUE(byDrive.ok() && byHost.ok());
    ASSERT_EQ(byDrive->frf->frf.size(), byHost->frf->frf.size());
    for (std::size_t i = 0; i < byDrive->frf->frf.size(); ++i)
        EXPECT_LE(std::abs(byHost->frf->frf.h[i] - byDrive->frf->frf.h[i]), 1e-9 * std::abs(byDrive->frf->frf.h[i]));
    EXPECT_DOUBLE_EQ(b->simulator("A")->parameter("trace.divider"), 1.0); // restored after the test
}

// Axis clock: the trace rate of the preset is 1/(h·N·D); a velocity period that is not a whole multiple
// of the current period is refused with the keys named.
TEST(TestRunnerHostFrf, AxisClockFromParameters)
{
    auto c = axisClockFromParameters({{"current.period", 62.5e-6}, {"velocity.period", 250e-6}, {"trace.divider", 2}});
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(c->ticksPerVelocity, 4);
    EXPECT_EQ(c->traceDivider, 2);
    EXPECT_DOUBLE_EQ(1.0 / c->tracePeriodS(), 2000.0);
    EXPECT_EQ(axisClockFromParameters({{"current.period", 62.5e-6}, {"velocity.period", 250e-6}}, 3)->traceDivider, 3);
    auto bad =
        axisClockFromParameters({{"current.period", 62.5e-6}, {"velocity.period", 200e-6}, {"trace.divider", 1}});
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().detail.find("velocity.period / current.period"), std::string::npos);
    auto missing = axisClockFromParameters({{"velocity.period", 250e-6}, {"trace.divider", 1}});
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().detail.find("current.period"), std::string::npos);
}

TEST(TestRunner, ProgressNeverFallsAndEndsAtOne)
{
    auto d = devtest::makeDrive("vmc");
    TestRequest r;
    r.axis = "X";
    auto& step = r.test.emplace<StepTest>();
    step.velocityRadS = 10.0;
    step.recordS = 0.2;
    std::vector<double> seen;
    RunOptions o;
    o.progress = [&seen](double f, const std::string&) { seen.push_back(f); };
    auto run = runTest(*d, r, o);
    ASSERT_TRUE(run.ok()) << run.error().detail;
    ASSERT_TRUE(run->trace);
    EXPECT_GT(run->trace->size(), 100u);
    EXPECT_FALSE(run->frf);
    ASSERT_GE(seen.size(), 3u);
    for (std::size_t i = 1; i < seen.size(); ++i)
        EXPECT_GE(seen[i], seen[i - 1]);
    EXPECT_GE(seen.front(), 0.0);
    EXPECT_EQ(seen.back(), 1.0);
}

TEST(TestRunner, AbortBeforeTheStartRunsNothing)
{
    auto inner = devtest::makeDrive("two-inertia");
    SamplesOnlyDrive d(*inner);
    std::atomic<bool> abort{true};
    RunOptions o;
    o.abort = &abort;
    auto run = runTest(d, frfRequest(FrfMethod::MultiSweep), o);
    ASSERT_FALSE(run.ok());
    EXPECT_EQ(run.error().code, ErrorCode::Aborted);
    EXPECT_EQ(d.starts, 0);
    EXPECT_EQ(inner->pollTest()->state, TestState::Idle);
}

// Abort while running: the drive's abortTest restores the parameters from before the test (the request's
// trace divider 2 back to 1) and the run says Aborted.
TEST(TestRunner, AbortWhileRunningRestoresTheParameters)
{
    auto inner = devtest::makeDrive("two-inertia");
    SamplesOnlyDrive d(*inner);
    std::atomic<bool> abort{false};
    TestRequest r = frfRequest(FrfMethod::MultiSweep);
    r.traceDivider = 2;
    RunOptions o;
    o.abort = &abort;
    bool sawDivider2 = false;
    o.progress = [&](double f, const std::string&) {
        sawDivider2 = sawDivider2 || inner->simulator("A")->parameter("trace.divider") == 2.0;
        if (f > 0.2)
            abort = true;
    };
    auto run = runTest(d, r, o);
    ASSERT_FALSE(run.ok());
    EXPECT_EQ(run.error().code, ErrorCode::Aborted);
    EXPECT_TRUE(sawDivider2);
    EXPECT_EQ(d.aborts, 1);
    EXPECT_DOUBLE_EQ(inner->simulator("A")->parameter("trace.divider"), 1.0);
    EXPECT_EQ(inner->pollTest()->state, TestState::Aborted);
}

TEST(TestRunner, LostConnectionIsPassedOnAndTheMotionStopped)
{
    auto inner = devtest::makeDrive("two-inertia");
    SamplesOnlyDrive d(*inner);
    d.failAfterPolls = 3;
    auto run = runTest(d, frfRequest(FrfMethod::MultiSweep));
    ASSERT_FALSE(run.ok());
    EXPECT_EQ(run.error().code, ErrorCode::Device);
    EXPECT_NE(run.error().detail.find("connection reset"), std::string::npos);
    EXPECT_EQ(d.aborts, 1);
    EXPECT_DOUBLE_EQ(inner->simulator("A")->parameter("trace.divider"), 1.0);
}

// A drive that answers but never advances: aborted after the stall timeout (50 ms here) with a Device error
// that names the time.
TEST(TestRunner, StalledDriveTimesOut)
{
    auto inner = devtest::makeDrive("two-inertia");
    SamplesOnlyDrive d(*inner);
    d.stallAfterPolls = 2;
    RunOptions o;
    o.stallTimeout = std::chrono::milliseconds(50);
    o.pollInterval = std::chrono::milliseconds(1);
    auto run = runTest(d, frfRequest(FrfMethod::MultiSweep), o);
    ASSERT_FALSE(run.ok());
    EXPECT_EQ(run.error().code, ErrorCode::Device);
    EXPECT_NE(run.error().detail.find("no progress for 0.05 s"), std::string::npos) << run.error().detail;
    EXPECT_EQ(d.aborts, 1);
}

TEST(TestRunner, FaultIsASafetyStopWithTheDrivesDetail)
{
    auto inner = devtest::makeDrive("two-inertia");
    SamplesOnlyDrive d(*inner);
    d.faultAfterPolls = 2;
    auto run = runTest(d, frfRequest(FrfMethod::MultiSweep));
    ASSERT_FALSE(run.ok());
    EXPECT_EQ(run.error().code, ErrorCode::Safety);
    EXPECT_NE(run.error().detail.find("following error too large"), std::string::npos);
}

TEST(TestRunner, RefusedRequestIsTheDrivesRefusal)
{
    auto d = devtest::makeDrive("two-inertia");
    TestRequest r = frfRequest(FrfMethod::MultiSweep);
    r.axis = "Q";
    auto run = runTest(*d, r);
    ASSERT_FALSE(run.ok());
    EXPECT_EQ(run.error().code, ErrorCode::NotFound);
}

// The machine time of a run (motionTimeS): the drive's own record in the trace's metadata wins over the plan; a
// run without a trace, or whose record is not a number, takes the plan's; without a plan, 0.
TEST(TestRunner, MotionTimeIsTheTracesRecordElseThePlans)
{
    TestPlan p;
    p.motionTimeS = 2.0;
    const Result<TestPlan> plan(p);
    const Result<TestPlan> noPlan(makeError(ErrorCode::NotFound, "no plan (test)"));
    TestRun bare;
    EXPECT_EQ(motionTimeS(bare, plan), 2.0);
    EXPECT_EQ(motionTimeS(bare, noPlan), 0.0);
    EXPECT_EQ(motionTimeS(bare), 0.0);
    TestRun recorded;
    recorded.trace.emplace();
    EXPECT_EQ(motionTimeS(recorded, plan), 2.0); // a trace that records no motion time
    recorded.trace->metadata.set(model::meta::kMotionTimeS, 1.25);
    EXPECT_EQ(motionTimeS(recorded, plan), 1.25);
    EXPECT_EQ(motionTimeS(recorded, noPlan), 1.25);
    EXPECT_EQ(motionTimeS(recorded), 1.25);
    TestRun garbled;
    garbled.trace.emplace();
    garbled.trace->metadata.set("motion_time_s", model::MetadataValue("soon"));
    EXPECT_EQ(motionTimeS(garbled, plan), 2.0);
    EXPECT_EQ(motionTimeS(garbled), 0.0);
}

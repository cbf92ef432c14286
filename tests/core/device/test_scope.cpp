// SPDX-License-Identifier: GPL-3.0-or-later
// The drive's scope on the embedded simulated drive (docs/scope.md): a triggered capture on a known
// velocity step puts the trigger at the requested pre-trigger row, on the step; roll mode streams every
// sample once; requests outside the drive's figures are refused naming the field.
#include "core/device/Scope.h"
#include "core/device/SimulatedDrive.h"
#include "core/device/TestRunner.h"
#include "core/io/CaptureCsv.h"
#include "core/io/ScopeCsv.h"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>

#include "tests/ScopedTempDir.h"
#include "tests/core/device/DriveTestUtil.h"
#include "tests/core/device/ScopeTestUtil.h"

using namespace axistune;
using namespace axistune::device;

namespace {

constexpr double kStepRadS = 10.0; ///< the velocity step of the test
constexpr double kStepDurationS = 0.2;

ScopeRequest stepTrigger(double prePct, int divider, ScopeEdge edge, std::uint64_t length)
{
    ScopeRequest r;
    r.axis = "X";
    r.channels = {"velocity_cmd_rad_s", "t_s", "motor_vel_rad_s"};
    r.divider = divider;
    r.mode = ScopeMode::Single;
    r.triggerChannel = "velocity_cmd_rad_s";
    r.triggerLevel = 0.5 * kStepRadS;
    r.edge = edge;
    r.preTriggerPct = prePct;
    r.lengthSamples = length;
    return r;
}

/// The first velocity period at or after time t0 of an axis with current period h and velDiv current
/// periods per velocity period, as the simulator times its periods (tick · h).
std::uint64_t firstVelocityTickAtOrAfter(double t0, double h, int velDiv)
{
    auto k = static_cast<std::int64_t>(std::floor(t0 / (h * velDiv))) - 2;
    while (static_cast<double>(k * velDiv) * h < t0)
        ++k;
    return static_cast<std::uint64_t>(k);
}

struct StepCapture {
    ScopeCapture capture;
    std::uint64_t expectedTriggerTick = 0; ///< velocity period of the step
};

/// Arms, lets the pre-trigger fill, runs a velocity step and returns the capture.
StepCapture captureStep(SimulatedDrive& drive, const ScopeRequest& r)
{
    StepCapture out;
    EXPECT_TRUE(drive.armScope(r).ok());
    const double fillS =
        static_cast<double>(scopePreTriggerSamples(r.preTriggerPct, r.lengthSamples)) * r.divider / 4000.0;
    for (int i = 0; i < 2 + static_cast<int>(fillS / 0.05); ++i) {
        auto s = drive.pollScope();
        EXPECT_TRUE(s.ok());
    }
    EXPECT_EQ(drive.pollScope()->state, ScopeState::Waiting);
    sim::AxisSimulator* sim = drive.simulator("X");
    const double start = sim->time();
    TestRequest step;
    step.axis = "X";
    auto& stepTest = step.test.emplace<StepTest>();
    stepTest.velocityRadS = kStepRadS;
    stepTest.recordS = kStepDurationS;
    EXPECT_TRUE(runTest(drive, step, {}).ok());
    // The simulated drive steps at 1 % of the record (SimulatedDrive::startTest).
    const double t0 = start + 0.01 * kStepDurationS;
    const int velDiv = static_cast<int>(std::llround(sim->velocityPeriod() / sim->currentPeriod()));
    out.expectedTriggerTick = firstVelocityTickAtOrAfter(t0, sim->currentPeriod(), velDiv);
    // A post-trigger part longer than the step test: the scope's axis runs on in pollScope.
    for (int i = 0; i < 400 && drive.pollScope()->state != ScopeState::Done; ++i) {
    }
    EXPECT_EQ(drive.pollScope()->state, ScopeState::Done);
    auto c = drive.readScopeCapture();
    EXPECT_TRUE(c.ok()) << (c.ok() ? "" : c.error().detail);
    if (c.ok())
        out.capture = std::move(c).value();
    return out;
}

} // namespace

TEST(Scope, CapabilitiesListTheChannelsWithUnits)
{
    auto drive = devtest::makeDrive("vmc", 7);
    auto caps = drive->capabilities("X");
    ASSERT_TRUE(caps.ok());
    EXPECT_TRUE(caps->scope);
    auto s = drive->scopeCapabilities("X");
    ASSERT_TRUE(s.ok());
    // vmc: velocity loop 250 µs → 4 kHz at divider 1 (presets/vmc.json).
    EXPECT_NEAR(s->fastestRateHz, 4000.0, 1e-9);
    bool found = false;
    for (const auto& c : s->channels) {
        EXPECT_FALSE(c.unit.empty()) << c.name;
        if (c.name == "following_error_m") {
            found = true;
            EXPECT_EQ(c.unit, "m");
        }
        if (c.name == "motor_vel_rad_s") {
            EXPECT_EQ(c.unit, "rad/s");
        }
    }
    EXPECT_TRUE(found);
    EXPECT_GE(s->maxChannels, 8);
    auto missing = drive->scopeCapabilities("Q");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().detail.find("'Q'"), std::string::npos);
}

/// Pre-trigger share, divider and edge: the trigger row is exactly round(pct · L / 100) (≤ L − 1), the step is
/// between that row and the one before, and the trigger's sample number is the velocity period of the step
/// divided by the divider (rounded up: the first scope sample at or after the step).
class ScopeTrigger : public ::testing::TestWithParam<std::tuple<double, int, ScopeEdge>> {};

TEST_P(ScopeTrigger, TriggerAtThePreTriggerRowOnTheStep)
{
    const auto [pct, divider, edge] = GetParam();
    auto drive = devtest::makeDrive("vmc", 7);
    const std::uint64_t length = 400;
    const StepCapture sc = captureStep(*drive, stepTrigger(pct, divider, edge, length));
    const ScopeCapture& c = sc.capture;
    ASSERT_EQ(c.rows(), length);
    const auto pre = static_cast<std::size_t>(std::min<double>(std::llround(pct / 100.0 * length), length - 1));
    EXPECT_EQ(c.triggerRow(), pre);
    EXPECT_EQ(c.missingSamples(), 0u);
    for (std::size_t i = 1; i < c.rows(); ++i)
        ASSERT_EQ(c.samples[i], c.samples[i - 1] + 1);
    const auto& v = c.columns[0];
    EXPECT_EQ(v[pre], kStepRadS);
    if (pre > 0) {
        EXPECT_EQ(v[pre - 1], 0.0);
    }
    const std::uint64_t d = static_cast<std::uint64_t>(divider);
    EXPECT_EQ(c.triggerSample, (sc.expectedTriggerTick + d - 1) / d);
    // t_s of every row is its sample number × divider × T_v (the drive's own clock), to 1e-12 s.
    for (std::size_t i = 0; i < c.rows(); ++i)
        ASSERT_NEAR(c.columns[1][i], static_cast<double>(c.samples[i] * d) * 250e-6, 1e-12) << i;
    EXPECT_EQ(c.channels[0].unit, "rad/s");
    EXPECT_EQ(c.channels[1].unit, "s");
}

INSTANTIATE_TEST_SUITE_P(Scope, ScopeTrigger,
                         ::testing::Values(std::tuple{25.0, 1, ScopeEdge::Rising},
                                           std::tuple{0.0, 1, ScopeEdge::Rising},
                                           std::tuple{100.0, 1, ScopeEdge::Either},
                                           std::tuple{50.0, 3, ScopeEdge::Either},
                                           std::tuple{10.0, 2, ScopeEdge::Rising}));

TEST(Scope, FallingEdgeFiresWhereTheStepEndsNotWhereItBegins)
{
    // The step rises 2 ms into the test; when the test ends the drive drops the command back to 0. A falling
    // trigger must fire there: the row before the trigger holds the step, the trigger row 0.
    auto drive = devtest::makeDrive("vmc", 7);
    ASSERT_TRUE(drive->armScope(stepTrigger(20.0, 1, ScopeEdge::Falling, 200)).ok());
    for (int i = 0; i < 3; ++i)
        (void)drive->pollScope();
    const double start = drive->simulator("X")->time();
    TestRequest step;
    step.axis = "X";
    auto& stepTest = step.test.emplace<StepTest>();
    stepTest.velocityRadS = kStepRadS;
    stepTest.recordS = kStepDurationS;
    ASSERT_TRUE(runTest(*drive, step, {}).ok());
    for (int i = 0; i < 4; ++i)
        (void)drive->pollScope();
    auto c = drive->readScopeCapture();
    ASSERT_TRUE(c.ok()) << c.error().detail;
    ASSERT_EQ(c->triggerRow(), 40u);
    EXPECT_EQ(c->columns[0][39], kStepRadS);
    EXPECT_EQ(c->columns[0][40], 0.0);
    // The end of the test: start + 0.2 s, within one velocity period (250 µs).
    EXPECT_NEAR(static_cast<double>(c->triggerSample) * 250e-6, start + kStepDurationS, 250e-6);
}

TEST(Scope, NormalModeReArmsAndKeepsTheLastCapture)
{
    auto drive = devtest::makeDrive("vmc", 7);
    ScopeRequest r = stepTrigger(25.0, 1, ScopeEdge::Rising, 200);
    r.mode = ScopeMode::Normal;
    ASSERT_TRUE(drive->armScope(r).ok());
    TestRequest step;
    step.axis = "X";
    auto& stepTest = step.test.emplace<StepTest>();
    stepTest.velocityRadS = kStepRadS;
    stepTest.recordS = kStepDurationS;
    for (int k = 1; k <= 2; ++k) {
        for (int i = 0; i < 3; ++i)
            (void)drive->pollScope();
        ASSERT_TRUE(runTest(*drive, step, {}).ok());
        for (int i = 0; i < 3; ++i)
            (void)drive->pollScope();
        auto s = drive->pollScope();
        ASSERT_TRUE(s.ok());
        EXPECT_EQ(s->captures, static_cast<std::uint64_t>(k));
        EXPECT_NE(s->state, ScopeState::Done);
        auto c = drive->readScopeCapture();
        ASSERT_TRUE(c.ok());
        EXPECT_EQ(c->number, static_cast<std::uint64_t>(k));
        EXPECT_EQ(c->triggerRow(), 50u);
        EXPECT_EQ(c->columns[0][50], kStepRadS);
        EXPECT_EQ(c->columns[0][49], 0.0);
    }
}

TEST(Scope, RollModeStreamsEverySampleOnce)
{
    auto drive = devtest::makeDrive("vmc", 7);
    ScopeRequest r;
    r.axis = "X";
    r.mode = ScopeMode::Roll;
    r.channels = {"t_s",       "velocity_cmd_rad_s", "motor_vel_rad_s", "torque_cmd_Nm",
                  "current_A", "position_cmd_m",     "table_pos_m",     "following_error_m"};
    ASSERT_TRUE(drive->armScope(r).ok());
    ScopeCapture all;
    all.triggered = false;
    all.columns.assign(r.channels.size(), {});
    std::uint64_t next = 0;
    bool first = true;
    for (int poll = 0; poll < 40; ++poll) { // 40 × 50 ms of machine time
        ASSERT_TRUE(drive->pollScope().ok());
        auto rows = drive->readScopeRows(next, 100000);
        ASSERT_TRUE(rows.ok());
        if (!first) {
            ASSERT_EQ(rows->firstSample, next) << "samples lost";
        }
        first = false;
        appendScopeRows(all, *rows);
        next = rows->firstSample + rows->rows;
    }
    // 2 s at 4 kHz: 8000 velocity periods run, every one a row (the slices are whole current periods).
    EXPECT_EQ(all.rows(), 8000u);
    EXPECT_EQ(all.missingSamples(), 0u);
    for (std::size_t i = 1; i < all.rows(); ++i)
        ASSERT_EQ(all.samples[i], all.samples[i - 1] + 1);
    for (std::size_t i = 0; i < all.rows(); ++i)
        ASSERT_NEAR(all.columns[0][i], static_cast<double>(all.samples[i]) * 250e-6, 1e-12);
    EXPECT_EQ(drive->pollScope()->state, ScopeState::Rolling);
    ASSERT_TRUE(drive->stopScope().ok());
    EXPECT_EQ(drive->pollScope()->state, ScopeState::Idle);
}

TEST(Scope, RequestsOutsideTheDrivesFiguresAreRefusedNamingTheField)
{
    auto drive = devtest::makeDrive("vmc", 7);
    auto refused = [&](const ScopeRequest& r, const std::string& words) {
        auto st = drive->armScope(r);
        ASSERT_FALSE(st.ok()) << words;
        EXPECT_NE(st.error().detail.find(words), std::string::npos) << st.error().detail;
    };
    ScopeRequest r = stepTrigger(25.0, 1, ScopeEdge::Rising, 400);
    ScopeRequest bad = r;
    bad.channels.push_back("nonsense");
    refused(bad, "scope channel 'nonsense' is not traceable on axis X (channels: t_s, velocity_cmd_rad_s");
    bad = r;
    bad.preTriggerPct = 101.0;
    refused(bad, "pre-trigger 101 % outside 0..100 %");
    bad = r;
    bad.triggerChannel = "current_A";
    refused(bad, "trigger channel 'current_A' is not one of the traced channels");
    bad = r;
    bad.divider = 0;
    refused(bad, "scope divider 0 outside 1..");
    bad = r;
    bad.lengthSamples = 1ull << 40;
    refused(bad, "scope length 1099511627776 samples outside 2..");
    bad = r;
    bad.triggerLevel = std::nan("");
    refused(bad, "trigger level must be finite");
    bad = r;
    bad.channels = {"t_s", "t_s"};
    bad.triggerChannel = "t_s";
    refused(bad, "given twice");
}

TEST(Scope, ABackendWithoutAScopeSaysSo)
{
    // The seam's default (the replay backend keeps it): refused with NotFound, capabilities say no scope.
    struct NoScope : Drive {
        Result<DriveIdentity> identify() override { return DriveIdentity{}; }
        Result<std::vector<model::ParameterMeta>> parameterMetadata(const std::string&) override
        {
            return std::vector<model::ParameterMeta>{};
        }
        Result<model::ParameterValues> readParameters(const std::string&, std::span<const std::string>) override
        {
            return model::ParameterValues{};
        }
        Status writeParameters(const std::string&, const model::ParameterValues&) override { return Status::success(); }
        Status startTest(const TestRequest&) override { return Status::success(); }
        Result<TestStatus> pollTest() override { return TestStatus{}; }
        Result<model::Capture> readTrace() override { return model::Capture{}; }
        Status abortTest() override { return Status::success(); }
    } d;
    ScopeRequest r = stepTrigger(25.0, 1, ScopeEdge::Rising, 400);
    auto st = d.armScope(r);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::NotFound);
    EXPECT_EQ(st.error().detail, "this drive has no scope (axis X)");
    EXPECT_FALSE(DriveCapabilities{}.scope);
}

TEST(ScopeRecorder, TheRingKeepsTheNewestRowsAndTellsWhatWasOverwritten)
{
    ScopeSetup s;
    s.channels = {0, 1};
    s.mode = ScopeMode::Roll;
    s.rateHz = 1000.0;
    ScopeRecorder rec;
    rec.arm(s, 10);
    for (std::uint64_t n = 100; n < 125; ++n) {
        const double row[] = {static_cast<double>(n), -static_cast<double>(n)};
        rec.push(n, row);
    }
    const ScopeStatus st = rec.status();
    EXPECT_EQ(st.nextSample, 125u);
    EXPECT_EQ(st.oldestSample, 115u);
    const ScopeRows r = rec.rows(100, 1000); // rows 100..114 were overwritten
    EXPECT_EQ(r.firstSample, 115u);
    ASSERT_EQ(r.rows, 10u);
    for (std::size_t i = 0; i < r.rows; ++i) {
        EXPECT_EQ(r.values[2 * i], 115.0 + static_cast<double>(i));
        EXPECT_EQ(r.values[2 * i + 1], -115.0 - static_cast<double>(i));
    }
    EXPECT_EQ(rec.rows(125, 10).rows, 0u);
}

TEST(ScopeRecorder, PreTriggerSamplesRoundAndStayInsideTheCapture)
{
    EXPECT_EQ(scopePreTriggerSamples(0.0, 400), 0u);
    EXPECT_EQ(scopePreTriggerSamples(25.0, 400), 100u);
    EXPECT_EQ(scopePreTriggerSamples(33.3, 10), 3u);
    EXPECT_EQ(scopePreTriggerSamples(35.0, 10), 4u); // 3.5 rounds away from zero
    EXPECT_EQ(scopePreTriggerSamples(100.0, 400), 399u);
}

TEST(ScopeCsv, ACaptureReloadsIdenticalFromItsCsv)
{
    // Every traceable channel of a triggered capture and of a roll record, written as the CLI writes it and
    // read back: the same sample numbers, rate and every value bit for bit (shortest round-trip text).
    auto drive = devtest::makeDrive("vmc", 7);
    auto caps = drive->scopeCapabilities("X");
    ASSERT_TRUE(caps.ok());
    ScopeRequest r = stepTrigger(25.0, 1, ScopeEdge::Rising, 400);
    r.channels.clear();
    for (const auto& c : caps->channels)
        if (c.name.find('.') == std::string::npos) // X's own channels, not the other axes' ("Y.table_pos_m")
            r.channels.push_back(c.name);
    const StepCapture sc = captureStep(*drive, r);
    ScopeRequest roll;
    roll.axis = "X";
    roll.mode = ScopeMode::Roll;
    roll.channels = {"following_error_m", "motor_vel_rad_s"};
    ASSERT_TRUE(drive->armScope(roll).ok());
    ASSERT_TRUE(drive->pollScope().ok());
    auto rows = drive->readScopeRows(0, 1000);
    ASSERT_TRUE(rows.ok());
    ScopeCapture rolled;
    rolled.triggered = false;
    rolled.rateHz = 4000.0;
    rolled.channels = {caps->channels[14], caps->channels[2]};
    rolled.columns.assign(2, {});
    appendScopeRows(rolled, *rows);
    ASSERT_EQ(rolled.rows(), 200u); // one 50 ms slice at 4 kHz

    const axistune::testing::ScopedTempDir dir("scope-csv-test");
    for (const ScopeCapture* c : std::initializer_list<const ScopeCapture*>{&sc.capture, &rolled}) {
        const auto path = (dir / "scope.csv").string();
        ASSERT_TRUE(io::writeCaptureCsvFile(path, scopeCaptureToTable(*c, "X", {{"connection", "sim:vmc"}})).ok());
        auto t = io::readScopeCsvFile(path);
        ASSERT_TRUE(t.ok()) << t.error().detail;
        EXPECT_EQ(t->fsHz, c->rateHz);
        EXPECT_EQ(t->samples, c->samples);
        EXPECT_EQ(t->missingSamples, 0u);
        ASSERT_EQ(t->capture.channels.size(), c->channels.size() + 1);
        EXPECT_EQ(t->capture.channels[0].name, "sample");
        for (std::size_t k = 0; k < c->channels.size(); ++k) {
            EXPECT_EQ(t->capture.channels[k + 1].name, c->channels[k].name);
            EXPECT_EQ(t->capture.metadata.text("unit." + c->channels[k].name), c->channels[k].unit);
            ASSERT_EQ(t->capture.channels[k + 1].data, c->columns[k]) << c->channels[k].name;
        }
        if (c->triggered) {
            EXPECT_EQ(t->capture.metadata.number("trigger_row").value(), 100.0);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Two axes in one scope: X against Y of a circle.

namespace {

/// A circle in the X–Y plane of vmc (R 50 mm at 1000 mm/min about (0, 0.1 m)), as the ball-bar tests run it.
TestRequest circleXY()
{
    TestRequest r;
    auto& circle = r.test.emplace<CircleTest>();
    r.axis = "X";
    circle.secondAxis = "Y";
    circle.radiusM = 0.05;
    circle.feedMPerS = 1000.0 / 60000.0;
    circle.centerXM = 0.0;
    circle.centerYM = 0.1;
    circle.dwellS = 0.1;
    return r;
}

/// Rolls the scope while the test runs to its end; returns every row and the test's trace.
std::pair<ScopeCapture, model::Capture> rollDuring(SimulatedDrive& drive, const ScopeRequest& r, const TestRequest& t)
{
    std::pair<ScopeCapture, model::Capture> out;
    ScopeCapture& all = out.first;
    all.triggered = false;
    all.columns.assign(r.channels.size(), {});
    EXPECT_TRUE(drive.armScope(r).ok());
    // The scope axes run a while before the test (they hold), then the test moves them.
    for (int i = 0; i < 3; ++i)
        EXPECT_TRUE(drive.pollScope().ok());
    EXPECT_TRUE(drive.startTest(t).ok());
    std::uint64_t next = 0;
    bool started = false;
    for (int i = 0; i < 100000; ++i) {
        auto s = drive.pollTest();
        EXPECT_TRUE(s.ok());
        EXPECT_TRUE(drive.pollScope().ok());
        auto rows = drive.readScopeRows(next, 1u << 20);
        EXPECT_TRUE(rows.ok());
        if (!rows.ok() || !s.ok())
            break;
        if (started) {
            EXPECT_EQ(rows->firstSample, next) << "samples lost";
        }
        started = true;
        appendScopeRows(all, *rows);
        next = rows->firstSample + rows->rows;
        if (s->state != TestState::Running) {
            EXPECT_EQ(s->state, TestState::Completed) << s->detail;
            break;
        }
    }
    auto trace = drive.readTrace();
    EXPECT_TRUE(trace.ok());
    if (trace.ok())
        out.second = *trace;
    return out;
}

} // namespace

TEST(Scope, OtherAxesPositionsAreOfferedAsCompanionChannels)
{
    auto drive = devtest::makeDrive("vmc", 7);
    auto s = drive->scopeCapabilities("X");
    ASSERT_TRUE(s.ok());
    // vmc has X, Y and Z on one clock: X's 15 signals, then 4 of Y and 4 of Z (positions and following error).
    const std::vector<std::string> companions = {"Y.position_cmd_m",    "Y.motor_pos_m",      "Y.table_pos_m",
                                                 "Y.following_error_m", "Z.position_cmd_m",   "Z.motor_pos_m",
                                                 "Z.table_pos_m",       "Z.following_error_m"};
    ASSERT_EQ(s->channels.size(), 15u + companions.size());
    for (std::size_t k = 0; k < companions.size(); ++k) {
        EXPECT_EQ(s->channels[15 + k].name, companions[k]);
        EXPECT_EQ(s->channels[15 + k].unit, "m");
    }
    // A machine with one axis offers none.
    auto dd = devtest::makeDrive("dd-table", 7);
    auto c = dd->scopeCapabilities("C");
    ASSERT_TRUE(c.ok());
    for (const auto& ch : c->channels)
        EXPECT_EQ(ch.name.find('.'), std::string::npos) << ch.name;
}

// The XY of a circle: X's and Y's table positions from one scope, row by row at one instant. The circle test's
// own trace (CircleRun, both axes read after each position period) is the independent reference: at every trace
// sample the scope row holding the same X position holds the same Y position. One velocity period of skew between
// the axes would move Y by v·T_v = 16.7 mm/s · 250 µs = 4.2 µm at this feed.
TEST(Scope, TwoAxesInOneScopeDrawTheCircleAtOneInstant)
{
    auto drive = devtest::makeDrive("vmc", 7);
    // Y runs ahead of X before the scope is armed: arming must bring them to one machine time.
    ASSERT_TRUE(drive
                    ->armScope([] {
                        ScopeRequest r;
                        r.axis = "Y";
                        r.mode = ScopeMode::Roll;
                        r.channels = {"t_s"};
                        return r;
                    }())
                    .ok());
    for (int i = 0; i < 5; ++i)
        ASSERT_TRUE(drive->pollScope().ok());
    ASSERT_TRUE(drive->stopScope().ok());

    ScopeRequest r;
    r.axis = "X";
    r.mode = ScopeMode::Roll;
    r.channels = {"t_s", "table_pos_m", "Y.table_pos_m", "position_cmd_m", "Y.position_cmd_m"};
    auto [scope, trace] = rollDuring(*drive, r, circleXY());
    ASSERT_GT(scope.rows(), 40000u); // 2π · 50 mm at 16.7 mm/s ≈ 18.8 s at 4 kHz, plus positioning
    EXPECT_EQ(scope.missingSamples(), 0u);
    for (std::size_t i = 1; i < scope.rows(); ++i)
        ASSERT_EQ(scope.samples[i], scope.samples[i - 1] + 1);
    for (std::size_t i = 0; i < scope.rows(); ++i) // X's machine time: 250 µs per sample
        ASSERT_NEAR(scope.columns[0][i], static_cast<double>(scope.samples[i]) * 250e-6, 1e-9);

    const auto* tx = trace.channel("X.table_pos_m");
    const auto* ty = trace.channel("Y.table_pos_m");
    ASSERT_NE(tx, nullptr);
    ASSERT_NE(ty, nullptr);
    const auto& sx = scope.columns[1];
    const auto& sy = scope.columns[2];
    // The trace takes one row per position period (its fs_Hz), the scope one per velocity period (4 kHz).
    const auto same = axistune::testing::sameInstant(sx, sy, *tx, *ty, trace.metadata.number("fs_Hz").value());
    ASSERT_TRUE(same.found) << same.report;
    EXPECT_EQ(same.worstY, 0.0) << "Y at the instant of X [m]";

    // The XY is the circle: every row after the positioning lies on R = 50 mm about (0, 0.1 m) within the
    // commanded path's own radius error plus the ball-bar's deviation of the trace (computed from the trace).
    double traceDev = 0.0;
    for (std::size_t k = 0; k < tx->data.size(); ++k)
        traceDev = std::max(traceDev, std::abs(std::hypot(tx->data[k], ty->data[k] - 0.1) - 0.05));
    std::size_t onCircle = 0;
    for (std::size_t i = 0; i < sx.size(); ++i) {
        const double rr = std::hypot(sx[i], sy[i] - 0.1);
        if (std::abs(rr - 0.05) <= traceDev + 1e-9)
            ++onCircle;
    }
    EXPECT_GT(onCircle, tx->data.size()); // the whole circle at 4 kHz holds more rows than the trace (1 kHz)
    ASSERT_TRUE(drive->stopScope().ok());
}

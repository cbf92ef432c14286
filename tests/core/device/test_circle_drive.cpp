// SPDX-License-Identifier: GPL-3.0-or-later
// The circle test through the drive seam (TestType::Circle, core/device/CircleDriveTest.h): on the
// embedded simulated drive against sim::runCircleTest, the lost motion it implies against the preset's
// plant (resources/machines/vmc.json), the refused requests, abort, and the same circle over Modbus
// against axistune-simdrive's server (in-process, loopback) against the embedded drive.
#include "core/device/CircleDriveTest.h"
#include "core/device/ModbusDrive.h"
#include "core/sim/CircleRun.h"
#include "core/tuning/LostMotion.h"
#include "tests/core/device/DriveTestUtil.h"
#include "tests/core/device/ServerThread.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace axistune;
using namespace axistune::device;

namespace {

TestRequest circle(const std::string& first, const std::string& second, double cx, double cy)
{
    TestRequest r;
    auto& c = r.test.emplace<CircleTest>();
    r.axis = first;
    c.secondAxis = second;
    c.radiusM = 0.05;
    c.feedMPerS = 1000.0 / 60000.0;
    c.centerXM = cx;
    c.centerYM = cy;
    c.dwellS = 0.1;
    return r;
}

/// Runs the test to its end (progress never falls) and returns the trace.
model::Capture runToEnd(Drive& d, const TestRequest& r)
{
    auto st = d.startTest(r);
    EXPECT_TRUE(st.ok()) << (st.ok() ? "" : st.error().detail);
    double progress = 0.0;
    for (int i = 0; i < 1000000; ++i) {
        auto s = d.pollTest();
        EXPECT_TRUE(s.ok()) << (s.ok() ? "" : s.error().detail);
        if (!s.ok())
            break;
        EXPECT_GE(s->progress, progress);
        progress = s->progress;
        if (s->state != TestState::Running) {
            EXPECT_EQ(s->state, TestState::Completed) << s->detail;
            break;
        }
    }
    auto t = d.readTrace();
    EXPECT_TRUE(t.ok()) << (t.ok() ? "" : t.error().detail);
    return t.ok() ? *t : model::Capture{};
}

double preset(const std::string& axis, const std::string& key)
{
    auto m = sim::loadPreset("vmc");
    return m->axis(axis)->values.at(key);
}

}  // namespace

// The drive's circle and runCircleTest command the same path sample by sample (CirclePath: same arc
// s(t) from the start of the command, same parameters, same loop code), so their ball-bar traces differ
// only by the state the drive's axes bring along (they position to the start point first; runCircleTest
// resets them there) and the realisation of the measurement noise, both well below the lost motion.
TEST(CircleDrive, RequestOfACircleCarriesEveryDriveField)
{
    sim::CircleTestOptions o;
    o.axisX = "Y";
    o.axisY = "Z";
    o.radiusM = 0.075;
    o.feedMPerS = 0.025;
    o.direction = model::CircleDirection::Cw;
    o.centerXM = -0.01;
    o.centerYM = 0.12;
    o.dataStartDeg = 30.0;
    o.leadArcDeg = 60.0;
    o.dwellS = 0.2;
    const TestRequest r = circleRequestOf(o);
    EXPECT_EQ(r.type(), TestType::Circle);
    const sim::CircleTestOptions back = circleOptionsOf(r);
    EXPECT_EQ(back.axisX, "Y");
    EXPECT_EQ(back.axisY, "Z");
    EXPECT_EQ(back.radiusM, 0.075);
    EXPECT_EQ(back.feedMPerS, 0.025);
    EXPECT_EQ(back.direction, model::CircleDirection::Cw);
    EXPECT_EQ(back.centerXM, -0.01);
    EXPECT_EQ(back.centerYM, 0.12);
    EXPECT_EQ(back.dataStartDeg, 30.0);
    EXPECT_EQ(back.leadArcDeg, 60.0);
    EXPECT_EQ(back.dwellS, 0.2);
}

TEST(CircleDrive, EmbeddedCircleIsTheSimulatedCircleTest)
{
    auto drive = devtest::makeDrive("vmc", 1);
    const TestRequest req = circle("X", "Y", 0.0, 0.1);
    const model::Capture trace = runToEnd(*drive, req);
    for (const char* ch : {"t_s", "arc_rad", "X.position_cmd_m", "X.table_pos_m", "X.torque_cmd_Nm", "X.torque_Nm",
                           "Y.position_cmd_m", "Y.table_pos_m", "Y.torque_cmd_Nm", "Y.torque_Nm"})
        EXPECT_NE(trace.channel(ch), nullptr) << ch;
    auto viaDrive = sim::ballBarFromCircleTrace(trace);
    ASSERT_TRUE(viaDrive.ok()) << viaDrive.error().detail;

    sim::CircleTestOptions o = circleOptionsOf(req);
    o.seed = 1;
    auto direct = sim::runCircleTest(*sim::loadPreset("vmc"), o);
    ASSERT_TRUE(direct.ok()) << direct.error().detail;
    const auto& a = *viaDrive;
    const auto& b = direct->ballbar;
    ASSERT_GT(b.size(), 10000u);
    // The same samples of the data arc: at most one dropped by the strict-monotonic rule either way.
    ASSERT_LE(std::max(a.size(), b.size()) - std::min(a.size(), b.size()), 1u);
    EXPECT_NEAR(a.angleRad.front(), b.angleRad.front(), 1e-5);  // 0.5 µm at R 50 mm
    double maxDiff = 0.0, sum2 = 0.0, maxAt = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0, j = 0; i < a.size() && j < b.size(); ++i, ++j) {
        if (std::abs(a.angleRad[i] - b.angleRad[j]) > 1e-4) {  // a sample dropped on one side: realign
            (a.angleRad[i] - b.angleRad[j]) * a.directionSign() > 0 ? --i : --j;
            continue;
        }
        const double d = std::abs(a.deviationM[i] - b.deviationM[j]);
        if (d > maxDiff)
            maxDiff = d, maxAt = a.angleRad[i];
        sum2 += d * d;
        ++n;
    }
    const double rmsDiff = std::sqrt(sum2 / static_cast<double>(n));

    std::printf("drive vs runCircleTest over %zu samples: rms %.4f um, max %.4f um at %.1f deg; dTx %.4f/%.4f, "
                "dTy %.4f/%.4f N m\n",
                n, rmsDiff * 1e6, maxDiff * 1e6, maxAt * 180.0 / std::numbers::pi, *a.dTxNm, *b.dTxNm, *a.dTyNm, *b.dTyNm);
    // Noise-level differences: rms 0.1 µm; the largest sits in a friction reversal spike (7.5 µm high,
    // about 1° wide, whose exact shape follows the noise), bounded by 0.5 µm. The Y reversal step at
    // cy = 100 mm is (0.70 + 17·0.3)·0.61 ≈ 3.5 µm.
    EXPECT_LT(rmsDiff, 0.1e-6);
    EXPECT_LT(maxDiff, 0.5e-6);
    EXPECT_NEAR(*a.dTxNm, *b.dTxNm, 0.01 * *b.dTxNm);
    EXPECT_NEAR(*a.dTyNm, *b.dTyNm, 0.01 * *b.dTyNm);
    // The axes stay where the circle ended (the drive's state carries on).
    auto path = sim::CirclePath::plan(o);
    EXPECT_NEAR(drive->simulator("X")->positionCommand(), path->endPosition(false), 1e-12);
    EXPECT_NEAR(drive->simulator("Y")->positionCommand(), path->endPosition(true), 1e-12);
}

// Three circles along Y through the drive, read as a ball bar and fitted (spec §4.3, LM-1/LM-2): A and
// B of Y within 10 % of the plant's lost_motion_A/B (vmc: 0.70 µm/(N·m), 17 µm/(N·m·m), x₀ = 200 mm).
TEST(CircleDrive, CirclesAlongYGiveThePresetLostMotion)
{
    auto drive = devtest::makeDrive("vmc", 2);
    std::vector<tuning::LostMotionPoint> points;
    const tuning::LostMotionSetup setup{1, preset("Y", "plant.screw_offset"), 1.0};
    tuning::BallBarOptions opt;
    opt.excludeDeg = 8.0;  // as the wizard: the friction spike leaves an apparent step at ±4° (ballbar.md)
    for (double cy : {-0.15, 0.0, 0.15}) {
        auto bb = sim::ballBarFromCircleTrace(runToEnd(*drive, circle("X", "Y", 0.0, cy)));
        ASSERT_TRUE(bb.ok()) << bb.error().detail;
        auto p = tuning::extractLostMotionPoints(*bb, setup, opt);
        ASSERT_TRUE(p.ok()) << p.error().detail;
        points.insert(points.end(), p->begin(), p->end());
    }
    auto fit = tuning::fitLostMotion(points);
    ASSERT_TRUE(fit.ok()) << fit.error().detail;
    const double a = preset("Y", "plant.lost_motion_A"), b = preset("Y", "plant.lost_motion_B");
    std::printf("A %.4f um/(N m) (plant %.2f), B %.3f um/(N m m) (plant %.1f)\n", fit->aMPerNm * 1e6, a * 1e6,
                fit->bPerNm * 1e6, b * 1e6);
    EXPECT_NEAR(fit->aMPerNm, a, 0.10 * a);
    EXPECT_NEAR(fit->bPerNm, b, 0.10 * b);
}

TEST(CircleDrive, UnsafeOrMalformedCirclesAreRefusedBeforeAnyMotion)
{
    auto drive = devtest::makeDrive("vmc", 1);
    const double x0 = drive->simulator("X")->positionCommand(), y0 = drive->simulator("Y")->positionCommand();
    struct Case {
        const char* what;
        TestRequest r;
        ErrorCode code;
        const char* mention;
    };
    std::vector<Case> cases;
    cases.push_back({"same axis twice", circle("X", "X", 0, 0), ErrorCode::BadInput, "two different axes"});
    cases.push_back({"no second axis", circle("X", "", 0, 0), ErrorCode::BadInput, "second plane axis"});
    cases.push_back({"unknown second axis", circle("X", "Q", 0, 0), ErrorCode::NotFound, "'Q'"});
    auto far = circle("X", "Y", 0.0, 0.47);
    cases.push_back({"outside the travel window", far, ErrorCode::OutOfRange, "axis Y"});
    auto fast = circle("X", "Y", 0, 0);
    fast.circle().feedMPerS = 10.0; // 10 m/s with a 12 mm lead: 5236 rad/s at the motor
    cases.push_back({"feed above the speed limit", fast, ErrorCode::OutOfRange, "speed limit"});
    auto slow = circle("X", "Y", 0, 0);
    slow.circle().feedMPerS = 1e-4; // 6 mm/min: a 50 mm circle takes over 50 min
    cases.push_back({"too long", slow, ErrorCode::OutOfRange, "raise the feed"});
    auto noRadius = circle("X", "Y", 0, 0);
    noRadius.circle().radiusM = 0.0;
    cases.push_back({"no radius", noRadius, ErrorCode::BadInput, "radius"});
    auto nanCentre = circle("X", "Y", 0, 0);
    nanCentre.circle().centerXM = std::nan("");
    cases.push_back({"NaN centre", nanCentre, ErrorCode::BadInput, "centre"});
    for (const auto& c : cases) {
        auto st = drive->startTest(c.r);
        ASSERT_FALSE(st.ok()) << c.what;
        EXPECT_EQ(st.error().code, c.code) << c.what << ": " << st.error().detail;
        EXPECT_NE(st.error().detail.find(c.mention), std::string::npos) << c.what << ": " << st.error().detail;
        auto s = drive->pollTest();
        ASSERT_TRUE(s.ok());
        EXPECT_NE(s->state, TestState::Running) << c.what;
    }
    EXPECT_EQ(drive->simulator("X")->positionCommand(), x0);
    EXPECT_EQ(drive->simulator("Y")->positionCommand(), y0);
    // A rotary axis is no plane axis (dd-table: its table axis is rotary).
    auto dd = devtest::makeDrive("dd-table", 1);
    auto id = dd->identify();
    ASSERT_TRUE(id.ok());
    ASSERT_FALSE(id->axes.empty());
    auto st = dd->startTest(circle(id->axes.front(), id->axes.size() > 1 ? id->axes[1] : "X", 0, 0));
    EXPECT_FALSE(st.ok());
}

TEST(CircleDrive, AbortStopsBothAxesAndRestoresTheirParameters)
{
    auto drive = devtest::makeDrive("vmc", 1);
    auto before = drive->readParameters("Y", {});
    ASSERT_TRUE(before.ok());
    drive->setSliceSeconds(0.5);
    ASSERT_TRUE(drive->startTest(circle("X", "Y", 0.0, 0.0)).ok());
    for (int i = 0; i < 10; ++i)
        ASSERT_TRUE(drive->pollTest().ok());
    auto busy = drive->writeParameters("Y", {{"position.kp", 20.0}});
    EXPECT_FALSE(busy.ok());
    EXPECT_EQ(busy.error().code, ErrorCode::Busy);
    EXPECT_TRUE(drive->startTest(circle("X", "Y", 0.0, 0.0)).error().code == ErrorCode::Busy);
    ASSERT_TRUE(drive->abortTest().ok());
    auto s = drive->pollTest();
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->state, TestState::Aborted);
    EXPECT_GT(s->progress, 0.0);
    EXPECT_LT(s->progress, 1.0);
    EXPECT_FALSE(drive->readTrace().ok());  // no trace of an aborted circle
    auto after = drive->readParameters("Y", {});
    ASSERT_TRUE(after.ok());
    EXPECT_EQ(*after, *before);
    // Both axes were stopped where they were: a hold test on either ends at rest within the stopping
    // distance of the feed (16.7 mm/s over the velocity loop's few ms: well under 0.2 mm).
    for (const char* axis : {"X", "Y"}) {
        TestRequest hold;
        hold.axis = axis;
        hold.test = HoldTest{0.3};
        const double p0 = drive->simulator(axis)->tablePosition();
        runToEnd(*drive, hold);
        EXPECT_NEAR(drive->simulator(axis)->tablePosition(), p0, 2e-4) << axis;
        EXPECT_LT(std::abs(drive->simulator(axis)->motorVelocity()), 0.05) << axis;
    }
}

// Over Modbus the trace is float64 page by page: the circle of axistune-simdrive's server is the
// embedded drive's circle with the same seed bit for bit.
TEST(CircleDrive, CircleOverModbusIsTheEmbeddedCircle)
{
    device::SimDriveServerOptions so;
    so.preset = "vmc";
    so.seed = 7;
    devtest::ServerThread srv(so);
    auto remote = connectAny({srv.uri(), 7});
    ASSERT_TRUE(remote.ok()) << remote.error().detail;
    auto local = connectAny({"sim:vmc", 7});
    ASSERT_TRUE(local.ok());
    TestRequest req = circle("X", "Y", 0.05, -0.1);
    req.circle().direction = model::CircleDirection::Cw;
    req.circle().feedMPerS = 3000.0 / 60000.0;
    const model::Capture tr = runToEnd(**remote, req);
    const model::Capture tl = runToEnd(**local, req);
    ASSERT_EQ(tr.channels.size(), tl.channels.size());
    ASSERT_GT(tl.size(), 1000u);
    EXPECT_EQ(tr.metadata, tl.metadata);
    for (std::size_t c = 0; c < tl.channels.size(); ++c) {
        EXPECT_EQ(tr.channels[c].name, tl.channels[c].name);
        EXPECT_EQ(tr.channels[c].data, tl.channels[c].data) << tl.channels[c].name;
    }
    auto br = sim::ballBarFromCircleTrace(tr);
    ASSERT_TRUE(br.ok()) << br.error().detail;
    EXPECT_EQ(br->direction, model::CircleDirection::Cw);
    EXPECT_NEAR(br->centerXM, 0.05, 1e-15);

    // The server refuses by its own limits, with its message passed on.
    auto far = circle("X", "Y", 0.0, 0.47);
    auto st = (*remote)->startTest(far);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::OutOfRange);
    EXPECT_NE(st.error().detail.find("travel window"), std::string::npos) << st.error().detail;
    auto same = circle("Y", "Y", 0.0, 0.0);
    st = (*remote)->startTest(same);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().detail.find("another axis"), std::string::npos) << st.error().detail;

    // Abort over Modbus stops the circle (a slow one: 100 mm/min, over 3 min of machine time).
    auto slow = circle("X", "Y", 0.0, 0.0);
    slow.circle().feedMPerS = 100.0 / 60000.0;
    ASSERT_TRUE((*remote)->startTest(slow).ok());
    auto s = (*remote)->pollTest();
    ASSERT_TRUE(s.ok());
    ASSERT_TRUE((*remote)->abortTest().ok());
    s = (*remote)->pollTest();
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->state, TestState::Aborted) << s->detail;
}

// A new client continues the drive's command tokens: its first start_test is executed, not taken for
// a repeat of the previous client's last command (which had the same token before the fix).
TEST(CircleDrive, ASecondClientsFirstTestIsExecuted)
{
    device::SimDriveServerOptions so;
    so.preset = "vmc";
    devtest::ServerThread srv(so);
    for (double cy : {-0.1, 0.1}) {
        auto client = connectAny({srv.uri(), 1});
        ASSERT_TRUE(client.ok()) << client.error().detail;
        auto trace = runToEnd(**client, circle("X", "Y", 0.0, cy));
        auto bb = sim::ballBarFromCircleTrace(trace);
        ASSERT_TRUE(bb.ok()) << bb.error().detail;
        EXPECT_NEAR(bb->centerYM, cy, 1e-15);
        const auto* y = trace.channel("Y.position_cmd_m");
        ASSERT_TRUE(y && !y->data.empty());
        // The path ends at 45° − 90° + 90° + 360° + 90° = 135° (lead-in, data arc, lead-out).
        EXPECT_NEAR(y->data.back(), cy + 0.05 * std::sin(0.75 * std::numbers::pi), 1e-9);
    }
}

// The server watches a running circle: with a following-error limit of 1 µm the first check, 50 ms
// into the move to the start point (accelerating at 0.5 m/s²: about 19 µm of following error),
// trips; the test faults with the server's message and leaves no trace.
TEST(CircleDrive, ServerTripsARunningCircle)
{
    device::SimDriveServerOptions so;
    so.preset = "vmc";
    so.safety.followingErrorLimit = 1e-6;
    devtest::ServerThread srv(so);
    auto client = connectAny({srv.uri(), 1});
    ASSERT_TRUE(client.ok()) << client.error().detail;
    ASSERT_TRUE((*client)->startTest(circle("X", "Y", 0.0, 0.1)).ok());
    Result<TestStatus> s = makeError(ErrorCode::Internal, "not polled");
    for (int i = 0; i < 100000; ++i) {
        s = (*client)->pollTest();
        if (!s || s->state != TestState::Running)
            break;
    }
    ASSERT_TRUE(s.ok()) << s.error().detail;
    EXPECT_EQ(s->state, TestState::Faulted);
    EXPECT_NE(s->detail.find("following error"), std::string::npos) << s->detail;
    EXPECT_FALSE((*client)->readTrace().ok());
}

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The drive conformance suite's rules (issue 16 item 5, docs/drive-seam.md "The conformance suite"): one
// parameterised suite every registered backend must pass. This header holds the fixture and the TEST_P rules; a
// test executable includes it in exactly one source file and instantiates it for its backends:
//   tests/conformance/test_drive_conformance.cpp   sim, modbus, replay
//   tests/linuxcnc/test_hal_conformance.cpp        hal (a HAL session of scripts/hal-testbed, one at a time)
// Backends:
//   sim     the embedded simulated drive, "sim:vmc" (seed 7),
//   modbus  a real axistune-simdrive child process on a free loopback port, "--preset vmc --seed 7",
//   replay  a capture of a step test recorded from sim:vmc, "replay:FILE",
//   hal     LinuxCNC's pid around AxisTune's plant component, started for each rule (scripts/hal-testbed).
// A rule is skipped only when the backend's own capabilities say it does not offer what the rule
// needs; the skip names the rule and the capability and is reported by ctest as skipped, never passed.
#include "core/device/Drive.h"
#include "core/device/DriveRegistry.h"
#include "core/io/CaptureCsv.h"
#include "core/model/MetadataKeys.h"

#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <gtest/gtest.h>
#include <iostream>
#include <limits>
#include <memory>
#include <set>
#include <thread>

#include "tests/app/cli/SimDriveProcess.h"
#include "tests/linuxcnc/HalMachineLock.h"

namespace axistune::device {
namespace {

constexpr std::uint64_t kSeed = 7;
using Clock = std::chrono::steady_clock;

std::string errorText(const Error& e)
{
    return e.detail;
}

/// A capture of a 0.2 s velocity step recorded from sim:vmc, written as `axistune-cli capture` does.
std::string recordedCapture()
{
    static const std::string path = [] {
        static const auto dir = testing::makeTempDir("conformance-replay"); // removed when the process ends
        const std::string file = (dir / "step.csv").string();
        auto d = connect({"sim:vmc", kSeed});
        if (!d)
            return std::string();
        TestRequest r;
        r.axis = "X";
        auto& step = r.test.emplace<StepTest>();
        step.velocityRadS = 10.0;
        step.recordS = 0.2;
        if (!(*d)->startTest(r))
            return std::string();
        for (auto s = (*d)->pollTest(); s && s->state == TestState::Running; s = (*d)->pollTest()) {
        }
        auto t = (*d)->readTrace();
        if (!t)
            return std::string();
        model::Capture cap = std::move(t).value();
        cap.metadata.set("test", "step");
        cap.metadata.set("connection", "sim:vmc");
        return io::writeCaptureCsvFile(file, cap) ? file : std::string();
    }();
    return path;
}

/// Runs a started test to its end; every progress value is checked to lie in [0, 1] and never fall.
struct RunOutcome {
    TestStatus last;
    int polls = 0;
    bool monotone = true;
    std::string error;
};

RunOutcome runToEnd(Drive& d, double wallLimitS = 300.0)
{
    RunOutcome o;
    double previous = 0.0;
    const auto end = Clock::now() + std::chrono::duration<double>(wallLimitS);
    while (Clock::now() < end) {
        auto s = d.pollTest();
        ++o.polls;
        if (!s) {
            o.error = s.error().detail;
            return o;
        }
        if (!(s->progress >= previous && s->progress <= 1.0))
            o.monotone = false;
        previous = s->progress;
        o.last = *s;
        if (s->state != TestState::Running)
            return o;
    }
    o.error = "still running after the wall-clock limit";
    return o;
}

class DriveConformance : public ::testing::TestWithParam<std::string> {
protected:
    void SetUp() override
    {
        const std::string b = GetParam();
        if (b == "sim") {
            m_uri = "sim:vmc";
        } else if (b == "modbus") {
            m_server = std::make_unique<testing::SimDrive>("--preset vmc --seed " + std::to_string(kSeed));
            ASSERT_GT(m_server->port(), 0) << m_server->log();
            m_uri = m_server->uri("timeout_ms=2000");
        } else if (b == "replay") {
            const std::string file = recordedCapture();
            ASSERT_FALSE(file.empty()) << "recording the capture to replay failed";
            m_uri = "replay:" + file;
        } else if (b == "hal" || b == "linuxcnc") {
#ifdef AXISTUNE_SOURCE_DIR
            // The repository's LinuxCNC test machine: LinuxCNC's pid around AxisTune's plant (docs/linuxcnc.md).
            const std::string script = std::string(AXISTUNE_SOURCE_DIR) + "/scripts/hal-testbed";
            m_halLock = std::make_unique<axistune::testing::HalMachineLock>();
            ASSERT_TRUE(m_halLock->held()) << "cannot open /tmp/axistune-hal-machine.lock";
            ASSERT_EQ(std::system((script + " start >/dev/null 2>&1").c_str()), 0) << script << " start failed";
            m_halScript = script;
            ::setenv("AXISTUNE_HALCMD", (script + " halcmd").c_str(), 1);
            // linuxcnc: the test machine's own INI, the configuration the HAL session was started from.
            m_uri = b == "hal"
                        ? std::string("hal:")
                        : "linuxcnc:" + std::string(AXISTUNE_SOURCE_DIR) + "/linuxcnc/testbed/axistune-testbed.ini";
#else
            FAIL() << "the hal backend's rules need AXISTUNE_SOURCE_DIR (tests/linuxcnc)";
#endif
        }
        auto d = connect({m_uri, kSeed});
        ASSERT_TRUE(d.ok()) << errorText(d.error());
        m_drive = std::move(d).value();
        auto id = m_drive->identify();
        ASSERT_TRUE(id.ok()) << errorText(id.error());
        ASSERT_FALSE(id->axes.empty());
        m_identity = *id;
        m_axis = id->axes.front();
        auto caps = m_drive->capabilities(m_axis);
        ASSERT_TRUE(caps.ok()) << "every backend describes itself: " << errorText(caps.error());
        m_caps = *caps;
        auto lim = m_drive->limits(m_axis);
        ASSERT_TRUE(lim.ok()) << "every backend states its limits: " << errorText(lim.error());
        m_limits = *lim;
    }

    void TearDown() override
    {
        m_drive.reset();
        if (!m_halScript.empty())
            (void)std::system((m_halScript + " stop >/dev/null 2>&1").c_str());
    }

    /// Skips the rule, printed with the backend, the rule and the capability it lacks.
    bool offered(bool offers, const std::string& rule, const std::string& capability)
    {
        if (!offers) {
            const std::string msg = "backend " + GetParam() + " (" + m_uri + ") does not offer " + capability +
                                    " (its capabilities say so): rule '" + rule + "' does not apply";
            std::cout << "[ NOT OFFERED ] " << msg << "\n";
            RecordProperty("not_offered", msg);
        }
        return offers;
    }

    /// A request of this type within the drive's limits (planTest accepts it), or nullopt.
    std::optional<TestRequest> requestFor(TestType t, FrfMethod method = FrfMethod::MultiSweep)
    {
        TestRequest r;
        r.axis = m_axis;
        r.test = testKindOf(t);
        switch (t) {
        case TestType::Step: {
            auto& s = r.step();
            // A position step in the command's units (hal:: mm on the test machine, like the jog's distance), else a
            // motor velocity step.
            if (m_caps.stepIsPositionStep)
                s.position = 0.002;
            else
                s.velocityRadS = std::min(10.0, 0.1 * m_limits.motorSpeedMaxRadS);
            s.recordS = 0.2;
            break;
        }
        case TestType::Jog: {
            auto& j = r.jog();
            j.distance = 0.002;
            j.velocity = 0.01;
            j.acceleration = 0.5;
            j.dwellS = 0.05;
            j.returnToStart = true;
            break;
        }
        case TestType::Hold:
            r.hold().recordS = 0.2;
            break;
        case TestType::CurrentStep: {
            auto& c = r.currentStep();
            c.currentA = 0.5 * m_limits.currentStepMaxA;
            c.recordS = std::min(0.02, m_limits.currentStepMaxS);
            break;
        }
        case TestType::Frf: {
            auto& f = r.frf();
            f.method = method;
            f.fminHz = 50.0;
            f.fmaxHz = 400.0;
            f.points = 6;
            f.amplitudePct = std::min(5.0, 0.5 * m_limits.frfAmplitudeMaxPct);
            break;
        }
        case TestType::Circle: {
            auto& c = r.circle();
            c.radiusM = 0.002;
            c.feedMPerS = 0.02;
            c.dwellS = 0.05;
            break;
        }
        }
        if (t == TestType::Step && GetParam() == "replay")
            return r; // the recorded test: whatever was asked
        // Halve an amplitude the drive would refuse (a current step's speed limit depends on the motor).
        for (int i = 0; i < 6; ++i) {
            if (t == TestType::Circle) {
                for (const auto& second : m_identity.axes) {
                    if (second == m_axis)
                        continue;
                    r.circle().secondAxis = second;
                    if (auto p = m_drive->planTest(r))
                        return r;
                    else
                        m_lastPlanError = errorText(p.error());
                }
                return std::nullopt;
            }
            if (auto p = m_drive->planTest(r))
                return r;
            else
                m_lastPlanError = errorText(p.error());
            if (auto* s = std::get_if<StepTest>(&r.test)) {
                s->velocityRadS *= 0.5;
                s->position *= 0.5;
            } else if (auto* c = std::get_if<CurrentStepTest>(&r.test)) {
                c->currentA *= 0.5;
            }
        }
        return std::nullopt;
    }

    bool halBackend() const
    {
        return GetParam() == "hal" || GetParam() == "linuxcnc";
    }

    std::string m_lastPlanError; ///< requestFor: why the drive refused the last request it planned
    std::string m_uri;
    std::string m_halScript; ///< hal: the test machine's script, stopped after the rule
    std::unique_ptr<axistune::testing::HalMachineLock>
        m_halLock; ///< hal:, linuxcnc: the machine's one HAL, held for the rule
    std::unique_ptr<testing::SimDrive> m_server;
    std::unique_ptr<Drive> m_drive;
    DriveIdentity m_identity;
    std::string m_axis;
    DriveCapabilities m_caps;
    DriveLimits m_limits;
};

TEST_P(DriveConformance, Identity)
{
    EXPECT_FALSE(m_identity.vendor.empty());
    EXPECT_FALSE(m_identity.model.empty());
    EXPECT_FALSE(m_identity.firmware.empty());
    EXPECT_FALSE(m_identity.machine.empty());
    // Asking twice gives the same answer.
    auto again = m_drive->identify();
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again->axes, m_identity.axes);
    EXPECT_EQ(again->machine, m_identity.machine);
    if (GetParam() == "hal") {
        EXPECT_EQ(m_identity.machine, "hal");
        EXPECT_EQ(m_identity.axes, std::vector<std::string>{"pid.x"}); // the test machine's one pid
    } else if (GetParam() == "linuxcnc") {
        EXPECT_EQ(m_identity.machine, "AxisTune test machine");    // [EMC]MACHINE
        EXPECT_EQ(m_identity.axes, std::vector<std::string>{"X"}); // joint 0, [TRAJ]COORDINATES
    } else if (GetParam() != "replay") {
        EXPECT_EQ(m_identity.machine, "vmc");
    } else {
        EXPECT_EQ(m_identity.axes, std::vector<std::string>{"X"}); // the recorded axis only
    }
    // An unknown axis is refused by name.
    auto none = m_drive->parameterMetadata("no-such-axis");
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().detail.find("no-such-axis"), std::string::npos) << none.error().detail;
}

TEST_P(DriveConformance, CapabilitiesAndLimitsAreStated)
{
    EXPECT_FALSE(m_caps.testTypes.empty());
    EXPECT_GT(m_caps.traceRateHz, 0.0);
    EXPECT_EQ(m_caps.offers(TestType::Frf), !m_caps.frfMethods.empty());
    // Every limit a test needs is stated as a positive number when the test is offered.
    if (m_caps.offers(TestType::Frf)) {
        EXPECT_GT(m_limits.frfAmplitudeMaxPct, 0.0);
    }
    if (m_caps.offers(TestType::CurrentStep)) {
        EXPECT_GT(m_limits.currentStepMaxA, 0.0);
        EXPECT_GT(m_limits.currentStepMaxS, 0.0);
        EXPECT_GT(m_limits.currentStepMaxSpeedRadS, 0.0);
        EXPECT_GT(m_caps.currentTraceRateHz, 0.0);
    }
    if (m_caps.offers(TestType::Step) && GetParam() != "replay" && !m_caps.stepIsPositionStep) {
        EXPECT_GT(m_limits.motorSpeedMaxRadS, 0.0);
    }
    // A test the drive does not advertise is refused, before anything moves.
    for (const auto t : {TestType::Step, TestType::Jog, TestType::Hold, TestType::Frf, TestType::CurrentStep}) {
        if (m_caps.offers(t))
            continue;
        TestRequest r;
        r.axis = m_axis;
        r.test = testKindOf(t);
        auto st = m_drive->startTest(r);
        ASSERT_FALSE(st.ok()) << testTypeName(t);
        EXPECT_NE(st.error().detail.find(testTypeName(t)), std::string::npos) << st.error().detail;
        auto plan = m_drive->planTest(r);
        EXPECT_FALSE(plan.ok()) << testTypeName(t);
    }
}

TEST_P(DriveConformance, ParameterMetadataAndRead)
{
    auto meta = m_drive->parameterMetadata(m_axis);
    ASSERT_TRUE(meta.ok()) << errorText(meta.error());
    ASSERT_FALSE(meta->empty());
    auto all = m_drive->readParameters(m_axis, {});
    ASSERT_TRUE(all.ok()) << errorText(all.error());
    for (const auto& m : *meta) {
        EXPECT_FALSE(m.key.empty());
        EXPECT_LE(m.minSi, m.maxSi) << m.key;
        ASSERT_EQ(all->count(m.key), 1u) << m.key << " has metadata but no value";
        const double v = all->at(m.key);
        EXPECT_TRUE(std::isfinite(v)) << m.key;
        EXPECT_GE(v, m.minSi) << m.key;
        EXPECT_LE(v, m.maxSi) << m.key;
    }
    // A read by key gives the same values; an unknown key is refused by name.
    std::vector<std::string> keys{meta->front().key, meta->back().key};
    auto some = m_drive->readParameters(m_axis, keys);
    ASSERT_TRUE(some.ok()) << errorText(some.error());
    for (const auto& k : keys)
        EXPECT_EQ(some->at(k), all->at(k)) << k;
    const std::vector<std::string> bad{"no.such_parameter"};
    auto unknown = m_drive->readParameters(m_axis, bad);
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(unknown.error().detail.find("no.such_parameter"), std::string::npos);
}

/// The first writable, non-integer parameter with a range to move in; loop periods are left out (they must
/// stay whole multiples of each other, a rule across parameters).
std::optional<model::ParameterMeta> writableParameter(Drive& d, const std::string& axis)
{
    auto meta = d.parameterMetadata(axis);
    if (!meta)
        return std::nullopt;
    for (const auto& m : *meta) {
        const bool period = m.key.size() >= 6 && m.key.compare(m.key.size() - 6, 6, "period") == 0;
        if (m.writable && !m.integer && !period && m.maxSi > m.minSi && m.minSi > 0.0)
            return m;
    }
    // hal: the pid's deadband (a gain of 0 or a negative bias is valid there: no pin has a positive minimum).
    if (const auto* deadband = model::findParameter(*meta, "deadband"); deadband && deadband->writable)
        return *deadband;
    return std::nullopt;
}

TEST_P(DriveConformance, WriteAndReadBack)
{
    if (!offered(m_caps.writesParameters, "write, read-back", "parameter writes")) {
        // Still a rule: the refusal names the parameter and nothing changes.
        auto meta = m_drive->parameterMetadata(m_axis);
        ASSERT_TRUE(meta.ok() && !meta->empty());
        const auto before = m_drive->readParameters(m_axis, {});
        auto st = m_drive->writeParameters(m_axis, {{meta->front().key, meta->front().minSi}});
        ASSERT_FALSE(st.ok());
        EXPECT_NE(st.error().detail.find(meta->front().key), std::string::npos) << st.error().detail;
        EXPECT_EQ(m_drive->readParameters(m_axis, {}).value(), before.value());
        return;
    }
    auto p = writableParameter(*m_drive, m_axis);
    ASSERT_TRUE(p.has_value()) << "no writable parameter on axis " << m_axis;
    const std::vector<std::string> key{p->key};
    const double old = m_drive->readParameters(m_axis, key).value().at(p->key);
    // Inside the range, not the value it had. hal:'s pid pins have no upper limit of their own (1e9 stands for
    // none): a tenth of that would be a gain that throws the test machine's loop; a small deadband step is written.
    const double wanted = halBackend() ? old + 1e-3 : old + 0.1 * (p->maxSi - old);
    ASSERT_NE(wanted, old);
    auto st = m_drive->writeParameters(m_axis, {{p->key, wanted}});
    ASSERT_TRUE(st.ok()) << errorText(st.error());
    const double back = m_drive->readParameters(m_axis, key).value().at(p->key);
    // Parameters travel as float32 over Modbus (docs/modbus.md): the read-back is the value rounded to
    // float32, a relative error of at most 2^-24; the embedded drive keeps the double exactly. halcmd shows a
    // pin with seven significant digits (hal:): half a unit of the seventh digit.
    const double tolerance = halBackend() ? 5e-7 * std::abs(wanted) : std::ldexp(std::abs(wanted), -24);
    EXPECT_LE(std::abs(back - wanted), tolerance) << p->key;
    ASSERT_TRUE(m_drive->writeParameters(m_axis, {{p->key, old}}).ok());
}

TEST_P(DriveConformance, WriteOutsideTheLimitsIsRefusedAndNothingChanges)
{
    auto meta = m_drive->parameterMetadata(m_axis);
    ASSERT_TRUE(meta.ok());
    const auto before = m_drive->readParameters(m_axis, {});
    ASSERT_TRUE(before.ok());
    if (!offered(m_caps.writesParameters, "write outside the limits", "parameter writes")) {
        auto st = m_drive->writeParameters(m_axis, {{meta->front().key, meta->front().maxSi + 1.0}});
        ASSERT_FALSE(st.ok());
        EXPECT_NE(st.error().detail.find(meta->front().key), std::string::npos) << st.error().detail;
        EXPECT_EQ(m_drive->readParameters(m_axis, {}).value(), before.value());
        return;
    }
    auto p = writableParameter(*m_drive, m_axis);
    ASSERT_TRUE(p.has_value());
    const double outside = p->maxSi + (p->maxSi - p->minSi) + 1.0;
    // Together with a valid write of another parameter: the whole write is refused, nothing changes.
    model::ParameterValues values{{p->key, outside}};
    auto st = m_drive->writeParameters(m_axis, values);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::OutOfRange) << st.error().detail;
    const std::string& msg = st.error().detail;
    EXPECT_NE(msg.find(p->key), std::string::npos) << msg;
    // The limits, as the parameter's display unit shows them (core/model/Parameter.h formatDisplay).
    EXPECT_NE(msg.find("[" + model::formatDisplay(*p, p->minSi) + ", " + model::formatDisplay(*p, p->maxSi) + "]"),
              std::string::npos)
        << msg;
    EXPECT_EQ(m_drive->readParameters(m_axis, {}).value(), before.value());
}

TEST_P(DriveConformance, EveryAdvertisedTestRunsToCompletionAsPlanned)
{
    std::vector<std::pair<TestType, FrfMethod>> tests;
    for (const auto t : m_caps.testTypes) {
        if (t == TestType::Frf) {
            for (const auto m : m_caps.frfMethods)
                tests.emplace_back(t, m);
        } else {
            tests.emplace_back(t, FrfMethod::MultiSweep);
        }
    }
    ASSERT_FALSE(tests.empty());
    for (const auto& [t, method] : tests) {
        const std::string what =
            std::string(testTypeName(t)) + (t == TestType::Frf ? std::string(" ") + frfMethodName(method) : "");
        SCOPED_TRACE(what);
        auto r = requestFor(t, method);
        ASSERT_TRUE(r.has_value()) << "no request within the drive's limits for " << what
                                   << "; the drive's last refusal: " << m_lastPlanError;
        auto plan = m_drive->planTest(*r);
        ASSERT_TRUE(plan.ok()) << errorText(plan.error());
        EXPECT_GT(plan->motionTimeS, 0.0);
        EXPECT_GT(plan->recordSamples, 0u);
        EXPECT_GT(plan->traceRateHz, 0.0);
        auto st = m_drive->startTest(*r);
        ASSERT_TRUE(st.ok()) << errorText(st.error());
        const auto out = runToEnd(*m_drive);
        ASSERT_TRUE(out.error.empty()) << out.error;
        ASSERT_EQ(out.last.state, TestState::Completed) << out.last.detail;
        EXPECT_TRUE(out.monotone) << "progress fell or left [0, 1]";
        EXPECT_EQ(out.last.progress, 1.0);
        auto trace = m_drive->readTrace();
        ASSERT_TRUE(trace.ok()) << errorText(trace.error());
        // The plan's trace rate is the trace's.
        const double fs = trace->metadata.number("fs_Hz").value();
        EXPECT_NEAR(fs, plan->traceRateHz, 1e-9 * fs);
        // The record length: the drive records on its trace grid, so the count can differ from the plan's
        // length / period by the one sample at either end of the record.
        EXPECT_NEAR(static_cast<double>(trace->size()), static_cast<double>(plan->recordSamples), 1.0);
        // The motion time the run reports equals the plan's: the drive runs in whole current-loop periods, so
        // they agree within one current period (1 / currentTraceRateHz; 1 / traceRateHz where the drive
        // has no current trace).
        const double tick =
            m_caps.currentTraceRateHz > 0.0 ? 1.0 / m_caps.currentTraceRateHz : 1.0 / m_caps.traceRateHz;
        double reported = std::numeric_limits<double>::quiet_NaN();
        if (t == TestType::Frf && m_caps.evaluatesFrf) {
            auto frf = m_drive->readFrequencyResponse();
            ASSERT_TRUE(frf.ok()) << errorText(frf.error());
            EXPECT_FALSE(frf->frf.freqHz.empty());
            reported = frf->motionTimeS;
        } else {
            reported = trace->metadata.number(model::meta::kMotionTimeS).value();
        }
        EXPECT_NEAR(reported, plan->motionTimeS, tick + 1e-12) << "plan " << plan->motionTimeS << " s";
    }
}

// A step's quantity is the drive's own (StepTest::velocityRadS or ::position, as
// DriveCapabilities::stepIsPositionStep says): a step given in the other one is refused before anything moves, so
// that millimetres are never taken for rad/s. A replay plays what it recorded whatever is asked.
TEST_P(DriveConformance, AStepInTheOtherQuantityIsRefused)
{
    if (!offered(m_caps.offers(TestType::Step) && GetParam() != "replay", "a step in the other quantity is refused",
                 "a step test of its own"))
        return;
    auto r = requestFor(TestType::Step).value();
    std::swap(r.step().velocityRadS, r.step().position);
    auto plan = m_drive->planTest(r);
    ASSERT_FALSE(plan.ok());
    EXPECT_EQ(plan.error().code, ErrorCode::BadInput) << errorText(plan.error());
    auto st = m_drive->startTest(r);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::BadInput) << errorText(st.error());
    auto s = m_drive->pollTest();
    ASSERT_TRUE(s.ok()) << errorText(s.error());
    EXPECT_NE(s->state, TestState::Running);
}

TEST_P(DriveConformance, AbortMidTestRestoresTheParameters)
{
    const auto before = m_drive->readParameters(m_axis, {});
    ASSERT_TRUE(before.ok());
    const TestType t = m_caps.offers(TestType::Hold) ? TestType::Hold : m_caps.testTypes.front();
    const FrfMethod method = m_caps.frfMethods.empty() ? FrfMethod::MultiSweep : m_caps.frfMethods.front();
    TestRequest r = requestFor(t, method).value();
    if (t == TestType::Hold) {
        r.hold().recordS = 20.0; // long enough to be running when the abort comes
        r.traceDivider = 2; // a parameter the test changes (trace.divider) and the abort must restore
    }
    if (t == TestType::Frf && method == FrfMethod::Multisine)
        r.frf().multisinePeriods = 40; // seconds, not a fraction of one
    ASSERT_TRUE(m_drive->startTest(r).ok());
    auto s = m_drive->pollTest();
    ASSERT_TRUE(s.ok()) << errorText(s.error());
    ASSERT_EQ(s->state, TestState::Running);
    ASSERT_TRUE(m_drive->abortTest().ok());
    s = m_drive->pollTest();
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->state, TestState::Aborted);
    EXPECT_LT(s->progress, 1.0);
    EXPECT_EQ(m_drive->readParameters(m_axis, {}).value(), before.value());
    // The drive takes the next test after an abort.
    auto again = requestFor(t, method).value();
    ASSERT_TRUE(m_drive->startTest(again).ok());
    EXPECT_EQ(runToEnd(*m_drive).last.state, TestState::Completed);
}

TEST_P(DriveConformance, LostConnectionIsReportedWithinTheTimeout)
{
    if (GetParam() == "sim") {
        // The embedded drive has no link; its fault injection drops it (FaultInjection.h): the 5th call
        // and every later one fail as a lost link would, at once.
        auto d = connect({"sim:vmc?fault=drop-after:5", kSeed});
        ASSERT_TRUE(d.ok()) << errorText(d.error());
        auto r = requestFor(TestType::Hold).value();
        r.hold().recordS = 20.0;
        ASSERT_TRUE((*d)->startTest(r).ok()); // call 1
        for (int call = 2; call <= 4; ++call)
            ASSERT_TRUE((*d)->pollTest().ok()) << call;
        const auto t0 = Clock::now();
        auto s = (*d)->pollTest(); // call 5
        ASSERT_FALSE(s.ok());
        EXPECT_EQ(s.error().code, ErrorCode::Device);
        EXPECT_NE(s.error().detail.find("connection lost"), std::string::npos) << s.error().detail;
        EXPECT_LT(std::chrono::duration<double>(Clock::now() - t0).count(), 0.1);
        EXPECT_FALSE((*d)->identify().ok());
        return;
    }
    if (!offered(m_caps.hasLink, "lost connection", "a connection that can be lost")) {
        // A backend without a link (replay: a file read when it opens) must never report one lost: it keeps
        // answering, test after test.
        for (int i = 0; i < 50; ++i) {
            auto id = m_drive->identify();
            ASSERT_TRUE(id.ok()) << "call " << i << ": " << errorText(id.error());
            auto st = m_drive->pollTest();
            ASSERT_TRUE(st.ok()) << "call " << i << ": " << errorText(st.error());
        }
        return;
    }
    if (halBackend()) {
        // The HAL session stops while a test runs: the sampler delivers no more rows, and the loss is reported
        // by pollTest as a Device error within the stall limit (3 s, HalAxis.cpp runExcitation) plus the halcmd
        // calls that find HAL gone; 2 s are allowed for them on a loaded machine.
        auto r = requestFor(TestType::Frf, FrfMethod::Multisine).value();
        r.frf().multisinePeriods = 100;
        ASSERT_TRUE(m_drive->startTest(r).ok());
        // Mid-test: once the excitation streams (progress above 0).
        for (auto p = m_drive->pollTest(); p.ok() && p->progress == 0.0; p = m_drive->pollTest())
            ASSERT_EQ(p->state, TestState::Running) << p->detail;
        ASSERT_EQ(std::system((m_halScript + " stop >/dev/null 2>&1").c_str()), 0);
        const auto t0 = Clock::now();
        Result<TestStatus> s = m_drive->pollTest();
        while (s.ok() && s->state == TestState::Running && Clock::now() - t0 < std::chrono::seconds(30))
            s = m_drive->pollTest();
        const double elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
        ASSERT_FALSE(s.ok()) << "state " << testStateName(s->state) << ": " << s->detail;
        EXPECT_EQ(s.error().code, ErrorCode::Device);
        EXPECT_NE(s.error().detail.find(GetParam() + ":"), std::string::npos) << s.error().detail;
        EXPECT_LT(elapsed, 3.0 + 2.0) << s.error().detail;
        EXPECT_FALSE(m_drive->identify().ok());
        return;
    }
    // modbus: the server is killed while a test runs. The client retries a read kMaxAttempts times with
    // 50 and 100 ms pauses, each attempt bounded by the response timeout (ModbusDrive.h), so the loss is
    // reported within kMaxAttempts × timeout + 150 ms; 0.5 s are added for the process scheduling.
    testing::SimDrive server("--preset vmc --seed 7");
    ASSERT_GT(server.port(), 0);
    const int timeoutMs = 300;
    auto d = connect({server.uri("timeout_ms=" + std::to_string(timeoutMs)), kSeed});
    ASSERT_TRUE(d.ok()) << errorText(d.error());
    auto r = requestFor(TestType::Hold).value();
    r.hold().recordS = 20.0;
    ASSERT_TRUE((*d)->startTest(r).ok());
    ASSERT_TRUE((*d)->pollTest().ok());
    server.stop(SIGKILL);
    const auto t0 = Clock::now();
    auto s = (*d)->pollTest();
    const double elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().code, ErrorCode::Device);
    EXPECT_NE(s.error().detail.find(server.uri("timeout_ms=300")), std::string::npos) << s.error().detail;
    EXPECT_LT(elapsed, 3 * timeoutMs / 1000.0 + 0.15 + 0.5) << s.error().detail;
}

// The scope (docs/scope.md): for every backend whose capabilities offer it.
/// Polls the scope until one of the states or the wall-clock limit.
ScopeState pollScopeUntil(Drive& d, std::initializer_list<ScopeState> states, double wallS)
{
    const auto end = Clock::now() + std::chrono::duration<double>(wallS);
    ScopeState last = ScopeState::Idle;
    while (Clock::now() < end) {
        auto s = d.pollScope();
        if (!s)
            return last;
        last = s->state;
        for (const auto w : states) {
            if (last == w)
                return last;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return last;
}

TEST_P(DriveConformance, ScopeDescribesItsChannelsWithUnits)
{
    if (!offered(m_caps.scope, "scope channels", "a scope")) {
        // The other side: a backend without a scope refuses clearly, before anything is armed.
        auto c = m_drive->scopeCapabilities(m_axis);
        ASSERT_FALSE(c.ok());
        EXPECT_NE(c.error().detail.find("no scope"), std::string::npos) << c.error().detail;
        ScopeRequest r;
        r.axis = m_axis;
        r.channels = {"t_s"};
        r.mode = ScopeMode::Roll;
        auto st = m_drive->armScope(r);
        ASSERT_FALSE(st.ok());
        EXPECT_NE(st.error().detail.find("no scope"), std::string::npos) << st.error().detail;
        return;
    }
    auto c = m_drive->scopeCapabilities(m_axis);
    ASSERT_TRUE(c.ok()) << errorText(c.error());
    ASSERT_FALSE(c->channels.empty());
    std::set<std::string> names;
    for (const auto& ch : c->channels) {
        EXPECT_FALSE(ch.name.empty());
        EXPECT_FALSE(ch.unit.empty()) << ch.name << " has no unit";
        EXPECT_TRUE(names.insert(ch.name).second) << ch.name << " listed twice";
    }
    EXPECT_GT(c->fastestRateHz, 0.0);
    EXPECT_GE(c->maxChannels, 1);
    EXPECT_GE(c->maxDivider, 1);
    EXPECT_GE(c->maxValues, 2u * static_cast<std::uint64_t>(c->maxChannels));
    EXPECT_GE(c->ringValues, 2u * static_cast<std::uint64_t>(c->maxChannels));
    // The same answer twice; an unknown channel refused by name.
    EXPECT_EQ(m_drive->scopeCapabilities(m_axis)->channels.size(), c->channels.size());
    ScopeRequest bad;
    bad.axis = m_axis;
    bad.mode = ScopeMode::Roll;
    bad.channels = {c->channels.front().name, "no_such_channel"};
    auto st = m_drive->armScope(bad);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().detail.find("'no_such_channel'"), std::string::npos) << st.error().detail;
}

TEST_P(DriveConformance, ScopeTriggersAtThePreTriggerRowOnAStep)
{
    if (!offered(m_caps.scope && m_caps.offers(TestType::Step), "scope trigger on a step", "a scope and a step test"))
        return;
    auto c = m_drive->scopeCapabilities(m_axis);
    ASSERT_TRUE(c.ok());
    const bool hasCmd = std::any_of(c->channels.begin(), c->channels.end(),
                                    [](const ScopeChannelInfo& ch) { return ch.name == "velocity_cmd_rad_s"; });
    if (!offered(hasCmd, "scope trigger on a step", "a velocity_cmd_rad_s scope channel"))
        return;
    auto step = requestFor(TestType::Step).value();
    ScopeRequest r;
    r.axis = m_axis;
    r.channels = {"velocity_cmd_rad_s"};
    r.triggerChannel = "velocity_cmd_rad_s";
    r.triggerLevel = 0.5 * step.step().velocityRadS;
    r.edge = ScopeEdge::Rising;
    r.preTriggerPct = 30.0;
    r.lengthSamples = 200;
    ASSERT_TRUE(m_drive->armScope(r).ok());
    ASSERT_EQ(pollScopeUntil(*m_drive, {ScopeState::Waiting}, 10.0), ScopeState::Waiting);
    ASSERT_TRUE(m_drive->startTest(step).ok());
    EXPECT_EQ(runToEnd(*m_drive).last.state, TestState::Completed);
    ASSERT_EQ(pollScopeUntil(*m_drive, {ScopeState::Done}, 10.0), ScopeState::Done);
    auto cap = m_drive->readScopeCapture();
    ASSERT_TRUE(cap.ok()) << errorText(cap.error());
    ASSERT_EQ(cap->rows(), 200u);
    ASSERT_EQ(cap->triggerRow(), 60u); // 30 % of 200
    EXPECT_EQ(cap->missingSamples(), 0u);
    EXPECT_LT(cap->columns[0][59], r.triggerLevel);
    EXPECT_GE(cap->columns[0][60], r.triggerLevel);
    EXPECT_EQ(cap->columns[0][60], step.step().velocityRadS); // the step itself, not a ramp through the level
}

TEST_P(DriveConformance, ScopeRollModeDeliversEverySampleOnce)
{
    if (!offered(m_caps.scope, "scope roll mode", "a scope"))
        return;
    auto c = m_drive->scopeCapabilities(m_axis);
    ASSERT_TRUE(c.ok());
    ScopeRequest r;
    r.axis = m_axis;
    r.mode = ScopeMode::Roll;
    for (std::size_t i = 0; i < c->channels.size() && static_cast<int>(r.channels.size()) < std::min(8, c->maxChannels);
         ++i)
        r.channels.push_back(c->channels[i].name);
    const auto armed = m_drive->armScope(r);
    ASSERT_TRUE(armed.ok()) << errorText(armed.error());
    ScopeCapture all;
    all.triggered = false;
    all.columns.assign(r.channels.size(), {});
    std::uint64_t next = 0;
    bool started = false;
    const auto end = Clock::now() + std::chrono::milliseconds(600);
    while (Clock::now() < end || all.rows() < 100) {
        ASSERT_TRUE(m_drive->pollScope().ok());
        auto rows = m_drive->readScopeRows(next, 100000);
        ASSERT_TRUE(rows.ok()) << errorText(rows.error());
        if (rows->rows == 0)
            continue;
        if (started) {
            ASSERT_EQ(rows->firstSample, next) << "samples lost between reads";
        }
        started = true;
        appendScopeRows(all, *rows);
        next = rows->firstSample + rows->rows;
        ASSERT_LT(all.rows(), 10'000'000u);
    }
    EXPECT_EQ(all.missingSamples(), 0u);
    for (std::size_t i = 1; i < all.rows(); ++i)
        ASSERT_EQ(all.samples[i], all.samples[i - 1] + 1);
    ASSERT_TRUE(m_drive->stopScope().ok());
    auto s = m_drive->pollScope();
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->state, ScopeState::Idle);
}

} // namespace
} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 17 item 2 on AxisTune's LinuxCNC test machine (scripts/hal-testbed): FRF by multi-sweep and by PRBS, and
// the position step, through the hal: drive (the seam every front end uses) and the command line.
#include "core/device/hal/HalDrive.h"
#include "core/io/CaptureCsv.h"
#include "core/io/FrfCsv.h"
#include "core/model/Number.h"

#include <chrono>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <thread>
#include <nlohmann/json.hpp>

#include "tests/ScopedTempDir.h"
#include "tests/linuxcnc/HalTestbed.h"

using namespace axistune;
using namespace axistune::device;
using namespace axistune::device::hal;
using namespace axistune::testing;

namespace {

std::unique_ptr<HalDrive> openDrive()
{
    auto d = HalDrive::open(halOptions());
    EXPECT_TRUE(d) << (d ? "" : d.error().detail);
    return d ? std::move(d).value() : nullptr;
}

/// Runs a started test to its end (at most 120 s); the final status.
TestStatus runToEnd(HalDrive& d)
{
    const auto t0 = std::chrono::steady_clock::now();
    for (;;) {
        auto s = d.pollTest();
        EXPECT_TRUE(s) << (s ? "" : s.error().detail);
        if (!s || s->state != TestState::Running)
            return s ? *s : TestStatus{TestState::Faulted, 0.0, s.error().detail};
        if (std::chrono::steady_clock::now() - t0 > std::chrono::seconds(120)) {
            (void)d.abortTest();
            return {TestState::Faulted, 0.0, "test did not end within 120 s"};
        }
    }
}

TestRequest frfRequest(FrfMethod method)
{
    TestRequest r;
    r.axis = "pid.x";
    auto& f = r.test.emplace<FrfTest>();
    f.method = method;
    f.fminHz = 2.0;
    f.fmaxHz = 450.0;
    f.points = 40;
    f.amplitudePeak = 0.2; // N·m, a tenth of maxoutput
    f.quantity = FrfQuantity::Plant;
    return r;
}

struct Worst {
    double dB = 0.0, deg = 0.0;
    std::size_t lines = 0;
};

} // namespace

// Multi-sweep on hal: planned and evaluated by core's FrfTest (the simulator's code) at the servo rate: the plant
// FRF equals the plant's exact discrete-time response within the 0.1 dB and 0.5° (friction and quantization
// off: the only departures are the residual transient of the settle time and rounding), every line valid, and the
// HAL as before afterwards. The open-loop quantity equals −C(z)·z⁻¹·P(z) with LinuxCNC's discrete pid C (the pid reads
// the feedback the plant wrote one period earlier) within the same tolerance.
TEST_F(HalTestbed, MultiSweepPlantFrfEqualsTheExactDiscreteResponse)
{
    startBed(1000000);
    const std::string sigBefore = netsOf(halText({"-s", "show", "sig"}));
    const std::string funBefore = halText({"-s", "show", "funct"});
    auto drive = openDrive();
    ASSERT_TRUE(drive);
    auto caps = drive->capabilities("pid.x");
    ASSERT_TRUE(caps) << caps.error().detail;
    EXPECT_TRUE(caps->offers(FrfMethod::MultiSweep));
    EXPECT_TRUE(caps->offers(FrfMethod::Prbs));
    EXPECT_TRUE(caps->offers(TestType::Step));
    EXPECT_TRUE(caps->stepIsPositionStep);

    const Plant plant = readPlant();
    const double T = 1e-3, P = getp("pid.x.Pgain"), I = getp("pid.x.Igain"), D = getp("pid.x.Dgain");
    for (const auto quantity : {FrfQuantity::Plant, FrfQuantity::OpenLoop}) {
        SCOPED_TRACE(quantity == FrfQuantity::Plant ? "plant" : "open loop");
        TestRequest r = frfRequest(FrfMethod::MultiSweep);
        r.frf().quantity = quantity;
        auto plan = drive->planTest(r);
        ASSERT_TRUE(plan) << plan.error().detail;
        ASSERT_TRUE(drive->startTest(r)) << "start";
        const TestStatus end = runToEnd(*drive);
        ASSERT_EQ(end.state, TestState::Completed) << end.detail;
        auto m = drive->readFrequencyResponse();
        ASSERT_TRUE(m) << m.error().detail;
        EXPECT_NEAR(m->motionTimeS, plan->motionTimeS, 1e-9);
        EXPECT_EQ(m->frf.metadata.text("method"), "multisweep");
        EXPECT_EQ(m->frf.metadata.text("quantity"), quantity == FrfQuantity::Plant ? "plant" : "open-loop");
        EXPECT_EQ(m->frf.metadata.number("fs_Hz").value(), 1000.0);
        ASSERT_GE(m->frf.size(), 35u); // 40 log-spaced targets, a few may share a grid frequency
        Worst w;
        for (std::size_t i = 0; i < m->frf.size(); ++i) {
            const double f = m->frf.freqHz[i];
            ASSERT_TRUE(m->frf.valid[i]) << f << " Hz";
            std::complex<double> exact = exactResponse(plant, T, f);
            if (quantity == FrfQuantity::OpenLoop) {
                const std::complex<double> zi = std::polar(1.0, -2.0 * M_PI * f * T); // z⁻¹
                const std::complex<double> c = P + I * T / (1.0 - zi) + D * (1.0 - zi) / T;
                exact = c * zi * exact;
            }
            const std::complex<double> ratio = m->frf.h[i] / exact;
            w.dB = std::max(w.dB, std::abs(20.0 * std::log10(std::abs(ratio))));
            w.deg = std::max(w.deg, std::abs(std::arg(ratio)) * 180.0 / M_PI);
        }
        EXPECT_LE(w.dB, 0.1);
        EXPECT_LE(w.deg, 0.5);
        RecordProperty(quantity == FrfQuantity::Plant ? "plant_worst_dB" : "open_loop_worst_dB",
                       model::formatShortest(w.dB));
        RecordProperty(quantity == FrfQuantity::Plant ? "plant_worst_deg" : "open_loop_worst_deg",
                       model::formatShortest(w.deg));
        // The trace carries the method and the servo rate.
        auto trace = drive->readTrace();
        ASSERT_TRUE(trace) << trace.error().detail;
        EXPECT_EQ(trace->metadata.text("method"), "multisweep");
        EXPECT_EQ(trace->size(), plan->recordSamples);
    }
    EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), sigBefore);
    EXPECT_EQ(halText({"-s", "show", "funct"}), funBefore);
}

// PRBS on hal: Welch H1 (core's evaluateFrfSignals) of the drive input and the feedback. Its error is statistical
// (leakage of the windowed, non-periodic record acts as noise uncorrelated with the input): Bendat & Piersol
// (Random Data, 4th ed., eq. 9.52 and 9.53) give the normalized random error of |H| and the standard deviation of its
// phase [rad] as ε = √(1−γ²) / (|γ|·√(2·n_d)) with coherence γ² and n_d averages. n_d is taken as 8, the number of
// disjoint segments in the record of 8·nperseg samples (its 15 half-overlapping Hann segments carry at least that
// many independent averages). Every line with γ² ≥ 0.9 must lie within 4ε in magnitude (relative) and in phase (4ε
// rad); at least 80 % of the lines must have γ² ≥ 0.9.
TEST_F(HalTestbed, PrbsPlantFrfAgreesWithTheExactResponseWithinItsStatisticalError)
{
    startBed(1000000);
    const std::string sigBefore = netsOf(halText({"-s", "show", "sig"}));
    auto drive = openDrive();
    ASSERT_TRUE(drive);
    const TestRequest r = frfRequest(FrfMethod::Prbs);
    auto plan = drive->planTest(r);
    ASSERT_TRUE(plan) << plan.error().detail;
    ASSERT_TRUE(drive->startTest(r));
    const TestStatus end = runToEnd(*drive);
    ASSERT_EQ(end.state, TestState::Completed) << end.detail;
    auto m = drive->readFrequencyResponse();
    ASSERT_TRUE(m) << m.error().detail;
    EXPECT_EQ(m->frf.metadata.text("method"), "prbs");
    const double nperseg = m->frf.metadata.number("nperseg").value();
    EXPECT_EQ(nperseg, 512.0); // the power of two at or above fs/fmin = 500
    const double nd = 8.0;
    const Plant plant = readPlant();
    std::size_t coherent = 0;
    double worstRel = 0.0, worstDeg = 0.0, worstRatio = 0.0;
    ASSERT_GE(m->frf.size(), 20u);
    for (std::size_t i = 0; i < m->frf.size(); ++i) {
        const double f = m->frf.freqHz[i], g2 = m->frf.coherence[i];
        if (!(g2 >= 0.9))
            continue;
        ++coherent;
        EXPECT_TRUE(m->frf.valid[i]) << f << " Hz";
        const double eps = std::sqrt(1.0 - g2) / (std::sqrt(g2) * std::sqrt(2.0 * nd));
        const std::complex<double> ratio = m->frf.h[i] / exactResponse(plant, 1e-3, f);
        const double rel = std::abs(std::abs(ratio) - 1.0), phase = std::abs(std::arg(ratio));
        EXPECT_LE(rel, 4.0 * eps) << f << " Hz, coherence " << g2;
        EXPECT_LE(phase, 4.0 * eps) << f << " Hz, coherence " << g2;
        worstRel = std::max(worstRel, rel);
        worstDeg = std::max(worstDeg, phase * 180.0 / M_PI);
        worstRatio = std::max(worstRatio, std::max(rel, phase) / std::max(eps, 1e-300));
    }
    EXPECT_GE(static_cast<double>(coherent), 0.8 * static_cast<double>(m->frf.size()));
    RecordProperty("coherent_lines", std::to_string(coherent) + " of " + std::to_string(m->frf.size()));
    RecordProperty("worst_relative_magnitude", model::formatShortest(worstRel));
    RecordProperty("worst_deg", model::formatShortest(worstDeg));
    RecordProperty("worst_error_in_sigma", model::formatShortest(worstRatio));
    EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), sigBefore);
}

// The position step on hal: (the command steps by the request's amplitude, holds, steps back) against an independent
// simulation of the component equations: the plant's exact discrete state space (HalTestbed.h) and LinuxCNC 2.9's
// pid.c (error = previous command − feedback, I += e·T, D on the difference of the command and feedback derivatives,
// output limited to maxoutput), run in the thread's order streamer → injection → pid → plant → sampler. Both are
// double-precision evaluations of the same equations: they agree to rounding, 1e-9 of the step (a period of delay or
// a wrong gain would differ by more than 1e-3 of it).
TEST_F(HalTestbed, PositionStepEqualsTheSimulatedPidAndPlant)
{
    startBed(1000000);
    const std::string sigBefore = netsOf(halText({"-s", "show", "sig"}));
    auto drive = openDrive();
    ASSERT_TRUE(drive);
    TestRequest r;
    r.axis = "pid.x";
    auto& stepTest = r.test.emplace<StepTest>();
    stepTest.position = 0.01; // mm: P·e 0.02 N·m, D·e/T 0.47 N·m, below maxoutput 2 N·m
    stepTest.recordS = 0.5;
    auto plan = drive->planTest(r);
    ASSERT_TRUE(plan) << plan.error().detail;
    EXPECT_EQ(plan->recordSamples, 50u + 2u * 500u);
    ASSERT_TRUE(drive->startTest(r));
    const TestStatus end = runToEnd(*drive);
    ASSERT_EQ(end.state, TestState::Completed) << end.detail;
    auto trace = drive->readTrace();
    ASSERT_TRUE(trace) << trace.error().detail;
    EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), sigBefore);
    EXPECT_EQ(trace->metadata.text("test"), "step");
    EXPECT_EQ(trace->metadata.number("step").value(), 0.01);
    const auto* off = trace->channel("position_offset");
    const auto* u = trace->channel("drive_input");
    const auto* y = trace->channel("feedback");
    const auto* e = trace->channel("following_error");
    ASSERT_TRUE(off && u && y && e);
    const std::size_t n = off->data.size();
    ASSERT_EQ(n, plan->recordSamples);
    for (std::size_t i = 0; i < n; ++i)
        ASSERT_EQ(off->data[i], i >= 50 && i < 550 ? 0.01 : 0.0) << "row " << i;

    ASSERT_EQ(getp("pid.x.FF0"), 0.0);
    ASSERT_EQ(getp("pid.x.FF1"), 0.0);
    ASSERT_EQ(getp("pid.x.FF2"), 0.0);
    ASSERT_EQ(halText({"getp", "pid.x.error-previous-target"}).substr(0, 4), "TRUE");
    const double T = 1e-3, P = getp("pid.x.Pgain"), I = getp("pid.x.Igain"), D = getp("pid.x.Dgain");
    const double maxOut = getp("pid.x.maxoutput");
    const PlantStateSpace s = plantStateSpace(readPlant(), T);
    Eigen::Vector4d x = Eigen::Vector4d::Zero(); // at rest at zero: the bed starts there, friction off
    double prevCmd = 0.0, prevFb = 0.0, errI = 0.0, worstY = 0.0, worstU = 0.0, worstE = 0.0, peakU = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double cmd = off->data[k]; // the test bed's command net is 0
        const double fb = s.C * x;       // what the plant wrote last period
        const double err = prevCmd - fb;
        errI += err * T;
        const double errD = (cmd - prevCmd) / T - (fb - prevFb) / T;
        double out = P * err + I * errI + D * errD;
        peakU = std::max(peakU, std::abs(out));
        out = std::clamp(out, -maxOut, maxOut);
        prevCmd = cmd;
        prevFb = fb;
        x = s.A * x + s.B * out;
        worstU = std::max(worstU, std::abs(u->data[k] - out));
        worstE = std::max(worstE, std::abs(e->data[k] - err));
        worstY = std::max(worstY, std::abs(y->data[k] - s.C * x));
    }
    EXPECT_LT(peakU, maxOut); // the linear range: the limit never acted
    EXPECT_LE(worstY, 1e-9 * stepTest.position);
    EXPECT_LE(worstE, 1e-9 * stepTest.position);
    EXPECT_LE(worstU, 1e-9 * stepTest.position * D / T);
    RecordProperty("worst_feedback_difference", model::formatShortest(worstY));
    // The step response itself: the feedback has moved most of the way by the end of the hold and is back near zero
    // at the end.
    EXPECT_GT(y->data[549], 0.5 * stepTest.position);
    EXPECT_LT(std::abs(y->data[n - 1]), 0.5 * stepTest.position);
}

// Refusals before anything is inserted, each with its reason, in planTest and startTest alike; the HAL's nets and
// functions are as before.
TEST_F(HalTestbed, RefusedMethodsAndStepsChangeNothing)
{
    startBed(1000000);
    const std::string sigBefore = netsOf(halText({"-s", "show", "sig"}));
    const std::string funBefore = halText({"-s", "show", "funct"});
    auto drive = openDrive();
    ASSERT_TRUE(drive);
    struct Case {
        TestRequest request;
        std::string reason;
    };
    std::vector<Case> cases;
    TestRequest top = frfRequest(FrfMethod::MultiSweep);
    top.frf().fmaxHz = 500.0; // half the servo rate
    cases.push_back({top, "below half the servo rate"});
    TestRequest prbsTop = frfRequest(FrfMethod::Prbs);
    prbsTop.frf().fmaxHz = 500.0;
    cases.push_back({prbsTop, "below half the servo rate"});
    TestRequest loud = frfRequest(FrfMethod::Prbs);
    loud.frf().amplitudePeak = 1.01; // maxoutput 2
    cases.push_back({loud, "at most half of pid.x.maxoutput"});
    TestRequest longSweep = frfRequest(FrfMethod::MultiSweep);
    longSweep.frf().settleS = 10.0;
    longSweep.frf().points = 100;
    cases.push_back({longSweep, "at most 600 s"});
    TestRequest conventional = frfRequest(FrfMethod::Conventional);
    cases.push_back({conventional, "multisine, multi-sweep or PRBS"});
    TestRequest step;
    step.axis = "pid.x";
    auto& stepTest = step.test.emplace<StepTest>();
    stepTest.position = 2.6; // FERROR 5 mm
    stepTest.recordS = 0.2;
    cases.push_back({step, "at most half of the following-error limit"});
    TestRequest velocityStep = step; // a caller that means a motor velocity step in rad/s (the simulator's step)
    velocityStep.step().position = 0.0;
    velocityStep.step().velocityRadS = 1.0;
    cases.push_back({velocityStep, "a velocity step request is refused"});
    TestRequest noDuration = step;
    noDuration.step().position = 0.01;
    noDuration.step().recordS = 0.0;
    cases.push_back({noDuration, "duration must be positive"});
    for (const auto& c : cases) {
        auto p = drive->planTest(c.request);
        ASSERT_FALSE(p) << c.reason;
        EXPECT_NE(p.error().detail.find(c.reason), std::string::npos) << p.error().detail;
        auto st = drive->startTest(c.request);
        ASSERT_FALSE(st) << c.reason;
        EXPECT_EQ(st.error().detail, p.error().detail);
    }
    // Without a following-error limit a step is a safety refusal.
    halText({"setp", "pid.x.maxerror", "0"});
    stepTest.position = 0.01;
    auto unbounded = drive->planTest(step);
    ASSERT_FALSE(unbounded);
    EXPECT_EQ(unbounded.error().code, ErrorCode::Safety);
    halText({"setp", "pid.x.maxerror", "5"});
    EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), sigBefore);
    EXPECT_EQ(halText({"-s", "show", "funct"}), funBefore);
}

// `axistune-cli capture --connect hal: --test frf --method multisweep|prbs` writes the plant FRF with the servo rate,
// quantity and method in its metadata; `--test step` writes the step's trace.
TEST_F(HalTestbed, CliCapturesMultiSweepPrbsAndStep)
{
    startBed(1000000);
    ::setenv("AXISTUNE_HALCMD", (kScript + " halcmd").c_str(), 1);
    const std::string sigBefore = netsOf(halText({"-s", "show", "sig"}));
    const ScopedTempDir tmp("hal-methods");
    const std::string dir = tmp.string();
    const std::string cli = std::string(AXISTUNE_CLI) + " capture --connect hal: --axis pid.x ";
    const Plant plant = readPlant();
    for (const std::string method : {"multisweep", "prbs"}) {
        SCOPED_TRACE(method);
        const std::string out = dir + "/hal-" + method + ".csv";
        ASSERT_EQ(std::system((cli + "--test frf --method " + method +
                               " --fmin 5 --fmax 400 --points 12 --amplitude "
                               "0.2 --out " +
                               out + " >" + dir + "/hal-" + method + ".json")
                                  .c_str()),
                  0);
        auto frf = io::readFrfCsvFile(out);
        ASSERT_TRUE(frf) << frf.error().detail;
        EXPECT_EQ(frf->metadata.text("method"), method);
        EXPECT_EQ(frf->metadata.text("quantity"), "plant");
        EXPECT_EQ(frf->metadata.text("connection"), "hal:");
        EXPECT_EQ(frf->metadata.number("fs_Hz").value(), 1000.0);
        ASSERT_GE(frf->size(), 8u);
        if (method == "multisweep") {
            // The CSV's 17 digits keep the measurement's 0.1 dB / 0.5° (MultiSweepPlantFrfEquals... above).
            for (std::size_t i = 0; i < frf->size(); ++i) {
                const std::complex<double> ratio = frf->h[i] / exactResponse(plant, 1e-3, frf->freqHz[i]);
                EXPECT_LE(std::abs(20.0 * std::log10(std::abs(ratio))), 0.1) << frf->freqHz[i] << " Hz";
                EXPECT_LE(std::abs(std::arg(ratio)) * 180.0 / M_PI, 0.5) << frf->freqHz[i] << " Hz";
            }
        }
    }
    const std::string stepOut = dir + "/hal-step.csv";
    ASSERT_EQ(std::system(
                  (cli + "--test step --amplitude 0.01 --duration 0.3 --out " + stepOut + " >" + dir + "/hal-step.json")
                      .c_str()),
              0);
    auto cap = io::readCaptureCsvFile(stepOut);
    ASSERT_TRUE(cap) << cap.error().detail;
    EXPECT_EQ(cap->metadata.text("test"), "step");
    ASSERT_TRUE(cap->channel("position_offset"));
    EXPECT_EQ(cap->size(), 30u + 600u);
    // A step above half of FERROR (5 mm) is refused with exit 2 before anything moves.
    EXPECT_EQ(WEXITSTATUS(std::system((cli + "--test step --amplitude 3 --duration 0.3 --out " + dir + "/never.csv 2>" +
                                       dir + "/step-err.txt")
                                          .c_str())),
              2);
    EXPECT_FALSE(std::filesystem::exists(dir + "/never.csv"));
    EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), sigBefore);
}

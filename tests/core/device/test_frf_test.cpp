// SPDX-License-Identifier: GPL-3.0-or-later
// FRF test of the simulated drive (issue 3 items 6–7, issue 6): plan properties, the closed loop
// T = PC/(1+PC) measured on sim:two-inertia and (linear) sim:dd-table against the independent lifted
// model of tests/core/sim/LiftedModel.h, the injection-hold correction for every method, the 3.3 kHz
// mode of sim:dd-table above the observation Nyquist frequency, conventional validity flags,
// amplitude refusal and abort.
#include "core/device/FrfTest.h"
#include "core/device/SimulatedDrive.h"
#include "core/dsp/FrequencyResponse.h"
#include "tests/core/sim/LiftedModel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include "tests/core/device/DriveTestUtil.h"

using namespace axistune;
using namespace axistune::device;

namespace {

using devtest::makeDrive;
using devtest::runFrf;

/// The closed velocity loop T = PC/(1+PC) of the discrete loop: −T_c/d of the lifted model for a
/// disturbance d that enters like T_c, held over the velocity period (every current tick of the
/// period sees d[k]). No injection-hold factor enters this reference.
std::complex<double> heldClosedLoop(const simtest::LiftedInjectionLoop& model, double fHz)
{
    const std::complex<double> z = std::polar(1.0, 2.0 * std::numbers::pi * fHz * model.periodS);
    const Eigen::VectorXcd rhs = model.g.rowwise().sum().cast<std::complex<double>>();
    const Eigen::MatrixXcd m = z * Eigen::MatrixXcd::Identity(model.a.rows(), model.a.cols()) - model.a.cast<std::complex<double>>();
    return -(model.torqueCmd.cast<std::complex<double>>() * m.partialPivLu().solve(rhs))(0);
}

/// T = C·P(ω)/(1 + C·P_v) with P the plant at the true frequency ω (also above the velocity loop's
/// Nyquist frequency): −T_c/d of the lifted model for d at every current tick, times the fundamental
/// (1/N)·Σ_{m<N} e^{−jωmh} of a velocity-period hold (N current ticks) — the torque T_c actually
/// delivers — summed here tick by tick. Equals heldClosedLoop where the images of P are negligible.
std::complex<double> trueFrequencyClosedLoop(const simtest::LiftedInjectionLoop& model, double fHz)
{
    const auto n = static_cast<int>(std::lround(model.periodS / model.currentPeriodS));
    std::complex<double> fundamental = 0.0;
    for (int m = 0; m < n; ++m)
        fundamental += std::polar(1.0 / n, -2.0 * std::numbers::pi * fHz * m * model.currentPeriodS);
    return model.closedLoop(fHz) * fundamental;
}

/// |a/b − 1| and arg(a/b) in degrees.
struct Deviation {
    double rel = 0.0, deg = 0.0;
};
Deviation deviation(std::complex<double> a, std::complex<double> b)
{
    return {std::abs(a / b - 1.0), std::arg(a / b) * 180.0 / std::numbers::pi};
}

}  // namespace

TEST(FrfTest, LoopTimeConstantIsTheSlowPoleOfTheVelocityPi)
{
    auto def = sim::loadPreset("two-inertia");
    ASSERT_TRUE(def.ok());
    const auto& v = def->axes.front().values;
    auto t = loopTimingFromParameters(v);
    ASSERT_TRUE(t.ok());
    // s = −1/τ must be a root of J s² + k_p s + k_i, and the slower of the two real roots.
    const double j = v.at("velocity.inertia"), kp = v.at("velocity.kp"), ki = v.at("velocity.ki");
    const double s = -1.0 / t->timeConstantS;
    EXPECT_NEAR((j * s * s + kp * s + ki) / ki, 0.0, 1e-9);
    EXPECT_GT(s, -kp / (2.0 * j));
    EXPECT_DOUBLE_EQ(t->settleS, 5.0 * t->timeConstantS);
    auto bad = v;
    bad["velocity.inertia"] = 0.0;
    EXPECT_FALSE(loopTimingFromParameters(bad).ok());
}

TEST(FrfTest, MultiSweepWindowsAreThreeThirdsOfOneContinuousSine)
{
    FrfPlanOptions o;
    o.fsHz = 4000.0;
    o.fminHz = 10.0;
    o.fmaxHz = 3900.0;
    o.points = 25;
    o.amplitudeNm = 2.0;
    o.timing = {0.01, 0.05, 8.0, 0.5, 0.02};
    auto plan = planFrfTest(o);
    ASSERT_TRUE(plan.ok()) << plan.error().detail;
    ASSERT_EQ(plan->segments.size() % 3, 0u);
    for (std::size_t i = 0; i < plan->segments.size(); i += 3) {
        const auto& s0 = plan->segments[i];
        const double f = s0.freqHz;
        // Each window spans p + 1/3 periods, so the next window starts 120° further on.
        const double cycles = f * static_cast<double>(s0.measureSamples) / o.fsHz;
        EXPECT_NEAR(cycles - 1.0 / 3.0, std::round(cycles - 1.0 / 3.0), 1e-9) << f;
        EXPECT_GE(3.0 * static_cast<double>(s0.measureSamples) / o.fsHz, 0.02 - 1.0 / o.fsHz);
        EXPECT_GE(static_cast<double>(s0.settleSamples) / o.fsHz, std::max(0.05, std::min(8.0 / f, 0.5)) - 1e-12);
        for (int w = 0; w < 3; ++w) {
            const auto& s = plan->segments[i + static_cast<std::size_t>(w)];
            EXPECT_EQ(s.freqHz, f);
            EXPECT_DOUBLE_EQ(s.phaseOffsetDeg, std::vector<double>({0.0, 120.0, -120.0})[static_cast<std::size_t>(w)]);
            for (double k : {0.0, 0.25, 1.0, 7.5}) {
                const double pos = static_cast<double>(s.windowStart) + k;
                const double expected = 2.0 * std::sin(2.0 * std::numbers::pi * f * (pos - static_cast<double>(s0.windowStart)) / o.fsHz);
                EXPECT_NEAR(frfExcitation(*plan, pos), expected, 1e-9) << f << " window " << w;
            }
        }
        if (i > 0) {
            EXPECT_GT(f, plan->segments[i - 3].freqHz);
        }
        EXPECT_NEAR(f / (10.0 * std::pow(390.0, (i / 3) / 24.0)), 1.0, 1e-2);
    }
    EXPECT_EQ(plan->totalSamples, static_cast<std::size_t>(plan->segments.back().windowStart) + plan->segments.back().measureSamples);
}

TEST(FrfTest, PlanRefusesBadRanges)
{
    FrfPlanOptions o;
    o.amplitudeNm = 1.0;
    o.timing = {0.01, 0.05, 8.0, 0.5, 0.02};
    o.fmaxHz = 4000.0;
    EXPECT_FALSE(planFrfTest(o).ok());  // not below fs
    o.fmaxHz = 2500.0;
    o.method = FrfMethod::Prbs;
    EXPECT_FALSE(planFrfTest(o).ok());  // PRBS only up to fs/2
    o.method = FrfMethod::MultiSweep;
    o.points = 0;
    EXPECT_FALSE(planFrfTest(o).ok());
    o.points = 10;
    o.fminHz = -1.0;
    EXPECT_FALSE(planFrfTest(o).ok());
    o.fminHz = 10.0;
    o.amplitudeNm = 0.0;
    EXPECT_FALSE(planFrfTest(o).ok());
}

// Issue 3 / issue 6: on sim:two-inertia the drive's FRF is the closed velocity loop T = PC/(1+PC)
// (the injection hold corrected by the drive, no factor applied here): within 1 % and 1° of the
// discrete closed loop of the lifted model built in the test from the preset's parameters, from 5 Hz
// to 300 Hz, with all the preset's nonlinearities and noise.
TEST(SimulatedDriveFrf, TwoInertiaMatchesTheAnalyticClosedLoop)
{
    auto def = sim::loadPreset("two-inertia");
    ASSERT_TRUE(def.ok());
    const auto model = simtest::buildLiftedInjectionLoop(def->axes.front());
    auto drive = makeDrive("two-inertia");
    TestRequest r;
    r.axis = "A";
    auto& frf = r.test.emplace<FrfTest>();
    frf.fminHz = 5.0;
    frf.fmaxHz = 300.0;
    frf.points = 15;
    const auto m = runFrf(*drive, r);
    ASSERT_EQ(m.frf.size(), 15u);
    EXPECT_EQ(m.frf.metadata.text("method"), "multisweep");
    EXPECT_EQ(m.frf.metadata.text("injection_hold_corrected"), "true");
    EXPECT_EQ(m.frf.metadata.number("injection_hold_ticks").value(), 4.0);
    for (std::size_t i = 0; i < m.frf.size(); ++i) {
        const double f = m.frf.freqHz[i];
        EXPECT_TRUE(m.frf.valid[i]) << f;
        const auto dev = deviation(m.frf.h[i], heldClosedLoop(model, f));
        EXPECT_LT(dev.rel, 0.01) << f << " Hz";
        EXPECT_NEAR(dev.deg, 0.0, 1.0) << f << " Hz";
    }
    // The sweep recording keeps the raw −T_c/d and names the hold for a re-analysis.
    EXPECT_FALSE(m.sweep.metadata.contains("injection_hold_corrected"));
    EXPECT_EQ(m.sweep.metadata.number("injection_hold_ticks").value(), 4.0);
    // The parameters return after the test.
    EXPECT_DOUBLE_EQ(drive->simulator("A")->parameter("trace.divider"), 1.0);
}

// Issue 6: the corrected multi-sweep FRF of the linear sim:dd-table (10 Hz … 3.9 kHz, 60 points)
// matches the closed loop at the true frequency within 1 % and 1° at every valid point, up to the
// highest valid frequency (above fs/2 = 2 kHz too; an absolute floor of −120 dB for the −97 dB point
// at 3.9 kHz, measured worst elsewhere 0.5 % / 0.3° at the −66 dB point at 2.9 kHz); below 400 Hz, where the images of the plant at
// ±4 kHz are negligible, it is also within 1 % / 1° of the discrete closed loop without any factor.
// The uncorrected −T_c/d is off by 10° at 300 Hz and 34° at 1 kHz (the factor this test must see gone).
TEST(SimulatedDriveFrf, DdTableLinearMatchesTheClosedLoopUpToTheHighestValidFrequency)
{
    auto def = sim::loadPreset("dd-table");
    ASSERT_TRUE(def.ok());
    const auto model = simtest::buildLiftedInjectionLoop(def->axes.front());
    auto drive = makeDrive("dd-table");
    drive->simulator("C")->setNonlinearities({false, false, false, false, false});
    TestRequest r;
    r.axis = "C";
    auto& frf = r.test.emplace<FrfTest>();
    frf.fminHz = 10.0;
    frf.fmaxHz = 3900.0;
    frf.points = 60;
    frf.amplitudePct = 3.0;
    const auto m = runFrf(*drive, r);
    ASSERT_GE(m.frf.size(), 55u);
    double highest = 0.0, worstRel = 0.0, worstDeg = 0.0;
    for (std::size_t i = 0; i < m.frf.size(); ++i) {
        if (!m.frf.valid[i])
            continue;
        const double f = m.frf.freqHz[i];
        highest = f;
        const auto ref = trueFrequencyClosedLoop(model, f);
        const auto dev = deviation(m.frf.h[i], ref);
        worstRel = std::max(worstRel, dev.rel);
        worstDeg = std::max(worstDeg, std::abs(dev.deg));
        // 1 %, with a floor of 1e-6 (−120 dB) for the −97 dB zero of T near 3.9 kHz (1.5 % there).
        EXPECT_LT(std::abs(m.frf.h[i] - ref), 0.01 * std::abs(ref) + 1e-6) << f << " Hz";
        EXPECT_NEAR(dev.deg, 0.0, 1.0) << f << " Hz";
        if (f < 400.0) {
            const auto held = deviation(m.frf.h[i], heldClosedLoop(model, f));
            EXPECT_LT(held.rel, 0.01) << f << " Hz";
            EXPECT_NEAR(held.deg, 0.0, 1.0) << f << " Hz";
        }
    }
    EXPECT_GT(highest, 3800.0);
    std::printf("dd-table linear: worst %.4f %% / %.3f deg up to %.1f Hz\n", 100.0 * worstRel, worstDeg, highest);
}

// Issue 6: PRBS injects d held over one trace sample, like T_c: with trace divider 1 the Welch FRF is
// the closed loop without any factor (the sine streams' factor would add 8° at 280 Hz and 31° at
// 860 Hz). Tolerance: the Welch estimate of a linear loop reaches 0.99 coherence here, 5 % / 2°.
TEST(SimulatedDriveFrf, PrbsIsTheClosedLoopWithoutAHoldFactor)
{
    auto def = sim::loadPreset("two-inertia");
    ASSERT_TRUE(def.ok());
    const auto model = simtest::buildLiftedInjectionLoop(def->axes.front());
    auto drive = makeDrive("two-inertia");
    drive->simulator("A")->setNonlinearities({false, false, false, false, false});
    TestRequest r;
    r.axis = "A";
    auto& frf = r.test.emplace<FrfTest>();
    frf.method = FrfMethod::Prbs;
    frf.fminHz = 40.0;
    frf.fmaxHz = 1000.0;
    frf.points = 12;
    const auto m = runFrf(*drive, r);
    ASSERT_GE(m.frf.size(), 6u);
    EXPECT_EQ(m.frf.metadata.text("injection_hold_corrected"), "true");
    EXPECT_EQ(m.frf.metadata.number("injection_hold_velocity_periods").value(), 1.0);
    for (std::size_t i = 0; i < m.frf.size(); ++i) {
        const double f = m.frf.freqHz[i];
        const auto dev = deviation(m.frf.h[i], heldClosedLoop(model, f));
        EXPECT_LT(dev.rel, 0.05) << f << " Hz";
        EXPECT_NEAR(dev.deg, 0.0, 2.0) << f << " Hz";
    }
}

// The independent model itself: integral action makes T → 1 at low frequency.
TEST(SimulatedDriveFrf, LiftedInjectionModelTendsToOneAtLowFrequency)
{
    auto def = sim::loadPreset("two-inertia");
    ASSERT_TRUE(def.ok());
    const auto model = simtest::buildLiftedInjectionLoop(def->axes.front());
    EXPECT_NEAR(std::abs(model.closedLoop(0.05) - 1.0), 0.0, 1e-3);
}

// Issue 3: on sim:dd-table the multi-sweep FRF shows the 3.3 kHz resonance within 2 % of its
// frequency, and the conventional FRF marks everything above 2 kHz (fs/2 at 4 kHz tracing) invalid.
// The preset as it is, all nonlinearities on: its 2^29 counts/rev encoder resolves the nanoradian
// motion of the table at kilohertz (the former 3.6e6 counts/rev did not; docs/frequency-response-sim.md).
TEST(SimulatedDriveFrf, DdTableMultiSweepShowsThe3300HzModeAndConventionalIsInvalidAboveNyquist)
{
    auto drive = makeDrive("dd-table");
    TestRequest r;
    r.axis = "C";
    auto& frf = r.test.emplace<FrfTest>();
    frf.fminHz = 2600.0;
    frf.fmaxHz = 3900.0;
    frf.points = 30;
    frf.amplitudePct = 3.0; // at 5 % the current loop reaches its voltage limit near 2.6–2.9 kHz
    const auto m = runFrf(*drive, r);
    std::size_t peak = 0;
    for (std::size_t i = 0; i < m.frf.size(); ++i) {
        EXPECT_TRUE(m.frf.valid[i]) << m.frf.freqHz[i];
        if (std::abs(m.frf.h[i]) > std::abs(m.frf.h[peak]))
            peak = i;
    }
    EXPECT_NEAR(m.frf.freqHz[peak], 3300.0, 0.02 * 3300.0);
    // A peak, not the end of a slope.
    ASSERT_GT(peak, 0u);
    ASSERT_LT(peak + 1, m.frf.size());

    frf.method = FrfMethod::Conventional;
    frf.fminHz = 100.0;
    frf.points = 16;
    const auto c = runFrf(*drive, r);
    ASSERT_GE(c.frf.size(), 14u);
    std::size_t above = 0;
    for (std::size_t i = 0; i < c.frf.size(); ++i) {
        if (c.frf.freqHz[i] >= 2000.0) {
            EXPECT_FALSE(c.frf.valid[i]) << c.frf.freqHz[i];
            ++above;
        } else {
            EXPECT_TRUE(c.frf.valid[i]) << c.frf.freqHz[i];
        }
    }
    EXPECT_GE(above, 3u);
    EXPECT_EQ(c.frf.metadata.text("method"), "conventional");
    EXPECT_EQ(c.frf.metadata.text("injection_hold_corrected"), "true");
}

TEST(SimulatedDriveFrf, AmplitudeAboveTheLimitIsRefusedAndAbortRestores)
{
    auto drive = makeDrive("two-inertia");
    TestRequest r;
    r.axis = "A";
    auto& frf = r.test.emplace<FrfTest>();
    frf.amplitudePct = drive->limits(r.axis).value().frfAmplitudeMaxPct + 1.0; // the drive's own limit
    auto st = drive->startTest(r);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::OutOfRange);
    EXPECT_NE(st.error().detail.find("refused"), std::string::npos);
    EXPECT_EQ(drive->pollTest()->state, TestState::Idle);

    frf.amplitudePct = 5.0;
    frf.fmaxHz = 1000.0;
    r.traceDivider = 2;
    ASSERT_TRUE(drive->startTest(r).ok());
    EXPECT_DOUBLE_EQ(drive->simulator("A")->parameter("trace.divider"), 2.0);
    (void)drive->pollTest();
    ASSERT_TRUE(drive->abortTest().ok());
    EXPECT_EQ(drive->pollTest()->state, TestState::Aborted);
    EXPECT_DOUBLE_EQ(drive->simulator("A")->parameter("trace.divider"), 1.0);
    EXPECT_FALSE(drive->readFrequencyResponse().ok());
    // The injection is gone: the axis stays at rest afterwards.
    auto* sim = drive->simulator("A");
    sim->startTrace();
    sim->run(0.2);
    const auto cap = sim->takeTrace();
    for (double d : cap.channel("injection_Nm")->data)
        ASSERT_EQ(d, 0.0);
}

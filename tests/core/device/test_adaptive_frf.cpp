// SPDX-License-Identifier: GPL-3.0-or-later
// Adaptive multisine FRF (core/device/AdaptiveFrf.h, issue 18 item 2) on the realistic sim:dd-table axis C
// (friction, quantization and noise on, as `axistune-cli capture --connect sim:dd-table` runs it):
//  * within the 5 s budget it finds the 3.3 kHz mode within 2 % (the criterion), makes more lines valid
//    than the plain multisine with the same motion time (16 periods, the comparison), and says why every
//    line left is invalid;
//  * its valid lines agree with the independent lifted model (tests/core/sim/LiftedModel.h) within the 0.5 dB / 3°
//    of issue 11 above 100 Hz (below, the preset's Coulomb friction distorts every method);
//  * through the seam: the host's evaluation of a drive that streams samples only gives the same result, and a
//    drive that takes no spectrum (Modbus) gets flat bands;
//  * refusals.
#include "core/device/AdaptiveFrf.h"
#include "core/device/Drive.h"
#include "core/device/SimulatedDrive.h"
#include "core/device/TestRunner.h"
#include "core/dsp/InjectionHold.h"
#include "core/sim/MachineDefinition.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "tests/core/device/DriveTestUtil.h"
#include "tests/core/sim/LiftedModel.h"

using namespace axistune;
using namespace axistune::device;

namespace {

/// Forwards everything to a drive; optionally hides readFrequencyResponse (a drive that streams samples only, the
/// host evaluates) and refuses a shaped multisine (as the Modbus register map does).
class WrappedDrive : public devtest::ForwardingDrive {
public:
    WrappedDrive(Drive& inner, bool samplesOnly, bool refuseShape)
        : ForwardingDrive(inner), m_samplesOnly(samplesOnly), m_refuseShape(refuseShape)
    {
    }
    Status startTest(const TestRequest& r) override
    {
        if (auto st = refuse(r); !st)
            return st;
        return m_inner.startTest(r);
    }
    Result<FrfMeasurement> readFrequencyResponse() override
    {
        return m_samplesOnly ? Drive::readFrequencyResponse() : m_inner.readFrequencyResponse();
    }
    Result<TestPlan> planTest(const TestRequest& r) override
    {
        if (auto st = refuse(r); !st)
            return st.error();
        return m_inner.planTest(r);
    }

private:
    Status refuse(const TestRequest& r) const
    {
        if (m_refuseShape && r.is<FrfTest>() && !r.frf().multisineShape.empty())
            return makeError(ErrorCode::BadInput, "a shaped multisine cannot be sent (test)");
        return Status::success();
    }
    bool m_samplesOnly, m_refuseShape;
};

std::unique_ptr<Drive> realisticDdTable()
{
    auto d = connect({"sim:dd-table", 1});
    EXPECT_TRUE(d.ok()) << (d ? "" : d.error().detail);
    return d ? std::move(d).value() : nullptr;
}

/// The first pass: what `capture --test frf --method multisine --fmin 20 --fmax 3900` runs (5 % peak, 10 Hz).
TestRequest firstPass()
{
    TestRequest r;
    r.axis = "C";
    auto& f = r.test.emplace<FrfTest>();
    f.method = FrfMethod::Multisine;
    f.fminHz = 20.0;
    f.fmaxHz = 3900.0;
    f.amplitudePct = 5.0;
    return r;
}

std::size_t validCount(const dsp::FrequencyResponse& f)
{
    return static_cast<std::size_t>(std::count(f.valid.begin(), f.valid.end(), true));
}

/// The largest valid |T| above 2.6 kHz (the 3.3 kHz mode, test_multisine_test.cpp), npos when none.
std::size_t modePeak(const dsp::FrequencyResponse& f)
{
    std::size_t peak = std::string::npos;
    for (std::size_t i = 0; i < f.size(); ++i)
        if (f.valid[i] && f.freqHz[i] > 2600.0 && (peak == std::string::npos || std::abs(f.h[i]) > std::abs(f.h[peak])))
            peak = i;
    return peak;
}

} // namespace

TEST(AdaptiveFrf, RealisticDdTableFindsTheModeWithinTheBudgetAndExplainsWhatIsLeft)
{
    auto drive = realisticDdTable();
    ASSERT_TRUE(drive);
    AdaptiveFrfOptions o; // 5 s of motion
    std::vector<std::pair<double, std::string>> progress;
    RunOptions ro;
    ro.progress = [&progress](double f, const std::string& detail) { progress.emplace_back(f, detail); };
    auto res = runAdaptiveFrf(*drive, firstPass(), o, ro);
    ASSERT_TRUE(res.ok()) << res.error().detail;
    const auto& f = res->measurement.frf;
    ASSERT_EQ(f.size(), 388u); // the first pass's lines: 20 Hz … 3.9 kHz every 10 Hz
    // One progress over all passes (the GUI's bar): never falling, a share of the budget, 1 at the end; each pass
    // named.
    ASSERT_GE(progress.size(), 3u);
    for (std::size_t i = 1; i < progress.size(); ++i)
        ASSERT_GE(progress[i].first, progress[i - 1].first) << i << ": " << progress[i].second;
    EXPECT_EQ(progress.back().first, 1.0);
    EXPECT_NE(progress.back().second.find(std::to_string(res->validLines) + " of 388 lines valid"), std::string::npos)
        << progress.back().second;
    const auto lastPass = std::find_if(progress.rbegin() + 1, progress.rend(), [&](const auto& p) {
        return p.second.rfind("adaptive multisine, pass " + std::to_string(res->passes.size()), 0) == 0;
    });
    ASSERT_NE(lastPass, progress.rend());
    // The last pass's own end: the motion of all passes over the budget (the drive's motion and its plan agree
    // within a current tick, 62.5 µs, per pass).
    EXPECT_NEAR(lastPass->first, res->motionTimeS / o.timeBudgetS, 1e-3);
    const double fraction = static_cast<double>(validCount(f)) / static_cast<double>(f.size());
    std::cout << "adaptive: " << res->passes.size() << " passes, motion " << res->motionTimeS << " s, valid "
              << validCount(f) << " of " << f.size() << " (" << fraction * 100.0 << " %)\n";
    // The budget holds (the drive advances in whole current ticks: 62.5 µs).
    EXPECT_LE(res->motionTimeS, 5.0 + 62.5e-6);
    EXPECT_NEAR(res->measurement.motionTimeS, res->motionTimeS, 1e-12);
    EXPECT_GE(res->passes.size(), 2u);
    EXPECT_EQ(res->validLines, validCount(f));
    // Every line left is named with a reason, and only those.
    EXPECT_EQ(res->invalid.size() + res->validLines, f.size());
    for (const auto& l : res->invalid) {
        const auto it = std::find(f.freqHz.begin(), f.freqHz.end(), l.freqHz);
        ASSERT_NE(it, f.freqHz.end());
        EXPECT_FALSE(f.valid[static_cast<std::size_t>(it - f.freqHz.begin())]);
    }
    // The 3.3 kHz mode within 2 % (issue 18), a peak and not the end of a slope.
    const auto peak = modePeak(f);
    ASSERT_NE(peak, std::string::npos);
    EXPECT_NEAR(f.freqHz[peak], 3300.0, 0.02 * 3300.0);
    ASSERT_LT(peak + 1, f.size());
    // More valid lines than the plain multisine with at least the same motion time: 16 periods (5.14 s), the
    // issue's comparison, on a fresh drive with the same seed.
    auto plainDrive = realisticDdTable();
    auto plainReq = firstPass();
    plainReq.frf().multisinePeriods = 16;
    auto plain = runTest(*plainDrive, plainReq);
    ASSERT_TRUE(plain.ok() && plain->frf);
    ASSERT_GE(plain->frf->motionTimeS, res->motionTimeS);
    const std::size_t plainValid = validCount(plain->frf->frf);
    std::cout << "plain multisine, 16 periods: motion " << plain->frf->motionTimeS << " s, valid " << plainValid
              << "\n";
    EXPECT_GT(validCount(f), plainValid + 20);
}

// The combined lines are right: on the preset with its noise only (friction, quantization, inductance drop and lost
// motion off, so that the linear lifted model of tests/core/sim/LiftedModel.h is the truth), every valid line agrees
// with the model within 3.5 times the validity limit σ_H/|H| = 0.03 (|ΔH| of a complex Gaussian exceeds 3.5σ with
// probability e^(−12.25) ≈ 5e-6 per line; the limit and not a line's own σ, which comes from a few periods and is
// uncertain by about ±40 %) plus the model's own 0.5 dB / 3° of issue 11 (≈ 6 % of |H|).
TEST(AdaptiveFrf, ValidLinesAgreeWithTheLiftedModel)
{
    auto def = sim::loadPreset("dd-table");
    ASSERT_TRUE(def.ok());
    const auto model = simtest::buildLiftedInjectionLoop(def->axes.front());
    auto created = SimulatedDrive::create(*def, 1);
    ASSERT_TRUE(created.ok());
    auto drive = std::move(created).value();
    sim::Nonlinearities noiseOnly{false, false, false, false, false};
    noiseOnly.noise = true;
    drive->simulator("C")->setNonlinearities(noiseOnly);
    auto res = runAdaptiveFrf(*drive, firstPass(), {});
    ASSERT_TRUE(res.ok()) << res.error().detail;
    const auto& m = res->measurement;
    const auto& f = m.frf;
    ASSERT_TRUE(dsp::isInjectionHoldCorrected(f));
    ASSERT_EQ(m.relativeNoise.size(), f.size());
    const int n = static_cast<int>(f.metadata.integer("injection_hold_ticks").value());
    const double h = f.metadata.number("injection_hold_period_s").value();
    std::size_t compared = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
        if (!f.valid[i])
            continue;
        const auto ref = model.closedLoop(f.freqHz[i]) / dsp::injectionHoldFactor(f.freqHz[i], h, n);
        const double rel = std::abs(f.h[i] / ref - 1.0);
        EXPECT_LE(m.relativeNoise[i], 0.03) << f.freqHz[i] << " Hz";
        EXPECT_LE(rel, 3.5 * 0.03 + 0.06) << f.freqHz[i] << " Hz";
        worst = std::max(worst, rel);
        if (rel > 0.05)
            std::cout << "DBG " << f.freqHz[i] << " rel " << rel << " r " << m.relativeNoise[i] << " dB "
                      << dsp::magnitudeDb(f.h[i] / ref) << " deg " << std::arg(f.h[i] / ref) * 57.3 << "\n";
        ++compared;
    }
    std::cout << "noise-only: " << compared << " valid lines, worst |H/H_model - 1| " << worst << "\n";
    EXPECT_GT(compared, 200u);
}

TEST(AdaptiveFrf, WorksThroughTheSeamHostEvaluatedAndWithoutAShapedSpectrum)
{
    // Host evaluation: the same passes and the same FRF as when the drive evaluates (same seed, same samples).
    auto a = realisticDdTable();
    auto b = realisticDdTable();
    ASSERT_TRUE(a && b);
    WrappedDrive samplesOnly(*b, true, false);
    auto ra = runAdaptiveFrf(*a, firstPass(), {});
    auto rb = runAdaptiveFrf(samplesOnly, firstPass(), {});
    ASSERT_TRUE(ra.ok() && rb.ok());
    ASSERT_EQ(ra->passes.size(), rb->passes.size());
    ASSERT_EQ(ra->measurement.frf.size(), rb->measurement.frf.size());
    EXPECT_EQ(ra->validLines, rb->validLines);
    for (std::size_t i = 0; i < ra->measurement.frf.size(); ++i)
        EXPECT_NEAR(std::abs(ra->measurement.frf.h[i] - rb->measurement.frf.h[i]), 0.0,
                    1e-9 * std::abs(ra->measurement.frf.h[i]));
    EXPECT_EQ(rb->measurement.frf.metadata.text("evaluated_by"), "host");

    // A drive that takes no spectrum: the passes after the first are flat bands, and they still add lines.
    auto c = realisticDdTable();
    ASSERT_TRUE(c);
    WrappedDrive flat(*c, false, true);
    auto rc = runAdaptiveFrf(flat, firstPass(), {});
    ASSERT_TRUE(rc.ok()) << rc.error().detail;
    ASSERT_GE(rc->passes.size(), 2u);
    for (std::size_t k = 1; k < rc->passes.size(); ++k) {
        EXPECT_FALSE(rc->passes[k].shaped);
        EXPECT_LE(rc->passes[k].bands, 4u);
    }
    EXPECT_GT(rc->validLines, rc->passes.front().validAfter);
    EXPECT_LE(rc->motionTimeS, 5.0 + 62.5e-6);
}

TEST(AdaptiveFrf, Refusals)
{
    auto drive = realisticDdTable();
    ASSERT_TRUE(drive);
    auto r = firstPass();
    r.frf().method = FrfMethod::MultiSweep;
    auto res = runAdaptiveFrf(*drive, r, {});
    ASSERT_FALSE(res.ok());
    EXPECT_EQ(res.error().code, ErrorCode::BadInput);
    AdaptiveFrfOptions o;
    o.timeBudgetS = 0.5; // the first pass alone takes 0.943 s
    res = runAdaptiveFrf(*drive, firstPass(), o);
    ASSERT_FALSE(res.ok());
    EXPECT_NE(res.error().detail.find("time budget"), std::string::npos) << res.error().detail;
    o.timeBudgetS = std::nan("");
    EXPECT_FALSE(runAdaptiveFrf(*drive, firstPass(), o).ok());
    // Beyond the drive's own amplitude limit: the drive's refusal, before anything moves.
    r = firstPass();
    r.frf().amplitudePct = 80.0;
    res = runAdaptiveFrf(*drive, r, {});
    ASSERT_FALSE(res.ok());
}

// The passes after the first have phases designed for the current loop's voltage (its crest factor, not the torque's,
// holds the excitation): each such pass reaches the peak voltage it was designed for (within 5 %: the current
// noise alone gives about 6 V peak at a hold, 2.5 % of the 240 V aimed at) without reaching the limit, and against
// phases designed for the torque (voltage crest factor about 3, where the designed one stays below 2:
// test_multisine.cpp) the same time budget excites at least 1.5 times the torque and validates more lines.
TEST(AdaptiveFrf, PhasesDesignedForTheVoltageMeetTheirPredictionAndExciteMore)
{
    auto drive = realisticDdTable();
    ASSERT_TRUE(drive);
    const std::vector<std::string> keys{"drive.max_voltage"};
    auto vmax = drive->readParameters("C", keys);
    ASSERT_TRUE(vmax.ok());
    const double maxV = vmax->at("drive.max_voltage");
    auto res = runAdaptiveFrf(*drive, firstPass(), AdaptiveFrfOptions{});
    ASSERT_TRUE(res.ok()) << res.error().detail;
    ASSERT_GE(res->passes.size(), 2u);
    EXPECT_TRUE(std::isnan(res->passes.front().voltagePredictedV));
    double peakPct = 0.0;
    for (std::size_t k = 1; k < res->passes.size(); ++k) {
        const auto& p = res->passes[k];
        ASSERT_TRUE(std::isfinite(p.voltagePredictedV)) << k;
        EXPECT_NEAR(p.voltagePeakV, p.voltagePredictedV, 0.05 * p.voltagePredictedV) << "pass " << k;
        EXPECT_LE(p.voltagePredictedV, 0.85 * maxV * (1.0 + 1e-9)) << "pass " << k;
        EXPECT_FALSE(p.voltageReached) << "pass " << k;
        peakPct = std::max(peakPct, p.peakPct);
    }
    auto torqueDrive = realisticDdTable();
    AdaptiveFrfOptions o;
    o.phasesForVoltage = false;
    auto torquePhases = runAdaptiveFrf(*torqueDrive, firstPass(), o);
    ASSERT_TRUE(torquePhases.ok()) << torquePhases.error().detail;
    double torquePeakPct = 0.0;
    for (std::size_t k = 1; k < torquePhases->passes.size(); ++k) {
        EXPECT_TRUE(std::isnan(torquePhases->passes[k].voltagePredictedV));
        torquePeakPct = std::max(torquePeakPct, torquePhases->passes[k].peakPct);
    }
    std::cout << "peak torque of the later passes: " << peakPct << " % (phases for the voltage), " << torquePeakPct
              << " % (for the torque); valid lines " << res->validLines << ", " << torquePhases->validLines << "\n";
    EXPECT_GE(peakPct, 1.5 * torquePeakPct);
    EXPECT_GT(res->validLines, torquePhases->validLines);
    EXPECT_LE(res->motionTimeS, 5.0 + 62.5e-6);
}

// SPDX-License-Identifier: GPL-3.0-or-later
// The amplitude map and the reversal backlash (core/autotune/AmplitudeMap.h) on the embedded simulated vmc X and
// variants of it built in the test from the preset (coulomb_motor, backlash changed): the reference for "non-linear"
// is a linear run of the same machine with its Coulomb friction switched off (docs/simulator.md: friction is the
// only amplitude-dependent element of vmc X at these torques), the reference for the backlash the variant's own
// plant.backlash.
#include "core/autotune/AmplitudeMap.h"
#include "core/autotune/AutoTune.h"
#include "core/device/SimulatedDrive.h"
#include "core/sim/MachineDefinition.h"

#include <cmath>
#include <complex>
#include <gtest/gtest.h>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "tests/core/device/DriveTestUtil.h"

using namespace axistune;

namespace {

std::unique_ptr<device::Drive> vmcX(double coulombMotorNm, double backlashM = 0.0)
{
    auto def = sim::loadPreset("vmc");
    EXPECT_TRUE(def.ok());
    if (!def.ok())
        return nullptr;
    sim::MachineDefinition m = *def;
    for (auto& a : m.axes)
        if (a.name == "X") {
            if (coulombMotorNm >= 0.0)
                a.values["plant.coulomb_motor"] = coulombMotorNm;
            a.values["plant.backlash"] = backlashM;
        }
    auto d = device::SimulatedDrive::create(m, 1);
    EXPECT_TRUE(d.ok());
    return d.ok() ? std::unique_ptr<device::Drive>(std::move(d).value()) : nullptr;
}

autotune::AmplitudeMap map(device::Drive& d)
{
    autotune::AmplitudeMapOptions o;
    o.axis = "X";
    o.amplitudesPct = {5.0, 10.0, 20.0};
    auto m = autotune::measureAmplitudeMap(d, o);
    EXPECT_TRUE(m.ok()) << (m.ok() ? "" : m.error().detail);
    return m.ok() ? *m : autotune::AmplitudeMap{};
}

struct Counts {
    int lines = 0, flagged = 0;
};
Counts countBand(const autotune::AmplitudeMap& m, double lo, double hi)
{
    Counts c;
    for (const auto& l : m.lines)
        if (l.freqHz >= lo && l.freqHz < hi && l.compared) {
            ++c.lines;
            c.flagged += l.nonlinear ? 1 : 0;
        }
    return c;
}

/// Of the lines the map flags, the fraction that differ at one of the amplitudes from the linear reference run at the
/// same amplitude by more than 3 combined standard errors (the friction really changed them).
double flaggedThatDifferFromTheLinearRun(const autotune::AmplitudeMap& m, const autotune::AmplitudeMap& linear)
{
    int flagged = 0, differ = 0;
    for (std::size_t i = 0; i < m.lines.size() && i < linear.lines.size(); ++i) {
        const auto& a = m.lines[i];
        const auto& b = linear.lines[i];
        if (!a.nonlinear)
            continue;
        EXPECT_NEAR(a.freqHz, b.freqHz, 1e-9);
        ++flagged;
        bool d = false;
        for (std::size_t k = 0; k < a.h.size(); ++k) {
            const double sa = a.relativeNoise[k] * std::abs(a.h[k]), sb = b.relativeNoise[k] * std::abs(b.h[k]);
            d = d || std::abs(a.h[k] - b.h[k]) > 3.0 * std::hypot(sa, sb);
        }
        differ += d ? 1 : 0;
    }
    return flagged > 0 ? static_cast<double>(differ) / flagged : 0.0;
}

} // namespace

TEST(AmplitudeMap, WithoutFrictionNothingIsFlagged)
{
    // vmc X with its Coulomb friction off: only noise and quantization differ between the amplitudes. z > 5 of a
    // complex difference with well-estimated noise happens with probability exp(-25/2) = 4e-6 per pair; the noise
    // from 4 periods is itself uncertain, so the bound is 1 % of the lines (3 of 388), not zero.
    auto d = vmcX(0.0);
    ASSERT_TRUE(d);
    const auto m = map(*d);
    ASSERT_EQ(m.runs.size(), 3u);
    EXPECT_GE(m.compared, 380u);
    EXPECT_LE(static_cast<double>(m.nonlinear), 0.01 * static_cast<double>(m.compared)) << m.nonlinear;
    for (const auto& r : m.runs)
        EXPECT_FALSE(r.voltageLimited);
}

TEST(AmplitudeMap, WeakCoulombFrictionFlagsTheLowLinesAndNotThoseWellAbove)
{
    // Coulomb friction F acts on the loop as a describing-function damping N(amplitude) in parallel with the plant:
    // T = C/(1/P + C + N), so its relative effect N/|1/P + C| falls with frequency as |1/P| ~ J*omega grows. With a
    // weak friction (0.03 N m, a tenth of the preset's) the low lines change with the amplitude, the lines well above
    // do not. Reference: the same machine without friction.
    auto df = vmcX(0.03);
    auto dl = vmcX(0.0);
    ASSERT_TRUE(df && dl);
    const auto m = map(*df);
    const auto lin = map(*dl);
    ASSERT_EQ(m.lines.size(), lin.lines.size());
    const auto low = countBand(m, 0.0, 150.0);
    const auto high = countBand(m, 1500.0, 1e9);
    ASSERT_GE(low.lines, 12);
    ASSERT_GE(high.lines, 200);
    EXPECT_GE(low.flagged, static_cast<int>(0.9 * low.lines)) << low.flagged << " of " << low.lines;
    EXPECT_LE(high.flagged, static_cast<int>(0.02 * high.lines)) << high.flagged << " of " << high.lines;
    // Every flagged line is one the friction changed: it differs from the linear run beyond the noise.
    EXPECT_GE(flaggedThatDifferFromTheLinearRun(m, lin), 0.95);
}

TEST(AmplitudeMap, ThePresetsFrictionFlagsTheLowLinesAgainstTheLinearRun)
{
    // The preset's 0.305 N m with its smoothing velocity 0.02 rad/s: below it the friction is a damping of
    // F/v_s = 15 N m s/rad, more than J*omega (2.2e-3 kg m^2) up to about 1 kHz, so at 5 ... 20 % of rated torque
    // most of the band changes with the amplitude (docs/tuning.md "Amplitude map and backlash"). The low lines are all
    // flagged, and the flagged lines are those that differ from the friction-free run.
    auto df = vmcX(-1.0);
    auto dl = vmcX(0.0);
    ASSERT_TRUE(df && dl);
    const auto m = map(*df);
    const auto lin = map(*dl);
    const auto low = countBand(m, 0.0, 150.0);
    ASSERT_GE(low.lines, 12);
    EXPECT_EQ(low.flagged, low.lines);
    EXPECT_GE(flaggedThatDifferFromTheLinearRun(m, lin), 0.95);
    // |T| at 20 % is closer to the linear run than at 5 % on the low lines (the friction's describing function falls
    // as 1/amplitude once the axis slides).
    int closer = 0, n = 0;
    for (std::size_t i = 0; i < m.lines.size(); ++i)
        if (m.lines[i].freqHz < 150.0) {
            ++n;
            closer += std::abs(m.lines[i].h[2] - lin.lines[i].h[2]) < std::abs(m.lines[i].h[0] - lin.lines[i].h[0]);
        }
    EXPECT_EQ(closer, n);
}

namespace {

/// Hands out the inner drive's FRFs with voltage_clamped_samples replaced, one text per FRF in turn.
class ClampedSamplesAs : public devtest::ForwardingDrive {
public:
    ClampedSamplesAs(device::Drive& inner, std::vector<std::string> texts)
        : ForwardingDrive(inner), m_texts(std::move(texts))
    {
    }
    Result<device::FrfMeasurement> readFrequencyResponse() override
    {
        auto m = m_inner.readFrequencyResponse();
        if (!m || m_next >= m_texts.size())
            return m;
        device::FrfMeasurement out = *m;
        out.frf.metadata.set("voltage_clamped_samples", model::MetadataValue(m_texts[m_next++]));
        return out;
    }

private:
    std::vector<std::string> m_texts;
    std::size_t m_next = 0;
};

} // namespace

TEST(AmplitudeMap, AVoltageLimitIsReadAsAWholeNumberAndOneNotANumberCountsAsReached)
{
    // voltage_clamped_samples is a count (docs/multisine.md "Validity flags"); "0" is a clean run, 12 samples at the
    // limit are not, and a count that cannot be read ("many", as a foreign drive might write) is taken as reached: the
    // run is left out of the comparison rather than trusted.
    auto d = vmcX(0.0);
    ASSERT_TRUE(d);
    ClampedSamplesAs drive(*d, {"0", "12", "many"});
    const auto m = map(drive);
    ASSERT_EQ(m.runs.size(), 3u);
    EXPECT_FALSE(m.runs[0].voltageLimited);
    EXPECT_TRUE(m.runs[1].voltageLimited);
    EXPECT_TRUE(m.runs[2].voltageLimited);
}

TEST(AmplitudeMap, BadAmplitudeListsAreRefused)
{
    EXPECT_FALSE(autotune::checkAmplitudeList({5.0, 10.0}).ok());
    EXPECT_FALSE(autotune::checkAmplitudeList({5.0, 5.0, 10.0}).ok());
    EXPECT_FALSE(autotune::checkAmplitudeList({-1.0, 5.0, 10.0}).ok());
    EXPECT_FALSE(autotune::checkAmplitudeList({5.0, std::nan(""), 10.0}).ok());
    EXPECT_TRUE(autotune::checkAmplitudeList({5.0, 10.0, 20.0}).ok());
    auto d = vmcX(0.0);
    ASSERT_TRUE(d);
    autotune::AmplitudeMapOptions o;
    o.axis = "X";
    o.amplitudesPct = {5.0, 10.0, 400.0}; // above the embedded drive's FRF limit
    EXPECT_FALSE(autotune::measureAmplitudeMap(*d, o).ok());
}

TEST(Backlash, TheReversalGivesTheVariantsPlay)
{
    // The play does not act back on the motor (docs/simulator.md "backlash"), so the motor side of the two runs is
    // the same and the difference of the estimates is the play itself: 20 um. Tolerance 0.5 um: the regression's
    // scatter (residual rms) is below 0.1 um here; 0.5 um is a quarter of the 2 um window the refusal compares with.
    // Without play the estimate is the wind-up of the motor-side friction, -2 F_m R/K: between -2 * 0.305 N m *
    // (12 mm / 2 pi) / 337.1 N m/rad = -3.46 um and 0 (the regression's slope also holds the nut's A = 1.8 um/N m).
    double bl[2] = {0.0, 0.0};
    for (int i = 0; i < 2; ++i) {
        auto d = vmcX(-1.0, i == 0 ? 0.0 : 20e-6);
        ASSERT_TRUE(d);
        double motion = 0.0;
        auto b = autotune::measureBacklash(*d, "X", 0.002, 0.05, 1.0, {}, motion);
        ASSERT_TRUE(b.ok()) << b.error().detail;
        EXPECT_GT(motion, 0.1);
        EXPECT_LT(b->residualRmsM, 2e-6); // the elastic model's misfit (the 124 Hz torsion mode), not the noise
        bl[i] = b->backlashM;
        std::cout << "backlash " << (i == 0 ? 0 : 20) << " um: estimate " << b->backlashM * 1e6 << " um, k "
                  << b->complianceMPerNm * 1e6 << " um/N m, residual rms " << b->residualRmsM * 1e6 << " um\n";
    }
    EXPECT_NEAR(bl[1] - bl[0], 20e-6, 0.5e-6);
    const double windUp = 2.0 * 0.305 * (0.012 / (2.0 * std::numbers::pi)) / 337.1;
    EXPECT_GE(bl[0], -windUp - 0.5e-6);
    EXPECT_LE(bl[0], 0.5e-6);
}

TEST(AutoTune, WithTheAmplitudeMapItDesignsFromTheAmplitudeInUse)
{
    // vmc X, map at 5, 10, 20 %: the move (10 mm, 1 m/s^2) needs at least J*a/R + F = 2.2031e-3 kg m^2 * 1 m/s^2 /
    // (12 mm / 2 pi) + 0.305 N m = 1.459 N m = 18.7 % of k_t*I_rated = 0.50911 * 15.30 = 7.789 N m (the preset); the
    // feedback's transient at the acceleration steps adds to it (at most half again). The nearest amplitude in log is
    // 20 %, where the FRF starts; the loop it designs keeps the standard style's 45 deg / 6 dB when re-measured.
    auto d = vmcX(-1.0);
    ASSERT_TRUE(d);
    autotune::Options o;
    o.axis = "X";
    o.amplitudeMapPct = {5.0, 10.0, 20.0};
    auto r = autotune::runAutoTune(*d, o);
    ASSERT_TRUE(r.ok()) << r.error().detail;
    ASSERT_EQ(r->outcome, autotune::Outcome::Applied) << r->reason;
    const auto j = autotune::resultJson(*r, o);
    const nlohmann::json* frf = nullptr;
    for (const auto& s : j["steps"])
        if (s["name"] == "frf")
            frf = &s;
    ASSERT_NE(frf, nullptr);
    const auto& map = (*frf)["measured"]["amplitude_map"];
    const double ideal = 100.0 * (2.2031e-3 * 1.0 / (0.012 / (2.0 * std::numbers::pi)) + 0.305) / (0.50911 * 15.30);
    EXPECT_NEAR(ideal, 18.73, 0.01);
    EXPECT_GE(map["use_torque_pct"].get<double>(), 0.95 * ideal);
    EXPECT_LE(map["use_torque_pct"].get<double>(), 1.5 * ideal);
    EXPECT_EQ(map["design_amplitude_pct"].get<double>(), 20.0);
    EXPECT_EQ((*frf)["measured"]["tries"][0]["amplitude_pct"].get<double>(), 20.0);
    EXPECT_EQ(map["lines"].size(), 388u);
    ASSERT_TRUE(r->final.has_value());
    EXPECT_GE(r->final->phaseMarginDeg, 45.0);
    EXPECT_GE(r->final->gainMarginDb, 6.0);
    EXPECT_LE(r->motionTimeS, 30.0);
}

// SPDX-License-Identifier: GPL-3.0-or-later
// Regression-level scenario of spec/cutting-force-observer-and-chatter-detection.md §3.10 (Appendix A,
// tests/data/machining/ref_sim_003.py, its output ref_sim_003.out): checks V-003-S1 … S4 of §3.9 with the
// tolerances given there, and the mode occupancy, which depends only on the noise-free velocity path and
// must equal the reference script's counts.
#include "core/machining/CuttingForceObserver.h"
#include "core/machining/SwitchingRls.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <random>
#include <vector>

using namespace axistune::machining;

namespace {
constexpr double kTs = 0.4e-3;
constexpr double kPi = std::numbers::pi;

struct Row {
    double t, jl, bl, fcl, fHat, fQ;
    RlsMode mode;
};

std::vector<Row> runScenario(RlsMethod method, bool vary, bool recommended, bool repair = true)
{
    SwitchingRlsOptions opt;
    opt.method = method;
    opt.matchQ = recommended;
    opt.handover = recommended ? Handover::Shadow : Handover::Substitute;
    opt.commitAtEnd = recommended;
    opt.repairCovariance = repair;
    auto rls = SwitchingRls::create({0.0032, 0.002, 0.15}, opt, kTs);
    auto qt = *butterworth2LowPass(250.0, kTs), qr = qt;
    std::mt19937_64 rng(1);
    std::normal_distribution<double> noise(0.0, 0.01);
    const double q = 2 * kPi / std::pow(2.0, 20);
    double th = 0.0, thqPrev = 0.0, ph1 = 0.0, ph2 = 0.0;
    std::vector<Row> log;
    const int n = static_cast<int>(20.0 / kTs);
    log.reserve(n);
    for (int k = 0; k < n; ++k) {
        const double t = k * kTs;
        const double m = 1 + 0.3 * std::sin(2 * kPi * 15 * t);
        const double w = 8 * std::sin(2 * kPi * t / 8) * m;
        const double wd = 2 * kPi * std::cos(2 * kPi * t / 8) * m +
                          8 * std::sin(2 * kPi * t / 8) * 0.3 * 2 * kPi * 15 * std::cos(2 * kPi * 15 * t);
        const bool late = vary && t >= 11.0;
        const double g = late ? 0.8 : 1.0, f1 = late ? 80.0 : 100.0;
        ph1 += 2 * kPi * f1 * kTs;
        ph2 += 2 * kPi * 2 * f1 * kTs;
        const double fc = g * (2.0 + std::sin(ph1) + std::sin(ph2));
        const double sg = w > 0 ? 1.0 : (w < 0 ? -1.0 : 0.0);
        const double tsHat = qt.process(0.0048 * wd + 0.002 * w + 0.20 * sg + fc) + noise(rng);
        th += w * kTs;
        const double thq = std::round(th / q) * q;
        const double wm = (thq - thqPrev) / kTs;
        thqPrev = thq;
        const auto s = rls.value().step(tsHat, wm);
        log.push_back(
            {t, s.estimate.inertia, s.estimate.viscous, s.estimate.coulomb, s.forceHat, qr.process(fc), s.mode});
    }
    return log;
}

double rmsError(const std::vector<Row>& log, double t0)
{
    double s = 0;
    int n = 0;
    for (const auto& r : log) {
        if (r.t >= t0) {
            s += (r.fHat - r.fQ) * (r.fHat - r.fQ);
            ++n;
        }
    }
    return std::sqrt(s / n);
}
} // namespace

TEST(SwitchingRlsScenario, RecommendedVariantMeetsS1ToS4)
{
    for (bool vary : {false, true}) {
        const double t0 = vary ? 11.0 : 1.0;
        const auto fixed = runScenario(RlsMethod::Fixed, vary, true);
        const auto conv = runScenario(RlsMethod::Conventional, vary, true);
        const auto prop = runScenario(RlsMethod::Switching, vary, true);
        const double eFixed = rmsError(fixed, t0), eConv = rmsError(conv, t0), eProp = rmsError(prop, t0);
        // V-003-S3 / S4.
        EXPECT_LE(eProp, 0.85 * eConv) << "vary " << vary;
        EXPECT_LE(eProp, 0.5 * eFixed) << "vary " << vary;
        // The fixed observer has no noise-dependent state: its RMS equals the reference script's to the
        // noise contribution (σ = 0.01 in quadrature with 0.19): 0.1915 / 0.1823.
        EXPECT_NEAR(eFixed, vary ? 0.1823 : 0.1915, 0.002);
        // Reference [SIM] Prop. RMS 0.0309 / 0.0368 (another noise realisation here): within 15 %.
        EXPECT_NEAR(eProp, vary ? 0.0368 : 0.0309, 0.15 * (vary ? 0.0368 : 0.0309));

        // V-003-S1: Ĵ_L within ±10 % of 0.0048 within 0.5 s; mean over t ≥ 4.2 s within ±3 %, σ ≤ 3 %.
        double firstWithin = -1;
        double sum = 0, sum2 = 0;
        int n = 0;
        for (const auto& r : prop) {
            if (firstWithin < 0 && std::abs(r.jl - 0.0048) <= 0.1 * 0.0048)
                firstWithin = r.t;
            if (r.t >= 4.2) {
                sum += r.jl;
                sum2 += r.jl * r.jl;
                ++n;
            }
        }
        ASSERT_GE(firstWithin, 0.0);
        EXPECT_LE(firstWithin, 0.5);
        const double mean = sum / n, sd = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
        EXPECT_NEAR(mean, 0.0048, 0.03 * 0.0048);
        EXPECT_LE(sd, 0.03 * 0.0048);

        // V-003-S2: F̂_CL within ±10 % of 0.20 after the first RLS4 window and constant outside RLS4.
        double lo = 1e9, hi = -1e9;
        for (std::size_t i = 1; i < prop.size(); ++i) {
            const auto& r = prop[i];
            if (r.t >= 4.2) {
                lo = std::min(lo, r.fcl);
                hi = std::max(hi, r.fcl);
            }
            if (r.mode != RlsMode::Rls4 && prop[i - 1].mode != RlsMode::Rls4) {
                ASSERT_EQ(r.fcl, prop[i - 1].fcl) << r.t;
            }
        }
        EXPECT_GE(lo, 0.18);
        EXPECT_LE(hi, 0.22);

        // Mode occupancy: the script's counts (hold 2213, rls3 47387, rls4 400), velocity path only.
        int counts[3] = {0, 0, 0};
        for (const auto& r : prop)
            ++counts[static_cast<int>(r.mode)];
        EXPECT_EQ(counts[2], 400);
        EXPECT_NEAR(counts[1], 47387, 5);
        EXPECT_NEAR(counts[0], 2213, 5);
    }
}

TEST(SwitchingRlsScenario, LiteralVariantPropBeatsConv)
{
    // Variant A (literal, no P4 repair as in the script): reference ratios Prop/Conv 0.65 / 0.66 (≤ 0.85 by V-003-S3).
    for (bool vary : {false, true}) {
        const double t0 = vary ? 11.0 : 1.0;
        const double eConv = rmsError(runScenario(RlsMethod::Conventional, vary, false), t0);
        const double eProp = rmsError(runScenario(RlsMethod::Switching, vary, false, false), t0);
        const double eRepaired = rmsError(runScenario(RlsMethod::Switching, vary, false, true), t0);

        // Reference [SIM] RMS, variant A: Conv 0.1204 / 0.1288, Prop 0.0778 / 0.0852 (another noise
        // realisation here, σ = 0.01 against errors of ~0.1: within 5 %).
        EXPECT_NEAR(eConv, vary ? 0.1288 : 0.1204, 0.05 * (vary ? 0.1288 : 0.1204));
        EXPECT_NEAR(eProp, vary ? 0.0852 : 0.0778, 0.05 * (vary ? 0.0852 : 0.0778));
        // The Cholesky repair of the assembled P4 (spec §1.9 item 3, not in the script) must not hurt.
        EXPECT_LE(eRepaired, eProp);
        EXPECT_LE(eProp, 0.85 * eConv) << "vary " << vary;
        EXPECT_NEAR(eProp / eConv, vary ? 0.66 : 0.65, 0.1);
    }
}

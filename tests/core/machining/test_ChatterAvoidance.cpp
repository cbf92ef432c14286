// SPDX-License-Identifier: GPL-3.0-or-later
// Chatter-avoidance building blocks (core/machining/ChatterAvoidance) on their own: the multi-resonance cost
// J_chat and its lobe search (spec §3.3 eqs. (5-3)–(5-6)) against hand-computed cases, the ESC design (6-24)
// against the spec's derived numbers, the stage DOB on a pure-inertia stage (spec §6.4 validation) and the
// option checks. Reference numbers: tests/data/chatter/jchat_reference.py (output jchat_reference.txt).
#include "core/machining/ChatterAvoidance.h"
#include "core/machining/ToolModel.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

using namespace axistune::machining;

namespace {
constexpr double kPi = std::numbers::pi;
}

TEST(ChatterAvoidance, JChatHandComputedTwoModes)
{
    // f = 1435.6, 1909.9 Hz (the two-mode tool), w = 1, 0.5: r_2 = ρ·1.330384 (jchat_reference.txt case A).
    const std::vector<double> f{1435.6, 1909.9}, w{1.0, 0.5};
    EXPECT_NEAR(multiModeCost(6, f, w).value(), 0.0001565202519, 1e-12);
    EXPECT_NEAR(multiModeCost(7, f, w).value(), 0.04888800508, 1e-10);
    EXPECT_NEAR(multiModeCost(8, f, w).value(), 0.06369734742, 1e-10);
    EXPECT_NEAR(multiModeCost(9, f, w).value(), 0.0003521705668, 1e-12);
    // Spec §6.3: ρ = 6 gives r_2 = 7.982 and J ≈ w_2·0.0003.
    EXPECT_NEAR(multiModeCost(6, f, w).value() / w[1], 0.0003, 0.00002);
}

TEST(ChatterAvoidance, JChatSearchPicksTheLeastCostLobe)
{
    const std::vector<double> f{1435.6, 1909.9}, w{1.0, 0.5};
    // 2800 rpm, 4 teeth: f_TPE 186.67 Hz, ratio 7.69 → ρ_new 8; over {7, 8, 9} the cost picks 9 → 2392.67 rpm
    // (spec §5.3: "the (5-3) cost over {7, 8, 9} would pick ρ = 9, giving about 2400 rpm").
    auto c = multiModeLobeSearch(f, w, 2800.0, 4, 1, 1);
    ASSERT_TRUE(c) << c.error().detail;
    EXPECT_EQ(c->rhoNew, 8);
    EXPECT_EQ(c->rhoProp, 9);
    EXPECT_NEAR(c->cost, 0.0003521705668, 1e-12);
    EXPECT_NEAR(c->rpm, 2392.666667, 1e-5);
    ASSERT_EQ(c->candidates.size(), 3u);
    EXPECT_EQ(c->candidates.front().rho, 7);
    // Widening the search below to 2 reaches ρ = 6 (the thesis's "r1, r2 ≈ 6, 8") at 3589 rpm (spec §6.3).
    auto wide = multiModeLobeSearch(f, w, 2800.0, 4, 2, 1);
    ASSERT_TRUE(wide);
    EXPECT_EQ(wide->rhoProp, 6);
    EXPECT_NEAR(wide->rpm, 3589.0, 1e-6);
}

TEST(ChatterAvoidance, JChatTieBreaks)
{
    // f = 1000, 1500 Hz, w = 1, 1: J = 0 for even ρ, 0.25 for odd ρ (case B).
    const std::vector<double> f{1000.0, 1500.0}, w{1.0, 1.0};
    EXPECT_DOUBLE_EQ(multiModeCost(4, f, w).value(), 0.0);
    EXPECT_DOUBLE_EQ(multiModeCost(3, f, w).value(), 0.25);
    // ρ_new = 4 (3750 rpm), candidates 2..6 all even ones at J = 0: the least (ρ − ρ_new)² wins → 4.
    auto a = multiModeLobeSearch(f, w, 3750.0, 4, 2, 2);
    ASSERT_TRUE(a);
    EXPECT_EQ(a->rhoNew, 4);
    EXPECT_EQ(a->rhoProp, 4);
    EXPECT_NEAR(a->rpm, 3750.0, 1e-9);
    // ρ_new = 3 (5000 rpm): J(2) = J(4) = 0 at equal distance → the lower lobe (higher speed) 2 → 7500 rpm.
    auto b = multiModeLobeSearch(f, w, 5000.0, 4, 1, 1);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->rhoNew, 3);
    EXPECT_EQ(b->rhoProp, 2);
    EXPECT_NEAR(b->rpm, 7500.0, 1e-9);
}

TEST(ChatterAvoidance, JChatOneFrequencyIsTheConventionalRule)
{
    // N = 1: J ≡ 0, the tie-break keeps ρ_new: 1394.8 Hz at 2800 rpm → ρ 7, 2988.857 rpm (case C).
    auto c = multiModeLobeSearch({1394.8}, {1.0}, 2800.0, 4, 1, 1);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->rhoProp, 7);
    EXPECT_DOUBLE_EQ(c->cost, 0.0);
    EXPECT_NEAR(c->rpm, 2988.857143, 1e-5);
}

TEST(ChatterAvoidance, JChatRefusesBadInput)
{
    EXPECT_FALSE(multiModeCost(3, {1000.0, 1500.0}, {0.5, 1.0})); // weights increase
    EXPECT_FALSE(multiModeCost(3, {1000.0, 1500.0}, {1.0}));      // sizes differ
    EXPECT_FALSE(multiModeCost(3, {1000.0, -1.0}, {1.0, 0.5}));   // f ≤ 0
    EXPECT_FALSE(multiModeCost(0, {1000.0, 1500.0}, {1.0, 0.5})); // ρ < 1
    EXPECT_FALSE(multiModeCost(3, {}, {}));
    EXPECT_FALSE(multiModeLobeSearch({1000.0, 1500.0}, {1.0, 0.5}, 0.0, 4, 1, 1));
    EXPECT_FALSE(multiModeLobeSearch({1000.0, 1500.0}, {1.0, 0.5}, 3000.0, 4, -1, 1));
    // f_1 below half the tooth-passing frequency: no lobe number.
    EXPECT_FALSE(multiModeLobeSearch({10.0, 15.0}, {1.0, 0.5}, 3000.0, 4, 1, 1));
}

TEST(ChatterAvoidance, EscDesignMatchesTheSeed)
{
    // Spec §3.4.3/§6.5 [derived]: p_c = 8·2π → h_c 16.755 rad/s (2.667 Hz), k_c 134.04, ω_p 87.06 rad/s (13.856 Hz).
    auto d = escDesign(8.0 * 2.0 * kPi);
    ASSERT_TRUE(d);
    EXPECT_NEAR(d->hcRadS, 16.75516082, 1e-7);
    EXPECT_NEAR(d->hcRadS / (2 * kPi), 2.666666667, 1e-8);
    EXPECT_NEAR(d->kcPerS, 134.0412866, 1e-6);
    EXPECT_NEAR(d->omegaPRadS, 87.06236948, 1e-7);
    EXPECT_NEAR(d->omegaPRadS / (2 * kPi), 13.85640646, 1e-7);
    // (6-22) denominator s³ + (h+k)s² + ω²s + ω²h has a triple root at −p_c (numpy: −50.2655 ± 4e-4 j).
    Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
    c(0, 0) = -(d->hcRadS + d->kcPerS);
    c(0, 1) = -d->omegaPRadS * d->omegaPRadS;
    c(0, 2) = -d->omegaPRadS * d->omegaPRadS * d->hcRadS;
    c(1, 0) = c(2, 1) = 1.0;
    Eigen::EigenSolver<Eigen::Matrix3d> es(c);
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(std::abs(es.eigenvalues()(i) + 8.0 * 2.0 * kPi), 0.0, 0.01);
    EXPECT_FALSE(escDesign(0.0));
    EXPECT_FALSE(escDesign(std::nan("")));
}

TEST(ChatterAvoidance, EscControllerRefusesBadOptions)
{
    EscOptions o;
    o.minRpm = 1200;
    o.maxRpm = 2200;
    EXPECT_TRUE(EscController::create(o, 1700.0));
    auto noBounds = o;
    noBounds.minRpm = noBounds.maxRpm = 0.0;
    EXPECT_FALSE(EscController::create(noBounds, 1700.0));
    auto outside = o;
    EXPECT_FALSE(EscController::create(outside, 2500.0)); // initial speed outside the bounds
    auto badDither = o;
    badDither.ditherRadS = 0.0;
    EXPECT_FALSE(EscController::create(badDither, 1700.0));
    auto badCurv = o;
    badCurv.curvature = -1.0;
    EXPECT_FALSE(EscController::create(badCurv, 1700.0));
    // The integrator gain normalises the averaged loop gain: k_int = 2 k_c/(a_c f'').
    auto c = EscController::create(o, 1700.0);
    EXPECT_NEAR(c->integratorGain(), 2.0 * 134.0412866 / (1.0 * 1e5), 1e-9);
}

TEST(ChatterAvoidance, EscFindsTheMinimumOfAQuadraticMap)
{
    // Static map y = f''/2 (ω − ω*)² (rad/s) with f'' as assumed: the averaged error decays as the triple pole
    // at −p_c (6-21) (time constant ~20 ms, a few hundred ms to settle with the dither ripple). From 1700 rpm
    // with ω* at 1750 rpm the mean speed must end within 1 rpm of 1750.
    EscOptions o;
    o.minRpm = 1000;
    o.maxRpm = 2500;
    o.startS = 0.0;
    o.curvature = 1e5;
    auto created = EscController::create(o, 1700.0);
    ASSERT_TRUE(created);
    auto c = &created.value();
    const double wStar = 1750.0 * 2 * kPi / 60.0;
    double cmd = 1700.0, sum = 0.0;
    int n = 0;
    for (int i = 0; i < 20000; ++i) { // 4 s at 200 µs
        const double w = cmd * 2 * kPi / 60.0;
        cmd = c->step(i * o.samplePeriodS, 0.5 * o.curvature * (w - wStar) * (w - wStar));
        if (i >= 15000) { // θ̂ ripples at ω_p and its harmonics (the sin² term of the dither): average the last 1 s
            sum += c->meanRpm();
            ++n;
        }
    }
    EXPECT_NEAR(sum / n, 1750.0, 1.0);
    EXPECT_EQ(c->boundHits(), 0u);
}

TEST(ChatterAvoidance, StageDobRecoversADisturbanceOnAPureInertia)
{
    // Spec §6.4 validation: a rigid stage M v' = F_t − F_d − D v with a 100 N disturbance at 1390 Hz and F_t = 0;
    // F̂ = G_F Q (F_t − (M s + D) v) recovers −(amplitude) × |Q G_F| at 1390 Hz. Q: 2nd-order Butterworth at
    // 2000 Hz, G_F: 2nd-order high-pass 1000 Hz + low-pass 2000 Hz; analytic magnitudes 1/√(1 + (f/fc)⁴) and
    // (f/fh)²/√(1 + (f/fh)⁴) (Tustin pre-warping at the corners leaves < 3 % at 1390 Hz, sampled at 62.5 µs).
    StageDobOptions opt;
    const double ts = 62.5e-6, f = 1390.0, amp = 100.0;
    auto created = StageDob::create(opt, ts);
    ASSERT_TRUE(created);
    auto dob = &created.value();
    double x = 0.0, v = 0.0, peak = 0.0;
    const int sub = 50;
    for (int i = 0; i < 16000; ++i) { // 1 s
        for (int k = 0; k < sub; ++k) {
            const double t = (i * sub + k) * ts / sub;
            const double fd = amp * std::sin(2 * kPi * f * t);
            const double acc = (-fd - opt.viscousNsPerM * v) / opt.massKg;
            v += acc * ts / sub;
            x += v * ts / sub;
        }
        const double est = dob->step(x, 0.0);
        if (i > 8000)
            peak = std::max(peak, std::abs(est));
    }
    auto lp = [](double fr, double fc) { return 1.0 / std::sqrt(1.0 + std::pow(fr / fc, 4)); };
    auto hp = [](double fr, double fc) { return std::pow(fr / fc, 2) / std::sqrt(1.0 + std::pow(fr / fc, 4)); };
    const double expected = amp * lp(f, 2000.0) * lp(f, 2000.0) * hp(f, 1000.0);
    EXPECT_NEAR(peak, expected, 0.05 * expected);
    // Bad options are refused with the option named.
    StageDobOptions bad = opt;
    bad.massKg = 0.0;
    EXPECT_FALSE(StageDob::create(bad, ts));
    bad = opt;
    bad.qCutoffHz = 9000.0; // above Nyquist at 62.5 µs
    EXPECT_FALSE(StageDob::create(bad, ts));
}

TEST(ChatterAvoidance, AdaptiveOptionsChecked)
{
    EXPECT_TRUE(AdaptiveAvoidance::create(adaptiveTable4Dob(), 4));
    EXPECT_TRUE(AdaptiveAvoidance::create(adaptiveTable3Accelerometer(), 4));
    EXPECT_TRUE(AdaptiveAvoidance::create(multiModeTable5Accelerometer(), 4));
    auto o = multiModeTable5Accelerometer();
    o.weights = {1.0}; // N_d = 4 needs two weights
    EXPECT_FALSE(AdaptiveAvoidance::create(o, 4));
    o = adaptiveTable4Dob();
    o.kalman.order = 3;
    EXPECT_FALSE(AdaptiveAvoidance::create(o, 4));
    o = adaptiveTable4Dob();
    o.thresholdPower = 0.0;
    EXPECT_FALSE(AdaptiveAvoidance::create(o, 4));
    o = adaptiveTable4Dob();
    o.highPassHz = 3000.0; // above Nyquist at 250 µs
    EXPECT_FALSE(AdaptiveAvoidance::create(o, 4));
}

TEST(ChatterAvoidance, ToolModeBandPassHasItsEdgesAndCentre)
{
    // n identical bilinear band-pass sections with pre-warped edges f1, f2: unit gain at the digital centre
    // f0 = atan(√(W1 W2))/(π t_s), W = tan(π f t_s), 2^(−n/2) at f1 and f2 (−3 dB per section); elsewhere the
    // analogue prototype at the warped frequency, |H| = (B W/√((W0² − W²)² + (B W)²))^n.
    const double ts = 250e-6, f1 = 1380.6 - 93.33, f2 = 1380.6 + 93.33;
    auto bp = bandPassSections(3, f1, f2, ts);
    ASSERT_TRUE(bp) << bp.error().detail;
    const auto warp = [ts](double f) { return std::tan(std::numbers::pi * f * ts); };
    const double w1 = warp(f1), w2 = warp(f2), b = w2 - w1, w0sq = w1 * w2;
    const double f0 = std::atan(std::sqrt(w0sq)) / (std::numbers::pi * ts);
    EXPECT_NEAR(std::abs(bp->response(f0, ts)), 1.0, 1e-9);
    EXPECT_NEAR(std::abs(bp->response(f1, ts)), std::pow(2.0, -1.5), 1e-9);
    EXPECT_NEAR(std::abs(bp->response(f2, ts)), std::pow(2.0, -1.5), 1e-9);
    for (double f : {1394.8, 1581.5, 1208.1, 500.0, 1900.0}) {
        const double w = warp(f);
        const double one = b * w / std::hypot(w0sq - w * w, b * w);
        EXPECT_NEAR(std::abs(bp->response(f, ts)), one * one * one, 1e-9) << f;
    }
    // The +1 tooth-passing sideband (1581.5 Hz) is passed at < 0.1 of the chatter line (1394.8 Hz).
    EXPECT_LT(std::abs(bp->response(1581.5, ts)), 0.1 * std::abs(bp->response(1394.8, ts)));
    EXPECT_FALSE(bandPassSections(0, f1, f2, ts));
    EXPECT_FALSE(bandPassSections(3, f2, f1, ts));
    EXPECT_FALSE(bandPassSections(3, f1, 2100.0, ts)); // above Nyquist 2000 Hz
}

TEST(ChatterAvoidance, NegativeResidueModeAcceptedMixedSignsRefused)
{
    // A mode with mass, damping and stiffness all negative is the negative residue of a product of resonances
    // (the cascade (5-1), tests/data/chatter/cascade_tool.py); a mode with mixed signs is a typo and refused,
    // the field named.
    ToolModes t;
    t.modesY = {{0.5346547242, 96.45171224, 43499722.22}, {-0.5346547242, -76.99028028, -76990280.28}};
    EXPECT_TRUE(validateTool(t).ok());
    EXPECT_NEAR(naturalFrequencyHz(t.modesY[1]), 12000.0 / (2.0 * kPi), 1e-3); // ω₂ of (5-1)
    EXPECT_NEAR(dampingRatio(t.modesY[1]), 0.006, 1e-9);                       // ζ₂ of (5-1)
    t.modesY[1].stiffnessNPerM = 76990280.28;
    auto e = validateTool(t);
    ASSERT_FALSE(e.ok());
    EXPECT_NE(e.error().detail.find("modes_y[1].stiffness_N_per_m"), std::string::npos) << e.error().detail;
    t.modesY[1] = {-0.53, 76.99, -76990280.28};
    e = validateTool(t);
    ASSERT_FALSE(e.ok());
    EXPECT_NE(e.error().detail.find("modes_y[1].damping_Ns_per_m"), std::string::npos) << e.error().detail;
    t.modesY[1] = {0.0, 0.0, 1e7};
    EXPECT_FALSE(validateTool(t).ok());
}

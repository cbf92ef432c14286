// SPDX-License-Identifier: GPL-3.0-or-later
// The drive-side two-inertia suppression filters (core/sim/SuppressionFilter.h) against the check
// values of spec/lost-motion-and-two-inertia.md §4.10 (TI-3 checks i, ii, iii, v) and §4.11 (TI-4
// Tustin coefficients at 1 ms and 250 µs, DC gain, |F_L(17 Hz)|), the parameter rules of the simulated
// drive (suppression.mode against position.feedback), and the rectangular-jerk profile of TI-6.
#include "core/sim/AxisSimulator.h"
#include "core/sim/SuppressionFilter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace axistune;
using namespace axistune::sim;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTwoPi = 2.0 * kPi;

double db(double v) { return 20.0 * std::log10(v); }

std::unique_ptr<AxisSimulator> twoInertia()
{
    auto def = loadPreset("two-inertia");
    EXPECT_TRUE(def.ok());
    auto s = AxisSimulator::create(*def->axis("A"), 1);
    EXPECT_TRUE(s.ok());
    return std::move(s).value();
}

}  // namespace

// §4.11: f₀ 17 Hz, ζ 0.14, τ 13 ms; coefficients printed to 9–10 digits (tolerance half a unit of the
// last printed digit), DC gain 1 (sum of b over sum of a), |H(17 Hz)| = −16.05 dB at 1 ms.
TEST(SuppressionFilter, FlTustinCoefficientsOfTheSpec)
{
    auto h1 = designFlTustin(17.0, 0.14, 0.013, 1e-3);
    ASSERT_TRUE(h1.ok());
    EXPECT_NEAR(h1->b0(), 2.117033662, 5e-10);
    EXPECT_NEAR(h1->b1(), -4.148127635, 5e-10);
    EXPECT_NEAR(h1->b2(), 2.054825201, 5e-10);
    EXPECT_NEAR(h1->a1(), -1.60555435, 5e-9);
    EXPECT_NEAR(h1->a2(), 0.629285577, 5e-10);
    EXPECT_NEAR((h1->b0() + h1->b1() + h1->b2()) / (1.0 + h1->a1() + h1->a2()), 1.0, 1e-9);
    EXPECT_NEAR(db(std::abs(h1->response(17.0, 1e-3))), -16.05, 0.005);

    auto h4 = designFlTustin(17.0, 0.14, 0.013, 250e-6);
    ASSERT_TRUE(h4.ok());
    EXPECT_NEAR(h4->b0(), 2.441073712, 5e-10);
    EXPECT_NEAR(h4->b1(), -4.862232862, 5e-10);
    EXPECT_NEAR(h4->b2(), 2.422893037, 5e-10);
    EXPECT_NEAR(h4->a1(), -1.889923315, 5e-10);
    EXPECT_NEAR(h4->a2(), 0.891657202, 5e-10);
    EXPECT_NEAR((h4->b0() + h4->b1() + h4->b2()) / (1.0 + h4->a1() + h4->a2()), 1.0, 1e-9);

    EXPECT_FALSE(designFlTustin(17.0, 0.0, 0.013, 1e-3).ok());
    EXPECT_FALSE(designFlTustin(17.0, 0.14, 0.0, 1e-3).ok());
}

// TI-3 (i): a constant-velocity command passes unchanged; (ii) under a constant acceleration α the
// motor command leads by α/ω₀²: 0.1101 rad at 17 Hz and 0.0658 rad at 22 Hz for α = 200 rev/s².
TEST(SuppressionFilter, FmDcGainAndAccelerationOffset)
{
    FmCommandShaper fm;
    ASSERT_TRUE(fm.configure(17.0, 0.07, 1e-3).ok());
    for (int k = 0; k < 100; ++k) {
        const double t = k * 1e-3;
        const MotionState out = fm.process({3.0 + 62.83 * t, 62.83, 0.0});
        EXPECT_NEAR(out.position, 3.0 + 62.83 * t, 1e-12);
        EXPECT_NEAR(out.velocity, 62.83, 1e-12);
    }
    const double alpha = 200.0 * kTwoPi;  // 1256.6 rad/s²
    for (const auto& [f0, expected] : {std::pair{17.0, 0.1101}, std::pair{22.0, 0.0658}}) {
        ASSERT_TRUE(fm.configure(f0, 0.07, 1e-3).ok());
        MotionState out;
        for (int k = 0; k < 200; ++k) {  // 200 ms ≫ T₁ = 2ζ/ω₀ ≈ 1.3 ms
            const double t = k * 1e-3;
            out = fm.process({0.5 * alpha * t * t, alpha * t, alpha});
            if (k == 199) {
                EXPECT_NEAR(out.position - 0.5 * alpha * t * t, expected, 5e-5) << f0;
                EXPECT_NEAR(out.velocity - alpha * t, 0.0, 1e-9) << f0;
            }
        }
    }
}

// TI-3 (iii): with ζ = 0 the shift is J_L·α/K exactly at every sample (5.8), Table 5.1 values.
TEST(SuppressionFilter, FmWithoutDampingIsTheSpringShift)
{
    const double jl = 0.0105, k = 200.0, alpha = 1256.6;
    FmCommandShaper fm;
    ASSERT_TRUE(fm.configure(std::sqrt(k / jl) / kTwoPi, 0.0, 1e-3).ok());
    for (int i = 0; i < 50; ++i) {
        const double a = i < 20 ? alpha * i / 20.0 : alpha;  // a ramp, then constant
        const MotionState out = fm.process({1.0, 2.0, a});
        EXPECT_NEAR(out.position - 1.0, jl * a / k, 1e-12 * jl * alpha / k) << i;
    }
}

// TI-3 (v): |F_m(j2π·17)| = 2ζ/√(1 + 4ζ²) = 0.1386 (−17.16 dB) for 17 Hz / ζ 0.07, measured with a
// sampled 17 Hz command through the shaper at 1 ms. Tolerance 0.1 dB: the ramp-invariant lag sees the
// piecewise-linear interpolant of the sampled acceleration, whose 17 Hz amplitude is low by
// (sin x/x)² ≈ 1 − x²/3 = 1 − 1e-3 (x = π·17 Hz·1 ms); next to the cancellation at f₀ that error grows by
// |L|/|F_m| ≈ 7 to 0.7 % (0.06 dB).
TEST(SuppressionFilter, FmMagnitudeAtItsFrequency)
{
    FmCommandShaper fm;
    const double f = 17.0, w = kTwoPi * f, h = 1e-3;
    ASSERT_TRUE(fm.configure(f, 0.07, h).ok());
    std::complex<double> in = 0.0, out = 0.0;
    const int settle = 2000, n = 1000;  // 1 s settles the lag; 1 s = 17 whole periods
    for (int k = 0; k < settle + n; ++k) {
        const double t = k * h;
        const MotionState c{std::sin(w * t), w * std::cos(w * t), -w * w * std::sin(w * t)};
        const MotionState y = fm.process(c);
        if (k >= settle) {
            in += c.position * std::polar(1.0, -w * t);
            out += y.position * std::polar(1.0, -w * t);
        }
    }
    EXPECT_NEAR(db(std::abs(out / in)), -17.16, 0.1);
}

// The simulated drive refuses the F_m/F_L mode that does not match the feedback, names both
// parameters, and changes nothing on a refusal; F_L needs τ > 0 and a bounded high-frequency gain.
TEST(SuppressionFilter, DriveParametersFollowTheFeedbackMode)
{
    auto s = twoInertia();
    EXPECT_EQ(s->parameter("suppression.mode"), 0.0);  // off by default
    auto st = s->setParameters({{"suppression.mode", 2}, {"suppression.f0", 17}, {"suppression.zeta", 0.14}});
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().detail.find("suppression.mode"), std::string::npos) << st.error().detail;
    EXPECT_NE(st.error().detail.find("position.feedback"), std::string::npos) << st.error().detail;
    EXPECT_EQ(s->parameter("suppression.mode"), 0.0);
    EXPECT_EQ(s->parameter("suppression.f0"), 20.0);
    EXPECT_TRUE(s->setParameters({{"suppression.mode", 1}, {"suppression.f0", 17}, {"suppression.zeta", 0.07}}).ok());
    st = s->setParameters({{"position.feedback", 1}});
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().detail.find("suppression.mode"), std::string::npos) << st.error().detail;
    EXPECT_NE(st.error().detail.find("position.feedback"), std::string::npos) << st.error().detail;
    EXPECT_TRUE(s->setParameters({{"position.feedback", 1}, {"suppression.mode", 2}, {"suppression.tau", 0.013},
                                  {"suppression.zeta", 0.14}})
                    .ok());
    st = s->setParameters({{"suppression.tau", 0.0}});
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().detail.find("suppression.tau"), std::string::npos) << st.error().detail;
    // 1/(2·0.01·2π·17·0.002) = 234 > 10
    st = s->setParameters({{"suppression.zeta", 0.01}, {"suppression.tau", 0.002}});
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().detail.find("high-frequency gain"), std::string::npos) << st.error().detail;
    st = s->setParameters({{"suppression.f0", 499}, {"position.period", 2e-3}});  // Nyquist 250 Hz
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().detail.find("suppression.f0"), std::string::npos) << st.error().detail;
    EXPECT_EQ(s->parameter("suppression.tau"), 0.013);
}

// TI-6: 10 rev/s, 200 rev/s², 20 000 rev/s³: jerk time a/j = 10 ms, constant acceleration v/a − a/j =
// 40 ms; the move ends exactly at the distance, at rest, and the peaks are a_max and v_max.
TEST(MotionProfileJerk, RectangularJerkMove)
{
    const double v = 10 * kTwoPi, a = 200 * kTwoPi, j = 20000 * kTwoPi, d = 5.0;
    MotionProfile p(1.0);
    p.move(d, v, a, j);
    const double ramp = 2 * 0.01 + 0.04;  // 60 ms, covering v·ramp/2 each
    EXPECT_NEAR(p.duration(), 2 * ramp + (d - v * ramp) / v, 1e-12);
    double amax = 0, vmax = 0;
    for (double t = 0; t <= p.duration(); t += 1e-4) {
        const auto s = p.at(t);
        amax = std::max(amax, std::abs(s.acceleration));
        vmax = std::max(vmax, s.velocity);
    }
    EXPECT_NEAR(amax, a, 1e-9 * a);
    EXPECT_NEAR(vmax, v, 1e-9 * v);
    const auto end = p.at(p.duration() + 1.0);
    EXPECT_NEAR(end.position, 1.0 + d, 1e-12);
    EXPECT_NEAR(end.velocity, 0.0, 1e-9);
    EXPECT_EQ(end.acceleration, 0.0);
    const auto mid = p.at(0.01);  // end of the first jerk phase: a = j·t, v = j·t²/2, x = j·t³/6
    EXPECT_NEAR(mid.acceleration, a, 1e-9 * a);
    EXPECT_NEAR(mid.velocity, 0.5 * j * 1e-4, 1e-9);
    EXPECT_NEAR(mid.position - 1.0, j * 1e-6 / 6.0, 1e-12);
    // Too short for v_max: the peak speed whose two ramps cover the distance, still ending at rest.
    MotionProfile q(0.0);
    q.move(-0.5, v, a, j);
    const auto qe = q.at(q.duration());
    EXPECT_NEAR(qe.position, -0.5, 1e-9);
    EXPECT_NEAR(qe.velocity, 0.0, 1e-9);
}

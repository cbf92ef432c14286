// SPDX-License-Identifier: GPL-3.0-or-later
// F_m / F_L vibration-suppression filters (spec/lost-motion-and-two-inertia.md (5.7), (5.9), §4.9–4.11)
// and the load-error prediction for the TI-6 trajectory. F_m is realised as y_m* = y* +
// LPF_{T1}(a*)/ω_0² with T_1 = 2ζ/ω_0 (§2.5 [DERIVED] decomposition). The load follows the motor
// through (5.6): y_L'' + 2ζ_0ω_0 y_L' + ω_0² y_L = 2ζ_0ω_0 y_m' + ω_0² y_m; the error e = y_L − y*
// is integrated with RK4 (the jerk is piecewise constant, so a*, v*, y* are exact polynomials).
#include "core/tuning/TwoInertiaFilter.h"

#include "core/model/Constants.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace axistune::tuning {

namespace {
using model::kTwoPi;
constexpr double kHfGain = 2.5;
}  // namespace

SuppressionFilter suppressionFilterFromModel(const TwoInertiaParams& p, SuppressionMode mode, double tauS)
{
    SuppressionFilter f;
    f.mode = mode;
    const double w0 = antiresonanceRadS(p);
    f.f0Hz = w0 / kTwoPi;
    f.zeta = zetaZero(p);
    if (mode == SuppressionMode::Full) {
        f.tauS = tauS > 0.0 ? tauS : 1.0 / (kHfGain * 2.0 * f.zeta * w0);
    }
    return f;
}

std::complex<double> suppressionFilterResponse(const SuppressionFilter& f, double fHz)
{
    const std::complex<double> s(0.0, kTwoPi * fHz);
    const double w0 = kTwoPi * f.f0Hz;
    auto h = (s * s + 2.0 * f.zeta * w0 * s + w0 * w0) / (2.0 * f.zeta * w0 * s + w0 * w0);
    if (f.mode == SuppressionMode::Full) {
        h /= (f.tauS * s + 1.0);
    }
    return h;
}

LoadErrorPrediction predictLoadError(const TwoInertiaParams& p, const SuppressionFilter& f, const MotionProfile& prof)
{
    // Jerk segments of the acceleration phase (7-segment S-curve).
    double ta = prof.aMax / prof.jerk;      // jerk time
    double aPeak = prof.aMax;
    double tc = prof.vMax / prof.aMax - ta;  // constant-acceleration time
    if (tc < 0.0) {                          // triangular acceleration: a_max not reached
        ta = std::sqrt(prof.vMax / prof.jerk);
        aPeak = prof.jerk * ta;
        tc = 0.0;
    }
    struct Seg {
        double dur;
        double jerk;
    };
    const std::vector<Seg> segs = {{ta, prof.jerk}, {tc, 0.0}, {ta, -prof.jerk}, {prof.cruiseS, 0.0},
                                   {ta, -prof.jerk}, {tc, 0.0}, {ta, prof.jerk}, {prof.settleS, 0.0}};
    (void)aPeak;
    const double w0 = antiresonanceRadS(p);
    const double z0 = zetaZero(p);
    const double wf = kTwoPi * f.f0Hz;
    const double t1 = 2.0 * f.zeta / wf;
    LoadErrorPrediction out;
    for (int withFilter = 0; withFilter < 2; ++withFilter) {
        // State: e, e', q (= LPF_{T1}(a*)); input a*(t), j(t).
        std::array<double, 3> x{0.0, 0.0, 0.0};
        double a = 0.0;
        double maxE = 0.0;
        auto deriv = [&](const std::array<double, 3>& s, double acc, double jerk) {
            double dm = 0.0;   // y_m − y*
            double dmv = 0.0;  // y_m' − v*
            double dq = 0.0;
            if (withFilter) {
                if (t1 > 0.0) {
                    dq = (acc - s[2]) / t1;
                    dm = s[2] / (wf * wf);
                    dmv = dq / (wf * wf);
                } else {
                    dm = acc / (wf * wf);
                    dmv = jerk / (wf * wf);
                }
            }
            const double ddE = -acc + 2.0 * z0 * w0 * (dmv - s[1]) + w0 * w0 * (dm - s[0]);
            return std::array<double, 3>{s[1], ddE, dq};
        };
        const double period = kTwoPi / std::max(w0, wf);
        for (const auto& seg : segs) {
            if (seg.dur <= 0.0) {
                continue;
            }
            const int n = std::max(1, static_cast<int>(std::ceil(seg.dur / (period / 400.0))));
            const double h = seg.dur / n;
            for (int i = 0; i < n; ++i) {
                const double a0 = a;
                const double am = a + seg.jerk * h / 2.0;
                const double a1 = a + seg.jerk * h;
                auto add = [](const std::array<double, 3>& s, const std::array<double, 3>& k, double c) {
                    return std::array<double, 3>{s[0] + c * k[0], s[1] + c * k[1], s[2] + c * k[2]};
                };
                const auto k1 = deriv(x, a0, seg.jerk);
                const auto k2 = deriv(add(x, k1, h / 2), am, seg.jerk);
                const auto k3 = deriv(add(x, k2, h / 2), am, seg.jerk);
                const auto k4 = deriv(add(x, k3, h), a1, seg.jerk);
                for (int k = 0; k < 3; ++k) {
                    x[k] += h / 6.0 * (k1[k] + 2 * k2[k] + 2 * k3[k] + k4[k]);
                }
                a = a1;
                maxE = std::max(maxE, std::abs(x[0]));
            }
        }
        (withFilter ? out.maxErrorWithFilter : out.maxErrorWithoutFilter) = maxE;
    }
    return out;
}

}  // namespace axistune::tuning

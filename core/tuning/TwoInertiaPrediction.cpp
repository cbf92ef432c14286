// SPDX-License-Identifier: GPL-3.0-or-later
// Plant from the closed velocity loop (docs/tuning.md "Two-inertia fit on the simulated drive's
// closed-loop FRF": injection hold, L = T/(1−T), P = L/C), load-error traces of the S-curve of
// TI-6 with and without F_m (spec §2.5, §4.10, §4.13), and the load position through the motor →
// load transfer (5.6) driven by a measured motor motion. RK4 throughout.
#include "core/tuning/TwoInertiaPrediction.h"

#include "core/dsp/InjectionHold.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/model/Constants.h"
#include "core/model/MetadataKeys.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace axistune::tuning {

namespace {
using model::kTwoPi;
using State = std::array<double, 3>;

State add(const State& s, const State& k, double c) { return {s[0] + c * k[0], s[1] + c * k[1], s[2] + c * k[2]}; }
}  // namespace

Result<dsp::FrequencyResponse> plantFromVelocityLoop(const dsp::FrequencyResponse& t, const VelocityPi& pi,
                                                     double velocityPeriodS, double currentPeriodS)
{
    if (!(pi.kpNmsPerRad >= 0.0) || !(pi.kiNmPerRad >= 0.0) || !(pi.kpNmsPerRad + pi.kiNmPerRad > 0.0))
        return makeError(ErrorCode::BadInput, "velocity PI: K_P and K_I must be >= 0 and not both 0");
    if (!(velocityPeriodS > 0.0) || !(currentPeriodS > 0.0))
        return makeError(ErrorCode::BadInput, "velocity and current periods must be > 0");
    if (const auto* v = t.metadata.find(model::meta::kMeasurement); v && v->text() != "complementary")
        return makeError(ErrorCode::BadInput,
                         "the FRF is not a closed velocity loop T = PC/(1+PC) (measurement=" + v->text() + ")");
    const double ratio = velocityPeriodS / currentPeriodS;
    const long n = std::lround(ratio);
    if (n < 1 || std::abs(ratio - static_cast<double>(n)) > 1e-6 * ratio)
        return makeError(ErrorCode::BadInput, "the velocity period must be an integer multiple of the current period");
    dsp::FrequencyResponse corrected = t;
    if (!dsp::isInjectionHoldCorrected(corrected)) {
        if (auto st = dsp::correctInjectionHold(corrected, currentPeriodS, static_cast<int>(n)); !st)
            return st.error();
    }
    auto p = dsp::openLoopFromClosedLoop(corrected, dsp::LoopMeasurement::Complementary);
    divideByVelocityPi(p, pi, velocityPeriodS);
    p.metadata.set(model::meta::kLoop, "plant-from-complementary");
    return p;
}

void divideByVelocityPi(dsp::FrequencyResponse& p, const VelocityPi& pi, double velocityPeriodS)
{
    for (std::size_t i = 0; i < p.size(); ++i) {
        const std::complex<double> zInv = std::polar(1.0, -kTwoPi * p.freqHz[i] * velocityPeriodS);
        const std::complex<double> c = pi.kpNmsPerRad + pi.kiNmPerRad * velocityPeriodS / (1.0 - zInv);
        if (!p.valid[i] || std::abs(c) == 0.0) {
            p.h[i] = 0.0;
            p.valid[i] = false;
        } else {
            p.h[i] /= c;
        }
    }
}

LoadErrorTraces loadErrorTraces(const TwoInertiaParams& p, const SuppressionFilter& f, const MotionProfile& prof,
                                double sampleS)
{
    LoadErrorTraces out;
    if (!(sampleS > 0.0) || !(prof.jerk > 0.0) || !(prof.aMax > 0.0) || !(prof.vMax > 0.0))
        return out;
    // The 7-segment S-curve of predictLoadError (triangular acceleration when a_max is not reached).
    double ta = prof.aMax / prof.jerk;
    double tc = prof.vMax / prof.aMax - ta;
    if (tc < 0.0) {
        ta = std::sqrt(prof.vMax / prof.jerk);
        tc = 0.0;
    }
    struct Seg {
        double dur, jerk;
    };
    const std::array<Seg, 8> segs{{{ta, prof.jerk}, {tc, 0.0}, {ta, -prof.jerk}, {prof.cruiseS, 0.0},
                                   {ta, -prof.jerk}, {tc, 0.0}, {ta, prof.jerk}, {prof.settleS, 0.0}}};
    const double w0 = antiresonanceRadS(p), z0 = zetaZero(p);
    const double wf = kTwoPi * f.f0Hz, t1 = 2.0 * f.zeta / wf;
    const double period = kTwoPi / std::max(w0, wf);
    for (int withFilter = 0; withFilter < 2; ++withFilter) {
        // State: e = y_L − y*, e', q = LPF_{T1}(a*) (F_m realised as y* + q/ω_f², spec §4.10).
        State x{0.0, 0.0, 0.0};
        auto deriv = [&](const State& s, double acc, double jerk) {
            double dm = 0.0, dmv = 0.0, dq = 0.0;
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
            return State{s[1], ddE, dq};
        };
        auto& err = withFilter ? out.withFilter : out.withoutFilter;
        double a = 0.0, t = 0.0, nextSample = 0.0;
        auto record = [&] {
            while (t >= nextSample - 1e-12) {
                err.push_back(x[0]);
                if (!withFilter) {
                    out.tS.push_back(nextSample);
                    out.accelCmd.push_back(a);
                }
                nextSample += sampleS;
            }
        };
        record();
        for (const auto& seg : segs) {
            if (seg.dur <= 0.0)
                continue;
            const int n = std::max(1, static_cast<int>(std::ceil(seg.dur / std::min(period / 400.0, sampleS))));
            const double h = seg.dur / n;
            for (int i = 0; i < n; ++i) {
                const double am = a + seg.jerk * h / 2.0, a1 = a + seg.jerk * h;
                const auto k1 = deriv(x, a, seg.jerk);
                const auto k2 = deriv(add(x, k1, h / 2), am, seg.jerk);
                const auto k3 = deriv(add(x, k2, h / 2), am, seg.jerk);
                const auto k4 = deriv(add(x, k3, h), a1, seg.jerk);
                for (int k = 0; k < 3; ++k)
                    x[k] += h / 6.0 * (k1[k] + 2 * k2[k] + 2 * k3[k] + k4[k]);
                a = a1;
                t += h;
                record();
            }
        }
    }
    const std::size_t n = std::min(out.withFilter.size(), out.withoutFilter.size());
    out.tS.resize(n);
    out.accelCmd.resize(n);
    out.withFilter.resize(n);
    out.withoutFilter.resize(n);
    return out;
}

std::vector<double> predictLoadFromMotor(const TwoInertiaParams& p, std::span<const double> tS,
                                         std::span<const double> ym, std::span<const double> vm)
{
    if (tS.size() != ym.size() || tS.size() != vm.size() || tS.empty())
        return {};
    const double w0 = antiresonanceRadS(p), z0 = zetaZero(p);
    const double hMax = kTwoPi / w0 / 200.0;
    std::vector<double> out(tS.size());
    double yl = ym[0], vl = vm[0];
    out[0] = yl;
    // y_L'' = 2ζω_0 (v_m − y_L') + ω_0² (y_m − y_L), (5.6) as a differential equation.
    auto acc = [&](double y, double v, double yM, double vM) { return 2.0 * z0 * w0 * (vM - v) + w0 * w0 * (yM - y); };
    for (std::size_t i = 1; i < tS.size(); ++i) {
        const double dt = tS[i] - tS[i - 1];
        const int n = std::max(1, static_cast<int>(std::ceil(dt / hMax)));
        const double h = dt / n;
        auto at = [&](double tau, double& yM, double& vM) {
            const double u = dt > 0.0 ? tau / dt : 0.0;
            yM = ym[i - 1] + u * (ym[i] - ym[i - 1]);
            vM = vm[i - 1] + u * (vm[i] - vm[i - 1]);
        };
        for (int k = 0; k < n; ++k) {
            const double tau = k * h;
            double y0, v0, y1, v1, y2, v2;
            at(tau, y0, v0);
            at(tau + h / 2, y1, v1);
            at(tau + h, y2, v2);
            const double k1y = vl, k1v = acc(yl, vl, y0, v0);
            const double k2y = vl + h / 2 * k1v, k2v = acc(yl + h / 2 * k1y, vl + h / 2 * k1v, y1, v1);
            const double k3y = vl + h / 2 * k2v, k3v = acc(yl + h / 2 * k2y, vl + h / 2 * k2v, y1, v1);
            const double k4y = vl + h * k3v, k4v = acc(yl + h * k3y, vl + h * k3v, y2, v2);
            yl += h / 6 * (k1y + 2 * k2y + 2 * k3y + k4y);
            vl += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        }
        out[i] = yl;
    }
    return out;
}

MeasuredLoadError measuredLoadError(std::span<const double> tS, std::span<const double> command,
                                    std::span<const double> load, int standstillSamples)
{
    MeasuredLoadError out;
    const std::size_t n = tS.size();
    if (n < 2 || command.size() != n || load.size() != n || standstillSamples < 1)
        return out;
    const auto w = static_cast<std::size_t>(standstillSamples);
    const double offset = load[0] - command[0];
    for (std::size_t i = 0; i < n; ++i) {
        bool fresh = i > 0 && command[i] != command[i - 1];
        if (!fresh) {
            const std::size_t lo = i >= w ? i - w : 0, hi = std::min(n - 1, i + w);
            fresh = std::all_of(command.begin() + static_cast<std::ptrdiff_t>(lo),
                                command.begin() + static_cast<std::ptrdiff_t>(hi) + 1,
                                [&](double c) { return c == command[i]; });
        }
        if (!fresh)
            continue;
        out.tS.push_back(tS[i] - tS[0]);
        out.error.push_back(load[i] - command[i] - offset);
        out.maxAbs = std::max(out.maxAbs, std::abs(out.error.back()));
    }
    return out;
}

double sCurveRampS(const MotionProfile& prof)
{
    double tj = prof.aMax / prof.jerk;
    double ta = prof.vMax / prof.aMax - tj;
    if (ta < 0.0) {
        tj = std::sqrt(prof.vMax / prof.jerk);
        ta = 0.0;
    }
    return 2.0 * tj + ta;
}

}  // namespace axistune::tuning

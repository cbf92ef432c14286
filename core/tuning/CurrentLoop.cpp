// SPDX-License-Identifier: GPL-3.0-or-later
// Current-loop gain and PI-ratio selection, spec/current-loop-and-multisweep-frf.md chapter 2:
// dead-time stability with a gain margin (§2.4, robust sum-of-atan phase, smallest phase crossover),
// voltage envelope (§2.5, quadratic form of (2.9)/(2.10) with τ = 0), overshoot (§2.6, (2.14)–(2.15)
// with atan2 and the log form), rise time 10–90 % of the delay-free closed loop (§2.8 [ANALYST]
// reading, which reproduces the paper's 100/180/120 µs), α sweep and optimum (§2.8), schedule (2.16).
// The voltage closed loop (2.6) is used with the corrected denominator L s² + R s + (k_p s + k_i)e^{−τs}
// (the printed one puts e^{−τs} on the s-term only); with τ = 0 both agree.
#include "core/tuning/CurrentLoop.h"

#include "core/model/Constants.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

namespace axistune::tuning {

namespace {

using model::kPi;

double gmFactor(double gainMarginDb) { return std::pow(10.0, -gainMarginDb / 20.0); }

double openLoopPhase(const MotorData& m, double tau, PiGains g, double w)
{
    return -kPi / 2.0 + std::atan2(g.kpVPerA * w, g.kiVPerAs) - std::atan2(w * m.inductanceQH, m.resistanceOhm) - tau * w;
}

}  // namespace

double openLoopMagnitude(const MotorData& m, PiGains g, double w)
{
    const double num = std::hypot(g.kpVPerA * w, g.kiVPerAs);
    const double den = w * std::hypot(m.inductanceQH * w, m.resistanceOhm);
    return num / den;
}

double phaseCrossoverRadS(const MotorData& m, double tau, PiGains g)
{
    if (tau <= 0.0) {
        return -1.0;  // the phase only approaches −π asymptotically
    }
    double w0 = 1.0 / tau;
    if (m.resistanceOhm > 0.0) {
        w0 = std::min(w0, m.resistanceOhm / m.inductanceQH);
    }
    if (g.kiVPerAs > 0.0 && g.kpVPerA > 0.0) {
        w0 = std::min(w0, g.kiVPerAs / g.kpVPerA);
    }
    // A start below the smallest normal double (a resistance or k_i/k_p near 5e-324) would never grow
    // by the factor 1.01 below: start there instead (at most ~72,000 steps up to 2π/τ).
    w0 = std::max(w0 * 1e-3, std::numeric_limits<double>::min());
    auto f = [&](double w) { return openLoopPhase(m, tau, g, w) + kPi; };
    if (f(w0) <= 0.0) {
        return w0;
    }
    // The sum of the atan terms lies in [−π/2, 0], so the phase is below −π once τω > π.
    double lo = w0;
    double hi = w0;
    while (true) {
        hi = lo * 1.01;
        if (f(hi) <= 0.0) {
            break;
        }
        lo = hi;
        if (tau * lo > 2.0 * kPi) {
            return -1.0;  // unreachable in theory; guards against NaN input
        }
    }
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) > 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

bool isStableWithMargin(const MotorData& m, double tau, double gainMarginDb, PiGains g)
{
    const double wpc = phaseCrossoverRadS(m, tau, g);
    if (wpc < 0.0) {
        return true;
    }
    return openLoopMagnitude(m, g, wpc) < gmFactor(gainMarginDb);
}

double maxStableKp(const MotorData& m, double tau, double gainMarginDb)
{
    // k_i → 0⁺: arg G = −atan(ωL/R) − τω (independent of k_p); |G| = k_p/|R + jωL|.
    if (tau <= 0.0) {
        return std::numeric_limits<double>::infinity();
    }
    auto f = [&](double w) { return std::atan2(w * m.inductanceQH, m.resistanceOhm) + tau * w - kPi; };
    double lo = 0.0;
    double hi = kPi / tau;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) < 0.0 ? lo : hi) = mid;
    }
    const double w = 0.5 * (lo + hi);
    return gmFactor(gainMarginDb) * std::hypot(m.resistanceOhm, w * m.inductanceQH);
}

double maxStableKi(const MotorData& m, double tau, double gainMarginDb, double kp)
{
    if (kp <= 0.0 || kp >= maxStableKp(m, tau, gainMarginDb)) {
        return 0.0;
    }
    auto stable = [&](double ki) { return isStableWithMargin(m, tau, gainMarginDb, PiGains{ki, kp}); };
    double lo = 0.0;
    double hi = std::max(kp / std::max(tau, 1e-9), 1.0);
    int guard = 0;
    while (stable(hi)) {
        lo = hi;
        hi *= 2.0;
        if (++guard > 200) {
            return std::numeric_limits<double>::infinity();
        }
    }
    for (int i = 0; i < 60 && (hi - lo) > 1e-9 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (stable(mid) ? lo : hi) = mid;
    }
    return lo;
}

bool isVoltageOk(const MotorData& m, double alpha, double r, PiGains g)
{
    const double L = m.inductanceQH;
    const double kp = g.kpVPerA;
    const double ki = g.kiVPerAs;
    const double a = L * L * (1.0 - alpha * alpha * r * r * kp * kp);
    const double b = (kp + m.resistanceOhm) * (kp + m.resistanceOhm) - r * r * L * L * ki * ki - 2.0 * L * ki;
    const double c = ki * ki;
    if (a < 0.0) {
        return false;
    }
    return b >= 0.0 || b * b <= 4.0 * a * c;
}

double maxVoltageKi(const MotorData& m, double alpha, double r, double kp, double kiUpper)
{
    auto ok = [&](double ki) { return isVoltageOk(m, alpha, r, PiGains{ki, kp}); };
    if (!ok(0.0)) {
        return 0.0;
    }
    if (ok(kiUpper)) {
        return kiUpper;
    }
    double lo = 0.0;
    double hi = kiUpper;
    for (int i = 0; i < 80 && (hi - lo) > 1e-10 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (ok(mid) ? lo : hi) = mid;
    }
    return lo;
}

double omegaSZero(const MotorData& m, double r) { return 1.0 / (r * m.inductanceQH); }

double omegaTZero(const MotorData& m, double alpha, double r)
{
    return alpha > 0.0 ? 1.0 / (alpha * r * m.inductanceQH) : std::numeric_limits<double>::infinity();
}

VoltageRegion voltageRegionAt(const MotorData& m, double alpha, double r, double wq)
{
    // S and T of (2.9) divided by V_max²; a relative tolerance decides "= 0".
    const double x = r * r * m.inductanceQH * m.inductanceQH * wq * wq;
    const double S = 1.0 - x;
    const double T = 1.0 - alpha * alpha * x;
    constexpr double kTol = 1e-6;
    const bool sZero = std::abs(S) < kTol;
    const bool tZero = std::abs(T) < kTol;
    if (sZero && T > 0.0) {
        return VoltageRegion::LeftOfParabola;
    }
    if (tZero && S < 0.0) {
        return VoltageRegion::AboveParabola;
    }
    if (S > 0.0 && T > 0.0) {
        return VoltageRegion::OutsideEllipse;
    }
    if (S < 0.0 && T > 0.0) {
        return VoltageRegion::InsideHyperbola;
    }
    return VoltageRegion::InsideEllipse;
}

double stepOvershoot(const MotorData& m, double alpha, PiGains g)
{
    const double ki = g.kiVPerAs;
    const double kp = g.kpVPerA;
    const double L = m.inductanceQH;
    if (ki <= 0.0) {
        return 0.0;  // first order with DC gain α k_p/(R + k_p) ≤ 1
    }
    const double wn = std::sqrt(ki / L);
    const double zeta = (m.resistanceOhm + kp) / (2.0 * std::sqrt(L * ki));
    const double A = alpha * kp / ki;
    if (std::abs(zeta - 1.0) < 1e-7) {
        const double x = A * wn;
        return x <= 1.0 ? 0.0 : (x - 1.0) * std::exp(-x / (x - 1.0));
    }
    if (zeta < 1.0) {
        const double wd = std::sqrt(1.0 - zeta * zeta);
        const double theta = std::atan2(A * wn * wd, 1.0 - A * zeta * wn);
        return std::sqrt(1.0 - 2.0 * A * zeta * wn + A * A * wn * wn) * std::exp(-zeta * (kPi - theta) / wd);
    }
    const double sq = std::sqrt(zeta * zeta - 1.0);
    const double p1 = (zeta - sq) * wn;
    const double p2 = (zeta + sq) * wn;
    if (A * p1 <= 1.0) {
        return 0.0;
    }
    return std::exp((p1 * std::log(A * p2 - 1.0) - p2 * std::log(A * p1 - 1.0)) / (p1 - p2));
}

double overshootBoundaryKi(const MotorData& m, double alpha, double osMax, double kp, double kiUpper)
{
    auto ok = [&](double ki) { return stepOvershoot(m, alpha, PiGains{ki, kp}) <= osMax; };
    if (ok(kiUpper)) {
        return kiUpper;
    }
    double lo = 0.0;
    double hi = kiUpper;
    for (int i = 0; i < 80 && (hi - lo) > 1e-10 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (ok(mid) ? lo : hi) = mid;
    }
    return lo;
}

double delayFreeStep(const MotorData& m, double alpha, PiGains g, double t)
{
    const double L = m.inductanceQH;
    const double kp = g.kpVPerA;
    const double ki = g.kiVPerAs;
    if (t <= 0.0) {
        return 0.0;
    }
    if (ki <= 0.0) {
        const double a = (m.resistanceOhm + kp) / L;
        return alpha * kp / (m.resistanceOhm + kp) * (1.0 - std::exp(-a * t));
    }
    const double wn = std::sqrt(ki / L);
    const double zeta = (m.resistanceOhm + kp) / (2.0 * std::sqrt(L * ki));
    const double A = alpha * kp / ki;
    if (std::abs(zeta - 1.0) < 1e-6) {
        const double e = std::exp(-wn * t);
        return 1.0 - e * (1.0 + wn * t) + A * wn * wn * t * e;
    }
    using C = std::complex<double>;
    const C sq = std::sqrt(C(zeta * zeta - 1.0, 0.0));
    const C s1 = (-zeta + sq) * wn;
    const C s2 = (-zeta - sq) * wn;
    auto term = [&](C s, C other) { return (A * s + 1.0) * wn * wn * std::exp(s * t) / (s * (s - other)); };
    return 1.0 + (term(s1, s2) + term(s2, s1)).real();
}

double riseTime1090(const MotorData& m, double alpha, PiGains g)
{
    const double L = m.inductanceQH;
    const double kp = g.kpVPerA;
    const double ki = g.kiVPerAs;
    double fast = (m.resistanceOhm + kp) / L;
    double slow = fast;
    double period = std::numeric_limits<double>::infinity();
    if (ki > 0.0) {
        const double wn = std::sqrt(ki / L);
        const double zeta = (m.resistanceOhm + kp) / (2.0 * std::sqrt(L * ki));
        if (zeta < 1.0) {
            fast = wn;
            slow = zeta * wn;
            period = 2.0 * kPi / (wn * std::sqrt(1.0 - zeta * zeta));
        } else {
            const double sq = std::sqrt(zeta * zeta - 1.0);
            fast = (zeta + sq) * wn;
            slow = (zeta - sq) * wn;
        }
    }
    if (!(fast > 0.0) || !(slow > 0.0)) {
        return -1.0;
    }
    const double dtMax = std::min(period / 40.0, 0.05 / slow);
    const double tEnd = 60.0 / slow;
    auto crossing = [&](double level, double tStart) -> double {
        double t = tStart;
        double dt = std::min(0.02 / fast, dtMax);
        double yPrev = delayFreeStep(m, alpha, g, t);
        if (yPrev >= level) {
            return t;
        }
        while (t < tEnd) {
            const double tn = t + dt;
            const double y = delayFreeStep(m, alpha, g, tn);
            if (y >= level) {
                double lo = t;
                double hi = tn;
                for (int i = 0; i < 50; ++i) {
                    const double mid = 0.5 * (lo + hi);
                    (delayFreeStep(m, alpha, g, mid) >= level ? hi : lo) = mid;
                }
                return 0.5 * (lo + hi);
            }
            t = tn;
            dt = std::min(dt * 1.03, dtMax);
        }
        return -1.0;
    };
    const double t10 = crossing(0.1, 0.0);
    if (t10 < 0.0) {
        return -1.0;
    }
    const double t90 = crossing(0.9, t10);
    return t90 < 0.0 ? -1.0 : t90 - t10;
}

double backEmfV(double backEmfVPerKrpm, double speedRpm) { return backEmfVPerKrpm * speedRpm / 1000.0; }

double scheduleFactor(const MotorData& m, double currentA)
{
    return (m.maxCurrentA - m.inductanceDropAtMax * std::abs(currentA)) / m.maxCurrentA;
}

}  // namespace axistune::tuning

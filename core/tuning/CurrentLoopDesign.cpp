// SPDX-License-Identifier: GPL-3.0-or-later
// Current-loop parameter-determination procedure, spec/current-loop-and-multisweep-frf.md §2.8:
// for each α on a grid, minimise the 10–90 % rise time over the (k_p, k_i) set that satisfies the
// dead-time stability, voltage-envelope and overshoot constraints; α* minimises over α; the gains
// are then scheduled with (2.16). Plot data (Figs. 2.5, 2.7, 2.8, 2.10) and a delay-inclusive
// discrete step response (ZOH at the current period plus the dead time, §2.8 "observation").
//
// Search: for a k_p the admissible k_i form an interval (0, k_i,lim] with
// k_i,lim = min(stability, overshoot, voltage) (each constraint is monotone in k_i, §2.4–2.6);
// the rise time is scanned inside that interval, first on a coarse k_p grid, then refined around
// the best k_p (numerical tolerance comparable to §4.6: k_p ±0.1 V/A, k_i ±1 %, t_r ±0.5 µs).
#include "core/tuning/CurrentLoop.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace axistune::tuning {

namespace {

struct KpEval {
    double kp = 0.0;
    double kiStab = 0.0;
    double kiOver = 0.0;
    double kiVolt = 0.0;
    double kiLim = 0.0;
    double ki = 0.0;
    double rise = std::numeric_limits<double>::infinity();
};

double currentPerVolt(const MotorData& m, const CurrentLoopSettings& s)
{
    return s.rippleFraction * m.maxCurrentA / m.maxVoltageV;
}

KpEval evalKp(const MotorData& m, const CurrentLoopSettings& s, double alpha, double kp, double kiStab)
{
    KpEval e;
    e.kp = kp;
    e.kiStab = kiStab;
    if (kiStab <= 0.0) {
        return e;
    }
    e.kiOver = overshootBoundaryKi(m, alpha, s.overshootMax, kp, kiStab);
    e.kiVolt = maxVoltageKi(m, alpha, currentPerVolt(m, s), kp, kiStab);
    e.kiLim = std::min({e.kiStab, e.kiOver, e.kiVolt});
    if (e.kiLim <= 0.0) {
        return e;
    }
    // The rise time is scanned from the limit downwards (the optimum usually sits on the limit).
    constexpr int kSteps = 40;
    for (int i = 0; i <= kSteps; ++i) {
        const double ki = e.kiLim * (1.0 - 0.9 * i / kSteps);
        const double tr = riseTime1090(m, alpha, PiGains{ki, kp});
        if (tr > 0.0 && tr < e.rise) {
            e.rise = tr;
            e.ki = ki;
        }
    }
    return e;
}

AlphaOptimum finish(const MotorData& m, const CurrentLoopSettings& s, double alpha, const KpEval& best)
{
    AlphaOptimum o;
    o.alpha = alpha;
    if (!std::isfinite(best.rise)) {
        return o;
    }
    o.feasible = true;
    o.gains = PiGains{best.ki, best.kp};
    o.riseTimeS = best.rise;
    o.overshoot = stepOvershoot(m, alpha, o.gains);
    constexpr double kNear = 0.98;  // "active" = within 2 % of that constraint's k_i limit
    if (best.ki >= kNear * best.kiStab) {
        o.activeConstraints.emplace_back("stability");
    }
    const double r = currentPerVolt(m, s);
    if (best.ki >= kNear * best.kiVolt || alpha * r * best.kp >= kNear) {
        o.activeConstraints.emplace_back("voltage");
    }
    if (best.ki >= kNear * best.kiOver) {
        o.activeConstraints.emplace_back("overshoot");
    }
    return o;
}

struct StabilityGrid {
    std::vector<double> kp;
    std::vector<double> kiMax;
};

StabilityGrid makeGrid(const MotorData& m, const CurrentLoopSettings& s, int points)
{
    StabilityGrid g;
    const double kpMax = maxStableKp(m, s.deadTimeS, s.gainMarginDb);
    for (int j = 1; j <= points; ++j) {
        const double kp = kpMax * j / (points + 1.0);
        g.kp.push_back(kp);
        g.kiMax.push_back(maxStableKi(m, s.deadTimeS, s.gainMarginDb, kp));
    }
    return g;
}

AlphaOptimum optimiseOnGrid(const MotorData& m, const CurrentLoopSettings& s, double alpha, const StabilityGrid& grid)
{
    KpEval best;
    std::size_t bestIdx = 0;
    for (std::size_t j = 0; j < grid.kp.size(); ++j) {
        KpEval e = evalKp(m, s, alpha, grid.kp[j], grid.kiMax[j]);
        if (e.rise < best.rise) {
            best = e;
            bestIdx = j;
        }
    }
    if (!std::isfinite(best.rise)) {
        return finish(m, s, alpha, best);
    }
    // Refinement: two passes of a finer k_p grid around the best coarse point.
    double step = grid.kp.size() > 1 ? grid.kp[1] - grid.kp[0] : grid.kp[0];
    double centre = grid.kp[bestIdx];
    for (int pass = 0; pass < 2; ++pass) {
        constexpr int kHalf = 10;
        const double fine = 1.5 * step / kHalf;
        for (int i = -kHalf; i <= kHalf; ++i) {
            const double kp = centre + i * fine;
            if (kp <= 0.0) {
                continue;
            }
            const double kiStab = maxStableKi(m, s.deadTimeS, s.gainMarginDb, kp);
            KpEval e = evalKp(m, s, alpha, kp, kiStab);
            if (e.rise < best.rise) {
                best = e;
            }
        }
        centre = best.kp;
        step = fine;
    }
    // Final 1-D refinement in k_i at the best k_p (the coarse k_i scan has 2.25 % steps).
    const double span = best.kiLim * 0.9 / 40.0;
    for (int i = -20; i <= 20; ++i) {
        const double ki = std::min(best.ki + i * span / 20.0, best.kiLim);
        const double tr = riseTime1090(m, alpha, PiGains{ki, best.kp});
        if (ki > 0.0 && tr > 0.0 && tr < best.rise) {
            best.rise = tr;
            best.ki = ki;
        }
    }
    return finish(m, s, alpha, best);
}

constexpr int kCoarsePoints = 100;

}  // namespace

Status validateSettings(const CurrentLoopSettings& s)
{
    auto bad = [](const std::string& what) { return Status(makeError(ErrorCode::OutOfRange, what)); };
    if (!(s.deadTimeS > 0.0) || s.deadTimeS > 0.01) {
        return bad("dead time must be in (0, 0.01] s, got " + std::to_string(s.deadTimeS));
    }
    if (!(s.gainMarginDb >= 0.0) || s.gainMarginDb > 40.0) {
        return bad("gain margin must be in [0, 40] dB, got " + std::to_string(s.gainMarginDb));
    }
    if (!(s.overshootMax > 0.0) || s.overshootMax >= 1.0) {
        return bad("overshoot limit must be in (0, 1), got " + std::to_string(s.overshootMax));
    }
    if (!(s.rippleFraction > 0.0) || s.rippleFraction > 1.0) {
        return bad("ripple fraction must be in (0, 1], got " + std::to_string(s.rippleFraction));
    }
    if (!(s.alphaStep >= 0.01) || s.alphaStep > 1.0) {
        return bad("alpha step must be in [0.01, 1], got " + std::to_string(s.alphaStep));
    }
    return Status::success();
}

AlphaOptimum optimiseAlpha(const MotorData& m, const CurrentLoopSettings& s, double alpha)
{
    return optimiseOnGrid(m, s, alpha, makeGrid(m, s, kCoarsePoints));
}

Result<CurrentLoopDesign> designCurrentLoop(const MotorData& m, const CurrentLoopSettings& s)
{
    if (auto st = validateMotor(m, "motor"); !st) {
        return st.error();
    }
    if (auto st = validateSettings(s); !st) {
        return st.error();
    }
    const StabilityGrid grid = makeGrid(m, s, kCoarsePoints);
    CurrentLoopDesign d;
    const int n = static_cast<int>(std::floor(1.0 / s.alphaStep + 1e-9));
    std::vector<double> alphas;
    for (int i = 0; i <= n; ++i) {
        alphas.push_back(std::min(1.0, i * s.alphaStep));
    }
    if (alphas.back() < 1.0 - 1e-12) {
        alphas.push_back(1.0);
    }
    const AlphaOptimum* best = nullptr;
    for (double a : alphas) {
        d.table.push_back(optimiseOnGrid(m, s, a, grid));
    }
    for (const auto& o : d.table) {
        if (o.feasible && (!best || o.riseTimeS < best->riseTimeS)) {
            best = &o;
        }
    }
    if (!best) {
        return makeError(ErrorCode::BadInput, "no (k_i, k_p) satisfies the stability, voltage and overshoot constraints");
    }
    d.alpha = best->alpha;
    d.gains = best->gains;
    d.riseTimeS = best->riseTimeS;
    std::vector<double> currents;
    for (int i = 0; i <= 10; ++i) {
        currents.push_back(m.maxCurrentA * i / 10.0);
    }
    if (m.ratedCurrentA > 0.0 && m.ratedCurrentA <= m.maxCurrentA) {
        currents.push_back(m.ratedCurrentA);
        std::sort(currents.begin(), currents.end());
    }
    for (double i : currents) {
        const double f = scheduleFactor(m, i);
        d.schedule.push_back(SchedulePoint{i, f, PiGains{d.gains.kiVPerAs * f, d.gains.kpVPerA * f}});
    }
    return d;
}

BoundaryCurve stabilityBoundary(const MotorData& m, const CurrentLoopSettings& s, int points)
{
    const StabilityGrid g = makeGrid(m, s, points);
    BoundaryCurve c;
    c.kpVPerA = g.kp;
    c.kiVPerAs = g.kiMax;
    return c;
}

BoundaryCurve voltageEnvelope(const MotorData& m, const CurrentLoopSettings& s, double alpha, int points)
{
    BoundaryCurve c;
    const double kpMax = maxStableKp(m, s.deadTimeS, s.gainMarginDb);
    const double r = currentPerVolt(m, s);
    // Upper search bound: far outside the stability region (k_i of the voltage region is finite for S > 0).
    const double kiUpper = 1e3 * std::max(1.0, kpMax) / s.deadTimeS;
    for (int j = 1; j <= points; ++j) {
        const double kp = kpMax * j / (points + 1.0);
        c.kpVPerA.push_back(kp);
        c.kiVPerAs.push_back(maxVoltageKi(m, alpha, r, kp, kiUpper));
    }
    return c;
}

BoundaryCurve overshootCurve(const MotorData& m, const CurrentLoopSettings& s, double alpha, int points)
{
    BoundaryCurve c;
    const double kpMax = maxStableKp(m, s.deadTimeS, s.gainMarginDb);
    const double kiUpper = 1e3 * std::max(1.0, kpMax) / s.deadTimeS;
    for (int j = 1; j <= points; ++j) {
        const double kp = kpMax * j / (points + 1.0);
        c.kpVPerA.push_back(kp);
        c.kiVPerAs.push_back(overshootBoundaryKi(m, alpha, s.overshootMax, kp, kiUpper));
    }
    return c;
}

StepResponse stepResponses(const MotorData& m, double alpha, PiGains g, double tau, double Ts, double duration)
{
    StepResponse r;
    if (!(Ts > 0.0) || !(duration > 0.0) || tau < 0.0) {
        return r;
    }
    const auto n = static_cast<long>(std::ceil(duration / Ts));
    const auto nDelay = static_cast<long>(std::floor(tau / Ts + 1e-9));
    const double frac = std::max(0.0, tau / Ts - static_cast<double>(nDelay));
    const double R = m.resistanceOhm;
    const double L = m.inductanceQH;
    // Exact ZOH integration of L di/dt = v − R i over a sub-interval of length h.
    auto advance = [&](double i, double v, double h) {
        if (h <= 0.0) {
            return i;
        }
        if (R <= 0.0) {
            return i + v * h / L;
        }
        const double e = std::exp(-R * h / L);
        return e * i + (1.0 - e) / R * v;
    };
    std::vector<double> v(static_cast<std::size_t>(n + 1), 0.0);
    auto vAt = [&](long k) { return k >= 0 ? v[static_cast<std::size_t>(k)] : 0.0; };
    double i = 0.0;
    double integ = 0.0;
    for (long k = 0; k <= n; ++k) {
        r.timeS.push_back(k * Ts);
        r.delayFree.push_back(delayFreeStep(m, alpha, g, k * Ts));
        r.discrete.push_back(i);
        const double e = 1.0 - i;
        integ += g.kiVPerAs * Ts * e;  // backward-Euler integrator: includes this sample's error
        v[static_cast<std::size_t>(k)] = integ + g.kpVPerA * (alpha - i);
        // Over [kT, (k+1)T) the voltage computed at k−nDelay−1 acts for frac·T, then v[k−nDelay].
        i = advance(i, vAt(k - nDelay - 1), frac * Ts);
        i = advance(i, vAt(k - nDelay), (1.0 - frac) * Ts);
    }
    return r;
}

}  // namespace axistune::tuning

// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/MotionProfile.h"

#include <algorithm>
#include <cmath>

namespace axistune::sim {

void MotionProfile::push(double dt, double a, double j)
{
    if (dt <= 0.0)
        return;
    double x = m_start, v = 0.0, t0 = 0.0;
    if (!m_pieces.empty()) {  // the end state of the last piece
        const Piece& p = m_pieces.back();
        x = p.x0 + p.v0 * p.dt + 0.5 * p.a * p.dt * p.dt + p.j * p.dt * p.dt * p.dt / 6.0;
        v = p.v0 + p.a * p.dt + 0.5 * p.j * p.dt * p.dt;
        t0 = p.t0 + p.dt;
    }
    m_pieces.push_back({t0, dt, x, v, a, j});
}

void MotionProfile::dwell(double durationS) { push(durationS, 0.0); }

void MotionProfile::move(double distance, double velocity, double acceleration)
{
    if (distance == 0.0 || velocity <= 0.0 || acceleration <= 0.0)
        return;
    const double sgn = distance > 0 ? 1.0 : -1.0;
    const double d = std::abs(distance);
    double vPeak = velocity;
    double tAcc = vPeak / acceleration;
    double dAcc = 0.5 * acceleration * tAcc * tAcc;
    double tConst = 0.0;
    if (2.0 * dAcc > d) {  // triangle
        tAcc = std::sqrt(d / acceleration);
        vPeak = acceleration * tAcc;
    } else {
        tConst = (d - 2.0 * dAcc) / vPeak;
    }
    push(tAcc, sgn * acceleration);
    push(tConst, 0.0);
    push(tAcc, -sgn * acceleration);
}

void MotionProfile::move(double distance, double velocity, double acceleration, double jerk)
{
    if (!(jerk > 0.0) || !std::isfinite(jerk)) {
        move(distance, velocity, acceleration);
        return;
    }
    if (distance == 0.0 || velocity <= 0.0 || acceleration <= 0.0)
        return;
    const double sgn = distance > 0 ? 1.0 : -1.0;
    const double d = std::abs(distance);
    // Jerk time tj and constant-acceleration time ta of the ramp to speed v; the ramp is point-symmetric
    // about its middle, so it covers v·(2·tj + ta)/2.
    auto ramp = [&](double v, double& tj, double& ta) {
        tj = acceleration / jerk;
        ta = v / acceleration - tj;
        if (ta < 0.0) {  // a_max is not reached
            tj = std::sqrt(v / jerk);
            ta = 0.0;
        }
        return v * (2.0 * tj + ta);  // both ramps
    };
    double tj = 0.0, ta = 0.0, vPeak = velocity;
    if (ramp(vPeak, tj, ta) > d) {  // v_max is not reached: the largest peak speed whose ramps fit
        double lo = 0.0, hi = velocity;
        for (int i = 0; i < 200 && hi - lo > 1e-15 * velocity; ++i) {
            const double mid = 0.5 * (lo + hi);
            (ramp(mid, tj, ta) > d ? hi : lo) = mid;
        }
        vPeak = lo;
    }
    const double both = ramp(vPeak, tj, ta);
    const double tc = (d - both) / vPeak;
    const double aPeak = jerk * tj;
    for (const double s : {sgn, -sgn}) {  // accelerate, (cruise), decelerate
        push(tj, 0.0, s * jerk);
        push(ta, s * aPeak, 0.0);
        push(tj, s * aPeak, -s * jerk);
        if (s == sgn)
            push(tc, 0.0, 0.0);
    }
}

MotionState MotionProfile::at(double tS) const
{
    if (m_pieces.empty() || tS <= 0.0)
        return {m_start, 0.0, 0.0};
    // The last piece that starts at or before tS.
    auto it = std::upper_bound(m_pieces.begin(), m_pieces.end(), tS,
                               [](double t, const Piece& p) { return t < p.t0; });
    const Piece& p = *(it - 1);
    const bool after = tS >= p.t0 + p.dt;
    const double tau = after ? p.dt : tS - p.t0;
    MotionState s;
    s.position = p.x0 + p.v0 * tau + 0.5 * p.a * tau * tau + p.j * tau * tau * tau / 6.0;
    s.velocity = p.v0 + p.a * tau + 0.5 * p.j * tau * tau;
    s.acceleration = after ? 0.0 : p.a + p.j * tau;
    return s;
}

}  // namespace axistune::sim

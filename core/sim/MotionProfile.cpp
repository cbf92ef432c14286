// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/MotionProfile.h"

#include <algorithm>
#include <cmath>

namespace axistune::sim {

void MotionProfile::push(double dt, double a)
{
    if (dt <= 0.0)
        return;
    double x = m_start, v = 0.0, t0 = 0.0;
    if (!m_pieces.empty()) {  // the end state of the last piece
        const Piece& p = m_pieces.back();
        x = p.x0 + p.v0 * p.dt + 0.5 * p.a * p.dt * p.dt;
        v = p.v0 + p.a * p.dt;
        t0 = p.t0 + p.dt;
    }
    m_pieces.push_back({t0, dt, x, v, a});
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
    s.position = p.x0 + p.v0 * tau + 0.5 * p.a * tau * tau;
    s.velocity = p.v0 + p.a * tau;
    s.acceleration = after ? 0.0 : p.a;
    return s;
}

}  // namespace axistune::sim

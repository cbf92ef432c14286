// SPDX-License-Identifier: GPL-3.0-or-later
// Milling with regeneration (regenerative chip thickness with a delay of one tooth period), the model of
// spec/chatter-stability-and-spindle-speed.md §1.3 (eqs. (1-1)–(1-9)) in the time domain with the
// loss-of-contact nonlinearity; modes integrated exactly under a zero-order hold of the force.
#include "core/sim/Milling.h"

#include "core/model/Constants.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace axistune::sim {
namespace {

using model::kTwoPi;

Status checkModes(const std::vector<MillingMode>& modes, const std::string& dir)
{
    for (std::size_t i = 0; i < modes.size(); ++i) {
        const auto& m = modes[i];
        const std::string at = "modes_" + dir + "[" + std::to_string(i) + "]";
        // mass, damping and stiffness all negative: a negative-residue mode (ToolModel.cpp, e.g. the cascade (5-1))
        if (!std::isfinite(m.massKg) || m.massKg == 0.0)
            return makeError(ErrorCode::OutOfRange, at + ".mass_kg must be non-zero (got " + std::to_string(m.massKg) +
                                                        "; > 0, or < 0 with negative damping and stiffness)");
        const double sign = m.massKg > 0.0 ? 1.0 : -1.0;
        if (!std::isfinite(m.stiffnessNPerM) || sign * m.stiffnessNPerM <= 0.0)
            return makeError(ErrorCode::OutOfRange, at +
                                                        ".stiffness_N_per_m must be non-zero with the sign of mass_kg "
                                                        "(got " +
                                                        std::to_string(m.stiffnessNPerM) + ")");
        if (!std::isfinite(m.dampingNsPerM) || sign * m.dampingNsPerM < 0.0)
            return makeError(ErrorCode::OutOfRange, at + ".damping_Ns_per_m must have the sign of mass_kg (got " +
                                                        std::to_string(m.dampingNsPerM) + ")");
        if (std::abs(m.dampingNsPerM) >= 2.0 * std::sqrt(m.massKg * m.stiffnessNPerM))
            return makeError(ErrorCode::OutOfRange, at + ": the mode must be underdamped (damping ratio < 1)");
    }
    return Status::success();
}

} // namespace

Status validateMillingSetup(const MillingSetup& s)
{
    if (s.modesX.empty() && s.modesY.empty())
        return makeError(ErrorCode::BadInput,
                         "modes_x, modes_y: at least one mode is needed (an empty list is a rigid direction)");
    if (auto st = checkModes(s.modesX, "x"); !st)
        return st;
    if (auto st = checkModes(s.modesY, "y"); !st)
        return st;
    if (s.teeth < 1 || s.teeth > 100)
        return makeError(ErrorCode::OutOfRange,
                         "teeth must be between 1 and 100 (got " + std::to_string(s.teeth) + ")");
    if (!std::isfinite(s.ktNPerM2) || s.ktNPerM2 <= 0.0)
        return makeError(ErrorCode::OutOfRange, "Kt_N_per_m2 must be > 0");
    if (!std::isfinite(s.krNPerM2) || s.krNPerM2 < 0.0)
        return makeError(ErrorCode::OutOfRange, "Kr_N_per_m2 must be >= 0");
    if (!std::isfinite(s.radialImmersion) || s.radialImmersion <= 0.0 || s.radialImmersion > 1.0)
        return makeError(ErrorCode::OutOfRange,
                         "radial_immersion must be in (0, 1] (got " + std::to_string(s.radialImmersion) + ")");
    if (!std::isfinite(s.spindleRpm) || s.spindleRpm <= 0.0)
        return makeError(ErrorCode::OutOfRange,
                         "spindle speed must be > 0 rpm (got " + std::to_string(s.spindleRpm) + ")");
    if (!std::isfinite(s.axialDepthM) || s.axialDepthM < 0.0)
        return makeError(ErrorCode::OutOfRange,
                         "axial depth must be >= 0 m (got " + std::to_string(s.axialDepthM) + ")");
    if (!std::isfinite(s.feedPerToothM) || s.feedPerToothM < 0.0)
        return makeError(ErrorCode::OutOfRange,
                         "feed per tooth must be >= 0 m (got " + std::to_string(s.feedPerToothM) + ")");
    if (s.stepsPerToothPeriod < 0 || s.stepsPerToothPeriod > 10'000'000)
        return makeError(ErrorCode::OutOfRange, "steps per tooth period must be in [0, 1e7]");
    if (!std::isfinite(s.spindleTimeConstantS) || s.spindleTimeConstantS < 0.0 || s.spindleTimeConstantS > 10.0)
        return makeError(ErrorCode::OutOfRange, "spindle time_constant_s must be in [0, 10] s (got " +
                                                    std::to_string(s.spindleTimeConstantS) + ")");
    if (!std::isfinite(s.spindleMinRpm) || !std::isfinite(s.spindleMaxRpm) || s.spindleMinRpm <= 0.0 ||
        s.spindleMaxRpm < s.spindleMinRpm)
        return makeError(ErrorCode::OutOfRange, "spindle min_rpm must be > 0 and max_rpm >= min_rpm (got " +
                                                    std::to_string(s.spindleMinRpm) + ", " +
                                                    std::to_string(s.spindleMaxRpm) + ")");
    if (s.spindleRpm < s.spindleMinRpm || s.spindleRpm > s.spindleMaxRpm)
        return makeError(ErrorCode::OutOfRange,
                         "spindle speed " + std::to_string(s.spindleRpm) + " rpm is outside the spindle limits [" +
                             std::to_string(s.spindleMinRpm) + ", " + std::to_string(s.spindleMaxRpm) + "] rpm");
    return Status::success();
}

Result<MillingProcess> MillingProcess::create(const MillingSetup& setup)
{
    if (auto st = validateMillingSetup(setup); !st)
        return st.error();
    MillingProcess p;
    p.m_setup = setup;
    p.m_tau = 60.0 / (setup.spindleRpm * setup.teeth);
    p.m_k = setup.stepsPerToothPeriod > 0 ? setup.stepsPerToothPeriod : static_cast<int>(std::ceil(p.m_tau / 5e-6));
    if (p.m_k < 8)
        p.m_k = 8;
    p.m_h = p.m_tau / p.m_k;
    p.m_omega = setup.spindleRpm * model::kRadPerSPerRpm;
    const double r = setup.radialImmersion;
    if (setup.upMilling) {
        p.m_entry = 0.0;
        p.m_exit = std::acos(1.0 - 2.0 * r);
    } else {
        p.m_entry = std::acos(2.0 * r - 1.0);
        p.m_exit = std::numbers::pi;
    }
    auto discretize = [h = p.m_h](const MillingMode& m) {
        // x'' + 2σ x' + ω² x = F/m: exact Φ = e^{Ah}, Γ = A⁻¹(Φ − I)[0, 1/m]ᵀ (underdamped).
        Mode d;
        d.invMass = 1.0 / m.massKg;
        d.damping = m.dampingNsPerM;
        d.stiffness = m.stiffnessNPerM;
        const double w2 = m.stiffnessNPerM / m.massKg;
        const double sigma = 0.5 * m.dampingNsPerM / m.massKg;
        const double wd = std::sqrt(w2 - sigma * sigma);
        const double e = std::exp(-sigma * h), c = std::cos(wd * h), s = std::sin(wd * h);
        d.phi[0][0] = e * (c + sigma / wd * s);
        d.phi[0][1] = e * s / wd;
        d.phi[1][0] = -e * w2 / wd * s;
        d.phi[1][1] = e * (c - sigma / wd * s);
        d.gamma[0] = (-2.0 * sigma / w2 * d.phi[0][1] - (d.phi[1][1] - 1.0) / w2) / m.massKg;
        d.gamma[1] = d.phi[0][1] / m.massKg;
        return d;
    };
    // The history must reach back one tooth period at the lowest spindle speed.
    const double ringLen = std::ceil(60.0 / (setup.spindleMinRpm * setup.teeth) / p.m_h) + 4.0;
    if (ringLen > 2e7)
        return makeError(ErrorCode::OutOfRange, "spindle min_rpm " + std::to_string(setup.spindleMinRpm) +
                                                    " is too low: the delay history would exceed 2e7 steps");
    p.m_ring = static_cast<std::size_t>(std::max(ringLen, static_cast<double>(p.m_k) + 4.0));
    p.m_spindleDecay = setup.spindleTimeConstantS > 0.0 ? std::exp(-p.m_h / setup.spindleTimeConstantS) : 0.0;
    p.m_feedVel = setup.feedPerToothM * setup.teeth * setup.spindleRpm / 60.0;
    for (const auto& m : setup.modesX)
        p.m_mx.push_back(discretize(m));
    for (const auto& m : setup.modesY)
        p.m_my.push_back(discretize(m));
    p.reset();
    return p;
}

void MillingProcess::reset()
{
    for (auto& m : m_mx)
        m.x = m.v = 0.0;
    for (auto& m : m_my)
        m.x = m.v = 0.0;
    m_histX.assign(m_ring * static_cast<std::size_t>(m_setup.teeth), 0.0);
    m_histY.assign(m_ring * static_cast<std::size_t>(m_setup.teeth), 0.0);
    m_histTheta.assign(m_ring, 0.0);
    m_step = 0;
    m_fx = m_fy = 0.0;
    m_rpm = m_rpmCmd = m_setup.spindleRpm;
    m_theta = 0.0;
    m_lag = static_cast<double>(m_k);
    m_delay = m_tau;
    m_cmdLimited = 0;
}

void MillingProcess::setSpindleCommandRpm(double rpm)
{
    if (!std::isfinite(rpm)) {
        ++m_cmdLimited;
        return;
    }
    if (rpm < m_setup.spindleMinRpm || rpm > m_setup.spindleMaxRpm)
        ++m_cmdLimited;
    m_rpmCmd = std::clamp(rpm, m_setup.spindleMinRpm, m_setup.spindleMaxRpm);
}

double MillingProcess::toolAccelX() const
{
    double a = 0.0;
    for (const auto& m : m_mx)
        a += (m_fx - m.damping * m.v - m.stiffness * m.x) * m.invMass;
    return a;
}

double MillingProcess::toolAccelY() const
{
    double a = 0.0;
    for (const auto& m : m_my)
        a += (m_fy - m.damping * m.v - m.stiffness * m.x) * m.invMass;
    return a;
}

double MillingProcess::toolX() const
{
    double x = 0.0;
    for (const auto& m : m_mx)
        x += m.x;
    return x;
}

double MillingProcess::toolY() const
{
    double y = 0.0;
    for (const auto& m : m_my)
        y += m.x;
    return y;
}

void MillingProcess::step()
{
    const double x = toolX(), y = toolY();
    // Delay τ(t): θ(t) − θ(t − τ) = 2π/N (eq. (1-7)). Angles and positions are kept per step; before the cut's
    // first step the spindle turned at the initial speed over a clean surface (positions 0).
    const double pitch = kTwoPi / m_setup.teeth;
    const double w0h = m_setup.spindleRpm * model::kRadPerSPerRpm * m_h;
    const auto n = m_step;
    const auto ring = static_cast<long long>(m_ring);
    auto thetaAt = [&](long long lag) {
        return lag <= n ? m_histTheta[static_cast<std::size_t>((n - lag) % ring)] : -static_cast<double>(lag - n) * w0h;
    };
    // θ history at lag 0 is the current angle (not yet stored).
    auto thetaLag = [&](long long lag) { return lag == 0 ? m_theta : thetaAt(lag); };
    long long lag = std::max(1LL, static_cast<long long>(std::ceil(m_lag - 1e-9)));
    while (lag < ring - 2 && m_theta - thetaLag(lag) < pitch)
        ++lag;
    while (lag > 1 && m_theta - thetaLag(lag - 1) >= pitch)
        --lag;
    // pitch lies between the angle advance over lag−1 and lag steps: interpolate.
    const double dPrev = m_theta - thetaLag(lag - 1), dLag = m_theta - thetaLag(lag);
    const double frac = dLag > dPrev ? std::clamp((pitch - dPrev) / (dLag - dPrev), 0.0, 1.0) : 1.0;
    m_lag = static_cast<double>(lag - 1) + frac;
    m_delay = m_lag * m_h;
    // Surface left by the previous tooth at the same angle: tooth j now meets what tooth j+1 left τ ago
    // (φ_j = θ + 2πj/N). Where a tooth was out of the material (h ≤ 0) it left the older surface, one feed
    // further away, so the chip of the next tooth grows accordingly (the multiple-regenerative effect).
    const auto teeth = static_cast<std::size_t>(m_setup.teeth);
    auto surfaceAt = [&](const std::vector<double>& hist, std::size_t tooth, double now, long long l) {
        if (l == 0)
            return now;
        return l <= n ? hist[static_cast<std::size_t>((n - l) % ring) * teeth + tooth] : 0.0;
    };
    const auto slot = static_cast<std::size_t>(n % ring);
    m_histTheta[slot] = m_theta;
    const double chip = m_feedVel * m_delay; // static chip: the table feed over one delay
    double fx = 0.0, fy = 0.0;
    const double a = m_setup.axialDepthM, kt = m_setup.ktNPerM2, kr = m_setup.krNPerM2;
    const double thetaWrapped = std::fmod(m_theta, kTwoPi);
    for (std::size_t j = 0; j < teeth; ++j) {
        const std::size_t prev = (j + 1) % teeth;
        const double xd = (1.0 - frac) * surfaceAt(m_histX, prev, x, lag - 1) + frac * surfaceAt(m_histX, prev, x, lag);
        const double yd = (1.0 - frac) * surfaceAt(m_histY, prev, y, lag - 1) + frac * surfaceAt(m_histY, prev, y, lag);
        double sx = x, sy = y; // surface this tooth leaves (its own path where it cuts or is out of the window)
        const double phi = std::fmod(thetaWrapped + pitch * static_cast<double>(j), kTwoPi);
        if (phi >= m_entry && phi <= m_exit) {
            const double s = std::sin(phi), c = std::cos(phi);
            const double h = (chip + xd - x) * s + (yd - y) * c;
            if (h > 0.0) {
                fx += a * h * (kt * c + kr * s);
                fy += a * h * (-kt * s + kr * c);
            } else {
                sx = xd + chip; // the tooth has left the material: the older surface stays
                sy = yd;
            }
        }
        m_histX[slot * teeth + j] = sx;
        m_histY[slot * teeth + j] = sy;
    }
    m_fx = fx;
    m_fy = fy;
    for (auto& m : m_mx) {
        const double nx = m.phi[0][0] * m.x + m.phi[0][1] * m.v + m.gamma[0] * fx;
        m.v = m.phi[1][0] * m.x + m.phi[1][1] * m.v + m.gamma[1] * fx;
        m.x = nx;
    }
    for (auto& m : m_my) {
        const double ny = m.phi[0][0] * m.x + m.phi[0][1] * m.v + m.gamma[0] * fy;
        m.v = m.phi[1][0] * m.x + m.phi[1][1] * m.v + m.gamma[1] * fy;
        m.x = ny;
    }
    // Spindle: exact first-order step towards the command; the angle advances by the mean speed.
    const double rpmNext = m_rpmCmd + (m_rpm - m_rpmCmd) * m_spindleDecay;
    m_theta += 0.5 * (m_rpm + rpmNext) * model::kRadPerSPerRpm * m_h;
    m_rpm = rpmNext;
    ++m_step;
}

double MillingProcess::advanceTo(double tS)
{
    double sum = 0.0;
    long n = 0;
    while (time() < tS - 1e-12 * m_h) {
        step();
        sum += m_fx;
        ++n;
    }
    return n > 0 ? sum / static_cast<double>(n) : m_fx;
}

} // namespace axistune::sim

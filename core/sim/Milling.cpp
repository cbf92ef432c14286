// SPDX-License-Identifier: GPL-3.0-or-later
// Milling with regeneration (regenerative chip thickness with a delay of one tooth period), the model of
// spec/chatter-stability-and-spindle-speed.md §1.3 (eqs. (1-1)–(1-9)) in the time domain with the
// loss-of-contact nonlinearity; modes integrated exactly under a zero-order hold of the force.
#include "core/sim/Milling.h"

#include "core/model/Constants.h"

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
        if (!std::isfinite(m.massKg) || m.massKg <= 0.0)
            return makeError(ErrorCode::OutOfRange, at + ".mass_kg must be > 0 (got " + std::to_string(m.massKg) + ")");
        if (!std::isfinite(m.stiffnessNPerM) || m.stiffnessNPerM <= 0.0)
            return makeError(ErrorCode::OutOfRange,
                             at + ".stiffness_N_per_m must be > 0 (got " + std::to_string(m.stiffnessNPerM) + ")");
        if (!std::isfinite(m.dampingNsPerM) || m.dampingNsPerM < 0.0)
            return makeError(ErrorCode::OutOfRange,
                             at + ".damping_Ns_per_m must be >= 0 (got " + std::to_string(m.dampingNsPerM) + ")");
        if (m.dampingNsPerM >= 2.0 * std::sqrt(m.massKg * m.stiffnessNPerM))
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
    m_histX.assign(static_cast<std::size_t>(m_k), 0.0);
    m_histY.assign(static_cast<std::size_t>(m_k), 0.0);
    m_step = 0;
    m_fx = m_fy = 0.0;
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
    const std::size_t slot = static_cast<std::size_t>(m_step % m_k);
    // The ring holds the position k steps ago (0 before the first tooth period: clean surface).
    const double dx = m_histX[slot] - x, dy = m_histY[slot] - y;
    m_histX[slot] = x;
    m_histY[slot] = y;
    const double t = time();
    double fx = 0.0, fy = 0.0;
    const double a = m_setup.axialDepthM, kt = m_setup.ktNPerM2, kr = m_setup.krNPerM2;
    for (int j = 0; j < m_setup.teeth; ++j) {
        double phi = std::fmod(m_omega * t + kTwoPi * j / m_setup.teeth, kTwoPi);
        if (phi < m_entry || phi > m_exit)
            continue;
        const double s = std::sin(phi), c = std::cos(phi);
        const double h = (m_setup.feedPerToothM + dx) * s + dy * c;
        if (h <= 0.0)
            continue; // the tooth has left the material
        fx += a * h * (kt * c + kr * s);
        fy += a * h * (-kt * s + kr * c);
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

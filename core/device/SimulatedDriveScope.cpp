// SPDX-License-Identifier: GPL-3.0-or-later
// The embedded simulated drive's scope (docs/scope.md): a tap on one axis's velocity loop, sampled every
// divider-th velocity period, into a ScopeRecorder. The sample number is the velocity period's number
// divided by the divider, so sample n is at machine time n · divider · T_v.
//
// Channels of the machine's other axes ("Y.table_pos_m": position command, motor and table position, following
// error of every other axis on the same current and velocity periods) come into the same rows, so an XY plot of
// two axes (a circle) pairs samples of one instant. Each axis's simulator runs on its own machine time, only when
// a call moves it; arming brings every sampled axis to the time of the one furthest ahead (they hold what they
// did last meanwhile, as a real axis does), and every poll keeps them together. Their taps write into rows keyed
// by the scope axis's velocity period; a row goes to the recorder once every axis has written it.
#include "core/device/SimulatedDrive.h"

#include <algorithm>
#include <string_view>

namespace axistune::device {

namespace {

/// Whether an axis's scope signal is one other axes' scopes offer (its positions and following error).
bool companionSignal(std::string_view name)
{
    for (std::string_view p : {"position_cmd_", "motor_pos_", "table_pos_", "following_error_"})
        if (name.substr(0, p.size()) == p)
            return true;
    return false;
}

bool sameClock(const sim::AxisSimulator& a, const sim::AxisSimulator& b)
{
    return a.currentPeriod() == b.currentPeriod() && a.velocityPeriod() == b.velocityPeriod();
}

} // namespace

Result<ScopeCapabilities> SimulatedDrive::scopeCapabilities(const std::string& axis)
{
    if (auto st = checkLink(); !st)
        return st.error();
    auto s = axisSim(axis);
    if (!s)
        return s.error();
    ScopeCapabilities c;
    for (const auto& sig : (*s)->scopeSignals())
        c.channels.push_back({sig.name, sig.unit, sig.description});
    for (const auto& [name, other] : m_axes) {
        if (name == axis || !sameClock(**s, *other))
            continue;
        for (const auto& sig : other->scopeSignals())
            if (companionSignal(sig.name))
                c.channels.push_back({name + "." + sig.name, sig.unit, "axis " + name + ": " + sig.description});
    }
    c.fastestRateHz = 1.0 / (*s)->velocityPeriod();
    c.maxChannels = kScopeMaxChannels;
    c.maxDivider = kScopeMaxDivider;
    c.maxValues = kScopeMaxValues;
    c.ringValues = kScopeRingValues;
    return c;
}

void SimulatedDrive::disarmScopeTaps()
{
    for (auto& a : m_scopeAxes)
        a.sim->setScopeTap({});
    if (m_scopeSim)
        m_scopeSim->setScopeTap({});
    m_scopeAxes.clear();
    m_scopePending.clear();
}

Status SimulatedDrive::armScope(const ScopeRequest& request)
{
    auto caps = scopeCapabilities(request.axis);
    if (!caps)
        return caps.error();
    auto setup = checkScopeRequest(request, *caps);
    if (!setup)
        return setup.error();
    disarmScopeTaps();
    m_scopeSim = simulator(request.axis);
    m_scopeChannels.clear();
    m_scopeAxes.push_back({m_scopeSim, {}, 0});
    const std::size_t own = m_scopeSim->scopeSignals().size();
    for (std::size_t col = 0; col < setup->channels.size(); ++col) {
        const std::size_t i = setup->channels[col];
        const ScopeChannelInfo& ch = caps->channels[i];
        m_scopeChannels.push_back(ch);
        if (i < own) {
            m_scopeAxes.front().picks.emplace_back(i, col);
            continue;
        }
        // "AXIS.signal": a companion axis's channel.
        const auto dot = ch.name.find('.');
        sim::AxisSimulator* other = simulator(ch.name.substr(0, dot));
        const auto sigs = other->scopeSignals();
        const auto sig = std::find_if(sigs.begin(), sigs.end(),
                                      [&](const sim::ScopeSignal& g) { return g.name == ch.name.substr(dot + 1); });
        auto a =
            std::find_if(m_scopeAxes.begin(), m_scopeAxes.end(), [&](const ScopeAxis& x) { return x.sim == other; });
        if (a == m_scopeAxes.end())
            a = m_scopeAxes.insert(m_scopeAxes.end(), ScopeAxis{other, {}, 0});
        a->picks.emplace_back(static_cast<std::size_t>(sig - sigs.begin()), col);
    }
    m_scopeRow.assign(setup->channels.size(), 0.0);
    m_scope.arm(*setup, kScopeRingValues / setup->channels.size());
    const auto divider = static_cast<std::int64_t>(setup->divider);
    if (m_scopeAxes.size() == 1) {
        const std::vector<std::size_t> pick = setup->channels;
        m_scopeSim->setScopeTap([this, divider, pick](std::int64_t tick, std::span<const double> row) {
            if (tick % divider != 0)
                return;
            for (std::size_t k = 0; k < pick.size(); ++k)
                m_scopeRow[k] = row[pick[k]];
            m_scope.push(static_cast<std::uint64_t>(tick / divider), m_scopeRow);
        });
        return Status::success();
    }
    // Several axes: one machine time first, then one velocity-period count (the offsets stay fixed while they run
    // together).
    syncScopeAxes();
    for (auto& a : m_scopeAxes)
        a.tickOffset = a.sim->velocityTicks() - m_scopeSim->velocityTicks();
    const std::size_t axes = m_scopeAxes.size(), width = setup->channels.size();
    // At most one ring of rows waits for an axis behind; older ones are dropped and show as a gap in the sample
    // numbers (they cannot be, while every poll keeps the axes together).
    const std::size_t maxPending = kScopeRingValues / width;
    for (const auto& a : m_scopeAxes) {
        a.sim->setScopeTap([this, divider, axes, width, maxPending, picks = a.picks,
                            offset = a.tickOffset](std::int64_t axisTick, std::span<const double> row) {
            const std::int64_t tick = axisTick - offset;
            if (tick < 0 || tick % divider != 0)
                return;
            auto& [values, written] = m_scopePending[tick];
            if (values.empty())
                values.assign(width, 0.0);
            for (const auto& [signal, col] : picks)
                values[col] = row[signal];
            if (++written < axes) {
                if (m_scopePending.size() > maxPending)
                    m_scopePending.erase(m_scopePending.begin());
                return;
            }
            // Rows complete in the order of the axis furthest behind, which writes its periods in order.
            m_scope.push(static_cast<std::uint64_t>(tick / divider), values);
            m_scopePending.erase(tick);
        });
    }
    return Status::success();
}

bool SimulatedDrive::scopeSamplesAxis(const std::string& axis) const
{
    const auto it = m_axes.find(axis);
    if (it == m_axes.end() || !m_scope.armed())
        return false;
    if (it->second.get() == m_scopeSim)
        return true;
    return std::any_of(m_scopeAxes.begin(), m_scopeAxes.end(),
                       [&](const ScopeAxis& a) { return a.sim == it->second.get(); });
}

void SimulatedDrive::syncScopeAxes()
{
    if (m_scopeAxes.size() < 2)
        return;
    std::int64_t ahead = 0;
    for (const auto& a : m_scopeAxes)
        ahead = std::max(ahead, a.sim->currentTicks());
    for (const auto& a : m_scopeAxes)
        if (a.sim->currentTicks() < ahead)
            a.sim->runTicks(ahead - a.sim->currentTicks());
}

void SimulatedDrive::runScopeAxes(std::int64_t ticks)
{
    if (!m_scopeSim || ticks <= 0)
        return;
    if (m_scopeAxes.size() < 2) {
        m_scopeSim->runTicks(ticks);
        return;
    }
    syncScopeAxes();
    for (const auto& a : m_scopeAxes)
        a.sim->runTicks(ticks);
}

Result<ScopeStatus> SimulatedDrive::pollScope()
{
    if (auto st = checkLink(); !st)
        return st.error();
    if (m_scopeSim && m_scope.armed()) {
        // A running test on one of the scope's axes advances it (pollTest), and the others follow it here;
        // otherwise the axes run on here, doing what they did last (holding their position or velocity).
        const bool testMovesIt =
            std::any_of(m_scopeAxes.begin(), m_scopeAxes.end(), [&](const ScopeAxis& a) { return testMoves(a.sim); });
        if (testMovesIt)
            syncScopeAxes();
        else
            runScopeAxes(std::llround(m_slice / m_scopeSim->currentPeriod()));
    }
    return m_scope.status();
}

Result<ScopeRows> SimulatedDrive::readScopeRows(std::uint64_t from, std::size_t maxRows)
{
    if (auto st = checkLink(); !st)
        return st.error();
    if (m_scope.setup().mode != ScopeMode::Roll || !m_scopeSim)
        return makeError(ErrorCode::NotFound, "the scope is not in roll mode");
    return m_scope.rows(from, maxRows);
}

Result<ScopeCapture> SimulatedDrive::readScopeCapture()
{
    if (auto st = checkLink(); !st)
        return st.error();
    auto c = m_scope.capture();
    if (!c)
        return c.error();
    ScopeCapture out = std::move(c).value();
    out.channels = m_scopeChannels;
    return out;
}

Status SimulatedDrive::stopScope()
{
    if (auto st = checkLink(); !st)
        return st;
    m_scope.stop();
    disarmScopeTaps();
    return Status::success();
}

} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
// The embedded simulated drive's scope (docs/scope.md): a tap on one axis's velocity loop, sampled every
// divider-th velocity period, into a ScopeRecorder. The sample number is the velocity period's number
// divided by the divider, so sample n is at machine time n · divider · T_v.
#include "core/device/SimulatedDrive.h"

namespace axistune::device {

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
    c.fastestRateHz = 1.0 / (*s)->velocityPeriod();
    c.maxChannels = kScopeMaxChannels;
    c.maxDivider = kScopeMaxDivider;
    c.maxValues = kScopeMaxValues;
    c.ringValues = kScopeRingValues;
    return c;
}

Status SimulatedDrive::armScope(const ScopeRequest& request)
{
    auto caps = scopeCapabilities(request.axis);
    if (!caps)
        return caps.error();
    auto setup = checkScopeRequest(request, *caps);
    if (!setup)
        return setup.error();
    if (m_scopeSim)
        m_scopeSim->setScopeTap({});
    m_scopeSim = simulator(request.axis);
    m_scopeChannels.clear();
    for (const auto i : setup->channels)
        m_scopeChannels.push_back(caps->channels[i]);
    m_scopeRow.assign(setup->channels.size(), 0.0);
    m_scope.arm(*setup, kScopeRingValues / setup->channels.size());
    const auto divider = static_cast<std::int64_t>(setup->divider);
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

Result<ScopeStatus> SimulatedDrive::pollScope()
{
    if (auto st = checkLink(); !st)
        return st.error();
    if (m_scopeSim && m_scope.armed()) {
        // A running test on the scope's axis advances it (pollTest); otherwise the axis runs on here, doing
        // what it did last (holding its position or velocity).
        const bool testMovesIt = m_status.state == TestState::Running && (m_circle || m_active == m_scopeSim);
        if (!testMovesIt)
            m_scopeSim->run(m_slice);
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
    if (m_scopeSim)
        m_scopeSim->setScopeTap({});
    return Status::success();
}

} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
// The scope of the hal: backend (HalScope.h): LinuxCNC's sampler on the pid's pins or any float pin, also while a
// test runs.
#include "core/device/hal/HalDrive.h"

namespace axistune::device::hal {

Result<ScopeCapabilities> HalDrive::scopeCapabilities(const std::string& axis)
{
    auto a = discoverAxis(m_options, axis);
    if (!a)
        return a.error();
    auto text = runHalcmd(m_options, {"-s", "show", "pin"});
    if (!text)
        return text.error();
    auto ps = parsePins(*text);
    if (!ps)
        return ps.error();
    return halScopeCapabilities(*a, *ps);
}

bool HalDrive::testRunning()
{
    std::lock_guard lock(m_mutex);
    return m_status.state == TestState::Running;
}

void HalDrive::finishDeferredScopeStop()
{
    if (m_scopeStopDeferred && m_scope && !testRunning()) {
        (void)m_scope->stop();
        m_scopeStopDeferred = false;
    }
}

Status HalDrive::armScope(const ScopeRequest& request)
{
    // A test inserts and removes its injection by changing HAL's nets, and the scope links its pins to nets: the two
    // must not change them at once (a scope armed during a test would also link to the test's own nets, which end
    // with it). A scope armed before the test records it.
    if (testRunning())
        return makeError(ErrorCode::Busy, "the scope cannot be armed while a test runs on LinuxCNC (the test rewires "
                                          "HAL's nets): arm it before the test, and it records the test");
    finishDeferredScopeStop();
    auto a = discoverAxis(m_options, request.axis);
    if (!a)
        return a.error();
    const auto caps = scopeCapabilities(request.axis);
    if (!caps)
        return caps.error();
    auto setup = checkScopeRequest(request, *caps);
    if (!setup)
        return setup.error();
    m_scope.reset(); // re-arming replaces the running scope
    auto scope = HalScope::start(m_options, *a, *caps, *setup);
    if (!scope)
        return scope.error();
    m_scope = std::move(scope).value();
    m_scopeChannels.clear();
    for (const auto i : setup->channels)
        m_scopeChannels.push_back(caps->channels[i]);
    m_scopeRateHz = setup->rateHz;
    return Status::success();
}

Result<ScopeStatus> HalDrive::pollScope()
{
    if (!m_scope)
        return ScopeStatus{};
    if (auto f = m_scope->failure(); !f.empty())
        return makeError(ErrorCode::Device, "connection hal: lost: " + f);
    return m_scope->status();
}

Result<ScopeRows> HalDrive::readScopeRows(std::uint64_t from, std::size_t maxRows)
{
    if (!m_scope)
        return makeError(ErrorCode::NotFound, "the scope is not armed");
    return m_scope->rows(from, maxRows);
}

Result<ScopeCapture> HalDrive::readScopeCapture()
{
    if (!m_scope)
        return makeError(ErrorCode::NotFound, "no scope capture: the scope was never armed");
    auto c = m_scope->capture();
    if (!c)
        return c.error();
    ScopeCapture out = std::move(c).value();
    out.channels = m_scopeChannels;
    return out;
}

Status HalDrive::stopScope()
{
    if (!m_scope)
        return Status::success();
    if (testRunning()) {
        // It stops reading now; its pins and function leave HAL when the test has ended (pollTest).
        m_scope->stopReading();
        m_scopeStopDeferred = true;
        return Status::success();
    }
    // The scope's pins and function are removed at once (the sampler too unless a test holds it); a complete
    // capture stays readable.
    return m_scope->stop();
}

} // namespace axistune::device::hal

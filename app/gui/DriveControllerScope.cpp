// SPDX-License-Identifier: GPL-3.0-or-later
// The scope requests of the drive link (docs/scope.md "The GUI scope"): served from the worker's side queue,
// so they also run between the polls of a running test.
#include "app/gui/DriveController.h"
#include "app/gui/WidgetUtil.h"

#include <QCoreApplication>

namespace axistune {
namespace gui {

namespace {
DriveReply scopeReply(int id)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::Scope;
    return r;
}
} // namespace

void DriveWorker::enqueueSide(std::function<void()> job)
{
    std::lock_guard lock(m_sideMutex);
    m_side.push_back(std::move(job));
}

void DriveWorker::drainSide()
{
    if (m_draining)
        return;
    m_draining = true;
    for (;;) {
        std::function<void()> job;
        {
            std::lock_guard lock(m_sideMutex);
            if (m_side.empty())
                break;
            job = std::move(m_side.front());
            m_side.pop_front();
        }
        job();
    }
    m_draining = false;
}

DriveReply DriveWorker::doScopeCapabilities(int id, const QString& axis)
{
    DriveReply r = scopeReply(id);
    r.axis = axis;
    if (!m_drive)
        return fail(r, notConnected());
    auto c = m_drive->scopeCapabilities(axis.toStdString());
    if (!c)
        return fail(r, c.error());
    r.scopeCaps = std::make_shared<const device::ScopeCapabilities>(std::move(c).value());
    r.ok = true;
    return r;
}

DriveReply DriveWorker::doArmScope(int id, const device::ScopeRequest& request)
{
    DriveReply r = scopeReply(id);
    r.axis = qs(request.axis);
    if (!m_drive)
        return fail(r, notConnected());
    if (auto st = m_drive->armScope(request); !st)
        return fail(r, st.error());
    auto s = m_drive->pollScope();
    if (!s)
        return fail(r, s.error());
    r.scopeStatus = *s;
    r.ok = true;
    return r;
}

DriveReply DriveWorker::doPollScope(int id, std::optional<std::uint64_t> rollFrom, std::uint64_t knownCaptures,
                                    std::size_t maxRows)
{
    DriveReply r = scopeReply(id);
    if (!m_drive)
        return fail(r, notConnected());
    auto s = m_drive->pollScope();
    if (!s)
        return fail(r, s.error());
    r.scopeStatus = *s;
    if (rollFrom) {
        // Everything the drive has from rollFrom on, in reads of the drive's own size, up to maxRows.
        auto all = std::make_shared<device::ScopeRows>();
        std::uint64_t from = *rollFrom;
        bool first = true;
        while (all->rows < maxRows) {
            auto got = m_drive->readScopeRows(from, maxRows - all->rows);
            if (!got)
                return fail(r, got.error());
            if (got->rows == 0)
                break;
            if (first)
                all->firstSample = got->firstSample;
            else if (got->firstSample != all->firstSample + all->rows)
                break; // a gap inside this read: the caller asks again from where the rows stop
            first = false;
            all->values.insert(all->values.end(), got->values.begin(), got->values.end());
            all->rows += got->rows;
            from = got->firstSample + got->rows;
            if (from >= s->nextSample)
                break;
        }
        if (first)
            all->firstSample = *rollFrom;
        r.scopeRows = std::move(all);
    } else if (s->captures > knownCaptures) {
        auto c = m_drive->readScopeCapture();
        if (!c)
            return fail(r, c.error());
        r.scopeCapture = std::make_shared<const device::ScopeCapture>(std::move(c).value());
    }
    r.ok = true;
    return r;
}

DriveReply DriveWorker::doStopScope(int id)
{
    DriveReply r = scopeReply(id);
    if (!m_drive)
        return fail(r, notConnected());
    if (auto st = m_drive->stopScope(); !st)
        return fail(r, st.error());
    r.ok = true;
    return r;
}

DriveRequest* DriveController::scopeCapabilities(const QString& axis)
{
    return post(
        DriveReply::Kind::Scope, [axis](DriveWorker& w, int id) { return w.doScopeCapabilities(id, axis); }, true);
}

DriveRequest* DriveController::armScope(const device::ScopeRequest& request)
{
    return post(
        DriveReply::Kind::Scope, [request](DriveWorker& w, int id) { return w.doArmScope(id, request); }, true);
}

DriveRequest* DriveController::pollScope(std::optional<std::uint64_t> rollFrom, std::uint64_t knownCaptures,
                                         std::size_t maxRows)
{
    return post(
        DriveReply::Kind::Scope,
        [rollFrom, knownCaptures, maxRows](DriveWorker& w, int id) {
            return w.doPollScope(id, rollFrom, knownCaptures, maxRows);
        },
        true);
}

DriveRequest* DriveController::stopScope()
{
    return post(
        DriveReply::Kind::Scope, [](DriveWorker& w, int id) { return w.doStopScope(id); }, true);
}

} // namespace gui
} // namespace axistune

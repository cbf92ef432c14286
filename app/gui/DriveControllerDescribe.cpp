// SPDX-License-Identifier: GPL-3.0-or-later
// The drive describes itself through the controller (issue 16 item 2, docs/drive-seam.md): the
// capabilities and limits of an axis, and the plan of a test request, asked on the worker thread.
#include "app/gui/DriveController.h"

#include <QCoreApplication>

namespace axistune {
namespace gui {

DriveReply DriveWorker::doDescribe(int id, const QString& axis)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::Describe;
    r.axis = axis;
    if (!m_drive)
        return fail(r,
                    {ErrorCode::Device, QCoreApplication::translate("DriveController", "Not connected").toStdString()});
    auto caps = m_drive->capabilities(axis.toStdString());
    if (!caps)
        return fail(r, caps.error());
    auto limits = m_drive->limits(axis.toStdString());
    if (!limits)
        return fail(r, limits.error());
    r.capabilities = std::move(caps).value();
    r.limits = *limits;
    r.ok = true;
    return r;
}

DriveReply DriveWorker::doPlan(int id, const device::TestRequest& request)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::Plan;
    r.axis = QString::fromStdString(request.axis);
    if (!m_drive)
        return fail(r,
                    {ErrorCode::Device, QCoreApplication::translate("DriveController", "Not connected").toStdString()});
    auto plan = m_drive->planTest(request);
    if (!plan)
        return fail(r, plan.error());
    r.plan = *plan;
    r.ok = true;
    return r;
}

int DriveController::describeAxis(const QString& axis)
{
    const int id = m_nextId;
    post([id, axis](DriveWorker& w) { return w.doDescribe(id, axis); });
    return id;
}

int DriveController::planTest(const device::TestRequest& request)
{
    const int id = m_nextId;
    post([id, request](DriveWorker& w) { return w.doPlan(id, request); });
    return id;
}

} // namespace gui
} // namespace axistune

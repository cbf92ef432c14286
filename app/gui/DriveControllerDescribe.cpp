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
        return fail(r, notConnected());
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
        return fail(r, notConnected());
    auto plan = m_drive->planTest(request);
    if (!plan)
        return fail(r, plan.error());
    r.plan = *plan;
    r.ok = true;
    return r;
}

DriveRequest* DriveController::describeAxis(const QString& axis)
{
    return post(DriveReply::Kind::Describe, [axis](DriveWorker& w, int id) { return w.doDescribe(id, axis); });
}

DriveRequest* DriveController::planTest(const device::TestRequest& request)
{
    return post(DriveReply::Kind::Plan, [request](DriveWorker& w, int id) { return w.doPlan(id, request); });
}

} // namespace gui
} // namespace axistune

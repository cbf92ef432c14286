// SPDX-License-Identifier: GPL-3.0-or-later
// The circle test of axistune-simdrive (docs/modbus.md "Circle test"): the circle block (second plane
// axis, direction, radius, feed, centre, arcs), the server-side limits before the start (travel window
// and speed limit of SafetyLimits, through device::checkCircleRequest) and the watch over the second
// axis while the circle runs (the first is the test's unit and checked by checkSafety).
#include "core/device/CircleDriveTest.h"
#include "core/model/Units.h"
#include "core/device/SimDriveServer.h"

#include <cmath>
#include <cstdio>
#include <modbus/modbus.h>

namespace axistune::device {
namespace {

std::string num(double v) { return model::formatNumber(v, 4); }

} // namespace

int SimDriveServer::startCircle(int ui, TestRequest& req)
{
    const Axis& first = m_axes[static_cast<std::size_t>(ui)];
    // Decoded from circle.second_axis: one of the drive's axes.
    const int secondIndex = axisIndex(req.circle().secondAxis);
    if (secondIndex < 0 || secondIndex == ui)
        return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, "circle: the second plane axis must be another axis of this "
                                                           "drive, not axis " + first.name + " (index " +
                                                               std::to_string(ui) + ")");
    const Axis& second = m_axes[static_cast<std::size_t>(secondIndex)];
    CircleLimits lim;
    lim.travelWindowM = m_opt.safety.travelLimit;
    lim.maxMotorSpeedRadS = m_opt.safety.speedLimitRadS;
    if (auto st = checkCircleRequest(req, *first.sim, *second.sim, lim); !st)
        return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, st.error().detail);
    return 0;
}

int SimDriveServer::axisIndex(const std::string& name) const
{
    for (std::size_t i = 0; i < m_axes.size(); ++i) {
        if (m_axes[i].name == name)
            return static_cast<int>(i);
    }
    return -1;
}

void SimDriveServer::checkCircleSecondAxis()
{
    if (m_state != "running" || m_testSecondUnit < 0)
        return;
    const Axis& ax = m_axes[static_cast<std::size_t>(m_testSecondUnit)];
    const SafetyLimits& lim = m_opt.safety;
    const sim::AxisSimulator& s = *ax.sim;
    const bool fullClosed = s.parameter("position.feedback") > 0.5;
    const double followingError = s.positionCommand() - (fullClosed ? s.tablePosition() : s.motorPosition());
    if (std::abs(s.tablePosition()) > lim.travelLimit)
        trip("travel_limit", "position of axis " + ax.name + " " + num(s.tablePosition()) +
                                 " m left the travel window ±" + num(lim.travelLimit) + " m");
    else if (std::abs(s.motorVelocity()) > lim.speedLimitRadS)
        trip("speed_limit", "motor speed of axis " + ax.name + " " + num(s.motorVelocity()) +
                                " rad/s above the limit " + num(lim.speedLimitRadS) + " rad/s");
    else if (std::abs(followingError) > lim.followingErrorLimit)
        trip("following_error", "following error of axis " + ax.name + " " + num(followingError) +
                                    " m above the limit " + num(lim.followingErrorLimit) + " m");
}

} // namespace axistune::device

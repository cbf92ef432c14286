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
    const TestConfig& c = m_config[static_cast<std::size_t>(ui)];
    const Axis& first = m_axes[static_cast<std::size_t>(ui)];
    if (c.circleSecondAxis >= m_axes.size() || static_cast<int>(c.circleSecondAxis) == ui)
        return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE,
                      "circle: second axis index " + std::to_string(c.circleSecondAxis) +
                          " must name another axis of this drive (axis " + first.name + " is index " +
                          std::to_string(ui) + ")");
    const Axis& second = m_axes[c.circleSecondAxis];
    req.type = TestType::Circle;
    req.secondAxis = second.name;
    req.direction = m_map.name("circle_direction", c.circleDirection) == "cw" ? model::CircleDirection::Cw
                                                                              : model::CircleDirection::Ccw;
    req.radiusM = c.circleRadius;
    req.feedMPerS = c.circleFeed;
    req.centerXM = c.circleCenterX;
    req.centerYM = c.circleCenterY;
    req.dataStartDeg = c.circleDataStartDeg;
    req.leadArcDeg = c.circleLeadArcDeg;
    CircleLimits lim;
    lim.travelWindowM = m_opt.safety.travelLimit;
    lim.maxMotorSpeedRadS = m_opt.safety.speedLimitRadS;
    if (auto st = checkCircleRequest(req, *first.sim, *second.sim, lim); !st)
        return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, st.error().detail);
    return 0;
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

int SimDriveServer::writeCircleField(const RegisterField& f, int ui, const std::uint16_t* w)
{
    TestConfig& c = m_config[static_cast<std::size_t>(ui)];
    const std::string& n = f.name;
    if (m_state == "running")
        return refuse(MODBUS_EXCEPTION_SLAVE_OR_SERVER_BUSY, "test configuration cannot change while a test runs");
    if (n == "circle.second_axis") {
        c.circleSecondAxis = w[0];
        return 0;
    }
    if (n == "circle.direction") {
        if (m_map.name("circle_direction", w[0]).empty())
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, "unknown circle direction " + std::to_string(w[0]));
        c.circleDirection = w[0];
        return 0;
    }
    const double v = decodeF64(w, m_map.wordOrder);
    if (!std::isfinite(v))
        return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, n + " must be finite");
    double* target = n == "circle.radius"           ? &c.circleRadius
                     : n == "circle.feed"           ? &c.circleFeed
                     : n == "circle.center_x"       ? &c.circleCenterX
                     : n == "circle.center_y"       ? &c.circleCenterY
                     : n == "circle.data_start_deg" ? &c.circleDataStartDeg
                     : n == "circle.lead_arc_deg"   ? &c.circleLeadArcDeg
                                                    : nullptr;
    if (!target)
        return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS, "field " + n + " is not used by this drive");
    *target = v;
    return 0;
}

bool SimDriveServer::encodeCircleField(const RegisterField& f, int ui, std::uint16_t* buf)
{
    const TestConfig& c = m_config[static_cast<std::size_t>(ui)];
    const std::string& n = f.name;
    if (n == "circle.second_axis" || n == "circle.direction") {
        buf[0] = n == "circle.second_axis" ? c.circleSecondAxis : c.circleDirection;
        return true;
    }
    const std::pair<const char*, double> f64s[] = {
        {"circle.radius", c.circleRadius},       {"circle.feed", c.circleFeed},
        {"circle.center_x", c.circleCenterX},    {"circle.center_y", c.circleCenterY},
        {"circle.data_start_deg", c.circleDataStartDeg}, {"circle.lead_arc_deg", c.circleLeadArcDeg}};
    for (const auto& [key, v] : f64s) {
        if (n == key) {
            encodeF64(v, m_map.wordOrder, buf);
            return true;
        }
    }
    return false;
}

} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
// Circular interpolation of two feed axes for the simulated ball-bar test (spec/lost-motion-and-two-
// inertia.md §1.7–1.9: the two axes of a plane follow x = c_x + r cos φ(t), y = c_y + r sin φ(t), each
// under its own servo loops): the path, the lock-step run on two axis simulators and its trace.
// Conventions: docs/ballbar.md "Simulated circle tests" and "Circle tests through the drive".
#include "core/sim/CircleRun.h"

#include "core/model/CircleDirectionName.h"
#include "core/model/Constants.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/sim/AxisSimulator.h"

#include <cmath>
#include <numbers>

namespace axistune::sim {
namespace {

using model::kPi;
using model::kRadPerDeg;
constexpr double kTailS = 0.2;  ///< recorded after the end of the path (the axes settle)

std::string fmtShort(double v)
{
    return model::formatNumber(v, 10);
}

Status checkOptions(const CircleTestOptions& o)
{
    auto bad = [](const std::string& m) { return Status(makeError(ErrorCode::BadInput, "circle test: " + m)); };
    if (!(o.radiusM > 0.0) || !std::isfinite(o.radiusM))
        return bad("radius must be positive (is " + fmtShort(o.radiusM) + " m)");
    if (!(o.feedMPerS > 0.0) || !std::isfinite(o.feedMPerS))
        return bad("feed must be positive (is " + fmtShort(o.feedMPerS) + " m/s)");
    if (!(o.leadArcDeg >= 10.0) || o.leadArcDeg > 360.0)
        return bad("lead arc must be 10..360 deg (is " + fmtShort(o.leadArcDeg) + ")");
    if (!(o.dataArcDeg >= 30.0) || o.dataArcDeg > 360.0)
        return bad("data arc must be 30..360 deg (is " + fmtShort(o.dataArcDeg) + ")");
    if (!std::isfinite(o.centerXM) || !std::isfinite(o.centerYM) || !std::isfinite(o.dataStartDeg))
        return bad("centre and start angle must be finite");
    if (!(o.dwellS >= 0.0) || !std::isfinite(o.dwellS) || !std::isfinite(o.squarenessPerM) ||
        !std::isfinite(o.scaleX) || !std::isfinite(o.scaleY))
        return bad("dwell must be >= 0 and the geometric errors finite");
    if (!(o.torqueExcludeDeg > 0.0 && o.torqueWindowDeg > o.torqueExcludeDeg && o.torqueWindowDeg < 90.0))
        return bad("torque plateau window must satisfy 0 < exclude < window < 90 deg");
    if (o.axisX.empty() || o.axisY.empty() || o.axisX == o.axisY)
        return bad("the plane needs two different axes (are '" + o.axisX + "' and '" + o.axisY + "')");
    return Status::success();
}

} // namespace

Result<CirclePath> CirclePath::plan(const CircleTestOptions& o)
{
    if (auto st = checkOptions(o); !st)
        return st.error();
    CirclePath p;
    p.m_o = o;
    p.m_sigma = o.direction == model::CircleDirection::Ccw ? 1.0 : -1.0;
    p.m_dwell = o.dwellS;
    p.m_omega = o.feedMPerS / o.radiusM;
    p.m_sAcc = 0.5 * o.leadArcDeg * kRadPerDeg;
    p.m_alpha = p.m_omega * p.m_omega / (2.0 * p.m_sAcc);
    p.m_tAcc = p.m_omega / p.m_alpha;
    p.m_sFrom = o.leadArcDeg * kRadPerDeg;
    p.m_sTo = p.m_sFrom + o.dataArcDeg * kRadPerDeg;
    p.m_tConst = (p.m_sTo + p.m_sFrom - 2.0 * p.m_sAcc) / p.m_omega;
    p.m_phi0 = o.dataStartDeg * kRadPerDeg - p.m_sigma * p.m_sFrom;
    return p;
}

double CirclePath::duration() const { return m_dwell + 2.0 * m_tAcc + m_tConst; }

MotionState CirclePath::arc(double t) const
{
    double u = t - m_dwell;
    if (u <= 0.0)
        return {0.0, 0.0, 0.0};
    if (u < m_tAcc)
        return {0.5 * m_alpha * u * u, m_alpha * u, m_alpha};
    if ((u -= m_tAcc) < m_tConst)
        return {m_sAcc + m_omega * u, m_omega, 0.0};
    if ((u -= m_tConst) < m_tAcc)
        return {m_sAcc + m_omega * m_tConst + m_omega * u - 0.5 * m_alpha * u * u, m_omega - m_alpha * u, -m_alpha};
    return {2.0 * m_sAcc + m_omega * m_tConst, 0.0, 0.0};
}

double CirclePath::arcAt(double t) const { return arc(t).position; }

MotionState CirclePath::command(double t, bool secondAxis) const
{
    const MotionState a = arc(t);
    const double r = m_o.radiusM;
    const double phi = m_phi0 + m_sigma * a.position, w = m_sigma * a.velocity, al = m_sigma * a.acceleration;
    const double c = std::cos(phi), s = std::sin(phi);
    if (secondAxis)
        return {m_o.centerYM + r * s, r * c * w, -r * s * w * w + r * c * al};
    return {m_o.centerXM + r * c, -r * s * w, -r * c * w * w - r * s * al};
}

Status checkCirclePlane(const AxisSimulator& x, const AxisSimulator& y)
{
    if (&x == &y || x.name() == y.name())
        return makeError(ErrorCode::BadInput, "circle test: the plane needs two different axes (both are " + x.name() + ")");
    for (const AxisSimulator* a : {&x, &y}) {
        if (a->kind() != AxisKind::Linear)
            return makeError(ErrorCode::BadInput, "circle test: axis " + a->name() + " is not linear");
    }
    if (std::abs(x.parameter("position.period") - y.parameter("position.period")) > 1e-12 ||
        std::abs(x.currentPeriod() - y.currentPeriod()) > 1e-15)
        return makeError(ErrorCode::BadInput, "circle test: axes " + x.name() + " and " + y.name() +
                                                  " must share the position and current periods");
    return Status::success();
}

std::size_t CircleRun::sampleCount(const CirclePath& path, double positionPeriodS)
{
    return static_cast<std::size_t>(std::ceil((path.duration() + kTailS) / positionPeriodS));
}

Result<CircleRun> CircleRun::begin(AxisSimulator& x, AxisSimulator& y, const CirclePath& path)
{
    if (auto st = checkCirclePlane(x, y); !st)
        return st.error();
    CircleRun run(x, y, path);
    run.m_tp = x.parameter("position.period");
    run.m_ticksPerSample = std::llround(run.m_tp / x.currentPeriod());
    run.m_t0x = x.time();
    run.m_total = sampleCount(path, run.m_tp);
    for (auto* v : {&run.m_t, &run.m_s, &run.m_cx, &run.m_px, &run.m_qx, &run.m_tx, &run.m_cy, &run.m_py, &run.m_qy,
                    &run.m_ty})
        v->reserve(run.m_total);
    const CirclePath p = path;
    x.setControlMode(ControlMode::Position);
    y.setControlMode(ControlMode::Position);
    x.setPositionCommand([p](double t) { return p.command(t, false); });
    y.setPositionCommand([p](double t) { return p.command(t, true); });
    return run;
}

void CircleRun::step(std::size_t samples)
{
    for (std::size_t k = 0; k < samples && !done(); ++k) {
        m_x->runTicks(m_ticksPerSample);
        m_y->runTicks(m_ticksPerSample);
        const double t = m_x->time() - m_t0x;
        m_t.push_back(t);
        m_s.push_back(m_path.arcAt(t));
        m_cx.push_back(m_x->positionCommand());
        m_px.push_back(m_x->tablePosition());
        m_qx.push_back(m_x->torqueCommand());
        m_tx.push_back(m_x->torque());
        m_cy.push_back(m_y->positionCommand());
        m_py.push_back(m_y->tablePosition());
        m_qy.push_back(m_y->torqueCommand());
        m_ty.push_back(m_y->torque());
    }
}

std::string circleChannel(const std::string& axis, const char* what) { return axis + "." + what; }

model::Capture CircleRun::trace() const
{
    const CircleTestOptions& o = m_path.options();
    model::Capture cap;
    cap.metadata = {{"axis_x", o.axisX},
                    {"axis_y", o.axisY},
                    {"feed_m_per_s", o.feedMPerS},
                    {"center_x_m", o.centerXM},
                    {"center_y_m", o.centerYM},
                    {"data_start_deg", o.dataStartDeg},
                    {"lead_arc_deg", o.leadArcDeg},
                    {"dwell_s", o.dwellS}};
    cap.metadata.set(model::meta::kTest, "circle");
    cap.metadata.set(model::meta::kRadiusM, o.radiusM);
    cap.metadata.set(model::meta::kDirection, model::circleDirectionName(o.direction));
    cap.metadata.set(model::meta::kFsHz, 1.0 / m_tp);
    cap.channels = {{"t_s", m_t},
                    {"arc_rad", m_s},
                    {circleChannel(o.axisX, "position_cmd_m"), m_cx},
                    {circleChannel(o.axisX, "table_pos_m"), m_px},
                    {circleChannel(o.axisX, "torque_cmd_Nm"), m_qx},
                    {circleChannel(o.axisX, "torque_Nm"), m_tx},
                    {circleChannel(o.axisY, "position_cmd_m"), m_cy},
                    {circleChannel(o.axisY, "table_pos_m"), m_py},
                    {circleChannel(o.axisY, "torque_cmd_Nm"), m_qy},
                    {circleChannel(o.axisY, "torque_Nm"), m_ty}};
    return cap;
}

Result<CircleTestOptions> circleOptionsFromTrace(const model::Capture& trace)
{
    auto bad = [](const std::string& m) { return makeError(ErrorCode::BadInput, "circle trace: " + m); };
    const auto& md = trace.metadata;
    auto text = [&](std::string_view key) -> Result<std::string> {
        auto v = md.text(key);
        if (!v || v->empty())
            return bad("metadata '" + std::string(key) + "' is missing");
        return *v;
    };
    auto number = [&](const char* key) -> Result<double> {
        auto v = md.number(key);
        return v ? v : bad(v.error().detail);
    };
    if (auto t = text(model::meta::kTest.name); !t || *t != "circle")
        return bad("not the trace of a circle test (metadata test=circle missing)");
    CircleTestOptions o;
    auto ax = text("axis_x"), ay = text("axis_y"), dir = text(model::meta::kDirection.name);
    for (const auto* r : {&ax, &ay, &dir}) {
        if (!*r)
            return r->error();
    }
    o.axisX = *ax;
    o.axisY = *ay;
    const auto direction = model::circleDirectionFromName(*dir);
    if (!direction)
        return bad("metadata 'direction' must be ccw or cw (is '" + *dir + "')");
    o.direction = *direction;
    const std::pair<const char*, double*> nums[] = {{model::meta::kRadiusM.name.data(), &o.radiusM},
                                                    {"feed_m_per_s", &o.feedMPerS},
                                                    {"center_x_m", &o.centerXM},
                                                    {"center_y_m", &o.centerYM},
                                                    {"data_start_deg", &o.dataStartDeg},
                                                    {"lead_arc_deg", &o.leadArcDeg},
                                                    {"dwell_s", &o.dwellS}};
    for (const auto& [key, target] : nums) {
        auto v = number(key);
        if (!v)
            return v.error();
        *target = *v;
    }
    return o;
}

} // namespace axistune::sim

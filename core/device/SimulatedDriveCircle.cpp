// SPDX-License-Identifier: GPL-3.0-or-later
// The circle test of the embedded simulated drive (CircleDriveTest.h): request checks, and the run on
// the drive's own two axis simulators (applied parameters act, and the axes stay where the circle
// left them): positioning to the start point, then sim::CircleRun, in slices from pollTest().
#include "core/device/CircleDriveTest.h"
#include "core/device/SimulatedDrive.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Units.h"
#include "core/sim/CircleRun.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace axistune::device {
namespace {

std::string num(double v)
{
    return model::formatNumber(v, 4);
}

} // namespace

sim::CircleTestOptions circleOptionsOf(const TestRequest& request)
{
    const CircleTest& r = request.circle();
    sim::CircleTestOptions o;
    o.axisX = request.axis;
    o.axisY = r.secondAxis;
    o.radiusM = r.radiusM;
    o.feedMPerS = r.feedMPerS;
    o.direction = r.direction;
    o.centerXM = r.centerXM;
    o.centerYM = r.centerYM;
    o.dataStartDeg = r.dataStartDeg;
    o.leadArcDeg = r.leadArcDeg;
    o.dwellS = r.dwellS;
    return o;
}

TestRequest circleRequestOf(const sim::CircleTestOptions& o)
{
    TestRequest request;
    request.axis = o.axisX;
    auto& r = request.test.emplace<CircleTest>();
    r.secondAxis = o.axisY;
    r.radiusM = o.radiusM;
    r.feedMPerS = o.feedMPerS;
    r.direction = o.direction;
    r.centerXM = o.centerXM;
    r.centerYM = o.centerYM;
    r.dataStartDeg = o.dataStartDeg;
    r.leadArcDeg = o.leadArcDeg;
    r.dwellS = o.dwellS;
    return request;
}

double circlePositioningSpeed(const TestRequest& request)
{
    const CircleTest& r = request.circle();
    return r.positioningMPerS > 0.0 ? r.positioningMPerS : kCirclePositioningSpeedMPerS;
}
double circlePositioningAccel(const TestRequest& request)
{
    const CircleTest& r = request.circle();
    return r.positioningMPerS2 > 0.0 ? r.positioningMPerS2 : kCirclePositioningAccelMPerS2;
}

Status checkCircleRequest(const TestRequest& request, const sim::AxisSimulator& x, const sim::AxisSimulator& y,
                          const CircleLimits& lim)
{
    auto out = [](const std::string& m) { return Status(makeError(ErrorCode::OutOfRange, "circle test: " + m)); };
    if (auto st = sim::checkCirclePlane(x, y); !st)
        return st;
    const CircleTest& r = request.circle();
    auto path = sim::CirclePath::plan(circleOptionsOf(request));
    if (!path)
        return path.error();
    if (!(r.dwellS > 0.0) || !std::isfinite(r.dwellS))
        return out("the dwell before the circle must be positive (is " + num(r.dwellS) + " s)");
    if (!std::isfinite(r.positioningMPerS) || r.positioningMPerS < 0.0 || !std::isfinite(r.positioningMPerS2) ||
        r.positioningMPerS2 < 0.0)
        return out("positioning velocity and acceleration must be finite and not negative (0: defaults)");
    const double radius = r.radiusM, vPos = circlePositioningSpeed(request), aPos = circlePositioningAccel(request);
    double positioningS = 0.0;
    for (const auto& [sim, centre, second] : {std::tuple{&x, r.centerXM, false}, std::tuple{&y, r.centerYM, true}}) {
        const std::string& n = sim->name();
        const double far = std::abs(centre) + radius;
        if (far > lim.travelWindowM)
            return out("the circle reaches " + num(far) + " m on axis " + n + " (centre " + num(centre) +
                       " m, radius " + num(radius) + " m), outside the travel window ±" + num(lim.travelWindowM) +
                       " m");
        const double now = sim->positionCommand();
        if (std::abs(now) > lim.travelWindowM)
            return out("axis " + n + " stands at " + num(now) + " m, outside the travel window ±" +
                       num(lim.travelWindowM) + " m");
        const double lead = sim->parameter("plant.screw_lead");
        for (const auto& [what, v] : {std::pair{"feed", r.feedMPerS}, std::pair{"positioning speed", vPos}}) {
            const double motor = v / lead;
            if (motor > lim.maxMotorSpeedRadS)
                return out(std::string(what) + " " + num(v) + " m/s means " + num(motor) +
                           " rad/s at the motor of axis " + n + ", above the speed limit " +
                           num(lim.maxMotorSpeedRadS) + " rad/s");
        }
        const double d = std::abs(path->startPosition(second) - now);
        // Trapezoid (or triangle) time of the move to the start point.
        const double t = d * aPos >= vPos * vPos ? d / vPos + vPos / aPos : 2.0 * std::sqrt(d / aPos);
        positioningS = std::max(positioningS, t);
    }
    const double total = positioningS + path->duration();
    if (total > kCircleMaxDurationS)
        return out("the test would take " + num(total) + " s (positioning " + num(positioningS) + " s, circle " +
                   num(path->duration()) + " s), more than " + num(kCircleMaxDurationS) + " s: raise the feed");
    return Status::success();
}

struct SimulatedDrive::CircleState {
    sim::AxisSimulator* x = nullptr;
    sim::AxisSimulator* y = nullptr;
    model::ParameterValues backupX, backupY;
    sim::CirclePath path;
    std::optional<sim::CircleRun> run;
    double startS = 0.0;      ///< x's time at the start of the test
    double positionedS = 0.0; ///< x's time at which both axes have reached the start point
    double totalS = 0.0;      ///< positioning + circle + tail [s]
};

namespace {

/// The move of one axis from where it stands to its start point on the path.
sim::MotionProfile positioningProfile(const sim::AxisSimulator& s, const sim::CirclePath& path, bool second,
                                      const TestRequest& r)
{
    sim::MotionProfile p(s.positionCommand());
    p.move(path.startPosition(second) - s.positionCommand(), circlePositioningSpeed(r), circlePositioningAccel(r));
    return p;
}

/// Positioning in whole position periods [s].
double positioningS(const sim::AxisSimulator& x, const sim::AxisSimulator& y, const sim::CirclePath& path,
                    const TestRequest& r)
{
    const double positioning =
        std::max(positioningProfile(x, path, false, r).duration(), positioningProfile(y, path, true, r).duration());
    const double tp = x.parameter("position.period");
    return std::ceil(positioning / tp) * tp;
}

/// Positioning, then the run of the path with its tail in whole position periods (sim::CircleRun) [s].
double circleLengthS(const sim::AxisSimulator& x, const sim::AxisSimulator& y, const sim::CirclePath& path,
                     const TestRequest& r)
{
    const double tp = x.parameter("position.period");
    return positioningS(x, y, path, r) + static_cast<double>(sim::CircleRun::sampleCount(path, tp)) * tp;
}

} // namespace

struct SimulatedDrive::CheckedCircle {
    sim::AxisSimulator* x = nullptr;
    sim::AxisSimulator* y = nullptr;
    sim::CirclePath path;
};

Result<SimulatedDrive::CheckedCircle> SimulatedDrive::checkCircle(const TestRequest& request)
{
    auto x = axisSim(request.axis);
    if (!x)
        return x.error();
    const std::string& secondAxis = request.circle().secondAxis;
    if (secondAxis.empty())
        return makeError(ErrorCode::BadInput, "circle test: the second plane axis is not named");
    auto y = axisSim(secondAxis);
    if (!y)
        return y.error();
    if (auto st = checkCircleRequest(request, **x, **y); !st)
        return st.error();
    auto path = sim::CirclePath::plan(circleOptionsOf(request));
    if (!path)
        return path.error();
    return CheckedCircle{*x, *y, *path};
}

Result<TestPlan> SimulatedDrive::planCircle(const TestRequest& request)
{
    auto c = checkCircle(request);
    if (!c)
        return c.error();
    const double tp = c->x->parameter("position.period");
    TestPlan p;
    p.motionTimeS = circleLengthS(*c->x, *c->y, c->path, request);
    p.traceRateHz = 1.0 / tp;
    p.recordSamples = sim::CircleRun::sampleCount(c->path, tp);
    return p;
}

Status SimulatedDrive::startCircle(const TestRequest& request)
{
    auto checked = checkCircle(request);
    if (!checked)
        return checked.error();
    const sim::CirclePath* path = &checked->path;
    auto c = std::make_shared<CircleState>();
    c->x = checked->x;
    c->y = checked->y;
    c->backupX = c->x->parameters();
    c->backupY = c->y->parameters();
    c->path = *path;
    c->startS = c->x->time();
    c->totalS = circleLengthS(*c->x, *c->y, *path, request);
    c->positionedS = c->startS + positioningS(*c->x, *c->y, *path, request);
    // Both axes move to the start point at once (each its own trapezoid), then the circle begins.
    for (const auto& [sim, second] : {std::pair{c->x, false}, std::pair{c->y, true}}) {
        auto p = positioningProfile(*sim, *path, second, request);
        sim->setControlMode(sim::ControlMode::Position);
        sim->setVelocityCommand({});
        sim->setTorqueInjection({});
        sim->setPositionProfile(p);
    }
    m_circle = c;
    m_request = request;
    m_active = nullptr;
    m_frfPlan.reset();
    m_multisinePlan.reset();
    m_frf.reset();
    m_trace.reset();
    m_status = {TestState::Running, 0.0, {}};
    return Status::success();
}

Result<TestStatus> SimulatedDrive::pollCircle()
{
    CircleState& c = *m_circle;
    const double tp = c.x->parameter("position.period");
    const auto ticks = std::llround(tp / c.x->currentPeriod());
    auto samples = static_cast<std::size_t>(std::max(1.0, std::round(m_slice / tp)));
    // Positioning: both axes in lock step, whole position periods.
    while (!c.run && samples > 0) {
        if (c.x->time() >= c.positionedS - 0.5 * c.x->currentPeriod()) {
            auto run = sim::CircleRun::begin(*c.x, *c.y, c.path);
            if (!run) {
                abortCircle(run.error().detail);
                m_status.state = TestState::Faulted;
                return m_status;
            }
            c.run.emplace(std::move(run).value());
            break;
        }
        c.x->runTicks(ticks);
        c.y->runTicks(ticks);
        --samples;
    }
    if (c.run)
        c.run->step(samples);
    m_status.progress = std::clamp((c.x->time() - c.startS) / c.totalS, 0.0, 1.0);
    if (!c.run || !c.run->done())
        return m_status;
    m_trace = c.run->trace();
    m_trace->metadata.set(model::meta::kMachine, m_machine.name);
    m_trace->metadata.set(model::meta::kMotionTimeS, c.x->time() - c.startS);
    // The axes hold the end point of the path; the parameters from before the test return.
    c.x->setPositionProfile(sim::MotionProfile(c.path.endPosition(false)));
    c.y->setPositionProfile(sim::MotionProfile(c.path.endPosition(true)));
    (void)c.x->setParameters(c.backupX);
    (void)c.y->setParameters(c.backupY);
    m_circle.reset();
    m_status = {TestState::Completed, 1.0, {}};
    return m_status;
}

bool SimulatedDrive::testMoves(const sim::AxisSimulator* axis) const
{
    if (m_status.state != TestState::Running)
        return false;
    return axis == m_active || (m_circle && (axis == m_circle->x || axis == m_circle->y));
}

void SimulatedDrive::abortCircle(const std::string& why)
{
    // Stop both axes at once: hold velocity 0 and restore both axes' parameters.
    for (auto [sim, backup] :
         {std::pair{m_circle->x, &m_circle->backupX}, std::pair{m_circle->y, &m_circle->backupY}}) {
        sim->stopTrace();
        sim->setVelocityCommand({});
        sim->setTorqueInjection({});
        sim->setControlMode(sim::ControlMode::Velocity);
        (void)sim->setParameters(*backup);
    }
    m_circle.reset();
    m_status = {TestState::Aborted, m_status.progress, why};
}

} // namespace axistune::device

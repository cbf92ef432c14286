// SPDX-License-Identifier: GPL-3.0-or-later
// Simulated ball-bar circle test: circular interpolation of two feed axes (each with its own servo
// loops and elastic lost motion, spec/lost-motion-and-two-inertia.md §1.7–1.9 and chapter 4), read
// by a ball bar pivoted at the programmed centre. The reversal torque change ΔT of each axis is taken
// from the torque plateaus either side of its reversals (spec §4.3, ΔT peak-to-peak). Geometry and
// conventions: docs/ballbar.md "Simulated circle tests".
#include "core/sim/CircleTest.h"

#include "core/model/Constants.h"
#include "core/model/Metadata.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/sim/AxisSimulator.h"
#include "core/sim/CircleRun.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

namespace axistune::sim {
namespace {

using model::kPi;
using model::kRadPerDeg;

double wrapPi(double a)
{
    return std::remainder(a, 2.0 * kPi);
}

std::string fmt(double v)
{
    return model::formatNumber(v, 10);
}

struct Samples {
    std::vector<double> s, x, y, tx, ty;
};

/// ΔT of one axis: |mean torque after − mean torque before| over the reversals inside the data arc.
double reversalTorqueChange(const Samples& d, const CircleTestOptions& o, double phi0, double sigma, int axis,
                            double sFrom, double sTo)
{
    const auto& torque = axis == 0 ? d.tx : d.ty;
    const double ex = o.torqueExcludeDeg * kRadPerDeg, win = o.torqueWindowDeg * kRadPerDeg;
    double sum = 0.0;
    int count = 0;
    for (int k = -2; k <= 6; ++k) {
        const double revPhi = (axis == 0 ? 0.0 : 0.5 * kPi) + k * kPi;
        const double sRev = sigma * (revPhi - phi0); // travelled arc at that reversal
        if (sRev - win < sFrom || sRev + win > sTo)
            continue;
        double before = 0, after = 0;
        int nb = 0, na = 0;
        for (std::size_t i = 0; i < d.s.size(); ++i) {
            const double ds = d.s[i] - sRev;
            if (ds > -win && ds < -ex)
                before += torque[i], ++nb;
            else if (ds > ex && ds < win)
                after += torque[i], ++na;
        }
        if (nb == 0 || na == 0)
            continue;
        sum += std::abs(after / na - before / nb);
        ++count;
    }
    return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN();
}

/// Ball-bar reading over the data arc [sFrom, sTo] of travelled arc.
model::BallBarTrace ballBarFromSamples(const Samples& d, const CircleTestOptions& o, double phi0, double sigma,
                                    double sFrom, double sTo)
{
    const double r = o.radiusM, cx = o.centerXM, cy = o.centerYM;
    model::BallBarTrace bb;
    bb.radiusM = o.radiusM;
    bb.feedMPerS = o.feedMPerS;
    bb.direction = o.direction;
    bb.plane = o.axisX + o.axisY;
    bb.centerXM = o.centerXM;
    bb.centerYM = o.centerYM;
    for (std::size_t i = 0; i < d.s.size(); ++i) {
        if (d.s[i] < sFrom || d.s[i] > sTo)
            continue;
        const double phi = phi0 + sigma * d.s[i];
        const double theta = phi + wrapPi(std::atan2(d.y[i] - cy, d.x[i] - cx) - phi);
        if (!bb.angleRad.empty() && !(sigma * (theta - bb.angleRad.back()) > 0.0))
            continue; // keeps the angles strictly monotonic
        bb.angleRad.push_back(theta);
        bb.deviationM.push_back(std::hypot(d.x[i] - cx, d.y[i] - cy) - r);
    }
    return bb;
}

} // namespace

Result<CircleTestResult> evaluateCircleTrace(const model::Capture& trace, const CircleTestOptions& o)
{
    auto path = CirclePath::plan(o);
    if (!path)
        return path.error();
    auto bad = [](const std::string& m) { return makeError(ErrorCode::BadInput, "circle trace: " + m); };
    const model::Channel* arc = trace.channel("arc_rad");
    const model::Channel* px = trace.channel(circleChannel(o.axisX, "table_pos_m"));
    const model::Channel* py = trace.channel(circleChannel(o.axisY, "table_pos_m"));
    const model::Channel* tx = trace.channel(circleChannel(o.axisX, "torque_Nm"));
    const model::Channel* ty = trace.channel(circleChannel(o.axisY, "torque_Nm"));
    const std::pair<const model::Channel*, std::string> need[] = {
        {arc, "arc_rad"},
        {px, circleChannel(o.axisX, "table_pos_m")},
        {py, circleChannel(o.axisY, "table_pos_m")},
        {tx, circleChannel(o.axisX, "torque_Nm")},
        {ty, circleChannel(o.axisY, "torque_Nm")}};
    for (const auto& [c, name] : need) {
        if (!c)
            return bad("channel '" + name + "' is missing");
        if (c->data.size() != arc->data.size())
            return bad("channel '" + name + "' has " + std::to_string(c->data.size()) + " samples, arc_rad " +
                       std::to_string(arc->data.size()));
    }
    if (arc->data.empty() || arc->data.back() < path->dataTo())
        return bad("the trace ends before the " + fmt(o.dataArcDeg) + " deg data arc (an aborted circle?)");
    Samples d;
    d.s = arc->data;
    d.tx = tx->data;
    d.ty = ty->data;
    d.x.resize(d.s.size());
    d.y.resize(d.s.size());
    for (std::size_t i = 0; i < d.s.size(); ++i) {
        const double xt = px->data[i], yt = py->data[i];
        d.x[i] = (1.0 + o.scaleX) * xt + o.squarenessPerM * yt;
        d.y[i] = (1.0 + o.scaleY) * yt;
    }
    const double phi0 = path->phi0(), sigma = path->sigma(), sFrom = path->dataFrom(), sTo = path->dataTo();
    CircleTestResult res;
    res.ballbar = ballBarFromSamples(d, o, phi0, sigma, sFrom, sTo);
    model::BallBarTrace& bb = res.ballbar;
    res.dTxNm = reversalTorqueChange(d, o, phi0, sigma, 0, sFrom, sTo);
    res.dTyNm = reversalTorqueChange(d, o, phi0, sigma, 1, sFrom, sTo);
    if (std::isfinite(res.dTxNm))
        bb.dTxNm = res.dTxNm;
    if (std::isfinite(res.dTyNm))
        bb.dTyNm = res.dTyNm;
    if (const auto* v = trace.metadata.find(model::meta::kMachine)) {
        bb.source = v->text();
        bb.metadata.set(model::meta::kSource, v->text());
    }
    return res;
}

Result<model::BallBarTrace> ballBarFromCircleTrace(const model::Capture& trace)
{
    auto o = circleOptionsFromTrace(trace);
    if (!o)
        return o.error();
    auto r = evaluateCircleTrace(trace, *o);
    if (!r)
        return r.error();
    return std::move(r.value().ballbar);
}

Result<CircleTestResult> runCircleTest(const MachineDefinition& machine, const CircleTestOptions& o)
{
    auto path = CirclePath::plan(o);
    if (!path)
        return path.error();
    const AxisDefinition* defX = machine.axis(o.axisX);
    const AxisDefinition* defY = machine.axis(o.axisY);
    if (!defX || !defY)
        return makeError(ErrorCode::BadInput, "circle test: machine '" + machine.name + "' has no axis '" +
                                                  (defX ? o.axisY : o.axisX) + "'");
    if (defX->kind != AxisKind::Linear || defY->kind != AxisKind::Linear || o.axisX == o.axisY)
        return makeError(ErrorCode::BadInput, "circle test: the plane needs two different linear axes");
    auto simX = AxisSimulator::create(*defX, o.seed);
    if (!simX)
        return simX.error();
    auto simY = AxisSimulator::create(*defY, o.seed + 1);
    if (!simY)
        return simY.error();
    AxisSimulator& ax = **simX;
    AxisSimulator& ay = **simY;
    // At rest on the start point at t = 0 (a drive positions its axes there first).
    ax.reset(path->startPosition(false));
    ay.reset(path->startPosition(true));
    auto started = CircleRun::begin(ax, ay, *path);
    if (!started)
        return started.error();
    CircleRun& run = started.value();
    ax.startTrace();
    ay.startTrace();
    run.step(run.totalSamples());
    auto evaluated = evaluateCircleTrace(run.trace(), o);
    if (!evaluated)
        return evaluated.error();
    CircleTestResult res = std::move(evaluated).value();
    model::BallBarTrace& bb = res.ballbar;
    bb.source = "sim:" + machine.name;
    bb.metadata.set(model::meta::kSource, bb.source);
    bb.metadata.set("squareness_um_per_m", o.squarenessPerM * 1e6);
    bb.metadata.set("scale_x_ppm", o.scaleX * 1e6);
    bb.metadata.set("scale_y_ppm", o.scaleY * 1e6);
    // A number while a double holds it exactly; larger seeds stay their exact digits (Metadata::set of an IntegerKey).
    bb.metadata.set(model::meta::kSeed, o.seed);
    res.traceX = ax.takeTrace();
    res.traceY = ay.takeTrace();
    return res;
}

} // namespace axistune::sim

// SPDX-License-Identifier: GPL-3.0-or-later
// Moving an axis to an absolute position (MoveTo.h).
#include "core/device/MoveTo.h"

#include "core/model/Number.h"

#include <algorithm>
#include <cmath>

namespace axistune::device {

namespace {

const model::Channel* positionCommand(const model::Capture& c)
{
    for (const auto& ch : c.channels)
        if (ch.name.rfind("position_cmd_", 0) == 0 && !ch.data.empty())
            return &ch;
    return nullptr;
}

} // namespace

Status checkCanMoveTo(Drive& drive, const std::string& axis)
{
    auto caps = drive.capabilities(axis);
    if (!caps)
        return caps.error();
    if (!caps->offers(TestType::Jog) || !caps->offers(TestType::Hold))
        return makeError(ErrorCode::BadInput,
                         "axis " + axis +
                             ": the drive offers no jog or hold test, so it cannot move the axis to a position");
    if (caps->jogInCommandUnits)
        return makeError(ErrorCode::BadInput, "axis " + axis +
                                                  ": the drive takes jog distances in its command units, not m or "
                                                  "rad, so the axis cannot be moved to a position in m or rad");
    auto w = travelWindow(drive, axis);
    return w ? Status::success() : Status(w.error());
}

Result<double> travelWindow(Drive& drive, const std::string& axis)
{
    auto lim = drive.limits(axis);
    if (!lim)
        return lim.error();
    if (!(lim->travelWindow > 0.0) || !std::isfinite(lim->travelWindow))
        return makeError(ErrorCode::BadInput, "axis " + axis +
                                                  ": the drive states no finite travel window, so positions along "
                                                  "the travel cannot be chosen within it");
    return lim->travelWindow;
}

Result<MoveToResult> findPosition(Drive& drive, const std::string& axis, const RunOptions& run)
{
    MoveToResult r;
    RunOptions withTrace = run;
    withTrace.readTrace = true;
    TestRequest hold;
    hold.axis = axis;
    hold.test = HoldTest{0.01};
    auto holdPlan = drive.planTest(hold);
    auto h = runTest(drive, hold, withTrace);
    if (!h)
        return makeError(h.error().code, "finding the position of axis " + axis + ": " + h.error().detail);
    r.motionTimeS = motionTimeS(*h, holdPlan);
    const model::Channel* pos = h->trace ? positionCommand(*h->trace) : nullptr;
    if (!pos)
        return makeError(ErrorCode::Device,
                         "finding the position of axis " + axis + ": the hold's trace has no position_cmd_* channel");
    r.linear = pos->name.size() < 2 || pos->name.substr(pos->name.size() - 2) == "_m";
    r.from = r.to = pos->data.back();
    return r;
}

Result<MoveToResult> moveAxisTo(Drive& drive, const std::string& axis, double target, const MoveToOptions& o,
                                const RunOptions& run)
{
    if (auto st = checkCanMoveTo(drive, axis); !st)
        return st.error();
    auto window = travelWindow(drive, axis);
    if (!window)
        return window.error();
    if (!std::isfinite(target) || std::abs(target) > *window * (1.0 + 1e-12))
        return makeError(ErrorCode::OutOfRange, "axis " + axis + ": position " + model::formatNumber(target, 6) +
                                                    " lies outside the drive's travel window +-" +
                                                    model::formatNumber(*window, 6));
    auto found = findPosition(drive, axis, run);
    if (!found)
        return found.error();
    MoveToResult r = *found;
    RunOptions withTrace = run;
    withTrace.readTrace = true;
    const double distance = target - r.from;
    if (std::abs(distance) <= 1e-9 * std::max(1.0, *window))
        return r;
    TestRequest jog;
    jog.axis = axis;
    JogTest& move = jog.test.emplace<JogTest>();
    move.distance = distance;
    move.velocity = o.velocity;
    if (!(move.velocity > 0.0))
        move.velocity = r.linear ? kMoveToSpeedLinear : kMoveToSpeedRotary;
    move.acceleration = o.acceleration > 0.0 ? o.acceleration : (r.linear ? 2.0 : 20.0);
    move.dwellS = o.dwellS;
    auto jogPlan = drive.planTest(jog);
    auto j = runTest(drive, jog, withTrace);
    if (!j)
        return makeError(j.error().code,
                         "moving axis " + axis + " to " + model::formatNumber(target, 6) + ": " + j.error().detail);
    r.motionTimeS += motionTimeS(*j, jogPlan);
    if (j->trace)
        if (const auto* p = positionCommand(*j->trace))
            r.to = p->data.back();
    return r;
}

} // namespace axistune::device

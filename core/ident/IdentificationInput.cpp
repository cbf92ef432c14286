// SPDX-License-Identifier: GPL-3.0-or-later
// Capture columns → identification and validation records (docs/identification.md "Input").
#include "core/ident/IdentificationInput.h"

#include <cmath>

namespace axistune::ident {
namespace {

bool endsWith(const std::string& s, const std::string& suffix)
{
    return s.size() > suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace

Result<AxisMotion> axisMotionFor(const std::string& unit, const std::string& column)
{
    if (unit == "m")
        return AxisMotion::Linear;
    if (unit == "rad")
        return AxisMotion::Rotary;
    if (!unit.empty())
        return makeError(ErrorCode::BadInput,
                         "position unit '" + unit + "' must be m (linear axis) or rad (rotary axis)");
    if (endsWith(column, "_m"))
        return AxisMotion::Linear;
    if (endsWith(column, "_rad"))
        return AxisMotion::Rotary;
    return makeError(ErrorCode::BadInput,
                     "position column '" + column + "' does not end in _m or _rad: give the position unit (m or rad)");
}

Result<std::vector<double>> captureColumn(const model::Capture& cap, const std::string& src, const std::string& name)
{
    if (const auto* c = cap.channel(name))
        return c->data;
    std::string known;
    for (const auto& c : cap.channels)
        known += (known.empty() ? "" : ", ") + c.name;
    return makeError(ErrorCode::NotFound, src + ": no column '" + name + "' (columns: " + known + ")");
}

Result<double> capturePeriod(const model::Capture& cap, const std::string& src, const CaptureColumns& cols)
{
    if (cols.fsHz > 0.0) {
        if (!std::isfinite(cols.fsHz))
            return makeError(ErrorCode::BadInput, "sample rate must be finite");
        return 1.0 / cols.fsHz;
    }
    if (!(cols.timeTolerance > 0.0 && cols.timeTolerance < 0.5))
        return makeError(ErrorCode::OutOfRange, "time tolerance must lie in (0, 0.5) of the median step");
    auto t = captureColumn(cap, src, cols.time);
    if (!t)
        return makeError(t.error().code, t.error().detail + "; give the time column or the sample rate");
    auto h = uniformSamplePeriod(*t, cols.timeTolerance);
    if (!h)
        return makeError(h.error().code, src + ", column '" + cols.time + "': " + h.error().detail);
    return h;
}

Result<MotionRecord> motionRecordFromCapture(const model::Capture& cap, const std::string& src,
                                             const CaptureColumns& cols)
{
    if (!(cols.forceScale > 0.0) || !std::isfinite(cols.forceScale))
        return makeError(ErrorCode::OutOfRange, "force scale must be a positive number");
    MotionRecord r;
    auto h = capturePeriod(cap, src, cols);
    if (!h)
        return h.error();
    r.periodS = *h;
    auto q = captureColumn(cap, src, cols.position);
    if (!q)
        return q.error();
    auto f = captureColumn(cap, src, cols.force);
    if (!f)
        return f.error();
    r.position = std::move(q).value();
    r.force = std::move(f).value();
    for (double& v : r.force)
        v *= cols.forceScale;
    if (!cols.velocity.empty()) {
        auto v = captureColumn(cap, src, cols.velocity);
        if (!v)
            return v.error();
        r.velocity = std::move(v).value();
    }
    return r;
}

Result<ValidationRecord> validationRecordFromCapture(const model::Capture& cap, const std::string& src,
                                                     const CaptureColumns& cols)
{
    if (cols.reference.empty())
        return makeError(ErrorCode::BadInput, src + ": validation needs the reference (commanded position) column");
    ValidationRecord r;
    auto h = capturePeriod(cap, src, cols);
    if (!h)
        return h.error();
    r.periodS = *h;
    for (auto [name, dst] : {std::pair{&cols.reference, &r.reference}, std::pair{&cols.position, &r.position},
                             std::pair{&cols.force, &r.command}}) {
        auto c = captureColumn(cap, src, *name);
        if (!c)
            return c.error();
        *dst = std::move(c).value();
    }
    if (!cols.extra.empty()) {
        auto c = captureColumn(cap, src, cols.extra);
        if (!c)
            return c.error();
        r.extra = std::move(c).value();
    }
    return r;
}

} // namespace axistune::ident

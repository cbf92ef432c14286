// SPDX-License-Identifier: GPL-3.0-or-later
// Simulated ball-bar circle test: circular interpolation of two feed axes (each with its own servo
// loops and elastic lost motion, spec/lost-motion-and-two-inertia.md §1.7–1.9 and chapter 4), read
// by a ball bar pivoted at the programmed centre. The reversal torque change ΔT of each axis is taken
// from the torque plateaus either side of its reversals (spec §4.3, ΔT peak-to-peak). Geometry and
// conventions: docs/ballbar.md "Simulated circle tests".
#include "core/sim/CircleTest.h"

#include "core/sim/AxisSimulator.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

namespace axistune::sim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

double wrapPi(double a)
{
    return std::remainder(a, 2.0 * kPi);
}

std::string fmt(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

/// Travelled arc s(τ) ≥ 0 [rad] with its derivatives: dwell, constant angular acceleration over half
/// the lead-in arc, constant speed, deceleration over half the lead-out arc.
struct ArcPlan {
    double dwell = 0, omega = 0, alpha = 0, tAcc = 0, tConst = 0, sAcc = 0;
    double duration() const { return dwell + 2.0 * tAcc + tConst; }
    MotionState at(double t) const
    {
        double s = 0, w = 0, a = 0;
        double u = t - dwell;
        if (u <= 0.0) {
            return {0.0, 0.0, 0.0};
        } else if (u < tAcc) {
            s = 0.5 * alpha * u * u, w = alpha * u, a = alpha;
        } else if ((u -= tAcc) < tConst) {
            s = sAcc + omega * u, w = omega;
        } else if ((u -= tConst) < tAcc) {
            s = sAcc + omega * tConst + omega * u - 0.5 * alpha * u * u, w = omega - alpha * u, a = -alpha;
        } else {
            s = 2.0 * sAcc + omega * tConst;
        }
        return {s, w, a};
    }
};

Status checkOptions(const CircleTestOptions& o)
{
    auto bad = [](const std::string& m) { return Status(makeError(ErrorCode::BadInput, "circle test: " + m)); };
    if (!(o.radiusM > 0.0) || !std::isfinite(o.radiusM))
        return bad("radius must be positive (is " + fmt(o.radiusM) + " m)");
    if (!(o.feedMPerS > 0.0) || !std::isfinite(o.feedMPerS))
        return bad("feed must be positive (is " + fmt(o.feedMPerS) + " m/s)");
    if (!(o.leadArcDeg >= 10.0) || o.leadArcDeg > 360.0)
        return bad("lead arc must be 10..360 deg (is " + fmt(o.leadArcDeg) + ")");
    if (!std::isfinite(o.centerXM) || !std::isfinite(o.centerYM) || !std::isfinite(o.dataStartDeg))
        return bad("centre and start angle must be finite");
    if (!(o.dwellS >= 0.0) || !std::isfinite(o.squarenessPerM) || !std::isfinite(o.scaleX) || !std::isfinite(o.scaleY))
        return bad("dwell must be >= 0 and the geometric errors finite");
    if (!(o.torqueExcludeDeg > 0.0 && o.torqueWindowDeg > o.torqueExcludeDeg && o.torqueWindowDeg < 90.0))
        return bad("torque plateau window must satisfy 0 < exclude < window < 90 deg");
    return Status::success();
}

struct Samples {
    std::vector<double> s, x, y, tx, ty;
};

/// ΔT of one axis: |mean torque after − mean torque before| over the reversals inside the data arc.
double reversalTorqueChange(const Samples& d, const CircleTestOptions& o, double phi0, double sigma, int axis,
                            double sFrom, double sTo)
{
    const auto& torque = axis == 0 ? d.tx : d.ty;
    const double ex = o.torqueExcludeDeg * kDeg, win = o.torqueWindowDeg * kDeg;
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

Result<CircleTestResult> runCircleTest(const MachineDefinition& machine, const CircleTestOptions& o)
{
    if (auto st = checkOptions(o); !st)
        return st.error();
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
    const double tp = ax.parameter("position.period");
    if (std::abs(tp - ay.parameter("position.period")) > 1e-12 ||
        std::abs(ax.currentPeriod() - ay.currentPeriod()) > 1e-15)
        return makeError(ErrorCode::BadInput, "circle test: axes " + o.axisX + " and " + o.axisY +
                                                  " must share the position and current periods");
    const std::int64_t ticksPerSample = std::llround(tp / ax.currentPeriod());

    const double sigma = o.direction == model::CircleDirection::Ccw ? 1.0 : -1.0;
    const double r = o.radiusM, cx = o.centerXM, cy = o.centerYM;
    ArcPlan plan;
    plan.dwell = o.dwellS;
    plan.omega = o.feedMPerS / r;
    plan.sAcc = 0.5 * o.leadArcDeg * kDeg;
    plan.alpha = plan.omega * plan.omega / (2.0 * plan.sAcc);
    plan.tAcc = plan.omega / plan.alpha;
    const double sFrom = o.leadArcDeg * kDeg, sTo = sFrom + 2.0 * kPi;
    plan.tConst = (sTo + sFrom - 2.0 * plan.sAcc) / plan.omega;
    const double phi0 = o.dataStartDeg * kDeg - sigma * sFrom;

    auto command = [plan, sigma, phi0, r](double centre, bool isY) {
        return [plan, sigma, phi0, r, centre, isY](double t) {
            const MotionState a = plan.at(t);
            const double phi = phi0 + sigma * a.position, w = sigma * a.velocity, al = sigma * a.acceleration;
            const double c = std::cos(phi), s = std::sin(phi);
            if (isY)
                return MotionState{centre + r * s, r * c * w, -r * s * w * w + r * c * al};
            return MotionState{centre + r * c, -r * s * w, -r * c * w * w - r * s * al};
        };
    };
    ax.reset(cx + r * std::cos(phi0));
    ay.reset(cy + r * std::sin(phi0));
    ax.setControlMode(ControlMode::Position);
    ay.setControlMode(ControlMode::Position);
    ax.setPositionCommand(command(cx, false));
    ay.setPositionCommand(command(cy, true));
    ax.startTrace();
    ay.startTrace();

    Samples d;
    const auto n = static_cast<std::size_t>(std::ceil((plan.duration() + 0.2) / tp));
    for (auto* v : {&d.s, &d.x, &d.y, &d.tx, &d.ty})
        v->reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
        ax.runTicks(ticksPerSample);
        ay.runTicks(ticksPerSample);
        const double xt = ax.tablePosition(), yt = ay.tablePosition();
        d.s.push_back(plan.at(ax.time()).position);
        d.x.push_back((1.0 + o.scaleX) * xt + o.squarenessPerM * yt);
        d.y.push_back((1.0 + o.scaleY) * yt);
        d.tx.push_back(ax.torque());
        d.ty.push_back(ay.torque());
    }

    CircleTestResult res;
    res.ballbar = ballBarFromSamples(d, o, phi0, sigma, sFrom, sTo);
    model::BallBarTrace& bb = res.ballbar;
    bb.source = "sim:" + machine.name;
    res.dTxNm = reversalTorqueChange(d, o, phi0, sigma, 0, sFrom, sTo);
    res.dTyNm = reversalTorqueChange(d, o, phi0, sigma, 1, sFrom, sTo);
    if (std::isfinite(res.dTxNm))
        bb.dTxNm = res.dTxNm;
    if (std::isfinite(res.dTyNm))
        bb.dTyNm = res.dTyNm;
    bb.metadata["source"] = bb.source;
    bb.metadata["squareness_um_per_m"] = fmt(o.squarenessPerM * 1e6);
    bb.metadata["scale_x_ppm"] = fmt(o.scaleX * 1e6);
    bb.metadata["scale_y_ppm"] = fmt(o.scaleY * 1e6);
    bb.metadata["seed"] = std::to_string(o.seed);
    res.traceX = ax.takeTrace();
    res.traceY = ay.takeTrace();
    return res;
}

} // namespace axistune::sim

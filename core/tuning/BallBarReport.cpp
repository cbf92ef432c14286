// SPDX-License-Identifier: GPL-3.0-or-later
// Ball-bar report: combines per-run diagnostics (BallBarDiagnostics.cpp) over CW and CCW runs.
// Squareness and servo mismatch both give a sin2θ term; servo mismatch changes sign with the travel
// direction (k = γR/2 + σvΔτ/2, docs/ballbar.md), so two directions separate them by least squares.
#include "core/model/Constants.h"
#include "core/model/Number.h"
#include "core/tuning/BallBarDiagnostics.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace axistune::tuning {
namespace {

using model::kRadPerDeg;

std::string fmt(double v, int prec = 2)
{
    return model::formatFixed(v, prec);
}

const char* axisName(int axis)
{
    return axis == 0 ? "X" : "Y";
}

void combineSin2(BallBarReport& rep, const std::vector<const RunDiagnostics*>& full)
{
    bool ccw = false, cw = false;
    for (const auto* r : full)
        (r->sigma > 0 ? ccw : cw) = true;
    if (ccw && cw) {
        const auto n = static_cast<Eigen::Index>(full.size());
        Eigen::MatrixXd a(n, 2);
        Eigen::VectorXd y(n);
        for (Eigen::Index i = 0; i < n; ++i) {
            a.row(i) << 0.5 * full[i]->radiusM, 0.5 * full[i]->sigma * full[i]->feedMPerS;
            y(i) = full[i]->sin2M;
        }
        const Eigen::VectorXd x = a.colPivHouseholderQr().solve(y);
        rep.squarenessRad = x(0);
        rep.servoMismatchS = x(1);
        rep.findings.push_back({"squareness", x(0) * 1e6, "um/m",
                                "sin2θ coefficient k of each run; k = γR/2 + σvΔτ/2 solved for γ over CW and CCW runs "
                                "(the part that keeps its sign with direction); positive = angle between +X and +Y "
                                "below 90°",
                                "squareness.both_directions",
                                {}});
        rep.findings.push_back({"servo_mismatch", x(1) * 1e3, "ms",
                                "the sin2θ part that changes sign with travel direction, Δτ from k = γR/2 + σvΔτ/2; "
                                "positive = X lags Y",
                                "servo_mismatch.both_directions",
                                {}});
        return;
    }
    double g = 0.0;
    for (const auto* r : full)
        g += 2.0 * r->sin2M / r->radiusM;
    rep.squarenessRad = g / static_cast<double>(full.size());
    rep.findings.push_back({"squareness", *rep.squarenessRad * 1e6, "um/m",
                            "γ = 2k/R from the sin2θ coefficient k of runs in one direction only: includes any servo "
                            "mismatch (measure CW and CCW to separate them)",
                            "squareness.one_direction",
                            {}});
    const std::string given = ccw ? "CCW" : "CW";
    rep.refused.push_back({"servo_mismatch.one_direction", {given},
                           "servo_mismatch: needs runs in both directions (CW and CCW); only " + given + " given"});
}

void combineCyclic(BallBarReport& rep, const std::vector<const RunDiagnostics*>& full)
{
    for (int axis = 0; axis < 2; ++axis) {
        CyclicFit c;
        double pitchAmp = -1.0;
        for (const auto* r : full) {
            const auto& rc = r->cyclic[axis];
            c.amplitudeM += rc.amplitudeM / static_cast<double>(full.size());
            c.thresholdM += rc.thresholdM / static_cast<double>(full.size());
            c.detected = c.detected || rc.detected;
            if (rc.amplitudeM > pitchAmp) {
                pitchAmp = rc.amplitudeM;
                c.pitchM = rc.pitchM;
            }
        }
        rep.cyclic[axis] = c;
        const std::vector<std::string> args{axisName(axis), fmt(c.pitchM * 1e3, 3), fmt(c.thresholdM * 1e6, 3)};
        rep.findings.push_back({std::string("cyclic_error_") + (axis == 0 ? "x" : "y"), c.amplitudeM * 1e6, "um",
                                std::string("largest least-squares sinusoid of the ") + args[0] +
                                    " coordinate (pitch scanned from the sampling limit to R/2, best pitch " + args[1] +
                                    " mm) in the residual of the smooth fit, projected radially; " +
                                    (c.detected ? "detected" : "not detected") + " against a noise threshold of " +
                                    args[2] + " um (false alarm ≈ 1e-3)",
                                c.detected ? "cyclic_error.detected" : "cyclic_error.not_detected", args});
    }
}

/// Reversal steps and spikes need only the windows around each reversal (partial arcs too).
void combineReversals(BallBarReport& rep, const BallBarOptions& opt)
{
    for (int axis = 0; axis < 2; ++axis) {
        double sum = 0.0, var = 0.0;
        int n = 0;
        for (const auto& r : rep.runs) {
            for (const auto& ev : r.events) {
                if (ev.axis != axis)
                    continue;
                sum += ev.stepM;
                var += ev.stepStdErrM * ev.stepStdErrM;
                ++n;
                if (ev.spike)
                    rep.spikes.push_back({axis, ev.spikeAngleRad, ev.spikeHeightM, ev.spikeWidthRad, r.source});
            }
        }
        if (n == 0) {
            rep.refused.push_back({"backlash.not_covered",
                                   {axisName(axis)},
                                   std::string("backlash_") + (axis == 0 ? "x" : "y") + ": no " + axisName(axis) +
                                       " reversal is covered by the trace(s)"});
            continue;
        }
        rep.backlashM[axis] = sum / n;
        rep.backlashThresholdM[axis] = std::max(4.0 * std::sqrt(var) / n, kMinBacklashM);
        const bool detected = std::abs(*rep.backlashM[axis]) > rep.backlashThresholdM[axis];
        rep.backlashDetected[axis] = detected;
        const std::vector<std::string> args{std::to_string(n),
                                            axisName(axis),
                                            axis == 0 ? "0°/180°" : "90°/270°",
                                            fmt(opt.excludeDeg, 1),
                                            fmt(opt.excludeDeg + opt.fitWindowDeg, 1),
                                            fmt(rep.backlashThresholdM[axis] * 1e6, 2)};
        rep.findings.push_back({std::string("backlash_") + (axis == 0 ? "x" : "y"), *rep.backlashM[axis] * 1e6, "um",
                                "mean radial step across " + args[0] + " " + args[1] + " reversal(s) (" + args[2] +
                                    "): joint fit of a cubic plus a step over " + args[3] + "–" + args[4] +
                                    "° each side of the reversal, where a spike has decayed; positive = outward step "
                                    "(lost motion), negative = inward (over-compensation); " +
                                    (detected ? "a backlash: " : "no backlash: ") + "|step| " +
                                    (detected ? "above " : "not above ") + args[5] +
                                    " um (4× its standard error, at least 0.3 um)",
                                detected ? "backlash" : "backlash.not_detected", args});
    }
    for (const auto& s : rep.spikes) {
        const std::vector<std::string> args{fmt(s.angleRad / kRadPerDeg, 1), fmt(opt.excludeDeg, 1), axisName(s.axis),
                                            fmt(s.widthRad / kRadPerDeg, 2)};
        rep.findings.push_back({std::string("reversal_spike_") + (s.axis == 0 ? "x" : "y"), s.heightM * 1e6, "um",
                                "transient at " + args[0] + "°, within ±" + args[1] + "° of a " + args[2] +
                                    " reversal (width " + args[3] +
                                    "° at half height): the peak departure from the step's own transition (the level "
                                    "before the reversal, then a monotonic move to the level after it, which a "
                                    "backlash follows) that comes back to that level; reported when above 4× the "
                                    "fit-window noise and 0.3 um",
                                "reversal_spike", args});
    }
}

/// Centre, radius deviation, circularity and scale mismatch of the full-circle runs.
void combineCircle(BallBarReport& rep, const std::vector<const RunDiagnostics*>& full)
{
    double circ = 0.0, cx = 0.0, cy = 0.0, r0 = 0.0, scale = 0.0;
    for (const auto* r : full) {
        circ = std::max(circ, r->circularityM);
        cx += r->centerXM / static_cast<double>(full.size());
        cy += r->centerYM / static_cast<double>(full.size());
        r0 += r->radiusDeviationM / static_cast<double>(full.size());
        scale += 2.0 * r->cos2M / r->radiusM / static_cast<double>(full.size());
    }
    rep.circularityM = circ;
    rep.centerXM = cx;
    rep.centerYM = cy;
    rep.radiusDeviationM = r0;
    rep.scaleMismatch = scale;
    rep.findings.push_back({"circularity", circ * 1e6, "um",
                            "max − min radial deviation after removing the least-squares circle (ISO 230-4), the "
                            "largest over the runs",
                            "circularity",
                            {}});
    rep.findings.push_back(
        {"center_x", cx * 1e6, "um", "least-squares circle centre offset along X (mean of runs)", "center_x", {}});
    rep.findings.push_back(
        {"center_y", cy * 1e6, "um", "least-squares circle centre offset along Y (mean of runs)", "center_y", {}});
    rep.findings.push_back({"radius_deviation", r0 * 1e6, "um",
                            "least-squares circle radius minus the nominal radius (includes mean scale error and "
                            "ball-bar length error)",
                            "radius_deviation",
                            {}});
    rep.findings.push_back({"scale_mismatch", scale * 1e6, "ppm",
                            "εx − εy = 2c/R from the cos2θ coefficient c of the joint fit (circle, 2nd harmonics, "
                            "lost motion) outside the reversal zones; positive = X travels further than Y",
                            "scale_mismatch",
                            {}});
}

} // namespace

Result<BallBarReport> analyzeBallBar(std::span<const io::BallBarTrace> traces, const BallBarOptions& opt)
{
    if (traces.empty())
        return makeError(ErrorCode::BadInput, "ball-bar analysis needs at least one trace");
    BallBarReport rep;
    for (const auto& t : traces) {
        auto r = analyzeRun(t, opt);
        if (!r)
            return r.error();
        rep.runs.push_back(std::move(r).value());
    }
    std::vector<const RunDiagnostics*> full;
    for (const auto& r : rep.runs) {
        if (r.fullCircle)
            full.push_back(&r);
        else
            rep.refused.push_back({"full_circle", r.refusalArgs, r.refusal});
    }
    combineReversals(rep, opt);
    if (full.empty())
        return rep;

    combineCircle(rep, full);
    combineSin2(rep, full);
    combineCyclic(rep, full);
    return rep;
}

} // namespace axistune::tuning

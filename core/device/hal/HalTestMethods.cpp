// SPDX-License-Identifier: GPL-3.0-or-later
// The hal: tests besides the multisine (docs/linuxcnc.md "Tests"): FRF by multi-sweep and by PRBS, planned by
// core's planFrfTest at the servo rate and evaluated by core's evaluateFrfSignals (FrfTest.h, the code the simulator
// and the host evaluation use); the jog out and back and the position step, both an offset added to the pid's
// command; the plan of a jog someone else makes (planExternalJog).
#include "core/device/FrfQuantityName.h"
#include "core/device/hal/HalDrive.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/sim/MotionProfile.h"

#include <algorithm>
#include <cmath>

namespace axistune::device::hal {
namespace {

std::string num(double v)
{
    return model::formatShortest(v);
}

Status checkCommandLinked(const HalAxis& axis, const char* what)
{
    if (!(axis.periodNs > 0))
        return makeError(ErrorCode::BadInput, axis.thread + " has no period");
    if (axis.commandSignal.empty())
        return makeError(ErrorCode::BadInput, axis.pid + ".command is not linked to a net: AxisTune adds its " + what +
                                                  " to the net the NC (or the HAL file) drives");
    return Status::success();
}

} // namespace

std::vector<double> HalFrfPlan::excitation() const
{
    std::vector<double> x;
    x.reserve(totalSamples());
    if (streams) {
        // One value per servo period: the sine (or PRBS value) at that period, as the simulator samples it at its
        // trace rate. The injection adds it to the PID output, which the drive holds for the period.
        for (std::size_t i = 0; i < streams->totalSamples; ++i)
            x.push_back(frfExcitation(*streams, static_cast<double>(i)));
        return x;
    }
    for (std::size_t p = 0; p < settlePeriods + periods; ++p)
        x.insert(x.end(), design.table.begin(), design.table.end());
    return x;
}

Result<HalFrfPlan> planHalStreams(const TestRequest& r, HalFrfPlan plan, double peak)
{
    if (!r.is<FrfTest>())
        return makeError(ErrorCode::Internal, "planHalStreams: multi-sweep or PRBS only");
    const auto& f = r.frf();
    if (f.method != FrfMethod::MultiSweep && f.method != FrfMethod::Prbs)
        return makeError(ErrorCode::Internal, "planHalStreams: multi-sweep or PRBS only");
    if (!f.multisineBands.empty() || f.multisineSpacingHz != 0.0 || f.multisinePeriods != 0 ||
        !f.multisineShape.empty() || !f.multisineCrestThrough.empty())
        return makeError(ErrorCode::BadInput,
                         std::string("FRF by ") + frfMethodName(f.method) +
                             ": bands, spacing, periods, shape and crest response are multisine options");
    if (!(f.fminHz > 0.0) || !std::isfinite(f.fminHz) || !(f.fmaxHz >= f.fminHz) || !std::isfinite(f.fmaxHz))
        return makeError(ErrorCode::OutOfRange, "FRF band: fmin must be positive and not above fmax");
    // The excitation is generated at the servo rate and the plant input is seen only there: a line at or above half
    // the rate would fold onto another (core's planner allows up to the rate for the simulator's faster injection).
    if (!(f.fmaxHz < 0.5 * plan.fsHz))
        return makeError(ErrorCode::OutOfRange, "FRF band up to " + num(f.fmaxHz) +
                                                    " Hz refused: lines must lie below half the servo rate (" +
                                                    num(0.5 * plan.fsHz) + " Hz on " + plan.axis.thread + ")");
    if (!(f.settleS >= 0.0) || !std::isfinite(f.settleS) || !(f.minMeasureS >= 0.0) || !std::isfinite(f.minMeasureS))
        return makeError(ErrorCode::OutOfRange, "FRF settle and measure times must not be negative");
    // hal: does not know the loop's dynamics: the request's times, else fixed defaults (plus, per frequency, eight
    // periods capped at 0.5 s, as the simulator's period rule).
    LoopTiming timing;
    timing.settleS = f.settleS > 0.0 ? f.settleS : kHalStreamSettleS;
    timing.settlePeriods = f.settleS > 0.0 ? 0.0 : 8.0;
    timing.minMeasureS = f.minMeasureS > 0.0 ? f.minMeasureS : kHalStreamMeasureS;
    FrfPlanOptions o;
    o.method = f.method;
    o.fsHz = plan.fsHz;
    o.fminHz = f.fminHz;
    o.fmaxHz = f.fmaxHz;
    o.points = f.points;
    o.amplitudeNm = peak; // the PID output's units here
    o.timing = timing;
    auto streams = planFrfTest(o);
    if (!streams)
        return streams.error();
    plan.streams = std::make_shared<const FrfPlan>(std::move(streams).value());
    const double motion = plan.streams->durationS();
    if (motion > HalDrive::kMaxTestS)
        return makeError(ErrorCode::OutOfRange,
                         "FRF test of " + num(motion) + " s refused: at most " + num(HalDrive::kMaxTestS) +
                             " s (fewer points, a higher fmin or shorter settle and measure times)");
    return plan;
}

Result<FrfMeasurement> evaluateHalStreams(const HalFrfPlan& plan, const HalRecord& record)
{
    if (!plan.streams)
        return makeError(ErrorCode::Internal, "evaluateHalStreams without a multi-sweep or PRBS plan");
    const std::size_t n = plan.totalSamples();
    const bool openLoop = plan.quantity == FrfQuantity::OpenLoop;
    std::vector<double> minusPid;
    if (openLoop) {
        minusPid.resize(n);
        for (std::size_t i = 0; i < n; ++i)
            minusPid[i] = -record.columns[PidOutput][i];
    }
    const std::span<const double> u(record.columns[DriveInput].data(), n);
    const std::span<const double> y =
        openLoop ? std::span<const double>(minusPid) : std::span<const double>(record.columns[Feedback].data(), n);
    auto evaluated = evaluateFrfSignals(*plan.streams, u, y, "drive_input", openLoop ? "-pid_output" : "feedback");
    if (!evaluated)
        return evaluated.error();
    FrfMeasurement out = std::move(evaluated).value();
    auto& md = out.frf.metadata;
    md.set(model::meta::kSettleS, plan.streams->timing.settleS);
    md.set(model::meta::kMinMeasureS, plan.streams->timing.minMeasureS);
    if (plan.method == FrfMethod::MultiSweep) {
        md.set(model::meta::kSettlePeriods, plan.streams->timing.settlePeriods);
        out.sweep.metadata.set(model::meta::kFsHz, plan.fsHz);
        out.sweep.metadata.set(model::meta::kQuantity, std::string(frfQuantityMetadataName(
                                                           openLoop ? FrfQuantity::OpenLoop : FrfQuantity::Plant)));
    }
    return out;
}

Result<HalMovePlan> planHalMove(const TestRequest& r, const HalAxis& axis)
{
    if (r.type() != TestType::Jog)
        return makeError(ErrorCode::BadInput,
                         std::string("hal: runs FRF, jog and step tests only (not ") + testTypeName(r.type()) + ")");
    const auto& j = r.jog();
    if (!j.returnToStart)
        return makeError(ErrorCode::BadInput, "hal: moves out and back only (--back): AxisTune's offset to the "
                                              "command must end at zero before it hands the command back");
    if (!std::isfinite(j.distance) || j.distance == 0.0)
        return makeError(ErrorCode::OutOfRange, "jog distance must be a non-zero number in the command's units");
    if (!std::isfinite(j.velocity) || !(j.velocity > 0.0))
        return makeError(ErrorCode::OutOfRange, "jog velocity must be positive (command units/s)");
    if (!std::isfinite(j.acceleration) || !(j.acceleration > 0.0))
        return makeError(ErrorCode::OutOfRange, "jog acceleration must be positive (command units/s²)");
    if (!std::isfinite(j.jerk) || j.jerk < 0.0)
        return makeError(ErrorCode::OutOfRange, "jog jerk must not be negative (0: a trapezoid)");
    if (!std::isfinite(j.dwellS) || j.dwellS < 0.0)
        return makeError(ErrorCode::OutOfRange, "jog dwell must not be negative");
    if (auto st = checkCommandLinked(axis, "move"); !st)
        return st.error();
    sim::MotionProfile profile;
    profile.dwell(j.dwellS);
    profile.move(j.distance, j.velocity, j.acceleration, j.jerk);
    profile.move(-j.distance, j.velocity, j.acceleration, j.jerk);
    profile.dwell(j.dwellS);
    HalMovePlan plan;
    plan.axis = axis;
    plan.type = TestType::Jog;
    plan.fsHz = 1e9 / static_cast<double>(axis.periodNs);
    plan.distance = j.distance;
    plan.velocity = j.velocity;
    plan.returnRate = j.velocity;
    if (profile.duration() > HalDrive::kMaxTestS)
        return makeError(ErrorCode::OutOfRange, "jog of " + num(profile.duration()) + " s refused: at most " +
                                                    num(HalDrive::kMaxTestS) + " s");
    const auto n = static_cast<std::size_t>(std::ceil(profile.duration() * plan.fsHz)) + 1;
    plan.offset.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double x = profile.at(static_cast<double>(i) / plan.fsHz).position;
        // The profile's own rounding must not end the move a few ulps away from zero, nor exceed the distance.
        plan.offset[i] = std::abs(x) < 1e-12 * std::abs(j.distance) ? 0.0 : x;
    }
    plan.offset.back() = 0.0;
    return plan;
}

Result<HalMovePlan> planHalStep(const TestRequest& r, const HalAxis& axis, double followingErrorTrip)
{
    if (r.type() != TestType::Step)
        return makeError(ErrorCode::Internal, "planHalStep: a step request only");
    const auto& s = r.step();
    if (s.velocityRadS != 0.0)
        return makeError(ErrorCode::BadInput, "hal: steps the pid's position command (in its units), not the motor "
                                              "velocity: a velocity step request is refused");
    if (!std::isfinite(s.position) || s.position == 0.0)
        return makeError(ErrorCode::OutOfRange,
                         "step must be a non-zero number: on hal: a position step of the command, in its units");
    if (!std::isfinite(s.recordS) || !(s.recordS > 0.0))
        return makeError(ErrorCode::OutOfRange, "step duration must be positive (how long the step is held) [s]");
    if (auto st = checkCommandLinked(axis, "step"); !st)
        return st.error();
    // Right after the step the following error equals it: a step the trip would stop at once, or nearly, is refused.
    if (!(followingErrorTrip > 0.0))
        return makeError(ErrorCode::Safety, "step refused: " + axis.pid +
                                                ".maxerror is 0 and the joint has no FERROR: the following error of a "
                                                "step equals the step, and nothing would bound it");
    if (std::abs(s.position) > 0.5 * followingErrorTrip)
        return makeError(ErrorCode::OutOfRange,
                         "step of " + num(s.position) +
                             " refused: at most half of the "
                             "following-error limit (" +
                             num(followingErrorTrip) + ", the smaller of " + axis.pid +
                             ".maxerror and the joint's FERROR): " + num(0.5 * followingErrorTrip));
    HalMovePlan plan;
    plan.axis = axis;
    plan.type = TestType::Step;
    plan.fsHz = 1e9 / static_cast<double>(axis.periodNs);
    plan.distance = s.position;
    plan.returnRate = std::abs(s.position) / kHalStepReturnS;
    const double total = 2.1 * s.recordS;
    if (total > HalDrive::kMaxTestS)
        return makeError(ErrorCode::OutOfRange, "step of " + num(total) +
                                                    " s (a tenth of the duration at rest, the "
                                                    "step held, the step back held) refused: at "
                                                    "most " +
                                                    num(HalDrive::kMaxTestS) + " s");
    const auto hold = std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(s.recordS * plan.fsHz)));
    const auto rest = std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(0.1 * s.recordS * plan.fsHz)));
    plan.stepAt = rest;
    plan.backAt = rest + hold;
    plan.offset.assign(rest + 2 * hold, 0.0);
    std::fill(plan.offset.begin() + static_cast<std::ptrdiff_t>(plan.stepAt),
              plan.offset.begin() + static_cast<std::ptrdiff_t>(plan.backAt), s.position);
    return plan;
}

Result<TestPlan> HalDrive::planExternalJog(const TestRequest& request, double recordS) const
{
    if (request.type() != TestType::Jog)
        return makeError(ErrorCode::Internal, "planExternalJog: a jog");
    if (!(recordS > 0.0) || !(recordS <= kMaxTestS))
        return makeError(ErrorCode::OutOfRange, "a recorded move of " + num(recordS) + " s: at most " +
                                                    num(kMaxTestS) + " s");
    auto move = movePlan(request);
    if (!move)
        return move.error();
    TestPlan p;
    p.traceRateHz = move->fsHz;
    p.recordSamples = static_cast<std::size_t>(std::ceil(recordS * move->fsHz)) + 1;
    p.motionTimeS = static_cast<double>(p.recordSamples) / move->fsHz;
    return p;
}

} // namespace axistune::device::hal

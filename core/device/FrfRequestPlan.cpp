// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/FrfRequestPlan.h"

#include "core/model/Constants.h"

#include <cmath>

namespace axistune::device {

namespace {

Result<double> positive(const model::ParameterValues& v, const std::string& key)
{
    const auto it = v.find(key);
    if (it == v.end())
        return makeError(ErrorCode::BadInput, "FRF plan: parameter '" + key + "' is missing");
    if (!std::isfinite(it->second) || !(it->second > 0.0))
        return makeError(ErrorCode::BadInput, "FRF plan: parameter '" + key + "' must be positive");
    return it->second;
}

} // namespace

Result<AxisClock> axisClockFromParameters(const model::ParameterValues& values, int traceDividerOverride)
{
    auto h = positive(values, "current.period");
    if (!h)
        return h.error();
    auto vp = positive(values, "velocity.period");
    if (!vp)
        return vp.error();
    const double ratio = *vp / *h;
    const auto n = std::llround(ratio);
    // The simulator's own rule (AxisSimulator: integerRatio): a whole number of current ticks.
    if (n < 1 || std::abs(ratio - static_cast<double>(n)) > 1e-6 * ratio)
        return makeError(ErrorCode::BadInput, "FRF plan: velocity.period / current.period must be a whole number");
    AxisClock c;
    c.currentPeriodS = *h;
    c.ticksPerVelocity = static_cast<int>(n);
    if (traceDividerOverride > 0) {
        c.traceDivider = traceDividerOverride;
    } else {
        auto d = positive(values, "trace.divider");
        if (!d)
            return d.error();
        c.traceDivider = static_cast<int>(std::llround(*d));
    }
    return c;
}

std::span<const std::string> frfPlanParameterKeys()
{
    static const std::string keys[] = {"motor.rated_current", "motor.torque_constant", "velocity.inertia",
                                       "velocity.kp",         "velocity.ki",           "drive.max_voltage",
                                       "current.period",      "velocity.period",       "trace.divider"};
    return keys;
}

double FrfRequestPlan::durationS() const
{
    return multisine ? multisine->durationS() : streams ? streams->durationS() : 0.0;
}

Result<FrfRequestPlan> planFrfRequest(const TestRequest& request, const model::ParameterValues& v,
                                      const AxisClock& clock)
{
    auto get = [&v](const char* k) {
        const auto it = v.find(k);
        return it == v.end() ? std::nan("") : it->second;
    };
    const double rated = model::ratedTorqueNm(get("motor.rated_current"), get("motor.torque_constant"));
    if (!(rated > 0.0) || !std::isfinite(rated))
        return makeError(ErrorCode::BadInput,
                         "FRF plan: the rated torque (motor.rated_current × motor.torque_constant) "
                         "must be positive");
    if (auto st = checkRatedTorqueFrfRequest(request); !st)
        return st.error();
    const FrfTest& r = request.frf();
    if (!std::isfinite(r.amplitudePct) || !(r.amplitudePct > 0.0))
        return makeError(ErrorCode::OutOfRange, "FRF amplitude must be a positive % of the rated torque");
    if (!(r.settleS >= 0.0) || !(r.minMeasureS >= 0.0))
        return makeError(ErrorCode::OutOfRange, "FRF settle and measure times must not be negative");
    LoopTiming timing;
    if (auto t = loopTimingFromParameters(v); t)
        timing = *t;
    else if (r.settleS <= 0.0 || r.minMeasureS <= 0.0)
        return t.error();
    if (r.settleS > 0.0) {
        timing.settleS = r.settleS; // the caller's settle time replaces both rules
        timing.settlePeriods = 0.0;
    }
    if (r.minMeasureS > 0.0)
        timing.minMeasureS = r.minMeasureS;
    const double amplitudeNm = model::torqueNmFromRatedPct(r.amplitudePct, rated);
    const double fsHz = 1.0 / clock.tracePeriodS();
    FrfRequestPlan out;
    if (r.method == FrfMethod::Multisine) {
        MultisinePlanOptions po;
        po.fsHz = fsHz;
        po.ticksPerSample = clock.ticksPerVelocity * clock.traceDivider;
        po.currentPeriodS = clock.currentPeriodS;
        po.ticksPerVelocity = clock.ticksPerVelocity;
        po.bands = multisineBandsOf(r);
        po.shape = r.multisineShape;
        po.crestThrough = r.multisineCrestThrough;
        po.phases = r.multisinePhases;
        po.peakNm = amplitudeNm; // the limit in % of rated torque holds at the multisine's peak
        po.timing = timing;
        po.periods = r.multisinePeriods;
        po.voltageLimitV = get("drive.max_voltage");
        auto plan = planMultisineTest(po);
        if (!plan)
            return plan.error();
        out.multisine = std::make_shared<const MultisinePlan>(std::move(plan).value());
        return out;
    }
    FrfPlanOptions po;
    po.method = r.method;
    po.fsHz = fsHz;
    po.fminHz = r.fminHz;
    po.fmaxHz = r.fmaxHz;
    po.points = r.points;
    po.amplitudeNm = amplitudeNm;
    po.timing = timing;
    po.voltageLimitV = get("drive.max_voltage");
    auto plan = planFrfTest(po);
    if (!plan)
        return plan.error();
    out.streams = std::make_shared<const FrfPlan>(std::move(plan).value());
    return out;
}

Result<FrfMeasurement> evaluateFrfRequestTrace(const FrfRequestPlan& plan, const model::Capture& trace)
{
    if (plan.multisine)
        return evaluateMultisineTrace(*plan.multisine, trace);
    if (plan.streams)
        return evaluateFrfTrace(*plan.streams, trace);
    return makeError(ErrorCode::Internal, "FRF evaluation without a plan");
}

} // namespace axistune::device

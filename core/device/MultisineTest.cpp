// SPDX-License-Identifier: GPL-3.0-or-later
// Three-phase multisine FRF test: the multi-sweep method of spec/current-loop-and-multisweep-frf.md
// §3.5 for every line of a multisine at once (issue 11, docs/multisine.md), injected at the
// current-loop rate (§3.6) into the closed velocity loop (§3.2, eq. 3.1), corrected by the
// injection-hold factor (docs/frequency-response-sim.md "Injection hold").
#include "core/device/MultisineTest.h"

#include "core/dsp/InjectionHold.h"
#include "core/model/MetadataKeys.h"

#include <algorithm>
#include <cmath>

namespace axistune::device {

std::vector<dsp::MultisineBand> multisineBandsOf(const FrfTest& r)
{
    if (!r.multisineBands.empty())
        return r.multisineBands;
    const double spacing = r.multisineSpacingHz > 0.0 ? r.multisineSpacingHz : 0.5 * r.fminHz;
    return {{r.fminHz, r.fmaxHz, spacing}};
}

Result<MultisinePlan> planMultisineTest(const MultisinePlanOptions& o)
{
    if (!std::isfinite(o.peakNm) || !(o.peakNm > 0.0))
        return makeError(ErrorCode::OutOfRange, "multisine test: the peak amplitude must be positive");
    if (o.periods < 0 || o.periods > kMaxMultisinePeriods)
        return makeError(ErrorCode::OutOfRange, "multisine test: periods must lie in [1, " +
                                                    std::to_string(kMaxMultisinePeriods) +
                                                    "] (0: from the loop's dynamics)");
    if (!(o.timing.settleS >= 0.0) || o.timing.settleS > 10.0 || !(o.timing.minMeasureS >= 0.0) ||
        o.timing.minMeasureS > 100.0)
        return makeError(ErrorCode::OutOfRange, "multisine test: settle time must lie in [0, 10] s");
    dsp::MultisineDesignOptions d;
    d.fsHz = o.fsHz;
    d.ticksPerSample = o.ticksPerSample;
    d.bands = o.bands;
    d.shape = o.shape;
    d.crestThrough = o.crestThrough;
    d.phases = o.phases;
    d.peak = o.peakNm;
    auto design = dsp::designMultisine(d);
    if (!design)
        return design.error();
    MultisinePlan plan;
    plan.design = std::move(design).value();
    plan.timing = o.timing;
    plan.currentPeriodS = o.currentPeriodS;
    plan.ticksPerVelocity = o.ticksPerVelocity;
    plan.voltageLimitV = o.voltageLimitV;
    plan.maxRelativeNoise = o.maxRelativeNoise;
    const double lowest = plan.design.freqHz.front();
    const double settle = std::max(o.timing.settleS, std::min(o.timing.settlePeriods / lowest, o.timing.maxSettleS));
    plan.settleSamples = static_cast<std::size_t>(std::ceil(settle * o.fsHz - 1e-9));
    const double periodS = static_cast<double>(plan.design.periodSamples()) / o.fsHz;
    plan.periods = o.periods > 0 ? static_cast<std::size_t>(o.periods)
                                 : static_cast<std::size_t>(std::max<double>(
                                       kMinMultisinePeriods, std::ceil(o.timing.minMeasureS / periodS - 1e-9)));
    plan.totalSamples = plan.settleSamples + plan.periods * plan.design.periodSamples();
    return plan;
}

double multisineExcitation(const MultisinePlan& plan, std::int64_t tick)
{
    const auto end = static_cast<std::int64_t>(plan.totalSamples) * plan.design.ticksPerSample;
    if (tick < 0 || tick >= end)
        return 0.0;
    return plan.design.valueAtTick(tick);
}

Result<FrfMeasurement> evaluateMultisineTrace(const MultisinePlan& plan, const model::Capture& trace)
{
    const auto* d = trace.channel("injection_Nm");
    const auto* tc = trace.channel("torque_cmd_Nm");
    if (!d || !tc)
        return makeError(ErrorCode::BadInput, "multisine trace: channels injection_Nm and torque_cmd_Nm are required");
    if (d->data.size() < plan.totalSamples || tc->data.size() < plan.totalSamples)
        return makeError(ErrorCode::BadInput, "multisine trace: " + std::to_string(d->data.size()) +
                                                  " samples, the plan needs " + std::to_string(plan.totalSamples));
    const std::size_t first = plan.settleSamples, n = plan.totalSamples - first;
    const std::span<const double> x(d->data.data() + first, n);
    std::vector<double> y(n);
    for (std::size_t i = 0; i < n; ++i)
        y[i] = -tc->data[first + i];
    dsp::MultisineAnalysisOptions ao;
    ao.maxRelativeNoise = plan.maxRelativeNoise;
    auto a = dsp::analyzeMultisine(plan.design, x, y, plan.periods, ao);
    if (!a)
        return a.error();
    FrfMeasurement out;
    out.frf = std::move(a->frf);
    out.relativeNoise = std::move(a->stats.relativeNoise);
    out.motionTimeS = plan.durationS();
    if (plan.currentPeriodS > 0.0) {
        if (auto st = dsp::correctInjectionHold(out.frf, plan.currentPeriodS, plan.ticksPerVelocity); !st)
            return st.error();
    }
    // A multisine spreads a nonlinearity over every line: a record in which the current loop ran
    // into its voltage limit is not a linear measurement anywhere.
    std::size_t clamped = 0;
    const auto* volt = trace.channel("voltage_V");
    if (volt && plan.voltageLimitV > 0.0 && volt->data.size() >= plan.totalSamples) {
        for (std::size_t i = first; i < plan.totalSamples; ++i)
            clamped += std::abs(volt->data[i]) >= 0.999 * plan.voltageLimitV ? 1 : 0;
        if (clamped > 0)
            std::fill(out.frf.valid.begin(), out.frf.valid.end(), false);
    }
    auto& md = out.frf.metadata;
    md.set(model::meta::kVoltageClampedSamples, clamped);
    md.set(model::meta::kInput, "injection_Nm");
    md.set(model::meta::kOutput, "-torque_cmd_Nm");
    md.set(model::meta::kMeasurement, "complementary"); // T = PC/(1+PC), dsp::LoopMeasurement::Complementary
    md.set(model::meta::kAmplitudeNm, plan.design.peak);
    md.set(model::meta::kPeakNm, plan.design.peak);
    md.set("rms_Nm", plan.design.rms);
    md.set(model::meta::kSettleS, static_cast<double>(plan.settleSamples) / plan.design.fsHz);
    md.set(model::meta::kPeriodS, static_cast<double>(plan.design.periodSamples()) / plan.design.fsHz);
    md.set(model::meta::kLoopTimeConstantS, plan.timing.timeConstantS);
    md.set(model::meta::kMotionTimeS, out.motionTimeS);
    return out;
}

bool voltageLimitReached(const model::Metadata& frfMetadata)
{
    if (!frfMetadata.contains(model::meta::kVoltageClampedSamples.name))
        return false;
    const auto clamped = frfMetadata.integer(model::meta::kVoltageClampedSamples);
    return !clamped.ok() || *clamped > 0;
}

} // namespace axistune::device

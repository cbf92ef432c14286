// SPDX-License-Identifier: GPL-3.0-or-later
// FRF test planning and evaluation: velocity-loop FRF from a torque disturbance injected at the
// current-loop rate, spec/current-loop-and-multisweep-frf.md §3.2 (eq. 3.1), §3.5 (three-phase
// multi-sweep, implementation form), §3.6 (alias-free ranges, excitation at the current-loop rate),
// §4.3 (wizard C). Settle and window from the closed velocity loop's slowest pole; the injection-hold
// correction G = N / Σ_{m<N} e^{−jωmh} (dsp::injectionHoldFactor) turns −T_c/d into T = PC/(1+PC)
// (docs/frequency-response-sim.md, "Injection hold").
#include "core/device/FrfTest.h"

#include "core/dsp/Excitation.h"
#include "core/dsp/InjectionHold.h"
#include "core/dsp/Welch.h"
#include "core/model/Constants.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>

namespace axistune::device {
namespace {

std::string num(double v)
{
    return model::formatNumber(v, 10);
}

/// The frequency of the window grid nearest to f: f' = (p + c)·fs/M with M ≥ mMin, p ≥ pMin.
struct GridPoint {
    double freqHz = 0.0;
    std::size_t m = 0;
};
GridPoint nearestGridFrequency(double f, double fs, double c, std::size_t mMin, long pMin)
{
    GridPoint best;
    double bestErr = std::numeric_limits<double>::infinity();
    // Up to twice the minimum window, and far enough for p = pMin to reach f.
    const double mReach = (static_cast<double>(pMin) + c + 1.0) * fs / f;
    const std::size_t span = std::max<std::size_t>({2 * mMin, 64, static_cast<std::size_t>(std::min(mReach, 1e7))});
    for (std::size_t m = mMin; m <= mMin + span; ++m) {
        const double md = static_cast<double>(m);
        const long p = std::max(pMin, std::lround(f * md / fs - c));
        const double fp = (static_cast<double>(p) + c) * fs / md;
        if (!(fp < fs))
            continue;
        const double err = std::abs(fp - f) / f;
        if (err < bestErr) {
            bestErr = err;
            best = {fp, m};
        }
        if (err < 1e-3)
            break;  // the shortest window that lands within 0.1 % (else the best of the span)
    }
    return best;
}

std::vector<double> logSpaced(double f0, double f1, int n)
{
    if (n == 1)
        return {f0};
    std::vector<double> out;
    for (int i = 0; i < n; ++i)
        out.push_back(f0 * std::pow(f1 / f0, static_cast<double>(i) / (n - 1)));
    return out;
}

/// Current and velocity period: the plan's, else the trace metadata's.
struct HoldPeriods {
    double currentS = 0.0, velocityS = 0.0;
    int ticksPerVelocity = 1;   ///< N: current ticks per velocity period
    int velocityPerSample = 1;  ///< D: velocity periods per trace sample
};
Result<HoldPeriods> holdPeriods(const FrfPlan& plan, const model::Capture& trace)
{
    // A period the plan does not know comes from the trace; a missing one is refused below.
    HoldPeriods p{plan.currentPeriodS, plan.velocityPeriodS};
    for (auto [key, value] : {std::pair{model::meta::kCurrentPeriodS, &p.currentS},
                              std::pair{model::meta::kVelocityPeriodS, &p.velocityS}}) {
        if (*value > 0.0)
            continue;
        const auto v = trace.metadata.optionalNumber(key);
        if (!v)
            return makeError(ErrorCode::BadInput, "FRF trace: " + v.error().detail);
        *value = v->value_or(0.0);
    }
    if (!(p.currentS > 0.0) || !(p.velocityS > 0.0))
        return makeError(ErrorCode::BadInput, "FRF trace: the injection-hold correction needs the current and velocity "
                                              "periods (trace metadata current_period_s, velocity_period_s)");
    const double n = p.velocityS / p.currentS, d = 1.0 / (plan.fsHz * p.velocityS);
    p.ticksPerVelocity = static_cast<int>(std::lround(n));
    p.velocityPerSample = static_cast<int>(std::lround(d));
    if (p.ticksPerVelocity < 1 || std::abs(n - p.ticksPerVelocity) > 1e-6 * n || p.velocityPerSample < 1
        || std::abs(d - p.velocityPerSample) > 1e-6 * d)
        return makeError(ErrorCode::BadInput, "FRF trace: velocity period " + num(p.velocityS) + " s and trace period "
                                                  + num(1.0 / plan.fsHz) + " s must be integer multiples of the current period "
                                                  + num(p.currentS) + " s and of the velocity period");
    return p;
}

/// Sine streams: −T_c/d = G·T, G = injectionHoldFactor(f, h, N). PRBS: d is held over the trace
/// sample like a D-tap hold at the velocity rate, −T_c/d ≈ T/G(f, T_v, D) (exact T for D = 1).
Status correctHold(FrfMeasurement& out, const FrfPlan& plan, const HoldPeriods& p)
{
    auto& md = out.frf.metadata;
    if (plan.method != FrfMethod::Prbs) {
        if (auto st = dsp::correctInjectionHold(out.frf, p.currentS, p.ticksPerVelocity); !st)
            return st;
        for (const auto key : {model::meta::kInjectionHoldPeriodS.name, model::meta::kInjectionHoldTicks.name})
            if (const auto* v = md.find(key))
                out.sweep.metadata.set(key, *v);
        return Status::success();
    }
    for (std::size_t i = 0; i < out.frf.size() && p.velocityPerSample > 1; ++i) {
        const auto g = dsp::injectionHoldFactor(out.frf.freqHz[i], p.velocityS, p.velocityPerSample);
        if (std::isfinite(g.real()) && std::isfinite(g.imag()))
            out.frf.h[i] *= g;
        else
            out.frf.valid[i] = false;
    }
    md.set(model::meta::kInjectionHoldCorrected, "true");
    md.set("injection_hold", "prbs-held-per-trace-sample");
    md.set("injection_hold_velocity_periods", static_cast<double>(p.velocityPerSample));
    return Status::success();
}

}  // namespace

Status checkRatedTorqueFrfRequest(const TestRequest& request)
{
    const FrfTest& r = request.frf();
    if (r.quantity != FrfQuantity::Default)
        return makeError(ErrorCode::BadInput, "FRF quantity: this drive measures its own quantity only (the closed "
                                              "velocity loop); plant and open-loop quantities are hal:'s (--quantity)");
    if (r.amplitudePeak != 0.0)
        return makeError(ErrorCode::BadInput, "FRF amplitude: this drive takes it in % of rated torque (amplitudePct, "
                                              "--amplitude-pct), not as a peak in output units (amplitudePeak, --amplitude)");
    return Status::success();
}

const char* frfMethodName(FrfMethod m)
{
    switch (m) {
    case FrfMethod::MultiSweep: return "multisweep";
    case FrfMethod::Conventional: return "conventional";
    case FrfMethod::Prbs: return "prbs";
    case FrfMethod::Multisine: return "multisine";
    }
    return "?";
}

Result<LoopTiming> loopTimingFromParameters(const model::ParameterValues& v, double settleTc, double measureTc,
                                            double settlePeriods)
{
    auto get = [&v](const char* k) {
        auto it = v.find(k);
        return it == v.end() ? 0.0 : it->second;
    };
    const double j = get("velocity.inertia"), kp = get("velocity.kp"), ki = get("velocity.ki");
    if (!(j > 0.0) || !(kp > 0.0)) {
        return makeError(ErrorCode::BadInput, "the settle time follows from velocity.inertia, velocity.kp and velocity.ki: "
                                              "velocity.inertia and velocity.kp must be positive (or give the settle time)");
    }
    double tau = 0.0;
    const double disc = kp * kp - 4.0 * j * ki;
    if (ki <= 0.0)
        tau = j / kp;
    else if (disc >= 0.0)
        tau = 2.0 * j / (kp - std::sqrt(disc));  // the slow real pole (−k_p + √disc)/(2J)
    else
        tau = 2.0 * j / kp;  // complex pair, real part −k_p/(2J)
    LoopTiming t;
    t.timeConstantS = tau;
    t.settleS = settleTc * tau;
    t.settlePeriods = settlePeriods;
    t.minMeasureS = measureTc * tau;
    return t;
}

Result<FrfPlan> planFrfTest(const FrfPlanOptions& o)
{
    if (!(o.fsHz > 0.0))
        return makeError(ErrorCode::BadInput, "FRF test: trace rate must be positive");
    if (!std::isfinite(o.amplitudeNm) || !(o.amplitudeNm > 0.0))
        return makeError(ErrorCode::OutOfRange, "FRF test: amplitude must be positive");
    if (!std::isfinite(o.fminHz) || !(o.fminHz > 0.0))
        return makeError(ErrorCode::OutOfRange, "FRF test: fmin must be positive (got " + num(o.fminHz) + " Hz)");
    if (!std::isfinite(o.fmaxHz) || o.fmaxHz < o.fminHz)
        return makeError(ErrorCode::OutOfRange, "FRF test: fmax must not be below fmin");
    const double fTop = o.method == FrfMethod::Prbs ? 0.5 * o.fsHz : o.fsHz;
    if (!(o.fmaxHz < fTop) && !(o.method == FrfMethod::Prbs && o.fmaxHz == fTop)) {
        return makeError(ErrorCode::OutOfRange, "FRF test: fmax " + num(o.fmaxHz) + " Hz must lie below "
                                                    + num(fTop) + " Hz (" + (o.method == FrfMethod::Prbs ? "fs/2" : "fs")
                                                    + " at the trace rate " + num(o.fsHz) + " Hz)");
    }
    if (o.points < 1 || (o.points == 1 && o.fmaxHz != o.fminHz) || o.points > 10000)
        return makeError(ErrorCode::OutOfRange, "FRF test: points must lie in [2, 10000] (1 only when fmin = fmax)");
    if (!(o.timing.settleS >= 0.0) || !(o.timing.minMeasureS >= 0.0) || o.timing.settleS > 10.0 || o.timing.minMeasureS > 10.0
        || !(o.timing.settlePeriods >= 0.0) || !(o.timing.maxSettleS >= 0.0))
        return makeError(ErrorCode::OutOfRange, "FRF test: settle and measure times must lie in [0, 10] s");

    FrfPlan plan;
    plan.method = o.method;
    plan.fsHz = o.fsHz;
    plan.amplitudeNm = o.amplitudeNm;
    plan.timing = o.timing;
    plan.fminHz = o.fminHz;
    plan.fmaxHz = o.fmaxHz;
    plan.points = o.points;
    plan.voltageLimitV = o.voltageLimitV;
    const auto settle = static_cast<std::size_t>(std::ceil(o.timing.settleS * o.fsHz - 1e-9));

    if (o.method == FrfMethod::Prbs) {
        std::size_t n = 64;
        while (n < 65536 && static_cast<double>(n) < o.fsHz / o.fminHz)
            n *= 2;
        unsigned order = 0;
        while ((std::size_t{1} << order) < n)
            ++order;
        const std::size_t record = 8 * n;  // 15 Hann segments with half overlap
        dsp::PrbsOptions po;
        po.order = order;
        po.amplitude = o.amplitudeNm;
        po.amplitudeLimit = o.amplitudeNm;
        po.periods = (settle + record) / (n - 1) + 1;
        auto seq = dsp::makePrbs(po);
        if (!seq)
            return seq.error();
        plan.prbs.assign(seq->begin(), seq->begin() + static_cast<std::ptrdiff_t>(settle + record));
        plan.prbsStart = static_cast<std::int64_t>(settle);
        plan.nperseg = n;
        plan.totalSamples = settle + record;
        return plan;
    }

    const bool multi = o.method == FrfMethod::MultiSweep;
    const double c = multi ? 1.0 / 3.0 : 0.0;
    const std::size_t windows = multi ? 3 : 1;
    const auto mMin = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::ceil(o.timing.minMeasureS * o.fsHz / static_cast<double>(windows) - 1e-9)));
    std::int64_t cursor = 0;
    double last = 0.0;
    for (double target : logSpaced(o.fminHz, o.fmaxHz, o.points)) {
        const GridPoint g = nearestGridFrequency(target, o.fsHz, c, mMin, multi ? 0 : 1);
        if (g.m == 0 || g.freqHz <= last)
            continue;  // two targets on one grid frequency: measured once
        last = g.freqHz;
        const double settleF = std::max(o.timing.settleS, std::min(o.timing.settlePeriods / g.freqHz, o.timing.maxSettleS));
        const auto settleSamples = static_cast<std::size_t>(std::ceil(settleF * o.fsHz - 1e-9));
        for (std::size_t w = 0; w < windows; ++w) {
            FrfSegment s;
            s.freqHz = g.freqHz;
            s.phaseOffsetDeg = dsp::kMultiSweepOffsetsDeg[w];
            s.settleSamples = w == 0 ? settleSamples : 0;
            s.windowStart = cursor + static_cast<std::int64_t>(s.settleSamples);
            s.measureSamples = g.m;
            cursor = s.windowStart + static_cast<std::int64_t>(g.m);
            plan.segments.push_back(s);
        }
    }
    plan.totalSamples = static_cast<std::size_t>(cursor);
    return plan;
}

double frfExcitation(const FrfPlan& plan, double s)
{
    if (s < 0.0 || s >= static_cast<double>(plan.totalSamples))
        return 0.0;
    if (plan.method == FrfMethod::Prbs) {
        const auto i = static_cast<std::size_t>(std::floor(s));
        return i < plan.prbs.size() ? plan.prbs[i] : 0.0;
    }
    // The last segment whose window ends after s.
    auto it = std::upper_bound(plan.segments.begin(), plan.segments.end(), s, [](double x, const FrfSegment& seg) {
        return x < static_cast<double>(seg.windowStart) + static_cast<double>(seg.measureSamples);
    });
    if (it == plan.segments.end())
        return 0.0;
    const double cycles = std::fmod(it->freqHz * (s - static_cast<double>(it->windowStart)) / plan.fsHz, 1.0);
    return plan.amplitudeNm * std::sin(model::kTwoPi * cycles + it->phaseOffsetDeg * model::kRadPerDeg);
}

Result<FrfMeasurement> evaluateFrfSignals(const FrfPlan& plan, std::span<const double> x, std::span<const double> y,
                                          const std::string& excitationName, const std::string& responseName)
{
    if (x.size() < plan.totalSamples || y.size() < plan.totalSamples)
        return makeError(ErrorCode::BadInput, "FRF trace: " + std::to_string(std::min(x.size(), y.size())) +
                                                  " samples, the plan needs " + std::to_string(plan.totalSamples));
    FrfMeasurement out;
    out.motionTimeS = plan.durationS();
    if (plan.method == FrfMethod::Prbs) {
        const auto first = static_cast<std::size_t>(plan.prbsStart);
        const std::size_t n = plan.totalSamples - first;
        dsp::WelchOptions wo;
        wo.nperseg = plan.nperseg;
        auto full = dsp::welchFrf(x.subspan(first, n), y.subspan(first, n), plan.fsHz, wo, dsp::FrfEstimator::H1);
        if (!full)
            return full.error();
        // Bins in [fmin, fmax], thinned to about `points` log-spaced frequencies.
        double next = plan.fminHz;
        const double step = plan.points > 1 ? std::pow(plan.fmaxHz / plan.fminHz, 1.0 / (plan.points - 1)) : 2.0;
        for (std::size_t i = 0; i < full->size(); ++i) {
            const double f = full->freqHz[i];
            if (f < plan.fminHz * (1 - 1e-12) || f > plan.fmaxHz * (1 + 1e-12) || f < next * (1 - 1e-12))
                continue;
            out.frf.push(f, full->h[i], full->coherence[i], full->valid[i] && f < 0.5 * plan.fsHz);
            next = f * step;
        }
        out.frf.metadata.set(model::meta::kMethod, "prbs");
        out.frf.metadata.set(model::meta::kFsHz, plan.fsHz);
        out.frf.metadata.set(model::meta::kNperseg, plan.nperseg);
        return out;
    }
    dsp::SweepRecording& rec = out.sweep;
    rec.fsHz = plan.fsHz;
    rec.amplitude = plan.amplitudeNm;
    rec.metadata.set("excitation", excitationName);
    rec.metadata.set("response", responseName);
    for (const auto& s : plan.segments) {
        dsp::SweepBlock b;
        b.freqHz = s.freqHz;
        b.phaseOffsetDeg = s.phaseOffsetDeg;
        const std::int64_t begin = s.windowStart - static_cast<std::int64_t>(s.settleSamples);
        const std::int64_t end = s.windowStart + static_cast<std::int64_t>(s.measureSamples);
        for (std::int64_t i = begin; i < end; ++i) {
            b.sample.push_back(i - s.windowStart);
            b.excitation.push_back(x[static_cast<std::size_t>(i)]);
            b.response.push_back(y[static_cast<std::size_t>(i)]);
        }
        rec.blocks.push_back(std::move(b));
    }
    auto frf = dsp::sineStreamFrf(rec);
    if (!frf)
        return frf.error();
    out.frf = std::move(frf).value();
    return out;
}

Result<FrfMeasurement> evaluateFrfTrace(const FrfPlan& plan, const model::Capture& trace)
{
    const auto* d = trace.channel("injection_Nm");
    const auto* tc = trace.channel("torque_cmd_Nm");
    if (!d || !tc)
        return makeError(ErrorCode::BadInput, "FRF trace: channels injection_Nm and torque_cmd_Nm are required");
    if (d->data.size() < plan.totalSamples)
        return makeError(ErrorCode::BadInput, "FRF trace: " + std::to_string(d->data.size()) +
                                                  " samples, the plan needs " + std::to_string(plan.totalSamples));
    auto periods = holdPeriods(plan, trace);
    if (!periods)
        return periods.error();
    // The response is −T_c (the velocity controller's output opposes the injected disturbance).
    std::vector<double> minusTc(tc->data.size());
    for (std::size_t i = 0; i < minusTc.size(); ++i)
        minusTc[i] = -tc->data[i];
    auto evaluated = evaluateFrfSignals(plan, d->data, minusTc, "injection_Nm", "-torque_cmd_Nm");
    if (!evaluated)
        return evaluated.error();
    FrfMeasurement out = std::move(evaluated).value();
    if (plan.method != FrfMethod::Prbs) {
        // A window in which the current loop ran into its voltage limit is not a linear measurement.
        const auto* volt = trace.channel("voltage_V");
        std::size_t clamped = 0;
        if (volt && plan.voltageLimitV > 0.0) {
            for (const auto& s : plan.segments) {
                bool hit = false;
                for (std::size_t i = 0; i < s.measureSamples && !hit; ++i)
                    hit = std::abs(volt->data[static_cast<std::size_t>(s.windowStart) + i]) >= 0.999 * plan.voltageLimitV;
                if (!hit)
                    continue;
                auto it = std::find(out.frf.freqHz.begin(), out.frf.freqHz.end(), s.freqHz);
                if (it != out.frf.freqHz.end()) {
                    auto idx = static_cast<std::size_t>(it - out.frf.freqHz.begin());
                    clamped += out.frf.valid[idx] ? 1 : 0;
                    out.frf.valid[idx] = false;
                }
            }
        }
        out.frf.metadata.set("voltage_clamped_points", static_cast<double>(clamped));
    }
    if (auto st = correctHold(out, plan, *periods); !st)
        return st.error();
    auto& md = out.frf.metadata;
    md.set(model::meta::kInput, "injection_Nm");
    md.set(model::meta::kOutput, "-torque_cmd_Nm");
    md.set(model::meta::kMeasurement, "complementary"); // T = PC/(1+PC), dsp::LoopMeasurement::Complementary
    md.set(model::meta::kAmplitudeNm, plan.amplitudeNm);
    md.set(model::meta::kSettleS, plan.timing.settleS);
    md.set(model::meta::kSettlePeriods, plan.timing.settlePeriods);
    md.set(model::meta::kMinMeasureS, plan.timing.minMeasureS);
    md.set(model::meta::kLoopTimeConstantS, plan.timing.timeConstantS);
    md.set(model::meta::kMotionTimeS, out.motionTimeS);
    for (const auto& [k, v] : md) {
        // The sweep keeps the raw −T_c and d: the correction is redone by whoever re-analyses it.
        if (k != model::meta::kMethod.name && k != model::meta::kFsHz.name &&
            k != model::meta::kInjectionHoldCorrected.name)
            out.sweep.metadata.set(k, v);
    }
    return out;
}

}  // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
// Simulated cut with chatter avoidance in the loop (AvoidanceCut.h).
#include "core/avoidance/AvoidanceCut.h"

#include "core/model/MetadataKeys.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <numeric>

namespace axistune::avoidance {

namespace {
using machining::AvoidanceSensor;

enum Probe { kFreq1, kFreq2, kSignal, kPower, kCost, kDobForce, kEscMean, kProbeCount };
const std::vector<std::string> kProbeNames = {
    "chatter_frequency_Hz", "chatter_frequency2_Hz", "avoid_signal", "avoid_power",
    "avoid_cost",           "dob_force_N",           "esc_mean_rpm"};
constexpr int kDobSubRate = 4; // the DOB runs at t_s/4 (encoder and current command rate), the KF/ESC at t_s
} // namespace

const char* methodName(Method m)
{
    switch (m) {
    case Method::None:
        return "none";
    case Method::Adaptive:
        return "adaptive";
    case Method::MultiMode:
        return "multimode";
    case Method::Esc:
        return "esc";
    }
    return "none";
}

Result<Method> parseMethod(const std::string& t)
{
    for (Method m : {Method::None, Method::Adaptive, Method::MultiMode, Method::Esc})
        if (t == methodName(m))
            return m;
    return makeError(ErrorCode::BadInput, "--avoid '" + t + "': must be none, adaptive, multimode or esc");
}

void applyMethodDefaults(AvoidanceCutOptions& o, Method method, AvoidanceSensor sensor)
{
    o.method = method;
    o.sensor = sensor;
    const bool dob = sensor == AvoidanceSensor::Dob;
    o.dob = machining::StageDobOptions{};
    if (method == Method::Adaptive)
        o.adaptive = dob ? machining::adaptiveTable4Dob() : machining::adaptiveTable3Accelerometer();
    o.toolModeBand = method == Method::Adaptive && dob;
    if (method == Method::MultiMode) {
        o.adaptive = machining::multiModeTable5Accelerometer();
        if (dob) {
            const auto t4 = machining::adaptiveTable4Dob();
            o.adaptive.samplePeriodS = t4.samplePeriodS;
            o.adaptive.thresholdPower = t4.thresholdPower;
            o.adaptive.highPassHz = t4.highPassHz;
            o.adaptive.lowPassHz = t4.lowPassHz;
        }
    }
    if (method == Method::Esc && dob) {
        o.dob.qCutoffHz = 2500.0; // Ch.6: DOB LPF 2500 Hz, G_F high-pass above 1000 Hz
        o.dob.bandHighHz = 0.0;
    }
}

Result<ToolModeBand> toolModeBand(const sim::MillingSetup& s)
{
    double best = 0.0;
    ToolModeBand b;
    for (const auto& m : s.modesY) {
        if (!(m.massKg > 0.0) || !(m.stiffnessNPerM > 0.0) || !(m.dampingNsPerM > 0.0))
            continue;
        const double wn = std::sqrt(m.stiffnessNPerM / m.massKg);
        const double peak = 1.0 / (m.dampingNsPerM * wn);
        if (peak > best) {
            best = peak;
            b.centreHz = wn / (2.0 * std::numbers::pi);
        }
    }
    if (!(best > 0.0))
        return makeError(ErrorCode::BadInput, "tool-mode band: the tool has no damped y mode");
    b.widthHz = s.teeth * s.spindleRpm / 60.0;
    if (!(b.widthHz > 0.0) || !(b.widthHz < 2.0 * b.centreHz))
        return makeError(ErrorCode::OutOfRange, "tool-mode band: the tooth-passing frequency " +
                                                    std::to_string(b.widthHz) + " Hz must lie in (0, 2 f_n)");
    return b;
}

Result<AvoidanceCutResult> runAvoidanceCut(const sim::AxisDefinition& axis, const AvoidanceCutOptions& o)
{
    sim::CutSimulationOptions cut = o.cut;
    const double rpm0 = cut.milling.spindleRpm;
    const bool dob = o.sensor == AvoidanceSensor::Dob;
    const double ts = o.method == Method::Esc ? o.esc.samplePeriodS : o.adaptive.samplePeriodS;
    std::shared_ptr<machining::AdaptiveAvoidance> adaptive;
    std::shared_ptr<machining::EscController> esc;
    std::shared_ptr<machining::StageDob> observer;
    AvoidanceCutResult result;
    if (o.method == Method::Adaptive || o.method == Method::MultiMode) {
        auto opt = o.adaptive;
        opt.multiMode = o.method == Method::MultiMode;
        if (o.toolModeBand && dob && opt.modeBandCentreHz == 0.0 && opt.modeBandWidthHz == 0.0) {
            auto b = toolModeBand(cut.milling);
            if (!b)
                return b.error();
            opt.modeBandCentreHz = b->centreHz;
            opt.modeBandWidthHz = b->widthHz;
        }
        auto a = machining::AdaptiveAvoidance::create(opt, cut.milling.teeth);
        if (!a)
            return a.error();
        adaptive = std::make_shared<machining::AdaptiveAvoidance>(std::move(a).value());
    } else if (o.method == Method::Esc) {
        auto opt = o.esc;
        opt.startS = o.esc.startS; // machine time
        auto e = machining::EscController::create(opt, rpm0);
        if (!e)
            return e.error();
        esc = std::make_shared<machining::EscController>(std::move(e).value());
        result.escDesign = esc->design();
        result.escIntegratorGain = esc->integratorGain();
    }
    if (o.method != Method::None && dob) {
        auto d = machining::StageDob::create(o.dob, ts / kDobSubRate);
        if (!d)
            return makeError(d.error().code, "DOB (runs at t_s/4): " + d.error().detail);
        observer = std::make_shared<machining::StageDob>(std::move(d).value());
    }
    if (o.method != Method::None) {
        cut.controllerPeriodS = dob ? ts / kDobSubRate : ts;
        cut.probeChannels = kProbeNames;
        auto count = std::make_shared<long long>(0);
        auto lastDob = std::make_shared<double>(0.0);
        cut.controller = [adaptive, esc, observer, count, lastDob](const sim::CutProbe& p,
                                                                   std::span<double> probes) -> double {
            double signal = p.toolAccelY;
            if (observer) {
                *lastDob = observer->step(p.tablePositionM, p.thrustCommandN);
                probes[kDobForce] = *lastDob;
                signal = *lastDob;
                if (++*count % kDobSubRate != 0)
                    return p.spindleCmdRpm;
            }
            if (adaptive) {
                const double cmd = adaptive->step(p.timeS, signal, p.spindleRpm);
                probes[kFreq1] = adaptive->chatterHz();
                probes[kFreq2] = adaptive->secondChatterHz();
                probes[kSignal] = adaptive->filtered();
                probes[kPower] = adaptive->filtered() * adaptive->filtered();
                probes[kCost] = adaptive->cost();
                return cmd;
            }
            const double y = signal * signal; // a_y² or F̂_x²
            const double cmd = esc->step(p.timeS, y);
            probes[kSignal] = signal;
            probes[kPower] = y;
            probes[kCost] = y;
            probes[kEscMean] = esc->meanRpm();
            return cmd;
        };
    }
    auto cap = sim::simulateCut(axis, cut);
    if (!cap)
        return cap.error();
    result.capture = std::move(cap).value();
    auto& md = result.capture.metadata;
    md.set(model::meta::kAvoid, methodName(o.method));
    if (o.method != Method::None) {
        md.set("avoid_sensor", dob ? "dob" : "accelerometer");
        md.set("avoid_sample_period_s", ts);
        md.set("avoid_signal_unit", dob ? "N" : "m/s^2");
        md.set(model::meta::kAvoidPowerUnit, dob ? "N^2" : "(m/s^2)^2");
    }
    if (adaptive) {
        result.steps = adaptive->steps();
        result.triggerTimeS = adaptive->triggerTimeS();
        md.set(model::meta::kAvoidCostUnit, "1 (J_chat)");
    }
    if (esc) {
        result.escBoundHits = esc->boundHits();
        md.set(model::meta::kAvoidCostUnit, md.textOr(model::meta::kAvoidPowerUnit, ""));
    }
    return result;
}

Result<double> channelRms(const model::Capture& cap, const std::string& channel, double t0, double t1)
{
    const auto* t = cap.channel("t_s");
    const auto* c = cap.channel(channel);
    if (!t || !c)
        return makeError(ErrorCode::NotFound, "capture has no channel '" + channel + "'");
    double s = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < t->data.size() && i < c->data.size(); ++i)
        if (t->data[i] >= t0 && t->data[i] <= t1) {
            s += c->data[i] * c->data[i];
            ++n;
        }
    if (n < 2)
        return makeError(ErrorCode::BadInput, "no samples of '" + channel + "' between the given times");
    return std::sqrt(s / static_cast<double>(n));
}

double peakMovingRms(const model::Capture& cap, const std::string& channel, double t0, double windowS)
{
    const auto* t = cap.channel("t_s");
    const auto* c = cap.channel(channel);
    if (!t || !c || t->data.size() < 4)
        return 0.0;
    const double dt = t->data[1] - t->data[0];
    const auto w = std::max<std::size_t>(2, static_cast<std::size_t>(std::llround(windowS / dt)));
    const std::size_t n = std::min(t->data.size(), c->data.size());
    double sum = 0.0, peak = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        sum += c->data[i] * c->data[i];
        if (i >= w)
            sum -= c->data[i - w] * c->data[i - w];
        if (i + 1 >= w && t->data[i + 1 - w] >= t0)
            peak = std::max(peak, std::sqrt(std::max(sum, 0.0) / static_cast<double>(w)));
    }
    return peak;
}

std::optional<double> settledFrom(const model::Capture& cap, const std::string& channel, double t0, double windowS,
                                  double limit)
{
    const auto* t = cap.channel("t_s");
    const auto* c = cap.channel(channel);
    if (!t || !c || t->data.size() < 4)
        return std::nullopt;
    const double dt = t->data[1] - t->data[0];
    const auto w = std::max<std::size_t>(2, static_cast<std::size_t>(std::llround(windowS / dt)));
    const std::size_t n = std::min(t->data.size(), c->data.size());
    if (n < w)
        return std::nullopt;
    // Walk back from the end: the last window whose RMS exceeds the limit ends the unsettled time.
    double sum = 0.0;
    for (std::size_t i = n - w; i < n; ++i)
        sum += c->data[i] * c->data[i];
    std::optional<double> from;
    for (std::size_t end = n; end >= w; --end) {
        const std::size_t begin = end - w;
        if (t->data[begin] < t0)
            break;
        if (std::sqrt(sum / static_cast<double>(w)) > limit)
            return from;
        from = t->data[begin];
        if (begin == 0)
            break;
        sum += c->data[begin - 1] * c->data[begin - 1] - c->data[end - 1] * c->data[end - 1];
    }
    return from;
}

} // namespace axistune::avoidance

// SPDX-License-Identifier: GPL-3.0-or-later
// The headless velocity/position-loop design (VelocityLoopDesign.h; docs/tuning.md "Velocity loop").
#include "core/tuning/VelocityLoopDesign.h"

#include "core/dsp/InjectionHold.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/model/Constants.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/tuning/TwoInertiaPrediction.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace axistune::tuning {

namespace {

using model::kTwoPi;

constexpr std::array<std::pair<LoopMeasurementKind, std::string_view>, 5> kNames{{
    {LoopMeasurementKind::Plant, "plant"},
    {LoopMeasurementKind::Open, "open"},
    {LoopMeasurementKind::Complementary, "complementary"},
    {LoopMeasurementKind::NegComplementary, "neg-complementary"},
    {LoopMeasurementKind::Sensitivity, "sensitivity"},
}};

bool positiveFinite(double v)
{
    return std::isfinite(v) && v > 0.0;
}

std::string num(double v, int significant)
{
    return model::formatNumber(v, significant);
}

} // namespace

std::string_view loopMeasurementName(LoopMeasurementKind kind)
{
    for (const auto& [k, n] : kNames)
        if (k == kind)
            return n;
    return "plant";
}

Result<LoopMeasurementKind> parseLoopMeasurement(std::string_view name)
{
    for (const auto& [k, n] : kNames)
        if (n == name)
            return k;
    return makeError(ErrorCode::BadInput,
                     "measurement '" + std::string(name) +
                         "' is none of plant, open, complementary, neg-complementary, sensitivity");
}

Result<LoopMeasurementKind> loopMeasurementOf(const dsp::FrequencyResponse& frf, LoopMeasurementKind absent)
{
    const auto name = frf.metadata.text(model::meta::kMeasurement);
    if (!name)
        return absent;
    return parseLoopMeasurement(*name);
}

Result<LoopForm> loopFormOf(LoopMeasurementKind kind)
{
    LoopForm f;
    switch (kind) {
    case LoopMeasurementKind::Open:
        f.open = true;
        return f;
    case LoopMeasurementKind::Complementary:
        f.closed = dsp::LoopMeasurement::Complementary;
        return f;
    case LoopMeasurementKind::NegComplementary:
        f.closed = dsp::LoopMeasurement::NegComplementary;
        return f;
    case LoopMeasurementKind::Sensitivity:
        f.closed = dsp::LoopMeasurement::Sensitivity;
        return f;
    case LoopMeasurementKind::Plant:
        break;
    }
    return makeError(ErrorCode::BadInput, "a plant FRF (torque -> velocity) is not a loop measurement; the notch "
                                          "analysis needs an open or closed loop");
}

Result<dsp::FrequencyResponse> plantFromMeasurement(const dsp::FrequencyResponse& measured, LoopMeasurementKind kind,
                                                    const VelocityPi& running, double velocityPeriodS,
                                                    double currentPeriodS)
{
    if (kind == LoopMeasurementKind::Plant)
        return measured;
    if (kind == LoopMeasurementKind::Complementary)
        return plantFromVelocityLoop(measured, running, velocityPeriodS, currentPeriodS);
    if (!(running.kpNmsPerRad >= 0.0) || !(running.kiNmPerRad >= 0.0) ||
        !(running.kpNmsPerRad + running.kiNmPerRad > 0.0))
        return makeError(ErrorCode::BadInput, "velocity PI: K_P and K_I must be >= 0 and not both 0");
    if (!positiveFinite(velocityPeriodS))
        return makeError(ErrorCode::BadInput, "the velocity period must be > 0");
    auto form = loopFormOf(kind);
    if (!form)
        return form.error();
    auto p = openLoopOf(measured, *form);
    divideByVelocityPi(p, running, velocityPeriodS);
    p.metadata.set(model::meta::kMeasurement, "plant");
    p.metadata.set(model::meta::kLoop, "plant-from-" + std::string(loopMeasurementName(kind)));
    return p;
}

Result<VelocityLoopDesign> designVelocityLoop(const VelocityLoopRequest& r)
{
    if (!positiveFinite(r.velocityPeriodS) || !positiveFinite(r.currentPeriodS))
        return makeError(ErrorCode::BadInput, "the velocity and current periods must be > 0");
    if (!(r.running.kpNmsPerRad >= 0.0) || !(r.running.kiNmPerRad >= 0.0) || !std::isfinite(r.running.kpNmsPerRad) ||
        !std::isfinite(r.running.kiNmPerRad))
        return makeError(ErrorCode::BadInput, "the running velocity PI must have finite K_P, K_I >= 0");
    if (!positiveFinite(r.stepRadS) || !positiveFinite(r.stepDurationS))
        return makeError(ErrorCode::BadInput, "the velocity step and its duration must be > 0");
    if (!positiveFinite(r.jmKgm2))
        return makeError(ErrorCode::BadInput, "the motor-side inertia J_m must be > 0 (the prediction model needs it)");
    VelocityLoopDesign d;
    // The prediction model: the fitted two-inertia model, else a rigid J_m; both with the loop's own delay of 1.5
    // velocity periods (the fitted delay is a measurement delay, §2.7).
    d.rigidModel = !r.model;
    if (r.model) {
        d.model = *r.model;
        d.model.jmKgm2 = r.jmKgm2;
    } else {
        // J_L tiny and K = C = 0: P_m = 1/(J_m s) (motorVelocityResponse), rigid in predictVelocityStep.
        d.model = {r.jmKgm2, 1e-9 * r.jmKgm2, 0.0, 0.0, 0.0};
    }
    d.model.delayS = kVelocityLoopDelayPeriods * r.velocityPeriodS;
    d.modelNote = d.rigidModel ? "rigid model J_m with a delay of 1.5 velocity periods"
                               : "two-inertia model with a delay of 1.5 velocity periods";
    // The plant of a measurement.
    if (r.method == VelocityLoopRequest::Method::Frf) {
        if (!r.measured)
            return makeError(ErrorCode::BadInput, "the margins rule needs a measured response");
        auto kind = loopMeasurementOf(*r.measured, r.absentKind);
        if (!kind)
            return kind.error();
        auto p = plantFromMeasurement(*r.measured, *kind, r.running, r.velocityPeriodS, r.currentPeriodS);
        if (!p)
            return p.error();
        d.plant = std::move(p).value();
    }
    // The proposal.
    if (r.method == VelocityLoopRequest::Method::Inertia) {
        if (!positiveFinite(r.omegaLHz) || !positiveFinite(r.k))
            return makeError(ErrorCode::BadInput, "the bandwidth omega_l/2pi and the gain factor k must be > 0");
        d.proposed = velocityPiFromInertia(r.jmKgm2, kTwoPi * r.omegaLHz, r.k);
        d.rule = "chapter 5 rule (corrected 5.13): K_P = k*sqrt(2)*omega_l*J_m = " + num(r.k, 4) + "*sqrt(2)*2pi*" +
                 num(r.omegaLHz, 4) + " Hz*" + num(r.jmKgm2, 5) + " kg*m^2, K_I = k*omega_l^2*J_m";
    } else {
        auto pi = velocityPiFromFrf(*d.plant, r.crossoverHz, r.phaseMarginDeg);
        if (!pi)
            return pi.error();
        d.proposed = *pi;
        d.rule = "margins on the measured plant: |C*P| = 1 and arg(C*P) = -180 deg + " +
                 model::formatFixed(r.phaseMarginDeg, 1) + " deg at " + model::formatFixed(r.crossoverHz, 1) + " Hz";
    }
    // The design grid: the plant's valid lines, else log-spaced 1 Hz … 2 kHz on the model.
    if (d.plant) {
        for (std::size_t i = 0; i < d.plant->size(); ++i)
            if (d.plant->valid[i]) {
                d.fHz.push_back(d.plant->freqHz[i]);
                d.plantH.push_back(d.plant->h[i]);
            }
    } else {
        for (int i = 0; i < 300; ++i) {
            d.fHz.push_back(std::pow(10.0, 3.3 * i / 299.0));
            d.plantH.push_back(motorVelocityResponse(d.model, d.fHz.back()));
        }
    }
    const std::size_t n = d.fHz.size();
    d.openLoopBefore.resize(n);
    d.openLoop.resize(n);
    d.closedLoop.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        d.openLoopBefore[i] = piResponse(r.running, d.fHz[i]) * d.plantH[i];
        d.openLoop[i] = piResponse(d.proposed, d.fHz[i]) * d.plantH[i];
        d.closedLoop[i] = d.openLoop[i] / (1.0 + d.openLoop[i]);
    }
    d.marginsBefore = loopMargins(d.fHz, d.openLoopBefore);
    d.marginsAfter = loopMargins(d.fHz, d.openLoop);
    // Position gain on the model with the proposed PI.
    d.position = positionGain(d.model, d.proposed, FeedbackMode::Semi, std::nullopt, true, kPositionGainMarginDb);
    d.positionRule = "position gain: recommended min(limit*10^(-" + model::formatFixed(kPositionGainMarginDb, 0) +
                     "/20), crossover*2pi/5) on the " + d.modelNote;
    // Step predictions before and after, on the model.
    d.stepTimeS = 0.01 * r.stepDurationS;
    if (auto pb = predictVelocityStep(d.model, r.running, r.velocityPeriodS, r.stepRadS, d.stepTimeS, r.stepDurationS))
        d.predictedBefore = std::move(pb).value();
    if (auto pa = predictVelocityStep(d.model, d.proposed, r.velocityPeriodS, r.stepRadS, d.stepTimeS, r.stepDurationS))
        d.predictedAfter = std::move(pa).value();
    return d;
}

model::ParameterValues velocityLoopParameters(const VelocityLoopDesign& design, bool withPositionGain)
{
    model::ParameterValues v{{"velocity.kp", design.proposed.kpNmsPerRad}, {"velocity.ki", design.proposed.kiNmPerRad}};
    if (withPositionGain && positiveFinite(design.position.recommendedPerS))
        v["position.kp"] = design.position.recommendedPerS;
    return v;
}

TwoInertiaProposal twoInertiaProposal(const TwoInertiaParams& p, SuppressionMode mode, double tauS, double bandwidthHz,
                                      double k)
{
    TwoInertiaProposal out;
    out.filter = suppressionFilterFromModel(p, mode, tauS);
    out.pi = velocityPiFromInertia(p.jmKgm2, kTwoPi * bandwidthHz, k);
    // The drive's filter (suppression.*) and the loop structure TI-3 needs for y_m ≈ y_m*: velocity feedforward and
    // the torque feedforward J·a* with J = J_m + J_L of the fit (spec §4.10).
    out.parameters = {{"velocity.kp", out.pi.kpNmsPerRad},
                      {"velocity.ki", out.pi.kiNmPerRad},
                      {"suppression.mode", mode == SuppressionMode::Full ? 2.0 : 1.0},
                      {"suppression.f0", out.filter.f0Hz},
                      {"suppression.zeta", out.filter.zeta},
                      {"position.velocity_ff", 1.0},
                      {"position.torque_ff", 1.0},
                      {"velocity.inertia", p.jmKgm2 + p.jlKgm2}};
    if (mode == SuppressionMode::Full)
        out.parameters["suppression.tau"] = out.filter.tauS;
    return out;
}

NormalisedStep normalisedStep(const model::Capture& cap, double step)
{
    NormalisedStep out;
    const auto* t = cap.channel("t_s");
    const auto* cmd = cap.channel("velocity_cmd_rad_s");
    const auto* v = cap.channel("motor_vel_rad_s");
    if (!t || !cmd || !v || step == 0.0 || !std::isfinite(step))
        return out;
    const std::size_t len = std::min({t->data.size(), cmd->data.size(), v->data.size()});
    std::size_t k0 = 0;
    while (k0 < len && std::abs(cmd->data[k0]) < 0.5 * std::abs(step))
        ++k0;
    if (k0 >= len)
        return out;
    for (std::size_t k = k0 > 0 ? k0 - 1 : 0; k < len; ++k) {
        out.tMs.push_back((t->data[k] - t->data[k0]) * 1e3);
        out.y.push_back(v->data[k] / step);
    }
    return out;
}

NormalisedStep normalisedStep(const VelocityStepPrediction& p, double step, double stepTimeS)
{
    NormalisedStep out;
    if (step == 0.0 || !std::isfinite(step))
        return out;
    for (std::size_t k = 0; k < p.tS.size() && k < p.motorVelRadS.size(); ++k) {
        out.tMs.push_back((p.tS[k] - stepTimeS) * 1e3);
        out.y.push_back(p.motorVelRadS[k] / step);
    }
    return out;
}

std::optional<double> stepOvershootPct(const NormalisedStep& s)
{
    if (s.y.empty())
        return std::nullopt;
    double m = 0.0;
    for (std::size_t k = 0; k < s.y.size(); ++k)
        if (s.tMs[k] >= 0.0)
            m = std::max(m, s.y[k]);
    return std::max(0.0, m - 1.0) * 100.0;
}

double backEmfFromTorqueConstant(double ktNmPerA)
{
    return ktNmPerA / 1.5;
}

std::vector<std::string> motorParameterKeys()
{
    return {"motor.max_current",     "drive.max_voltage", "motor.rated_current",
            "motor.torque_constant", "current.period",    "current.dead_time"};
}

MotorData motorFromDriveParameters(const model::ParameterValues& values, MotorData m)
{
    auto get = [&](const char* k, double fallback) {
        const auto it = values.find(k);
        return it != values.end() && std::isfinite(it->second) ? it->second : fallback;
    };
    m.maxCurrentA = get("motor.max_current", m.maxCurrentA);
    m.maxVoltageV = get("drive.max_voltage", m.maxVoltageV);
    m.ratedCurrentA = get("motor.rated_current", m.ratedCurrentA);
    const double kt = get("motor.torque_constant", 0.0);
    if (kt > 0.0)
        m.backEmfVPerKrpm = backEmfFromTorqueConstant(kt) * kKeToVPerKrpm;
    return m;
}

} // namespace axistune::tuning

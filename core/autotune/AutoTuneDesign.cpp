// SPDX-License-Identifier: GPL-3.0-or-later
// The one-position sequence's design steps: the plant (and the plant in motion), 5 velocity PI, 6 position gain and
// feedforward (AutoTuneSequence.h).
#include "core/autotune/AutoTuneSequence.h"
#include "core/model/MetadataKeys.h"
#include "core/model/ResultJson.h"
#include "core/tuning/VelocityLoop.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune::autotune::detail {

std::optional<AutoTuneResult> Sequence::plant()
{
    const dsp::FrequencyResponse& t0 = m_measured.measurement.frf;
    const tuning::VelocityPi running{value("velocity.kp"), value("velocity.ki")};
    const double vPeriod = value("velocity.period"), cPeriod = value("current.period");
    auto plantR =
        tuning::plantFromMeasurement(t0, tuning::LoopMeasurementKind::Complementary, running, vPeriod, cPeriod);
    if (!plantR)
        return refuse("velocity loop: " + plantR.error().detail, plantR.error().code);
    dsp::FrequencyResponse plantF = std::move(plantR).value();
    // The axis in motion (SlidingPlant.h): the damping that friction adds at standstill removed from the plant.
    auto standstill = standstillDamping(plantF);
    if (!standstill)
        return refuse("velocity loop: " + standstill.error().detail, standstill.error().code);
    m_standstill = *standstill;
    std::vector<std::complex<double>> slideFactor; // P_s/P = 1/(1 − b·P) on every line of the plant
    slideFactor.reserve(plantF.size());
    for (const auto& p : plantF.h)
        slideFactor.push_back(slidingPlant(p, m_standstill.bNmsPerRad) / p);
    m_plant = std::move(plantF);
    // The new notches in the plant: L_after/L_before of the notch prediction (Π N_k on every line).
    const std::size_t withNotches =
        std::min(m_notches.prediction.openLoopBefore.size(), m_notches.prediction.openLoopAfter.size());
    for (std::size_t i = 0; i < m_plant.size() && i < withNotches; ++i) {
        const auto lb = m_notches.prediction.openLoopBefore.h[i];
        const auto la = m_notches.prediction.openLoopAfter.h[i];
        if (m_plant.valid[i] && std::abs(lb) > 0.0 && std::isfinite(std::abs(la)))
            m_plant.h[i] *= la / lb;
    }
    m_plant.metadata.set(model::meta::kMeasurement, "plant");
    m_phSlide.clear();
    validLines(m_plant, m_pf, m_ph);
    for (std::size_t i = 0, k = 0; i < m_plant.size(); ++i)
        if (k < m_pf.size() && m_plant.freqHz[i] == m_pf[k])
            m_phSlide.push_back(m_ph[k++] * slideFactor[i]);
    return std::nullopt;
}

std::optional<AutoTuneResult> Sequence::velocityPi(double capHz)
{
    const double fReq = m_t.minBandwidthHz;
    const tuning::VelocityPi running{value("velocity.kp"), value("velocity.ki")};
    const double vPeriod = value("velocity.period"), cPeriod = value("current.period");
    Step s;
    s.name = "velocity-pi";
    if (!begin("velocity-pi"))
        return aborted("velocity-pi");
    const double fTop = std::min(0.125 * m_caps.traceRateHz, m_pf.empty() ? 0.0 : m_pf.back() / 2.0);
    const double fBottom = std::max(0.5 * fReq, m_pf.empty() ? 1.0 : m_pf.front());
    nlohmann::json scan = nlohmann::json::array();
    double bestF = 0.0, bestBw = 0.0, bestPm = m_t.phaseMarginDeg + kDesignPhaseReserveDeg;
    Margins bestM, bestSliding;
    double heldByFriction = 0.0;
    tuning::VelocityPi bestPi;
    const int n = 96;
    for (const double extraPm : kDesignPhaseSteps) {
        const double pmDesign = m_t.phaseMarginDeg + kDesignPhaseReserveDeg + extraPm;
        for (int i = 0; i <= n && fTop > fBottom; ++i) {
            const double f = fBottom * std::pow(fTop / fBottom, static_cast<double>(i) / n);
            if (f > capHz)
                break;
            auto pi = tuning::velocityPiFromFrf(m_plant, f, pmDesign);
            if (!pi || !(pi->kpNmsPerRad > 0.0) || !(pi->kiNmPerRad >= 0.0))
                continue;
            std::vector<std::complex<double>> l(m_pf.size()), t(m_pf.size()), ls(m_pf.size());
            for (std::size_t k = 0; k < m_pf.size(); ++k) {
                const auto c = tuning::piResponse(*pi, m_pf[k]);
                l[k] = c * m_ph[k];
                ls[k] = c * m_phSlide[k];
                t[k] = l[k] / (1.0 + l[k]);
            }
            const auto m = marginsOf(m_pf, l);
            const auto ms = marginsOf(m_pf, ls);
            const auto meets = [&](const Margins& x) {
                return x.phaseMarginDeg >= m_t.phaseMarginDeg &&
                       x.gainMarginDb >= m_t.gainMarginDb + kDesignGainReserveDb && std::isfinite(x.phaseMarginDeg);
            };
            const bool ok = meets(m) && meets(ms);
            const double bw = closedLoopBandwidthHz(m_pf, t).value_or(0.0);
            if (ok && f >= fReq && bw > bestBw) {
                bestF = f;
                bestBw = bw;
                bestPm = pmDesign;
                bestM = m;
                bestSliding = ms;
                bestPi = *pi;
            }
            if (ok && bestBw <= 0.0 && f > bestF) // below the required crossover: for the refusal's text
                bestF = f;
            if (meets(m) && !meets(ms) && f >= fReq) // for the refusal's text: only friction held it
                heldByFriction = std::max(heldByFriction, f);
        }
    }
    s.measured = {{"plant_lines", m_pf.size()},
                  {"standstill_damping_Nms_per_rad", m_standstill.bNmsPerRad},
                  {"standstill_inertia_kgm2", m_standstill.inertiaKgm2},
                  {"standstill_lines_up_to_Hz", m_standstill.upToHz},
                  {"crossover_searched_Hz", {fBottom, fTop}},
                  {"running_kp_Nms_per_rad", running.kpNmsPerRad},
                  {"running_ki_Nm_per_rad", running.kiNmPerRad}};
    if (!(bestBw > 0.0) && heldByFriction > 0.0) {
        done(s);
        const double jw = m_standstill.inertiaKgm2 * kTwoPi * fReq;
        return refuse(
            "friction holds the axis during the FRF: the damping at standstill b = " + num(m_standstill.bNmsPerRad, 3) +
            " N m s/rad is " + num(m_standstill.bNmsPerRad / jw, 3) +
            " x the inertia's J w at the required crossover " + num(fReq, 4) +
            " Hz, so the measured plant is not the plant in motion; the PIs that keep " + num(m_t.phaseMarginDeg, 3) +
            " deg and " + num(m_t.gainMarginDb, 3) + " dB on the measured plant (up to " + num(heldByFriction, 4) +
            " Hz) lose them once the axis slides. Measure at a larger amplitude (--amplitudes) or "
            "tune by hand");
    }
    if (!(bestBw > 0.0)) {
        done(s);
        return refuse("the required velocity crossover " + num(fReq, 4) + " Hz cannot be reached with " +
                      num(m_t.phaseMarginDeg, 3) + " deg phase and " + num(m_t.gainMarginDb, 3) +
                      " dB gain margin on the measured plant" +
                      (bestF > 0.0 ? " (highest: " + num(bestF, 4) + " Hz)" : std::string()));
    }
    m_fc = bestF;
    m_predicted = bestM;
    m_predictedInMotion = bestSliding;
    tuning::VelocityLoopRequest req;
    req.method = tuning::VelocityLoopRequest::Method::Frf;
    req.measured = m_plant;
    req.crossoverHz = m_fc;
    req.phaseMarginDeg = bestPm;
    req.running = running;
    req.positionKpRunning = value("position.kp");
    req.velocityPeriodS = vPeriod;
    req.currentPeriodS = cPeriod;
    req.jmKgm2 = finitePositive(value("velocity.inertia")) ? value("velocity.inertia") : 1.0;
    auto d = tuning::designVelocityLoop(req);
    if (!d)
        return refuse("velocity loop: " + d.error().detail, d.error().code);
    m_design = std::move(d).value();
    const auto bw = closedLoopBandwidthHz(m_design.fHz, m_design.closedLoop);
    m_velocityBwHz = bw;
    s.chosen = {{"velocity.kp", m_design.proposed.kpNmsPerRad},
                {"velocity.ki", m_design.proposed.kiNmPerRad},
                {"crossover_Hz", m_fc},
                {"predicted", marginsJson(m_predicted)},
                {"predicted_in_motion", marginsJson(bestSliding)}};
    model::putOptional(s.chosen["predicted"], "velocity_bandwidth_Hz", bw, 1.0,
                       "the predicted closed loop does not fall 3 dB in the measured band");
    s.rule = "of the PIs designed for a crossover on a 96-step log grid " + num(fBottom, 4) + " ... " + num(fTop, 4) +
             " Hz (at least the required " + num(fReq, 4) + " Hz) and a phase margin of " +
             num(m_t.phaseMarginDeg + kDesignPhaseReserveDeg, 3) + " ... " +
             num(m_t.phaseMarginDeg + kDesignPhaseReserveDeg + kDesignPhaseSteps[4], 3) +
             " deg, the one with the widest closed-loop bandwidth that keeps, on the measured plant with the "
             "notches, at least " +
             num(m_t.phaseMarginDeg, 3) + " deg and " + num(m_t.gainMarginDb + kDesignGainReserveDb, 3) + " dB (" +
             styleName(m_o.style) + " " + num(m_t.gainMarginDb, 3) + " dB + " + num(kDesignGainReserveDb, 2) +
             " dB reserve) over every crossover, on the plant as measured and on the plant in motion (the "
             "damping at standstill b = Re(1/P) = " +
             num(m_standstill.bNmsPerRad, 3) + " N m s/rad on the lines up to " + num(m_standstill.upToHz, 3) +
             " Hz removed: P/(1 - b P); friction that holds the axis during a small FRF is gone once it "
             "moves): " +
             m_design.rule;
    if (auto st =
            write({{"velocity.kp", m_design.proposed.kpNmsPerRad}, {"velocity.ki", m_design.proposed.kiNmPerRad}});
        !st)
        return refuse("velocity loop: " + st.error().detail, st.error().code);
    done(s);
    return std::nullopt;
}

std::optional<AutoTuneResult> Sequence::position()
{
    Step s;
    s.name = "position";
    if (!begin("position"))
        return aborted("position");
    // The predicted closed velocity loop on the measured lines.
    std::vector<std::complex<double>> tv(m_pf.size());
    for (std::size_t k = 0; k < m_pf.size(); ++k) {
        const auto l = tuning::piResponse(m_design.proposed, m_pf[k]) * m_ph[k];
        tv[k] = l / (1.0 + l);
    }
    // K_p: the ANALYST rule of the velocity wizard, ω_c,vel/5 (the model's stability limit −6 dB when lower). ω_c is
    // the velocity loop's designed crossover or its predicted −3 dB bandwidth, whichever is lower: a PI designed for
    // a crossover above what the measured plant lets the closed loop follow (a design crossover of 400 Hz whose loop
    // falls 3 dB at 80 Hz) must not give a position loop faster than the velocity loop it commands.
    const double fVel = m_velocityBwHz && *m_velocityBwHz > 0.0 ? std::min(m_fc, *m_velocityBwHz) : m_fc;
    m_kpPos = std::min(kTwoPi * fVel / 5.0,
                       finitePositive(m_design.position.limitPerS)
                           ? m_design.position.limitPerS * std::pow(10.0, -tuning::kPositionGainMarginDb / 20.0)
                           : std::numeric_limits<double>::infinity());
    const auto bw = closedLoopBandwidthHz(m_pf, positionClosedLoop(m_pf, tv, m_kpPos));
    s.measured = {
        {"running_position_kp_per_s", value("position.kp")},
        {"velocity_crossover_Hz", m_fc},
        {"velocity_frequency_Hz", fVel},
        {"model_limit_per_s", std::isfinite(m_design.position.limitPerS) ? m_design.position.limitPerS : 0.0}};
    model::ParameterValues v{{"position.kp", m_kpPos}};
    if (m_writable.count("position.velocity_ff"))
        v["position.velocity_ff"] = 1.0;
    if (m_writable.count("position.torque_ff") && finitePositive(value("velocity.inertia")))
        v["position.torque_ff"] = 1.0;
    for (const auto& [k, x] : v)
        s.chosen[k] = x;
    model::putOptional(s.chosen, "predicted_position_bandwidth_Hz", bw, 1.0,
                       "the predicted position loop does not fall 3 dB in the measured band");
    s.rule =
        "K_p = min(2pi*f_v/5, the model's stability limit -" + num(tuning::kPositionGainMarginDb, 2) +
        " dB), f_v = min(the velocity crossover f_c, the predicted velocity loop's -3 dB bandwidth) = " + num(fVel, 4) +
        " Hz (the velocity wizard's rule, " + m_design.modelNote +
        "); velocity feedforward 1 and torque feedforward 1 with the drive's velocity.inertia (J = " +
        num(value("velocity.inertia"), 4) + " kg m^2, kept) so the command is followed without lag";
    if (auto st = write(v); !st)
        return refuse("position loop: " + st.error().detail, st.error().code);
    done(s);
    return std::nullopt;
}

} // namespace axistune::autotune::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// The one-position sequence's measuring steps: 1 safety envelope, 2 current loop, 3 adaptive FRF, 4 notches
// (AutoTuneSequence.h).
#include "core/autotune/AmplitudeMap.h"
#include "core/autotune/AutoTuneSequence.h"
#include "core/model/Number.h"
#include "core/model/ResultJson.h"
#include "core/tuning/CurrentStep.h"
#include "core/tuning/Resonance.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune::autotune::detail {

std::optional<AutoTuneResult> Sequence::safetyEnvelope()
{
    const std::string& axis = m_o.axis;
    m_ratedA = value("motor.rated_current");
    m_maxTorqueNm = value("motor.torque_constant") * value("motor.max_current");
    m_amplitudePct = std::min(m_t.frfAmplitudePct, m_limits.frfAmplitudeMaxPct);
    m_stepA = std::min(0.2 * m_ratedA, m_limits.currentStepMaxA);
    bool feStop = false;
    for (const auto& k : m_keys)
        feStop = feStop || k.find("following_error") != std::string::npos;
    if (!begin("safety-envelope"))
        return aborted("safety-envelope");
    Step hold;
    hold.name = "safety-envelope";
    {
        device::TestRequest h;
        h.axis = axis;
        auto& ht = h.test.emplace<device::HoldTest>();
        ht.recordS = 0.05;
        auto run = test(h, "the standstill check (hold)", hold.motionTimeS);
        if (!run)
            return refuse(run.error().detail, run.error().code);
        hold.measured = {{"max_torque_Nm", m_maxTorqueNm}, {"standstill_s", ht.recordS}};
        for (const auto& [k, v] : {std::pair<const char*, double>{"frf_amplitude_max_pct", m_limits.frfAmplitudeMaxPct},
                                   {"current_step_max_A", m_limits.currentStepMaxA},
                                   {"motor_speed_max_rad_s", m_limits.motorSpeedMaxRadS},
                                   {"travel_window", m_limits.travelWindow}})
            model::putOptional(hold.measured, k, std::isfinite(v) ? std::optional<double>(v) : std::nullopt, 1.0,
                               "the drive sets no limit of its own");
        const auto* pos = run->trace ? channelWithPrefix(*run->trace, "position_cmd_") : nullptr;
        m_linear = pos == nullptr || pos->name.size() < 2 || pos->name.substr(pos->name.size() - 2) == "_m";
    }
    hold.chosen = {{"frf_amplitude_pct", m_amplitudePct},
                   {"frf_amplitude_max_pct", std::min(kLadderPeakCapPct, m_limits.frfAmplitudeMaxPct)},
                   {"current_step_A", m_stepA},
                   {"time_budget_s", m_o.timeBudgetS},
                   {"following_error_stop", feStop ? "the drive's" : "not offered by the drive"},
                   {"axis_units", m_linear ? "m" : "rad"}};
    hold.rule = "FRF peak " + num(m_t.frfAmplitudePct, 3) + " % of rated torque (" + styleName(m_o.style) +
                "), at most the drive's limit; current step 20 % of rated current within the drive's limit; every "
                "test planned against the drive's limits and the time budget before it moves; " +
                (feStop ? std::string("the drive's following-error stop stays as set")
                        : std::string("the drive offers no following-error stop: the move evaluation checks "
                                      "the following error afterwards"));
    done(hold);
    return std::nullopt;
}

std::optional<AutoTuneResult> Sequence::currentLoop()
{
    const std::string& axis = m_o.axis;
    Step s;
    s.name = "current-loop";
    if (!begin("current-loop"))
        return aborted("current-loop");
    const double kp = value("current.kp"), ki = value("current.ki");
    s.measured = {{"running_kp_V_per_A", kp}, {"running_ki_V_per_As", ki}};
    std::optional<double> predictedRise;
    if (m_o.motor) {
        const auto motor = tuning::motorFromDriveParameters(m_now, *m_o.motor);
        tuning::CurrentLoopSettings cs;
        cs.deadTimeS = value("current.period");
        auto d = tuning::designCurrentLoop(motor, cs);
        if (!d)
            return refuse("current loop: " + d.error().detail, d.error().code);
        model::ParameterValues v{{"current.kp", d->gains.kpVPerA}, {"current.ki", d->gains.kiVPerAs}};
        if (m_writable.count("current.alpha"))
            v["current.alpha"] = d->alpha;
        if (auto st = write(v); !st)
            return refuse("current loop: " + st.error().detail, st.error().code);
        for (const auto& [k, x] : v)
            s.chosen[k] = x;
        predictedRise = d->riseTimeS;
        s.rule = "spec chapter 2 design on the motor data (R_a, L_q, delta from the motor file; I_max, V_max, "
                 "k_e = k_t/1.5 from the drive): the fastest step within stability (gain margin " +
                 num(cs.gainMarginDb, 3) + " dB), voltage and " + num(100.0 * cs.overshootMax, 2) +
                 " % overshoot, best alpha";
    } else {
        s.chosen = {{"current.kp", kp}, {"current.ki", ki}};
        s.rule = "kept: the drive states I_max, V_max and k_t but not R_a and L_q, without which the chapter 2 "
                 "design cannot run (give --motor FILE); the running loop is verified by its step";
    }
    if (m_caps.offers(device::TestType::CurrentStep) && m_caps.currentTraceRateHz > 0.0 && m_stepA > 0.0) {
        device::TestRequest c;
        c.axis = axis;
        auto& cur = c.test.emplace<device::CurrentStepTest>();
        cur.currentA = m_stepA;
        cur.recordS = std::min(0.005, m_limits.currentStepMaxS);
        auto run = test(c, "the current step", s.motionTimeS);
        if (!run)
            return refuse(run.error().detail, run.error().code);
        if (run->trace) {
            auto step = tuning::currentStepFromCapture(*run->trace);
            if (step) {
                const auto fig = tuning::stepFigures(step->tS, step->normalised);
                s.measured["step_A"] = m_stepA;
                model::putOptional(s.measured, "rise_time_s",
                                   std::isfinite(fig.riseTimeS) ? std::optional<double>(fig.riseTimeS) : std::nullopt,
                                   1.0, "the current never reached 90 % of the step");
                s.measured["overshoot_pct"] = 100.0 * fig.overshoot;
                if (predictedRise)
                    s.measured["predicted_rise_time_s"] = *predictedRise;
                if (!std::isfinite(fig.riseTimeS))
                    return refuse("current loop: the measured current step never reaches 90 % of " + num(m_stepA, 3) +
                                  " A; the current loop must be fixed before the velocity loop");
            }
        }
    } else {
        s.measured["step"] = "the drive offers no current step";
    }
    done(s);
    return std::nullopt;
}

std::optional<AutoTuneResult> Sequence::measureFrf()
{
    const std::string& axis = m_o.axis;
    Step s;
    s.name = "frf";
    if (!begin("frf"))
        return aborted("frf");
    nlohmann::json tries = nlohmann::json::array();
    std::optional<device::AdaptiveFrfResult> best;
    double bestPct = m_amplitudePct;
    const double maxPct = std::min(kLadderPeakCapPct, m_limits.frfAmplitudeMaxPct);
    double pct = m_amplitudePct;
    std::string mapRule;
    if (!m_o.amplitudeMapPct.empty()) { // the amplitude map (AmplitudeMap.h): the FRF at the amplitude in use
        AmplitudeMapOptions mo;
        mo.axis = axis;
        mo.amplitudesPct = m_o.amplitudeMapPct;
        mo.fminHz = kFrfMinHz;
        mo.spacingHz = kFrfSpacingHz;
        mo.timeBudgetS = std::max(m_o.timeBudgetS - m_motion, 1e-9); // > 0: a limit (0 would be none)
        auto mp = amplitudeMapInUse(m_drive, mo, m_linear, value("motor.torque_constant") * m_ratedA, m_o.run);
        if (!mp)
            return refuse("amplitude map: " + mp.error().detail, mp.error().code);
        m_motion += mp->motionTimeS;
        s.motionTimeS += mp->motionTimeS;
        s.measured["amplitude_map"] = inUseJson(*mp);
        if (mp->use)
            pct = std::min(mp->map.runs[*mp->use].amplitudePct, maxPct);
        mapRule = "; amplitude map at " + count(static_cast<long long>(mp->map.runs.size())) + " amplitudes first (" +
                  count(static_cast<long long>(mp->map.nonlinear)) + " of " +
                  count(static_cast<long long>(mp->map.compared)) +
                  " lines non-linear): the FRF starts at its amplitude nearest the peak torque of the move "
                  "evaluation's move with the running gains (" +
                  num(mp->useTorquePct, 3) + " % of rated torque) and is not doubled for non-linear lines";
    }
    for (int attempt = 0; attempt < kMaxFrfTries; ++attempt) {
        double t = 0.0;
        auto a = frf(pct, kFrfBudgetS, t);
        s.motionTimeS += t;
        if (!a)
            return refuse(a.error().detail, a.error().code);
        tries.push_back(frfJson(*a, pct));
        const auto f = figuresOf(*a);
        if (!best || f.valid > best->validLines) {
            best = std::move(a).value();
            bestPct = pct;
        }
        const double lines = static_cast<double>(std::max<std::size_t>(f.lines, 1));
        const auto voltage = f.invalidByReason.count("voltage limit") ? f.invalidByReason.at("voltage limit") : 0;
        double next = pct;
        if (static_cast<double>(voltage) > kRetryVoltageFraction * lines)
            next = std::max(0.5 * pct, kMinFrfAmplitudePct);
        else if (static_cast<double>(f.nonlinear) > kRetryNonlinearFraction * lines && mapRule.empty())
            next = std::min(2.0 * pct, maxPct);
        if (next == pct || m_motion + kFrfBudgetS > m_o.timeBudgetS)
            break;
        pct = next;
    }
    m_measured = std::move(*best);
    const auto f = figuresOf(m_measured);
    s.measured["tries"] = tries;
    s.chosen = {{"amplitude_pct", bestPct}, {"valid_lines", f.valid}, {"lines", f.lines}};
    s.rule = "adaptive multisine " + num(kFrfMinHz, 3) + " Hz ... 0.975 fs, " + num(kFrfSpacingHz, 3) +
             " Hz spacing, " + num(kFrfBudgetS, 2) + " s budget each; at most " +
             count(static_cast<long long>(kMaxFrfTries)) + " tries: the peak halves (down to " +
             num(kMinFrfAmplitudePct, 2) + " %) while more than " + num(100.0 * kRetryVoltageFraction, 2) +
             " % of the lines reach the voltage limit, else doubles (up to " + num(maxPct, 3) + " %) while more than " +
             num(100.0 * kRetryNonlinearFraction, 2) +
             " % are non-linear (friction); the try with the most valid lines is used" + mapRule;
    done(s);
    if (auto why = frfRefusal(f))
        return refuse(*why);
    return std::nullopt;
}

std::optional<AutoTuneResult> Sequence::notches()
{
    const dsp::FrequencyResponse& t0 = m_measured.measurement.frf;
    const double fReq = m_t.minBandwidthHz;
    const double execRateHz = 1.0 / value("current.period");
    std::map<int, dsp::NotchSpec> existing;
    int slotCount = 0;
    for (int k = 1; k <= 16; ++k) {
        const std::string p = "filter.notch" + count(static_cast<long long>(k)) + ".";
        if (!std::isfinite(value(p + "center")))
            break;
        slotCount = k;
        if (value(p + "center") > 0.0 && value(p + "depth") < 1.0)
            existing[k] = {value(p + "center"), value(p + "width"), value(p + "depth")};
    }
    Step s;
    s.name = "notches";
    if (!begin("notches"))
        return aborted("notches");
    const auto open = tuning::openLoopOf(t0, m_form);
    tuning::ResonanceOptions ro;
    ro.fminHz = t0.freqHz.front();
    ro.fmaxHz = t0.freqHz.back();
    auto all = tuning::findResonances(open, ro);
    if (!all)
        return refuse("notches: " + all.error().detail, all.error().code);
    nlohmann::json res = nlohmann::json::array();
    for (const auto& r : *all)
        res.push_back({{"f_Hz", r.freqHz}, {"height_dB", r.peakDb}, {"open_loop_dB", r.levelDb}});
    s.measured = {{"resonances", res}, {"existing_notches", existing.size()}, {"exec_rate_Hz", execRateHz}};
    for (const auto& r : *all)
        if (r.freqHz >= fReq / kResonanceSeparation && r.freqHz <= fReq * kResonanceSeparation) {
            done(s);
            return refuse("resonance too close to the required bandwidth: " + num(r.freqHz, 4) + " Hz (" +
                          num(r.peakDb, 3) + " dB above its baseline) lies within a factor " +
                          num(kResonanceSeparation, 2) + " of the required velocity crossover " + num(fReq, 4) +
                          " Hz: a notch there takes the phase margin, and the loop gain cannot dominate it");
        }
    ro.fminHz = std::max(ro.fminHz, kResonanceSeparation * fReq);
    tuning::NotchOptions no;
    no.execRateHz = execRateHz;
    no.slotCount = std::max(slotCount, 0);
    no.maxNotches = no.slotCount;
    auto a = tuning::analyseNotches(t0, m_form, ro, no, existing);
    if (!a)
        return refuse("notches: " + a.error().detail, a.error().code);
    m_notches = std::move(a).value();
    model::ParameterValues v;
    nlohmann::json chosen = nlohmann::json::array();
    for (const auto& n : m_notches.notches) {
        const std::string p = "filter.notch" + count(static_cast<long long>(n.slot)) + ".";
        v[p + "center"] = n.spec.centerHz;
        v[p + "width"] = n.spec.widthHz;
        v[p + "depth"] = n.spec.depth;
        chosen.push_back({{"slot", n.slot},
                          {"center_Hz", n.spec.centerHz},
                          {"width_Hz", n.spec.widthHz},
                          {"depth", n.spec.depth},
                          {"resonance_Hz", n.resonanceHz}});
    }
    nlohmann::json skipped = nlohmann::json::array();
    for (const auto& k : m_notches.proposal.skipped)
        skipped.push_back({{"f_Hz", k.freqHz}, {"reason", k.reason}});
    s.chosen = {{"notches", chosen}, {"skipped", skipped}};
    s.rule = "resonances of the open loop L = T/(1-T) above " + num(kResonanceSeparation, 2) +
             "x the required crossover (" + num(fReq, 4) +
             " Hz) get a notch on a free slot (the notch "
             "wizard's rule: depth to the baseline or to -20 dB open loop, width from the mode's damping); one "
             "within a factor " +
             num(kResonanceSeparation, 2) + " of it refuses the tuning";
    if (!v.empty())
        if (auto st = write(v); !st)
            return refuse("notches: " + st.error().detail, st.error().code);
    done(s);
    return std::nullopt;
}

} // namespace axistune::autotune::detail

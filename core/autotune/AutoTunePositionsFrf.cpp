// SPDX-License-Identifier: GPL-3.0-or-later
// The measurements of the tuner over the travel (AutoTunePositionsRun.h): the adaptive FRF and the resonance map at
// every position, the point-to-point move at the last, the verification at every position.
#include "core/autotune/AutoTunePositionsRun.h"
#include "core/device/MoveTo.h"
#include "core/model/Number.h"
#include "core/model/ResultJson.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune::autotune::detail {

Result<Step> Positions::measurePositions(double pct)
{
    Step s;
    s.name = "frf";
    nlohmann::json per = nlohmann::json::array(), map = nlohmann::json::array();
    for (auto& site : m_sites) {
        if (auto st = moveTo(site.x, s.motionTimeS); !st)
            return st.error();
        auto a = measure(pct, s.motionTimeS);
        if (!a)
            return a.error();
        site.frf = std::move(a).value();
        std::size_t nonlinear = 0;
        for (const auto& l : site.frf.invalid)
            nonlinear += l.reason == device::InvalidReason::Nonlinear ? 1 : 0;
        const auto& t = site.frf.measurement.frf;
        const double lines = static_cast<double>(std::max<std::size_t>(t.size(), 1));
        const std::string at = "at " + num(site.x, 4) + (m_linear ? " m: " : " rad: ");
        if (static_cast<double>(nonlinear) > kMaxNonlinearFraction * lines)
            return makeError(ErrorCode::Safety, "strong non-linearity " + at +
                                                    wholeText(static_cast<long long>(nonlinear)) + " of " +
                                                    wholeText(static_cast<long long>(t.size())) +
                                                    " FRF lines change with the excitation beyond their noise");
        if (static_cast<double>(site.frf.validLines) < kMinValidFraction * lines)
            return makeError(ErrorCode::Safety, "coherence too low " + at + "only " +
                                                    wholeText(static_cast<long long>(site.frf.validLines)) + " of " +
                                                    wholeText(static_cast<long long>(t.size())) +
                                                    " FRF lines are valid");
        tuning::ResonanceOptions ro;
        ro.fminHz = t.freqHz.front();
        ro.fmaxHz = t.freqHz.back();
        auto res = tuning::findResonances(tuning::openLoopOf(t, m_form), ro);
        if (!res)
            return makeError(res.error().code, "resonances " + at + res.error().detail);
        nlohmann::json rj = nlohmann::json::array();
        for (const auto& r : *res)
            rj.push_back({{"f_Hz", r.freqHz}, {"height_dB", r.peakDb}});
        if (!res->empty())
            site.first = res->front();
        site.fin.position = site.x;
        site.fin.firstResonanceHz = site.first ? std::optional<double>(site.first->freqHz) : std::nullopt;
        site.fin.firstResonanceHeightDb = site.first ? std::optional<double>(site.first->peakDb) : std::nullopt;
        per.push_back({{"position", site.x},
                       {"lines", t.size()},
                       {"valid_lines", site.frf.validLines},
                       {"nonlinear_lines", nonlinear},
                       {"motion_time_s", site.frf.motionTimeS},
                       {"resonances", rj}});
        nlohmann::json m{{"position", site.x}};
        model::putOptional(m, "frequency_Hz", site.fin.firstResonanceHz, 1.0, "no resonance in the measured band");
        model::putOptional(m, "height_dB", site.fin.firstResonanceHeightDb, 1.0, "no resonance in the measured band");
        map.push_back(m);
    }
    s.measured = {{"positions", per}, {"resonance_map", map}};
    s.chosen = {{"amplitude_pct", pct}};
    s.rule = "at each position (moved there by a jog through the drive): the adaptive multisine " + num(kFrfMinHz, 3) +
             " Hz ... 0.975 fs, " + num(kFrfSpacingHz, 3) + " Hz spacing, " + num(kFrfBudgetS, 2) +
             " s budget, at the style's amplitude; refused where fewer than " + num(100.0 * kMinValidFraction, 2) +
             " % of the lines are valid or more than " + num(100.0 * kMaxNonlinearFraction, 2) +
             " % are non-linear; the resonance map is the lowest resonance of the open loop L = T/(1-T) at each";
    return s;
}

Result<Step> Positions::move()
{
    Step s;
    s.name = "move";
    // A point-to-point move of 10 mm (0.2 rad) back and forth at the last position, with the tuned gains.
    device::TestRequest r;
    r.axis = m_o.axis;
    auto& j = r.test.emplace<device::JogTest>();
    j.distance = (m_sites.back().x > 0.0 ? -1.0 : 1.0) * (m_linear ? 0.01 : 0.2);
    j.velocity = m_linear ? 0.05 : 1.0;
    j.acceleration = m_linear ? 1.0 : 20.0;
    j.returnToStart = true;
    j.dwellS = 0.15;
    const double window = m_linear ? 1e-6 : 1e-5;
    auto plan = m_drive.planTest(r);
    if (plan && m_motion + plan->motionTimeS > m_o.timeBudgetS)
        return makeError(ErrorCode::Safety,
                         "the move would exceed the time budget (" + num(m_o.timeBudgetS, 3) + " s)");
    device::RunOptions ro = m_o.run;
    ro.readTrace = true;
    auto run = device::runTest(m_drive, r, ro);
    if (!run)
        return makeError(run.error().code, "the point-to-point move: " + run.error().detail);
    s.motionTimeS = device::motionTimeS(*run, plan);
    m_motion += s.motionTimeS;
    if (!run->trace)
        return makeError(ErrorCode::Device, "the move gave no trace");
    const auto& c = *run->trace;
    const bool full = value("position.feedback") >= 0.5;
    const model::Channel *tc = c.channel("t_s"), *cmd = nullptr, *pos = nullptr, *tq = c.channel("torque_cmd_Nm");
    for (const auto& ch : c.channels) {
        if (ch.name.rfind("position_cmd_", 0) == 0)
            cmd = &ch;
        if (ch.name.rfind(full ? "table_pos_" : "motor_pos_", 0) == 0)
            pos = &ch;
    }
    if (!tc || !cmd || !pos || !tq)
        return makeError(ErrorCode::Device,
                         "the move's trace lacks t_s, position_cmd_*, the feedback or torque_cmd_Nm");
    const std::size_t n = std::min({tc->data.size(), cmd->data.size(), pos->data.size(), tq->data.size()});
    if (n < 2)
        return makeError(ErrorCode::Device, "the move's trace is empty");
    // The end of the command: the last sample where it still changed.
    std::size_t end = n - 1;
    while (end > 0 && cmd->data[end - 1] == cmd->data[n - 1])
        --end;
    double fe = 0.0, peakTq = 0.0;
    std::optional<std::size_t> lastOutside;
    for (std::size_t k = 0; k < n; ++k) {
        fe = std::max(fe, std::abs(cmd->data[k] - pos->data[k]));
        peakTq = std::max(peakTq, std::abs(tq->data[k]));
        if (k >= end && std::abs(pos->data[k] - cmd->data[n - 1]) > window)
            lastOutside = k;
    }
    std::optional<double> settling;
    if (!lastOutside)
        settling = 0.0;
    else if (*lastOutside + 1 < n)
        settling = tc->data[*lastOutside + 1] - tc->data[end];
    const double maxTq = value("motor.torque_constant") * value("motor.max_current");
    const double headroom = maxTq > 0.0 ? 1.0 - peakTq / maxTq : 0.0;
    s.measured = {{"peak_following_error", fe}, {"peak_torque_Nm", peakTq}, {"torque_headroom_pct", 100.0 * headroom}};
    model::putOptional(s.measured, "settling_time_s", settling, 1.0,
                       "the position did not stay within the window before the record ended");
    s.chosen = {{"position", m_sites.back().x},
                {"distance", j.distance},
                {"velocity", j.velocity},
                {"acceleration", j.acceleration},
                {"window", window}};
    s.rule = "a point-to-point move there and back at the last position with the tuned gains; settling time from the "
             "end of the command until the feedback stays within the window; peak following error; torque headroom "
             "against k_t * I_max (at least 10 %)";
    if (headroom < 0.1)
        return makeError(ErrorCode::Safety, "the move needs " + num(peakTq, 3) + " N m of " + num(maxTq, 3) +
                                                " N m: less than 10 % torque headroom");
    m_fin.settlingTimeS = settling;
    m_fin.peakFollowingError = fe;
    return s;
}

Result<std::string> Positions::verify(Step& s)
{
    s.name = "verify";
    std::string why;
    nlohmann::json per = nlohmann::json::array();
    // In the reverse order: the axis stands at the last position.
    for (auto it = m_sites.rbegin(); it != m_sites.rend(); ++it) {
        auto& site = *it;
        if (auto st = moveTo(site.x, s.motionTimeS); !st)
            return st.error();
        auto a = measure(m_pct, s.motionTimeS);
        if (!a)
            return a.error();
        std::vector<double> f, lf;
        std::vector<std::complex<double>> tm, lh;
        validOf(a->measurement.frf, f, tm);
        validOf(dsp::openLoopFromClosedLoop(a->measurement.frf, dsp::LoopMeasurement::Complementary), lf, lh);
        const auto m = loopMarginsOn(lf, lh);
        const auto bw = closedLoopBandwidthHz(f, tm);
        const auto pbw = closedLoopBandwidthHz(f, positionClosed(f, tm, m_kpPos));
        nlohmann::json p{{"position", site.x}, {"valid_lines", a->validLines}};
        model::putOptional(p, "phase_margin_deg", finiteOr(m.phaseMarginDeg), 1.0, "no gain crossover in the band");
        model::putOptional(p, "gain_margin_dB", finiteOr(m.gainMarginDb), 1.0, "no -180 deg crossing in the band");
        model::putOptional(p, "velocity_bandwidth_Hz", bw, 1.0, "|T| does not fall 3 dB in the band");
        per.push_back(p);
        site.fin.phaseMarginDeg = std::isfinite(m.phaseMarginDeg) ? m.phaseMarginDeg : 0.0;
        site.fin.gainMarginDb = std::isfinite(m.gainMarginDb) ? m.gainMarginDb : 0.0;
        site.fin.velocityBandwidthHz = bw.value_or(0.0);
        site.fin.positionBandwidthHz = pbw.value_or(0.0);
        const std::string at = (why.empty() ? "" : "; ") + std::string("at ") + num(site.x, 4) + ": ";
        if (!std::isfinite(m.phaseMarginDeg) || m.phaseMarginDeg < m_t.acceptPhaseMarginDeg ||
            !std::isfinite(m.gainMarginDb) || m.gainMarginDb < m_t.acceptGainMarginDb)
            why += at + (std::isfinite(m.phaseMarginDeg) ? num(m.phaseMarginDeg, 3) + " deg" : std::string("no")) +
                   " phase margin and " +
                   (std::isfinite(m.gainMarginDb) ? num(m.gainMarginDb, 3) + " dB" : std::string("an unknown")) +
                   " gain margin";
        else if (!bw || !pbw)
            why += at + "the re-measured closed loop does not fall 3 dB within the band";
    }
    s.measured = {{"positions", per}};
    s.chosen = {{"accept_phase_margin_deg", m_t.acceptPhaseMarginDeg},
                {"accept_gain_margin_dB", m_t.acceptGainMarginDb}};
    s.rule = "the closed velocity loop measured again at every position (moved there by a jog); margins of "
             "L = T/(1-T) on its valid lines (smallest over every crossover) must be at least the style's " +
             num(m_t.acceptPhaseMarginDeg, 3) + " deg and " + num(m_t.acceptGainMarginDb, 3) + " dB at EVERY position";
    return why;
}

} // namespace axistune::autotune::detail

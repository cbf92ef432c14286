// SPDX-License-Identifier: GPL-3.0-or-later
// The one-position sequence's checks: 7 move evaluation (with the backlash reversal), 8 verify (AutoTuneSequence.h).
#include "core/autotune/AmplitudeMap.h"
#include "core/autotune/AutoTuneSequence.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/model/ResultJson.h"

#include <algorithm>
#include <cmath>

namespace axistune::autotune::detail {

std::optional<AutoTuneResult> Sequence::move()
{
    const std::string& axis = m_o.axis;
    Step s;
    s.name = "move";
    if (!begin("move"))
        return aborted("move");
    const device::TestRequest move = moveEvaluationRequest(axis, m_linear);
    const device::JogTest& j = move.jog();
    const double window = m_linear ? 1e-6 : 1e-5;
    auto run = test(move, "the point-to-point move", s.motionTimeS);
    if (!run)
        return refuse(run.error().detail, run.error().code);
    if (!run->trace)
        return refuse("the move gave no trace", ErrorCode::Device);
    const auto& c = *run->trace;
    const bool full = value("position.feedback") >= 0.5;
    const auto* t = c.channel("t_s");
    const auto* cmd = channelWithPrefix(c, "position_cmd_");
    const auto* pos = channelWithPrefix(c, full ? "table_pos_" : "motor_pos_");
    const auto* tq = c.channel("torque_cmd_Nm");
    if (!t || !cmd || !pos || !tq)
        return refuse("the move's trace lacks t_s, position_cmd_*, the position feedback or torque_cmd_Nm",
                      ErrorCode::Device);
    const std::size_t len = std::min({t->data.size(), cmd->data.size(), pos->data.size(), tq->data.size()});
    if (len < 2)
        return refuse("the move's trace is empty", ErrorCode::Device);
    const double target = cmd->data[len - 1];
    std::size_t kEnd = len - 1;
    while (kEnd > 0 && cmd->data[kEnd - 1] == target)
        --kEnd;
    double peakFe = 0.0, peakTq = 0.0, over = 0.0;
    const double dir = target >= cmd->data[0] ? 1.0 : -1.0;
    std::size_t lastOut = kEnd;
    bool everOut = false;
    for (std::size_t k = 0; k < len; ++k) {
        peakFe = std::max(peakFe, std::abs(cmd->data[k] - pos->data[k]));
        peakTq = std::max(peakTq, std::abs(tq->data[k]));
        if (k >= kEnd) {
            over = std::max(over, dir * (pos->data[k] - target));
            if (std::abs(pos->data[k] - target) > window) {
                lastOut = k;
                everOut = true;
            }
        }
    }
    std::optional<double> settling;
    if (lastOut + 1 < len)
        settling = everOut ? t->data[lastOut + 1] - t->data[kEnd] : 0.0;
    const double headroom = m_maxTorqueNm > 0.0 ? 1.0 - peakTq / m_maxTorqueNm : 0.0;
    s.measured = {{"peak_following_error", peakFe},
                  {"overshoot", over},
                  {"peak_torque_Nm", peakTq},
                  {"torque_headroom_pct", 100.0 * headroom}};
    model::putOptional(s.measured, "settling_time_s", settling, 1.0,
                       "the position did not stay within the window before the record ended");
    s.chosen = {{"distance", j.distance},
                {"velocity", j.velocity},
                {"acceleration", j.acceleration},
                {"window", window},
                {"feedback", full ? "table (full-closed)" : "motor (semi-closed)"}};
    s.rule = std::string("a point-to-point move of the axis with the tuned gains; settling time from the end of "
                         "the command until the position stays within ±") +
             num(window, 2) + (m_linear ? " m" : " rad") +
             "; overshoot past the target; peak following error; torque headroom against k_t * I_max";
    // Backlash against the settling window (AmplitudeMap.h backlashFromReversal): a linear axis whose trace
    // has the motor and the table position reverses once; the lost motion at zero torque b must stay within
    // the window's width 2w, else the table cannot be brought within ±w from both sides.
    std::optional<BacklashEstimate> backlash;
    if (m_linear && c.channel("motor_pos_m") && c.channel("table_pos_m")) {
        double reversalS = 0.0;
        auto rev = test(backlashReversal(axis, kBacklashReversalM, j.velocity, j.acceleration),
                        "the reversal (backlash)", reversalS);
        s.motionTimeS += reversalS;
        if (!rev)
            return refuse(rev.error().detail, rev.error().code);
        if (!rev->trace)
            return refuse("the reversal (backlash) gave no trace", ErrorCode::Device);
        auto b = backlashFromReversal(*rev->trace);
        if (!b)
            return refuse("the reversal (backlash): " + b.error().detail, ErrorCode::Device);
        backlash = *b;
        s.measured["backlash"] = b->backlashM;
        s.measured["lost_motion_compliance_m_per_Nm"] = b->complianceMPerNm;
        s.rule += "; backlash: a reversal " + num(kBacklashReversalM * 1e3, 2) +
                  " mm forth and back, motor-side minus table position regressed on the motor torque with one "
                  "intercept per direction while moving at >= half speed; the lost motion at zero torque "
                  "must not exceed the window's width " +
                  num(2.0 * window, 2) + " m";
    }
    done(s);
    if (backlash && backlash->backlashM > 2.0 * window)
        return refuse("backlash larger than the settling window: " + num(backlash->backlashM * 1e6, 3) +
                      " um of lost motion at zero torque at a reversal, the window is +-" + num(window * 1e6, 2) +
                      " um (" + num(2.0 * window * 1e6, 2) +
                      " um wide): the table cannot settle into it from both directions");
    if (headroom < 0.1)
        return refuse("the move needs " + num(peakTq, 3) + " N m of " + num(m_maxTorqueNm, 3) +
                      " N m: less than 10 % torque headroom");
    m_fin.settlingTimeS = settling;
    m_fin.peakFollowingError = peakFe;
    return std::nullopt;
}

std::optional<AutoTuneResult> Sequence::verify(int attempt)
{
    Step s;
    s.name = "verify";
    if (!begin("verify"))
        return aborted("verify");
    double t = 0.0;
    auto a = frf(m_measured.passes.front().peakPct, kFrfBudgetS, t);
    s.motionTimeS = t;
    if (!a)
        return refuse(a.error().detail, a.error().code);
    std::vector<double> f;
    std::vector<std::complex<double>> tm;
    validLines(a->measurement.frf, f, tm);
    const auto open = dsp::openLoopFromClosedLoop(a->measurement.frf, dsp::LoopMeasurement::Complementary);
    std::vector<double> lf;
    std::vector<std::complex<double>> lh;
    validLines(open, lf, lh);
    const auto m = marginsOf(lf, lh);
    const auto bw = closedLoopBandwidthHz(f, tm);
    const auto pbw = closedLoopBandwidthHz(f, positionClosedLoop(f, tm, m_kpPos));
    s.measured = frfJson(*a, m_measured.passes.front().peakPct);
    s.measured["margins"] = marginsJson(m);
    model::putOptional(s.measured, "velocity_bandwidth_Hz", bw, 1.0, "|T| does not fall 3 dB in the band");
    s.chosen = {{"predicted", marginsJson(m_predicted)},
                {"predicted_in_motion", marginsJson(m_predictedInMotion)},
                {"accept_phase_margin_deg", m_t.acceptPhaseMarginDeg},
                {"accept_gain_margin_dB", m_t.acceptGainMarginDb}};
    s.rule = "the closed velocity loop measured again as in the FRF step; margins of L = T/(1-T) on its valid "
             "lines (smallest over every crossover) must be at least the style's " +
             num(m_t.acceptPhaseMarginDeg, 3) + " deg and " + num(m_t.acceptGainMarginDb, 3) +
             " dB. Measured at standstill like the FRF step: friction's equivalent damping grows as the motion "
             "shrinks (Coulomb: 4 F_c / (pi V)), and the new gains let the axis move less under the same "
             "excitation, so the re-measured margins can exceed the prediction from the first FRF; once the axis "
             "slides the loop has the margins predicted in motion (velocity-pi step, also checked there)";
    done(s);
    if (!std::isfinite(m.phaseMarginDeg) || m.phaseMarginDeg < m_t.acceptPhaseMarginDeg ||
        m.gainMarginDb < m_t.acceptGainMarginDb) {
        const std::string why =
            "the re-measured loop has " +
            (std::isfinite(m.phaseMarginDeg) ? num(m.phaseMarginDeg, 3) + " deg" : std::string("no")) +
            " phase margin and " + (std::isfinite(m.gainMarginDb) ? num(m.gainMarginDb, 3) : std::string("unbounded")) +
            " dB gain margin (predicted " + num(m_predicted.phaseMarginDeg, 3) + " deg, " +
            num(m_predicted.gainMarginDb, 3) + " dB; needed " + num(m_t.acceptPhaseMarginDeg, 3) + " deg, " +
            num(m_t.acceptGainMarginDb, 3) + " dB)";
        if (attempt < kMaxDesignAttempts && m_motion + kFrfBudgetS + 1.0 <= m_o.timeBudgetS) {
            m_r.steps.back().rule += "; missed (" + why + "): designed again below 0.8 x " + num(m_fc, 4) + " Hz";
            m_capHz = 0.8 * m_fc;
            m_again = true;
            return std::nullopt;
        }
        return refuse("verification: " + why);
    }
    if (!bw || !pbw)
        return refuse("verification: the re-measured closed loop does not fall 3 dB within the measured band");
    m_fin.phaseMarginDeg = m.phaseMarginDeg;
    m_fin.gainMarginDb = std::isfinite(m.gainMarginDb) ? m.gainMarginDb : 0.0;
    m_fin.velocityBandwidthHz = *bw;
    m_fin.positionBandwidthHz = *pbw;
    if (!std::isfinite(m.gainMarginDb))
        return refuse("verification: no -180 deg crossing in the measured band, the gain margin is not known");
    return std::nullopt;
}

} // namespace axistune::autotune::detail

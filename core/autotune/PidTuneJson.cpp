// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/autotune/PidTune.h"
#include "core/model/ResultJson.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune::autotune {
namespace {

nlohmann::json gainsJson(const tuning::PositionPid& g)
{
    return {{"Pgain", g.p}, {"Igain", g.i}, {"Dgain", g.d}, {"FF1", g.ff1}, {"FF2", g.ff2}};
}

nlohmann::json marginsJson(const tuning::PositionLoopMargins& m)
{
    nlohmann::json j = nlohmann::json::object();
    const char* noCrossover = "no gain crossover in the measured band";
    const char* noPhase = "the phase never crosses -180 deg where |L| < 1 in the measured band";
    model::putNumber(j, "crossover_Hz", m.crossoverHz, noCrossover);
    model::putNumber(j, "phase_margin_deg", m.phaseMarginDeg, noCrossover);
    model::putNumber(j, "gain_margin_dB", m.gainMarginDb, noPhase);
    model::putNumber(j, "gain_margin_freq_Hz", std::isfinite(m.gainMarginDb) ? m.gainMarginFreqHz : NAN, noPhase);
    return j;
}

} // namespace

nlohmann::json pidTuneJson(const PidTuneRequest& request, const PidLoopMeasurement& measured,
                           const PidTuneProposal& proposal, const PidTuneApplied* applied)
{
    nlohmann::json out;
    out["axis"] = request.axis;
    out["scope"] = request.scope == PidTuneScope::NotchOnly ? "notch" : "gains-and-notch";
    out["servo_rate_Hz"] = measured.servoRateHz;
    out["band_Hz"] = {request.fminHz, measured.fmaxHz};
    out["drive_input"] = proposal.input == tuning::DriveInput::Torque ? "torque" : "velocity";
    out["drive_input_rule"] = proposal.inputRule;
    out["running"] = {{"gains", gainsJson(measured.running)},
                      {"margins", marginsJson(proposal.runningMargins)},
                      {"motion_time_s", measured.motionTimeS}};
    out["proposed"] = {{"gains", gainsJson(proposal.gains)},
                       {"predicted", marginsJson(proposal.predicted)},
                       {"rules", proposal.rules}};
    if (measured.runningNotch)
        out["running"]["notch"] = {{"f0_Hz", measured.runningNotch->f0Hz}, {"Q", measured.runningNotch->q}};
    if (!proposal.notchRule.empty())
        out["proposed"]["notch_rule"] = proposal.notchRule;
    if (proposal.notch)
        out["proposed"]["notch"] = {{"f0_Hz", proposal.notch->f0Hz}, {"Q", proposal.notch->q}};
    out["applied"] = applied && applied->applied;
    if (applied) {
        if (applied->measuredOk)
            out["verified"] = {{"measured", marginsJson(applied->measured)}, {"motion_time_s", applied->motionTimeS}};
        if (!applied->applied)
            out["refused"] = applied->refusal;
        else
            out["journal"] = pidTuneWritesJson(pidTuneAppliedWrites(*applied, proposal));
    }
    return out;
}

} // namespace axistune::autotune

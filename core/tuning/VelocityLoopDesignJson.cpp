// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/tuning/VelocityLoopDesignJson.h"

#include "core/dsp/LoopMarginsJson.h"
#include "core/model/ResultJson.h"
#include <nlohmann/json.hpp>

namespace axistune::tuning {

nlohmann::json velocityLoopMarginsJson(const LoopMargins& m)
{
    nlohmann::json j = nlohmann::json::object();
    model::putNumber(j, "crossover_Hz", m.crossoverHz, dsp::kNoGainCrossover);
    model::putNumber(j, "phase_margin_deg", m.phaseMarginDeg, dsp::kNoGainCrossover);
    model::putNumber(j, "gain_margin_dB", m.gainMarginDb, dsp::kNoPhaseCrossover);
    model::putNumber(j, "phase_crossover_Hz", m.phaseCrossoverHz, dsp::kNoPhaseCrossover);
    model::putNumber(j, "peak_sensitivity_dB", m.peakSensitivityDb, dsp::kNoValidPoint);
    return j;
}

nlohmann::json velocityLoopProposalJson(const VelocityLoopDesign& d)
{
    nlohmann::json j{{"velocity_kp_Nms_per_rad", d.proposed.kpNmsPerRad},
                     {"velocity_ki_Nm_per_rad", d.proposed.kiNmPerRad},
                     {"rule", d.rule},
                     {"margins_before", velocityLoopMarginsJson(d.marginsBefore)},
                     {"margins", velocityLoopMarginsJson(d.marginsAfter)},
                     {"position_gain_limit_Hz", d.position.limitFrequencyHz}};
    const char* noLimit = "no stability limit of the position gain below 1e5 1/s";
    model::putNumber(j, "position_gain_limit_per_s", d.position.limitPerS, noLimit);
    model::putNumber(j, "position_gain_per_s", d.position.recommendedPerS, noLimit);
    return j;
}

} // namespace axistune::tuning

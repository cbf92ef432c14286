// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/dsp/LoopMarginsJson.h"

#include "core/model/ResultJson.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace axistune::dsp {

nlohmann::json loopMarginsJson(const LoopMargins& m)
{
    nlohmann::json j = nlohmann::json::object();
    const double inf = std::numeric_limits<double>::infinity();
    model::putNumber(j, "gain_margin_dB", m.gainMarginDb, kNoPhaseCrossover);
    model::putNumber(j, "gain_margin_Hz", std::isfinite(m.gainMarginDb) ? m.gainMarginFreqHz : inf, kNoPhaseCrossover);
    model::putNumber(j, "phase_margin_deg", m.phaseMarginDeg, kNoGainCrossover);
    model::putNumber(j, "phase_margin_Hz", std::isfinite(m.phaseMarginDeg) ? m.phaseMarginFreqHz : inf,
                     kNoGainCrossover);
    model::putNumber(j, "peak_sensitivity_dB", m.peakSensitivityDb, kNoValidPoint);
    model::putNumber(j, "peak_sensitivity_Hz", std::isfinite(m.peakSensitivityDb) ? m.peakSensitivityFreqHz : inf,
                     kNoValidPoint);
    return j;
}

} // namespace axistune::dsp

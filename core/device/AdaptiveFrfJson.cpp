// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/AdaptiveFrfJson.h"

#include "core/device/AdaptiveFrf.h"
#include "core/model/ResultJson.h"

#include <nlohmann/json.hpp>

namespace axistune::device {

nlohmann::json adaptiveFrfJson(const AdaptiveFrfResult& result, double timeBudgetS)
{
    nlohmann::json a;
    a["time_budget_s"] = timeBudgetS;
    a["motion_time_s"] = result.motionTimeS;
    a["valid_lines"] = result.validLines;
    a["passes"] = nlohmann::json::array();
    for (const auto& p : result.passes) {
        nlohmann::json pass{{"lines", p.lines},
                            {"bands", p.bands},
                            {"peak_pct", p.peakPct},
                            {"periods", p.periods},
                            {"motion_time_s", p.motionTimeS},
                            {"shaped", p.shaped},
                            {"voltage_limit_reached", p.voltageReached},
                            {"valid_after", p.validAfter},
                            {"limited_by", p.limitedBy}};
        model::putNumber(pass, "voltage_peak_V", p.voltagePeakV, "the drive traces no voltage");
        model::putNumber(pass, "voltage_predicted_V", p.voltagePredictedV,
                         "phases designed for the torque: the first pass, a drive that takes no spectrum (Modbus) "
                         "or traces no voltage");
        a["passes"].push_back(pass);
    }
    a["invalid_lines"] = nlohmann::json::array();
    for (const auto& l : result.invalid) {
        nlohmann::json line{{"f_Hz", l.freqHz}, {"reason", invalidReasonName(l.reason)}};
        model::putNumber(line, "relative_noise", l.relativeNoise,
                         "never measured below the voltage limit (every pass that excited it reached the limit)");
        a["invalid_lines"].push_back(line);
    }
    nlohmann::json counts = nlohmann::json::object();
    const auto n = invalidByReason(result);
    for (std::size_t r = 0; r < n.size(); ++r)
        counts[invalidReasonName(static_cast<InvalidReason>(r))] = n[r];
    a["invalid_by_reason"] = counts;
    return a;
}

} // namespace axistune::device

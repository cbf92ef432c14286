// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli current-loop: PI ratio α and current gains from motor data (docs/tuning.md).
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/model/ResultJson.h"
#include "core/tuning/CurrentLoop.h"

#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {

namespace {

struct CurrentLoopOptions {
    std::string motorPath;
    std::string outPath;
    tuning::CurrentLoopSettings settings;
    double periodS = 0.0;  // 0 → the dead time
    bool plots = false;
};

nlohmann::json curveJson(const tuning::BoundaryCurve& c)
{
    return nlohmann::json{{"kp_V_per_A", c.kpVPerA}, {"ki_V_per_As", c.kiVPerAs}};
}

int runCurrentLoop(const CurrentLoopOptions& o)
{
    const std::string cmd = "current-loop";
    auto motor = tuning::readMotorJsonFile(o.motorPath);
    if (!motor) {
        return reportError(cmd, motor.error());
    }
    if (auto st = tuning::validateSettings(o.settings); !st) {
        return reportError(cmd, st.error());
    }
    if (o.periodS < 0.0) {
        return reportError(cmd, makeError(ErrorCode::OutOfRange, "--period-s must be > 0"));
    }
    auto design = tuning::designCurrentLoop(*motor, o.settings);
    if (!design) {
        return reportError(cmd, design.error());
    }
    const auto& d = *design;
    nlohmann::json j;
    j["alpha"] = d.alpha;
    j["ki_V_per_As"] = d.gains.kiVPerAs;
    j["kp_V_per_A"] = d.gains.kpVPerA;
    j["rise_time_s"] = d.riseTimeS;
    j["settings"] = {{"tau_s", o.settings.deadTimeS},
                     {"gain_margin_dB", o.settings.gainMarginDb},
                     {"overshoot", o.settings.overshootMax},
                     {"ripple", o.settings.rippleFraction},
                     {"alpha_step", o.settings.alphaStep}};
    j["table"] = nlohmann::json::array();
    for (const auto& row : d.table) {
        nlohmann::json r{{"alpha", row.alpha}, {"feasible", row.feasible}};
        if (row.feasible) {
            r["ki_V_per_As"] = row.gains.kiVPerAs;
            r["kp_V_per_A"] = row.gains.kpVPerA;
            r["rise_time_s"] = row.riseTimeS;
            r["overshoot"] = row.overshoot;
        } else {
            // Left out and named (docs/formats.md "Undefined values"): no gains meet the constraints.
            for (const char* key : {"ki_V_per_As", "kp_V_per_A", "rise_time_s"})
                model::putUndefined(r, key, "infeasible: no gains at this alpha meet the active constraints");
        }
        r["active_constraints"] = row.activeConstraints;
        j["table"].push_back(r);
    }
    j["schedule"] = nlohmann::json::array();
    for (const auto& p : d.schedule) {
        j["schedule"].push_back({{"current_A", p.currentA},
                                 {"factor", p.factor},
                                 {"ki_V_per_As", p.gains.kiVPerAs},
                                 {"kp_V_per_A", p.gains.kpVPerA}});
    }
    if (o.plots) {
        constexpr int kPoints = 60;
        nlohmann::json plots;
        plots["stability_boundary"] = curveJson(tuning::stabilityBoundary(*motor, o.settings, kPoints));
        plots["voltage_envelope"] = nlohmann::json::array();
        plots["overshoot_curve"] = nlohmann::json::array();
        for (const auto& row : d.table) {
            auto v = curveJson(tuning::voltageEnvelope(*motor, o.settings, row.alpha, kPoints));
            v["alpha"] = row.alpha;
            plots["voltage_envelope"].push_back(v);
            auto c = curveJson(tuning::overshootCurve(*motor, o.settings, row.alpha, kPoints));
            c["alpha"] = row.alpha;
            plots["overshoot_curve"].push_back(c);
        }
        const double period = o.periodS > 0.0 ? o.periodS : o.settings.deadTimeS;
        const auto step = tuning::stepResponses(*motor, d.alpha, d.gains, o.settings.deadTimeS, period,
                                                std::max(20.0 * d.riseTimeS, 40.0 * period));
        plots["step_response"] = {{"period_s", period},
                                  {"time_s", step.timeS},
                                  {"delay_free", step.delayFree},
                                  {"discrete_with_delay", step.discrete}};
        j["plots"] = plots;
    }
    return writeJsonResult(cmd, j, o.outPath);
}

const CliRegistrar kRegistrar{CliCommand{
    "current-loop",
    "Current-loop PI ratio alpha and gains from motor data (dead time, voltage, overshoot, saturation)",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<CurrentLoopOptions>();
        sub.add_option("--motor", o->motorPath, "motor JSON (resistance_ohm, inductance_q_H, max_current_A, "
                                                "max_voltage_V, inductance_drop_at_max, ...)")
            ->required();
        sub.add_option("--tau-s", o->settings.deadTimeS, "dead time [s] (default 62.5e-6)");
        sub.add_option("--gain-margin-db", o->settings.gainMarginDb,
                       "gain margin [dB] (default 3.0103 = the paper's factor sqrt(2))");
        sub.add_option("--overshoot", o->settings.overshootMax, "step overshoot limit, fraction (default 0.1)");
        sub.add_option("--ripple", o->settings.rippleFraction, "current ripple I_q/I_max of the voltage check (default 0.05)");
        sub.add_option("--alpha-step", o->settings.alphaStep, "alpha grid step (default 0.1)");
        sub.add_option("--period-s", o->periodS, "current-loop period of the discrete step response (default = tau)");
        sub.add_flag("--plots", o->plots, "add plot data: boundaries per alpha and step responses");
        sub.add_option("--out", o->outPath, "write the JSON to this file instead of stdout");
        return recordSessions(sub, [o] { return runCurrentLoop(*o); });
    }}};

}  // namespace

}  // namespace axistune::cli

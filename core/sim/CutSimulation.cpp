// SPDX-License-Identifier: GPL-3.0-or-later
// Milling cut on a simulated feed axis: the feed motion, the process force as a load torque, the process
// signals in the trace (CutSimulation.h; spec/chatter-stability-and-spindle-speed.md for the process).
#include "core/sim/CutSimulation.h"

#include "core/sim/AxisSimulator.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace axistune::sim {

Result<model::Capture> simulateCut(const AxisDefinition& axisDef, const CutSimulationOptions& o)
{
    if (axisDef.kind != AxisKind::Linear)
        return makeError(ErrorCode::BadInput, "axis " + axisDef.name + ": a cut needs a linear feed axis");
    if (!(o.durationS > 0.0) || !std::isfinite(o.durationS) || !(o.engageS >= 0.0) || !std::isfinite(o.engageS))
        return makeError(ErrorCode::BadInput, "cut: the duration must be positive and the engage time non-negative");
    auto proc = MillingProcess::create(o.milling);
    if (!proc)
        return proc.error();
    auto created = AxisSimulator::create(axisDef, o.seed);
    if (!created)
        return created.error();
    auto& axis = *created.value();
    auto process = std::make_shared<MillingProcess>(proc.value());

    // Feed motion: accelerate to the feed rate f_z N n / 60 before the tool engages, then cut at constant feed.
    const auto& ms = o.milling;
    const double feed = ms.feedPerToothM * ms.teeth * ms.spindleRpm / 60.0;
    MotionProfile profile(0.0);
    profile.move(feed * (o.durationS + 1.0), std::max(feed, 1e-9), std::max(feed / (0.5 * o.engageS + 1e-6), 1e-6));
    Nonlinearities nl = axis.nonlinearities();
    nl.lostMotion = o.lostMotion;
    axis.setNonlinearities(nl);
    axis.reset(0.0);
    axis.setControlMode(ControlMode::Position);
    axis.setPositionProfile(profile);
    // Force on the table along +x = −(force on the tool); load torque = R · force (R = lead per radian).
    const double lead = axis.parameter("plant.screw_lead");
    const double h = axis.currentPeriod();
    auto forces = std::make_shared<std::vector<double>>();
    auto tools = std::make_shared<std::vector<double>>();
    const double engage = o.engageS;
    axis.setLoadTorque([process, forces, tools, lead, h, engage](double t) {
        double tableForce = 0.0;
        if (t + h > engage)
            tableForce = -process->advanceTo(t + h - engage);
        forces->push_back(tableForce);
        tools->push_back(process->toolX());
        return lead * tableForce;
    });
    axis.startTrace();
    axis.run(o.durationS);
    model::Capture cap = axis.takeTrace();
    // The process signals at the trace instants (the hook ran once per current-loop period).
    const auto* t = cap.channel("t_s");
    if (!t)
        return makeError(ErrorCode::Internal, "trace without t_s");
    model::Channel cf{"cutting_force_N", {}}, tv{"tool_x_m", {}};
    for (double ti : t->data) {
        const auto k = static_cast<std::size_t>(std::llround(ti / h));
        cf.data.push_back(k < forces->size() ? (*forces)[k] : 0.0);
        tv.data.push_back(k < tools->size() ? (*tools)[k] : 0.0);
    }
    cap.channels.push_back(std::move(cf));
    cap.channels.push_back(std::move(tv));
    cap.metadata["test"] = "simulate-cut";
    cap.metadata["teeth"] = std::to_string(ms.teeth);
    cap.metadata["lost_motion"] = o.lostMotion ? "on" : "off";
    cap.metadata["cutting_force_sign"] = "force of the process on the table along +axis";
    return cap;
}

}  // namespace axistune::sim

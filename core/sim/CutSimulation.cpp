// SPDX-License-Identifier: GPL-3.0-or-later
// Milling cut on a simulated feed axis: the feed motion, the process force as a load torque, the process
// signals in the trace (CutSimulation.h; spec/chatter-stability-and-spindle-speed.md for the process).
#include "core/sim/CutSimulation.h"

#include "core/model/MetadataKeys.h"
#include "core/sim/AxisSimulator.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
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
    struct Recorded {
        std::vector<double> force, tool, accelY, rpm, rpmCmd;
        std::vector<std::vector<double>> probes;
    };
    auto rec = std::make_shared<Recorded>();
    rec->probes.resize(o.probeChannels.size());
    auto probeNow = std::make_shared<std::vector<double>>(o.probeChannels.size(), 0.0);
    const double engage = o.engageS;
    const double ts = o.controllerPeriodS;
    auto nextSample = std::make_shared<long long>(1);
    AxisSimulator* ax = &axis;
    auto controller = o.controller;
    axis.setLoadTorque([process, rec, probeNow, lead, h, engage, ts, nextSample, ax, controller](double t) {
        // The process runs from the engagement on (process time = machine time − engage). The controller
        // samples at n·t_s of machine time from the start (within the step resolution of the process), so
        // that its filters and observers are settled when the tool enters the material.
        const double t0 = process->time();
        double impulse = 0.0;
        auto advance = [&](double machineT) {
            if (machineT <= engage)
                return;
            const double ta = process->time();
            const double f = process->advanceTo(machineT - engage);
            impulse += f * (process->time() - ta);
        };
        if (controller && ts > 0.0) {
            while (static_cast<double>(*nextSample) * ts <= t + h * (1.0 + 1e-6)) {
                const double tk = static_cast<double>(*nextSample) * ts;
                advance(tk);
                CutProbe p;
                p.timeS = tk;
                p.toolAccelX = process->toolAccelX();
                p.toolAccelY = process->toolAccelY();
                p.tablePositionM = ax->tablePosition();
                p.thrustCommandN = ax->torqueCommand() / lead;
                p.spindleRpm = process->spindleRpm();
                p.spindleCmdRpm = process->spindleCommandRpm();
                process->setSpindleCommandRpm(controller(p, std::span<double>(*probeNow)));
                ++*nextSample;
            }
        }
        advance(t + h);
        const double dt = process->time() - t0;
        double tableForce = 0.0;
        if (t + h > engage)
            tableForce = dt > 0.0 ? -impulse / dt : -process->forceX();
        rec->force.push_back(tableForce);
        rec->tool.push_back(process->toolX());
        rec->accelY.push_back(process->toolAccelY());
        rec->rpm.push_back(process->spindleRpm());
        rec->rpmCmd.push_back(process->spindleCommandRpm());
        for (std::size_t i = 0; i < probeNow->size(); ++i)
            rec->probes[i].push_back((*probeNow)[i]);
        return lead * tableForce;
    });
    axis.startTrace();
    const double chunk = 0.05;
    for (double done = 0.0; done < o.durationS - 1e-12;) {
        const double d = std::min(chunk, o.durationS - done);
        axis.run(d);
        done += d;
        if (o.progress && !o.progress(done))
            return makeError(ErrorCode::Aborted, "cut aborted at " + std::to_string(done) + " s");
    }
    model::Capture cap = axis.takeTrace();
    // The process signals at the trace instants (the hook ran once per current-loop period).
    const auto* t = cap.channel("t_s");
    if (!t)
        return makeError(ErrorCode::Internal, "trace without t_s");
    auto sampled = [&](const std::string& name, const std::vector<double>& v) {
        model::Channel c{name, {}};
        c.data.reserve(t->data.size());
        for (double ti : t->data) {
            const auto k = static_cast<std::size_t>(std::llround(ti / h));
            c.data.push_back(k < v.size() ? v[k] : (v.empty() ? 0.0 : v.back()));
        }
        return c;
    };
    std::vector<model::Channel> extra;
    extra.push_back(sampled("cutting_force_N", rec->force));
    extra.push_back(sampled("tool_x_m", rec->tool));
    extra.push_back(sampled("tool_accel_y_m_s2", rec->accelY));
    extra.push_back(sampled("spindle_speed_rpm", rec->rpm));
    extra.push_back(sampled("spindle_speed_cmd_rpm", rec->rpmCmd));
    for (std::size_t i = 0; i < o.probeChannels.size(); ++i)
        extra.push_back(sampled(o.probeChannels[i], rec->probes[i]));
    for (auto& c : extra)
        cap.channels.push_back(std::move(c));
    cap.metadata.set(model::meta::kSpindleCommandLimited, process->commandLimitCount());
    cap.metadata.set(model::meta::kTest, "simulate-cut");
    cap.metadata.set("teeth", static_cast<double>(ms.teeth));
    cap.metadata.set("lost_motion", o.lostMotion ? "on" : "off");
    cap.metadata.set(model::meta::kCuttingForceSign, "force of the process on the table along +axis");
    return cap;
}

} // namespace axistune::sim

// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli simulate-cut: a milling cut with regeneration on a simulated feed axis (core/sim/Milling
// coupled to the AxisSimulator through its load-torque input), written as a capture CSV (docs/machining.md).
#include "app/cli/CliCommand.h"
#include "core/model/Units.h"
#include "core/io/CaptureCsv.h"
#include "core/machining/MachiningJson.h"
#include "core/sim/CutSimulation.h"
#include "core/sim/MachineDefinition.h"
#include "core/sim/Milling.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

namespace axistune::cli {
namespace {

struct SimulateCutArgs {
    std::string machine, axis, tool, cut, out;
    double rpm = 0.0, depthM = 0.0, durationS = 1.0, feedPerToothM = 0.1e-3, engageS = 0.2;
    std::uint64_t seed = 1;
    bool lostMotion = false;
};

std::string num(double v) { return model::formatNumber(v, 17); }

int runSimulateCut(const SimulateCutArgs& a)
{
    const std::string cmd = "simulate-cut";
    auto def = a.machine.size() > 5 && a.machine.substr(a.machine.size() - 5) == ".json"
                   ? sim::loadMachineDefinitionFile(a.machine)
                   : sim::loadPreset(a.machine);
    if (!def)
        return reportError(cmd, makeError(ErrorCode::BadInput, "--machine '" + a.machine + "': " + def.error().detail));
    const auto* axisDef = def->axis(a.axis);
    if (!axisDef)
        return reportError(
            cmd, makeError(ErrorCode::NotFound, "--axis '" + a.axis + "': machine " + def->name + " has no such axis"));
    if (axisDef->kind != sim::AxisKind::Linear)
        return reportError(cmd,
                           makeError(ErrorCode::BadInput, "--axis '" + a.axis + "': a cut needs a linear feed axis"));
    auto tool = machining::readToolJsonFile(a.tool);
    if (!tool)
        return reportError(cmd, tool.error());
    auto cut = machining::readCutJsonFile(a.cut);
    if (!cut)
        return reportError(cmd, cut.error());
    if (!(a.durationS > 0.0) || a.durationS > 60.0)
        return reportError(
            cmd, makeError(ErrorCode::OutOfRange, "--duration-s must be in (0, 60] (got " + num(a.durationS) + ")"));
    if (!(a.engageS >= 0.0) || a.engageS >= a.durationS)
        return reportError(cmd, makeError(ErrorCode::OutOfRange, "--engage-s must be in [0, duration)"));

    sim::MillingSetup ms;
    for (const auto& m : tool->modesX)
        ms.modesX.push_back({m.massKg, m.dampingNsPerM, m.stiffnessNPerM});
    for (const auto& m : tool->modesY)
        ms.modesY.push_back({m.massKg, m.dampingNsPerM, m.stiffnessNPerM});
    ms.teeth = cut->teeth;
    ms.ktNPerM2 = cut->ktNPerM2;
    ms.krNPerM2 = cut->krNPerM2;
    ms.radialImmersion = cut->radialImmersion;
    ms.upMilling = cut->milling == machining::MillingDirection::Up;
    ms.spindleRpm = a.rpm;
    ms.axialDepthM = a.depthM;
    ms.feedPerToothM = a.feedPerToothM;
    sim::CutSimulationOptions opt;
    opt.milling = ms;
    opt.durationS = a.durationS;
    opt.engageS = a.engageS;
    opt.lostMotion = a.lostMotion;
    opt.seed = a.seed;
    auto simulated = sim::simulateCut(*axisDef, opt);
    if (!simulated)
        return reportError(cmd, makeError(simulated.error().code, "--tool/--cut/--rpm/--depth-m: " + simulated.error().detail));
    model::Capture cap = std::move(simulated).value();
    cap.metadata["machine"] = def->name;
    cap.metadata["connection"] = "sim:" + def->name;
    cap.metadata["spindle_rpm"] = num(a.rpm);
    cap.metadata["axial_depth_m"] = num(a.depthM);
    cap.metadata["feed_per_tooth_m"] = num(a.feedPerToothM);
    cap.metadata["tooth_frequency_Hz"] = num(a.rpm * ms.teeth / 60.0);
    cap.metadata["engage_s"] = num(a.engageS);
    if (auto st = io::writeCaptureCsvFile(a.out, cap); !st)
        return reportError(cmd, st.error());
    return 0;
}

const CliRegistrar kRegistrar{{
    "simulate-cut",
    "Simulated milling cut with regeneration on a feed axis → capture CSV (feed-axis trace + cutting force)",
    [](CLI::App& sub) -> std::function<int()> {
        auto a = std::make_shared<SimulateCutArgs>();
        sub.add_option("--machine", a->machine, "machine preset (e.g. vmc) or machine .json file")->required();
        sub.add_option("--axis", a->axis, "linear feed axis (x = feed direction of the tool model)")->required();
        sub.add_option("--tool", a->tool, "tool.json (modes_x, modes_y)")->required();
        sub.add_option("--cut", a->cut, "cut.json (teeth, Kt_N_per_m2, Kr_N_per_m2, radial_immersion, milling)")
            ->required();
        sub.add_option("--rpm", a->rpm, "spindle speed [min^-1]")->required();
        sub.add_option("--depth-m", a->depthM, "axial depth of cut [m]")->required();
        sub.add_option("--duration-s", a->durationS, "traced machine time [s] (default 1)");
        sub.add_option("--engage-s", a->engageS, "time the tool enters the material [s] (default 0.2)");
        sub.add_option("--feed-per-tooth-m", a->feedPerToothM, "feed per tooth [m] (default 1e-4)");
        sub.add_option("--seed", a->seed, "simulator seed (default 1)");
        sub.add_flag("--lost-motion", a->lostMotion, "keep the quasi-static lost-motion deflection (default off)");
        sub.add_option("--out", a->out, "capture CSV to write")->required();
        return [a] { return runSimulateCut(*a); };
    },
}};

} // namespace
} // namespace axistune::cli

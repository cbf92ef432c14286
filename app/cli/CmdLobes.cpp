// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli lobes: stability lobe table by semi-discretization (docs/machining.md).
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/machining/MachiningJson.h"
#include "core/machining/StabilityLobes.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

namespace axistune::cli {
namespace {

struct LobesArgs {
    std::string tool, cut, out;
    double rpmMin = 0.0, rpmMax = 0.0, rpmStep = 0.0;
    int steps = 40;
    double depthMaxMm = 50.0;
    int threads = 2;
};

int runLobes(const LobesArgs& a)
{
    const std::string cmd = "lobes";
    auto tool = machining::readToolJsonFile(a.tool);
    if (!tool)
        return reportError(cmd, tool.error());
    auto cut = machining::readCutJsonFile(a.cut);
    if (!cut)
        return reportError(cmd, cut.error());
    auto grid = machining::rpmGrid(a.rpmMin, a.rpmMax, a.rpmStep);
    if (!grid)
        return reportError(cmd, grid.error());
    machining::LobeOptions opt;
    opt.stepsPerPeriod = a.steps;
    opt.depthMaxM = a.depthMaxMm * 1e-3;
    opt.threads = a.threads;
    auto lobes = machining::stabilityLobes(*tool, *cut, *grid, opt);
    if (!lobes)
        return reportError(cmd, lobes.error());
    std::ofstream file;
    std::ostream* os = &std::cout;
    if (!a.out.empty()) {
        file.open(a.out);
        if (!file)
            return reportError(cmd, makeError(ErrorCode::Io, a.out + ": cannot write"));
        os = &file;
    }
    *os << "rpm,limit_depth_m\n";
    char line[96];
    for (const auto& p : *lobes) {
        if (std::isinf(p.limitDepthM))
            std::snprintf(line, sizeof line, "%.10g,inf\n", p.rpm);
        else
            std::snprintf(line, sizeof line, "%.10g,%.9e\n", p.rpm, p.limitDepthM);
        *os << line;
    }
    if (!*os)
        return reportError(cmd, makeError(ErrorCode::Io, (a.out.empty() ? "stdout" : a.out) + ": write failed"));
    return 0;
}

const CliRegistrar kRegistrar{{
    "lobes",
    "Stability lobes (limit axial depth vs spindle speed) by semi-discretization → CSV rpm,limit_depth_m",
    [](CLI::App& sub) -> std::function<int()> {
        auto a = std::make_shared<LobesArgs>();
        sub.add_option("--tool", a->tool, "tool.json: modes_x, modes_y lists of mass_kg, damping_Ns_per_m, stiffness_N_per_m")
            ->required();
        sub.add_option("--cut", a->cut, "cut.json: teeth, Kt_N_per_m2, Kr_N_per_m2, radial_immersion (0-1], milling down|up")
            ->required();
        sub.add_option("--rpm-min", a->rpmMin, "lowest spindle speed [min^-1]")->required();
        sub.add_option("--rpm-max", a->rpmMax, "highest spindle speed [min^-1]")->required();
        sub.add_option("--rpm-step", a->rpmStep, "spindle speed step [min^-1]")->required();
        sub.add_option("--steps-per-period", a->steps, "SDM steps per tooth period k (default 40; >= 160 for ~1 %)");
        sub.add_option("--depth-max-mm", a->depthMaxMm, "search limit [mm]; stable up to here is written as inf (default 50)");
        sub.add_option("--threads", a->threads, "worker threads (default 2)");
        sub.add_option("--out", a->out, "output CSV (default stdout)");
        return recordSessions(sub, [a] { return runLobes(*a); });
    },
}};

}  // namespace
}  // namespace axistune::cli

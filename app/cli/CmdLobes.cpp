// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli lobes: stability lobe table by semi-discretization (docs/machining.md).
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/io/FrfCsv.h"
#include "core/machining/MachiningJson.h"
#include "core/machining/StabilityLobes.h"
#include "core/machining/ToolModeFit.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>

namespace axistune::cli {
namespace {

struct LobesArgs {
    std::string tool, cut, out;
    std::string toolFrfX, toolFrfY;  ///< alternative to --tool: measured tool-tip receptance FRFs [m/N]
    int modes = 1;
    double frfMinHz = 0.0, frfMaxHz = std::numeric_limits<double>::infinity();
    double rpmMin = 0.0, rpmMax = 0.0, rpmStep = 0.0;
    int steps = 40;
    double depthMaxMm = 50.0;
    int threads = 2;
};

// Fits the modes of one direction to a receptance FRF CSV; a summary goes to stderr.
Result<std::vector<machining::ModalParameters>> fitDirection(const LobesArgs& a, const std::string& path, const char* dir)
{
    auto frf = io::readFrfCsvFile(path);
    if (!frf)
        return frf.error();
    machining::ToolModeFitOptions opt;
    opt.modes = a.modes;
    opt.minHz = a.frfMinHz;
    opt.maxHz = a.frfMaxHz;
    auto fit = machining::fitToolModes(*frf, opt);
    if (!fit)
        return makeError(fit.error().code, path + ": " + fit.error().detail);
    char line[160];
    std::snprintf(line, sizeof line, "lobes: %s from %s: %zu points, rms relative fit error %.3g\n", dir, path.c_str(),
                  fit->points, fit->rmsRelativeError);
    std::cerr << line;
    for (const auto& m : fit->modes) {
        std::snprintf(line, sizeof line, "  mass_kg=%.6g damping_Ns_per_m=%.6g stiffness_N_per_m=%.6g (%.1f Hz, zeta %.4f)\n",
                      m.massKg, m.dampingNsPerM, m.stiffnessNPerM, machining::naturalFrequencyHz(m), machining::dampingRatio(m));
        std::cerr << line;
    }
    return fit->modes;
}

Result<machining::ToolModes> loadTool(const LobesArgs& a)
{
    const bool haveFrf = !a.toolFrfX.empty() || !a.toolFrfY.empty();
    if (!a.tool.empty() && haveFrf)
        return makeError(ErrorCode::BadInput, "--tool and --tool-frf-x/--tool-frf-y are alternatives: give one of them");
    if (!haveFrf) {
        if (a.tool.empty())
            return makeError(ErrorCode::BadInput, "give --tool tool.json or both --tool-frf-x and --tool-frf-y");
        return machining::readToolJsonFile(a.tool);
    }
    if (a.toolFrfX.empty() || a.toolFrfY.empty())
        return makeError(ErrorCode::BadInput, "--tool-frf-x and --tool-frf-y must both be given");
    machining::ToolModes tool;
    auto x = fitDirection(a, a.toolFrfX, "x");
    if (!x)
        return x.error();
    auto y = fitDirection(a, a.toolFrfY, "y");
    if (!y)
        return y.error();
    tool.modesX = std::move(*x);
    tool.modesY = std::move(*y);
    if (auto st = machining::validateTool(tool); !st)
        return st.error();
    return tool;
}

int runLobes(const LobesArgs& a)
{
    const std::string cmd = "lobes";
    auto tool = loadTool(a);
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
    // Composed in memory, then stdout or written atomically (a full disk never leaves half a file).
    std::ostringstream text;
    std::ostream* os = &text;
    *os << "rpm,limit_depth_m\n";
    char line[96];
    for (const auto& p : *lobes) {
        if (std::isinf(p.limitDepthM))
            std::snprintf(line, sizeof line, "%.10g,inf\n", p.rpm);
        else
            std::snprintf(line, sizeof line, "%.10g,%.9e\n", p.rpm, p.limitDepthM);
        *os << line;
    }
    return writeResult(cmd, text.str(), a.out);
}

const CliRegistrar kRegistrar{{
    "lobes",
    "Stability lobes (limit axial depth vs spindle speed) by semi-discretization → CSV rpm,limit_depth_m",
    [](CLI::App& sub) -> std::function<int()> {
        auto a = std::make_shared<LobesArgs>();
        sub.add_option("--tool", a->tool, "tool.json: modes_x, modes_y lists of mass_kg, damping_Ns_per_m, stiffness_N_per_m");
        sub.add_option("--tool-frf-x", a->toolFrfX,
                       "instead of --tool: measured tool-tip receptance FRF CSV in x (feed), h in m/N; modes are fitted");
        sub.add_option("--tool-frf-y", a->toolFrfY, "instead of --tool: the same in y");
        sub.add_option("--modes", a->modes, "modes fitted per direction to --tool-frf-x/-y (default 1)");
        sub.add_option("--frf-min-hz", a->frfMinHz, "fit band lower edge [Hz] (default: all points)");
        sub.add_option("--frf-max-hz", a->frfMaxHz, "fit band upper edge [Hz] (default: all points)");
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

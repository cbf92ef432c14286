// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli lobes: stability lobe table by semi-discretization (docs/machining.md).
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/io/FrfCsv.h"
#include "core/machining/ExponentialWindow.h"
#include "core/machining/MachiningJson.h"
#include "core/machining/StabilityLobes.h"
#include "core/machining/ToolModeFit.h"
#include "core/model/Number.h"
#include "core/model/Units.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <nlohmann/json.hpp>

namespace axistune::cli {
namespace {

struct LobesArgs {
    std::string tool, cut, out;
    std::string toolFrfX, toolFrfY;  ///< alternative to --tool: measured tool-tip receptance FRFs [m/N]
    int modes = 0;                   ///< 0: one per significant resonance peak
    std::string band;                ///< "FMIN:FMAX" [Hz]; empty: automatic
    double frfMinHz = std::numeric_limits<double>::quiet_NaN(), frfMaxHz = std::numeric_limits<double>::quiet_NaN();
    double rpmMin = 0.0, rpmMax = 0.0, rpmStep = 0.0;
    int steps = 40;
    double depthMaxMm = 50.0;
    int threads = 2;
};

// "FMIN:FMAX" in Hz ('.' decimal point, no locale).
Result<std::pair<double, double>> parseBand(const std::string& text)
{
    const auto colon = text.find(':');
    auto num = [](std::string_view t, double& v) {
        const auto x = model::parseNumber(t);
        if (x)
            v = *x;
        return x.has_value();
    };
    double lo = 0.0, hi = 0.0;
    const std::string_view all(text);
    if (colon == std::string::npos || !num(all.substr(0, colon), lo) || !num(all.substr(colon + 1), hi))
        return makeError(ErrorCode::BadInput, "--band '" + text + "': expected FMIN:FMAX in Hz, e.g. --band 900:3000");
    if (!(lo >= 0.0) || !(hi > lo))
        return makeError(ErrorCode::OutOfRange, "--band '" + text + "': need 0 <= FMIN < FMAX");
    return std::pair{lo, hi};
}

// Fits the modes of one direction to a receptance FRF CSV (core/machining/ToolModeFit.h: automatic band and
// mode count unless given, quality gate); a summary goes to stderr. A refused fit is an error (exit 2).
Result<std::vector<machining::ModalParameters>> fitDirection(const LobesArgs& a, const std::string& path, const char* dir)
{
    using model::formatNumber;
    auto frf = io::readFrfCsvFile(path);
    if (!frf)
        return frf.error();
    machining::ToolModeFitOptions opt;
    opt.modes = a.modes;
    opt.minHz = a.frfMinHz;
    opt.maxHz = a.frfMaxHz;
    if (!a.band.empty()) {
        if (!std::isnan(a.frfMinHz) || !std::isnan(a.frfMaxHz))
            return makeError(ErrorCode::BadInput,
                             "--band and --frf-min-hz/--frf-max-hz are alternatives: give one of them");
        auto band = parseBand(a.band);
        if (!band)
            return band.error();
        opt.minHz = band->first;
        opt.maxHz = band->second;
    }
    auto fit = machining::fitToolModes(*frf, opt);
    if (!fit)
        return makeError(fit.error().code, path + ": " + fit.error().detail);
    // A tap-test FRF measured with an exponential window (frf --impact --exp-tau) carries its decay σ:
    // the damping the window added is taken out of the fitted modes, as the tap page does.
    std::vector<machining::ModalParameters> modes = fit->modes;
    if (auto st = machining::removeExponentialWindow(modes, *frf); !st)
        return makeError(st.error().code, path + ": " + st.error().detail);
    std::cerr << "lobes: " << dir << " from " << path << ": " << fit->modes.size() << " mode(s) in the "
              << (fit->automaticBand ? "automatic" : "given") << " band " << formatNumber(fit->bandMinHz, 6) << " to "
              << formatNumber(fit->bandMaxHz, 6) << " Hz, " << fit->points << " points, weighted residual "
              << formatNumber(100.0 * fit->residualRatio, 3) << " % (accepted up to "
              << formatNumber(100.0 * opt.maxResidual, 3) << " %)\n";
    for (const auto& m : modes)
        std::cerr << "  mass_kg=" << formatNumber(m.massKg, 6)
                  << " damping_Ns_per_m=" << formatNumber(m.dampingNsPerM, 6)
                  << " stiffness_N_per_m=" << formatNumber(m.stiffnessNPerM, 6) << " ("
                  << formatNumber(machining::naturalFrequencyHz(m), 5) << " Hz, zeta "
                  << formatNumber(machining::dampingRatio(m), 4) << ")\n";
    std::cerr << "  residual terms (not used by the lobes): upper " << formatNumber(fit->upperResidual.real(), 4)
              << " + j·" << formatNumber(fit->upperResidual.imag(), 4) << " m/N, lower "
              << formatNumber(fit->lowerResidual, 4) << " m/N·(rad/s)^2\n";
    return modes;
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
    for (const auto& p : *lobes) {
        *os << model::formatNumber(p.rpm, 10) << ','
            << (std::isinf(p.limitDepthM) ? std::string("inf") : model::formatScientific(p.limitDepthM, 9)) << '\n';
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
        sub.add_option("--modes", a->modes,
                       "modes fitted per direction to --tool-frf-x/-y (default 0: one per resonance peak above 25 % of "
                       "the largest)");
        sub.add_option("--band", a->band, "fit band FMIN:FMAX [Hz] (default: chosen from the resonance peaks)");
        sub.add_option("--frf-min-hz", a->frfMinHz,
                       "fit band lower edge [Hz] (instead of --band; the upper edge is then the data's end)");
        sub.add_option("--frf-max-hz", a->frfMaxHz, "fit band upper edge [Hz] (instead of --band)");
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

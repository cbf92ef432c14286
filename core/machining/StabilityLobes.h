// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Milling stability lobes by the semi-discretization method (spec/chatter-stability-and-spindle-speed.md §2).
// The monodromy matrix over one tooth period is built with the shift structure of the lifted system
// (only the tool-state rows are multiplied; the delay rows are a ring of row blocks), and its spectral
// radius decides stability. The limit depth is the smallest a_p with ρ(F) = 1 found by bracketing and a
// safeguarded secant search on log ρ versus log a_p. Speeds run in parallel on std::thread.

#include "core/machining/ToolModel.h"
#include "core/model/Result.h"

#include <vector>

namespace axistune::machining {

struct LobeOptions {
    int stepsPerPeriod = 40;     ///< k: time steps per tooth period (spec §2.8: Δt ≤ ~40 µs for 3-digit accuracy)
    double depthMaxM = 0.05;     ///< search limit; a speed stable up to here reports +infinity
    double depthGuessM = 1e-3;   ///< first trial depth when no neighbouring result is known
    double relTolerance = 1e-4;  ///< relative width of the final depth bracket
    int threads = 2;             ///< worker threads (spindle speeds are shared out dynamically)
};

struct LobePoint {
    double rpm = 0.0;
    double limitDepthM = 0.0;  ///< +infinity when stable up to depthMaxM
};

/// Spectral radius of the monodromy matrix over one tooth period at spindle speed rpm and depth a_p.
Result<double> monodromySpectralRadius(const ToolModes& tool, const CuttingConditions& cut, double rpm,
                                       double depthM, int stepsPerPeriod);

/// Self-excited and forced chatter indices of spec §2.5/§2.6 at one operating point:
/// lambda = ρ(F), sigma = σ_max(H (I − F)⁻¹ G) with H the y-position history and G the feed input
/// (static chip per unit feed per tooth, so sigma is in m of y displacement per m of feed per tooth).
struct ChatterIndices {
    double lambda = 0.0;
    double sigma = 0.0;  ///< +infinity when lambda ≥ 1
};
Result<ChatterIndices> chatterIndices(const ToolModes& tool, const CuttingConditions& cut, double rpm, double depthM,
                                      int stepsPerPeriod);

/// Limit axial depth [m] at one spindle speed.
Result<double> limitDepth(const ToolModes& tool, const CuttingConditions& cut, double rpm, const LobeOptions& opt);

/// Limit depths for a list of spindle speeds (rpm > 0), computed in parallel.
Result<std::vector<LobePoint>> stabilityLobes(const ToolModes& tool, const CuttingConditions& cut,
                                              const std::vector<double>& rpms, const LobeOptions& opt);

/// rpm grid min, min+step, ... ≤ max (+ half a step of rounding slack). Errors on non-positive values.
Result<std::vector<double>> rpmGrid(double rpmMin, double rpmMax, double rpmStep);

}  // namespace axistune::machining

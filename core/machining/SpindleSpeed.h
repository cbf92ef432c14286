// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Spindle-speed advice from a chatter frequency (spec/chatter-stability-and-spindle-speed.md §3.0.2, §3.1, §6.3).

#include "core/machining/StabilityLobes.h"
#include "core/machining/ToolModel.h"
#include "core/model/Result.h"

#include <optional>
#include <vector>

namespace axistune::machining {

struct PocketCandidate {
    int lobe = 0;                 ///< ρ
    double rpm = 0.0;             ///< 60·f_chat/(ρ·N_t)
    double notchGainAtChatter = 0.0;  ///< |1 − e^{−jωτ}| at f_chat for the current speed's neighbours (spec Fig. 35)
};

struct PocketAdvice {
    double toothPassingHz = 0.0;  ///< N_t·rpm/60
    double ratio = 0.0;           ///< f_chat / f_TPE
    int lobe = 0;                 ///< ρ_new = round half up (eq. (1-21))
    double rpm = 0.0;             ///< n_new (eq. (1-22))
    double notchGainNow = 0.0;    ///< 2|sin(π f_chat τ_now)|
    std::vector<PocketCandidate> candidates;  ///< ρ−1, ρ, ρ+1 (ρ ≥ 1)
};

/// The stable-pocket rule. Errors on non-positive or non-finite inputs, or when the ratio rounds to 0.
Result<PocketAdvice> pocketAdvice(double chatterHz, double rpm, int teeth);

struct CostOptions {
    double depthM = 0.0;      ///< axial depth at which the cost is evaluated
    double alpha = 2.0;       ///< forced-chatter weight (Table 3)
    double beta = 1.0;        ///< self-excited weight (Table 3)
    double tauNormS = 0.014;  ///< λ normalised to this period (Fig. 23); 0 = no normalisation
    int stepsPerPeriod = 40;
    double rpmStep = 5.0;
    int threads = 2;
};

struct LobeCostAdvice {
    int lobe = 0;
    double rpmSearchMin = 0.0, rpmSearchMax = 0.0;  ///< the speeds of lobe ρ searched
    std::optional<double> bestRpm;                  ///< argmin J_ρ (empty: unstable everywhere at this depth)
    double bestCostDb = 0.0;
    double lambdaAtBest = 0.0, sigmaAtBest = 0.0;
    double gamma = 0.0;                             ///< bestRpm / n_new (eq. (3-32) with ω_n → 2π f_chat)
    double peakLimitRpm = 0.0, peakLimitDepthM = 0.0;  ///< highest lobe limit in the searched range
};

/// Chapter-3 cost J_ρ = 20α log10 σ − 20β log10(1 − λ_norm) (eq. (3-30)) scanned over the speeds of lobe ρ
/// (between the pocket speeds of ρ+½ and ρ−½ for f_chat), plus the lobe-limit peak in the same range.
Result<LobeCostAdvice> lobeCostAdvice(const ToolModes& tool, const CuttingConditions& cut, double chatterHz, int lobe,
                                      const CostOptions& opt);

}  // namespace axistune::machining

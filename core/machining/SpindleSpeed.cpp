// SPDX-License-Identifier: GPL-3.0-or-later
// Stable-pocket rule ρ = round(f_chat/f_TPE), n = 60 f_chat/(ρ N_t) (spec §3.0.2, eqs. (1-20)–(1-23)), and the
// SDM-based cost of Method 1 (spec §3.1, eq. (3-30)) evaluated over the speeds of one lobe.
#include "core/machining/SpindleSpeed.h"

#include <cmath>
#include <numbers>
#include <string>

namespace axistune::machining {

namespace {
double notchGain(double fHz, double rpm, int teeth)
{
    const double tau = 60.0 / (rpm * teeth);
    return 2.0 * std::abs(std::sin(std::numbers::pi * fHz * tau));
}
}  // namespace

Result<PocketAdvice> pocketAdvice(double chatterHz, double rpm, int teeth)
{
    if (!(chatterHz > 0.0) || !std::isfinite(chatterHz))
        return makeError(ErrorCode::OutOfRange, "chatter frequency must be > 0 Hz");
    if (!(rpm > 0.0) || !std::isfinite(rpm))
        return makeError(ErrorCode::OutOfRange, "spindle speed must be > 0 rpm");
    if (teeth < 1 || teeth > 100)
        return makeError(ErrorCode::OutOfRange, "teeth must be between 1 and 100");
    PocketAdvice a;
    a.toothPassingHz = teeth * rpm / 60.0;
    a.ratio = chatterHz / a.toothPassingHz;
    a.lobe = static_cast<int>(std::floor(a.ratio + 0.5));  // 四捨五入: round half up
    if (a.lobe < 1)
        return makeError(ErrorCode::OutOfRange, "chatter frequency " + std::to_string(chatterHz) +
                                                    " Hz is below half the tooth-passing frequency: no lobe number");
    a.rpm = 60.0 * chatterHz / (a.lobe * teeth);
    a.notchGainNow = notchGain(chatterHz, rpm, teeth);
    for (int l = std::max(1, a.lobe - 1); l <= a.lobe + 1; ++l) {
        const double r = 60.0 * chatterHz / (l * teeth);
        a.candidates.push_back({l, r, notchGain(chatterHz, r, teeth)});
    }
    return a;
}

Result<LobeCostAdvice> lobeCostAdvice(const ToolModes& tool, const CuttingConditions& cut, double chatterHz, int lobe,
                                      const CostOptions& opt)
{
    if (!(chatterHz > 0.0) || lobe < 1 || !(opt.depthM > 0.0) || !(opt.rpmStep > 0.0))
        return makeError(ErrorCode::OutOfRange, "cost search needs f_chat > 0, lobe >= 1, depth > 0 and rpm step > 0");
    LobeCostAdvice out;
    out.lobe = lobe;
    const double toRpm = 60.0 * chatterHz / cut.teeth;
    out.rpmSearchMin = toRpm / (lobe + 0.5);
    out.rpmSearchMax = toRpm / (lobe - 0.5);
    std::vector<double> rpms;
    for (double r = out.rpmSearchMin; r <= out.rpmSearchMax; r += opt.rpmStep)
        rpms.push_back(r);
    if (rpms.size() > 5000)
        return makeError(ErrorCode::OutOfRange, "cost search: more than 5000 speeds; increase the rpm step");
    LobeOptions lo;
    lo.stepsPerPeriod = opt.stepsPerPeriod;
    lo.threads = opt.threads;
    auto lobes = stabilityLobes(tool, cut, rpms, lo);
    if (!lobes)
        return lobes.error();
    double bestJ = std::numeric_limits<double>::infinity();
    for (const auto& p : *lobes) {
        if (p.limitDepthM > out.peakLimitDepthM)
            out.peakLimitDepthM = p.limitDepthM, out.peakLimitRpm = p.rpm;
        if (p.limitDepthM <= opt.depthM)
            continue;  // J is defined only where the cut is stable
        auto ci = chatterIndices(tool, cut, p.rpm, opt.depthM, opt.stepsPerPeriod);
        if (!ci)
            return ci.error();
        if (ci->lambda >= 1.0 || !(ci->sigma > 0.0))
            continue;
        const double tau = 60.0 / (p.rpm * cut.teeth);
        const double lam = opt.tauNormS > 0.0 ? std::pow(ci->lambda, opt.tauNormS / tau) : ci->lambda;
        if (lam >= 1.0)
            continue;
        const double j = 20.0 * opt.alpha * std::log10(ci->sigma) - 20.0 * opt.beta * std::log10(1.0 - lam);
        if (j < bestJ) {
            bestJ = j;
            out.bestRpm = p.rpm;
            out.bestCostDb = j;
            out.lambdaAtBest = ci->lambda;
            out.sigmaAtBest = ci->sigma;
        }
    }
    if (out.bestRpm)
        out.gamma = *out.bestRpm / (toRpm / lobe);
    return out;
}

}  // namespace axistune::machining

// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli two-inertia: two-inertia fit of a torque → motor-velocity FRF, F_m/F_L settings,
// velocity PI and position-gain limit on the fitted model, predicted load error (docs/tuning.md).
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/dsp/InjectionHold.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/io/FrfCsv.h"
#include "core/model/Constants.h"
#include "core/model/MetadataKeys.h"
#include "core/model/ResultJson.h"
#include "core/tuning/TwoInertia.h"
#include "core/tuning/TwoInertiaFilter.h"
#include "core/tuning/VelocityLoop.h"
#include "core/tuning/VelocityLoopDesign.h"

#include <cmath>
#include <complex>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>

namespace axistune::cli {

namespace {

using model::kTwoPi;

struct TwoInertiaOptions {
    std::string frfPath;
    std::string outPath;
    tuning::TwoInertiaFitOptions fit;
    std::string mode = "semi";
    double tauS = 0.0;
    double bandwidthHz = tuning::kDefaultVelocityBandwidthHz;
    double staticGain = tuning::kDefaultVelocityGainFactor;
    tuning::MotionProfile profile;
    std::vector<double> loopPi;      ///< KP,KI: the FRF is T = PC/(1+PC) of this velocity PI; fit P
    double loopPeriodS = 250e-6;     ///< velocity-loop period of C(z)
    double injectionPeriodS = 0.0;   ///< period d was applied at, for an uncorrected FRF (0: none)
};

/// P = L / C with L = T/(1−T) and C(z) = K_P + K_I·T_v/(1 − z⁻¹), z = e^{jωT_v} (the simulated
/// drive's velocity PI, integral divider 1, docs/frequency-response-sim.md). Points where T = 1 stay invalid.
/// The drive's FRF is already T (metadata injection_hold_corrected=true). --injection-period-s h is only
/// for a −T_c/d measured with an injection applied every h = T_v/N and not corrected at the source:
/// T = (−T_c/d) / G, G = dsp::injectionHoldFactor(f, h, N); refused for a file that says corrected.
Result<dsp::FrequencyResponse> plantFromComplementary(const dsp::FrequencyResponse& t, const TwoInertiaOptions& o,
                                                      const std::string& path)
{
    if (o.loopPi.size() != 2 || !(o.loopPi[0] >= 0.0) || !(o.loopPi[1] >= 0.0) || !(o.loopPi[0] + o.loopPi[1] > 0.0) ||
        !(o.loopPeriodS > 0.0))
        return makeError(ErrorCode::BadInput, "--loop-pi needs KP,KI >= 0 (not both 0) and --loop-period-s > 0");
    if (const auto* m = t.metadata.find(model::meta::kMeasurement); m && m->text() != "complementary")
        return makeError(ErrorCode::BadInput,
                         path +
                             ": --loop-pi needs a complementary FRF (T = PC/(1+PC)), the file says "
                             "measurement=" +
                             m->text());
    if (!(o.injectionPeriodS >= 0.0))
        return makeError(ErrorCode::BadInput, "--injection-period-s must not be negative");
    dsp::FrequencyResponse corrected = t;
    if (o.injectionPeriodS > 0.0) {
        const double ratio = o.loopPeriodS / o.injectionPeriodS;
        const long n = std::lround(ratio);
        if (n < 1 || std::abs(ratio - static_cast<double>(n)) > 1e-6 * ratio)
            return makeError(ErrorCode::BadInput, "--loop-period-s must be an integer multiple of --injection-period-s");
        if (dsp::isInjectionHoldCorrected(t))
            return makeError(ErrorCode::BadInput, path + ": --injection-period-s: the FRF is already corrected for the "
                                                      "injection hold (injection_hold_corrected=true); leave the option out");
        if (auto st = dsp::correctInjectionHold(corrected, o.injectionPeriodS, static_cast<int>(n)); !st)
            return st.error();
    }
    auto p = dsp::openLoopFromClosedLoop(corrected, dsp::LoopMeasurement::Complementary);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const std::complex<double> zInv = std::polar(1.0, -kTwoPi * p.freqHz[i] * o.loopPeriodS);
        const std::complex<double> c = o.loopPi[0] + o.loopPi[1] * o.loopPeriodS / (1.0 - zInv);
        p.h[i] = p.valid[i] ? p.h[i] / c : std::complex<double>(0.0, 0.0);
    }
    p.metadata.set(model::meta::kLoop, "plant-from-complementary");
    return p;
}

int runTwoInertia(const TwoInertiaOptions& o)
{
    const std::string cmd = "two-inertia";
    if (o.mode != "semi" && o.mode != "full") {
        return reportError(cmd, makeError(ErrorCode::BadInput, "--mode must be 'semi' or 'full', got '" + o.mode + "'"));
    }
    if (!(o.bandwidthHz > 0.0) || !(o.staticGain > 0.0) || o.tauS < 0.0 || !(o.profile.vMax > 0.0) ||
        !(o.profile.aMax > 0.0) || !(o.profile.jerk > 0.0)) {
        return reportError(cmd, makeError(ErrorCode::OutOfRange,
                                          "--bandwidth-hz, --k, --vmax, --accel, --jerk must be > 0 and --tau-s >= 0"));
    }
    auto frf = io::readFrfCsvFile(o.frfPath);
    if (!frf) {
        return reportError(cmd, frf.error());
    }
    dsp::FrequencyResponse data = std::move(frf).value();
    if (!o.loopPi.empty()) {
        auto plant = plantFromComplementary(data, o, o.frfPath);
        if (!plant)
            return reportError(cmd, plant.error());
        data = std::move(plant).value();
    }
    auto fit = tuning::fitTwoInertia(data, o.fit);
    if (!fit) {
        return reportError(cmd, Error{fit.error().code, o.frfPath + ": " + fit.error().detail});
    }
    const auto& p = fit->params;
    const auto mode = o.mode == "full" ? tuning::SuppressionMode::Full : tuning::SuppressionMode::Semi;
    const auto proposal = tuning::twoInertiaProposal(p, mode, o.tauS, o.bandwidthHz, o.staticGain);
    const auto& filter = proposal.filter;
    const auto& pi = proposal.pi;
    const auto fbMode = mode == tuning::SuppressionMode::Full ? tuning::FeedbackMode::Full : tuning::FeedbackMode::Semi;
    const auto posPlain = tuning::positionGain(p, pi, fbMode, std::nullopt, false, tuning::kPositionGainMarginDb);
    std::optional<tuning::SuppressionFilter> inLoop;
    if (mode == tuning::SuppressionMode::Full) {
        inLoop = filter;
    }
    const auto posFilter = tuning::positionGain(p, pi, fbMode, inLoop, false, tuning::kPositionGainMarginDb);
    const auto semiFilter = tuning::suppressionFilterFromModel(p, tuning::SuppressionMode::Semi, 0.0);
    const auto loadError = tuning::predictLoadError(p, semiFilter, o.profile);

    nlohmann::json j;
    j["Jm_kgm2"] = p.jmKgm2;
    j["JL_kgm2"] = p.jlKgm2;
    j["K_Nm_per_rad"] = p.kNmPerRad;
    j["C_Nms_per_rad"] = p.cNmsPerRad;
    j["delay_s"] = p.delayS;
    j["antiresonance_Hz"] = tuning::antiresonanceRadS(p) / kTwoPi;
    j["resonance_Hz"] = tuning::resonanceRadS(p) / kTwoPi;
    j["zeta_zero"] = tuning::zetaZero(p);
    j["zeta_pole"] = tuning::zetaPole(p);
    j["fit_error"] = fit->fitError;
    j["fit"] = {{"fmin_Hz", o.fit.fminHz},
                {"fmax_Hz", o.fit.fmaxHz},
                {"points_used", fit->pointsUsed},
                {"iterations", fit->iterations},
                {"data_antiresonance_Hz", fit->dataAntiresonanceHz},
                {"data_resonance_Hz", fit->dataResonanceHz}};
    j["filter"] = {{"mode", o.mode}, {"f0_Hz", filter.f0Hz}, {"zeta", filter.zeta}, {"tau_s", filter.tauS}};
    j["velocity_pi"] = {{"bandwidth_Hz", o.bandwidthHz},
                        {"k", o.staticGain},
                        {"kp_Nms_per_rad", pi.kpNmsPerRad},
                        {"ki_Nm_per_rad", pi.kiNmPerRad}};
    // A limit that does not exist is left out and named (docs/formats.md "Undefined values").
    const char* noLimit = "no stability limit of the position gain below 1e5 1/s";
    nlohmann::json pg{{"mode", o.mode}};
    model::putNumber(pg, "limit_per_s", posPlain.limitPerS, noLimit);
    model::putNumber(pg, "limit_with_filter_per_s", posFilter.limitPerS, noLimit);
    model::putNumber(pg, "recommended_per_s",
                     mode == tuning::SuppressionMode::Full ? posFilter.recommendedPerS : posPlain.recommendedPerS,
                     noLimit);
    j["position_gain"] = pg;
    // What the two-inertia wizard writes to the drive (keys as `params` names them).
    nlohmann::json params = nlohmann::json::object();
    for (const auto& [key, v] : proposal.parameters)
        params[key] = v;
    j["parameters"] = params;
    j["load_error"] = {{"profile", {{"vmax_rad_s", o.profile.vMax}, {"accel_rad_s2", o.profile.aMax},
                                    {"jerk_rad_s3", o.profile.jerk}}},
                       {"without_filter_rad", loadError.maxErrorWithoutFilter},
                       {"with_filter_rad", loadError.maxErrorWithFilter}};
    return writeJsonResult(cmd, j, o.outPath);
}

const CliRegistrar kRegistrar{CliCommand{
    "two-inertia",
    "Two-inertia fit (J_m, J_L, K, C, delay) of a torque->motor-velocity FRF and F_m/F_L filter settings",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<TwoInertiaOptions>();
        sub.add_option("--frf", o->frfPath, "FRF CSV (f_Hz,re,im,mag_dB,phase_deg,coherence,valid)")->required();
        sub.add_option("--fmin", o->fit.fminHz, "lower end of the fit band [Hz] (default 5)");
        sub.add_option("--fmax", o->fit.fmaxHz, "upper end of the fit band [Hz] (default 300)");
        sub.add_option("--mode", o->mode, "semi (F_m on the position command) or full (F_L in the loop)");
        sub.add_option("--tau-s", o->tauS, "F_L time constant [s] (default: high-frequency gain 2.5)");
        sub.add_option("--min-coherence", o->fit.minCoherence, "ignore points with a lower coherence (default 0)");
        sub.add_option("--bandwidth-hz", o->bandwidthHz, "velocity-loop omega_l/2pi for k = 1 (default 24)");
        sub.add_option("--k", o->staticGain, "velocity-loop static gain k (default 10)");
        sub.add_option("--vmax", o->profile.vMax, "profile speed [rad/s] (default 62.83 = 10 rev/s)");
        sub.add_option("--accel", o->profile.aMax, "profile acceleration [rad/s^2] (default 1256.6 = 200 rev/s^2)");
        sub.add_option("--jerk", o->profile.jerk, "profile jerk [rad/s^3] (default 125660)");
        sub.add_option("--loop-pi", o->loopPi, "KP,KI: the FRF is the closed velocity loop T = PC/(1+PC) of this PI "
                                               "[Nm*s/rad, Nm/rad]; fit P = T/((1-T)C)")
            ->delimiter(',')
            ->expected(2);
        sub.add_option("--loop-period-s", o->loopPeriodS, "velocity-loop period of the PI for --loop-pi (default 250e-6)");
        sub.add_option("--injection-period-s", o->injectionPeriodS,
                       "for --loop-pi and an FRF not corrected at the source (no injection_hold_corrected=true): "
                       "period the injection was applied at, e.g. 62.5e-6 (default 0: taken as is)");
        sub.add_option("--out", o->outPath, "write the JSON to this file instead of stdout");
        return recordSessions(sub, [o] { return runTwoInertia(*o); });
    }}};

}  // namespace

}  // namespace axistune::cli

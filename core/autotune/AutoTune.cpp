// SPDX-License-Identifier: GPL-3.0-or-later
// The one-button tuner's sequence (AutoTune.h; docs/tuning.md "One-button tuning").
#include "core/autotune/AutoTune.h"

#include "core/autotune/AmplitudeMap.h"
#include "core/autotune/AutoTuneRun.h"
#include "core/autotune/SlidingPlant.h"
#include "core/device/AdaptiveFrf.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/model/Number.h"
#include "core/model/ResultJson.h"
#include "core/tuning/CurrentStep.h"
#include "core/tuning/Notch.h"
#include "core/tuning/Resonance.h"
#include "core/tuning/VelocityLoop.h"
#include "core/tuning/VelocityLoopDesign.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>

namespace axistune::autotune {

namespace {

using namespace detail;

/// Non-linear fraction above which the FRF is measured again at twice the amplitude (friction).
constexpr double kRetryNonlinearFraction = 0.05;
/// Voltage-limited fraction above which the FRF is measured again at half the amplitude.
constexpr double kRetryVoltageFraction = 0.2;
constexpr double kMinFrfAmplitudePct = 2.5;
constexpr int kMaxFrfTries = 3;
/// Largest FRF peak the ladder goes to [% rated torque] (and never above the drive's own limit).
constexpr double kLadderPeakCapPct = 30.0;
/// Distance of the reversal that measures the backlash [m] (back and forth).
constexpr double kBacklashReversalM = 0.002;

/// An integer as text, without the locale.
std::string count(long long n)
{
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, n);
    return std::string(buf, r.ptr);
}

bool finitePositive(double v)
{
    return std::isfinite(v) && v > 0.0;
}

struct Margins {
    double phaseMarginDeg = std::numeric_limits<double>::infinity();
    double phaseMarginFreqHz = 0.0;
    double gainMarginDb = std::numeric_limits<double>::infinity();
    double gainMarginFreqHz = 0.0;
    std::size_t gainCrossovers = 0;
};

Margins marginsOf(const std::vector<double>& f, const std::vector<std::complex<double>>& open)
{
    dsp::FrequencyResponse l;
    for (std::size_t i = 0; i < f.size(); ++i)
        l.push(f[i], open[i], std::numeric_limits<double>::quiet_NaN(), true);
    const auto m = dsp::loopMargins(l);
    return {m.phaseMarginDeg, m.phaseMarginFreqHz, m.gainMarginDb, m.gainMarginFreqHz, m.gainCrossovers.size()};
}

nlohmann::json marginsJson(const Margins& m)
{
    nlohmann::json j = nlohmann::json::object();
    model::putOptional(j, "phase_margin_deg",
                       std::isfinite(m.phaseMarginDeg) ? std::optional<double>(m.phaseMarginDeg) : std::nullopt, 1.0,
                       "no gain crossover in the measured band");
    if (std::isfinite(m.phaseMarginDeg))
        j["phase_margin_Hz"] = m.phaseMarginFreqHz;
    model::putOptional(j, "gain_margin_dB",
                       std::isfinite(m.gainMarginDb) ? std::optional<double>(m.gainMarginDb) : std::nullopt, 1.0,
                       "no -180 deg crossing in the measured band");
    if (std::isfinite(m.gainMarginDb))
        j["gain_margin_Hz"] = m.gainMarginFreqHz;
    return j;
}

/// Valid lines of a response.
void validLines(const dsp::FrequencyResponse& r, std::vector<double>& f, std::vector<std::complex<double>>& h)
{
    f.clear();
    h.clear();
    for (std::size_t i = 0; i < r.size(); ++i)
        if (r.valid[i] && std::isfinite(r.h[i].real()) && std::isfinite(r.h[i].imag())) {
            f.push_back(r.freqHz[i]);
            h.push_back(r.h[i]);
        }
}

/// Closed position loop (position feedback K_p/s around the closed velocity loop T_v) on T_v's lines.
std::vector<std::complex<double>> positionClosedLoop(const std::vector<double>& f,
                                                     const std::vector<std::complex<double>>& tv, double kp)
{
    std::vector<std::complex<double>> out(f.size());
    for (std::size_t i = 0; i < f.size(); ++i) {
        const std::complex<double> lp = kp * tv[i] / std::complex<double>(0.0, kTwoPi * f[i]);
        out[i] = lp / (1.0 + lp);
    }
    return out;
}

const model::Channel* channelWithPrefix(const model::Capture& c, const std::string& prefix)
{
    for (const auto& ch : c.channels)
        if (ch.name.rfind(prefix, 0) == 0)
            return &ch;
    return nullptr;
}

class Sequence : public Run {
public:
    using Run::Run;

    Result<AutoTuneResult> run();

private:
    AutoTuneResult aborted(const char* name)
    {
        return refuse(std::string("aborted by the user before the step ") + name, ErrorCode::Aborted);
    }
    /// Runs one test within the budget; a refusal reason on failure.
    Result<device::TestRun> test(const device::TestRequest& r, const std::string& what, double& motionS);

    device::DriveLimits m_limits;
};

Result<device::TestRun> Sequence::test(const device::TestRequest& r, const std::string& what, double& motionS)
{
    auto plan = m_drive.planTest(r);
    if (plan && m_motion + plan->motionTimeS > m_o.timeBudgetS)
        return makeError(ErrorCode::Safety, what + " would take " + num(plan->motionTimeS, 3) + " s of motion, " +
                                                "beyond the time budget (" + num(m_o.timeBudgetS, 3) + " s, " +
                                                num(m_motion, 3) + " s used)");
    auto run = device::runTest(m_drive, r, m_o.run);
    if (!run) {
        const auto& e = run.error();
        if (e.code == ErrorCode::Safety)
            return makeError(ErrorCode::Safety, "drive fault during " + what + ": " + e.detail);
        return makeError(e.code, what + ": " + e.detail);
    }
    double t = plan ? plan->motionTimeS : 0.0;
    if (run->trace) {
        const auto it = run->trace->metadata.find(device::kMotionTimeMetadataKey);
        if (it != run->trace->metadata.end())
            if (auto x = model::parseNumber(it->second))
                t = *x;
    }
    motionS = t;
    m_motion += t;
    return run;
}

struct FrfFigures {
    std::size_t lines = 0, valid = 0, nonlinear = 0;
    std::map<std::string, std::size_t> invalidByReason;
};

FrfFigures figuresOf(const device::AdaptiveFrfResult& a)
{
    FrfFigures f;
    f.lines = a.measurement.frf.size();
    f.valid = a.validLines;
    for (const auto& l : a.invalid) {
        ++f.invalidByReason[device::invalidReasonName(l.reason)];
        if (l.reason == device::InvalidReason::Nonlinear)
            ++f.nonlinear;
    }
    return f;
}

nlohmann::json frfJson(const device::AdaptiveFrfResult& a, double amplitudePct)
{
    const auto f = figuresOf(a);
    nlohmann::json j{{"amplitude_pct", amplitudePct},
                     {"lines", f.lines},
                     {"valid_lines", f.valid},
                     {"passes", a.passes.size()},
                     {"motion_time_s", a.motionTimeS}};
    nlohmann::json by = nlohmann::json::object();
    for (const auto& [k, n] : f.invalidByReason)
        by[k] = n;
    j["invalid_by_reason"] = by;
    return j;
}

Result<AutoTuneResult> Sequence::run()
{
    const std::string& axis = m_o.axis;
    if (!finitePositive(m_o.timeBudgetS))
        return makeError(ErrorCode::BadInput, "the time budget must be > 0 s");
    if (!(m_o.minBandwidthHz >= 0.0) || !std::isfinite(m_o.minBandwidthHz))
        return makeError(ErrorCode::BadInput, "the required bandwidth must be >= 0 Hz (0: the style's)");
    auto caps = m_drive.capabilities(axis);
    if (!caps)
        return caps.error();
    m_caps = *caps;
    if (!m_caps.offers(device::FrfMethod::Multisine) || (!m_caps.evaluatesFrf && m_caps.traceRateHz <= 0.0))
        return makeError(ErrorCode::BadInput, "axis " + axis +
                                                  ": the drive offers no multisine FRF test; the "
                                                  "one-button tuner needs it");
    if (!m_caps.offers(device::TestType::Jog) || !m_caps.offers(device::TestType::Hold))
        return makeError(ErrorCode::BadInput,
                         "axis " + axis + ": the drive offers no jog or hold test (move evaluation)");
    if (!m_caps.writesParameters)
        return makeError(ErrorCode::BadInput, "axis " + axis + ": the drive's parameters cannot be written");
    auto limits = m_drive.limits(axis);
    if (!limits)
        return limits.error();
    m_limits = *limits;
    auto metas = m_drive.parameterMetadata(axis);
    if (!metas)
        return metas.error();
    for (const auto& m : *metas) {
        m_keys.push_back(m.key);
        if (m.writable)
            m_writable.insert(m.key);
    }
    auto before = m_drive.readParameters(axis, m_keys);
    if (!before)
        return before.error();
    m_r.before = *before;
    m_now = *before;
    for (const char* k : {"velocity.kp", "velocity.ki", "velocity.period", "current.period", "position.kp",
                          "motor.torque_constant", "motor.max_current", "motor.rated_current"})
        if (!std::isfinite(value(k)))
            return makeError(ErrorCode::Device, "axis " + axis + ": the drive does not give " + k);

    // ---- 1. Safety envelope -------------------------------------------------------------------------------
    const double ratedA = value("motor.rated_current");
    const double maxTorqueNm = value("motor.torque_constant") * value("motor.max_current");
    double amplitudePct = std::min(m_t.frfAmplitudePct, m_limits.frfAmplitudeMaxPct);
    const double stepA = std::min(0.2 * ratedA, m_limits.currentStepMaxA);
    bool feStop = false;
    for (const auto& k : m_keys)
        feStop = feStop || k.find("following_error") != std::string::npos;
    if (!begin("safety-envelope"))
        return aborted("safety-envelope");
    Step hold;
    hold.name = "safety-envelope";
    {
        device::TestRequest h;
        h.axis = axis;
        h.type = device::TestType::Hold;
        h.durationS = 0.05;
        auto run = test(h, "the standstill check (hold)", hold.motionTimeS);
        if (!run)
            return refuse(run.error().detail, run.error().code);
        hold.measured = {{"max_torque_Nm", maxTorqueNm}, {"standstill_s", h.durationS}};
        for (const auto& [k, v] : {std::pair<const char*, double>{"frf_amplitude_max_pct", m_limits.frfAmplitudeMaxPct},
                                   {"current_step_max_A", m_limits.currentStepMaxA},
                                   {"motor_speed_max_rad_s", m_limits.motorSpeedMaxRadS},
                                   {"travel_window", m_limits.travelWindow}})
            model::putOptional(hold.measured, k, std::isfinite(v) ? std::optional<double>(v) : std::nullopt, 1.0,
                               "the drive sets no limit of its own");
        const auto* pos = run->trace ? channelWithPrefix(*run->trace, "position_cmd_") : nullptr;
        m_linear = pos == nullptr || pos->name.size() < 2 || pos->name.substr(pos->name.size() - 2) == "_m";
    }
    hold.chosen = {{"frf_amplitude_pct", amplitudePct},
                   {"frf_amplitude_max_pct", std::min(kLadderPeakCapPct, m_limits.frfAmplitudeMaxPct)},
                   {"current_step_A", stepA},
                   {"time_budget_s", m_o.timeBudgetS},
                   {"following_error_stop", feStop ? "the drive's" : "not offered by the drive"},
                   {"axis_units", m_linear ? "m" : "rad"}};
    hold.rule = "FRF peak " + num(m_t.frfAmplitudePct, 3) + " % of rated torque (" + styleName(m_o.style) +
                "), at most the drive's limit; current step 20 % of rated current within the drive's limit; every "
                "test planned against the drive's limits and the time budget before it moves; " +
                (feStop ? std::string("the drive's following-error stop stays as set")
                        : std::string("the drive offers no following-error stop: the move evaluation checks "
                                      "the following error afterwards"));
    done(hold);

    // ---- 2. Current loop ----------------------------------------------------------------------------------
    {
        Step s;
        s.name = "current-loop";
        if (!begin("current-loop"))
            return aborted("current-loop");
        const double kp = value("current.kp"), ki = value("current.ki");
        s.measured = {{"running_kp_V_per_A", kp}, {"running_ki_V_per_As", ki}};
        std::optional<double> predictedRise;
        if (m_o.motor) {
            const auto motor = tuning::motorFromDriveParameters(m_now, *m_o.motor);
            tuning::CurrentLoopSettings cs;
            cs.deadTimeS = value("current.period");
            auto d = tuning::designCurrentLoop(motor, cs);
            if (!d)
                return refuse("current loop: " + d.error().detail, d.error().code);
            model::ParameterValues v{{"current.kp", d->gains.kpVPerA}, {"current.ki", d->gains.kiVPerAs}};
            if (m_writable.count("current.alpha"))
                v["current.alpha"] = d->alpha;
            if (auto st = write(v); !st)
                return refuse("current loop: " + st.error().detail, st.error().code);
            for (const auto& [k, x] : v)
                s.chosen[k] = x;
            predictedRise = d->riseTimeS;
            s.rule = "spec chapter 2 design on the motor data (R_a, L_q, delta from the motor file; I_max, V_max, "
                     "k_e = k_t/1.5 from the drive): the fastest step within stability (gain margin " +
                     num(cs.gainMarginDb, 3) + " dB), voltage and " + num(100.0 * cs.overshootMax, 2) +
                     " % overshoot, best alpha";
        } else {
            s.chosen = {{"current.kp", kp}, {"current.ki", ki}};
            s.rule = "kept: the drive states I_max, V_max and k_t but not R_a and L_q, without which the chapter 2 "
                     "design cannot run (give --motor FILE); the running loop is verified by its step";
        }
        if (m_caps.offers(device::TestType::CurrentStep) && m_caps.currentTraceRateHz > 0.0 && stepA > 0.0) {
            device::TestRequest c;
            c.axis = axis;
            c.type = device::TestType::CurrentStep;
            c.amplitude = stepA;
            c.durationS = std::min(0.005, m_limits.currentStepMaxS);
            auto run = test(c, "the current step", s.motionTimeS);
            if (!run)
                return refuse(run.error().detail, run.error().code);
            if (run->trace) {
                auto step = tuning::currentStepFromCapture(*run->trace);
                if (step) {
                    const auto fig = tuning::stepFigures(step->tS, step->normalised);
                    s.measured["step_A"] = stepA;
                    model::putOptional(s.measured, "rise_time_s",
                                       std::isfinite(fig.riseTimeS) ? std::optional<double>(fig.riseTimeS)
                                                                    : std::nullopt,
                                       1.0, "the current never reached 90 % of the step");
                    s.measured["overshoot_pct"] = 100.0 * fig.overshoot;
                    if (predictedRise)
                        s.measured["predicted_rise_time_s"] = *predictedRise;
                    if (!std::isfinite(fig.riseTimeS))
                        return refuse("current loop: the measured current step never reaches 90 % of " + num(stepA, 3) +
                                      " A; the current loop must be fixed before the velocity loop");
                }
            }
        } else {
            s.measured["step"] = "the drive offers no current step";
        }
        done(s);
    }

    // ---- 3. Adaptive FRF ----------------------------------------------------------------------------------
    device::AdaptiveFrfResult measured;
    {
        Step s;
        s.name = "frf";
        if (!begin("frf"))
            return aborted("frf");
        nlohmann::json tries = nlohmann::json::array();
        std::optional<device::AdaptiveFrfResult> best;
        double bestPct = amplitudePct;
        const double maxPct = std::min(kLadderPeakCapPct, m_limits.frfAmplitudeMaxPct);
        double pct = amplitudePct;
        std::string mapRule;
        if (!m_o.amplitudeMapPct.empty()) { // the amplitude map (AmplitudeMap.h): the FRF at the amplitude in use
            AmplitudeMapOptions mo;
            mo.axis = axis;
            mo.amplitudesPct = m_o.amplitudeMapPct;
            mo.fminHz = kFrfMinHz;
            mo.spacingHz = kFrfSpacingHz;
            mo.timeBudgetS = std::max(m_o.timeBudgetS - m_motion, 1e-9); // > 0: a limit (0 would be none)
            auto mp = amplitudeMapInUse(m_drive, mo, m_linear, value("motor.torque_constant") * ratedA, m_o.run);
            if (!mp)
                return refuse("amplitude map: " + mp.error().detail, mp.error().code);
            m_motion += mp->motionTimeS;
            s.motionTimeS += mp->motionTimeS;
            s.measured["amplitude_map"] = inUseJson(*mp);
            if (mp->use)
                pct = std::min(mp->map.runs[*mp->use].amplitudePct, maxPct);
            mapRule = "; amplitude map at " + count(static_cast<long long>(mp->map.runs.size())) +
                      " amplitudes first (" + count(static_cast<long long>(mp->map.nonlinear)) + " of " +
                      count(static_cast<long long>(mp->map.compared)) +
                      " lines non-linear): the FRF starts at its amplitude nearest the peak torque of the move "
                      "evaluation's move with the running gains (" +
                      num(mp->useTorquePct, 3) + " % of rated torque) and is not doubled for non-linear lines";
        }
        for (int attempt = 0; attempt < kMaxFrfTries; ++attempt) {
            double t = 0.0;
            auto a = frf(pct, kFrfBudgetS, t);
            s.motionTimeS += t;
            if (!a)
                return refuse(a.error().detail, a.error().code);
            tries.push_back(frfJson(*a, pct));
            const auto f = figuresOf(*a);
            if (!best || f.valid > best->validLines) {
                best = std::move(a).value();
                bestPct = pct;
            }
            const double lines = static_cast<double>(std::max<std::size_t>(f.lines, 1));
            const auto voltage = f.invalidByReason.count("voltage limit") ? f.invalidByReason.at("voltage limit") : 0;
            double next = pct;
            if (static_cast<double>(voltage) > kRetryVoltageFraction * lines)
                next = std::max(0.5 * pct, kMinFrfAmplitudePct);
            else if (static_cast<double>(f.nonlinear) > kRetryNonlinearFraction * lines && mapRule.empty())
                next = std::min(2.0 * pct, maxPct);
            if (next == pct || m_motion + kFrfBudgetS > m_o.timeBudgetS)
                break;
            pct = next;
        }
        measured = std::move(*best);
        const auto f = figuresOf(measured);
        s.measured["tries"] = tries;
        s.chosen = {{"amplitude_pct", bestPct}, {"valid_lines", f.valid}, {"lines", f.lines}};
        s.rule = "adaptive multisine " + num(kFrfMinHz, 3) + " Hz ... 0.975 fs, " + num(kFrfSpacingHz, 3) +
                 " Hz spacing, " + num(kFrfBudgetS, 2) + " s budget each; at most " +
                 count(static_cast<long long>(kMaxFrfTries)) + " tries: the peak halves (down to " +
                 num(kMinFrfAmplitudePct, 2) + " %) while more than " + num(100.0 * kRetryVoltageFraction, 2) +
                 " % of the lines reach the voltage limit, else doubles (up to " + num(maxPct, 3) +
                 " %) while more than " + num(100.0 * kRetryNonlinearFraction, 2) +
                 " % are non-linear (friction); the try with the most valid lines is used" + mapRule;
        done(s);
        const double lines = static_cast<double>(std::max<std::size_t>(f.lines, 1));
        if (static_cast<double>(f.nonlinear) > kMaxNonlinearFraction * lines)
            return refuse("strong non-linearity: " + count(static_cast<long long>(f.nonlinear)) + " of " +
                          count(static_cast<long long>(f.lines)) +
                          " FRF lines change with the excitation beyond their noise (more than " +
                          num(100.0 * kMaxNonlinearFraction, 2) +
                          " %); friction or backlash dominate the small-signal response");
        if (static_cast<double>(f.valid) < kMinValidFraction * lines)
            return refuse("coherence too low: only " + count(static_cast<long long>(f.valid)) + " of " +
                          count(static_cast<long long>(f.lines)) + " FRF lines are valid (at least " +
                          num(100.0 * kMinValidFraction, 2) + " % needed) within the torque limit and the time budget");
    }
    const dsp::FrequencyResponse& t0 = measured.measurement.frf;

    // ---- 4. Notches ---------------------------------------------------------------------------------------
    const double fReq = m_t.minBandwidthHz;
    const double execRateHz = 1.0 / value("current.period");
    std::map<int, dsp::NotchSpec> existing;
    int slotCount = 0;
    for (int k = 1; k <= 16; ++k) {
        const std::string p = "filter.notch" + count(static_cast<long long>(k)) + ".";
        if (!std::isfinite(value(p + "center")))
            break;
        slotCount = k;
        if (value(p + "center") > 0.0 && value(p + "depth") < 1.0)
            existing[k] = {value(p + "center"), value(p + "width"), value(p + "depth")};
    }
    tuning::LoopForm form; // the drive's closed velocity loop T (complementary)
    tuning::NotchAnalysis notches;
    {
        Step s;
        s.name = "notches";
        if (!begin("notches"))
            return aborted("notches");
        const auto open = tuning::openLoopOf(t0, form);
        tuning::ResonanceOptions ro;
        ro.fminHz = t0.freqHz.front();
        ro.fmaxHz = t0.freqHz.back();
        auto all = tuning::findResonances(open, ro);
        if (!all)
            return refuse("notches: " + all.error().detail, all.error().code);
        nlohmann::json res = nlohmann::json::array();
        for (const auto& r : *all)
            res.push_back({{"f_Hz", r.freqHz}, {"height_dB", r.peakDb}, {"open_loop_dB", r.levelDb}});
        s.measured = {{"resonances", res}, {"existing_notches", existing.size()}, {"exec_rate_Hz", execRateHz}};
        for (const auto& r : *all)
            if (r.freqHz >= fReq / kResonanceSeparation && r.freqHz <= fReq * kResonanceSeparation) {
                done(s);
                return refuse("resonance too close to the required bandwidth: " + num(r.freqHz, 4) + " Hz (" +
                              num(r.peakDb, 3) + " dB above its baseline) lies within a factor " +
                              num(kResonanceSeparation, 2) + " of the required velocity crossover " + num(fReq, 4) +
                              " Hz: a notch there takes the phase margin, and the loop gain cannot dominate it");
            }
        ro.fminHz = std::max(ro.fminHz, kResonanceSeparation * fReq);
        tuning::NotchOptions no;
        no.execRateHz = execRateHz;
        no.slotCount = std::max(slotCount, 0);
        no.maxNotches = no.slotCount;
        auto a = tuning::analyseNotches(t0, form, ro, no, existing);
        if (!a)
            return refuse("notches: " + a.error().detail, a.error().code);
        notches = std::move(a).value();
        model::ParameterValues v;
        nlohmann::json chosen = nlohmann::json::array();
        for (const auto& n : notches.notches) {
            const std::string p = "filter.notch" + count(static_cast<long long>(n.slot)) + ".";
            v[p + "center"] = n.spec.centerHz;
            v[p + "width"] = n.spec.widthHz;
            v[p + "depth"] = n.spec.depth;
            chosen.push_back({{"slot", n.slot},
                              {"center_Hz", n.spec.centerHz},
                              {"width_Hz", n.spec.widthHz},
                              {"depth", n.spec.depth},
                              {"resonance_Hz", n.resonanceHz}});
        }
        nlohmann::json skipped = nlohmann::json::array();
        for (const auto& k : notches.proposal.skipped)
            skipped.push_back({{"f_Hz", k.freqHz}, {"reason", k.reason}});
        s.chosen = {{"notches", chosen}, {"skipped", skipped}};
        s.rule = "resonances of the open loop L = T/(1-T) above " + num(kResonanceSeparation, 2) +
                 "x the required crossover (" + num(fReq, 4) +
                 " Hz) get a notch on a free slot (the notch "
                 "wizard's rule: depth to the baseline or to -20 dB open loop, width from the mode's damping); one "
                 "within a factor " +
                 num(kResonanceSeparation, 2) + " of it refuses the tuning";
        if (!v.empty())
            if (auto st = write(v); !st)
                return refuse("notches: " + st.error().detail, st.error().code);
        done(s);
    }

    // ---- 5. Velocity PI -----------------------------------------------------------------------------------
    const tuning::VelocityPi running{value("velocity.kp"), value("velocity.ki")};
    const double vPeriod = value("velocity.period"), cPeriod = value("current.period");
    auto plantR =
        tuning::plantFromMeasurement(t0, tuning::LoopMeasurementKind::Complementary, running, vPeriod, cPeriod);
    if (!plantR)
        return refuse("velocity loop: " + plantR.error().detail, plantR.error().code);
    dsp::FrequencyResponse plantF = std::move(plantR).value();
    // The axis in motion (SlidingPlant.h): the damping that friction adds at standstill removed from the plant.
    auto standstill = standstillDamping(plantF);
    if (!standstill)
        return refuse("velocity loop: " + standstill.error().detail, standstill.error().code);
    std::vector<std::complex<double>> slideFactor; // P_s/P = 1/(1 − b·P) on every line of the plant
    slideFactor.reserve(plantF.size());
    for (const auto& p : plantF.h)
        slideFactor.push_back(slidingPlant(p, standstill->bNmsPerRad) / p);
    dsp::FrequencyResponse* plant = &plantF;
    // The new notches in the plant: L_after/L_before of the notch prediction (Π N_k on every line).
    const std::size_t withNotches =
        std::min(notches.prediction.openLoopBefore.size(), notches.prediction.openLoopAfter.size());
    for (std::size_t i = 0; i < plant->size() && i < withNotches; ++i) {
        const auto lb = notches.prediction.openLoopBefore.h[i];
        const auto la = notches.prediction.openLoopAfter.h[i];
        if (plant->valid[i] && std::abs(lb) > 0.0 && std::isfinite(std::abs(la)))
            plant->h[i] *= la / lb;
    }
    plant->metadata["measurement"] = "plant";
    std::vector<double> pf;
    std::vector<std::complex<double>> ph, phSlide;
    validLines(*plant, pf, ph);
    for (std::size_t i = 0, k = 0; i < plant->size(); ++i)
        if (k < pf.size() && plant->freqHz[i] == pf[k])
            phSlide.push_back(ph[k++] * slideFactor[i]);
    tuning::VelocityLoopDesign design;
    Margins predicted;
    double fc = 0.0;
    double kpPos = 0.0;
    Final fin;
    // Steps 5 to 8 run again, at most kMaxDesignAttempts times, with the crossover below 0.8 of the last one while
    // the re-measured loop misses the style's margins (the plant measured at the running gains is not the truth).
    double capHz = std::numeric_limits<double>::infinity();
    for (int attempt = 1;; ++attempt) {
        {
            Step s;
            s.name = "velocity-pi";
            if (!begin("velocity-pi"))
                return aborted("velocity-pi");
            const double fTop = std::min(0.125 * m_caps.traceRateHz, pf.empty() ? 0.0 : pf.back() / 2.0);
            const double fBottom = std::max(0.5 * fReq, pf.empty() ? 1.0 : pf.front());
            nlohmann::json scan = nlohmann::json::array();
            double bestF = 0.0, bestBw = 0.0, bestPm = m_t.phaseMarginDeg + kDesignPhaseReserveDeg;
            Margins bestM, bestSliding;
            double heldByFriction = 0.0;
            tuning::VelocityPi bestPi;
            const int n = 96;
            for (const double extraPm : kDesignPhaseSteps) {
                const double pmDesign = m_t.phaseMarginDeg + kDesignPhaseReserveDeg + extraPm;
                for (int i = 0; i <= n && fTop > fBottom; ++i) {
                    const double f = fBottom * std::pow(fTop / fBottom, static_cast<double>(i) / n);
                    if (f > capHz)
                        break;
                    auto pi = tuning::velocityPiFromFrf(*plant, f, pmDesign);
                    if (!pi || !(pi->kpNmsPerRad > 0.0) || !(pi->kiNmPerRad >= 0.0))
                        continue;
                    std::vector<std::complex<double>> l(pf.size()), t(pf.size()), ls(pf.size());
                    for (std::size_t k = 0; k < pf.size(); ++k) {
                        const auto c = tuning::piResponse(*pi, pf[k]);
                        l[k] = c * ph[k];
                        ls[k] = c * phSlide[k];
                        t[k] = l[k] / (1.0 + l[k]);
                    }
                    const auto m = marginsOf(pf, l);
                    const auto ms = marginsOf(pf, ls);
                    const auto meets = [&](const Margins& x) {
                        return x.phaseMarginDeg >= m_t.phaseMarginDeg &&
                               x.gainMarginDb >= m_t.gainMarginDb + kDesignGainReserveDb &&
                               std::isfinite(x.phaseMarginDeg);
                    };
                    const bool ok = meets(m) && meets(ms);
                    const double bw = closedLoopBandwidthHz(pf, t).value_or(0.0);
                    if (ok && f >= fReq && bw > bestBw) {
                        bestF = f;
                        bestBw = bw;
                        bestPm = pmDesign;
                        bestM = m;
                        bestSliding = ms;
                        bestPi = *pi;
                    }
                    if (ok && bestBw <= 0.0 && f > bestF) // below the required crossover: for the refusal's text
                        bestF = f;
                    if (meets(m) && !meets(ms) && f >= fReq) // for the refusal's text: only friction held it
                        heldByFriction = std::max(heldByFriction, f);
                }
            }
            s.measured = {{"plant_lines", pf.size()},
                          {"standstill_damping_Nms_per_rad", standstill->bNmsPerRad},
                          {"standstill_inertia_kgm2", standstill->inertiaKgm2},
                          {"standstill_lines_up_to_Hz", standstill->upToHz},
                          {"crossover_searched_Hz", {fBottom, fTop}},
                          {"running_kp_Nms_per_rad", running.kpNmsPerRad},
                          {"running_ki_Nm_per_rad", running.kiNmPerRad}};
            if (!(bestBw > 0.0) && heldByFriction > 0.0) {
                done(s);
                const double jw = standstill->inertiaKgm2 * kTwoPi * fReq;
                return refuse("friction holds the axis during the FRF: the damping at standstill b = " +
                              num(standstill->bNmsPerRad, 3) + " N m s/rad is " + num(standstill->bNmsPerRad / jw, 3) +
                              " x the inertia's J w at the required crossover " + num(fReq, 4) +
                              " Hz, so the measured plant is not the plant in motion; the PIs that keep " +
                              num(m_t.phaseMarginDeg, 3) + " deg and " + num(m_t.gainMarginDb, 3) +
                              " dB on the measured plant (up to " + num(heldByFriction, 4) +
                              " Hz) lose them once the axis slides. Measure at a larger amplitude (--amplitudes) or "
                              "tune by hand");
            }
            if (!(bestBw > 0.0)) {
                done(s);
                return refuse("the required velocity crossover " + num(fReq, 4) + " Hz cannot be reached with " +
                              num(m_t.phaseMarginDeg, 3) + " deg phase and " + num(m_t.gainMarginDb, 3) +
                              " dB gain margin on the measured plant" +
                              (bestF > 0.0 ? " (highest: " + num(bestF, 4) + " Hz)" : std::string()));
            }
            fc = bestF;
            predicted = bestM;
            tuning::VelocityLoopRequest req;
            req.method = tuning::VelocityLoopRequest::Method::Frf;
            req.measured = *plant;
            req.crossoverHz = fc;
            req.phaseMarginDeg = bestPm;
            req.running = running;
            req.positionKpRunning = value("position.kp");
            req.velocityPeriodS = vPeriod;
            req.currentPeriodS = cPeriod;
            req.jmKgm2 = finitePositive(value("velocity.inertia")) ? value("velocity.inertia") : 1.0;
            auto d = tuning::designVelocityLoop(req);
            if (!d)
                return refuse("velocity loop: " + d.error().detail, d.error().code);
            design = std::move(d).value();
            const auto bw = closedLoopBandwidthHz(design.fHz, design.closedLoop);
            s.chosen = {{"velocity.kp", design.proposed.kpNmsPerRad},
                        {"velocity.ki", design.proposed.kiNmPerRad},
                        {"crossover_Hz", fc},
                        {"predicted", marginsJson(predicted)},
                        {"predicted_in_motion", marginsJson(bestSliding)}};
            model::putOptional(s.chosen["predicted"], "velocity_bandwidth_Hz", bw, 1.0,
                               "the predicted closed loop does not fall 3 dB in the measured band");
            s.rule = "of the PIs designed for a crossover on a 96-step log grid " + num(fBottom, 4) + " ... " +
                     num(fTop, 4) + " Hz (at least the required " + num(fReq, 4) + " Hz) and a phase margin of " +
                     num(m_t.phaseMarginDeg + kDesignPhaseReserveDeg, 3) + " ... " +
                     num(m_t.phaseMarginDeg + kDesignPhaseReserveDeg + kDesignPhaseSteps[4], 3) +
                     " deg, the one with the widest closed-loop bandwidth that keeps, on the measured plant with the "
                     "notches, at least " +
                     num(m_t.phaseMarginDeg, 3) + " deg and " + num(m_t.gainMarginDb + kDesignGainReserveDb, 3) +
                     " dB (" + styleName(m_o.style) + " " + num(m_t.gainMarginDb, 3) + " dB + " +
                     num(kDesignGainReserveDb, 2) +
                     " dB reserve) over every crossover, on the plant as measured and on the plant in motion (the "
                     "damping at standstill b = Re(1/P) = " +
                     num(standstill->bNmsPerRad, 3) + " N m s/rad on the lines up to " + num(standstill->upToHz, 3) +
                     " Hz removed: P/(1 - b P); friction that holds the axis during a small FRF is gone once it "
                     "moves): " +
                     design.rule;
            if (auto st =
                    write({{"velocity.kp", design.proposed.kpNmsPerRad}, {"velocity.ki", design.proposed.kiNmPerRad}});
                !st)
                return refuse("velocity loop: " + st.error().detail, st.error().code);
            done(s);
        }

        // ---- 6. Position gain and feedforward -----------------------------------------------------------------
        {
            Step s;
            s.name = "position";
            if (!begin("position"))
                return aborted("position");
            // The predicted closed velocity loop on the measured lines.
            std::vector<std::complex<double>> tv(pf.size());
            for (std::size_t k = 0; k < pf.size(); ++k) {
                const auto l = tuning::piResponse(design.proposed, pf[k]) * ph[k];
                tv[k] = l / (1.0 + l);
            }
            // K_p: the ANALYST rule of the velocity wizard, ω_c,vel/5 (the model's stability limit −6 dB when lower).
            kpPos = std::min(kTwoPi * fc / 5.0,
                             finitePositive(design.position.limitPerS)
                                 ? design.position.limitPerS * std::pow(10.0, -tuning::kPositionGainMarginDb / 20.0)
                                 : std::numeric_limits<double>::infinity());
            const auto bw = closedLoopBandwidthHz(pf, positionClosedLoop(pf, tv, kpPos));
            s.measured = {
                {"running_position_kp_per_s", value("position.kp")},
                {"velocity_crossover_Hz", fc},
                {"model_limit_per_s", std::isfinite(design.position.limitPerS) ? design.position.limitPerS : 0.0}};
            model::ParameterValues v{{"position.kp", kpPos}};
            if (m_writable.count("position.velocity_ff"))
                v["position.velocity_ff"] = 1.0;
            if (m_writable.count("position.torque_ff") && finitePositive(value("velocity.inertia")))
                v["position.torque_ff"] = 1.0;
            for (const auto& [k, x] : v)
                s.chosen[k] = x;
            model::putOptional(s.chosen, "predicted_position_bandwidth_Hz", bw, 1.0,
                               "the predicted position loop does not fall 3 dB in the measured band");
            s.rule = "K_p = min(2pi*f_c/5, the model's stability limit -" + num(tuning::kPositionGainMarginDb, 2) +
                     " dB) (the velocity wizard's rule, " + design.modelNote +
                     "); velocity feedforward 1 and torque feedforward 1 with the drive's velocity.inertia (J = " +
                     num(value("velocity.inertia"), 4) + " kg m^2, kept) so the command is followed without lag";
            if (auto st = write(v); !st)
                return refuse("position loop: " + st.error().detail, st.error().code);
            done(s);
        }

        // ---- 7. Move evaluation -------------------------------------------------------------------------------
        {
            Step s;
            s.name = "move";
            if (!begin("move"))
                return aborted("move");
            const device::TestRequest j = moveEvaluationRequest(axis, m_linear);
            const double window = m_linear ? 1e-6 : 1e-5;
            auto run = test(j, "the point-to-point move", s.motionTimeS);
            if (!run)
                return refuse(run.error().detail, run.error().code);
            if (!run->trace)
                return refuse("the move gave no trace", ErrorCode::Device);
            const auto& c = *run->trace;
            const bool full = value("position.feedback") >= 0.5;
            const auto* t = c.channel("t_s");
            const auto* cmd = channelWithPrefix(c, "position_cmd_");
            const auto* pos = channelWithPrefix(c, full ? "table_pos_" : "motor_pos_");
            const auto* tq = c.channel("torque_cmd_Nm");
            if (!t || !cmd || !pos || !tq)
                return refuse("the move's trace lacks t_s, position_cmd_*, the position feedback or torque_cmd_Nm",
                              ErrorCode::Device);
            const std::size_t len = std::min({t->data.size(), cmd->data.size(), pos->data.size(), tq->data.size()});
            if (len < 2)
                return refuse("the move's trace is empty", ErrorCode::Device);
            const double target = cmd->data[len - 1];
            std::size_t kEnd = len - 1;
            while (kEnd > 0 && cmd->data[kEnd - 1] == target)
                --kEnd;
            double peakFe = 0.0, peakTq = 0.0, over = 0.0;
            const double dir = target >= cmd->data[0] ? 1.0 : -1.0;
            std::size_t lastOut = kEnd;
            bool everOut = false;
            for (std::size_t k = 0; k < len; ++k) {
                peakFe = std::max(peakFe, std::abs(cmd->data[k] - pos->data[k]));
                peakTq = std::max(peakTq, std::abs(tq->data[k]));
                if (k >= kEnd) {
                    over = std::max(over, dir * (pos->data[k] - target));
                    if (std::abs(pos->data[k] - target) > window) {
                        lastOut = k;
                        everOut = true;
                    }
                }
            }
            std::optional<double> settling;
            if (lastOut + 1 < len)
                settling = everOut ? t->data[lastOut + 1] - t->data[kEnd] : 0.0;
            const double headroom = maxTorqueNm > 0.0 ? 1.0 - peakTq / maxTorqueNm : 0.0;
            s.measured = {{"peak_following_error", peakFe},
                          {"overshoot", over},
                          {"peak_torque_Nm", peakTq},
                          {"torque_headroom_pct", 100.0 * headroom}};
            model::putOptional(s.measured, "settling_time_s", settling, 1.0,
                               "the position did not stay within the window before the record ended");
            s.chosen = {{"distance", j.distance},
                        {"velocity", j.velocity},
                        {"acceleration", j.acceleration},
                        {"window", window},
                        {"feedback", full ? "table (full-closed)" : "motor (semi-closed)"}};
            s.rule =
                std::string("a point-to-point move of the axis with the tuned gains; settling time from the end of "
                            "the command until the position stays within ±") +
                num(window, 2) + (m_linear ? " m" : " rad") +
                "; overshoot past the target; peak following error; torque headroom against k_t * I_max";
            // Backlash against the settling window (AmplitudeMap.h backlashFromReversal): a linear axis whose trace
            // has the motor and the table position reverses once; the lost motion at zero torque b must stay within
            // the window's width 2w, else the table cannot be brought within ±w from both sides.
            std::optional<BacklashEstimate> backlash;
            if (m_linear && c.channel("motor_pos_m") && c.channel("table_pos_m")) {
                double reversalS = 0.0;
                auto rev = test(backlashReversal(axis, kBacklashReversalM, j.velocity, j.acceleration),
                                "the reversal (backlash)", reversalS);
                s.motionTimeS += reversalS;
                if (!rev)
                    return refuse(rev.error().detail, rev.error().code);
                if (!rev->trace)
                    return refuse("the reversal (backlash) gave no trace", ErrorCode::Device);
                auto b = backlashFromReversal(*rev->trace);
                if (!b)
                    return refuse("the reversal (backlash): " + b.error().detail, ErrorCode::Device);
                backlash = *b;
                s.measured["backlash"] = b->backlashM;
                s.measured["lost_motion_compliance_m_per_Nm"] = b->complianceMPerNm;
                s.rule += "; backlash: a reversal " + num(kBacklashReversalM * 1e3, 2) +
                          " mm forth and back, motor-side minus table position regressed on the motor torque with one "
                          "intercept per direction while moving at >= half speed; the lost motion at zero torque "
                          "must not exceed the window's width " +
                          num(2.0 * window, 2) + " m";
            }
            done(s);
            if (backlash && backlash->backlashM > 2.0 * window)
                return refuse("backlash larger than the settling window: " + num(backlash->backlashM * 1e6, 3) +
                              " um of lost motion at zero torque at a reversal, the window is +-" +
                              num(window * 1e6, 2) + " um (" + num(2.0 * window * 1e6, 2) +
                              " um wide): the table cannot settle into it from both directions");
            if (headroom < 0.1)
                return refuse("the move needs " + num(peakTq, 3) + " N m of " + num(maxTorqueNm, 3) +
                              " N m: less than 10 % torque headroom");
            fin.settlingTimeS = settling;
            fin.peakFollowingError = peakFe;
        }

        // ---- 8. Verify ----------------------------------------------------------------------------------------
        {
            Step s;
            s.name = "verify";
            if (!begin("verify"))
                return aborted("verify");
            double t = 0.0;
            auto a = frf(measured.passes.front().peakPct, kFrfBudgetS, t);
            s.motionTimeS = t;
            if (!a)
                return refuse(a.error().detail, a.error().code);
            std::vector<double> f;
            std::vector<std::complex<double>> tm;
            validLines(a->measurement.frf, f, tm);
            const auto open = dsp::openLoopFromClosedLoop(a->measurement.frf, dsp::LoopMeasurement::Complementary);
            std::vector<double> lf;
            std::vector<std::complex<double>> lh;
            validLines(open, lf, lh);
            const auto m = marginsOf(lf, lh);
            const auto bw = closedLoopBandwidthHz(f, tm);
            const auto pbw = closedLoopBandwidthHz(f, positionClosedLoop(f, tm, kpPos));
            s.measured = frfJson(*a, measured.passes.front().peakPct);
            s.measured["margins"] = marginsJson(m);
            model::putOptional(s.measured, "velocity_bandwidth_Hz", bw, 1.0, "|T| does not fall 3 dB in the band");
            s.chosen = {{"predicted", marginsJson(predicted)},
                        {"accept_phase_margin_deg", m_t.acceptPhaseMarginDeg},
                        {"accept_gain_margin_dB", m_t.acceptGainMarginDb}};
            s.rule = "the closed velocity loop measured again as in the FRF step; margins of L = T/(1-T) on its valid "
                     "lines (smallest over every crossover) must be at least the style's " +
                     num(m_t.acceptPhaseMarginDeg, 3) + " deg and " + num(m_t.acceptGainMarginDb, 3) + " dB";
            done(s);
            if (!std::isfinite(m.phaseMarginDeg) || m.phaseMarginDeg < m_t.acceptPhaseMarginDeg ||
                m.gainMarginDb < m_t.acceptGainMarginDb) {
                const std::string why =
                    "the re-measured loop has " +
                    (std::isfinite(m.phaseMarginDeg) ? num(m.phaseMarginDeg, 3) + " deg" : std::string("no")) +
                    " phase margin and " +
                    (std::isfinite(m.gainMarginDb) ? num(m.gainMarginDb, 3) : std::string("unbounded")) +
                    " dB gain margin (predicted " + num(predicted.phaseMarginDeg, 3) + " deg, " +
                    num(predicted.gainMarginDb, 3) + " dB; needed " + num(m_t.acceptPhaseMarginDeg, 3) + " deg, " +
                    num(m_t.acceptGainMarginDb, 3) + " dB)";
                if (attempt < kMaxDesignAttempts && m_motion + kFrfBudgetS + 1.0 <= m_o.timeBudgetS) {
                    m_r.steps.back().rule += "; missed (" + why + "): designed again below 0.8 x " + num(fc, 4) + " Hz";
                    capHz = 0.8 * fc;
                    continue;
                }
                return refuse("verification: " + why);
            }
            if (!bw || !pbw)
                return refuse("verification: the re-measured closed loop does not fall 3 dB within the measured band");
            fin.phaseMarginDeg = m.phaseMarginDeg;
            fin.gainMarginDb = std::isfinite(m.gainMarginDb) ? m.gainMarginDb : 0.0;
            fin.velocityBandwidthHz = *bw;
            fin.positionBandwidthHz = *pbw;
            if (!std::isfinite(m.gainMarginDb))
                return refuse("verification: no -180 deg crossing in the measured band, the gain margin is not known");
        }

        break;
    }

    // ---- 9. Apply or roll back ----------------------------------------------------------------------------
    {
        Step s;
        s.name = "apply";
        if (!begin("apply"))
            return aborted("apply");
        fin.parameters = m_written;
        fin.motionTimeS = m_motion;
        for (const auto& [k, v] : m_written) {
            s.chosen[k] = v;
            s.measured["before." + k] = m_r.before.at(k);
        }
        if (auto refused = keepOrRestore(s, ""))
            return std::move(*refused);
    }
    m_r.motionTimeS = m_motion;
    m_r.final = fin;
    return std::move(m_r);
}

} // namespace

StyleTargets styleTargets(Style s)
{
    switch (s) {
    case Style::Gentle:
        return {60.0, 10.0, 20.0, 10.0, 55.0, 8.0};
    case Style::Stiff:
        return {45.0, 6.0, 80.0, 10.0, 40.0, 4.5};
    case Style::Standard:
        break;
    }
    return {50.0, 8.0, 40.0, 10.0, 45.0, 6.0};
}

const char* styleName(Style s)
{
    switch (s) {
    case Style::Gentle:
        return "gentle";
    case Style::Stiff:
        return "stiff";
    case Style::Standard:
        break;
    }
    return "standard";
}

Result<Style> parseStyle(std::string_view name)
{
    for (Style s : {Style::Gentle, Style::Standard, Style::Stiff})
        if (name == styleName(s))
            return s;
    return makeError(ErrorCode::BadInput, "style '" + std::string(name) + "' is none of gentle, standard, stiff");
}

std::optional<double> closedLoopBandwidthHz(const std::vector<double>& fHz, const std::vector<std::complex<double>>& t)
{
    if (fHz.empty() || t.size() != fHz.size())
        return std::nullopt;
    const double ref = std::abs(t.front());
    if (!(ref > 0.0))
        return std::nullopt;
    const double level = ref * std::pow(10.0, -3.0 / 20.0);
    for (std::size_t i = 1; i < fHz.size(); ++i)
        if (std::abs(t[i]) < level) {
            const double a = std::abs(t[i - 1]), b = std::abs(t[i]);
            const double x = (a - level) / (a - b);
            return std::pow(10.0, std::log10(fHz[i - 1]) + x * (std::log10(fHz[i]) - std::log10(fHz[i - 1])));
        }
    return std::nullopt;
}

const std::vector<std::string>& stepNames()
{
    static const std::vector<std::string> names{"safety-envelope", "current-loop", "frf",    "notches", "velocity-pi",
                                                "position",        "move",         "verify", "apply"};
    return names;
}

Result<AutoTuneResult> runAutoTune(device::Drive& drive, const Options& options)
{
    if (options.axis.empty())
        return makeError(ErrorCode::BadInput, "no axis given");
    if (options.positions < 1)
        return makeError(ErrorCode::BadInput, "the number of positions must be >= 1");
    if (options.positions > 1)
        return runAutoTunePositions(drive, options);
    Sequence s(drive, options);
    return s.run();
}

nlohmann::json resultJson(const AutoTuneResult& r, const Options& o)
{
    nlohmann::json j;
    j["axis"] = o.axis;
    j["style"] = styleName(o.style);
    j["dry_run"] = o.dryRun;
    j["outcome"] = r.outcome == Outcome::Applied ? "applied" : r.outcome == Outcome::DryRun ? "dry-run" : "refused";
    if (!r.reason.empty())
        j["reason"] = r.reason;
    j["parameters_restored"] = r.outcome != Outcome::Applied && r.restored;
    j["motion_time_s"] = r.motionTimeS;
    nlohmann::json steps = nlohmann::json::array();
    for (const auto& s : r.steps)
        steps.push_back({{"name", s.name},
                         {"measured", s.measured},
                         {"chosen", s.chosen},
                         {"rule", s.rule},
                         {"motion_time_s", s.motionTimeS}});
    j["steps"] = steps;
    if (r.final) {
        const auto& f = *r.final;
        nlohmann::json fj{
            {"phase_margin_deg", f.phaseMarginDeg},           {"gain_margin_dB", f.gainMarginDb},
            {"velocity_bandwidth_Hz", f.velocityBandwidthHz}, {"position_bandwidth_Hz", f.positionBandwidthHz},
            {"peak_following_error", f.peakFollowingError},   {"motion_time_s", f.motionTimeS}};
        model::putOptional(fj, "settling_time_s", f.settlingTimeS, 1.0,
                           "the position did not stay within the window before the record ended");
        nlohmann::json p = nlohmann::json::object();
        for (const auto& [k, v] : f.parameters)
            p[k] = v;
        fj["parameters"] = p;
        j["final"] = fj;
    }
    addPositionsJson(r, j);
    return j;
}

} // namespace axistune::autotune

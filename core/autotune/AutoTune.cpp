// SPDX-License-Identifier: GPL-3.0-or-later
// The one-button tuner (AutoTune.h; docs/tuning.md "One-button tuning"): its public functions, the one-position
// sequence's order (its steps in AutoTuneMeasure.cpp, AutoTuneDesign.cpp, AutoTuneCheck.cpp) and what the steps share.
#include "core/autotune/AutoTune.h"

#include "core/autotune/AutoTuneSequence.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/model/Number.h"
#include "core/model/ResultJson.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune::autotune {

namespace detail {

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
    motionS = device::motionTimeS(*run, plan);
    m_motion += motionS;
    return run;
}

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

std::optional<std::string> frfRefusal(const FrfFigures& f)
{
    const double lines = static_cast<double>(std::max<std::size_t>(f.lines, 1));
    if (static_cast<double>(f.nonlinear) > kMaxNonlinearFraction * lines)
        return "strong non-linearity: " + count(static_cast<long long>(f.nonlinear)) + " of " +
               count(static_cast<long long>(f.lines)) +
               " FRF lines change with the excitation beyond their noise (more than " +
               num(100.0 * kMaxNonlinearFraction, 2) + " %); friction or backlash dominate the small-signal response";
    if (static_cast<double>(f.valid) < kMinValidFraction * lines)
        return "coherence too low: only " + count(static_cast<long long>(f.valid)) + " of " +
               count(static_cast<long long>(f.lines)) + " FRF lines are valid (at least " +
               num(100.0 * kMinValidFraction, 2) + " % needed) within the torque limit and the time budget";
    return std::nullopt;
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
    // An axis whose position loop the NC closes with a PID (hal:, linuxcnc:: its FRF reports the plant and the open
    // position loop in the PID output's units) has no drive velocity loop for this sequence to tune: its one-button
    // tuner is pid-tune (docs/linuxcnc.md "Tuning from the command line").
    if (device::isNcPositionPid(m_caps))
        return makeError(ErrorCode::BadInput,
                         "axis " + axis +
                             " is a position PID the NC closes (no drive velocity loop to tune): use axistune-cli "
                             "pid-tune --connect ... --axis " +
                             axis + " [--apply], the one-button tuner for a LinuxCNC joint");
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

    if (auto r = safetyEnvelope())
        return std::move(*r);
    if (auto r = currentLoop())
        return std::move(*r);
    if (auto r = measureFrf())
        return std::move(*r);
    if (auto r = notches())
        return std::move(*r);
    if (auto r = plant())
        return std::move(*r);
    // Steps 5 to 8 run again, at most kMaxDesignAttempts times, with the crossover below 0.8 of the last one while
    // the re-measured loop misses the style's margins (the plant measured at the running gains is not the truth).
    for (int attempt = 1;; ++attempt) {
        m_again = false;
        if (auto r = velocityPi(m_capHz))
            return std::move(*r);
        if (auto r = position())
            return std::move(*r);
        if (auto r = move())
            return std::move(*r);
        if (auto r = verify(attempt))
            return std::move(*r);
        if (!m_again)
            break;
    }

    // ---- 9. Apply or roll back ----------------------------------------------------------------------------
    {
        Step s;
        s.name = "apply";
        if (!begin("apply"))
            return aborted("apply");
        m_fin.parameters = m_written;
        m_fin.motionTimeS = m_motion;
        for (const auto& [k, v] : m_written) {
            s.chosen[k] = v;
            s.measured["before." + k] = m_r.before.at(k);
        }
        if (auto refused = keepOrRestore(s, ""))
            return std::move(*refused);
    }
    m_r.motionTimeS = m_motion;
    m_r.final = m_fin;
    return std::move(m_r);
}

} // namespace detail

using namespace detail;

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

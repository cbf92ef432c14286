// SPDX-License-Identifier: GPL-3.0-or-later
// The one-button tuner over the travel (issue 18 item 4; AutoTune.h Options::positions; docs/tuning.md "Over the
// travel"): the drive moves the axis to N positions spread over its travel window (device::moveAxisTo: a hold to
// find the axis, a jog by the difference), measures the adaptive FRF at each, finds the first resonance there (the
// resonance map), chooses the notch design for the resonances of every position (AutoTunePositionsNotches.h), designs
// the velocity PI whose predicted margins hold at EVERY position (the worst case over the positions decides), the
// position gain whose position loop keeps its gain margin at every position, evaluates a move, verifies by measuring
// again at every position and applies or rolls back. The rules are core/tuning's; the thresholds are those of the
// single-position sequence (AutoTune.cpp), restated here where they are used. The steps are in files of their own
// (AutoTunePositionsRun.h).
#include "core/autotune/AutoTunePositionsRun.h"
#include "core/autotune/TravelChoice.h"
#include "core/device/MoveTo.h"
#include "core/model/ResultJson.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune::autotune {

namespace detail {

void Positions::returnToStart()
{
    if (!m_moved)
        return;
    // After an Abort the axis stays where the abort stopped it: Abort means stop, not a move back.
    if (m_o.run.abort && m_o.run.abort->load()) {
        m_r.reason += "; the axis was stopped where it stood and not moved back to " + num(m_start, 6) +
                      (m_linear ? " m" : " rad");
        return;
    }
    auto r = device::moveAxisTo(m_drive, m_o.axis, m_start, {}, m_o.run);
    if (!r) {
        m_r.reason += "; the axis could not be moved back to " + num(m_start, 6) + " (" + r.error().detail + ")";
        return;
    }
    m_motion += r->motionTimeS;
    m_moved = false;
}

Status Positions::moveTo(double x, double& motionS)
{
    // From the first move on the axis may be away from its start, also when this move is aborted or fails midway
    // (the drive stops it where it stands): the return (or the reason's "not moved back") must not depend on the
    // move having completed.
    m_moved = true;
    auto r = device::moveAxisTo(m_drive, m_o.axis, x, {}, m_o.run);
    if (!r)
        return makeError(r.error().code,
                         (r.error().code == ErrorCode::Safety ? "drive fault while moving to " : "moving to ") +
                             num(x, 6) + ": " + r.error().detail);
    m_motion += r->motionTimeS;
    motionS += r->motionTimeS;
    if (m_motion > m_o.timeBudgetS)
        return makeError(ErrorCode::Safety, "the moves along the travel used " + num(m_motion, 3) +
                                                " s of motion, beyond the time budget (" + num(m_o.timeBudgetS, 3) +
                                                " s)");
    return {};
}

Result<device::AdaptiveFrfResult> Positions::measure(double pct, double& motionS)
{
    double t = 0.0;
    auto a = frf(pct, kFrfBudgetS, t);
    if (a)
        motionS += t;
    return a;
}

Result<AutoTuneResult> Positions::run()
{
    const std::string& axis = m_o.axis;
    if (!(m_o.timeBudgetS > 0.0) || !std::isfinite(m_o.timeBudgetS))
        return makeError(ErrorCode::BadInput, "the time budget must be > 0 s");
    if (!(m_o.minBandwidthHz >= 0.0) || !std::isfinite(m_o.minBandwidthHz))
        return makeError(ErrorCode::BadInput, "the required bandwidth must be >= 0 Hz (0: the style's)");
    if (m_o.positions < 2)
        return makeError(ErrorCode::BadInput, "a tune over positions needs at least 2 positions");
    auto caps = m_drive.capabilities(axis);
    if (!caps)
        return caps.error();
    m_caps = *caps;
    if (!m_caps.offers(device::FrfMethod::Multisine) || m_caps.traceRateHz <= 0.0)
        return makeError(ErrorCode::BadInput, "axis " + axis + ": the drive offers no multisine FRF test");
    if (!m_caps.writesParameters)
        return makeError(ErrorCode::BadInput, "axis " + axis + ": the drive's parameters cannot be written");
    // A drive that cannot move the axis between the measurements cannot tune over positions.
    if (auto st = device::checkCanMoveTo(m_drive, axis); !st)
        return makeError(ErrorCode::BadInput, "--positions " + wholeText(m_o.positions) + ": " + st.error().detail);
    auto window = device::travelWindow(m_drive, axis);
    if (!window)
        return window.error();
    auto limits = m_drive.limits(axis);
    if (!limits)
        return limits.error();
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
                          "motor.torque_constant", "motor.max_current"})
        if (!std::isfinite(value(k)))
            return makeError(ErrorCode::Device, "axis " + axis + ": the drive does not give " + k);

    // ---- 1. Safety envelope: where the axis stands, the positions within the travel window ------------------
    if (!begin("safety-envelope"))
        return refuse("aborted by the user before the step safety-envelope", ErrorCode::Aborted);
    {
        Step s;
        s.name = "safety-envelope";
        auto here = device::findPosition(m_drive, axis, m_o.run);
        if (!here)
            return refuseWith(here.error());
        m_start = here->from;
        m_linear = here->linear;
        m_motion += here->motionTimeS;
        s.motionTimeS = here->motionTimeS;
        const double w = *window;
        // Inside the window by the move's servo lag (positionsInset): a move's overshoot must not take the axis out
        // of a window the drive checks on the measured position.
        const double kp = value("position.kp");
        const double inset = positionsInset(m_linear, kp);
        auto spread = positionsOverTravel(w, inset, m_o.positions);
        if (!spread)
            return refuse(spread.error().detail, spread.error().code);
        for (const double x : *spread) {
            Site site;
            site.x = x;
            m_sites.push_back(std::move(site));
        }
        m_pct = std::min(m_t.frfAmplitudePct, limits->frfAmplitudeMaxPct);
        nlohmann::json xs = nlohmann::json::array();
        for (const auto& site : m_sites)
            xs.push_back(site.x);
        s.measured = {{"travel_window", w},
                      {"start_position", m_start},
                      {"axis_units", m_linear ? "m" : "rad"},
                      {"position_gain_per_s", kp}};
        s.chosen = {
            {"positions", xs}, {"inset", inset}, {"frf_amplitude_pct", m_pct}, {"time_budget_s", m_o.timeBudgetS}};
        s.rule = wholeText(m_o.positions) + " positions evenly over the drive's travel window -" + num(w, 4) +
                 " ... +" + num(w, 4) + (m_linear ? " m" : " rad") + ", inset from its ends by the move's servo lag " +
                 "v/K_p = " + num(m_linear ? device::kMoveToSpeedLinear : device::kMoveToSpeedRotary, 3) +
                 (m_linear ? " m/s" : " rad/s") + " / " + num(kp, 4) + " 1/s = " + num(inset, 4) +
                 (m_linear ? " m" : " rad") + " (the overshoot of a move stays inside it)" +
                 ", reached by jogs the drive checks against its limits; FRF peak " + num(m_t.frfAmplitudePct, 3) +
                 " % of rated torque (" + styleName(m_o.style) +
                 "), at most the drive's limit; every test within the "
                 "time budget; the axis returns to where it stood at the end";
        done(s);
    }
    // ---- 2. Current loop: kept ------------------------------------------------------------------------------
    if (!begin("current-loop"))
        return refuse("aborted by the user before the step current-loop", ErrorCode::Aborted);
    {
        Step s;
        s.name = "current-loop";
        s.measured = {{"running_kp_V_per_A", value("current.kp")}, {"running_ki_V_per_As", value("current.ki")}};
        s.chosen = {{"current.kp", value("current.kp")}, {"current.ki", value("current.ki")}};
        s.rule = "kept: the current loop does not depend on the position; tune it with autotune at one position "
                 "(without --positions) first";
        done(s);
    }
    // ---- 3. FRF at every position ---------------------------------------------------------------------------
    if (!begin("frf"))
        return refuse("aborted by the user before the step frf", ErrorCode::Aborted);
    {
        auto s = measurePositions(m_pct);
        if (!s)
            return refuseWith(s.error());
        done(*s);
    }
    // ---- 4. Notches for every position ----------------------------------------------------------------------
    if (!begin("notches"))
        return refuse("aborted by the user before the step notches", ErrorCode::Aborted);
    {
        auto s = notches();
        if (!s)
            return refuseWith(s.error());
        done(*s);
    }
    // ---- 5.–8. Velocity PI, position gain, move, verify (again below 0.8 f_c while a position misses) -------
    double capHz = kInf;
    for (int attempt = 1;; ++attempt) {
        for (const char* name : {"velocity-pi", "position", "move"}) {
            if (!begin(name))
                return refuse(std::string("aborted by the user before the step ") + name, ErrorCode::Aborted);
            const std::string n = name;
            auto s = n == "velocity-pi" ? velocityPi(capHz) : n == "position" ? position() : move();
            if (!s)
                return refuseWith(s.error());
            done(*s);
        }
        if (!begin("verify"))
            return refuse("aborted by the user before the step verify", ErrorCode::Aborted);
        Step s;
        auto why = verify(s);
        if (!why)
            return refuseWith(why.error());
        done(s);
        if (why->empty())
            break;
        if (attempt < kMaxDesignAttempts) {
            m_r.steps.back().rule += "; missed (" + *why + "): designed again below 0.8 x " + num(m_fc, 4) + " Hz";
            capHz = 0.8 * m_fc;
            continue;
        }
        return refuse("verification over the travel: " + *why);
    }
    // ---- 9. Apply or roll back -------------------------------------------------------------------------------
    if (!begin("apply"))
        return refuse("aborted by the user before the step apply", ErrorCode::Aborted);
    Step s;
    s.name = "apply";
    returnToStart();
    for (const auto& [k, v] : m_written) {
        s.chosen[k] = v;
        s.measured["before." + k] = m_r.before.at(k);
    }
    m_fin.parameters = m_written;
    m_fin.phaseMarginDeg = m_fin.gainMarginDb = m_fin.velocityBandwidthHz = m_fin.positionBandwidthHz = kInf;
    for (const auto& site : m_sites) {
        m_fin.phaseMarginDeg = std::min(m_fin.phaseMarginDeg, site.fin.phaseMarginDeg);
        m_fin.gainMarginDb = std::min(m_fin.gainMarginDb, site.fin.gainMarginDb);
        m_fin.velocityBandwidthHz = std::min(m_fin.velocityBandwidthHz, site.fin.velocityBandwidthHz);
        m_fin.positionBandwidthHz = std::min(m_fin.positionBandwidthHz, site.fin.positionBandwidthHz);
        m_fin.positions.push_back(site.fin);
    }
    if (auto refused = keepOrRestore(s, "; the axis back at " + num(m_start, 6)))
        return std::move(*refused);
    m_fin.motionTimeS = m_motion;
    m_r.motionTimeS = m_motion;
    m_r.final = m_fin;
    return std::move(m_r);
}

} // namespace detail

using namespace detail;

Result<AutoTuneResult> runAutoTunePositions(device::Drive& drive, const Options& options)
{
    if (options.axis.empty())
        return makeError(ErrorCode::BadInput, "no axis given");
    Positions p(drive, options);
    return p.run();
}

void addPositionsJson(const AutoTuneResult& r, nlohmann::json& j)
{
    if (!r.final || r.final->positions.empty()) {
        // A refused run over positions: the map as the frf step measured it.
        for (const auto& s : r.steps)
            if (s.name == "frf" && s.measured.contains("resonance_map"))
                j["resonance_map"] = s.measured["resonance_map"];
        return;
    }
    nlohmann::json per = nlohmann::json::array(), map = nlohmann::json::array();
    for (const auto& p : r.final->positions) {
        per.push_back({{"position", p.position},
                       {"phase_margin_deg", p.phaseMarginDeg},
                       {"gain_margin_dB", p.gainMarginDb},
                       {"velocity_bandwidth_Hz", p.velocityBandwidthHz},
                       {"position_bandwidth_Hz", p.positionBandwidthHz},
                       {"predicted_phase_margin_deg", p.predictedPhaseMarginDeg},
                       {"predicted_gain_margin_dB", p.predictedGainMarginDb}});
        nlohmann::json m{{"position", p.position}};
        model::putOptional(m, "frequency_Hz", p.firstResonanceHz, 1.0, "no resonance in the measured band");
        model::putOptional(m, "height_dB", p.firstResonanceHeightDb, 1.0, "no resonance in the measured band");
        map.push_back(m);
    }
    j["final"]["positions"] = per;
    j["resonance_map"] = map;
}

} // namespace axistune::autotune

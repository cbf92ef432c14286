// SPDX-License-Identifier: GPL-3.0-or-later
// The one-button tuner over the travel (issue 18 item 4; AutoTune.h Options::positions; docs/tuning.md "Over the
// travel"): the drive moves the axis to N positions spread over its travel window (device::moveAxisTo: a hold to
// find the axis, a jog by the difference), measures the adaptive FRF at each, finds the first resonance there (the
// resonance map), places notches for the resonances of every position, designs the velocity PI whose predicted
// margins hold at EVERY position (the worst case over the positions decides), the position gain whose position
// loop keeps its gain margin at every position, evaluates a move, verifies by measuring again at every position and
// applies or rolls back. The rules are core/tuning's; the thresholds are those of the single-position sequence
// (AutoTune.cpp), restated here where they are used.
#include "core/autotune/AutoTune.h"
#include "core/autotune/AutoTuneRun.h"
#include "core/device/AdaptiveFrf.h"
#include "core/device/MoveTo.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/model/Number.h"
#include "core/model/ResultJson.h"
#include "core/tuning/Notch.h"
#include "core/tuning/Resonance.h"
#include "core/tuning/VelocityLoop.h"
#include "core/tuning/VelocityLoopDesign.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

namespace axistune::autotune {

namespace {

using namespace detail;

constexpr double kInf = std::numeric_limits<double>::infinity();
/// Two positions' notches within this fraction of the centre are one notch (the earlier position's).
constexpr double kSameNotch = 0.05;
/// Smallest integral corner k_i/k_p [rad/s] (1 Hz) of a PI the search considers: a slower integrator leaves the
/// loop seconds to settle (the drive's FRF settle time follows the slowest closed-loop pole and refuses beyond 10 s).
constexpr double kMinIntegralCornerRadS = kTwoPi;
/// Crossover grid of the PI search (log steps).
constexpr int kGridSteps = 96;

std::string whole(long long n)
{
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, n);
    return std::string(buf, r.ptr);
}

/// One position's measured loop: the valid lines of the plant (with the new notches) and of the measured T.
struct Site {
    double x = 0.0;
    device::AdaptiveFrfResult frf;
    dsp::FrequencyResponse plant; ///< P·Π N_new on the measured lines
    std::vector<double> f;
    std::vector<std::complex<double>> p; ///< valid lines of `plant`
    std::optional<tuning::Resonance> first;
    PositionFinal fin;
};

dsp::LoopMargins margins(const std::vector<double>& f, const std::vector<std::complex<double>>& l)
{
    dsp::FrequencyResponse r;
    for (std::size_t i = 0; i < f.size(); ++i)
        r.push(f[i], l[i], std::numeric_limits<double>::quiet_NaN(), true);
    return dsp::loopMargins(r);
}

std::optional<double> finiteOr(double v)
{
    return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

/// Closed velocity loop and open loop of PI `pi` on a site's plant lines.
void loops(const tuning::VelocityPi& pi, const Site& s, std::vector<std::complex<double>>& l,
           std::vector<std::complex<double>>& t)
{
    l.resize(s.f.size());
    t.resize(s.f.size());
    for (std::size_t k = 0; k < s.f.size(); ++k) {
        l[k] = tuning::piResponse(pi, s.f[k]) * s.p[k];
        t[k] = l[k] / (1.0 + l[k]);
    }
}

/// Open position loop K_p·T_v/(jω) at K_p = 1.
std::vector<std::complex<double>> positionOpen(const std::vector<double>& f,
                                               const std::vector<std::complex<double>>& tv)
{
    std::vector<std::complex<double>> out(f.size());
    for (std::size_t k = 0; k < f.size(); ++k)
        out[k] = tv[k] / std::complex<double>(0.0, kTwoPi * f[k]);
    return out;
}

std::vector<std::complex<double>> positionClosed(const std::vector<double>& f,
                                                 const std::vector<std::complex<double>>& tv, double kp)
{
    auto l = positionOpen(f, tv);
    for (auto& v : l) {
        v *= kp;
        v = v / (1.0 + v);
    }
    return l;
}

void validOf(const dsp::FrequencyResponse& r, std::vector<double>& f, std::vector<std::complex<double>>& h)
{
    f.clear();
    h.clear();
    for (std::size_t i = 0; i < r.size(); ++i)
        if (r.valid[i] && std::isfinite(std::abs(r.h[i]))) {
            f.push_back(r.freqHz[i]);
            h.push_back(r.h[i]);
        }
}

class Positions : public Run {
public:
    using Run::Run;
    Result<AutoTuneResult> run();

private:
    void afterRefusal() override { returnToStart(); }
    void returnToStart();
    /// Moves to x within the budget; the step's motion time grows by the move's.
    Status moveTo(double x, double& motionS);
    Result<device::AdaptiveFrfResult> measure(double pct, double& motionS);
    Result<Step> measurePositions(double pct);
    Result<Step> notches();
    Result<Step> velocityPi(double capHz);
    Result<Step> position();
    Result<Step> move();
    /// Empty when every position keeps the style's margins; else why not.
    Result<std::string> verify(Step& s);

    double m_start = 0.0; ///< where the axis stood
    bool m_moved = false;
    double m_pct = 0.0;
    std::vector<Site> m_sites;
    tuning::LoopForm m_form;
    tuning::VelocityPi m_pi;
    double m_fc = 0.0, m_kpPos = 0.0;
    Final m_fin;
};

void Positions::returnToStart()
{
    if (!m_moved)
        return;
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
    auto r = device::moveAxisTo(m_drive, m_o.axis, x, {}, m_o.run);
    if (!r)
        return makeError(r.error().code,
                         (r.error().code == ErrorCode::Safety ? "drive fault while moving to " : "moving to ") +
                             num(x, 6) + ": " + r.error().detail);
    m_moved = true;
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

Result<Step> Positions::measurePositions(double pct)
{
    Step s;
    s.name = "frf";
    nlohmann::json per = nlohmann::json::array(), map = nlohmann::json::array();
    for (auto& site : m_sites) {
        if (auto st = moveTo(site.x, s.motionTimeS); !st)
            return st.error();
        auto a = measure(pct, s.motionTimeS);
        if (!a)
            return a.error();
        site.frf = std::move(a).value();
        std::size_t nonlinear = 0;
        for (const auto& l : site.frf.invalid)
            nonlinear += l.reason == device::InvalidReason::Nonlinear ? 1 : 0;
        const auto& t = site.frf.measurement.frf;
        const double lines = static_cast<double>(std::max<std::size_t>(t.size(), 1));
        const std::string at = "at " + num(site.x, 4) + (m_linear ? " m: " : " rad: ");
        if (static_cast<double>(nonlinear) > kMaxNonlinearFraction * lines)
            return makeError(ErrorCode::Safety, "strong non-linearity " + at +
                                                    whole(static_cast<long long>(nonlinear)) + " of " +
                                                    whole(static_cast<long long>(t.size())) +
                                                    " FRF lines change with the excitation beyond their noise");
        if (static_cast<double>(site.frf.validLines) < kMinValidFraction * lines)
            return makeError(ErrorCode::Safety, "coherence too low " + at + "only " +
                                                    whole(static_cast<long long>(site.frf.validLines)) + " of " +
                                                    whole(static_cast<long long>(t.size())) + " FRF lines are valid");
        tuning::ResonanceOptions ro;
        ro.fminHz = t.freqHz.front();
        ro.fmaxHz = t.freqHz.back();
        auto res = tuning::findResonances(tuning::openLoopOf(t, m_form), ro);
        if (!res)
            return makeError(res.error().code, "resonances " + at + res.error().detail);
        nlohmann::json rj = nlohmann::json::array();
        for (const auto& r : *res)
            rj.push_back({{"f_Hz", r.freqHz}, {"height_dB", r.peakDb}});
        if (!res->empty())
            site.first = res->front();
        site.fin.position = site.x;
        site.fin.firstResonanceHz = site.first ? std::optional<double>(site.first->freqHz) : std::nullopt;
        site.fin.firstResonanceHeightDb = site.first ? std::optional<double>(site.first->peakDb) : std::nullopt;
        per.push_back({{"position", site.x},
                       {"lines", t.size()},
                       {"valid_lines", site.frf.validLines},
                       {"nonlinear_lines", nonlinear},
                       {"motion_time_s", site.frf.motionTimeS},
                       {"resonances", rj}});
        nlohmann::json m{{"position", site.x}};
        model::putOptional(m, "frequency_Hz", site.fin.firstResonanceHz, 1.0, "no resonance in the measured band");
        model::putOptional(m, "height_dB", site.fin.firstResonanceHeightDb, 1.0, "no resonance in the measured band");
        map.push_back(m);
    }
    s.measured = {{"positions", per}, {"resonance_map", map}};
    s.chosen = {{"amplitude_pct", pct}};
    s.rule = "at each position (moved there by a jog through the drive): the adaptive multisine " + num(kFrfMinHz, 3) +
             " Hz ... 0.975 fs, " + num(kFrfSpacingHz, 3) + " Hz spacing, " + num(kFrfBudgetS, 2) +
             " s budget, at the style's amplitude; refused where fewer than " + num(100.0 * kMinValidFraction, 2) +
             " % of the lines are valid or more than " + num(100.0 * kMaxNonlinearFraction, 2) +
             " % are non-linear; the resonance map is the lowest resonance of the open loop L = T/(1-T) at each";
    return s;
}

Result<Step> Positions::notches()
{
    Step s;
    s.name = "notches";
    const double fReq = m_t.minBandwidthHz;
    const double exec = 1.0 / value("current.period");
    std::map<int, dsp::NotchSpec> existing;
    int slots = 0;
    for (int k = 1; k <= 16; ++k) {
        const std::string p = "filter.notch" + whole(k) + ".";
        if (!std::isfinite(value(p + "center")))
            break;
        slots = k;
        if (value(p + "center") > 0.0 && value(p + "depth") < 1.0)
            existing[k] = {value(p + "center"), value(p + "width"), value(p + "depth")};
    }
    // Notches proposed at each position; one whose resonance lies within kSameNotch of an earlier position's notch
    // centre is left out (a notch's -3 dB band is no measure: at its edge it takes only 3 dB off the peak).
    std::vector<tuning::ProposedNotch> chosen;
    nlohmann::json per = nlohmann::json::array();
    for (const auto& site : m_sites) {
        const auto& t = site.frf.measurement.frf;
        tuning::ResonanceOptions ro;
        ro.fminHz = t.freqHz.front();
        ro.fmaxHz = t.freqHz.back();
        auto all = tuning::findResonances(tuning::openLoopOf(t, m_form), ro);
        if (!all)
            return all.error();
        for (const auto& r : *all)
            if (r.freqHz >= fReq / kResonanceSeparation && r.freqHz <= fReq * kResonanceSeparation)
                return makeError(ErrorCode::Safety, "resonance too close to the required bandwidth at " +
                                                        num(site.x, 4) + ": " + num(r.freqHz, 4) +
                                                        " Hz lies within a factor " + num(kResonanceSeparation, 2) +
                                                        " of the required velocity crossover " + num(fReq, 4) + " Hz");
        ro.fminHz = std::max(ro.fminHz, kResonanceSeparation * fReq);
        tuning::NotchOptions no;
        no.execRateHz = exec;
        no.slotCount = slots;
        no.maxNotches = slots;
        auto a = tuning::analyseNotches(t, m_form, ro, no, existing);
        if (!a)
            return a.error();
        nlohmann::json proposed = nlohmann::json::array();
        for (const auto& n : a->notches) {
            proposed.push_back({{"center_Hz", n.spec.centerHz}, {"resonance_Hz", n.resonanceHz}});
            const bool covered = std::any_of(chosen.begin(), chosen.end(), [&](const tuning::ProposedNotch& c) {
                return std::abs(n.resonanceHz - c.spec.centerHz) <= kSameNotch * c.spec.centerHz;
            });
            if (!covered)
                chosen.push_back(n);
        }
        per.push_back({{"position", site.x}, {"proposed", proposed}});
    }
    // Slots: the free ones in increasing order.
    std::vector<int> free;
    for (int k = 1; k <= slots; ++k)
        if (!existing.count(k))
            free.push_back(k);
    if (chosen.size() > free.size())
        return makeError(ErrorCode::Safety, "the resonances over the travel need " +
                                                whole(static_cast<long long>(chosen.size())) +
                                                " notches, the drive has " +
                                                whole(static_cast<long long>(free.size())) + " free notch slots");
    model::ParameterValues v;
    std::vector<dsp::NotchSpec> specs;
    nlohmann::json cj = nlohmann::json::array();
    for (std::size_t i = 0; i < chosen.size(); ++i) {
        auto& n = chosen[i];
        n.slot = free[i];
        const std::string p = "filter.notch" + whole(n.slot) + ".";
        v[p + "center"] = n.spec.centerHz;
        v[p + "width"] = n.spec.widthHz;
        v[p + "depth"] = n.spec.depth;
        specs.push_back(n.spec);
        cj.push_back({{"slot", n.slot},
                      {"center_Hz", n.spec.centerHz},
                      {"width_Hz", n.spec.widthHz},
                      {"depth", n.spec.depth},
                      {"resonance_Hz", n.resonanceHz}});
    }
    // Each position's plant with every new notch: P = plant of the measured T at the running PI, times
    // L_after/L_before of the notch prediction (Π N_k on every line), as the single-position sequence.
    const tuning::VelocityPi running{value("velocity.kp"), value("velocity.ki")};
    for (auto& site : m_sites) {
        const auto& t = site.frf.measurement.frf;
        auto plant = tuning::plantFromMeasurement(t, tuning::LoopMeasurementKind::Complementary, running,
                                                  value("velocity.period"), value("current.period"));
        if (!plant)
            return plant.error();
        site.plant = std::move(plant).value();
        if (!specs.empty()) {
            auto pred = tuning::predictWithNotches(t, m_form, specs, exec);
            if (!pred)
                return pred.error();
            const std::size_t n =
                std::min({site.plant.size(), pred->openLoopBefore.size(), pred->openLoopAfter.size()});
            for (std::size_t i = 0; i < n; ++i) {
                const auto lb = pred->openLoopBefore.h[i], la = pred->openLoopAfter.h[i];
                if (site.plant.valid[i] && std::abs(lb) > 0.0 && std::isfinite(std::abs(la)))
                    site.plant.h[i] *= la / lb;
            }
        }
        validOf(site.plant, site.f, site.p);
    }
    s.measured = {{"positions", per}, {"existing_notches", existing.size()}, {"exec_rate_Hz", exec}};
    s.chosen = {{"notches", cj}};
    s.rule = "at each position the notch wizard's rule on the open loop L = T/(1-T) above " +
             num(kResonanceSeparation, 2) + "x the required crossover (" + num(fReq, 4) +
             " Hz); a notch whose resonance lies within " + num(100.0 * kSameNotch, 2) +
             " % of the centre of an earlier position's notch is left out; the rest go to the free slots; a resonance "
             "within a factor " +
             num(kResonanceSeparation, 2) + " of the crossover at any position refuses the tuning";
    if (!v.empty())
        if (auto st = write(v); !st)
            return st.error();
    return s;
}

Result<Step> Positions::velocityPi(double capHz)
{
    Step s;
    s.name = "velocity-pi";
    const double fReq = m_t.minBandwidthHz;
    double fTop = 0.125 * m_caps.traceRateHz, fBottom = 0.5 * fReq;
    for (const auto& site : m_sites) {
        if (site.f.empty())
            return makeError(ErrorCode::Safety, "no valid plant line at " + num(site.x, 4));
        fTop = std::min(fTop, site.f.back() / 2.0);
        fBottom = std::max(fBottom, site.f.front());
    }
    // Every PI designed on any position's plant for a crossover on the grid and a phase margin of the style plus
    // the reserve steps; it must keep the margins on EVERY position's plant; the widest worst-case bandwidth wins.
    double bestBw = 0.0, bestF = 0.0, highestOk = 0.0;
    std::size_t bestBase = 0;
    tuning::VelocityPi best;
    std::vector<dsp::LoopMargins> bestM;
    std::vector<std::complex<double>> l, t;
    for (std::size_t base = 0; base < m_sites.size(); ++base)
        for (const double extra : kDesignPhaseSteps) {
            const double pm = m_t.phaseMarginDeg + kDesignPhaseReserveDeg + extra;
            for (int i = 0; i <= kGridSteps && fTop > fBottom; ++i) {
                const double f = fBottom * std::pow(fTop / fBottom, static_cast<double>(i) / kGridSteps);
                if (f > capHz)
                    break;
                auto pi = tuning::velocityPiFromFrf(m_sites[base].plant, f, pm);
                if (!pi || !(pi->kpNmsPerRad > 0.0) || !(pi->kiNmPerRad >= 0.0))
                    continue;
                if (pi->kiNmPerRad < kMinIntegralCornerRadS * pi->kpNmsPerRad)
                    continue;
                bool ok = true;
                double worstBw = kInf;
                std::vector<dsp::LoopMargins> ms;
                for (const auto& site : m_sites) {
                    loops(*pi, site, l, t);
                    const auto m = margins(site.f, l);
                    ok = ok && std::isfinite(m.phaseMarginDeg) && m.phaseMarginDeg >= m_t.phaseMarginDeg &&
                         m.gainMarginDb >= m_t.gainMarginDb + kDesignGainReserveDb;
                    worstBw = std::min(worstBw, closedLoopBandwidthHz(site.f, t).value_or(0.0));
                    ms.push_back(m);
                    if (!ok)
                        break;
                }
                if (ok && f > highestOk)
                    highestOk = f;
                if (ok && f >= fReq && worstBw > bestBw) {
                    bestBw = worstBw;
                    bestF = f;
                    best = *pi;
                    bestM = ms;
                    bestBase = base;
                }
            }
        }
    s.measured = {{"plant_lines", m_sites.front().f.size()},
                  {"positions", m_sites.size()},
                  {"crossover_searched_Hz", {fBottom, fTop}},
                  {"running_kp_Nms_per_rad", value("velocity.kp")},
                  {"running_ki_Nm_per_rad", value("velocity.ki")}};
    if (!(bestBw > 0.0))
        return makeError(ErrorCode::Safety,
                         "the required velocity crossover " + num(fReq, 4) + " Hz cannot be reached with " +
                             num(m_t.phaseMarginDeg, 3) + " deg phase and " + num(m_t.gainMarginDb, 3) +
                             " dB gain margin at every position" +
                             (highestOk > 0.0 ? " (highest: " + num(highestOk, 4) + " Hz)" : std::string()));
    m_pi = best;
    m_fc = bestF;
    nlohmann::json pred = nlohmann::json::array();
    for (std::size_t i = 0; i < m_sites.size(); ++i) {
        m_sites[i].fin.predictedPhaseMarginDeg = bestM[i].phaseMarginDeg;
        m_sites[i].fin.predictedGainMarginDb = bestM[i].gainMarginDb;
        nlohmann::json p{{"position", m_sites[i].x}};
        model::putOptional(p, "phase_margin_deg", finiteOr(bestM[i].phaseMarginDeg), 1.0, "no gain crossover");
        model::putOptional(p, "gain_margin_dB", finiteOr(bestM[i].gainMarginDb), 1.0, "no -180 deg crossing");
        pred.push_back(p);
    }
    s.chosen = {{"velocity.kp", best.kpNmsPerRad},
                {"velocity.ki", best.kiNmPerRad},
                {"crossover_Hz", bestF},
                {"designed_on_position", m_sites[bestBase].x},
                {"predicted_worst_velocity_bandwidth_Hz", bestBw},
                {"predicted", pred}};
    s.rule = "of the PIs designed (tuning::velocityPiFromFrf) on the plant of each position for a crossover on a " +
             whole(kGridSteps) + "-step log grid " + num(fBottom, 4) + " ... " + num(std::min(fTop, capHz), 4) +
             " Hz (at least the required " + num(fReq, 4) + " Hz) and a phase margin of " +
             num(m_t.phaseMarginDeg + kDesignPhaseReserveDeg, 3) + " ... " +
             num(m_t.phaseMarginDeg + kDesignPhaseReserveDeg + kDesignPhaseSteps[4], 3) +
             " deg, the one with the widest worst-case closed-loop bandwidth that keeps at least " +
             num(m_t.phaseMarginDeg, 3) + " deg and " + num(m_t.gainMarginDb + kDesignGainReserveDb, 3) +
             " dB on the measured plant with the notches at EVERY position (integral corner k_i/k_p at least 1 Hz)";
    if (auto st = write({{"velocity.kp", best.kpNmsPerRad}, {"velocity.ki", best.kiNmPerRad}}); !st)
        return st.error();
    return s;
}

Result<Step> Positions::position()
{
    Step s;
    s.name = "position";
    // K_p = ω_c/5 (the velocity wizard's rule), lowered until the open position loop K_p·T_v/(jω) keeps
    // kPositionGainMarginDb of gain margin at every position (T_v the predicted closed velocity loop there).
    double kp = kTwoPi * m_fc / 5.0, limit = kInf;
    std::vector<std::complex<double>> l, t;
    for (const auto& site : m_sites) {
        loops(m_pi, site, l, t);
        const auto m = margins(site.f, positionOpen(site.f, t));
        if (std::isfinite(m.gainMarginDb))
            limit = std::min(limit, std::pow(10.0, (m.gainMarginDb - tuning::kPositionGainMarginDb) / 20.0));
    }
    kp = std::min(kp, limit);
    m_kpPos = kp;
    model::ParameterValues v{{"position.kp", kp}};
    if (m_writable.count("position.velocity_ff"))
        v["position.velocity_ff"] = 1.0;
    if (m_writable.count("position.torque_ff") && value("velocity.inertia") > 0.0)
        v["position.torque_ff"] = 1.0;
    for (const auto& [k, x] : v)
        s.chosen[k] = x;
    s.measured = {{"running_position_kp_per_s", value("position.kp")}, {"velocity_crossover_Hz", m_fc}};
    model::putOptional(s.measured, "worst_stability_limit_per_s", finiteOr(limit), 1.0,
                       "the predicted position loops have no -180 deg crossing in the band");
    s.rule = "K_p = min(2pi*f_c/5, the largest K_p that keeps " + num(tuning::kPositionGainMarginDb, 2) +
             " dB of gain margin in K_p*T_v/(j omega) at every position, T_v predicted there); velocity and torque "
             "feedforward 1 (torque with the drive's velocity.inertia, kept)";
    if (auto st = write(v); !st)
        return st.error();
    return s;
}

Result<Step> Positions::move()
{
    Step s;
    s.name = "move";
    // A point-to-point move of 10 mm (0.2 rad) back and forth at the last position, with the tuned gains.
    device::TestRequest j;
    j.axis = m_o.axis;
    j.type = device::TestType::Jog;
    j.distance = (m_sites.back().x > 0.0 ? -1.0 : 1.0) * (m_linear ? 0.01 : 0.2);
    j.velocity = m_linear ? 0.05 : 1.0;
    j.acceleration = m_linear ? 1.0 : 20.0;
    j.returnToStart = true;
    j.durationS = 0.15;
    const double window = m_linear ? 1e-6 : 1e-5;
    auto plan = m_drive.planTest(j);
    if (plan && m_motion + plan->motionTimeS > m_o.timeBudgetS)
        return makeError(ErrorCode::Safety,
                         "the move would exceed the time budget (" + num(m_o.timeBudgetS, 3) + " s)");
    device::RunOptions ro = m_o.run;
    ro.readTrace = true;
    auto run = device::runTest(m_drive, j, ro);
    if (!run)
        return makeError(run.error().code, "the point-to-point move: " + run.error().detail);
    double t = plan ? plan->motionTimeS : 0.0;
    if (run->trace)
        if (auto it = run->trace->metadata.find(device::kMotionTimeMetadataKey); it != run->trace->metadata.end())
            if (auto x = model::parseNumber(it->second))
                t = *x;
    s.motionTimeS = t;
    m_motion += t;
    if (!run->trace)
        return makeError(ErrorCode::Device, "the move gave no trace");
    const auto& c = *run->trace;
    const bool full = value("position.feedback") >= 0.5;
    const model::Channel *tc = c.channel("t_s"), *cmd = nullptr, *pos = nullptr, *tq = c.channel("torque_cmd_Nm");
    for (const auto& ch : c.channels) {
        if (ch.name.rfind("position_cmd_", 0) == 0)
            cmd = &ch;
        if (ch.name.rfind(full ? "table_pos_" : "motor_pos_", 0) == 0)
            pos = &ch;
    }
    if (!tc || !cmd || !pos || !tq)
        return makeError(ErrorCode::Device,
                         "the move's trace lacks t_s, position_cmd_*, the feedback or torque_cmd_Nm");
    const std::size_t n = std::min({tc->data.size(), cmd->data.size(), pos->data.size(), tq->data.size()});
    if (n < 2)
        return makeError(ErrorCode::Device, "the move's trace is empty");
    // The end of the command: the last sample where it still changed.
    std::size_t end = n - 1;
    while (end > 0 && cmd->data[end - 1] == cmd->data[n - 1])
        --end;
    double fe = 0.0, peakTq = 0.0;
    std::optional<std::size_t> lastOutside;
    for (std::size_t k = 0; k < n; ++k) {
        fe = std::max(fe, std::abs(cmd->data[k] - pos->data[k]));
        peakTq = std::max(peakTq, std::abs(tq->data[k]));
        if (k >= end && std::abs(pos->data[k] - cmd->data[n - 1]) > window)
            lastOutside = k;
    }
    std::optional<double> settling;
    if (!lastOutside)
        settling = 0.0;
    else if (*lastOutside + 1 < n)
        settling = tc->data[*lastOutside + 1] - tc->data[end];
    const double maxTq = value("motor.torque_constant") * value("motor.max_current");
    const double headroom = maxTq > 0.0 ? 1.0 - peakTq / maxTq : 0.0;
    s.measured = {{"peak_following_error", fe}, {"peak_torque_Nm", peakTq}, {"torque_headroom_pct", 100.0 * headroom}};
    model::putOptional(s.measured, "settling_time_s", settling, 1.0,
                       "the position did not stay within the window before the record ended");
    s.chosen = {{"position", m_sites.back().x},
                {"distance", j.distance},
                {"velocity", j.velocity},
                {"acceleration", j.acceleration},
                {"window", window}};
    s.rule = "a point-to-point move there and back at the last position with the tuned gains; settling time from the "
             "end of the command until the feedback stays within the window; peak following error; torque headroom "
             "against k_t * I_max (at least 10 %)";
    if (headroom < 0.1)
        return makeError(ErrorCode::Safety, "the move needs " + num(peakTq, 3) + " N m of " + num(maxTq, 3) +
                                                " N m: less than 10 % torque headroom");
    m_fin.settlingTimeS = settling;
    m_fin.peakFollowingError = fe;
    return s;
}

Result<std::string> Positions::verify(Step& s)
{
    s.name = "verify";
    std::string why;
    nlohmann::json per = nlohmann::json::array();
    // In the reverse order: the axis stands at the last position.
    for (auto it = m_sites.rbegin(); it != m_sites.rend(); ++it) {
        auto& site = *it;
        if (auto st = moveTo(site.x, s.motionTimeS); !st)
            return st.error();
        auto a = measure(m_pct, s.motionTimeS);
        if (!a)
            return a.error();
        std::vector<double> f, lf;
        std::vector<std::complex<double>> tm, lh;
        validOf(a->measurement.frf, f, tm);
        validOf(dsp::openLoopFromClosedLoop(a->measurement.frf, dsp::LoopMeasurement::Complementary), lf, lh);
        const auto m = margins(lf, lh);
        const auto bw = closedLoopBandwidthHz(f, tm);
        const auto pbw = closedLoopBandwidthHz(f, positionClosed(f, tm, m_kpPos));
        nlohmann::json p{{"position", site.x}, {"valid_lines", a->validLines}};
        model::putOptional(p, "phase_margin_deg", finiteOr(m.phaseMarginDeg), 1.0, "no gain crossover in the band");
        model::putOptional(p, "gain_margin_dB", finiteOr(m.gainMarginDb), 1.0, "no -180 deg crossing in the band");
        model::putOptional(p, "velocity_bandwidth_Hz", bw, 1.0, "|T| does not fall 3 dB in the band");
        per.push_back(p);
        site.fin.phaseMarginDeg = std::isfinite(m.phaseMarginDeg) ? m.phaseMarginDeg : 0.0;
        site.fin.gainMarginDb = std::isfinite(m.gainMarginDb) ? m.gainMarginDb : 0.0;
        site.fin.velocityBandwidthHz = bw.value_or(0.0);
        site.fin.positionBandwidthHz = pbw.value_or(0.0);
        const std::string at = (why.empty() ? "" : "; ") + std::string("at ") + num(site.x, 4) + ": ";
        if (!std::isfinite(m.phaseMarginDeg) || m.phaseMarginDeg < m_t.acceptPhaseMarginDeg ||
            !std::isfinite(m.gainMarginDb) || m.gainMarginDb < m_t.acceptGainMarginDb)
            why += at + (std::isfinite(m.phaseMarginDeg) ? num(m.phaseMarginDeg, 3) + " deg" : std::string("no")) +
                   " phase margin and " +
                   (std::isfinite(m.gainMarginDb) ? num(m.gainMarginDb, 3) + " dB" : std::string("an unknown")) +
                   " gain margin";
        else if (!bw || !pbw)
            why += at + "the re-measured closed loop does not fall 3 dB within the band";
    }
    s.measured = {{"positions", per}};
    s.chosen = {{"accept_phase_margin_deg", m_t.acceptPhaseMarginDeg},
                {"accept_gain_margin_dB", m_t.acceptGainMarginDb}};
    s.rule = "the closed velocity loop measured again at every position (moved there by a jog); margins of "
             "L = T/(1-T) on its valid lines (smallest over every crossover) must be at least the style's " +
             num(m_t.acceptPhaseMarginDeg, 3) + " deg and " + num(m_t.acceptGainMarginDb, 3) + " dB at EVERY position";
    return why;
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
        return makeError(ErrorCode::BadInput, "--positions " + whole(m_o.positions) + ": " + st.error().detail);
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
        for (int i = 0; i < m_o.positions; ++i) {
            Site site;
            site.x = -w + 2.0 * w * static_cast<double>(i) / static_cast<double>(m_o.positions - 1);
            m_sites.push_back(std::move(site));
        }
        m_pct = std::min(m_t.frfAmplitudePct, limits->frfAmplitudeMaxPct);
        nlohmann::json xs = nlohmann::json::array();
        for (const auto& site : m_sites)
            xs.push_back(site.x);
        s.measured = {{"travel_window", w}, {"start_position", m_start}, {"axis_units", m_linear ? "m" : "rad"}};
        s.chosen = {{"positions", xs}, {"frf_amplitude_pct", m_pct}, {"time_budget_s", m_o.timeBudgetS}};
        s.rule = whole(m_o.positions) + " positions evenly over the drive's travel window -" + num(w, 4) + " ... +" +
                 num(w, 4) + (m_linear ? " m" : " rad") +
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

} // namespace

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

// SPDX-License-Identifier: GPL-3.0-or-later
// The notch step of the tuner over the travel (AutoTunePositionsRun.h) and the notch designs for a resonance that
// moves over the travel (AutoTunePositionsNotches.h).
#include "core/autotune/AutoTunePositionsNotches.h"

#include "core/autotune/AutoTunePositionsRun.h"
#include "core/autotune/SlidingPlant.h"
#include "core/tuning/VelocityLoopDesign.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

namespace axistune::autotune::detail {

namespace {

/// A notch at f0 with digital -3 dB width `width` and `depth`, or nothing when the rate cannot run it.
std::optional<tuning::ProposedNotch> notchAt(double f0, double width, double depth, double resonanceHz,
                                             double execRateHz)
{
    const double nyquist = 0.5 * execRateHz;
    if (!(f0 > 0.0) || !(f0 < nyquist) || !(depth >= 0.0) || !(depth < 1.0) || !(width > 0.0))
        return std::nullopt;
    width = std::min(width, std::min(f0, 2.0 * (nyquist - f0)));
    tuning::ProposedNotch n;
    n.spec = {f0, tuning::notchWidthParameter(f0, width, execRateHz), depth};
    n.digitalWidthHz = width;
    n.resonanceHz = resonanceHz;
    if (!dsp::designNotch(n.spec, 1.0 / execRateHz))
        return std::nullopt;
    return n;
}

/// Adds n unless its resonance lies within kSameNotch of the centre of a notch already in `out`.
void addMerged(std::vector<tuning::ProposedNotch>& out, const tuning::ProposedNotch& n)
{
    const bool covered = std::any_of(out.begin(), out.end(), [&](const tuning::ProposedNotch& c) {
        return std::abs(n.resonanceHz - c.spec.centerHz) <= kSameNotch * c.spec.centerHz;
    });
    if (!covered)
        out.push_back(n);
}

std::string fraction(double q)
{
    return num(q, 3);
}

} // namespace

std::vector<NotchDesign> movingResonanceNotchDesigns(const std::vector<PositionResonances>& positions,
                                                     double execRateHz)
{
    std::vector<NotchDesign> out;
    out.push_back({"none", "no new notch", {}});
    const auto peakSized = [&](double q, bool zeroPole, const tuning::Resonance& r) {
        const double d = std::pow(10.0, -q * r.peakDb / 20.0);
        const double w = zeroPole ? std::max(r.widthHz / d, r.widthHz) : r.widthHz;
        return notchAt(r.freqHz, w, d, r.freqHz, execRateHz);
    };
    // The moving resonance: the lowest of every position that has one.
    double lo = kInf, hi = 0.0, hMin = kInf;
    for (const auto& p : positions)
        if (!p.resonances.empty()) {
            lo = std::min(lo, p.resonances.front().freqHz);
            hi = std::max(hi, p.resonances.front().freqHz);
            hMin = std::min(hMin, p.resonances.front().peakDb);
        }
    if (hi > lo * (1.0 + kSameNotch))
        for (const double k : kBandWidthFactors)
            for (const double q : kPeakFractions) {
                NotchDesign d;
                d.name = "band " + fraction(q) + " x" + num(k, 2);
                d.rule = "one notch for the moving resonance " + num(lo, 4) + " ... " + num(hi, 4) +
                         " Hz at their geometric mean, digital width " + num(k, 2) + " x their distance, depth 10^(-" +
                         fraction(q) + " H_min/20), H_min " + num(hMin, 3) + " dB; the other resonances as 'peak " +
                         fraction(q) + " zp'";
                const double c = std::sqrt(lo * hi);
                if (auto n = notchAt(c, k * (hi - lo), std::pow(10.0, -q * hMin / 20.0), c, execRateHz))
                    d.notches.push_back(*n);
                for (const auto& p : positions)
                    for (std::size_t i = 1; i < p.resonances.size(); ++i)
                        if (auto n = peakSized(q, true, p.resonances[i]))
                            addMerged(d.notches, *n);
                out.push_back(std::move(d));
            }
    for (const bool zeroPole : {true, false})
        for (const double q : kPeakFractions) {
            NotchDesign d;
            d.name = "peak " + fraction(q) + (zeroPole ? " zp" : " w");
            d.rule = "at each position a notch at every resonance, depth 10^(-" + fraction(q) +
                     " H/20) (H its height above the baseline), digital width " +
                     (zeroPole ? std::string("w/depth (zeros on the mode's poles) within w ... f_r")
                               : std::string("w (the peak's own -3 dB width)"));
            for (const auto& p : positions)
                for (const auto& r : p.resonances)
                    if (auto n = peakSized(q, zeroPole, r))
                        addMerged(d.notches, *n);
            out.push_back(std::move(d));
        }
    NotchDesign w;
    w.name = "wizard";
    w.rule = "the notch wizard's proposal at each position (tuning::analyseNotches)";
    for (const auto& p : positions)
        for (const auto& n : p.wizard)
            addMerged(w.notches, n);
    out.push_back(std::move(w));
    return out;
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
        const std::string p = "filter.notch" + wholeText(k) + ".";
        if (!std::isfinite(value(p + "center")))
            break;
        slots = k;
        if (value(p + "center") > 0.0 && value(p + "depth") < 1.0)
            existing[k] = {value(p + "center"), value(p + "width"), value(p + "depth")};
    }
    std::vector<PositionResonances> found;
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
        PositionResonances pr;
        pr.x = site.x;
        nlohmann::json rj = nlohmann::json::array();
        for (const auto& r : a->resonances)
            if (r.freqHz >= ro.fminHz) {
                pr.resonances.push_back(r);
                rj.push_back({{"f_Hz", r.freqHz},
                              {"height_dB", r.peakDb},
                              {"width_Hz", r.widthHz},
                              {"open_loop_dB", r.levelDb}});
            }
        pr.wizard = a->notches;
        found.push_back(std::move(pr));
        per.push_back({{"position", site.x}, {"resonances", rj}});
    }
    std::vector<int> free;
    for (int k = 1; k <= slots; ++k)
        if (!existing.count(k))
            free.push_back(k);
    // Every design: each position's plant with its notches, the PI search of the velocity-PI step over all of them;
    // the widest worst-case bandwidth wins (an earlier design in the list keeps its place unless a later one is wider
    // by more than kDesignBandwidthGain).
    const auto designs = movingResonanceNotchDesigns(found, exec);
    nlohmann::json tried = nlohmann::json::array();
    std::optional<std::size_t> best;
    double bestBw = 0.0, highest = 0.0;
    for (std::size_t i = 0; i < designs.size(); ++i) {
        const auto& d = designs[i];
        nlohmann::json dj{{"design", d.name}, {"notches", d.notches.size()}};
        if (d.notches.size() > free.size()) {
            dj["result"] = "needs " + wholeText(static_cast<long long>(d.notches.size())) + " notch slots, " +
                           wholeText(static_cast<long long>(free.size())) + " free";
            tried.push_back(dj);
            continue;
        }
        std::vector<dsp::NotchSpec> specs;
        for (const auto& n : d.notches)
            specs.push_back(n.spec);
        if (auto st = plantsWith(specs, exec); !st)
            return st.error();
        auto r = searchPi(m_sites, m_t, m_caps.traceRateHz, kInf);
        if (!r)
            return r.error();
        highest = std::max(highest, r->highestOkHz);
        dj["highest_crossover_Hz"] = r->highestOkHz;
        if (r->found) {
            dj["worst_velocity_bandwidth_Hz"] = r->worstBandwidthHz;
            dj["crossover_Hz"] = r->crossoverHz;
            if (!best || r->worstBandwidthHz > bestBw * (1.0 + kDesignBandwidthGain)) {
                best = i;
                bestBw = r->worstBandwidthHz;
            }
        } else
            dj["result"] = "no PI reaches " + num(fReq, 4) + " Hz with the margins at every position";
        tried.push_back(dj);
    }
    s.measured = {{"positions", per},
                  {"designs", tried},
                  {"existing_notches", existing.size()},
                  {"free_slots", free.size()},
                  {"exec_rate_Hz", exec}};
    s.rule = "notch designs for the resonances of every position above " + num(kResonanceSeparation, 2) +
             "x the required crossover (" + num(fReq, 4) +
             " Hz) on the open loop L = T/(1-T), in this order: none; one band notch over the moving resonance (width "
             "1 ... 2x its range, depth 10^(-q H_min/20), q = 0.25 ... 1); a peak-sized notch at every resonance of "
             "every position (depth 10^(-q H/20), width w/depth or w); the notch wizard's at every position; each "
             "predicted on every position's measured plant and searched with the velocity-PI step's rule; the design "
             "with the widest worst-case closed-loop bandwidth wins, a later one in the order only when wider by more "
             "than " +
             num(100.0 * kDesignBandwidthGain, 2) +
             " % (a notch sized at the measured positions does not follow the resonance between them); a resonance "
             "within a factor " +
             num(kResonanceSeparation, 2) + " of the crossover at any position refuses the tuning";
    if (!best) {
        // The refusal's reason is the velocity-PI step's: no design reaches the required crossover.
        if (auto st = plantsWith({}, exec); !st)
            return st.error();
        s.chosen = {{"design", nullptr}};
        done(s);
        return makeError(ErrorCode::Safety,
                         "the required velocity crossover " + num(fReq, 4) + " Hz cannot be reached with " +
                             num(m_t.phaseMarginDeg, 3) + " deg phase and " + num(m_t.gainMarginDb, 3) +
                             " dB gain margin at every position with any of " +
                             wholeText(static_cast<long long>(designs.size())) + " notch designs" +
                             (highest > 0.0 ? " (highest: " + num(highest, 4) + " Hz)" : std::string()));
    }
    const auto& d = designs[*best];
    model::ParameterValues v;
    std::vector<dsp::NotchSpec> specs;
    nlohmann::json cj = nlohmann::json::array();
    for (std::size_t i = 0; i < d.notches.size(); ++i) {
        auto n = d.notches[i];
        n.slot = free[i];
        const std::string p = "filter.notch" + wholeText(n.slot) + ".";
        v[p + "center"] = n.spec.centerHz;
        v[p + "width"] = n.spec.widthHz;
        v[p + "depth"] = n.spec.depth;
        specs.push_back(n.spec);
        cj.push_back({{"slot", n.slot},
                      {"center_Hz", n.spec.centerHz},
                      {"width_Hz", n.spec.widthHz},
                      {"digital_width_Hz", n.digitalWidthHz},
                      {"depth", n.spec.depth},
                      {"resonance_Hz", n.resonanceHz}});
    }
    if (auto st = plantsWith(specs, exec); !st)
        return st.error();
    s.chosen = {{"design", d.name}, {"notches", cj}, {"predicted_worst_velocity_bandwidth_Hz", bestBw}};
    s.rule += "; chosen: '" + d.name + "': " + d.rule;
    if (!v.empty())
        if (auto st = write(v); !st)
            return st.error();
    return s;
}

Status Positions::plantsWith(const std::vector<dsp::NotchSpec>& specs, double execRateHz)
{
    // P = plant of the measured T at the running PI, times L_after/L_before of the notch prediction (Π N_k on every
    // line), as the single-position sequence.
    const tuning::VelocityPi running{value("velocity.kp"), value("velocity.ki")};
    for (auto& site : m_sites) {
        const auto& t = site.frf.measurement.frf;
        auto plant = tuning::plantFromMeasurement(t, tuning::LoopMeasurementKind::Complementary, running,
                                                  value("velocity.period"), value("current.period"));
        if (!plant)
            return plant.error();
        site.plant = std::move(plant).value();
        // The axis in motion (SlidingPlant.h): the damping friction adds at standstill removed, before the notches.
        auto standstill = standstillDamping(site.plant);
        if (!standstill)
            return makeError(standstill.error().code, "at " + num(site.x, 4) + ": " + standstill.error().detail);
        site.standstillDampingNmsPerRad = standstill->bNmsPerRad;
        std::vector<std::complex<double>> slide(site.plant.size());
        for (std::size_t i = 0; i < site.plant.size(); ++i)
            slide[i] = slidingPlant(site.plant.h[i], standstill->bNmsPerRad) / site.plant.h[i];
        if (!specs.empty()) {
            auto pred = tuning::predictWithNotches(t, m_form, specs, execRateHz);
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
        site.pSlide.clear();
        for (std::size_t i = 0, k = 0; i < site.plant.size(); ++i)
            if (k < site.f.size() && site.plant.freqHz[i] == site.f[k])
                site.pSlide.push_back(site.p[k++] * slide[i]);
    }
    return {};
}

} // namespace axistune::autotune::detail

// SPDX-License-Identifier: GPL-3.0-or-later
// The design steps of the tuner over the travel (AutoTunePositionsRun.h): the PI search over every position's
// plant, the velocity PI and the position gain, and the helpers the steps share.
#include "core/autotune/AutoTunePositionsRun.h"
#include "core/model/ResultJson.h"
#include "core/tuning/VelocityLoopDesign.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune::autotune::detail {

std::string wholeText(long long n)
{
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, n);
    return std::string(buf, r.ptr);
}

dsp::LoopMargins loopMarginsOn(const std::vector<double>& f, const std::vector<std::complex<double>>& l)
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

void piLoops(const tuning::VelocityPi& pi, const Site& s, std::vector<std::complex<double>>& l,
             std::vector<std::complex<double>>& t)
{
    l.resize(s.f.size());
    t.resize(s.f.size());
    for (std::size_t k = 0; k < s.f.size(); ++k) {
        l[k] = tuning::piResponse(pi, s.f[k]) * s.p[k];
        t[k] = l[k] / (1.0 + l[k]);
    }
}

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

Result<PiSearch> searchPi(const std::vector<Site>& sites, const StyleTargets& tg, double traceRateHz, double capHz)
{
    PiSearch out;
    const double fReq = tg.minBandwidthHz;
    double fTop = 0.125 * traceRateHz, fBottom = 0.5 * fReq;
    for (const auto& site : sites) {
        if (site.f.empty())
            return makeError(ErrorCode::Safety, "no valid plant line at " + num(site.x, 4));
        fTop = std::min(fTop, site.f.back() / 2.0);
        fBottom = std::max(fBottom, site.f.front());
    }
    out.fBottom = fBottom;
    out.fTop = fTop;
    // Every PI designed on any position's plant for a crossover on the grid and a phase margin of the style plus
    // the reserve steps; it must keep the margins on EVERY position's plant; the widest worst-case bandwidth wins.
    std::vector<std::complex<double>> l, t, ls;
    for (std::size_t base = 0; base < sites.size(); ++base)
        for (const double extra : kDesignPhaseSteps) {
            const double pm = tg.phaseMarginDeg + kDesignPhaseReserveDeg + extra;
            for (int i = 0; i <= kGridSteps && fTop > fBottom; ++i) {
                const double f = fBottom * std::pow(fTop / fBottom, static_cast<double>(i) / kGridSteps);
                if (f > capHz)
                    break;
                auto pi = tuning::velocityPiFromFrf(sites[base].plant, f, pm);
                if (!pi || !(pi->kpNmsPerRad > 0.0) || !(pi->kiNmPerRad >= 0.0))
                    continue;
                if (pi->kiNmPerRad < kMinIntegralCornerRadS * pi->kpNmsPerRad)
                    continue;
                bool ok = true;
                double worstBw = kInf;
                std::vector<dsp::LoopMargins> ms;
                for (const auto& site : sites) {
                    l.resize(site.f.size());
                    for (std::size_t k = 0; k < site.f.size(); ++k)
                        l[k] = tuning::piResponse(*pi, site.f[k]) * site.p[k];
                    const auto m = loopMarginsOn(site.f, l);
                    ok = std::isfinite(m.phaseMarginDeg) && m.phaseMarginDeg >= tg.phaseMarginDeg &&
                         m.gainMarginDb >= tg.gainMarginDb + kDesignGainReserveDb;
                    if (!ok)
                        break;
                    // And on the plant in motion (SlidingPlant.h), as the one-position sequence.
                    ls.assign(site.f.size(), {});
                    for (std::size_t k = 0; k < site.f.size() && k < site.pSlide.size(); ++k)
                        ls[k] = tuning::piResponse(*pi, site.f[k]) * site.pSlide[k];
                    const auto msl = loopMarginsOn(site.f, ls);
                    ok = std::isfinite(msl.phaseMarginDeg) && msl.phaseMarginDeg >= tg.phaseMarginDeg &&
                         msl.gainMarginDb >= tg.gainMarginDb + kDesignGainReserveDb;
                    if (!ok)
                        break;
                    // The closed loop only for a PI that keeps the margins here (most of the grid does not).
                    t.resize(l.size());
                    for (std::size_t k = 0; k < l.size(); ++k)
                        t[k] = l[k] / (1.0 + l[k]);
                    worstBw = std::min(worstBw, closedLoopBandwidthHz(site.f, t).value_or(0.0));
                    ms.push_back(m);
                }
                if (ok && f > out.highestOkHz)
                    out.highestOkHz = f;
                if (ok && f >= fReq && worstBw > out.worstBandwidthHz) {
                    out.found = true;
                    out.worstBandwidthHz = worstBw;
                    out.crossoverHz = f;
                    out.pi = *pi;
                    out.margins = ms;
                    out.base = base;
                }
            }
        }
    return out;
}

Result<Step> Positions::velocityPi(double capHz)
{
    Step s;
    s.name = "velocity-pi";
    const double fReq = m_t.minBandwidthHz;
    auto search = searchPi(m_sites, m_t, m_caps.traceRateHz, capHz);
    if (!search)
        return search.error();
    const auto& r = *search;
    s.measured = {{"plant_lines", m_sites.front().f.size()},
                  {"positions", m_sites.size()},
                  {"crossover_searched_Hz", {r.fBottom, r.fTop}},
                  {"running_kp_Nms_per_rad", value("velocity.kp")},
                  {"running_ki_Nm_per_rad", value("velocity.ki")}};
    nlohmann::json damping = nlohmann::json::array();
    for (const auto& site : m_sites)
        damping.push_back({{"position", site.x}, {"standstill_damping_Nms_per_rad", site.standstillDampingNmsPerRad}});
    s.measured["standstill_damping"] = damping;
    if (!r.found)
        return makeError(ErrorCode::Safety,
                         "the required velocity crossover " + num(fReq, 4) + " Hz cannot be reached with " +
                             num(m_t.phaseMarginDeg, 3) + " deg phase and " + num(m_t.gainMarginDb, 3) +
                             " dB gain margin at every position" +
                             (r.highestOkHz > 0.0 ? " (highest: " + num(r.highestOkHz, 4) + " Hz)" : std::string()));
    m_pi = r.pi;
    m_fc = r.crossoverHz;
    m_worstVelocityBwHz = r.worstBandwidthHz;
    nlohmann::json pred = nlohmann::json::array();
    for (std::size_t i = 0; i < m_sites.size(); ++i) {
        m_sites[i].fin.predictedPhaseMarginDeg = r.margins[i].phaseMarginDeg;
        m_sites[i].fin.predictedGainMarginDb = r.margins[i].gainMarginDb;
        nlohmann::json p{{"position", m_sites[i].x}};
        model::putOptional(p, "phase_margin_deg", finiteOr(r.margins[i].phaseMarginDeg), 1.0, "no gain crossover");
        model::putOptional(p, "gain_margin_dB", finiteOr(r.margins[i].gainMarginDb), 1.0, "no -180 deg crossing");
        pred.push_back(p);
    }
    s.chosen = {{"velocity.kp", r.pi.kpNmsPerRad},
                {"velocity.ki", r.pi.kiNmPerRad},
                {"crossover_Hz", r.crossoverHz},
                {"designed_on_position", m_sites[r.base].x},
                {"predicted_worst_velocity_bandwidth_Hz", r.worstBandwidthHz},
                {"predicted", pred}};
    s.rule = "of the PIs designed (tuning::velocityPiFromFrf) on the plant of each position for a crossover on a " +
             wholeText(kGridSteps) + "-step log grid " + num(r.fBottom, 4) + " ... " + num(std::min(r.fTop, capHz), 4) +
             " Hz (at least the required " + num(fReq, 4) + " Hz) and a phase margin of " +
             num(m_t.phaseMarginDeg + kDesignPhaseReserveDeg, 3) + " ... " +
             num(m_t.phaseMarginDeg + kDesignPhaseReserveDeg + kDesignPhaseSteps[4], 3) +
             " deg, the one with the widest worst-case closed-loop bandwidth that keeps at least " +
             num(m_t.phaseMarginDeg, 3) + " deg and " + num(m_t.gainMarginDb + kDesignGainReserveDb, 3) +
             " dB on the measured plant with the notches at EVERY position (integral corner k_i/k_p at least 1 Hz)";
    if (auto st = write({{"velocity.kp", r.pi.kpNmsPerRad}, {"velocity.ki", r.pi.kiNmPerRad}}); !st)
        return st.error();
    return s;
}

Result<Step> Positions::position()
{
    Step s;
    s.name = "position";
    // K_p = ω_v/5 (the velocity wizard's rule; ω_v the crossover or the narrowest predicted velocity bandwidth,
    // whichever is lower: the position loop never faster than the velocity loop it commands), lowered until the open
    // position loop K_p·T_v/(jω) keeps kPositionGainMarginDb of gain margin at every position (T_v the predicted closed
    // velocity loop there).
    const double fVel = m_worstVelocityBwHz > 0.0 ? std::min(m_fc, m_worstVelocityBwHz) : m_fc;
    double kp = kTwoPi * fVel / 5.0, limit = kInf;
    std::vector<std::complex<double>> l, t;
    for (const auto& site : m_sites) {
        piLoops(m_pi, site, l, t);
        const auto m = loopMarginsOn(site.f, positionOpen(site.f, t));
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
    s.measured = {{"running_position_kp_per_s", value("position.kp")},
                  {"velocity_crossover_Hz", m_fc},
                  {"velocity_frequency_Hz", fVel}};
    model::putOptional(s.measured, "worst_stability_limit_per_s", finiteOr(limit), 1.0,
                       "the predicted position loops have no -180 deg crossing in the band");
    s.rule = "K_p = min(2pi*f_v/5, f_v = min(the velocity crossover, the narrowest predicted velocity bandwidth) = " +
             num(fVel, 4) + " Hz; the largest K_p that keeps " + num(tuning::kPositionGainMarginDb, 2) +
             " dB of gain margin in K_p*T_v/(j omega) at every position, T_v predicted there); velocity and torque "
             "feedforward 1 (torque with the drive's velocity.inertia, kept)";
    if (auto st = write(v); !st)
        return st.error();
    return s;
}

} // namespace axistune::autotune::detail

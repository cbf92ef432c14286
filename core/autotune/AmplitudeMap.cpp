// SPDX-License-Identifier: GPL-3.0-or-later
// Amplitude dependence map and reversal backlash (AmplitudeMap.h; docs/tuning.md "Amplitude map and backlash").
#include "core/autotune/AmplitudeMap.h"

#include "core/device/MultisineTest.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/model/ResultJson.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>

namespace axistune::autotune {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string num(double v, int significant = 4)
{
    return model::formatNumber(v, significant);
}

bool finite(std::complex<double> h)
{
    return std::isfinite(h.real()) && std::isfinite(h.imag());
}

/// Index of the line at f (lines increasing), or npos.
std::size_t lineAt(const std::vector<AmplitudeLine>& lines, double f, double spacing)
{
    auto it = std::lower_bound(lines.begin(), lines.end(), f - 0.1 * spacing,
                               [](const AmplitudeLine& l, double v) { return l.freqHz < v; });
    if (it != lines.end() && std::abs(it->freqHz - f) < 0.1 * spacing)
        return static_cast<std::size_t>(it - lines.begin());
    return std::string::npos;
}

} // namespace

void classifyAmplitudeLines(AmplitudeMap& map)
{
    map.compared = 0;
    map.nonlinear = 0;
    for (auto& l : map.lines) {
        std::vector<std::size_t> use;
        for (std::size_t a = 0; a < l.h.size() && a < map.runs.size(); ++a)
            if (!map.runs[a].voltageLimited && finite(l.h[a]) && std::abs(l.h[a]) > 0.0 && a < l.relativeNoise.size() &&
                std::isfinite(l.relativeNoise[a]) && l.relativeNoise[a] > 0.0)
                use.push_back(a);
        l.compared = use.size() >= 2;
        l.nonlinear = false;
        l.maxZ = kNaN;
        l.magnitudeSpreadDb = kNaN;
        l.phaseSpreadDeg = kNaN;
        if (!l.compared)
            continue;
        ++map.compared;
        double maxZ = 0.0, dbMin = 1e300, dbMax = -1e300, phMin = 1e300, phMax = -1e300;
        const double ref = std::arg(l.h[use.front()]);
        for (std::size_t i = 0; i < use.size(); ++i) {
            const auto ha = l.h[use[i]];
            const double sa = l.relativeNoise[use[i]] * std::abs(ha);
            const double db = 20.0 * std::log10(std::abs(ha));
            // Phase relative to the first compared amplitude, wrapped into (−180°, 180°].
            const double ph = 180.0 / std::numbers::pi * std::arg(ha * std::polar(1.0, -ref));
            dbMin = std::min(dbMin, db);
            dbMax = std::max(dbMax, db);
            phMin = std::min(phMin, ph);
            phMax = std::max(phMax, ph);
            for (std::size_t k = i + 1; k < use.size(); ++k) {
                const auto hb = l.h[use[k]];
                const double sb = l.relativeNoise[use[k]] * std::abs(hb);
                maxZ = std::max(maxZ, std::abs(ha - hb) / std::hypot(sa, sb));
            }
        }
        l.maxZ = maxZ;
        l.magnitudeSpreadDb = dbMax - dbMin;
        l.phaseSpreadDeg = phMax - phMin;
        l.nonlinear = maxZ > kNonlinearSigmas;
        if (l.nonlinear)
            ++map.nonlinear;
    }
}

Status checkAmplitudeList(const std::vector<double>& pct)
{
    if (pct.size() < 3)
        return makeError(ErrorCode::BadInput, "an amplitude map needs at least three amplitudes A1,A2,A3 (got " +
                                                  num(static_cast<double>(pct.size()), 3) + ")");
    for (std::size_t i = 0; i < pct.size(); ++i) {
        if (!std::isfinite(pct[i]) || !(pct[i] > 0.0))
            return makeError(ErrorCode::BadInput, "amplitude " + num(pct[i], 4) + " %: must be > 0 % of rated torque");
        if (i > 0 && !(pct[i] > pct[i - 1]))
            return makeError(ErrorCode::BadInput,
                             "amplitudes must increase: " + num(pct[i], 4) + " % after " + num(pct[i - 1], 4) + " %");
    }
    return {};
}

Result<AmplitudeMap> measureAmplitudeMap(device::Drive& drive, const AmplitudeMapOptions& o,
                                         const device::RunOptions& run)
{
    if (auto st = checkAmplitudeList(o.amplitudesPct); !st)
        return st.error();
    if (!(o.periods >= 2))
        return makeError(ErrorCode::BadInput, "at least 2 periods per amplitude are needed (the noise of each line)");
    if (!(o.spacingHz > 0.0) || !std::isfinite(o.spacingHz) || !(o.fminHz > 0.0) || !std::isfinite(o.fminHz))
        return makeError(ErrorCode::BadInput, "the band's lowest frequency and spacing must be > 0 Hz");
    auto caps = drive.capabilities(o.axis);
    if (!caps)
        return caps.error();
    if (!caps->offers(device::FrfMethod::Multisine))
        return makeError(ErrorCode::BadInput, "axis " + o.axis + ": the drive offers no multisine FRF test");
    const double fmax = o.fmaxHz > 0.0 ? o.fmaxHz : 0.975 * caps->traceRateHz;
    if (!(fmax > o.fminHz))
        return makeError(ErrorCode::BadInput,
                         "the band " + num(o.fminHz, 4) + " ... " + num(fmax, 4) + " Hz is empty on axis " + o.axis);
    auto limits = drive.limits(o.axis);
    if (!limits)
        return limits.error();
    if (o.amplitudesPct.back() > limits->frfAmplitudeMaxPct)
        return makeError(ErrorCode::OutOfRange, "amplitude " + num(o.amplitudesPct.back(), 4) +
                                                    " % is above the drive's FRF limit of " +
                                                    num(limits->frfAmplitudeMaxPct, 4) + " % of rated torque");

    AmplitudeMap map;
    map.axis = o.axis;
    const std::size_t na = o.amplitudesPct.size();
    for (std::size_t a = 0; a < na; ++a) {
        device::TestRequest r;
        r.axis = o.axis;
        auto& f = r.test.emplace<device::FrfTest>();
        f.method = device::FrfMethod::Multisine;
        f.fminHz = o.fminHz;
        f.fmaxHz = fmax;
        f.multisineSpacingHz = o.spacingHz;
        f.multisinePeriods = o.periods;
        f.amplitudePct = o.amplitudesPct[a];
        if (o.timeBudgetS > 0.0) {
            auto plan = drive.planTest(r);
            if (plan && map.motionTimeS + plan->motionTimeS > o.timeBudgetS)
                return makeError(ErrorCode::Safety, "the amplitude map at " + num(f.amplitudePct, 3) +
                                                        " % would take " + num(plan->motionTimeS, 3) +
                                                        " s of motion, beyond its budget (" + num(o.timeBudgetS, 3) +
                                                        " s, " + num(map.motionTimeS, 3) + " s used)");
        }
        auto t = device::runTest(drive, r, run);
        if (!t) {
            const auto& e = t.error();
            return makeError(e.code, "amplitude map at " + num(f.amplitudePct, 3) + " %: " + e.detail);
        }
        if (!t->frf)
            return makeError(ErrorCode::Device,
                             "amplitude map at " + num(f.amplitudePct, 3) + " %: the drive gave no frequency response");
        const auto& m = *t->frf;
        AmplitudeRun ar;
        ar.amplitudePct = f.amplitudePct;
        ar.motionTimeS = m.motionTimeS;
        const auto& md = m.frf.metadata;
        ar.peakNm = kNaN;
        if (const auto* pk = md.find(model::meta::kPeakNm))
            if (auto x = pk->number())
                ar.peakNm = *x;
        ar.voltageLimited = device::voltageLimitReached(md);
        map.motionTimeS += m.motionTimeS;
        if (a == 0)
            for (std::size_t k = 0; k < m.frf.size(); ++k) {
                AmplitudeLine l;
                l.freqHz = m.frf.freqHz[k];
                l.h.assign(na, {kNaN, kNaN});
                l.relativeNoise.assign(na, kNaN);
                map.lines.push_back(std::move(l));
            }
        const double pd = static_cast<double>(o.periods);
        for (std::size_t k = 0; k < m.frf.size(); ++k) {
            const auto i = lineAt(map.lines, m.frf.freqHz[k], o.spacingHz);
            if (i == std::string::npos)
                continue;
            // σ_H/|H| as the drive gave it, else (a drive that sends the coherence only, e.g. over Modbus) from the
            // coherence over P periods of an exactly periodic excitation (as the adaptive FRF does).
            double rel = kNaN;
            if (m.relativeNoise.size() == m.frf.size())
                rel = m.relativeNoise[k];
            else if (k < m.frf.coherence.size() && m.frf.coherence[k] > 0.0)
                rel = std::sqrt(std::max(0.0, 1.0 - m.frf.coherence[k]) / (m.frf.coherence[k] * (pd - 1.0)));
            map.lines[i].h[a] = m.frf.h[k];
            map.lines[i].relativeNoise[a] = rel;
            if (k < m.frf.valid.size() && m.frf.valid[k])
                ++ar.validLines;
        }
        map.runs.push_back(ar);
    }
    classifyAmplitudeLines(map);
    return map;
}

std::optional<std::size_t> amplitudeInUse(const AmplitudeMap& map, double useTorquePct)
{
    std::optional<std::size_t> best;
    double bestD = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < map.runs.size(); ++a) {
        if (map.runs[a].voltageLimited || !(map.runs[a].amplitudePct > 0.0))
            continue;
        const double d = std::abs(std::log(map.runs[a].amplitudePct / std::max(useTorquePct, 1e-9)));
        if (d < bestD) {
            bestD = d;
            best = a;
        }
    }
    return best;
}

nlohmann::json amplitudeMapJson(const AmplitudeMap& map)
{
    nlohmann::json j;
    j["axis"] = map.axis;
    j["rule"] = "closed velocity loop T by multisine at each amplitude; a line is non-linear when two amplitudes "
                "below the voltage limit differ by more than " +
                num(kNonlinearSigmas, 2) + " combined standard errors: |H_a - H_b| / sqrt(sigma_a^2 + sigma_b^2) > " +
                num(kNonlinearSigmas, 2) + ", sigma = (sigma_H/|H|)*|H| from the scatter over the periods";
    j["threshold_sigmas"] = kNonlinearSigmas;
    nlohmann::json runs = nlohmann::json::array();
    for (const auto& r : map.runs) {
        nlohmann::json rj{{"amplitude_pct", r.amplitudePct},
                          {"motion_time_s", r.motionTimeS},
                          {"voltage_limited", r.voltageLimited},
                          {"valid_lines", r.validLines}};
        model::putNumber(rj, "peak_Nm", r.peakNm, "the drive did not state the multisine's peak torque");
        runs.push_back(rj);
    }
    j["amplitudes"] = runs;
    nlohmann::json lines = nlohmann::json::array();
    for (const auto& l : map.lines) {
        nlohmann::json per = nlohmann::json::array();
        for (std::size_t a = 0; a < l.h.size() && a < map.runs.size(); ++a) {
            if (!finite(l.h[a]) || !(std::abs(l.h[a]) > 0.0))
                continue;
            nlohmann::json pa{{"amplitude_pct", map.runs[a].amplitudePct},
                              {"magnitude_dB", 20.0 * std::log10(std::abs(l.h[a]))},
                              {"phase_deg", 180.0 / std::numbers::pi * std::arg(l.h[a])}};
            model::putNumber(pa, "relative_noise", a < l.relativeNoise.size() ? l.relativeNoise[a] : kNaN,
                             "the drive gave neither the line's noise nor its coherence");
            per.push_back(pa);
        }
        nlohmann::json lj{{"f_Hz", l.freqHz}, {"at", per}, {"compared", l.compared}, {"nonlinear", l.nonlinear}};
        const std::string why = "fewer than two amplitudes below the voltage limit with a noise estimate";
        model::putNumber(lj, "max_z", l.maxZ, why);
        model::putNumber(lj, "magnitude_spread_dB", l.magnitudeSpreadDb, why);
        model::putNumber(lj, "phase_spread_deg", l.phaseSpreadDeg, why);
        lines.push_back(lj);
    }
    j["lines"] = lines;
    j["lines_compared"] = map.compared;
    j["nonlinear_lines"] = map.nonlinear;
    j["nonlinear_fraction"] = map.nonlinearFraction();
    j["motion_time_s"] = map.motionTimeS;
    return j;
}

Result<BacklashEstimate> backlashFromReversal(const model::Capture& c)
{
    const auto* cmd = c.channel("position_cmd_m");
    const auto* xm = c.channel("motor_pos_m");
    const auto* xt = c.channel("table_pos_m");
    const auto* tq = c.channel("torque_Nm");
    if (!cmd || !xm || !xt || !tq)
        return makeError(ErrorCode::NotFound,
                         "the reversal's trace lacks position_cmd_m, motor_pos_m, table_pos_m or torque_Nm (a linear "
                         "axis with motor and table position is needed)");
    const std::size_t n = std::min({cmd->data.size(), xm->data.size(), xt->data.size(), tq->data.size()});
    if (n < 3)
        return makeError(ErrorCode::BadInput, "the reversal's trace is empty");
    // Commanded velocity by central differences (only its sign and its size relative to the peak matter).
    std::vector<double> v(n, 0.0);
    double vmax = 0.0;
    for (std::size_t k = 1; k + 1 < n; ++k) {
        v[k] = 0.5 * (cmd->data[k + 1] - cmd->data[k - 1]);
        vmax = std::max(vmax, std::abs(v[k]));
    }
    if (!(vmax > 0.0))
        return makeError(ErrorCode::BadInput, "the reversal's command does not move");
    // y = x_m − x_t = c_+·[v > 0] + c_−·[v < 0] + k·T over the samples moving at ≥ half the peak speed (the play taken
    // up on one flank). With one intercept per direction the slope is the pooled within-direction regression.
    double n1[2] = {0, 0}, st[2] = {0, 0}, sy[2] = {0, 0}, stt = 0.0, sty = 0.0;
    std::vector<std::array<double, 3>> rows; // direction, T, y
    for (std::size_t k = 1; k + 1 < n; ++k) {
        if (std::abs(v[k]) < 0.5 * vmax)
            continue;
        const int d = v[k] > 0.0 ? 0 : 1;
        const double t = tq->data[k], y = xm->data[k] - xt->data[k];
        n1[d] += 1.0;
        st[d] += t;
        sy[d] += y;
        stt += t * t;
        sty += t * y;
        rows.push_back({static_cast<double>(d), t, y});
    }
    if (n1[0] < 10.0 || n1[1] < 10.0)
        return makeError(ErrorCode::BadInput, "the reversal's trace has fewer than 10 samples moving in a direction");
    const double sxx = stt - st[0] * st[0] / n1[0] - st[1] * st[1] / n1[1];
    const double sxy = sty - st[0] * sy[0] / n1[0] - st[1] * sy[1] / n1[1];
    if (!(sxx > 0.0))
        return makeError(ErrorCode::BadInput, "the reversal's torque does not vary: the elastic part is not separable");
    const double k = sxy / sxx;
    const double cp = (sy[0] - k * st[0]) / n1[0], cn = (sy[1] - k * st[1]) / n1[1];
    double ss = 0.0;
    for (const auto& r : rows) {
        const double e = r[2] - (r[0] == 0.0 ? cp : cn) - k * r[1];
        ss += e * e;
    }
    BacklashEstimate b;
    b.backlashM = cp - cn;
    b.complianceMPerNm = k;
    b.samples = rows.size();
    b.residualRmsM = std::sqrt(ss / static_cast<double>(rows.size()));
    if (!std::isfinite(b.backlashM))
        return makeError(ErrorCode::BadInput, "the reversal's lost motion is not finite");
    return b;
}

device::TestRequest backlashReversal(const std::string& axis, double distanceM, double velocityMPerS,
                                     double accelerationMPerS2)
{
    device::JogTest j;
    j.distance = distanceM;
    j.velocity = velocityMPerS;
    j.acceleration = accelerationMPerS2;
    j.returnToStart = true;
    j.dwellS = kBacklashDwellS;
    device::TestRequest r;
    r.axis = axis;
    r.test = j;
    return r;
}

Result<BacklashEstimate> measureBacklash(device::Drive& drive, const std::string& axis, double distanceM,
                                         double velocityMPerS, double accelerationMPerS2, const device::RunOptions& run,
                                         double& motionS)
{
    motionS = 0.0;
    auto r = device::runTest(drive, backlashReversal(axis, distanceM, velocityMPerS, accelerationMPerS2), run);
    if (!r)
        return r.error();
    if (!r->trace)
        return makeError(ErrorCode::Device, "the reversal gave no trace");
    motionS = device::motionTimeS(*r);
    return backlashFromReversal(*r->trace);
}

device::TestRequest moveEvaluationRequest(const std::string& axis, bool linear)
{
    device::JogTest j;
    j.distance = linear ? 0.01 : 0.2;
    j.velocity = linear ? 0.05 : 1.0;
    j.acceleration = linear ? 1.0 : 20.0;
    j.dwellS = 0.15;
    device::TestRequest r;
    r.axis = axis;
    r.test = j;
    return r;
}

Result<InUseMap> amplitudeMapInUse(device::Drive& drive, const AmplitudeMapOptions& options, bool linear,
                                   double ratedTorqueNm, const device::RunOptions& run)
{
    if (!(ratedTorqueNm > 0.0) || !std::isfinite(ratedTorqueNm))
        return makeError(ErrorCode::Device, "the rated torque k_t * I_rated is not known");
    InUseMap out;
    auto move = moveEvaluationRequest(options.axis, linear);
    auto plan = drive.planTest(move);
    if (options.timeBudgetS > 0.0 && plan && plan->motionTimeS > options.timeBudgetS)
        return makeError(ErrorCode::Safety, "the move for the torque in use would take " + num(plan->motionTimeS, 3) +
                                                " s of motion, beyond the budget left (" + num(options.timeBudgetS, 3) +
                                                " s)");
    auto r = device::runTest(drive, move, run);
    if (!r) {
        const auto& e = r.error();
        return makeError(e.code, (e.code == ErrorCode::Safety ? "drive fault during the move for the torque in use: "
                                                              : "the move for the torque in use: ") +
                                     e.detail);
    }
    const model::Channel* tq = r->trace ? r->trace->channel("torque_cmd_Nm") : nullptr;
    if (!tq || tq->data.empty())
        return makeError(ErrorCode::Device, "the move for the torque in use gave no torque_cmd_Nm trace");
    for (double x : tq->data)
        out.peakTorqueNm = std::max(out.peakTorqueNm, std::abs(x));
    const double moveS = device::motionTimeS(*r, plan);
    out.useTorquePct = 100.0 * out.peakTorqueNm / ratedTorqueNm;
    AmplitudeMapOptions o = options;
    if (o.timeBudgetS > 0.0) {
        o.timeBudgetS -= moveS;
        if (!(o.timeBudgetS > 0.0))
            return makeError(ErrorCode::Safety, "no time left in the budget for the amplitude map");
    }
    auto m = measureAmplitudeMap(drive, o, run);
    if (!m) {
        const auto& e = m.error();
        return makeError(e.code, e.code == ErrorCode::Safety && e.detail.find("budget") == std::string::npos
                                     ? "drive fault during the " + e.detail
                                     : e.detail);
    }
    out.map = std::move(m).value();
    out.motionTimeS = moveS + out.map.motionTimeS;
    out.use = amplitudeInUse(out.map, out.useTorquePct);
    return out;
}

nlohmann::json inUseJson(const InUseMap& m)
{
    auto j = amplitudeMapJson(m.map);
    j["move_peak_torque_Nm"] = m.peakTorqueNm;
    j["use_torque_pct"] = m.useTorquePct;
    if (m.use)
        j["design_amplitude_pct"] = m.map.runs[*m.use].amplitudePct;
    else
        model::putUndefined(j, "design_amplitude_pct", "every amplitude reached the voltage limit");
    return j;
}

} // namespace axistune::autotune

// SPDX-License-Identifier: GPL-3.0-or-later
// Adaptive multisine FRF (AdaptiveFrf.h; docs/multisine.md "Adaptive measurement").
#include "core/device/AdaptiveFrf.h"

#include "core/device/FrfRequestPlan.h"
#include "core/device/MultisineTest.h"
#include "core/dsp/Multisine.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numeric>

namespace axistune::device {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// Lines that need no more excitation but sit inside a band get this fraction of the largest amplitude.
constexpr double kFillWeight = 0.03;
/// Two passes of a line disagree (non-linear) when they differ by more than this many standard errors.
constexpr double kConsistencySigmas = 5.0;
constexpr std::size_t kMaxBands = 4;

struct Line {
    double f = 0.0;
    double sumW = 0.0;                                         ///< Σ 1/σ_k²
    std::complex<double> sumWH{0.0};                           ///< Σ H_k/σ_k²
    double info = 0.0;                                         ///< Σ A_k²·P_k of the passes below the voltage limit
    std::vector<std::pair<std::complex<double>, double>> seen; ///< (H_k, σ_k)
    double coherence = kNaN;
    double bestW = 0.0;
    bool valid = false;
    bool nonlinear = false;
    int heldBy = 0; ///< 0: nothing; 1: torque limit; 2: voltage limit (the last planned pass left it out or short)
    double relNoise() const
    {
        if (!(sumW > 0.0))
            return kNaN;
        const auto h = sumWH / sumW;
        return std::abs(h) > 0.0 ? 1.0 / std::sqrt(sumW) / std::abs(h) : kNaN;
    }
};

struct PassPlan {
    TestRequest request;
    double peakNm = 0.0;
    std::size_t lines = 0;
    std::string limitedBy;
    double predictedV = kNaN; ///< peak voltage predicted from the lines' Z_i (NaN: no voltage trace yet)
};

/// Index of the line at `f` (lines of the first pass, increasing), or npos.
std::size_t lineIndex(const std::vector<Line>& lines, double f, double spacing)
{
    auto it = std::lower_bound(lines.begin(), lines.end(), f - 0.1 * spacing,
                               [](const Line& l, double v) { return l.f < v; });
    if (it != lines.end() && std::abs(it->f - f) < 0.1 * spacing)
        return static_cast<std::size_t>(it - lines.begin());
    return std::string::npos;
}

/// Groups the sorted line indices into at most kMaxBands runs by joining the smallest gaps.
std::vector<std::pair<std::size_t, std::size_t>> groupBands(const std::vector<std::size_t>& idx)
{
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    for (std::size_t i : idx) {
        if (!runs.empty() && runs.back().second + 1 == i)
            runs.back().second = i;
        else
            runs.push_back({i, i});
    }
    while (runs.size() > kMaxBands) {
        std::size_t best = 0;
        for (std::size_t k = 1; k + 1 < runs.size(); ++k)
            if (runs[k + 1].first - runs[k].second < runs[best + 1].first - runs[best].second)
                best = k;
        runs[best].second = runs[best + 1].second;
        runs.erase(runs.begin() + static_cast<std::ptrdiff_t>(best) + 1);
    }
    return runs;
}

std::string fmt(double v, int sig)
{
    return model::formatNumber(v, sig);
}

} // namespace

const char* invalidReasonName(InvalidReason r)
{
    switch (r) {
    case InvalidReason::Noise:
        return "noise";
    case InvalidReason::TorqueLimit:
        return "torque limit";
    case InvalidReason::VoltageLimit:
        return "voltage limit";
    case InvalidReason::Nonlinear:
        return "nonlinearity";
    }
    return "noise";
}

std::array<std::size_t, kInvalidReasonCount> invalidByReason(const AdaptiveFrfResult& result)
{
    std::array<std::size_t, kInvalidReasonCount> n{};
    for (const auto& l : result.invalid)
        ++n[static_cast<std::size_t>(l.reason)];
    return n;
}

Result<AdaptiveFrfResult> runAdaptiveFrf(Drive& drive, const TestRequest& first, const AdaptiveFrfOptions& o,
                                         const RunOptions& runOptions)
{
    if (first.type() != TestType::Frf || first.frf().method != FrfMethod::Multisine)
        return makeError(ErrorCode::BadInput, "the adaptive FRF is a multisine measurement (--method multisine)");
    if (!(o.timeBudgetS > 0.0) || !std::isfinite(o.timeBudgetS))
        return makeError(ErrorCode::BadInput, "the time budget must be > 0 s");
    // The re-excitation is shaped on the host from the drive's own plan (its clock, rated torque and voltage): a
    // drive that evaluates FRFs in its own units (hal:, linuxcnc:) offers none of that.
    auto caps = drive.capabilities(first.axis);
    if (!caps)
        return caps.error();
    if (caps->frfPeakInOutputUnits)
        return makeError(ErrorCode::BadInput,
                         "axis " + first.axis +
                             ": --adaptive needs a drive that plans its multisine in % of rated torque (sim:, "
                             "modbus:); this connection measures in its output's own units: use --periods and "
                             "--amplitude instead");
    auto limits = drive.limits(first.axis);
    if (!limits)
        return limits.error();
    const double maxPct = limits->frfAmplitudeMaxPct;
    std::vector<std::string> keys(frfPlanParameterKeys().begin(), frfPlanParameterKeys().end());
    auto values = drive.readParameters(first.axis, keys);
    if (!values)
        return values.error();
    auto clock = axisClockFromParameters(*values, first.traceDivider);
    if (!clock)
        return clock.error();
    const auto valueOr = [&](const char* k) {
        const auto it = values->find(k);
        return it == values->end() ? 0.0 : it->second;
    };
    const double ratedNm = valueOr("motor.rated_current") * valueOr("motor.torque_constant");
    const double maxVoltage = valueOr("drive.max_voltage");
    if (!(ratedNm > 0.0))
        return makeError(ErrorCode::Device, "axis " + first.axis +
                                                ": the drive states no rated torque "
                                                "(motor.rated_current × motor.torque_constant)");
    auto hostPlan = [&](const TestRequest& r) -> Result<std::shared_ptr<const MultisinePlan>> {
        auto p = planFrfRequest(r, *values, *clock);
        if (!p)
            return p.error();
        if (!p->multisine)
            return makeError(ErrorCode::Internal, "not a multisine plan");
        return p->multisine;
    };
    auto firstPlan = drive.planTest(first);
    if (!firstPlan)
        return firstPlan.error();
    if (firstPlan->motionTimeS > o.timeBudgetS)
        return makeError(ErrorCode::OutOfRange, "the first multisine takes " + fmt(firstPlan->motionTimeS, 4) +
                                                    " s of motion, more than the time budget of " +
                                                    fmt(o.timeBudgetS, 4) + " s");
    auto plan1 = hostPlan(first);
    if (!plan1)
        return plan1.error();
    const double spacing = (*plan1)->design.spacingHz;
    const double noiseLimit = (*plan1)->maxRelativeNoise;
    const double target = o.noiseTargetFraction * noiseLimit;

    AdaptiveFrfResult out;
    std::vector<Line> lines;
    for (double f : (*plan1)->design.freqHz)
        lines.emplace_back().f = f;
    // Voltage per injected torque Z_i of every line (NaN until measured) and the calibration of the predicted peak
    // voltage.
    std::vector<std::complex<double>> zLine(lines.size(), kNaN);
    double voltageScale = 0.0; ///< V_peak / sqrt(Σ |Z_i A_i|²) of the last pass below the limit
    /// Measured over predicted peak voltage of the last pass below the limit (≥ 1: the prediction from the lines'
    /// Z_i leaves out the noise and what the trace samples miss).
    double voltageCal = 1.0;
    bool shapedOk = true;
    bool voltageEverReached = false;
    double blindScale = 1.0; ///< without a voltage trace: the excitation lowered after each pass that reached the limit

    // Plans the next pass: which lines (the cheapest first, within the torque and voltage budgets), how many
    // periods, what peak. nullopt: nothing fits the time left.
    auto planNextPass = [&](const std::vector<std::size_t>& todo) -> Result<std::optional<PassPlan>> {
        const double remaining = o.timeBudgetS - out.motionTimeS;
        // What each line still needs: A²·P so that σ/|H| reaches the target (σ ∝ 1/(A·√P) at a fixed noise).
        std::vector<double> need(lines.size(), 0.0);
        double maxInfo = 0.0;
        for (const auto& l : lines)
            maxInfo = std::max(maxInfo, l.info);
        for (std::size_t i : todo) {
            const auto& l = lines[i];
            const double r = l.relNoise();
            if (std::isfinite(r) && l.info > 0.0)
                need[i] = std::max(l.info * ((r / target) * (r / target) - 1.0), 0.05 * l.info);
            else // never measured below the voltage limit: what the strongest line has had so far
                need[i] = maxInfo > 0.0 ? maxInfo : std::pow((*plan1)->design.peak, 2) * 2.0;
        }
        // Budgets: Σ a_i² (the torque peak ≈ crest·√(Σ a_i²/2)) and Σ |Z_i a_i|² (the voltage peak, calibrated).
        const double crest = std::max(1.4, (*plan1)->design.crestFactor);
        const double maxPeak = maxPct / 100.0 * ratedNm;
        const double torqueBudget = 0.9 * 2.0 * std::pow(maxPeak / crest, 2) * blindScale;
        const bool voltageKnown = maxVoltage > 0.0 && voltageScale > 0.0;
        double vScale = voltageScale; // the voltage peak per √Σ|Z_i a_i|² this pass's spectrum is expected to have
        auto voltageBudget = [&] {
            return voltageKnown ? std::pow(o.voltageHeadroom * maxVoltage / vScale, 2)
                                : std::numeric_limits<double>::infinity();
        };
        double zFallback = 0.0;
        for (const auto& z : zLine)
            if (std::isfinite(std::abs(z)))
                zFallback = std::max(zFallback, std::abs(z));
        auto zOf = [&](std::size_t i) { return std::isfinite(std::abs(zLine[i])) ? std::abs(zLine[i]) : zFallback; };
        // Time of a pass over all of them: settle + P periods.
        TestRequest probe = first;
        FrfTest& pf = probe.frf();
        pf.multisineBands.clear();
        for (const auto& [a, b] : groupBands(todo))
            pf.multisineBands.push_back({lines[a].f - 0.5 * spacing, lines[b].f + 0.5 * spacing, spacing});
        pf.multisineShape.clear();
        pf.multisinePeriods = 2;
        auto pp = hostPlan(probe);
        if (!pp)
            return pp.error();
        const double fs = (*pp)->design.fsHz;
        const double periodS = static_cast<double>((*pp)->design.periodSamples()) / fs;
        const double settleS = static_cast<double>((*pp)->settleSamples) / fs;
        // Leave time for one more pass when there is enough: the noise of a line is known only roughly.
        const double share = remaining > 4.0 * (settleS + 2.0 * periodS) ? 0.7 : 1.0;
        const int pMax = static_cast<int>(std::floor((share * remaining - settleS) / periodS + 1e-9));
        if (pMax < kMinMultisinePeriods)
            return std::optional<PassPlan>{};
        // Phases designed for the voltage (its crest factor, not the torque's, limits the excitation) lower the
        // voltage peak of a spectrum: the lines are chosen again for the spectrum's own voltage peak (at most twice).
        for (int refine = 0; refine < 3; ++refine) {
            // The cheapest lines first, at pMax periods.
            std::vector<std::size_t> order = todo;
            auto costT = [&](std::size_t i) { return need[i] / pMax; };
            auto costV = [&](std::size_t i) { return std::pow(zOf(i), 2) * need[i] / pMax; };
            auto normCost = [&](std::size_t i) {
                return std::max(costT(i) / torqueBudget, voltageKnown ? costV(i) / voltageBudget() : 0.0);
            };
            std::sort(order.begin(), order.end(),
                      [&](std::size_t x, std::size_t y) { return normCost(x) < normCost(y); });
            std::vector<std::size_t> chosen;
            double sumT = 0.0, sumV = 0.0;
            for (std::size_t i : order) {
                const bool fitsT = sumT + costT(i) <= 0.95 * torqueBudget;
                const bool fitsV = !voltageKnown || sumV + costV(i) <= 0.95 * voltageBudget();
                if (fitsT && fitsV) {
                    chosen.push_back(i);
                    sumT += costT(i);
                    sumV += costV(i);
                    lines[i].heldBy = 0;
                } else {
                    lines[i].heldBy = fitsV ? 1 : 2;
                }
            }
            if (chosen.empty())
                return std::optional<PassPlan>{};
            std::string heldBy;
            for (std::size_t i : todo)
                if (lines[i].heldBy == 2 || (lines[i].heldBy == 1 && heldBy.empty()))
                    heldBy = lines[i].heldBy == 2 ? "voltage limit" : "torque limit";
            std::sort(chosen.begin(), chosen.end());
            // The fewest periods that still fit the budgets.
            const double load =
                std::max(sumT / (0.95 * torqueBudget), voltageKnown ? sumV / (0.95 * voltageBudget()) : 0.0);
            int periods = std::clamp(static_cast<int>(std::ceil(load * pMax - 1e-9)), kMinMultisinePeriods, pMax);
            const auto runs = groupBands(chosen);
            bool rechoose = false;
            for (int attempt = 0; attempt < 2; ++attempt) {
                TestRequest next = first;
                FrfTest& nf = next.frf();
                nf.multisineBands.clear();
                for (const auto& [a, b] : runs)
                    nf.multisineBands.push_back({lines[a].f - 0.5 * spacing, lines[b].f + 0.5 * spacing, spacing});
                nf.fminHz = nf.multisineBands.front().fminHz;
                nf.fmaxHz = nf.multisineBands.back().fmaxHz;
                nf.multisineSpacingHz = spacing;
                nf.multisinePeriods = periods;
                std::vector<double> ampReq(lines.size(), 0.0);
                double maxReq = 0.0;
                for (std::size_t i : chosen) {
                    ampReq[i] = std::sqrt(need[i] / periods);
                    maxReq = std::max(maxReq, ampReq[i]);
                }
                nf.multisineShape.clear();
                nf.multisineCrestThrough.clear();
                // Phases for the voltage when every line of the spectrum has its measured Z_i.
                bool crestForVoltage = o.phasesForVoltage && shapedOk && voltageKnown;
                for (const auto& [a, b] : runs)
                    for (std::size_t i = a; i <= b; ++i)
                        crestForVoltage = crestForVoltage && std::abs(zLine[i]) > 0.0; // false for NaN
                if (shapedOk)
                    for (const auto& [a, b] : runs)
                        for (std::size_t i = a; i <= b; ++i) {
                            nf.multisineShape.push_back({lines[i].f, std::max(ampReq[i], kFillWeight * maxReq)});
                            if (crestForVoltage)
                                nf.multisineCrestThrough.push_back({lines[i].f, zLine[i]});
                        }
                nf.amplitudePct = maxPct;
                auto p = hostPlan(next);
                if (!p)
                    return p.error();
                const auto& d = (*p)->design;
                // Design amplitudes scale with the peak: the peak that gives every chosen line what it needs.
                double peak = 0.0, sumZ = 0.0;
                std::vector<std::complex<double>> zDesign(d.freqHz.size(), 0.0);
                for (std::size_t k = 0; k < d.freqHz.size(); ++k) {
                    const auto i = lineIndex(lines, d.freqHz[k], spacing);
                    if (i == std::string::npos)
                        continue;
                    const double unit = d.amplitude[k] / d.peak;
                    if (ampReq[i] > 0.0 && unit > 0.0)
                        peak = std::max(peak, ampReq[i] / unit);
                    sumZ += std::pow(zOf(i) * unit, 2);
                    zDesign[k] = zLine[i];
                }
                // The voltage peak per unit torque peak of this very spectrum, from the lines' Z_i.
                double vPerPeak = kNaN;
                if (crestForVoltage && sumZ > 0.0) {
                    vPerPeak = voltageCal * dsp::multisinePeakThrough(d, zDesign) / d.peak;
                    const double scale = vPerPeak / std::sqrt(sumZ);
                    if (refine < 2 && std::isfinite(scale) && scale < 0.9 * vScale) {
                        vScale = scale; // more lines fit: choose again
                        rechoose = true;
                        break;
                    }
                }
                std::string by = heldBy;
                if (peak > maxPeak * blindScale) {
                    peak = maxPeak * blindScale;
                    by = "torque limit";
                }
                if (voltageKnown && sumZ > 0.0) {
                    const double vPeak = std::isfinite(vPerPeak) && vPerPeak > 0.0
                                             ? o.voltageHeadroom * maxVoltage / vPerPeak
                                             : o.voltageHeadroom * maxVoltage / (voltageScale * std::sqrt(sumZ));
                    if (peak > vPeak) {
                        peak = vPeak;
                        by = "voltage limit";
                    } else if (std::isfinite(vPerPeak)) {
                        // The voltage peak of this spectrum is known: excite up to it (more than the chosen lines
                        // need costs no motion time and helps a line whose noise was misjudged).
                        peak = std::min(vPeak, maxPeak * blindScale);
                    }
                }
                nf.amplitudePct = 100.0 * peak / ratedNm;
                auto drivePlan = drive.planTest(next);
                if (!drivePlan && shapedOk) {
                    shapedOk = false; // a drive that takes no spectrum (Modbus): flat bands from here on
                    continue;
                }
                if (!drivePlan)
                    return drivePlan.error();
                if (drivePlan->motionTimeS > remaining + 1e-9)
                    return std::optional<PassPlan>{};
                return std::optional<PassPlan>{PassPlan{next, peak, chosen.size(), by, vPerPeak * peak}};
            }
            if (!rechoose)
                return std::optional<PassPlan>{};
        }
        return std::optional<PassPlan>{};
    };

    TestRequest request = first;
    std::shared_ptr<const MultisinePlan> plan = *plan1;
    std::string limitedBy;
    double predictedV = kNaN;
    for (int pass = 0; pass < o.maxPasses; ++pass) {
        auto planned = drive.planTest(request);
        if (!planned)
            return planned.error();
        if (out.motionTimeS + planned->motionTimeS > o.timeBudgetS + 1e-9)
            break;
        RunOptions ro = runOptions;
        ro.readTrace = true;
        if (runOptions.progress) {
            // One progress over every pass, as a share of the time budget: the motion of the passes before and
            // this pass's share of its planned motion (never falling; 1 when the measurement ends).
            const double before = out.motionTimeS, plannedS = planned->motionTimeS, budget = o.timeBudgetS;
            const std::string what = "adaptive multisine, pass " + std::to_string(pass + 1);
            ro.progress = [&runOptions, before, plannedS, budget, what](double f, const std::string& detail) {
                runOptions.progress(std::clamp((before + f * plannedS) / budget, 0.0, 1.0),
                                    detail.empty() ? what : what + ": " + detail);
            };
        }
        auto run = runTest(drive, request, ro);
        if (!run)
            return run.error();
        if (!run->frf)
            return makeError(ErrorCode::Device, "the drive returned no FRF for the multisine pass");
        const FrfMeasurement& m = *run->frf;
        out.motionTimeS += m.motionTimeS > 0.0 ? m.motionTimeS : planned->motionTimeS;
        if (pass == 0) {
            out.measurement = m;
        }
        AdaptiveFrfPass rec;
        rec.lines = plan->design.freqHz.size();
        const FrfTest& rf = request.frf();
        rec.bands = rf.multisineBands.empty() ? 1 : rf.multisineBands.size();
        rec.peakPct = rf.amplitudePct;
        rec.periods = static_cast<int>(plan->periods);
        rec.motionTimeS = m.motionTimeS;
        rec.shaped = !rf.multisineShape.empty();
        rec.limitedBy = limitedBy;
        rec.voltagePredictedV = predictedV;
        rec.voltageReached = voltageLimitReached(m.frf.metadata);
        // The voltage per torque of the excited lines, from the trace (when it has the voltage).
        const auto* volt = run->trace ? run->trace->channel("voltage_V") : nullptr;
        const auto* inj = run->trace ? run->trace->channel("injection_Nm") : nullptr;
        std::vector<double> amp(lines.size(), 0.0);
        for (std::size_t k = 0; k < plan->design.freqHz.size(); ++k) {
            const auto i = lineIndex(lines, plan->design.freqHz[k], spacing);
            if (i != std::string::npos)
                amp[i] = plan->design.amplitude[k];
        }
        if (volt && inj && volt->data.size() >= plan->totalSamples && inj->data.size() >= plan->totalSamples) {
            const std::size_t a = plan->settleSamples, n = plan->totalSamples - a;
            dsp::MultisineAnalysisOptions ao;
            ao.maxRelativeNoise = 0.0;
            auto z = dsp::analyzeMultisine(plan->design, std::span<const double>(inj->data.data() + a, n),
                                           std::span<const double>(volt->data.data() + a, n), plan->periods, ao);
            double peakV = 0.0;
            for (std::size_t s = a; s < plan->totalSamples; ++s)
                peakV = std::max(peakV, std::abs(volt->data[s]));
            rec.voltagePeakV = peakV;
            if (z && z->frf.size() == plan->design.freqHz.size()) {
                double sum = 0.0;
                for (std::size_t k = 0; k < z->frf.size(); ++k) {
                    const auto i = lineIndex(lines, z->frf.freqHz[k], spacing);
                    if (i == std::string::npos)
                        continue;
                    zLine[i] = z->frf.h[k];
                    sum += std::pow(std::abs(zLine[i]) * amp[i], 2);
                }
                const double predicted = dsp::multisinePeakThrough(plan->design, z->frf.h);
                if (!rec.voltageReached && predicted > 0.0 && std::isfinite(predicted))
                    voltageCal = std::max(1.0, peakV / predicted);
                if (sum > 0.0 && !rec.voltageReached)
                    voltageScale = peakV / std::sqrt(sum);
                else if (sum > 0.0 && rec.voltageReached)
                    voltageScale = std::max(voltageScale, maxVoltage / std::sqrt(sum)) / 0.8;
            }
        }
        if (rec.voltageReached) {
            voltageEverReached = true;
            if (!(voltageScale > 0.0))
                blindScale *= 0.5; // no voltage trace: lower the excitation by a fixed factor
        } else {
            // Combine the lines of this pass. σ_H/|H| as the drive gave it, else (a drive that sends the coherence
            // only, e.g. over Modbus) from the coherence over P periods of an exactly periodic excitation:
            // γ² = |Ȳ|²/(|Ȳ|² + (P−1)/P·s²), so σ_H/|H| = √(s²/P)/|Ȳ| = √((1 − γ²)/(γ²·(P − 1))).
            const double pd = static_cast<double>(plan->periods);
            for (std::size_t k = 0; k < m.frf.size(); ++k) {
                const auto i = lineIndex(lines, m.frf.freqHz[k], spacing);
                if (i == std::string::npos)
                    continue;
                double r = kNaN;
                if (k < m.relativeNoise.size() && m.relativeNoise.size() == m.frf.size())
                    r = m.relativeNoise[k];
                else if (k < m.frf.coherence.size() && pd >= 2.0 && m.frf.coherence[k] > 0.0)
                    r = std::sqrt(std::max(0.0, 1.0 - m.frf.coherence[k]) / (m.frf.coherence[k] * (pd - 1.0)));
                const double mag = std::abs(m.frf.h[k]);
                if (!std::isfinite(r) || !(r > 0.0) || !(mag > 0.0) || !std::isfinite(mag))
                    continue;
                const double sigma = r * mag;
                const double w = 1.0 / (sigma * sigma);
                auto& l = lines[i];
                l.sumW += w;
                l.sumWH += w * m.frf.h[k];
                l.info += amp[i] * amp[i] * static_cast<double>(plan->periods);
                // σ from two or three periods is itself uncertain by about a factor of two: widened for the check.
                l.seen.push_back({m.frf.h[k], plan->periods < 4 ? 2.0 * sigma : sigma});
                if (w > l.bestW) {
                    l.bestW = w;
                    l.coherence = k < m.frf.coherence.size() ? m.frf.coherence[k] : kNaN;
                }
            }
            for (auto& l : lines) {
                if (!(l.sumW > 0.0))
                    continue;
                const auto h = l.sumWH / l.sumW;
                l.nonlinear = false;
                for (const auto& [hk, sk] : l.seen)
                    if (l.seen.size() > 1 &&
                        std::abs(hk - h) > kConsistencySigmas * std::hypot(sk, 1.0 / std::sqrt(l.sumW)))
                        l.nonlinear = true;
                l.valid = !l.nonlinear && l.relNoise() <= noiseLimit;
            }
        }
        rec.validAfter =
            static_cast<std::size_t>(std::count_if(lines.begin(), lines.end(), [](const Line& l) { return l.valid; }));
        out.passes.push_back(rec);
        // The next pass: the lines not yet valid (non-linear ones are not re-excited).
        std::vector<std::size_t> todo;
        for (std::size_t i = 0; i < lines.size(); ++i)
            if (!lines[i].valid && !lines[i].nonlinear)
                todo.push_back(i);
        if (todo.empty())
            break;
        auto next = planNextPass(todo);
        if (!next)
            return next.error();
        if (!next->has_value())
            break;
        request = (*next)->request;
        limitedBy = (*next)->limitedBy;
        predictedV = (*next)->predictedV;
        auto p = hostPlan(request);
        if (!p)
            return p.error();
        plan = *p;
    }
    // The combined FRF on the first pass's lines.
    FrfMeasurement& m = out.measurement;
    m.relativeNoise.assign(m.frf.size(), kNaN);
    for (std::size_t k = 0; k < m.frf.size(); ++k) {
        const auto i = lineIndex(lines, m.frf.freqHz[k], spacing);
        if (i == std::string::npos)
            continue;
        const auto& l = lines[i];
        if (l.sumW > 0.0) {
            m.frf.h[k] = l.sumWH / l.sumW;
            m.frf.coherence[k] = l.coherence;
            m.relativeNoise[k] = l.relNoise();
        }
        m.frf.valid[k] = l.valid;
        if (l.valid)
            ++out.validLines;
        else {
            InvalidLine bad{l.f, InvalidReason::Noise, l.relNoise()};
            if (l.nonlinear)
                bad.reason = InvalidReason::Nonlinear;
            else if (l.heldBy == 2 || (!(l.sumW > 0.0) && voltageEverReached))
                bad.reason = InvalidReason::VoltageLimit;
            else if (l.heldBy == 1)
                bad.reason = InvalidReason::TorqueLimit;
            out.invalid.push_back(bad);
        }
    }
    m.motionTimeS = out.motionTimeS;
    auto& md = m.frf.metadata;
    md.set("adaptive", "true");
    md.set("adaptive_passes", static_cast<double>(out.passes.size()));
    md.set("adaptive_time_budget_s", o.timeBudgetS);
    md.set(model::meta::kMotionTimeS, out.motionTimeS);
    md.set("valid_lines", static_cast<double>(out.validLines));
    const auto byReason = invalidByReason(out);
    md.set("invalid_noise", static_cast<double>(byReason[0]));
    md.set("invalid_torque_limit", static_cast<double>(byReason[1]));
    md.set("invalid_voltage_limit", static_cast<double>(byReason[2]));
    md.set("invalid_nonlinear", static_cast<double>(byReason[3]));
    md.erase(model::meta::kNoiseInvalidLines);
    if (runOptions.progress)
        runOptions.progress(1.0, "adaptive multisine: " + std::to_string(out.passes.size()) + " passes, " +
                                     std::to_string(out.validLines) + " of " + std::to_string(m.frf.size()) +
                                     " lines valid");
    return out;
}

} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
// Seed 004 front end: modal decomposition of the two-inertia ball-screw stage (eqs. (3)–(4), spec §2.5),
// Butterworth pre-filters and central differences (spec §2.6, §3.6 CD-1), moving-window correlations and
// the rule r_Fx < r_Fa (CD-2, CD-3 in CorrelationChatterDetector), grouped into intervals.
#include "core/machining/VibrationModeChatter.h"

#include "core/dsp/Fft.h"
#include "core/machining/CorrelationChatterDetector.h"
#include "core/model/Constants.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace axistune::machining {
namespace {

using model::kPi;

Result<dsp::FilterCascade> butterworth(int order, double fc, double ts, bool high)
{
    if (order < 2 || order % 2 != 0 || order > 16)
        return makeError(ErrorCode::OutOfRange,
                         "Butterworth order must be even in [2, 16] (got " + std::to_string(order) + ")");
    if (!(ts > 0.0))
        return makeError(ErrorCode::OutOfRange, "sample period must be > 0");
    if (!(fc > 0.0) || fc >= 0.5 / ts)
        return makeError(ErrorCode::OutOfRange, "cutoff " + std::to_string(fc) + " Hz must be in (0, Nyquist " +
                                                    std::to_string(0.5 / ts) + " Hz)");
    const double k = std::tan(kPi * fc * ts);
    dsp::FilterCascade c;
    for (int i = 0; i < order / 2; ++i) {
        // Pole pair i of the analogue prototype: Q = 1 / (2 sin((2i+1)π / (2n))).
        const double q = 1.0 / (2.0 * std::sin((2.0 * i + 1.0) * kPi / (2.0 * order)));
        const double norm = 1.0 / (1.0 + k / q + k * k);
        const double a1 = 2.0 * (k * k - 1.0) * norm, a2 = (1.0 - k / q + k * k) * norm;
        if (high)
            c.add(dsp::Biquad(norm, -2.0 * norm, norm, a1, a2));
        else
            c.add(dsp::Biquad(k * k * norm, 2.0 * k * k * norm, k * k * norm, a1, a2));
    }
    return c;
}

/// The frequency that drives r_Fa up: the peak of Re{F_load(f) A*(f)} (cross spectrum of the load −F_vib and
/// a_vib over [i0, i1), means removed, Hann window), i.e. the line with the largest positive contribution
/// to S_FA. Tooth-passing lines below the vibration mode contribute negatively and are never chosen.
double chatterFrequency(const std::vector<double>& f, const std::vector<double>& a, std::size_t i0, std::size_t i1,
                        double fs, double fMin)
{
    const std::size_t n = i1 - i0;
    if (n < 16)
        return 0.0;
    double mf = 0.0, ma = 0.0;
    for (std::size_t i = i0; i < i1; ++i) {
        mf += f[i];
        ma += a[i];
    }
    mf /= static_cast<double>(n);
    ma /= static_cast<double>(n);
    dsp::RealFft ff(n), fa(n);
    auto inF = ff.input();
    auto inA = fa.input();
    for (std::size_t i = 0; i < n; ++i) {
        const double w = 0.5 - 0.5 * std::cos(2.0 * kPi * static_cast<double>(i) / static_cast<double>(n));
        inF[i] = -(f[i0 + i] - mf) * w;
        inA[i] = (a[i0 + i] - ma) * w;
    }
    ff.execute();
    fa.execute();
    const auto F = ff.output();
    const auto A = fa.output();
    const std::size_t kMin = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(fMin * n / fs)));
    std::size_t best = 0;
    double bestVal = 0.0;
    std::vector<double> c(F.size(), 0.0);
    for (std::size_t k = kMin; k + 1 < F.size(); ++k) {
        c[k] = std::real(F[k] * std::conj(A[k]));
        if (c[k] > bestVal) {
            bestVal = c[k];
            best = k;
        }
    }
    if (best == 0)
        return 0.0;
    double delta = 0.0;
    if (best > kMin && c[best - 1] > 0.0 && c[best + 1] > 0.0) {
        const double l = std::log(c[best - 1]), m = std::log(bestVal), r = std::log(c[best + 1]);
        const double den = l - 2.0 * m + r;
        delta = den != 0.0 ? std::clamp(0.5 * (l - r) / den, -0.5, 0.5) : 0.0;
    }
    return (static_cast<double>(best) + delta) * fs / static_cast<double>(n);
}

/// Runs of flagged samples, merged across short gaps, debounced, with score and frequency.
void buildIntervals(ChatterAnalysis& out, const std::vector<double>& accel, double fs, const ChatterDetectOptions& o)
{
    const double ts = 1.0 / fs;
    const std::size_t m = out.timeS.size();
    std::vector<std::pair<std::size_t, std::size_t>> runs; // [first, last] indices into the index arrays
    for (std::size_t i = 0; i < m;) {
        if (!out.chatter[i]) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j + 1 < m && out.chatter[j + 1])
            ++j;
        if (!runs.empty() && out.timeS[i] - out.timeS[runs.back().second] <= o.mergeGapS + 0.5 * ts)
            runs.back().second = j;
        else
            runs.emplace_back(i, j);
        i = j + 1;
    }
    for (const auto& [a, b] : runs) {
        const double start = out.timeS[a], end = out.timeS[b] + ts;
        if (end - start < o.minDurationS)
            continue;
        ChatterInterval iv;
        iv.startS = start;
        iv.endS = end;
        double sum = 0.0;
        for (std::size_t k = a; k <= b; ++k)
            sum += out.rFa[k] - out.rFx[k];
        iv.score = sum / static_cast<double>(b - a + 1);
        // Frequency over the interval's samples (+1: index arrays start at sample 1).
        iv.frequencyHz = chatterFrequency(out.forceVibN, accel, a + 1, b + 2, fs, o.highPassHz);
        out.intervals.push_back(iv);
    }
}

} // namespace

double VibrationMode::frequencyHz() const
{
    return std::sqrt(stiffnessNPerM / massKg) / (2.0 * kPi);
}

Result<VibrationMode> vibrationModeOf(const TwoMassStage& s)
{
    if (!(s.motorMassKg > 0.0) || !std::isfinite(s.motorMassKg))
        return makeError(ErrorCode::OutOfRange, "motor-side mass (J_M/R²) must be > 0");
    if (!(s.tableMassKg > 0.0) || !std::isfinite(s.tableMassKg))
        return makeError(ErrorCode::OutOfRange, "table mass (J_L/R²) must be > 0");
    if (!(s.stiffnessNPerM > 0.0) || !std::isfinite(s.stiffnessNPerM))
        return makeError(ErrorCode::OutOfRange, "coupling stiffness must be > 0 (a rigid stage has no vibration mode)");
    if (!(s.dampingNsPerM >= 0.0) || !std::isfinite(s.dampingNsPerM))
        return makeError(ErrorCode::OutOfRange, "coupling damping must be >= 0");
    VibrationMode m;
    m.alpha = s.tableMassKg / s.motorMassKg;
    const double g = (1.0 + m.alpha) / m.alpha;
    m.massKg = s.motorMassKg * g;
    m.stiffnessNPerM = s.stiffnessNPerM * g * g;
    m.dampingNsPerM = s.dampingNsPerM * g * g;
    return m;
}

Result<dsp::FilterCascade> butterworthLowPass(int order, double cutoffHz, double periodS)
{
    return butterworth(order, cutoffHz, periodS, false);
}

Result<dsp::FilterCascade> butterworthHighPass(int order, double cutoffHz, double periodS)
{
    return butterworth(order, cutoffHz, periodS, true);
}

Result<ChatterAnalysis> detectChatter(const std::vector<double>& timeS, const std::vector<double>& motorForceN,
                                      const std::vector<double>& motorPositionM,
                                      const std::vector<double>& tablePositionM, double fs, const VibrationMode& mode,
                                      const ChatterDetectOptions& o)
{
    const std::size_t n = timeS.size();
    if (motorForceN.size() != n || motorPositionM.size() != n || tablePositionM.size() != n)
        return makeError(ErrorCode::BadInput,
                         "the time, motor force, motor position and table position signals differ in length");
    if (!(fs > 0.0) || !std::isfinite(fs))
        return makeError(ErrorCode::BadInput, "sample rate must be > 0");
    if (!(o.windowS > 0.0))
        return makeError(ErrorCode::OutOfRange, "window must be > 0 s");
    const auto window = static_cast<std::size_t>(std::llround(o.windowS * fs));
    if (window < 2)
        return makeError(ErrorCode::OutOfRange, "window " + std::to_string(o.windowS) + " s is shorter than 2 samples");
    if (n < window + 2)
        return makeError(ErrorCode::BadInput, "the trace has " + std::to_string(n) +
                                                  " samples, fewer than one window (" + std::to_string(window) +
                                                  ") + 2");
    if (!(mode.alpha > 0.0 && mode.massKg > 0.0 && mode.stiffnessNPerM > 0.0))
        return makeError(ErrorCode::OutOfRange, "vibration mode parameters must be > 0");
    const double ts = 1.0 / fs;
    auto hp = butterworthHighPass(4, o.highPassHz, ts);
    if (!hp)
        return makeError(hp.error().code, "high-pass: " + hp.error().detail);
    ChatterAnalysis out;
    dsp::FilterCascade lp;
    if (o.lowPassHz < 0.5 * fs) {
        auto l = butterworthLowPass(4, o.lowPassHz, ts);
        if (!l)
            return makeError(l.error().code, "low-pass: " + l.error().detail);
        lp = *l;
        out.lowPassApplied = true;
    }
    // CD-1: filters on the three inputs (same filters, same initial state), then eq. (3).
    std::vector<double> f(n), x(n);
    dsp::FilterCascade fF = *hp, fM = *hp, fT = *hp, lF = lp, lM = lp, lT = lp;
    const double share = mode.alpha / (1.0 + mode.alpha);
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(motorForceN[i]) || !std::isfinite(motorPositionM[i]) || !std::isfinite(tablePositionM[i]))
            return makeError(ErrorCode::BadInput, "sample " + std::to_string(i) + ": not a finite number");
        f[i] = lF.process(fF.process(motorForceN[i]));
        const double xm = lM.process(fM.process(motorPositionM[i]));
        const double xt = lT.process(fT.process(tablePositionM[i]));
        x[i] = share * (xm - xt);
    }
    if (!(o.baselineS >= 0.0) || !(o.baselineFactor > 0.0))
        return makeError(ErrorCode::OutOfRange, "baseline must be >= 0 s and its factor > 0");
    // Central differences, aligned at sample i; eq. (4); correlations of F_load = −F_vib with x and a.
    CorrelationChatterDetector det(window, o.energyFloor);
    std::vector<double> accel(n, 0.0), forceSq(window, 0.0);
    double sumSq = 0.0, floor = 0.0, baselineMax = 0.0;
    const double t0 = timeS.front();
    out.timeS.reserve(n);
    std::size_t validCount = 0, flagCount = 0;
    out.forceVibN.assign(n, 0.0);
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double v = (x[i + 1] - x[i - 1]) * 0.5 * fs;
        const double a = (x[i + 1] - 2.0 * x[i] + x[i - 1]) * fs * fs;
        const double fv = mode.alpha * (f[i] - o.inertialScale * mode.massKg * a - mode.dampingNsPerM * v -
                                        mode.stiffnessNPerM * x[i]);
        out.forceVibN[i] = fv;
        accel[i] = a;
        auto s = det.step(-fv, x[i], a);
        // Moving mean square of the force over the same window (the baseline gate).
        const std::size_t slot = i % window;
        sumSq += fv * fv - forceSq[slot];
        forceSq[slot] = fv * fv;
        const double meanSq = std::max(0.0, sumSq) / static_cast<double>(window);
        if (o.baselineS > 0.0 && s.valid) {
            if (timeS[i] - t0 <= o.baselineS) {
                baselineMax = std::max(baselineMax, meanSq);
                floor = o.baselineFactor * baselineMax;
                s.valid = false; // the baseline itself is not judged
            } else if (meanSq < floor) {
                s.valid = false;
            }
            s.chatter = s.chatter && s.valid;
        }
        out.timeS.push_back(timeS[i]);
        out.rFx.push_back(s.rFx);
        out.rFa.push_back(s.rFa);
        out.valid.push_back(s.valid ? 1 : 0);
        out.chatter.push_back(s.chatter ? 1 : 0);
        validCount += s.valid;
        flagCount += s.chatter;
    }
    if (o.baselineS > 0.0 && baselineMax <= 0.0)
        return makeError(ErrorCode::BadInput, "baseline " + std::to_string(o.baselineS) +
                                                  " s holds no full correlation window (window " +
                                                  std::to_string(o.windowS) + " s)");
    out.forceFloorN2 = floor;
    out.flaggedFraction = validCount ? static_cast<double>(flagCount) / static_cast<double>(validCount) : 0.0;
    out.vibrationModeHz = mode.frequencyHz();

    buildIntervals(out, accel, fs, o);
    return out;
}

} // namespace axistune::machining

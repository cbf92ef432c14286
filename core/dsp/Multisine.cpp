// SPDX-License-Identifier: GPL-3.0-or-later
// Three-phase multisine: design, crest factor and FFT demodulation of all lines at once.
// Method: the three-phase multi-sweep demodulation of spec/current-loop-and-multisweep-frf.md §3.5
// (phase offsets 0, +120°, −120°; the sum-frequency term cancels) applied to every line of a
// multisine (issue 11, docs/multisine.md). Phases: M. R. Schroeder, "Synthesis of low-peak-factor
// signals and binary sequences with low autocorrelation", IEEE Trans. Inf. Theory 16 (1970) 85;
// iterative clipping after E. Van der Ouderaa, J. Schoukens, J. Renneboog, "Peak factor minimization
// using a time-frequency domain swapping algorithm", IEEE Trans. Instrum. Meas. 37 (1988) 145.
#include "core/dsp/Multisine.h"

#include "core/dsp/Fft.h"
#include "core/model/Constants.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

namespace axistune::dsp {
namespace {

using model::kTwoPi;
constexpr std::size_t kMaxWindow = std::size_t{1} << 20;
constexpr std::size_t kMaxLines = 20000;

std::string num(double v)
{
    return model::formatNumber(v, 10);
}

/// X[m] = Σ_t x[t] e^{−2πimt/n} for all n bins, from two real FFTs (FFTW plans cached, dsp::RealFft).
std::vector<std::complex<double>> complexDft(std::span<const std::complex<double>> x)
{
    const std::size_t n = x.size();
    RealFft fa(n), fb(n);
    for (std::size_t t = 0; t < n; ++t) {
        fa.input()[t] = x[t].real();
        fb.input()[t] = x[t].imag();
    }
    fa.execute();
    fb.execute();
    std::vector<std::complex<double>> out(n);
    const auto a = fa.output(), b = fb.output();
    for (std::size_t m = 0; m < n; ++m) {
        const std::complex<double> am = m <= n / 2 ? a[m] : std::conj(a[n - m]);
        const std::complex<double> bm = m <= n / 2 ? b[m] : std::conj(b[n - m]);
        out[m] = am + std::complex<double>(0.0, 1.0) * bm;
    }
    return out;
}

/// One period of Σ A_i sin(2π k_i t/L + φ_i), t = 0…L−1, by one inverse DFT.
std::vector<double> synthesize(std::size_t length, const std::vector<std::size_t>& k, const std::vector<double>& amp,
                               const std::vector<double>& phase)
{
    // x[t] = Im Σ C_k e^{+j2πkt/L} = −Im DFT(conj C)[t].
    std::vector<std::complex<double>> c(length);
    for (std::size_t i = 0; i < k.size(); ++i)
        c[k[i]] = std::conj(std::polar(amp[i], phase[i]));
    const auto s = complexDft(c);
    std::vector<double> x(length);
    for (std::size_t t = 0; t < length; ++t)
        x[t] = -s[t].imag();
    return x;
}

/// Phases of the lines k_i in x: for x = A sin(2πkt/L + φ), X[k] = −j(L/2)A e^{jφ}.
std::vector<double> linePhases(std::span<const double> x, const std::vector<std::size_t>& k)
{
    RealFft f(x.size());
    std::copy(x.begin(), x.end(), f.input().begin());
    f.execute();
    // A line above the grid's Nyquist bin (k > L/2: lines up to the trace rate on a grid of that rate) is read from
    // its mirror, X[k] = conj(X[L − k]) for a real signal. The FFT holds only the bins 0..L/2.
    const std::size_t n = x.size();
    std::vector<double> out(k.size());
    for (std::size_t i = 0; i < k.size(); ++i) {
        const std::complex<double> xk = k[i] < f.bins() ? f.output()[k[i]] : std::conj(f.output()[n - k[i]]);
        out[i] = std::arg(xk * std::complex<double>(0.0, 1.0));
    }
    return out;
}

double peakOf(std::span<const double> x)
{
    double p = 0.0;
    for (double v : x)
        p = std::max(p, std::abs(v));
    return p;
}

/// The points' value at f: linear in log f between them, held beyond the ends (1 when there are none).
template <typename T> T interpolateLogF(const std::vector<std::pair<double, T>>& points, double f)
{
    if (points.empty())
        return T(1.0);
    if (f <= points.front().first)
        return points.front().second;
    if (f >= points.back().first)
        return points.back().second;
    auto it = std::upper_bound(points.begin(), points.end(), f,
                               [](double v, const std::pair<double, T>& p) { return v < p.first; });
    const auto& [f1, w1] = *it;
    const auto& [f0, w0] = *(it - 1);
    const double u = std::log(f / f0) / std::log(f1 / f0);
    return w0 + u * (w1 - w0);
}

Status checkOptions(const MultisineDesignOptions& o)
{
    if (!(o.fsHz > 0.0) || !std::isfinite(o.fsHz))
        return makeError(ErrorCode::OutOfRange, "multisine: trace rate must be positive");
    if (o.ticksPerSample < 1 || o.ticksPerSample > 1000)
        return makeError(ErrorCode::OutOfRange, "multisine: generation ticks per trace sample must lie in [1, 1000]");
    if (!(o.peak > 0.0) || !std::isfinite(o.peak))
        return makeError(ErrorCode::OutOfRange, "multisine: peak must be positive");
    if (o.bands.empty())
        return makeError(ErrorCode::OutOfRange, "multisine: at least one band is needed");
    for (std::size_t b = 0; b < o.bands.size(); ++b) {
        const auto& band = o.bands[b];
        const std::string name = "multisine band " + std::to_string(b + 1) + ": ";
        if (!(band.fminHz > 0.0) || !std::isfinite(band.fminHz))
            return makeError(ErrorCode::OutOfRange, name + "fmin must be positive (got " + num(band.fminHz) + " Hz)");
        if (!std::isfinite(band.fmaxHz) || band.fmaxHz < band.fminHz)
            return makeError(ErrorCode::OutOfRange, name + "fmax must not be below fmin");
        if (!(band.fmaxHz < o.fsHz))
            return makeError(ErrorCode::OutOfRange, name + "fmax " + num(band.fmaxHz) +
                                                        " Hz must lie below the trace rate " + num(o.fsHz) + " Hz");
        if (!(band.spacingHz > 0.0) || !(o.fsHz / band.spacingHz <= static_cast<double>(kMaxWindow)))
            return makeError(ErrorCode::OutOfRange,
                             name + "spacing " + num(band.spacingHz) + " Hz must be positive and at least fs/2^20");
    }
    for (std::size_t i = 0; i < o.shape.size(); ++i) {
        const auto& [f, w] = o.shape[i];
        if (!(f > 0.0) || !(w > 0.0) || !std::isfinite(f) || !std::isfinite(w) ||
            (i > 0 && !(f > o.shape[i - 1].first)))
            return makeError(ErrorCode::OutOfRange,
                             "multisine shape: point " + std::to_string(i + 1) +
                                 " needs a positive frequency above the previous one and a positive weight");
    }
    for (std::size_t i = 0; i < o.crestThrough.size(); ++i) {
        const auto& [f, g] = o.crestThrough[i];
        if (!(f > 0.0) || !std::isfinite(f) || !(std::abs(g) > 0.0) || !std::isfinite(std::abs(g)) ||
            (i > 0 && !(f > o.crestThrough[i - 1].first)))
            return makeError(ErrorCode::OutOfRange,
                             "multisine crest response: point " + std::to_string(i + 1) +
                                 " needs a positive frequency above the previous one and a finite, nonzero gain");
    }
    if (o.clippingIterations < 0 || o.clippingIterations > 100000)
        return makeError(ErrorCode::OutOfRange, "multisine: clipping iterations must lie in [0, 100000]");
    return Status::success();
}

} // namespace

const char* multisinePhasesName(MultisinePhases p)
{
    return p == MultisinePhases::Schroeder ? "schroeder" : "clipping";
}

double crestFactor(std::span<const double> x)
{
    if (x.empty())
        return std::numeric_limits<double>::quiet_NaN();
    double s = 0.0;
    for (double v : x)
        s += v * v;
    return peakOf(x) / std::sqrt(s / static_cast<double>(x.size()));
}

double MultisineDesign::valueAtTick(std::int64_t tick) const
{
    if (table.empty())
        return 0.0;
    const auto n = static_cast<std::int64_t>(table.size());
    return table[static_cast<std::size_t>(((tick % n) + n) % n)];
}

double MultisineDesign::valueAt(double tS) const
{
    double x = 0.0;
    for (std::size_t i = 0; i < freqHz.size(); ++i) {
        // Reduce the phase over the period 3/Δf exactly: k_i = 3 m_i + 1 cycles per period.
        const double periods = tS * spacingHz / 3.0;
        const double frac = periods - std::floor(periods);
        const double cycles = std::fmod(frac * static_cast<double>(3 * bins[i] + 1), 1.0);
        x += amplitude[i] * std::sin(kTwoPi * cycles + phaseRad[i]);
    }
    return x;
}

Result<MultisineDesign> designMultisine(const MultisineDesignOptions& o)
{
    if (auto st = checkOptions(o); !st)
        return st.error();
    double finest = std::numeric_limits<double>::infinity();
    for (const auto& b : o.bands)
        finest = std::min(finest, b.spacingHz);
    MultisineDesign d;
    d.fsHz = o.fsHz;
    d.ticksPerSample = o.ticksPerSample;
    d.phases = o.phases;
    d.windowSamples = static_cast<std::size_t>(std::max(1.0, std::round(o.fsHz / finest)));
    const auto m = d.windowSamples;
    d.spacingHz = o.fsHz / static_cast<double>(m);
    std::set<std::size_t> bins;
    for (std::size_t b = 0; b < o.bands.size(); ++b) {
        const auto& band = o.bands[b];
        const auto q = static_cast<std::size_t>(std::max(1.0, std::round(band.spacingHz / d.spacingHz)));
        const double m0 = std::max(0.0, std::ceil(band.fminHz / d.spacingHz - 1.0 / 3.0 - 1e-9));
        std::size_t added = 0;
        for (auto k = static_cast<std::size_t>(m0);
             k < m && (static_cast<double>(k) + 1.0 / 3.0) * d.spacingHz <= band.fmaxHz * (1.0 + 1e-12); k += q) {
            bins.insert(k);
            if (bins.size() > kMaxLines)
                return makeError(ErrorCode::OutOfRange, "multisine: more than " + std::to_string(kMaxLines) + " lines");
            ++added;
        }
        if (added == 0)
            return makeError(ErrorCode::OutOfRange, "multisine band " + std::to_string(b + 1) +
                                                        ": no line of the grid (m + 1/3)·" + num(d.spacingHz) +
                                                        " Hz lies in [" + num(band.fminHz) + ", " + num(band.fmaxHz) +
                                                        "] Hz");
    }
    d.bins.assign(bins.begin(), bins.end());
    const std::size_t lines = d.bins.size();
    std::vector<std::size_t> k(lines);
    std::vector<double> weight(lines);
    // The phases keep the crest factor of Σ |G_i|·A_i sin(…) low (G = 1 without crestThrough).
    std::vector<std::complex<double>> gain(lines, 1.0);
    std::vector<double> crestWeight(lines);
    double power = 0.0;
    for (std::size_t i = 0; i < lines; ++i) {
        k[i] = 3 * d.bins[i] + 1;
        d.freqHz.push_back((static_cast<double>(d.bins[i]) + 1.0 / 3.0) * d.spacingHz);
        weight[i] = interpolateLogF(o.shape, d.freqHz.back());
        if (!o.crestThrough.empty())
            gain[i] = interpolateLogF(o.crestThrough, d.freqHz.back());
        crestWeight[i] = weight[i] * std::abs(gain[i]);
        power += crestWeight[i] * crestWeight[i];
    }
    if (!(power > 0.0) || !std::isfinite(power))
        return makeError(ErrorCode::OutOfRange, "multisine: the crest response is zero or not finite at the lines");
    // Schroeder: φ_i = −2π Σ_{l<i} (i − l) p_l with p_l the power share (−π i(i−1)/L for a flat spectrum).
    std::vector<double> phase(lines, 0.0);
    double cum = 0.0, cumWeighted = 0.0; // Σ_{l<i} p_l and Σ_{l<i} l·p_l
    for (std::size_t i = 0; i < lines; ++i) {
        phase[i] = std::remainder(-kTwoPi * (static_cast<double>(i) * cum - cumWeighted), kTwoPi);
        const double p = crestWeight[i] * crestWeight[i] / power;
        cum += p;
        cumWeighted += static_cast<double>(i) * p;
    }
    const std::size_t length = 3 * m * static_cast<std::size_t>(o.ticksPerSample);
    std::vector<double> x = synthesize(length, k, crestWeight, phase);
    double bestCf = crestFactor(x);
    if (o.phases == MultisinePhases::Clipping && lines > 1) {
        std::vector<double> trial = phase;
        std::vector<double> y = x;
        // Long periods (fine spacing): at most about 1.5e7 table samples of work, at least 10 iterations,
        // so that a 0.01 Hz grid designs in seconds, not minutes.
        const int iterations =
            std::min(o.clippingIterations, std::max(10, static_cast<int>(1.5e7 / static_cast<double>(length))));
        for (int it = 0; it < iterations; ++it) {
            // Clip the peaks a little below the present peak, keep the phases the clipping produces,
            // restore the amplitudes; keep the best crest factor found.
            const double level = 0.9 * peakOf(y);
            for (double& v : y)
                v = std::clamp(v, -level, level);
            trial = linePhases(y, k);
            y = synthesize(length, k, crestWeight, trial);
            const double cf = crestFactor(y);
            if (cf < bestCf) {
                bestCf = cf;
                phase = trial;
                x = y;
            }
        }
    }
    if (!o.crestThrough.empty()) {
        // The excitation's phases: those of the response less the response's own phase.
        for (std::size_t i = 0; i < lines; ++i)
            phase[i] = std::remainder(phase[i] - std::arg(gain[i]), kTwoPi);
        x = synthesize(length, k, weight, phase);
    }
    // Scale so that the peak over the generation grid is the requested peak (never above it).
    const double scale = o.peak / peakOf(x) * (1.0 - 1e-12);
    for (double& v : x)
        v *= scale;
    for (std::size_t i = 0; i < lines; ++i)
        d.amplitude.push_back(weight[i] * scale);
    d.phaseRad = phase;
    d.table = std::move(x);
    d.peak = peakOf(d.table);
    d.crestFactor = crestFactor(d.table);
    d.rms = d.peak / d.crestFactor;
    return d;
}

double multisinePeakThrough(const MultisineDesign& d, std::span<const std::complex<double>> gains)
{
    const std::size_t lines = d.bins.size();
    if (gains.size() != lines || d.amplitude.size() != lines || d.phaseRad.size() != lines || d.table.empty())
        return std::numeric_limits<double>::quiet_NaN();
    std::vector<std::size_t> k(lines);
    std::vector<double> amp(lines), phase(lines);
    for (std::size_t i = 0; i < lines; ++i) {
        k[i] = 3 * d.bins[i] + 1;
        amp[i] = std::abs(gains[i]) * d.amplitude[i];
        phase[i] = d.phaseRad[i] + std::arg(gains[i]);
    }
    return peakOf(synthesize(d.table.size(), k, amp, phase));
}

std::vector<std::complex<double>> demodulateThreePhase(const MultisineDesign& d, std::span<const double> w0,
                                                       std::span<const double> w1, std::span<const double> w2)
{
    const std::size_t m = d.windowSamples;
    // z'[k] = (Σ_n w_n[k] e^{−jψ_n}) e^{−j2πk/(3M)}, ψ_n = n·120°; P_m = (2j/(3M)) DFT(z')[m].
    const std::complex<double> r1 = std::polar(1.0, -kTwoPi / 3.0), r2 = std::conj(r1);
    std::vector<std::complex<double>> z(m);
    for (std::size_t k = 0; k < m; ++k)
        z[k] = (w0[k] + w1[k] * r1 + w2[k] * r2) *
               std::polar(1.0, -kTwoPi * static_cast<double>(k) / (3.0 * static_cast<double>(m)));
    const auto zf = complexDft(z);
    const std::complex<double> norm(0.0, 2.0 / (3.0 * static_cast<double>(m)));
    std::vector<std::complex<double>> out;
    out.reserve(d.bins.size());
    for (std::size_t b : d.bins)
        out.push_back(norm * zf[b]);
    return out;
}

std::vector<std::complex<double>> demodulateSinglePhase(const MultisineDesign& d, std::span<const double> w0)
{
    const std::size_t m = d.windowSamples;
    std::vector<std::complex<double>> z(m);
    for (std::size_t k = 0; k < m; ++k)
        z[k] = w0[k] * std::polar(1.0, -kTwoPi * static_cast<double>(k) / (3.0 * static_cast<double>(m)));
    const auto zf = complexDft(z);
    const std::complex<double> norm(0.0, 2.0 / static_cast<double>(m));
    std::vector<std::complex<double>> out;
    for (std::size_t b : d.bins)
        out.push_back(norm * zf[b]);
    return out;
}

Result<MultisineAnalysis> analyzeMultisine(const MultisineDesign& d, std::span<const double> x,
                                           std::span<const double> y, std::size_t periods,
                                           const MultisineAnalysisOptions& o)
{
    const std::size_t m = d.windowSamples, per = 3 * m;
    if (periods < 1)
        return makeError(ErrorCode::BadInput, "multisine analysis: at least one period is needed");
    if (m == 0 || d.bins.empty())
        return makeError(ErrorCode::BadInput, "multisine analysis: empty design");
    if (x.size() != y.size() || x.size() < periods * per)
        return makeError(ErrorCode::BadInput, "multisine analysis: " + std::to_string(periods) + " periods need " +
                                                  std::to_string(periods * per) +
                                                  " samples of excitation and response (got " +
                                                  std::to_string(x.size()) + " and " + std::to_string(y.size()) + ")");
    const std::size_t lines = d.bins.size();
    std::vector<std::complex<double>> sx(lines), sy(lines), sxy(lines);
    std::vector<double> sxx(lines), syy(lines);
    std::vector<std::vector<std::complex<double>>> px, py;
    for (std::size_t p = 0; p < periods; ++p) {
        auto win = [&](std::span<const double> s, std::size_t n) { return s.subspan(p * per + n * m, m); };
        auto xp = o.threePhase ? demodulateThreePhase(d, win(x, 0), win(x, 1), win(x, 2))
                               : demodulateSinglePhase(d, win(x, 0));
        auto yp = o.threePhase ? demodulateThreePhase(d, win(y, 0), win(y, 1), win(y, 2))
                               : demodulateSinglePhase(d, win(y, 0));
        for (std::size_t i = 0; i < lines; ++i) {
            sx[i] += xp[i];
            sy[i] += yp[i];
            sxy[i] += std::conj(xp[i]) * yp[i];
            sxx[i] += std::norm(xp[i]);
            syy[i] += std::norm(yp[i]);
        }
        px.push_back(std::move(xp));
        py.push_back(std::move(yp));
    }
    MultisineAnalysis out;
    out.stats.periods = periods;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double pd = static_cast<double>(periods);
    for (std::size_t i = 0; i < lines; ++i) {
        const std::complex<double> h = sy[i] / sx[i];
        // Residual of each period's response from H·X: the noise of the response phasor; the mean of
        // P periods has the variance s²/P, relative to |Ȳ|.
        double rel = nan, coh = nan;
        if (periods >= 2) {
            double s2 = 0.0;
            for (std::size_t p = 0; p < periods; ++p)
                s2 += std::norm(py[p][i] - h * px[p][i]);
            s2 /= pd - 1.0;
            rel = std::sqrt(s2 / pd) / std::abs(sy[i] / pd);
            coh = std::norm(sxy[i]) / (sxx[i] * syy[i]);
        }
        bool valid = o.threePhase && std::isfinite(h.real()) && std::isfinite(h.imag()) && std::abs(sx[i]) > 0.0;
        if (valid && o.maxRelativeNoise > 0.0 && std::isfinite(rel) && rel > o.maxRelativeNoise) {
            valid = false;
            ++out.stats.invalidNoise;
        }
        out.frf.push(d.freqHz[i], h, coh, valid);
        out.stats.relativeNoise.push_back(rel);
        out.stats.excitationPhasor.push_back(std::abs(sx[i]) / pd);
    }
    auto& md = out.frf.metadata;
    md.set(model::meta::kMethod, o.threePhase ? "multisine" : "multisine-single-phase");
    md.set(model::meta::kFsHz, d.fsHz);
    md.set("lines", static_cast<double>(lines));
    md.set("spacing_Hz", d.spacingHz);
    md.set("window_samples", static_cast<double>(m));
    md.set("periods", static_cast<double>(periods));
    md.set("crest_factor", d.crestFactor);
    md.set("phases", multisinePhasesName(d.phases));
    md.set("max_relative_noise", o.maxRelativeNoise);
    md.set(model::meta::kNoiseInvalidLines, out.stats.invalidNoise);
    if (!o.threePhase) {
        // A window of 1/Δf holds m + 1/3 periods of every line: the other lines and the
        // sum-frequency terms do not cancel, so no line of a single-phase analysis is a measurement.
        md.set("invalid_reason", "single-phase analysis of a three-phase multisine");
    }
    return out;
}

} // namespace axistune::dsp

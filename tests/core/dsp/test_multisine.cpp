// SPDX-License-Identifier: GPL-3.0-or-later
// Three-phase multisine (issue 11, docs/multisine.md): design (grid, bands, shape, crest factor,
// peak), exactness of the all-lines FFT demodulation through known transfer functions with modes
// above fs/2, the single-phase analysis of the same data flagged invalid, agreement with the
// per-line three-phase sums of dsp::demodulate, and the noise estimate against white noise of known σ.
#include "core/dsp/DigitalFilter.h"
#include "core/dsp/Multisine.h"
#include "core/dsp/SineDemodulation.h"

#include <cmath>
#include <complex>
#include <gtest/gtest.h>
#include <numbers>
#include <random>

using namespace axistune;
using namespace axistune::dsp;

namespace {

constexpr double kPi = std::numbers::pi;

MultisineDesign design(std::vector<MultisineBand> bands, MultisinePhases ph = MultisinePhases::Clipping, int ticks = 1,
                       double peak = 1.0, std::vector<std::pair<double, double>> shape = {})
{
    MultisineDesignOptions o;
    o.fsHz = 4000.0;
    o.ticksPerSample = ticks;
    o.bands = std::move(bands);
    o.phases = ph;
    o.peak = peak;
    o.shape = std::move(shape);
    auto d = designMultisine(o);
    EXPECT_TRUE(d.ok()) << (d.ok() ? "" : d.error().detail);
    return std::move(d).value();
}

/// A continuous system with a well-damped low-frequency part and two lightly damped modes above
/// fs/2 = 2 kHz (2.5 kHz and 3.3 kHz), evaluated analytically.
std::complex<double> plant(double fHz)
{
    const std::complex<double> s(0.0, 2.0 * kPi * fHz);
    auto mode = [&](double f0, double zeta) {
        const double w = 2.0 * kPi * f0;
        return w * w / (s * s + 2.0 * zeta * w * s + w * w);
    };
    const double wc = 2.0 * kPi * 300.0;
    return wc / (s + wc) + 0.3 * mode(2500.0, 0.02) + 0.5 * mode(3300.0, 0.01) * std::exp(-s * 1.3e-4);
}

/// Steady-state samples of Σ A_i |H_i| sin(ω_i t + φ_i + ∠H_i) at t = (s0 + k)/fs.
std::vector<double> steadyState(const MultisineDesign& d, std::size_t s0, std::size_t n, bool throughPlant)
{
    std::vector<double> y(n, 0.0);
    for (std::size_t i = 0; i < d.freqHz.size(); ++i) {
        const std::complex<double> h = throughPlant ? plant(d.freqHz[i]) : 1.0;
        for (std::size_t k = 0; k < n; ++k) {
            // Phase reduced over the period 3/Δf (k_i = 3 m_i + 1 cycles per period) to keep 1e-12 accuracy.
            const std::size_t t = (s0 + k) % d.periodSamples();
            const double cycles = static_cast<double>((3 * d.bins[i] + 1) * t % d.periodSamples()) /
                                  static_cast<double>(d.periodSamples());
            y[k] += d.amplitude[i] * std::abs(h) * std::sin(2.0 * kPi * cycles + d.phaseRad[i] + std::arg(h));
        }
    }
    return y;
}

} // namespace

// Issue 11: crest factor of the designed multisine reported and below 2.0 for a flat spectrum of
// 200 lines; the peak over the generation grid equals the requested peak; the table is the sum of
// the designed sines (checked here term by term).
TEST(Multisine, FlatTwoHundredLinesHaveACrestFactorBelowTwoAndThePeakIsRespected)
{
    for (auto ph : {MultisinePhases::Schroeder, MultisinePhases::Clipping}) {
        const auto d = design({{10.0, 2004.0, 10.0}}, ph, 4, 1.956);
        ASSERT_EQ(d.freqHz.size(), 200u);
        EXPECT_NEAR(d.freqHz.front(), 13.0 + 1.0 / 3.0, 1e-9);
        double peak = 0.0, ss = 0.0;
        for (std::size_t n = 0; n < d.table.size(); ++n) {
            const double t = static_cast<double>(n) / (4.0 * 4000.0);
            double x = 0.0;
            for (std::size_t i = 0; i < d.freqHz.size(); ++i)
                x += d.amplitude[i] * std::sin(2.0 * kPi * d.freqHz[i] * t + d.phaseRad[i]);
            ASSERT_NEAR(d.table[n], x, 1e-9) << n;
            peak = std::max(peak, std::abs(x));
            ss += x * x;
        }
        const double cf = peak / std::sqrt(ss / static_cast<double>(d.table.size()));
        EXPECT_NEAR(d.crestFactor, cf, 1e-9);
        EXPECT_LT(cf, 2.0) << multisinePhasesName(ph);
        EXPECT_LE(peak, 1.956 * (1.0 + 1e-12));
        EXPECT_NEAR(peak, 1.956, 1e-9);
        // Flat: every line has the same amplitude.
        for (double a : d.amplitude)
            EXPECT_NEAR(a, d.amplitude.front(), 1e-12);
        std::cout << multisinePhasesName(ph) << ": crest factor of 200 flat lines " << cf << "\n";
    }
    // Clipping improves on its Schroeder start.
    EXPECT_LT(design({{10.0, 2004.0, 10.0}}, MultisinePhases::Clipping, 4).crestFactor,
              design({{10.0, 2004.0, 10.0}}, MultisinePhases::Schroeder, 4).crestFactor);
}

// The windows of 1/Δf are the three phases: window n equals the multisine with every line shifted by n·120°.
TEST(Multisine, ConsecutiveWindowsAreTheThreePhasesOfEveryLine)
{
    const auto d = design({{10.0, 3900.0, 10.0}}, MultisinePhases::Schroeder, 4);
    const std::size_t m = d.windowSamples, ticks = 4 * m;
    ASSERT_EQ(m, 400u);
    for (int n = 0; n < 3; ++n) {
        for (std::size_t k : {0u, 1u, 3u, 257u, 1599u}) {
            const double t = static_cast<double>(k) / 16000.0;
            double x = 0.0;
            for (std::size_t i = 0; i < d.freqHz.size(); ++i)
                x += d.amplitude[i] * std::sin(2.0 * kPi * d.freqHz[i] * t + d.phaseRad[i] + n * 2.0 * kPi / 3.0);
            EXPECT_NEAR(d.valueAtTick(static_cast<std::int64_t>(n * ticks + k)), x, 1e-9) << n << " " << k;
        }
    }
}

// Issue 11: through a known transfer function with modes above fs/2, the three-phase multisine
// (390 lines from 10 Hz to 3.9 kHz, fs = 4 kHz, one 0.1 s window per phase) recovers the response to
// 1e-9 relative; a single-phase analysis of the same data is flagged invalid (and is wrong).
TEST(Multisine, ThreePhaseIsExactThroughModesAboveNyquistAndSinglePhaseIsInvalid)
{
    const auto d = design({{10.0, 3900.0, 10.0}});
    EXPECT_EQ(d.freqHz.size(), 389u);
    EXPECT_NEAR(d.freqHz.back(), 3893.0 + 1.0 / 3.0, 1e-9);
    for (std::size_t periods : {1u, 2u}) {
        const std::size_t s0 = 137, n = periods * d.periodSamples();
        const auto x = steadyState(d, s0, n, false);
        const auto y = steadyState(d, s0, n, true);
        auto a = analyzeMultisine(d, x, y, periods);
        ASSERT_TRUE(a.ok()) << a.error().detail;
        ASSERT_EQ(a->frf.size(), d.freqHz.size());
        double worst = 0.0;
        for (std::size_t i = 0; i < a->frf.size(); ++i) {
            EXPECT_TRUE(a->frf.valid[i]) << a->frf.freqHz[i];
            const auto ref = plant(a->frf.freqHz[i]);
            worst = std::max(worst, std::abs(a->frf.h[i] - ref) / std::abs(ref));
        }
        EXPECT_LT(worst, 1e-9) << periods;
        if (periods == 2)
            EXPECT_NEAR(a->frf.coherence[200], 1.0, 1e-12);
        else
            EXPECT_TRUE(std::isnan(a->frf.coherence[200]));

        MultisineAnalysisOptions single;
        single.threePhase = false;
        auto s = analyzeMultisine(d, x, y, periods, single);
        ASSERT_TRUE(s.ok());
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < s->frf.size(); ++i) {
            EXPECT_FALSE(s->frf.valid[i]) << s->frf.freqHz[i];
            const auto ref = plant(s->frf.freqHz[i]);
            wrong += std::abs(s->frf.h[i] - ref) / std::abs(ref) > 0.01 ? 1 : 0;
        }
        EXPECT_GT(wrong, 9 * s->frf.size() / 10); // wrong nearly everywhere
        EXPECT_EQ(s->frf.metadata.text("method"), "multisine-single-phase");
    }
}

// The same through a digital resonance executed at the generation rate (16 kHz) and traced at 4 kHz
// (as the drive injects at the current-loop rate): the FRF is the filter's response at e^{jωh}.
TEST(Multisine, DigitalResonanceRunAtTheGenerationRateIsRecoveredFromTheTrace)
{
    const int ticks = 4;
    const double h = 1.0 / 16000.0;
    const auto d = design({{20.0, 200.0, 2.0}, {200.0, 3900.0, 10.0}}, MultisinePhases::Clipping, ticks);
    auto notch = designNotch({3300.0, 600.0, 0.05}, h);
    auto low = designLowPass(1500.0, h);
    ASSERT_TRUE(notch.ok() && low.ok());
    auto response = [&](double f) {
        const std::complex<double> z = std::polar(1.0, 2.0 * kPi * f * h);
        auto biq = [&](const Biquad& b) {
            return (b.b0() + b.b1() / z + b.b2() / (z * z)) / (1.0 + b.a1() / z + b.a2() / (z * z));
        };
        return biq(*notch) * biq(*low);
    };
    const std::size_t periods = 2, settlePeriods = 1;
    const std::size_t total = (periods + settlePeriods) * d.periodTicks();
    std::vector<double> x, y;
    Biquad f1 = *notch, f2 = *low;
    for (std::size_t n = 0; n < total; ++n) {
        const double in = d.valueAtTick(static_cast<std::int64_t>(n));
        const double out = f2.process(f1.process(in));
        if (n % ticks == 0 && n >= settlePeriods * d.periodTicks()) {
            x.push_back(in);
            y.push_back(out);
        }
    }
    auto a = analyzeMultisine(d, x, y, periods);
    ASSERT_TRUE(a.ok()) << a.error().detail;
    double worst = 0.0;
    for (std::size_t i = 0; i < a->frf.size(); ++i)
        worst = std::max(worst, std::abs(a->frf.h[i] / response(a->frf.freqHz[i]) - 1.0));
    EXPECT_LT(worst, 1e-9);
    // Two bands: 2 Hz lines from 20 Hz to 200 Hz, 10 Hz lines above.
    EXPECT_EQ(d.spacingHz, 2.0);
    EXPECT_NEAR(d.freqHz.front(), 20.0 + 2.0 / 3.0, 1e-9);
    std::size_t low2 = 0;
    for (std::size_t i = 1; i < d.freqHz.size(); ++i) {
        const double step = d.freqHz[i] - d.freqHz[i - 1];
        if (d.freqHz[i] <= 200.0) {
            EXPECT_NEAR(step, 2.0, 1e-9);
            ++low2;
        } else if (d.freqHz[i - 1] > 200.0) {
            EXPECT_NEAR(step, 10.0, 1e-9);
        }
    }
    EXPECT_EQ(low2 + 1, 90u); // 90 lines from 20.67 Hz to 198.67 Hz
}

// The FFT demodulation equals the per-line three-phase sums of dsp::demodulate (spec §3.5 form).
TEST(Multisine, FftDemodulationEqualsThePerLineThreePhaseSums)
{
    const auto d = design({{100.0, 3900.0, 40.0}});
    std::mt19937 rng(5);
    std::normal_distribution<double> g;
    std::vector<double> w(3 * d.windowSamples);
    for (double& v : w)
        v = g(rng);
    const std::span<const double> all(w);
    const auto m = d.windowSamples;
    const auto fft = demodulateThreePhase(d, all.subspan(0, m), all.subspan(m, m), all.subspan(2 * m, m));
    for (std::size_t i = 0; i < d.freqHz.size(); ++i) {
        const SweepSamples sw[3] = {
            {0.0, 0, all.subspan(0, m)}, {120.0, 0, all.subspan(m, m)}, {-120.0, 0, all.subspan(2 * m, m)}};
        auto r = demodulate(sw, d.freqHz[i], d.fsHz);
        ASSERT_TRUE(r.ok());
        EXPECT_NEAR(std::abs(fft[i] - r->phasor()), 0.0, 1e-12 * (1.0 + std::abs(r->phasor()))) << d.freqHz[i];
        const auto single = demodulateSinglePhase(d, all.subspan(0, m));
        const SweepSamples one[1] = {{0.0, 0, all.subspan(0, m)}};
        auto c = demodulate(one, std::min(d.freqHz[i], 1999.0), d.fsHz);
        if (d.freqHz[i] < 1999.0) {
            ASSERT_TRUE(c.ok());
            EXPECT_NEAR(std::abs(single[i] - c->phasor()), 0.0, 1e-12 * (1.0 + std::abs(c->phasor())));
        }
    }
}

// Noise estimate: with white noise of known σ on the response, the estimated σ_H/|H| matches the
// theory σ_Y² = 4σ²/(3M) per period, mean over P periods, averaged over the lines; coherence
// tends to 1/P without excitation.
TEST(Multisine, NoiseEstimateMatchesWhiteNoiseOfKnownSigma)
{
    const auto d = design({{50.0, 3900.0, 20.0}});
    const std::size_t periods = 8, n = periods * d.periodSamples();
    const auto x = steadyState(d, 0, n, false);
    auto y = steadyState(d, 0, n, true);
    std::mt19937 rng(11);
    const double sigma = 0.01;
    std::normal_distribution<double> g(0.0, sigma);
    std::vector<double> pure(n);
    for (std::size_t k = 0; k < n; ++k) {
        pure[k] = g(rng);
        y[k] += pure[k];
    }
    MultisineAnalysisOptions o;
    o.maxRelativeNoise = 0.0;
    auto a = analyzeMultisine(d, x, y, periods, o);
    ASSERT_TRUE(a.ok());
    double ratio = 0.0;
    for (std::size_t i = 0; i < a->frf.size(); ++i) {
        const double expected = std::sqrt(4.0 * sigma * sigma / (3.0 * d.windowSamples * periods)) /
                                (d.amplitude[i] * std::abs(plant(d.freqHz[i])));
        ratio += std::pow(a->stats.relativeNoise[i] / expected, 2);
    }
    ratio /= static_cast<double>(a->frf.size());
    EXPECT_NEAR(ratio, 1.0, 0.1); // 195 lines × 14 degrees of freedom: about ±2.5 % (1σ)
    // Noise alone: coherence about 1/P.
    auto z = analyzeMultisine(d, x, pure, periods, o);
    ASSERT_TRUE(z.ok());
    double coh = 0.0;
    for (double c : z->frf.coherence)
        coh += c;
    EXPECT_NEAR(coh / static_cast<double>(z->frf.size()), 1.0 / periods, 0.03);
    // The validity threshold: lines whose noise exceeds maxRelativeNoise are marked invalid.
    o.maxRelativeNoise = 1e-3;
    auto t = analyzeMultisine(d, x, y, periods, o);
    ASSERT_TRUE(t.ok());
    std::size_t invalid = 0;
    for (std::size_t i = 0; i < t->frf.size(); ++i) {
        EXPECT_EQ(t->frf.valid[i], t->stats.relativeNoise[i] <= 1e-3) << t->frf.freqHz[i];
        invalid += t->frf.valid[i] ? 0 : 1;
    }
    EXPECT_EQ(invalid, t->stats.invalidNoise);
}

TEST(Multisine, ShapedSpectrumFollowsTheWeightsAndThePeak)
{
    const std::vector<std::pair<double, double>> shape = {{100.0, 1.0}, {1000.0, 0.1}};
    const auto d = design({{20.0, 3000.0, 20.0}}, MultisinePhases::Clipping, 4, 2.5, shape);
    for (std::size_t i = 0; i < d.freqHz.size(); ++i) {
        const double f = d.freqHz[i];
        const double w = f <= 100.0 ? 1.0 : f >= 1000.0 ? 0.1 : 1.0 - 0.9 * std::log10(f / 100.0);
        EXPECT_NEAR(d.amplitude[i] / d.amplitude.front(), w, 1e-12) << f;
    }
    double peak = 0.0;
    for (double v : d.table)
        peak = std::max(peak, std::abs(v));
    EXPECT_NEAR(peak, 2.5, 1e-9);
    EXPECT_LE(peak, 2.5);
}

TEST(Multisine, BadDesignsAreRefused)
{
    MultisineDesignOptions o;
    o.fsHz = 4000.0;
    o.bands = {{10.0, 4000.0, 10.0}};
    auto r = designMultisine(o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().detail.find("below the trace rate"), std::string::npos);
    o.bands = {};
    EXPECT_FALSE(designMultisine(o).ok());
    o.bands = {{10.0, 100.0, -1.0}};
    EXPECT_FALSE(designMultisine(o).ok());
    o.bands = {{101.0, 102.0, 10.0}}; // no line of the grid inside
    EXPECT_FALSE(designMultisine(o).ok());
    o.bands = {{10.0, 100.0, 10.0}};
    o.shape = {{100.0, 1.0}, {50.0, 1.0}};
    EXPECT_FALSE(designMultisine(o).ok());
    o.shape = {};
    o.peak = 0.0;
    EXPECT_FALSE(designMultisine(o).ok());
    o.peak = 1.0;
    auto d = designMultisine(o);
    ASSERT_TRUE(d.ok());
    std::vector<double> shortRec(d->periodSamples() - 1);
    EXPECT_FALSE(analyzeMultisine(*d, shortRec, shortRec, 1).ok());
}

namespace {

/// A current loop's voltage per torque, roughly: R + jωL (1 Ω, 5 mH): |G| rises 120-fold over the band, phase → 90°.
std::complex<double> voltagePerTorque(double fHz)
{
    return {1.0, 2.0 * kPi * fHz * 5e-3};
}

/// max over the generation grid of Σ |G_i| A_i sin(2π f_i t + φ_i + arg G_i), summed line by line (independent of
/// the inverse FFT the design uses).
double directPeakThrough(const MultisineDesign& d, const std::vector<std::complex<double>>& g)
{
    double peak = 0.0;
    const double rate = d.fsHz * d.ticksPerSample;
    for (std::size_t n = 0; n < d.periodTicks(); ++n) {
        double x = 0.0;
        for (std::size_t i = 0; i < d.freqHz.size(); ++i)
            x += std::abs(g[i]) * d.amplitude[i] *
                 std::sin(2.0 * kPi * d.freqHz[i] * static_cast<double>(n) / rate + d.phaseRad[i] + std::arg(g[i]));
        peak = std::max(peak, std::abs(x));
    }
    return peak;
}

double rmsThrough(const MultisineDesign& d, const std::vector<std::complex<double>>& g)
{
    double s = 0.0;
    for (std::size_t i = 0; i < d.freqHz.size(); ++i)
        s += std::pow(std::abs(g[i]) * d.amplitude[i], 2) / 2.0;
    return std::sqrt(s);
}

} // namespace

// Issue 18 item 2: when the current loop's voltage, not the torque, limits the excitation, the phases are designed
// for the voltage's crest factor. The amplitudes and the torque peak stay as requested; the voltage's crest factor
// (peak over rms of Σ|G_i|A_i, computed here line by line) drops below 2 (the flat design's bound of the first test)
// where the torque-designed phases leave it far above.
TEST(Multisine, PhasesDesignedThroughAResponseLowerThatResponsesCrestFactor)
{
    MultisineDesignOptions o;
    o.fsHz = 4000.0;
    o.ticksPerSample = 4;
    o.bands = {{20.0, 3900.0, 20.0}};
    o.peak = 2.0;
    auto plain = designMultisine(o);
    ASSERT_TRUE(plain.ok());
    std::vector<std::complex<double>> g;
    for (double f : plain->freqHz) {
        g.push_back(voltagePerTorque(f));
        o.crestThrough.emplace_back(f, voltagePerTorque(f));
    }
    auto through = designMultisine(o);
    ASSERT_TRUE(through.ok()) << through.error().detail;
    ASSERT_EQ(through->freqHz, plain->freqHz);
    // The excitation: same relative amplitudes, the requested peak, the table is the sum of the designed sines.
    for (std::size_t i = 0; i < plain->freqHz.size(); ++i)
        EXPECT_NEAR(through->amplitude[i] / through->amplitude.front(), 1.0, 1e-12);
    EXPECT_NEAR(through->peak, 2.0, 1e-9);
    EXPECT_LE(through->peak, 2.0);
    const double rate = o.fsHz * o.ticksPerSample;
    for (std::size_t n = 0; n < through->periodTicks(); n += 37)
        EXPECT_NEAR(through->table[n], through->valueAt(static_cast<double>(n) / rate), 1e-9) << n;
    // The response: multisinePeakThrough against the line-by-line sum, and the crest factors.
    const double peakThrough = multisinePeakThrough(*through, g);
    const double peakPlain = multisinePeakThrough(*plain, g);
    EXPECT_NEAR(peakThrough, directPeakThrough(*through, g), 1e-9 * peakThrough);
    EXPECT_NEAR(peakPlain, directPeakThrough(*plain, g), 1e-9 * peakPlain);
    const double cfThrough = peakThrough / rmsThrough(*through, g);
    const double cfPlain = peakPlain / rmsThrough(*plain, g);
    EXPECT_LT(cfThrough, 2.0);
    EXPECT_GT(cfPlain, 1.3 * cfThrough) << "torque-designed phases: voltage crest " << cfPlain;
    // A real positive gain scales the excitation's own peak; a gain per line of the wrong count gives NaN.
    const std::vector<std::complex<double>> twice(plain->freqHz.size(), 2.5);
    EXPECT_NEAR(multisinePeakThrough(*plain, twice), 2.5 * plain->peak, 1e-9);
    EXPECT_TRUE(std::isnan(multisinePeakThrough(*plain, std::vector<std::complex<double>>(3, 1.0))));
}

TEST(Multisine, BadCrestResponsesAreRefused)
{
    MultisineDesignOptions o;
    o.fsHz = 4000.0;
    o.bands = {{10.0, 100.0, 10.0}};
    o.crestThrough = {{50.0, {1.0, 1.0}}, {20.0, 1.0}}; // not increasing
    auto r = designMultisine(o);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().detail.find("crest response: point 2"), std::string::npos) << r.error().detail;
    o.crestThrough = {{50.0, 0.0}}; // zero gain
    EXPECT_FALSE(designMultisine(o).ok());
    o.crestThrough = {{50.0, {std::nan(""), 1.0}}};
    EXPECT_FALSE(designMultisine(o).ok());
    o.crestThrough = {{-5.0, 1.0}};
    EXPECT_FALSE(designMultisine(o).ok());
    o.crestThrough = {{50.0, {0.0, 3.0}}};
    EXPECT_TRUE(designMultisine(o).ok());
}

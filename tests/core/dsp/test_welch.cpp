// SPDX-License-Identifier: GPL-3.0-or-later
// Welch spectra, H1/H2 and coherence against scipy.signal.csd/welch/coherence reference values
// (tests/data/welch/make_reference.py, scipy 1.10), to 1e-9 relative.
#include "core/dsp/DigitalFilter.h"
#include "core/dsp/Excitation.h"
#include "core/dsp/Welch.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <numbers>
#include <sstream>
#include <string>

#include "tests/NumberText.h"

using namespace axistune;
using namespace axistune::dsp;

namespace {

const std::string kDir = std::string(AXISTUNE_TEST_DATA_DIR) + "/welch/";

// Numeric table with a header line; '#' lines skipped.
std::map<std::string, std::vector<double>> readTable(const std::string& path)
{
    std::ifstream f(path);
    EXPECT_TRUE(f.good()) << "missing reference file " << path;
    std::map<std::string, std::vector<double>> t;
    std::vector<std::string> names;
    std::string line;
    while (std::getline(f, line)) {
        if (line.empty() || line[0] == '#')
            continue;
        std::vector<std::string> cells;
        std::stringstream ss(line);
        for (std::string c; std::getline(ss, c, ',');)
            cells.push_back(c);
        if (names.empty()) {
            names = cells;
            continue;
        }
        for (std::size_t i = 0; i < cells.size(); ++i) {
            std::size_t used = 0;
            const double v = axistune::testutil::stod(cells[i], &used); // the reference files hold Python repr() floats
            EXPECT_EQ(used, cells[i].size()) << path << ": " << line;
            t[names[i]].push_back(v);
        }
    }
    return t;
}

// |a - r| ≤ 1e-9·|r|, with an absolute floor of 1e-13 of the largest reference value for values that
// are zero up to rounding (the DC bin of a rectangular window after mean removal).
void expectRel(double a, double r, double peak, const std::string& what)
{
    EXPECT_LE(std::abs(a - r), 1e-9 * std::abs(r) + 1e-13 * peak) << what << ": " << a << " vs " << r;
}

double peakOf(const std::vector<double>& v)
{
    double m = 0;
    for (double x : v)
        m = std::max(m, std::abs(x));
    return m;
}

struct Case {
    const char* name;
    std::size_t nperseg;
    std::optional<std::size_t> noverlap;
    WelchWindow window;
};

class WelchVsScipy : public ::testing::TestWithParam<Case> {};

}  // namespace

TEST_P(WelchVsScipy, SpectraH1H2AndCoherence)
{
    const Case c = GetParam();
    auto in = readTable(kDir + "input.csv");
    auto ref = readTable(kDir + "ref_" + c.name + ".csv");
    ASSERT_EQ(in["x"].size(), 6000u);
    WelchOptions o;
    o.nperseg = c.nperseg;
    o.noverlap = c.noverlap;
    o.window = c.window;
    auto s = crossSpectra(in["x"], in["y"], 4000.0, o);
    ASSERT_TRUE(s.ok()) << s.error().detail;
    const auto& f = ref["f_Hz"];
    ASSERT_EQ(s->freqHz.size(), f.size());
    const double pxxPeak = peakOf(ref["pxx"]), pyyPeak = peakOf(ref["pyy"]);
    const double pxyPeak = std::max(peakOf(ref["pxy_re"]), peakOf(ref["pxy_im"]));
    for (std::size_t k = 0; k < f.size(); ++k) {
        const std::string at = std::string(c.name) + " bin " + std::to_string(k);
        EXPECT_NEAR(s->freqHz[k], f[k], 1e-9 * f[k]) << at;
        expectRel(s->pxx[k], ref["pxx"][k], pxxPeak, "pxx " + at);
        expectRel(s->pyy[k], ref["pyy"][k], pyyPeak, "pyy " + at);
        expectRel(s->pxy[k].real(), ref["pxy_re"][k], pxyPeak, "pxy re " + at);
        expectRel(s->pxy[k].imag(), ref["pxy_im"][k], pxyPeak, "pxy im " + at);
    }
    for (auto est : {FrfEstimator::H1, FrfEstimator::H2}) {
        auto frf = welchFrf(in["x"], in["y"], 4000.0, o, est);
        ASSERT_TRUE(frf.ok());
        ASSERT_EQ(frf->size(), f.size() - 1);  // DC omitted
        const std::string p = est == FrfEstimator::H1 ? "h1" : "h2";
        for (std::size_t k = 1; k < f.size(); ++k) {
            const std::string at = std::string(c.name) + " " + p + " bin " + std::to_string(k);
            const std::complex<double> r(ref[p + "_re"][k], ref[p + "_im"][k]);
            EXPECT_EQ(frf->freqHz[k - 1], s->freqHz[k]);
            // relative to |H| (both parts), so a component that is nearly zero does not need 1e-9 of itself
            EXPECT_LE(std::abs(frf->h[k - 1] - r), 1e-9 * std::abs(r)) << at;
            expectRel(frf->coherence[k - 1], ref["coherence"][k], 1.0, "coherence " + at);
            EXPECT_TRUE(frf->valid[k - 1]);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Scipy, WelchVsScipy,
                         ::testing::Values(Case{"hann256", 256, std::nullopt, WelchWindow::Hann},
                                           Case{"hann500_ov100", 500, 100, WelchWindow::Hann},
                                           Case{"hann255_odd", 255, std::nullopt, WelchWindow::Hann},
                                           Case{"boxcar128_ov0", 128, 0, WelchWindow::Rectangular}),
                         [](const auto& p) { return std::string(p.param.name); });

TEST(Welch, PeriodicHannWindow)
{
    const auto w = makeWindow(WelchWindow::Hann, 4);
    ASSERT_EQ(w.size(), 4u);
    EXPECT_NEAR(w[0], 0.0, 1e-15);
    EXPECT_NEAR(w[1], 0.5, 1e-15);
    EXPECT_NEAR(w[2], 1.0, 1e-15);
    EXPECT_NEAR(w[3], 0.5, 1e-15);
}

TEST(Welch, KnownGainAndDelayRecovered)
{
    // y[n] = 0.5·x[n-1]: H(f) = 0.5·e^{-j2πf/fs} exactly, coherence 1 (up to the segment-edge effect
    // of the one-sample shift, bounded here by a long segment).
    std::vector<double> x(1 << 14), y(x.size());
    unsigned s = 12345;
    for (auto& v : x) {
        s = s * 1103515245u + 12345u;
        v = static_cast<double>((s >> 8) & 0xffff) / 65536.0 - 0.5;
    }
    y[0] = 0.0;
    for (std::size_t i = 1; i < x.size(); ++i)
        y[i] = 0.5 * x[i - 1];
    WelchOptions o;
    o.nperseg = 1024;
    auto frf = welchFrf(x, y, 1000.0, o);
    ASSERT_TRUE(frf.ok());
    for (std::size_t k = 10; k < frf->size() - 10; k += 50) {
        const auto expected = std::polar(0.5, -2 * std::numbers::pi * frf->freqHz[k] / 1000.0);
        EXPECT_LT(std::abs(frf->h[k] - expected), 0.01) << frf->freqHz[k];
        EXPECT_GT(frf->coherence[k], 0.99);
    }
}

TEST(Welch, BadInputIsAnError)
{
    std::vector<double> x(100, 1.0), y(100, 2.0), shortY(99, 0.0);
    WelchOptions o;
    o.nperseg = 128;
    auto a = crossSpectra(x, y, 1000.0, o);
    ASSERT_FALSE(a.ok());
    EXPECT_NE(a.error().detail.find("fewer than nperseg"), std::string::npos);
    o.nperseg = 64;
    EXPECT_FALSE(crossSpectra(x, shortY, 1000.0, o).ok());
    EXPECT_FALSE(crossSpectra(x, y, 0.0, o).ok());
    o.noverlap = 64;
    EXPECT_FALSE(crossSpectra(x, y, 1000.0, o).ok());
    o.noverlap.reset();
    y[37] = std::nan("");
    auto b = crossSpectra(x, y, 1000.0, o);
    ASSERT_FALSE(b.ok());
    EXPECT_NE(b.error().detail.find("sample 37 of the output"), std::string::npos) << b.error().detail;
}

TEST(Welch, PeriodicPrbsThroughAFilterGivesItsExactResponse)
{
    // A periodic excitation with a rectangular window of one period and the transient discarded:
    // Y[k]/X[k] = H(e^{j2πk/N}) exactly at every bin (circular convolution), so H1 must equal the
    // biquad's own response to rounding, and coherence is 1.
    PrbsOptions p;
    p.order = 10;
    p.periods = 9;
    p.amplitude = 0.5;
    p.amplitudeLimit = 1.0;
    auto x = makePrbs(p);
    ASSERT_TRUE(x.ok());
    const double fs = 4000.0;
    auto notch = designNotch({600.0, 150.0, 0.1}, 1.0 / fs);
    ASSERT_TRUE(notch.ok());
    Biquad q = notch.value();
    std::vector<double> y;
    for (double v : *x)
        y.push_back(q.process(v));
    const std::size_t n = 1023;
    // drop the first period (transient of the filter)
    const std::span<const double> xs(x->data() + n, x->size() - n), ys(y.data() + n, y.size() - n);
    WelchOptions o;
    o.nperseg = n;
    o.noverlap = 0;
    o.window = WelchWindow::Rectangular;
    auto frf = welchFrf(xs, ys, fs, o);
    ASSERT_TRUE(frf.ok());
    ASSERT_EQ(frf->size(), n / 2);
    for (std::size_t k = 0; k < frf->size(); ++k) {
        const auto truth = notch->response(frf->freqHz[k], 1.0 / fs);
        EXPECT_LT(std::abs(frf->h[k] - truth), 1e-9) << frf->freqHz[k];
        EXPECT_NEAR(frf->coherence[k], 1.0, 1e-9);
    }
}

// SPDX-License-Identifier: GPL-3.0-or-later
// Welch's averaged modified periodogram for cross spectra, H1/H2 estimators and coherence
// (P. D. Welch, IEEE Trans. Audio Electroacoust. 15(2), 1967; Bendat & Piersol, "Random Data",
// ch. 9), with the scaling and segmentation conventions of scipy.signal.csd (see Welch.h).
#include "core/dsp/Welch.h"

#include "core/dsp/Fft.h"
#include "core/model/MetadataKeys.h"

#include <cmath>
#include <numbers>
#include <string>

namespace axistune::dsp {

std::vector<double> makeWindow(WelchWindow window, std::size_t n)
{
    std::vector<double> w(n, 1.0);
    if (window == WelchWindow::Hann) {
        for (std::size_t k = 0; k < n; ++k)
            w[k] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n));
    }
    return w;
}

namespace {

Status checkInput(std::span<const double> x, std::span<const double> y, double fsHz, const WelchOptions& o,
                  std::size_t noverlap)
{
    if (x.size() != y.size()) {
        return makeError(ErrorCode::BadInput, "input and output have different lengths (" + std::to_string(x.size())
                                                  + " and " + std::to_string(y.size()) + " samples)");
    }
    if (!(fsHz > 0.0) || !std::isfinite(fsHz))
        return makeError(ErrorCode::BadInput, "sampling frequency must be positive");
    if (o.nperseg < 2)
        return makeError(ErrorCode::OutOfRange, "nperseg must be at least 2");
    if (noverlap >= o.nperseg) {
        return makeError(ErrorCode::OutOfRange, "noverlap (" + std::to_string(noverlap)
                                                    + ") must be smaller than nperseg (" + std::to_string(o.nperseg) + ")");
    }
    if (x.size() < o.nperseg) {
        return makeError(ErrorCode::BadInput, "only " + std::to_string(x.size()) + " samples, fewer than nperseg = "
                                                  + std::to_string(o.nperseg));
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {
            return makeError(ErrorCode::BadInput, "sample " + std::to_string(i) + " of the "
                                                      + (std::isfinite(x[i]) ? "output" : "input") + " is not finite");
        }
    }
    return {};
}

// Copies one segment into the FFT buffer: mean removed (optional), then windowed.
void loadSegment(std::span<const double> src, const std::vector<double>& w, bool detrend, std::span<double> dst)
{
    double mean = 0.0;
    if (detrend) {
        for (double v : src)
            mean += v;
        mean /= static_cast<double>(src.size());
    }
    for (std::size_t k = 0; k < src.size(); ++k)
        dst[k] = (src[k] - mean) * w[k];
}

}  // namespace

Result<CrossSpectra> crossSpectra(std::span<const double> x, std::span<const double> y, double fsHz,
                                  const WelchOptions& options)
{
    const std::size_t n = options.nperseg;
    const std::size_t noverlap = options.noverlap.value_or(n / 2);
    if (auto s = checkInput(x, y, fsHz, options, noverlap); !s)
        return s.error();
    const std::size_t step = n - noverlap;
    const std::size_t segments = (x.size() - n) / step + 1;
    const auto w = makeWindow(options.window, n);

    RealFft fx(n), fy(n);
    const std::size_t bins = fx.bins();
    CrossSpectra s;
    s.pxx.assign(bins, 0.0);
    s.pyy.assign(bins, 0.0);
    s.pxy.assign(bins, {0.0, 0.0});
    for (std::size_t seg = 0; seg < segments; ++seg) {
        const std::size_t start = seg * step;
        loadSegment(x.subspan(start, n), w, options.detrendConstant, fx.input());
        loadSegment(y.subspan(start, n), w, options.detrendConstant, fy.input());
        fx.execute();
        fy.execute();
        const auto X = fx.output();
        const auto Y = fy.output();
        for (std::size_t k = 0; k < bins; ++k) {
            const double xr = X[k].real(), xi = X[k].imag(), yr = Y[k].real(), yi = Y[k].imag();
            s.pxx[k] += xr * xr + xi * xi;
            s.pyy[k] += yr * yr + yi * yi;
            // conj(X)·Y
            s.pxy[k] += std::complex<double>(xr * yr + xi * yi, xr * yi - xi * yr);
        }
    }
    double sumW2 = 0.0;
    for (double v : w)
        sumW2 += v * v;
    const double scale = 1.0 / (fsHz * sumW2);
    s.freqHz.resize(bins);
    for (std::size_t k = 0; k < bins; ++k) {
        // One-sided: double every bin that has a negative-frequency twin.
        const bool twin = k != 0 && !(n % 2 == 0 && k == n / 2);
        const double f = scale * (twin ? 2.0 : 1.0) / static_cast<double>(segments);
        s.pxx[k] *= f;
        s.pyy[k] *= f;
        s.pxy[k] *= f;
        s.freqHz[k] = static_cast<double>(k) * fsHz / static_cast<double>(n);
    }
    s.segments = segments;
    return s;
}

FrequencyResponse frfFromSpectra(const CrossSpectra& s, FrfEstimator estimator)
{
    FrequencyResponse frf;
    const std::size_t bins = s.freqHz.size();
    frf.freqHz.reserve(bins);
    frf.h.reserve(bins);
    frf.coherence.reserve(bins);
    frf.valid.reserve(bins);
    for (std::size_t k = 1; k < bins; ++k) {
        const bool ok = s.pxx[k] > 0.0 && s.pyy[k] > 0.0;
        std::complex<double> h = estimator == FrfEstimator::H1 ? s.pxy[k] / s.pxx[k] : s.pyy[k] / std::conj(s.pxy[k]);
        const double coh = ok ? std::norm(s.pxy[k]) / s.pxx[k] / s.pyy[k] : std::nan("");
        if (!ok)
            h = {0.0, 0.0};  // undefined; flagged invalid (kept finite so that files stay readable)
        frf.push(s.freqHz[k], h, coh, ok);
    }
    frf.metadata.set(model::meta::kMethod, estimator == FrfEstimator::H1 ? "welch-h1" : "welch-h2");
    frf.metadata.set("segments", static_cast<double>(s.segments));
    return frf;
}

Result<FrequencyResponse> welchFrf(std::span<const double> x, std::span<const double> y, double fsHz,
                                   const WelchOptions& options, FrfEstimator estimator)
{
    auto s = crossSpectra(x, y, fsHz, options);
    if (!s)
        return s.error();
    // Samples near the double range (1e308) overflow the spectra: refused, never written as valid points.
    for (std::size_t k = 0; k < s->freqHz.size(); ++k) {
        if (!std::isfinite(s->pxx[k]) || !std::isfinite(s->pyy[k]) || !std::isfinite(s->pxy[k].real()) ||
            !std::isfinite(s->pxy[k].imag()))
            return makeError(ErrorCode::OutOfRange, "the spectra overflow in frequency bin " + std::to_string(k) +
                                                        ": the samples are too large (near the double range)");
    }
    auto frf = frfFromSpectra(s.value(), estimator);
    frf.metadata.set(model::meta::kNperseg, options.nperseg);
    frf.metadata.set("noverlap", static_cast<double>(options.noverlap.value_or(options.nperseg / 2)));
    return frf;
}

}  // namespace axistune::dsp

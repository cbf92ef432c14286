// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Welch cross-spectral estimation and the H1/H2 frequency-response estimators with coherence.
// Conventions are those of scipy.signal.csd / welch / coherence (scipy 1.10):
//   one-sided spectra, detrend='constant' (segment mean removed before windowing), periodic Hann
//   window by default, noverlap = nperseg/2 (floor) by default, nfft = nperseg,
//   Pxy = conj(X)·Y, density scaling 1/(fs·Σw²), bins other than DC and (even nperseg) Nyquist doubled,
//   segments averaged by the mean; trailing samples that do not fill a segment are not used.
//   H1 = Pxy/Pxx, H2 = Pyy/Pyx with Pyx = conj(Pxy), coherence = |Pxy|²/(Pxx·Pyy).
// Differences from scipy: fewer samples than nperseg is an error (scipy shrinks nperseg), and the
// FRF omits the DC bin (after constant detrending it carries no information).

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Result.h"

#include <complex>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace axistune::dsp {

enum class WelchWindow { Hann, Rectangular };
enum class FrfEstimator { H1, H2 };

struct WelchOptions {
    std::size_t nperseg = 256;
    std::optional<std::size_t> noverlap;  ///< default nperseg/2
    WelchWindow window = WelchWindow::Hann;
    bool detrendConstant = true;
};

/// One-sided averaged (cross) power spectral densities, in (unit of x)·(unit of y)/Hz.
struct CrossSpectra {
    std::vector<double> freqHz;
    std::vector<double> pxx;
    std::vector<double> pyy;
    std::vector<std::complex<double>> pxy;
    std::size_t segments = 0;
};

/// The window samples (periodic Hann as scipy.signal.get_window('hann', n)).
std::vector<double> makeWindow(WelchWindow window, std::size_t n);

/// Pxx, Pyy and Pxy of two equally long channels sampled at fsHz. The channels are read in place
/// (no copy of the whole input). Errors: unequal lengths, fewer samples than nperseg, nperseg < 2,
/// noverlap ≥ nperseg, fs ≤ 0, non-finite samples (the message names the sample index).
Result<CrossSpectra> crossSpectra(std::span<const double> x, std::span<const double> y, double fsHz,
                                  const WelchOptions& options);

/// H1 or H2 with coherence, from the spectra; the DC bin is omitted. A point is valid where
/// Pxx > 0 and Pyy > 0 (coherence defined).
FrequencyResponse frfFromSpectra(const CrossSpectra& spectra, FrfEstimator estimator);

/// crossSpectra + frfFromSpectra; x is the excitation (input), y the response (output).
Result<FrequencyResponse> welchFrf(std::span<const double> x, std::span<const double> y, double fsHz,
                                   const WelchOptions& options, FrfEstimator estimator = FrfEstimator::H1);

}  // namespace axistune::dsp

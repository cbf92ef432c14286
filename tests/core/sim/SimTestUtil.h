// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small helpers for simulator tests: single-frequency Fourier coefficients over whole periods,
// computed directly (independent of core/dsp).

#include "core/model/Capture.h"

#include <complex>
#include <numbers>
#include <vector>

namespace axistune::simtest {

/// Σ x[n] e^{-jωt_n} over [first, first+count): the complex amplitude (×count/2) at f.
inline std::complex<double> fourierAt(const std::vector<double>& x, const std::vector<double>& t, std::size_t first,
                                      std::size_t count, double fHz)
{
    std::complex<double> acc = 0.0;
    for (std::size_t n = first; n < first + count; ++n)
        acc += x[n] * std::polar(1.0, -2.0 * std::numbers::pi * fHz * t[n]);
    return acc;
}

inline double phaseDiffDeg(std::complex<double> a, std::complex<double> b)
{
    return std::arg(a / b) * 180.0 / std::numbers::pi;
}

}  // namespace axistune::simtest

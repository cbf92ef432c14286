// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Frequency-response data: complex response per frequency, coherence where a Welch estimate defines
// it, and a validity flag per point (e.g. above the alias-free range of a sine-stream method).
// Phase convention: phase = arg(h) in degrees, in (-180, 180]; unwrapped phase removes 360° jumps.

#include "core/model/Metadata.h"

#include <complex>
#include <cstddef>
#include <string>
#include <vector>

namespace axistune::dsp {

struct FrequencyResponse {
    std::vector<double> freqHz;                 ///< increasing frequencies [Hz]
    std::vector<std::complex<double>> h;        ///< response (output/input, dimension of the channels)
    std::vector<double> coherence;              ///< 0..1, NaN where not defined (sine streams)
    std::vector<bool> valid;                    ///< false where the method cannot measure this point
    model::Metadata metadata;                   ///< "# key=value" lines of the FRF CSV (numbers as numbers)

    std::size_t size() const { return freqHz.size(); }
    bool empty() const { return freqHz.empty(); }
    /// Appends a point; coherence NaN means "not defined".
    void push(double fHz, std::complex<double> value, double coh, bool isValid);
};

/// 20·log10|h| [dB]; -inf for h = 0.
double magnitudeDb(std::complex<double> h);
/// arg(h) in degrees, in (-180, 180].
double phaseDeg(std::complex<double> h);
std::vector<double> magnitudeDb(const FrequencyResponse& frf);
std::vector<double> phaseDeg(const FrequencyResponse& frf);
/// Removes jumps larger than 180° between consecutive values (degrees); the first value is kept.
std::vector<double> unwrapDeg(const std::vector<double>& phaseDegrees);
/// Unwrapped phase of a response [deg].
std::vector<double> unwrappedPhaseDeg(const FrequencyResponse& frf);

}  // namespace axistune::dsp

// SPDX-License-Identifier: GPL-3.0-or-later
// Frequency-response data type and Bode helpers (magnitude in dB, phase in degrees, unwrapping).
#include "core/dsp/FrequencyResponse.h"

#include "core/model/Constants.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace axistune::dsp {

void FrequencyResponse::push(double fHz, std::complex<double> value, double coh, bool isValid)
{
    freqHz.push_back(fHz);
    h.push_back(value);
    coherence.push_back(coh);
    valid.push_back(isValid);
}

double magnitudeDb(std::complex<double> h)
{
    const double a = std::abs(h);
    if (a == 0.0)
        return -std::numeric_limits<double>::infinity();
    return 20.0 * std::log10(a);
}

double phaseDeg(std::complex<double> h)
{
    const double p = std::arg(h) * model::kDegPerRad;
    return p == -180.0 ? 180.0 : p;
}

std::vector<double> magnitudeDb(const FrequencyResponse& frf)
{
    std::vector<double> out;
    out.reserve(frf.size());
    for (const auto& v : frf.h)
        out.push_back(magnitudeDb(v));
    return out;
}

std::vector<double> phaseDeg(const FrequencyResponse& frf)
{
    std::vector<double> out;
    out.reserve(frf.size());
    for (const auto& v : frf.h)
        out.push_back(phaseDeg(v));
    return out;
}

std::vector<double> unwrapDeg(const std::vector<double>& phaseDegrees)
{
    std::vector<double> out(phaseDegrees.size());
    double offset = 0.0;
    for (std::size_t i = 0; i < phaseDegrees.size(); ++i) {
        if (i > 0) {
            const double d = phaseDegrees[i] + offset - out[i - 1];
            // Whole turns only, so that the unwrapped phase equals the wrapped one modulo 360°.
            offset -= 360.0 * std::round(d / 360.0);
        }
        out[i] = phaseDegrees[i] + offset;
    }
    return out;
}

std::vector<double> unwrappedPhaseDeg(const FrequencyResponse& frf) { return unwrapDeg(phaseDeg(frf)); }

}  // namespace axistune::dsp

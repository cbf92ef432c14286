// SPDX-License-Identifier: GPL-3.0-or-later
// Prediction against measurement of a loop's frequency response (docs/wizards/notch.md "Verify");
// interpolation in (log10 f, dB) as in the margins of dsp::loopMargins.
#include "core/tuning/FrfComparison.h"

#include <cmath>
#include <vector>

namespace axistune::tuning {

namespace {

bool usable(const dsp::FrequencyResponse& r, std::size_t i)
{
    return r.valid[i] && r.freqHz[i] > 0.0 && std::isfinite(std::abs(r.h[i])) && std::abs(r.h[i]) > 0.0;
}

/// |a| in dB at fHz, interpolated between the neighbouring usable points; NaN outside or at a gap.
double interpolatedDb(const dsp::FrequencyResponse& a, const std::vector<std::size_t>& idx, double fHz)
{
    if (idx.empty() || fHz < a.freqHz[idx.front()] || fHz > a.freqHz[idx.back()])
        return std::nan("");
    std::size_t lo = 0, hi = idx.size() - 1;
    while (hi - lo > 1) {
        const std::size_t mid = (lo + hi) / 2;
        (a.freqHz[idx[mid]] <= fHz ? lo : hi) = mid;
    }
    const std::size_t i = idx[lo], j = idx[hi];
    const double di = dsp::magnitudeDb(a.h[i]), dj = dsp::magnitudeDb(a.h[j]);
    if (i == j || a.freqHz[j] == a.freqHz[i])
        return di;
    const double t = std::log10(fHz / a.freqHz[i]) / std::log10(a.freqHz[j] / a.freqHz[i]);
    return di + t * (dj - di);
}

}  // namespace

FrfDeviation compareMagnitudes(const dsp::FrequencyResponse& reference, const dsp::FrequencyResponse& measured,
                               double floorDb)
{
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < reference.size(); ++i)
        if (usable(reference, i))
            idx.push_back(i);
    FrfDeviation d;
    double sum2 = 0.0;
    for (std::size_t k = 0; k < measured.size(); ++k) {
        if (!usable(measured, k))
            continue;
        const double ref = interpolatedDb(reference, idx, measured.freqHz[k]);
        const double mdb = dsp::magnitudeDb(measured.h[k]);
        if (!std::isfinite(ref) || (ref < floorDb && mdb < floorDb))
            continue;
        const double delta = mdb - ref;
        if (d.points == 0) {
            d.fminHz = measured.freqHz[k];
            d.maxAbsDb = -1.0;
        }
        d.fmaxHz = measured.freqHz[k];
        if (std::abs(delta) > d.maxAbsDb) {
            d.maxAbsDb = std::abs(delta);
            d.maxAtHz = measured.freqHz[k];
        }
        sum2 += delta * delta;
        ++d.points;
    }
    if (d.points > 0)
        d.rmsDb = std::sqrt(sum2 / static_cast<double>(d.points));
    return d;
}

double peakMagnitudeDb(const dsp::FrequencyResponse& frf, double centerHz, double relHalfWidth)
{
    double best = std::nan("");
    for (std::size_t i = 0; i < frf.size(); ++i) {
        if (!usable(frf, i) || std::abs(frf.freqHz[i] - centerHz) > relHalfWidth * centerHz)
            continue;
        const double db = dsp::magnitudeDb(frf.h[i]);
        if (!(best >= db))
            best = db;
    }
    return best;
}

}  // namespace axistune::tuning

// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/autotune/SlidingPlant.h"

#include "core/model/Number.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace axistune::autotune {

namespace {

double median(std::vector<double> v)
{
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    if (v.size() % 2 == 1)
        return *mid;
    const double hi = *mid;
    return 0.5 * (hi + *std::max_element(v.begin(), mid));
}

} // namespace

Result<StandstillDamping> standstillDamping(const dsp::FrequencyResponse& plant)
{
    std::vector<double> re, inertia;
    double first = 0.0, upTo = 0.0;
    for (std::size_t i = 0; i < plant.size(); ++i) {
        const auto p = plant.h[i];
        const double f = plant.freqHz[i];
        if (!plant.valid[i] || !std::isfinite(p.real()) || !std::isfinite(p.imag()) || std::abs(p) == 0.0 || !(f > 0.0))
            continue;
        if (first == 0.0)
            first = f;
        else if (f > kStandstillBandFactor * first && re.size() >= 3)
            break;
        const auto z = 1.0 / p;
        re.push_back(z.real());
        inertia.push_back(z.imag() / (2.0 * std::numbers::pi * f));
        upTo = f;
    }
    if (re.size() < 3)
        return makeError(ErrorCode::BadInput, "the plant has fewer than 3 valid lines at its low end; the damping at "
                                              "standstill cannot be read");
    StandstillDamping d;
    d.lines = re.size();
    d.upToHz = upTo;
    d.inertiaKgm2 = median(inertia);
    if (!(d.inertiaKgm2 > 0.0) || !std::isfinite(d.inertiaKgm2))
        return makeError(ErrorCode::BadInput, "the plant's lowest lines (up to " + model::formatNumber(upTo, 4) +
                                                  " Hz) are not those of an inertia (Im(1/P) <= 0)");
    d.bNmsPerRad = std::max(0.0, median(re));
    return d;
}

} // namespace axistune::autotune

// SPDX-License-Identifier: GPL-3.0-or-later
// Injection-hold factor: the fundamental of an N-tap zero-order hold relative to a sine sampled at
// every tap (spec/current-loop-and-multisweep-frf.md §3.6, the excitation at the current-loop rate;
// derivation in docs/frequency-response-sim.md, "Injection hold").
#include "core/dsp/InjectionHold.h"

#include "core/model/MetadataKeys.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace axistune::dsp {

std::complex<double> injectionHoldFactor(double fHz, double currentPeriodS, int ticksPerVelocity)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (ticksPerVelocity < 1 || !std::isfinite(fHz) || !std::isfinite(currentPeriodS) || !(currentPeriodS > 0.0))
        return {nan, nan};
    if (ticksPerVelocity == 1)
        return {1.0, 0.0};
    const double theta = 2.0 * std::numbers::pi * fHz * currentPeriodS;
    std::complex<double> sum = 0.0;
    for (int m = 0; m < ticksPerVelocity; ++m)
        sum += std::polar(1.0, -theta * static_cast<double>(m));
    const double n = static_cast<double>(ticksPerVelocity);
    if (std::abs(sum) < 1e-12 * n)
        return {nan, nan};
    return n / sum;
}

bool isInjectionHoldCorrected(const FrequencyResponse& frf)
{
    const auto* v = frf.metadata.find(model::meta::kInjectionHoldCorrected);
    return v && v->text() == "true";
}

Status correctInjectionHold(FrequencyResponse& frf, double currentPeriodS, int ticksPerVelocity)
{
    if (ticksPerVelocity < 1 || !std::isfinite(currentPeriodS) || !(currentPeriodS > 0.0))
        return makeError(ErrorCode::BadInput, "injection-hold correction: the current period must be positive and the "
                                              "ticks per velocity period at least 1");
    if (isInjectionHoldCorrected(frf))
        return makeError(ErrorCode::BadInput, "injection-hold correction: the FRF is already corrected "
                                              "(injection_hold_corrected=true)");
    for (std::size_t i = 0; i < frf.size(); ++i) {
        const std::complex<double> g = injectionHoldFactor(frf.freqHz[i], currentPeriodS, ticksPerVelocity);
        if (std::isfinite(g.real()) && std::isfinite(g.imag())) {
            frf.h[i] /= g;
        } else {
            frf.valid[i] = false;
        }
    }
    frf.metadata.set(model::meta::kInjectionHoldCorrected, "true");
    frf.metadata.set(model::meta::kInjectionHoldPeriodS, currentPeriodS);
    frf.metadata.set(model::meta::kInjectionHoldTicks, ticksPerVelocity);
    return Status::success();
}

} // namespace axistune::dsp

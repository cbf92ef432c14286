// SPDX-License-Identifier: GPL-3.0-or-later
// Exponential-window damping removed from fitted modes (core/machining/ExponentialWindow.h).
#include "core/machining/ExponentialWindow.h"

#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/model/Units.h"

#include <cmath>

namespace axistune::machining {

Result<ModalParameters> removeExponentialWindow(const ModalParameters& w, double sigma)
{
    if (!(sigma >= 0.0) || !std::isfinite(sigma))
        return makeError(ErrorCode::BadInput, "exponential-window decay must be a finite number >= 0");
    ModalParameters m = w;
    m.dampingNsPerM = w.dampingNsPerM - 2.0 * w.massKg * sigma;
    m.stiffnessNPerM = w.stiffnessNPerM - m.dampingNsPerM * sigma - w.massKg * sigma * sigma;
    if (!(m.dampingNsPerM > 0.0))
        return makeError(ErrorCode::OutOfRange,
                         "the exponential window adds more damping (" + model::formatNumber(2.0 * w.massKg * sigma, 4) +
                             " N·s/m) than the fitted mode has (" + model::formatNumber(w.dampingNsPerM, 4) +
                             " N·s/m): use a longer time constant");
    if (!(m.stiffnessNPerM > 0.0))
        return makeError(ErrorCode::OutOfRange, "removing the exponential window leaves no positive stiffness");
    return m;
}

Result<double> exponentialWindowDecay(const dsp::FrequencyResponse& frf)
{
    const auto v = frf.metadata.optionalNumber(model::meta::kExpWindowDecay);
    if (!v)
        return v.error();
    if (!(v->value_or(0.0) >= 0.0))
        return makeError(ErrorCode::BadInput, "metadata 'exp_window_decay_1_s' must be >= 0 ('" +
                                                  *frf.metadata.text(model::meta::kExpWindowDecay) + "')");
    return v->value_or(0.0);
}

Status removeExponentialWindow(std::vector<ModalParameters>& modes, const dsp::FrequencyResponse& frf)
{
    auto sigma = exponentialWindowDecay(frf);
    if (!sigma)
        return sigma.error();
    if (*sigma == 0.0)
        return {};
    for (auto& m : modes) {
        auto c = removeExponentialWindow(m, *sigma);
        if (!c)
            return c.error();
        m = *c;
    }
    return {};
}

} // namespace axistune::machining

// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/Parameter.h"

#include "core/model/Units.h"

#include <cmath>

namespace axistune::model {

std::string formatDisplay(const ParameterMeta& meta, double valueSi)
{
    auto v = convertUnit(valueSi, meta.siUnit, meta.displayUnit);
    if (v) {
        const auto label = unitLabel(meta.displayUnit);
        return formatNumber(*v, 6) + (label.empty() ? "" : " " + label);
    }
    return formatNumber(valueSi, 6) + " " + unitLabel(meta.siUnit);
}

Status checkParameterValue(const ParameterMeta& meta, double valueSi)
{
    if (!std::isfinite(valueSi)) {
        return makeError(ErrorCode::BadInput, "parameter '" + meta.key + "': value is not a finite number");
    }
    if (meta.integer && std::floor(valueSi) != valueSi) {
        return makeError(ErrorCode::BadInput, "parameter '" + meta.key + "' takes an integer value");
    }
    if (valueSi < meta.minSi || valueSi > meta.maxSi) {
        return makeError(ErrorCode::OutOfRange, "parameter '" + meta.key + "' = " + formatDisplay(meta, valueSi)
                                                    + " is outside its limits [" + formatDisplay(meta, meta.minSi)
                                                    + ", " + formatDisplay(meta, meta.maxSi) + "]");
    }
    return Status::success();
}

const ParameterMeta* findParameter(const std::vector<ParameterMeta>& metas, const std::string& key)
{
    for (const auto& m : metas) {
        if (m.key == key)
            return &m;
    }
    return nullptr;
}

}  // namespace axistune::model

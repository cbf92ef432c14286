// SPDX-License-Identifier: GPL-3.0-or-later
// Identified rigid-body model → simulated plant parameters (docs/identification.md "Using the result").
#include "core/sim/IdentifiedPlant.h"

#include "core/model/Parameter.h"

#include <cmath>

namespace axistune::sim {

Status applyIdentifiedModel(AxisDefinition& axis, const ident::IdentifiedModel& m, const std::string& src)
{
    const bool linear = axis.kind == AxisKind::Linear;
    if (linear != (m.motion == ident::AxisMotion::Linear)) {
        return makeError(ErrorCode::BadInput, src + ": a " + ident::axisMotionName(m.motion) +
                                                  " model cannot be applied to " + (linear ? "linear" : "rotary") +
                                                  " axis " + axis.name);
    }
    const double r = linear ? axis.values.at("plant.screw_lead") : 1.0;
    const double totals[3] = {m.model.inertia * r * r,
                              0.5 * (m.model.viscousPositive + m.model.viscousNegative) * r * r,
                              0.5 * (m.model.coulombPositive + m.model.coulombNegative) * r};
    const char* pairs[3][2] = {{"plant.inertia_motor", "plant.inertia_load"},
                               {"plant.viscous_motor", "plant.viscous_load"},
                               {"plant.coulomb_motor", "plant.coulomb_load"}};
    model::ParameterValues next = axis.values;
    for (int i = 0; i < 3; ++i) {
        const double a = axis.values.at(pairs[i][0]), b = axis.values.at(pairs[i][1]);
        const double share = a + b > 0.0 ? a / (a + b) : 1.0;
        next[pairs[i][0]] = totals[i] * share;
        next[pairs[i][1]] = totals[i] * (1.0 - share);
    }
    const auto& metas = axisParameterMetas(axis.kind);
    for (const auto& pair : pairs) {
        for (const char* key : pair) {
            const auto* meta = model::findParameter(metas, key);
            if (meta == nullptr)
                return makeError(ErrorCode::Internal, std::string("no parameter ") + key);
            if (auto st = model::checkParameterValue(*meta, next[key]); !st)
                return makeError(ErrorCode::OutOfRange, src + ", axis " + axis.name + ": " + st.error().detail);
            axis.sources[key] = "identified: " + src;
        }
    }
    axis.values = std::move(next);
    return Status::success();
}

} // namespace axistune::sim

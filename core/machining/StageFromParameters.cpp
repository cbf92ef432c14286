// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/machining/StageFromParameters.h"

#include "core/model/Constants.h"

namespace axistune::machining {

Result<StageDescription> stageFromAxisParameters(const model::ParameterValues& values)
{
    for (const char* k : {"plant.screw_lead", "motor.torque_constant", "plant.inertia_motor", "plant.viscous_motor",
                          "plant.coulomb_motor", "plant.inertia_load", "plant.viscous_load", "plant.coulomb_load",
                          "plant.coupling_stiffness", "plant.coupling_damping"})
        if (values.find(k) == values.end())
            return makeError(ErrorCode::NotFound,
                             std::string("stage from the axis parameters: '") + k + "' is missing");
    const auto v = [&values](const char* k) { return values.at(k); };
    StageDescription d;
    d.leadMPerRev = v("plant.screw_lead") * model::kTwoPi; // m/rad → m/rev
    d.torqueConstantNmPerA = v("motor.torque_constant");
    d.motor = {v("plant.inertia_motor"), v("plant.viscous_motor"), v("plant.coulomb_motor")};
    d.load = {v("plant.inertia_load"), v("plant.viscous_load"), v("plant.coulomb_load")};
    d.couplingStiffnessNmPerRad = v("plant.coupling_stiffness");
    d.couplingDampingNmsPerRad = v("plant.coupling_damping");
    d.hasCoupling = d.couplingStiffnessNmPerRad > 0.0;
    return d;
}

} // namespace axistune::machining

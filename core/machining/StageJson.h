// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// stage.json (docs/machining.md "stage.json"): the feed-drive parameters the cutting force observer
// (seed 003) and the vibration-mode chatter detection (seed 004) need, in SI with the unit in the key:
//   {"screw_lead_m_per_rev": 0.012, "torque_constant_Nm_per_A": 0.50911,
//    "motor": {"inertia_kgm2": ..., "viscous_Nms_per_rad": ..., "coulomb_Nm": ...},
//    "load":  {"inertia_kgm2": ..., "viscous_Nms_per_rad": ..., "coulomb_Nm": ...},
//    "coupling": {"stiffness_Nm_per_rad": ..., "damping_Nms_per_rad": ...},      (chatter detection only)
//    "observer": {...}, "rls": {...}, "chatter": {...}}                             (optional settings)
// Unknown keys are refused (a typo must not silently fall back to a default). Errors name the source and key.

#include "core/machining/CuttingForceObserver.h"
#include "core/machining/SwitchingRls.h"
#include "core/machining/VibrationModeChatter.h"
#include "core/model/Result.h"

#include <string>

namespace axistune::machining {

struct StageDescription {
    double leadMPerRev = 0.0;
    double torqueConstantNmPerA = 0.0;
    MotorParameters motor;
    LoadParameters load;
    bool hasCoupling = false;
    double couplingStiffnessNmPerRad = 0.0;
    double couplingDampingNmsPerRad = 0.0;
    ObserverOptions observer;
    SwitchingRlsOptions rls;
    ChatterDetectOptions chatter;

    double leadMPerRad() const;
    /// The two-mass stage in linear units (needs the coupling).
    TwoMassStage twoMass() const;
};

Result<StageDescription> parseStageJson(const std::string& text, const std::string& sourceName);
Result<StageDescription> readStageJsonFile(const std::string& path);

} // namespace axistune::machining

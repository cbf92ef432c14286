// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The stage of a feed axis (StageJson.h) from the drive parameters of the axis (core/sim/AxisParameters.cpp
// keys, SI): screw lead per revolution = plant.screw_lead [m/rad] × 2π, the motor's torque constant, the
// motor and load inertia/friction and the coupling. Used where no stage file is given (chatter-detect, the
// machining wizard on a simulated machine).

#include "core/machining/StageJson.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"

namespace axistune::machining {

/// NotFound naming the key when a parameter is missing.
Result<StageDescription> stageFromAxisParameters(const model::ParameterValues& values);

} // namespace axistune::machining

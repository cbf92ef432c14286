// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Predicted velocity step of the velocity loop (velocity/position-loop wizard, issue 9 item 2;
// docs/wizards/velocity-loop.md): the PI C = K_P + K_I/s evaluated once per velocity period on the
// sampled error (zero-order hold of the torque command, the integral summed per period), the plant the
// two-inertia model of spec/lost-motion-and-two-inertia.md (5.1) (motor J_m, load J_L, spring K,
// damper C), integrated between samples with small substeps. K = 0 stands for a rigid axis of inertia
// J_m + J_L. The current loop is taken as ideal (torque = command) and the measurement delay is left out.

#include "core/model/Result.h"
#include "core/tuning/TwoInertia.h"
#include "core/tuning/VelocityLoop.h"

#include <vector>

namespace axistune::tuning {

struct VelocityStepPrediction {
    std::vector<double> tS;           ///< one sample per velocity period, from 0
    std::vector<double> commandRadS;  ///< the step command (0 before stepTimeS)
    std::vector<double> motorVelRadS; ///< motor velocity
    std::vector<double> loadVelRadS;  ///< load velocity (= motor velocity when rigid)
    std::vector<double> torqueNm;     ///< torque command
};

/// Step of `stepRadS` at `stepTimeS` over `durationS`. BadInput for non-positive inertia or period,
/// a negative spring or damper, a non-finite gain or a duration below one period.
Result<VelocityStepPrediction> predictVelocityStep(const TwoInertiaParams& p, const VelocityPi& pi, double periodS,
                                                   double stepRadS, double stepTimeS, double durationS);

} // namespace axistune::tuning

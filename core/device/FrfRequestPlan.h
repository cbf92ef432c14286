// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The plan and the evaluation of an FRF test request (TestType::Frf) from the axis's parameter values,
// shared by the drive that runs the test (SimulatedDrive plans its excitation with it) and by the host
// (device::runTest evaluates the trace of a drive that only streams samples; docs/device.md "Host-side
// evaluation"). Same request, same parameters, same trace: the same FRF, to the last bit.

#include "core/device/Drive.h"
#include "core/device/FrfTest.h"
#include "core/device/MultisineTest.h"
#include "core/model/Capture.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"

#include <memory>
#include <span>
#include <string>

namespace axistune::device {

/// The clock of an axis: current-loop period h, velocity ticks (N current ticks each), trace samples
/// (D velocity ticks each). The trace rate is 1 / (h·N·D).
struct AxisClock {
    double currentPeriodS = 0.0;
    int ticksPerVelocity = 1;
    int traceDivider = 1;
    double velocityPeriodS() const { return currentPeriodS * ticksPerVelocity; }
    double tracePeriodS() const { return velocityPeriodS() * traceDivider; }
};

/// The clock from current.period, velocity.period and trace.divider (the request's traceDivider when > 0).
/// BadInput naming the key when one is missing, not positive or velocity.period is not a whole multiple of h.
Result<AxisClock> axisClockFromParameters(const model::ParameterValues& values, int traceDividerOverride = 0);

/// The parameter keys planFrfRequest reads (read them from the drive before the test starts).
std::span<const std::string> frfPlanParameterKeys();

/// One of the two plans: sine streams / PRBS (FrfTest.h) or the three-phase multisine (MultisineTest.h).
struct FrfRequestPlan {
    std::shared_ptr<const FrfPlan> streams;
    std::shared_ptr<const MultisinePlan> multisine;
    double durationS() const;
};

/// The plan of an FRF request on an axis with these parameter values and clock: amplitude from % of the
/// rated torque (motor.rated_current × motor.torque_constant), settle and measure times from the request
/// or the velocity loop's dynamics (loopTimingFromParameters), voltage limit drive.max_voltage.
/// The drive's own amplitude limits are not checked here (the drive checks them before it plans).
Result<FrfRequestPlan> planFrfRequest(const TestRequest& request, const model::ParameterValues& values,
                                      const AxisClock& clock);

/// The FRF of a completed trace of that plan (evaluateFrfTrace or evaluateMultisineTrace).
Result<FrfMeasurement> evaluateFrfRequestTrace(const FrfRequestPlan& plan, const model::Capture& trace);

} // namespace axistune::device

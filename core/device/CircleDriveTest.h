// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The circle test through the drive seam (TestType::Circle; docs/ballbar.md "Circle tests through the
// drive"): the two axes of a plane position to the start point, dwell and run the circle of core/sim
// CirclePath together. The request's checks are shared by the embedded drive (its own limits) and
// axistune-simdrive (the server's SafetyLimits), so both refuse the same requests with the same words.
// The client turns the trace into a ball-bar trace with sim::ballBarFromCircleTrace.

#include "core/device/Drive.h"
#include "core/device/SimulatedDriveLimits.h"
#include "core/model/Result.h"
#include "core/sim/CircleTest.h"

#include <numbers>

namespace axistune::sim {
class AxisSimulator;
}

namespace axistune::device {

inline constexpr double kCirclePositioningSpeedMPerS = 0.05;  ///< default speed to the start point (3000 mm/min)
inline constexpr double kCirclePositioningAccelMPerS2 = 0.5;  ///< default acceleration of that move
inline constexpr double kCircleMaxDurationS = 600.0;          ///< positioning, dwell and circle together

/// Limits a circle must respect; the embedded drive uses the defaults (those of axistune-simdrive).
struct CircleLimits {
    double travelWindowM = kTravelWindowM;          ///< |position| of either axis, programmed path and start point
    double maxMotorSpeedRadS = kMaxMotorSpeedRadS;  ///< feed and positioning speed at the motor
};

/// The circle options of a Circle request (data arc, lead arcs, dwell = CircleTest::dwellS; no geometric errors).
sim::CircleTestOptions circleOptionsOf(const TestRequest& request);
/// The Circle test request of a circle (the inverse of circleOptionsOf; the seed and the geometric errors of
/// the options are the simulator's, not the drive's, and are not carried).
TestRequest circleRequestOf(const sim::CircleTestOptions& circle);

/// Positioning speed and acceleration of a Circle request (positioningMPerS, positioningMPerS2; the defaults when 0).
double circlePositioningSpeed(const TestRequest& request);
double circlePositioningAccel(const TestRequest& request);

/// Checks a circle request on the two axes of the plane before any motion: both axes linear and
/// distinct with the same loop periods, the path valid, the circle and the way to its start point
/// inside the travel window, feed and positioning speed within the motor speed limit, the whole test
/// not longer than kCircleMaxDurationS. OutOfRange / BadInput with a message that names axis and value.
Status checkCircleRequest(const TestRequest& request, const sim::AxisSimulator& first, const sim::AxisSimulator& second,
                          const CircleLimits& limits = {});

}  // namespace axistune::device

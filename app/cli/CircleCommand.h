// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The simulated ball-bar circle test of the CLI, shared by `circle` and `capture --test circle`.

#include "core/device/Drive.h"
#include "core/model/Capture.h"
#include "core/model/Result.h"
#include "core/sim/CircleTest.h"

#include <cstdint>
#include <string>
#include <vector>

namespace axistune::cli {

struct CircleCliOptions {
    std::string connect = "sim:vmc";
    std::string plane = "XY";
    double radiusMm = 50.0;
    double feedMmMin = 1000.0;
    std::string direction = "ccw";
    double centerXMm = 0.0, centerYMm = 0.0;
    double squarenessUmPerM = 0.0, scaleXPpm = 0.0, scaleYPpm = 0.0;
    double leadArcDeg = 90.0, startDeg = 45.0;
    std::vector<std::string> sets;
    std::uint64_t seed = 1;
    std::string out, servoOutX, servoOutY;
};

/// The simulator's circle options of the CLI options (plane, radius, feed, centre, arcs, injected errors).
sim::CircleTestOptions circleOptions(const CircleCliOptions& o);

/// Runs the circle test and writes the ball-bar CSV (and servo traces); returns the exit code.
int runCircle(const CircleCliOptions& o);

/// A circle measured through a drive: its two-axis trace and the ball-bar reading of it.
struct DriveCircle {
    model::Capture trace;
    sim::CircleTestResult result;
};

/// One Circle test of the drive (start, poll to the end, read the trace, evaluate it). A fault gives
/// ErrorCode::Safety, an abort Aborted, each with the drive's reason.
Result<DriveCircle> measureCircleOnDrive(device::Drive& drive, const sim::CircleTestOptions& circle);

}  // namespace axistune::cli

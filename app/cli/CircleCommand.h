// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The simulated ball-bar circle test of the CLI, shared by `circle` and `capture --test circle`.

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

/// Runs the circle test and writes the ball-bar CSV (and servo traces); returns the exit code.
int runCircle(const CircleCliOptions& o);

}  // namespace axistune::cli

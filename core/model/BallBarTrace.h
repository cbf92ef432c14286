// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A ball-bar trace in SI: radial deviation against angle with the test's metadata. Read and written
// by core/io/BallBarCsv.h, produced by the simulated circle test (core/sim/CircleTest.h).

#include "core/model/Metadata.h"

#include <optional>
#include <string>
#include <vector>

namespace axistune::model {

enum class CircleDirection { Ccw, Cw };

struct BallBarTrace {
    std::string source;     ///< file name used in messages
    double radiusM = 0.0;   ///< nominal radius
    double feedMPerS = 0.0; ///< programmed feed
    CircleDirection direction = CircleDirection::Ccw;
    std::string plane = "XY"; ///< two axis letters: first = "x" role, second = "y" role
    double centerXM = 0.0;    ///< circle centre, machine coordinates
    double centerYM = 0.0;
    std::optional<double> dTxNm;                 ///< reversal torque change of the first axis (p-p)
    std::optional<double> dTyNm;                 ///< reversal torque change of the second axis (p-p)
    std::vector<double> angleRad;                ///< as in the file (unwrapped, monotonic)
    std::vector<double> deviationM;              ///< measured minus nominal radius
    Metadata metadata;                           ///< every metadata line (a file's text kept byte for byte)

    std::size_t size() const { return angleRad.size(); }
    /// +1 for counter-clockwise travel, -1 for clockwise.
    double directionSign() const { return direction == CircleDirection::Ccw ? 1.0 : -1.0; }
};

}  // namespace axistune::model

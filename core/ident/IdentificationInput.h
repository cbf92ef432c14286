// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// From a capture (core/model/Capture.h, read by core/io/CaptureCsv) to the records of
// MotionIdentification: columns by name, the sample period from a jittery time column, the axis kind
// from the position unit. Shared by `axistune-cli identify` and the GUI's identification dialog.

#include "core/ident/MotionIdentification.h"
#include "core/model/Capture.h"
#include "core/model/Result.h"

#include <string>

namespace axistune::ident {

/// Default tolerance of the time stamps: every step within 0.1 % of the median step.
inline constexpr double kDefaultTimeTolerance = 1e-3;

struct CaptureColumns {
    std::string time = "t_s"; ///< ignored when fsHz > 0
    double fsHz = 0.0;        ///< overrides the time column
    double timeTolerance = kDefaultTimeTolerance;
    std::string position, force, velocity; ///< velocity optional
    double forceScale = 1.0;               ///< force units per unit of the force column
    std::string reference, extra;          ///< validation only; extra optional
};

/// "m" → Linear, "rad" → Rotary; empty: from the position column's suffix "_m" / "_rad".
/// Errors name the column and what to give.
Result<AxisMotion> axisMotionFor(const std::string& positionUnit, const std::string& positionColumn);

/// A column's samples; NotFound naming the source, the column and the columns there are.
Result<std::vector<double>> captureColumn(const model::Capture& cap, const std::string& src, const std::string& name);
/// 1/fsHz, or the uniform period of the time column (errors name the source and the column).
Result<double> capturePeriod(const model::Capture& cap, const std::string& src, const CaptureColumns& cols);

Result<MotionRecord> motionRecordFromCapture(const model::Capture& cap, const std::string& src,
                                             const CaptureColumns& cols);
Result<ValidationRecord> validationRecordFromCapture(const model::Capture& cap, const std::string& src,
                                                     const CaptureColumns& cols);

} // namespace axistune::ident

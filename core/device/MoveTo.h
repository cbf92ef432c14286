// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Moving an axis to an absolute position through the drive seam (issue 18 item 4; docs/drive-seam.md "Moving to
// a position"): a short hold test reads where the axis stands (the last sample of its position_cmd_* channel),
// then a jog by the difference. The target must lie within the drive's travel window; a drive without a jog or
// hold test, with jog distances in command units (hal:) or without a finite travel window cannot be positioned
// this way. Used by `autotune --positions` and `capture --at`.

#include "core/device/Drive.h"
#include "core/device/TestRunner.h"
#include "core/model/Result.h"

#include <string>

namespace axistune::device {

/// The jog speed of moveAxisTo unless MoveToOptions::velocity is set: 0.5 m/s (linear) or 2 rad/s (rotary).
inline constexpr double kMoveToSpeedLinear = 0.5;
inline constexpr double kMoveToSpeedRotary = 2.0;

struct MoveToOptions {
    double velocity = 0.0;     ///< [m/s or rad/s]; 0: kMoveToSpeedLinear or kMoveToSpeedRotary (the drive refuses what
                               ///< its speed limit forbids)
    double acceleration = 0.0; ///< [m/s² or rad/s²]; 0: 2 m/s² or 20 rad/s²
    double dwellS = 0.05;      ///< jog dwell before and after (the axis settles at the target)
};

struct MoveToResult {
    double from = 0.0;        ///< position found [m or rad]
    double to = 0.0;          ///< position command at the end [m or rad]
    double motionTimeS = 0.0; ///< machine time of the hold and the jog
    bool linear = true;       ///< axis units m (else rad)
};

/// Why `drive` cannot position `axis` (BadInput naming what is missing), or success.
Status checkCanMoveTo(Drive& drive, const std::string& axis);

/// The drive's travel window of `axis` [m or rad] (finite and > 0), or the reason it has none.
Result<double> travelWindow(Drive& drive, const std::string& axis);

/// Where `axis` stands: a 10 ms hold, the last sample of its position_cmd_* channel (from = to = that position).
Result<MoveToResult> findPosition(Drive& drive, const std::string& axis, const RunOptions& run = {});

/// Moves `axis` to `target`. Errors: checkCanMoveTo's, a target outside the travel window (OutOfRange, naming both),
/// the drive's refusals and errors of the tests (runTest's).
Result<MoveToResult> moveAxisTo(Drive& drive, const std::string& axis, double target, const MoveToOptions& options = {},
                                const RunOptions& run = {});

} // namespace axistune::device

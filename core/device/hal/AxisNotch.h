// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The HAL side of a position PID the NC closes, reached from a Drive (docs/linuxcnc.md "Notches"): the HAL session
// and the `pid` of an axis of a hal: or linuxcnc: drive, and AxisTune's biquad notch on it (HalAxis.h insertNotch,
// removeNotch). Used by pid-tune (CLI) and the wizards through core/autotune/PidTune.h.

#include "core/device/Drive.h"
#include "core/device/hal/HalAxis.h"
#include "core/model/Result.h"

#include <string>

namespace axistune::device::hal {

struct DriveHalAxis {
    HalSessionOptions session;
    HalAxis axis;
};

/// The HAL session (halSessionFromEnvironment) and the axis's pid: hal: names the pid, linuxcnc: maps its axis name
/// to the joint's pid. BadInput for a drive of another backend.
Result<DriveHalAxis> halAxisOf(Drive& drive, const std::string& axis);

/// Inserts (or retunes) AxisTune's notch after the axis's pid (insertNotch's refusals).
Status insertAxisNotch(Drive& drive, const std::string& axis, double f0Hz, double q);

/// Removes AxisTune's notch from the drive's HAL session (nothing to do when there is none).
Status removeAxisNotch(Drive& drive, const std::string& axis);

} // namespace axistune::device::hal

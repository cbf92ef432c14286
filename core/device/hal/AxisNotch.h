// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// AxisTune's biquad notch on an axis of a hal: or linuxcnc: drive (docs/linuxcnc.md "Notches"; HalAxis.h insertNotch,
// removeNotch), reached from a Drive: used by pid-tune (CLI) and the wizards through core/autotune/PidTune.h. This
// header keeps HAL's own headers (which use the name `signals`) out of the GUI's.

#include "core/device/Drive.h"
#include "core/model/Result.h"

#include <string>

namespace axistune::device::hal {

/// Inserts (or retunes) AxisTune's notch after the axis's pid (insertNotch's refusals).
Status insertAxisNotch(Drive& drive, const std::string& axis, double f0Hz, double q);

/// Removes AxisTune's notch from the drive's HAL session (nothing to do when there is none).
Status removeAxisNotch(Drive& drive, const std::string& axis);

} // namespace axistune::device::hal

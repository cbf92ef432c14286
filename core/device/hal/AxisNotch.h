// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// AxisTune's biquad notch on an axis of a hal: or linuxcnc: drive (docs/linuxcnc.md "Notches"; HalAxis.h insertNotch,
// removeNotch), reached from a Drive: used by pid-tune (CLI) and the wizards through core/autotune/PidTune.h. This
// header keeps HAL's own headers (which use the name `signals`) out of the GUI's.

#include "core/device/Drive.h"
#include "core/model/Result.h"

#include <optional>
#include <string>

namespace axistune::device::hal {

/// AxisTune's notch as the component holds it.
struct AxisNotch {
    double f0Hz = 0.0;
    double q = 0.0;
    friend bool operator==(const AxisNotch&, const AxisNotch&) = default;
};

/// AxisTune's notch after the axis's pid as it runs now; none when there is none, when its input is linked to no pid
/// (a leftover in no loop), or when the drive is not a HAL session (no notch of AxisTune's can run there). Refused
/// when the notch runs after another pid: LinuxCNC loads it once per HAL session, and a tune of this axis would move
/// it off the other one.
Result<std::optional<AxisNotch>> readAxisNotch(Drive& drive, const std::string& axis);

/// Inserts (or retunes) AxisTune's notch after the axis's pid (insertNotch's refusals; refused as readAxisNotch when
/// the notch runs after another pid).
Status insertAxisNotch(Drive& drive, const std::string& axis, double f0Hz, double q);

/// Removes AxisTune's notch from after the axis's pid (nothing to do when there is none; refused as readAxisNotch
/// when it runs after another pid).
Status removeAxisNotch(Drive& drive, const std::string& axis);

/// Puts the axis's notch back as it was before a tune: `before` inserted with its f0 and Q, or, without one, the
/// notch removed.
Status restoreAxisNotch(Drive& drive, const std::string& axis, const std::optional<AxisNotch>& before);

} // namespace axistune::device::hal

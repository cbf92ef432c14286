// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/hal/AxisNotch.h"

#include "core/device/hal/HalDrive.h"
#include "core/device/hal/LinuxCncDrive.h"

namespace axistune::device::hal {

Result<DriveHalAxis> halAxisOf(Drive& drive, const std::string& axis)
{
    std::string pid = axis;
    if (auto* lc = dynamic_cast<LinuxCncDrive*>(&drive)) {
        auto p = lc->pidOf(axis);
        if (!p)
            return p.error();
        pid = *p;
    } else if (!dynamic_cast<HalDrive*>(&drive)) {
        return makeError(ErrorCode::BadInput,
                         "axis " + axis + " is not a PID of a HAL session (hal:, linuxcnc:): no biquad notch there");
    }
    auto session = halSessionFromEnvironment();
    if (!session)
        return session.error();
    auto a = discoverAxis(*session, pid);
    if (!a)
        return a.error();
    return DriveHalAxis{std::move(session).value(), std::move(a).value()};
}

namespace {

/// The notch after the axis's pid; none when there is none or its input is linked to no pid (a leftover that is in
/// no loop: inserting or removing the axis's notch clears it). Refused when it runs after another pid.
Result<std::optional<AxisNotch>> notchOf(const DriveHalAxis& a)
{
    auto n = readNotch(a.session);
    if (!n)
        return n.error();
    if (!*n || (*n)->pidOutput.empty())
        return std::optional<AxisNotch>();
    const std::string mine = a.axis.pid + ".output";
    if ((*n)->pidOutput != mine)
        return makeError(ErrorCode::BadInput, "AxisTune's notch runs after " + (*n)->pidOutput + ", not after " + mine +
                                                  ": LinuxCNC loads it once per HAL session; remove it there first "
                                                  "(pid-tune --remove-notch on that axis)");
    return std::optional<AxisNotch>(AxisNotch{(*n)->f0Hz, (*n)->q});
}

} // namespace

Result<std::optional<AxisNotch>> readAxisNotch(Drive& drive, const std::string& axis)
{
    if (!dynamic_cast<HalDrive*>(&drive) && !dynamic_cast<LinuxCncDrive*>(&drive))
        return std::optional<AxisNotch>();
    auto a = halAxisOf(drive, axis);
    if (!a)
        return a.error();
    return notchOf(*a);
}

Status insertAxisNotch(Drive& drive, const std::string& axis, double f0Hz, double q)
{
    auto a = halAxisOf(drive, axis);
    if (!a)
        return a.error();
    if (auto n = notchOf(*a); !n)
        return n.error();
    return insertNotch(a->session, a->axis, f0Hz, q);
}

Status removeAxisNotch(Drive& drive, const std::string& axis)
{
    auto a = halAxisOf(drive, axis);
    if (!a)
        return a.error();
    if (auto n = notchOf(*a); !n)
        return n.error();
    return removeNotch(a->session); // nothing to do when there is none
}

Status restoreAxisNotch(Drive& drive, const std::string& axis, const std::optional<AxisNotch>& before)
{
    return before ? insertAxisNotch(drive, axis, before->f0Hz, before->q) : removeAxisNotch(drive, axis);
}

} // namespace axistune::device::hal

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

Status insertAxisNotch(Drive& drive, const std::string& axis, double f0Hz, double q)
{
    auto a = halAxisOf(drive, axis);
    if (!a)
        return a.error();
    return insertNotch(a->session, a->axis, f0Hz, q);
}

Status removeAxisNotch(Drive& drive, const std::string& axis)
{
    auto a = halAxisOf(drive, axis);
    if (!a)
        return a.error();
    return removeNotch(a->session);
}

} // namespace axistune::device::hal

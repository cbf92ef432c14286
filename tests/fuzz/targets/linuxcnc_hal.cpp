// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: linuxcnc/testbed/*.hal
// The HAL-file reader of a LinuxCNC configuration (core/device/hal/LinuxCncConfig.h addHalText,
// docs/linuxcnc.md "Configurations"): refused with the file named, or pid instances with distinct non-empty
// names, gains whose HAL line lies inside the text, each fed by an INI key or a literal.
#include "core/device/hal/LinuxCncConfig.h"

#include <algorithm>
#include <set>

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(linuxcnc_hal)
{
    device::hal::LinuxCncConfig cfg;
    const auto added = device::hal::addHalText(cfg, fuzz::kSource, input, "XYZ");
    if (!added.ok()) {
        fuzz::requireRefusal(added.error());
        return;
    }
    const auto lines = static_cast<std::size_t>(std::count(input.begin(), input.end(), '\n')) + 1;
    std::set<std::string> names;
    for (const auto& pid : cfg.pids) {
        fuzz::require(!pid.name.empty(), "a pid with an empty name");
        fuzz::require(names.insert(pid.name).second, "pid " + pid.name + " listed twice");
        fuzz::require(pid.joint >= -1 && pid.joint < 64, "joint outside -1..63");
        fuzz::require(pid.axisLetter.size() <= 1, "axis letter longer than one character");
        for (const auto& [gain, source] : pid.gains) {
            fuzz::require(!gain.empty(), "an empty gain name");
            fuzz::require(source.pin == pid.name + "." + gain,
                          "gain pin " + source.pin + " is not " + pid.name + "." + gain);
            fuzz::require(source.halFile == fuzz::kSource, "gain source names another file");
            fuzz::require(source.halLine >= 1 && source.halLine <= lines, "gain line outside the text");
            fuzz::require(source.key.empty() == source.section.empty(),
                          "INI section without key or key without section");
            fuzz::require(!source.section.empty() || !source.literal.empty(),
                          "gain fed by neither INI key nor literal");
        }
    }
}

// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: linuxcnc/testbed/*.ini
// The LinuxCNC INI reader (core/device/hal/LinuxCncConfig.h, docs/linuxcnc.md): refused with the file
// named, or entries whose line numbers lie inside the text and whose first value per key is found again.
#include "core/device/hal/LinuxCncConfig.h"

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(linuxcnc_ini)
{
    auto ini = device::hal::parseIni(fuzz::kSource, input);
    if (!ini) {
        fuzz::requireRefusal(ini.error());
        return;
    }
    for (const auto& e : ini->entries) {
        fuzz::require(e.line >= 1, "entry line number 0");
        fuzz::require(e.valueBegin <= e.valueEnd && e.valueEnd <= input.size(), "value offsets outside the text");
        fuzz::require(ini->find(e.section, e.key) != nullptr, "an entry is not found again by section and key");
    }
}

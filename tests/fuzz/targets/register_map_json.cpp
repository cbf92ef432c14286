// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/drives/*.json
// Drive register map JSON: refused, or a map whose fields lie inside the register space.
#include "core/device/RegisterMap.h"

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(register_map_json)
{
    fuzz::expect(device::parseRegisterMap(input, fuzz::kSource), [](const device::RegisterMap&) {});
}

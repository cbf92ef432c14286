// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/machines/*.json
// Machine preset JSON: refused, or axes with finite parameters and positive modal data.
#include "core/sim/MachineDefinition.h"

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(machine_json)
{
    const auto j = fuzz::parsedJson(input);
    if (!j)
        return;
    fuzz::expect(sim::machineDefinitionFromJson(*j, fuzz::kSource), [](const sim::MachineDefinition& d) {
        fuzz::require(!d.axes.empty(), "no axes");
        for (const auto& a : d.axes) {
            for (const auto& [k, v] : a.values)
                fuzz::requireFinite(v, a.name + " " + k);
            for (const auto& m : a.modes)
                fuzz::require(std::isnormal(m.frequencyHz) && m.frequencyHz > 0 && m.modalInertiaKgm2 > 0,
                              "mode not positive");
        }
    });
}

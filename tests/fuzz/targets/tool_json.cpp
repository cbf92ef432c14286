// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/samples/tool-*.json
// Tool modes JSON: refused, or positive finite modal masses, stiffnesses and non-negative damping.
#include "core/machining/MachiningJson.h"

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(tool_json)
{
    fuzz::expect(machining::parseToolJson(input, fuzz::kSource), [](const machining::ToolModes& t) {
        for (const auto* list : {&t.modesX, &t.modesY})
            for (const auto& m : *list) {
                fuzz::require(std::isnormal(m.massKg) && m.massKg > 0, "mass");
                fuzz::require(std::isnormal(m.stiffnessNPerM) && m.stiffnessNPerM > 0, "stiffness");
                fuzz::require(std::isfinite(m.dampingNsPerM) && m.dampingNsPerM >= 0, "damping");
            }
    });
}

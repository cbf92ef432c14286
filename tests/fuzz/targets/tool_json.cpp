// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/samples/tool-*.json
// Tool modes JSON: refused, or finite non-zero modal masses with stiffnesses of the same sign and damping of the
// same sign or zero (all positive, or all negative: a negative-residue mode, docs/machining.md).
#include "core/machining/MachiningJson.h"

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(tool_json)
{
    fuzz::expect(machining::parseToolJson(input, fuzz::kSource), [](const machining::ToolModes& t) {
        for (const auto* list : {&t.modesX, &t.modesY})
            for (const auto& m : *list) {
                fuzz::require(std::isnormal(m.massKg), "mass");
                const double sign = m.massKg > 0 ? 1.0 : -1.0;
                fuzz::require(std::isnormal(m.stiffnessNPerM) && sign * m.stiffnessNPerM > 0, "stiffness");
                fuzz::require(std::isfinite(m.dampingNsPerM) && sign * m.dampingNsPerM >= 0, "damping");
            }
    });
}

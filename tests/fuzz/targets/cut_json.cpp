// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/samples/cut-*.json
// Cutting-condition JSON: refused, or conditions that pass validateCut.
#include "core/machining/MachiningJson.h"

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(cut_json)
{
    fuzz::expect(machining::parseCutJson(input, fuzz::kSource), [](const machining::CuttingConditions& c) {
        fuzz::require(machining::validateCut(c).ok(), "accepted conditions fail validateCut");
        fuzz::requireFinite(c.ktNPerM2, "K_t");
        fuzz::requireFinite(c.krNPerM2, "K_r");
    });
}

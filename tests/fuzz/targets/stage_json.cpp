// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/samples/stage.json
// Stage JSON: refused, or a stage whose two-mass model is finite and positive.
#include "core/machining/StageJson.h"
#include "core/machining/VibrationModeChatter.h"

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(stage_json)
{
    fuzz::expect(machining::parseStageJson(input, fuzz::kSource), [](const machining::StageDescription& d) {
        const auto tm = d.twoMass();
        fuzz::require(std::isnormal(tm.motorMassKg) && tm.motorMassKg > 0, "motor mass");
        fuzz::require(std::isnormal(tm.tableMassKg) && tm.tableMassKg > 0, "table mass");
        fuzz::requireFinite(tm.stiffnessNPerM, "stiffness");
        fuzz::requireFinite(tm.dampingNsPerM, "damping");
    });
}

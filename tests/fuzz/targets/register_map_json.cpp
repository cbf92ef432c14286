// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/drives/*.json
// Drive register map JSON: refused, or a map whose fields lie inside the register space and whose test fields
// carry known quantities: a multisine FRF and a circle go through its registers (TestRegisterCodec.h) and back, or
// are refused with a reason, never a crash.
#include "core/device/RegisterMap.h"
#include "core/device/TestRegisterCodec.h"

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(register_map_json)
{
    fuzz::expect(device::parseRegisterMap(input, fuzz::kSource), [](const device::RegisterMap& map) {
        device::TestRequest frf;
        frf.axis = "X";
        auto& frfTest = frf.test.emplace<device::FrfTest>();
        frfTest.method = device::FrfMethod::Multisine;
        frfTest.multisineBands = {{10.0, 100.0, 5.0}, {100.0, 1000.0, 10.0}};
        device::TestRequest circle;
        circle.axis = "X";
        auto& circleTest = circle.test.emplace<device::CircleTest>();
        circleTest.secondAxis = "Y";
        circleTest.radiusM = 0.01;
        const std::vector<std::string> axes{"X", "Y"};
        for (const auto& r : {frf, circle}) {
            auto values = device::testValuesOf(r, map, [](const std::string& a) -> Result<int> { return a == "Y"; });
            if (!values)
                continue; // the map lacks a register the request needs: refused by name
            auto writes = device::encodeTestRegisters(*values, map);
            if (!writes)
                continue;
            for (const auto& w : *writes)
                fuzz::require(!w.words.empty() && w.words.size() <= 123 && w.address >= 0 &&
                                  w.address + static_cast<int>(w.words.size()) <= 65536,
                              "a test register write outside the register space or over 123 registers");
            auto back = device::testRequestOf(*values, map, "X", axes);
            if (back)
                fuzz::require(back->type() == r.type(), "the test type did not come back");
        }
    });
}

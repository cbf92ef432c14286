// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: tests/data/ident/*.json resources/samples/identif*.json
// The JSON files of identification: the controller file of `identify --controller` and the result file
// read back by the GUI and `readIdentifiedModelFile`. Refused with the source named, or a controller
// with finite positive numbers and a delay in 0..100, a model with a positive finite inertia.
#include "core/ident/IdentificationJson.h"

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(identify_json)
{
    auto j = fuzz::parsedJson(input);
    if (!j)
        return;
    fuzz::expect(ident::controllerFromJson(*j, fuzz::kSource), [](const ident::PositionController& c) {
        fuzz::require(std::isfinite(c.kpPerS) && std::isfinite(c.kv), "controller gains not finite");
        fuzz::require(c.saturation > 0.0 && std::isfinite(c.saturation), "saturation not positive and finite");
        fuzz::require(c.forceScale > 0.0 && std::isfinite(c.forceScale), "force scale not positive and finite");
        fuzz::require(c.delaySamples >= 0 && c.delaySamples <= 100, "delay outside 0..100");
    });
    fuzz::expect(ident::identifiedModelFromJson(*j, fuzz::kSource), [](const ident::IdentifiedModel& m) {
        fuzz::require(m.model.inertia > 0.0 && std::isfinite(m.model.inertia), "inertia not positive and finite");
        fuzz::require(m.model.viscousPositive >= 0.0 && m.model.coulombPositive >= 0.0, "negative friction");
        fuzz::requireFinite(m.model.offset, "offset");
    });
}

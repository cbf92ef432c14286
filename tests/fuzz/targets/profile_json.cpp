// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/samples/*profile*.json tests/data/nc/vmc.json.expected
// Machine profile JSON (profile import): refused, or finite parameters and a canonical text that reads
// back to the same profile.
#include "core/io/Profile.h"

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(profile_json)
{
    const auto j = fuzz::parsedJson(input);
    if (!j)
        return;
    fuzz::expect(io::profileFromJson(*j, fuzz::kSource), [](const io::MachineProfile& p) {
        for (const auto& a : p.axes)
            for (const auto& [k, v] : a.parameters)
                fuzz::requireFinite(v, a.name + " " + k);
        const std::string text = io::profileToText(p);
        auto j2 = model::parseJsonText(text, fuzz::kSource);
        fuzz::require(j2.ok(), "canonical text is not valid JSON");
        auto again = io::profileFromJson(*j2, fuzz::kSource);
        fuzz::require(again.ok(), "canonical text does not read back: " + (again.ok() ? "" : again.error().detail));
        fuzz::require(io::profileToText(*again) == text, "round trip changed the profile");
    });
}

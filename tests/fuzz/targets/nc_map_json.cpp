// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/nc/*.json
// NC map JSON and an export of a two-axis profile through it: refused, or a file that holds the VERIFY
// notice and every mapped value (or an export refusal naming the map).
#include "core/io/NcExport.h"

#include "core/io/Profile.h"
#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(nc_map_json)
{
    const auto j = fuzz::parsedJson(input);
    if (!j)
        return;
    fuzz::expect(io::ncMapFromJson(*j, fuzz::kSource), [](const io::NcMap& map) {
        io::MachineProfile p;
        p.name = "fuzz";
        p.axes = {{"X", {{"position.kp", 30.0}, {"filter.notch1.center", 812.5}}, {}},
                  {"Y", {{"position.kp", 25.0}, {"lostmotion.backlash", 4e-6}}, {}}};
        auto out = io::exportNc(p, map);
        if (!out) {
            fuzz::requireRefusal(out.error());
            return;
        }
        fuzz::require(out->text.find(map.verify) != std::string::npos || map.verify.empty(),
                      "the VERIFY notice is missing from the file");
    });
}

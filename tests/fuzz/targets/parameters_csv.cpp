// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: tests/data/nc/vmc.csv.expected
// Flat parameter CSV (import --format csv): refused, or finite parameters that write and read back.
#include "core/io/Profile.h"

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(parameters_csv)
{
    fuzz::expect(io::parametersFromCsv(input, fuzz::kSource), [](const io::MachineProfile& p) {
        for (const auto& a : p.axes)
            for (const auto& [k, v] : a.parameters)
                fuzz::requireFinite(v, a.name + " " + k);
        auto again = io::parametersFromCsv(io::parametersToCsv(p), fuzz::kSource);
        fuzz::require(again.ok(), "written parameters do not read back: " + (again.ok() ? "" : again.error().detail));
    });
}

// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/samples/halscope.log
// halscope "Save Log" reader (io::readHalscope): refused with the source named, or channels of one
// length with finite values and a positive, finite sample rate.
#include "core/io/TableImport.h"

#include <sstream>

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(halscope_log)
{
    std::istringstream in(input);
    fuzz::expect(io::readHalscope(in, fuzz::kSource), [](const model::Capture& c) {
        for (const auto& ch : c.channels) {
            fuzz::require(ch.data.size() == c.size(), "channels of different lengths");
            for (double v : ch.data)
                fuzz::requireFinite(v, "value of " + ch.name);
        }
        const auto fs = c.metadata.number("fs_Hz");
        fuzz::require(fs.ok() && *fs > 0.0, "an accepted log without a positive fs_Hz");
    });
}

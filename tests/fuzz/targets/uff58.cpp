// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/samples/uff58-frf.unv tests/data/uff/*.unv
// Universal file dataset 58 reader (io::readUff58): refused with the source named, or records whose
// abscissa and ordinate have one length and hold only finite values.
#include "core/io/Uff58.h"

#include <sstream>

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(uff58)
{
    std::istringstream in(input);
    fuzz::expect(io::readUff58(in, fuzz::kSource), [](const std::vector<io::Uff58Record>& records) {
        for (const auto& r : records) {
            fuzz::require(r.x.size() == r.y.size(), "abscissa and ordinate of different lengths");
            for (std::size_t i = 0; i < r.x.size(); ++i) {
                fuzz::requireFinite(r.x[i], "abscissa");
                fuzz::requireFinite(r.y[i].real(), "ordinate (real)");
                fuzz::requireFinite(r.y[i].imag(), "ordinate (imaginary)");
            }
        }
    });
}

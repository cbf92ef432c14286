// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/samples/frf-*.csv
// FRF CSV: refused, or increasing finite frequencies, finite values, and a file the writer writes and
// the reader reads back to the same points.
#include "core/io/FrfCsv.h"

#include <sstream>

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(frf_csv)
{
    std::istringstream in(input);
    fuzz::expect(io::readFrfCsv(in, fuzz::kSource), [](const dsp::FrequencyResponse& f) {
        for (std::size_t i = 0; i < f.size(); ++i) {
            fuzz::requireFinite(f.freqHz[i], "frequency");
            fuzz::requireFinite(f.h[i].real(), "re");
            fuzz::requireFinite(f.h[i].imag(), "im");
            if (i > 0)
                fuzz::require(f.freqHz[i] > f.freqHz[i - 1], "frequencies not increasing");
        }
        std::ostringstream out;
        auto st = io::writeFrfCsv(out, f);
        fuzz::require(st.ok(), "an accepted FRF cannot be written: " + (st.ok() ? "" : st.error().detail));
        std::istringstream back(out.str());
        auto again = io::readFrfCsv(back, fuzz::kSource);
        fuzz::require(again.ok(), "the written FRF does not read back: " + (again.ok() ? "" : again.error().detail));
        fuzz::require(again->size() == f.size(), "round trip changed the point count");
    });
}

// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/samples/capture-*.csv tests/data/welch/input.csv
// Capture CSV and the Welch FRF of `frf --in` on its second and third columns: the capture is refused
// with the file named, or every sample is finite and every channel as long as the others; the FRF is
// refused or holds only finite values.
#include "core/dsp/Welch.h"
#include "core/io/CaptureCsv.h"

#include <sstream>

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(capture_csv)
{
    std::istringstream in(input);
    fuzz::expect(io::readCaptureCsv(in, fuzz::kSource), [](const model::Capture& c) {
        for (const auto& ch : c.channels) {
            fuzz::require(ch.data.size() == c.size(), "channel '" + ch.name + "' length differs");
            for (double v : ch.data)
                fuzz::requireFinite(v, "sample of '" + ch.name + "'");
        }
        if (c.channels.size() < 3 || c.size() < 16)
            return;
        dsp::WelchOptions w;
        w.nperseg = 16;
        auto frf = dsp::welchFrf(c.channels[1].data, c.channels[2].data, 1000.0, w, dsp::FrfEstimator::H1);
        if (!frf)
            return;
        for (std::size_t i = 0; i < frf->size(); ++i) {
            fuzz::requireFinite(frf->h[i].real(), "FRF re");
            fuzz::requireFinite(frf->h[i].imag(), "FRF im");
            if (frf->valid[i])
                fuzz::requireFinite(frf->coherence[i], "coherence of a valid point");
        }
    });
}

// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/samples/sweep-*.csv
// Sine-stream CSV and its demodulation to an FRF: refused, or finite samples and a finite FRF.
#include "core/dsp/SineDemodulation.h"
#include "core/io/SweepCsv.h"

#include <sstream>

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(sweep_csv)
{
    std::istringstream in(input);
    auto rec = io::readSweepCsv(in, fuzz::kSource);
    fuzz::expect(rec, [](const dsp::SweepRecording& r) {
        fuzz::requireFinite(r.fsHz, "fs_Hz");
        fuzz::require(r.fsHz > 0.0, "fs_Hz not positive");
        auto frf = dsp::sineStreamFrf(r);
        if (!frf)
            return; // refusals of the demodulation name the frequency, not the file
        for (std::size_t i = 0; i < frf->size(); ++i) {
            fuzz::requireFinite(frf->freqHz[i], "FRF frequency");
            if (frf->valid[i]) {
                fuzz::requireFinite(frf->h[i].real(), "FRF re of a valid point");
                fuzz::requireFinite(frf->h[i].imag(), "FRF im of a valid point");
            }
        }
    });
}

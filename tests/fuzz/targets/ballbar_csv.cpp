// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/samples/ballbar-*.csv tests/data/ballbar/*.csv
// Ball-bar CSV and the run diagnostics: refused, or finite samples; the diagnostics refuse with a reason
// or give finite numbers.
#include "core/io/BallBarCsv.h"
#include "core/tuning/BallBarDiagnostics.h"

#include <sstream>

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(ballbar_csv)
{
    std::istringstream in(input);
    fuzz::expect(io::readBallBarCsv(in, fuzz::kSource), [](const io::BallBarTrace& t) {
        fuzz::require(t.radiusM > 0.0 && std::isnormal(t.radiusM), "radius not positive and normal");
        fuzz::require(t.feedMPerS > 0.0 && std::isnormal(t.feedMPerS), "feed not positive and normal");
        for (std::size_t i = 0; i < t.size(); ++i) {
            fuzz::requireFinite(t.angleRad[i], "angle");
            fuzz::requireFinite(t.deviationM[i], "deviation");
        }
        auto run = tuning::analyzeRun(t);
        if (run) {
            fuzz::requireFinite(run->circularityM, "circularity");
            fuzz::requireFinite(run->residualRmsM, "residual");
            fuzz::requireFinite(run->radiusDeviationM, "radius deviation");
        }
    });
}

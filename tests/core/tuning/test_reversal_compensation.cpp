// SPDX-License-Identifier: GPL-3.0-or-later
// Reversal (quadrant-glitch) compensation tuned on sim:vmc (core/tuning/ReversalCompensation.h).
#include "core/tuning/ReversalCompensation.h"

#include <cstdio>
#include <gtest/gtest.h>

using namespace axistune;
using namespace axistune::tuning;

TEST(ReversalCompensation, Explore)
{
    auto m = sim::loadPreset("vmc");
    ASSERT_TRUE(m.ok());
    sim::CircleTestOptions o;
    auto meas = sim::runCircleTest(*m, o);
    ASSERT_TRUE(meas.ok());
    auto r = tuneReversalCompensation(*m, o, meas->ballbar, meas->dTxNm, meas->dTyNm);
    ASSERT_TRUE(r.ok()) << r.error().detail;
    for (const auto& a : r->axes)
        std::printf("%s a=%g mm/min tau=%g ms meas=%g model=%g pred=%g red=%g evals=%d\n", a.axis.c_str(),
                    a.amplitudeMPerS * 60000, a.timeConstantS * 1e3, a.measuredSpikeM * 1e6, a.modelSpikeM * 1e6,
                    a.predictedSpikeM * 1e6, a.predictedReduction, a.evaluations);
}

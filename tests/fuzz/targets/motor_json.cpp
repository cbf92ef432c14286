// SPDX-License-Identifier: GPL-3.0-or-later
// seeds: resources/samples/motor-*.json
// Motor JSON and the current-loop design on it: refused, or finite gains (the design terminates).
#include "core/tuning/CurrentLoop.h"

#include "tests/fuzz/FuzzTarget.h"

using namespace axistune;

AXISTUNE_FUZZ_TARGET(motor_json)
{
    fuzz::expect(tuning::parseMotorJson(input, fuzz::kSource), [](const tuning::MotorData& m) {
        tuning::CurrentLoopSettings s;
        s.alphaStep = 0.5;  // three α instead of eleven: the same searches, a fuzzing speed of executions per second
        auto d = tuning::designCurrentLoop(m, s);
        if (!d)
            return;
        fuzz::requireFinite(d->gains.kpVPerA, "kp");
        fuzz::requireFinite(d->gains.kiVPerAs, "ki");
        fuzz::requireFinite(d->riseTimeS, "rise time");
    });
}

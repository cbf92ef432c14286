// SPDX-License-Identifier: GPL-3.0-or-later
// Adaptive multisine FRF on the realistic sim:dd-table axis C (friction, quantization and noise on, as
// `axistune-cli capture --connect sim:dd-table` runs it; issue 18 item 2, docs/multisine.md "Adaptive
// measurement"), against the plain multisine of the same first pass. Counters: motion_s (machine time of all
// passes), passes, valid_fraction (lines from 20 Hz to 3.9 kHz valid), mode_Hz (largest valid |T| above
// 2.6 kHz: the 3.3 kHz mode). Wall time is the simulator's. AXISTUNE_BENCH_DUMP=1 prints every pass and the lines
// left invalid with their reason to stderr; AXISTUNE_BENCH_SPACING=HZ sets the line spacing of the first pass
// (default 0: fmin/2 = 10 Hz).
#include "core/device/AdaptiveFrf.h"
#include "core/device/Drive.h"
#include "core/device/TestRunner.h"

#include <benchmark/benchmark.h>
#include <cmath>
#include <cstdio>
#include <cstdlib>

using namespace axistune;
using namespace axistune::device;

namespace {

TestRequest firstPass()
{
    TestRequest r;
    r.axis = "C";
    auto& f = r.test.emplace<FrfTest>();
    f.method = FrfMethod::Multisine;
    f.fminHz = 20.0;
    f.fmaxHz = 3900.0;
    f.amplitudePct = 5.0; // the CLI's default
    if (const char* s = std::getenv("AXISTUNE_BENCH_SPACING"))
        f.multisineSpacingHz = std::atof(s);
    return r;
}

void report(benchmark::State& state, const FrfMeasurement& m, double motionS, std::size_t passes)
{
    std::size_t valid = 0, peak = 0;
    bool havePeak = false;
    for (std::size_t i = 0; i < m.frf.size(); ++i) {
        valid += m.frf.valid[i] ? 1 : 0;
        if (m.frf.valid[i] && m.frf.freqHz[i] > 2600.0 &&
            (!havePeak || std::abs(m.frf.h[i]) > std::abs(m.frf.h[peak]))) {
            peak = i;
            havePeak = true;
        }
    }
    state.counters["motion_s"] = motionS;
    state.counters["passes"] = static_cast<double>(passes);
    state.counters["valid_fraction"] = static_cast<double>(valid) / static_cast<double>(m.frf.size());
    state.counters["mode_Hz"] = havePeak ? m.frf.freqHz[peak] : 0.0;
}

void BM_PlainMultisine(benchmark::State& state)
{
    for (auto _ : state) {
        auto drive = connect({"sim:dd-table", 1});
        if (!drive) {
            state.SkipWithError(drive.error().detail.c_str());
            return;
        }
        auto r = firstPass();
        r.frf().multisinePeriods = static_cast<int>(state.range(0));
        auto run = runTest(**drive, r);
        if (!run || !run->frf) {
            state.SkipWithError("the multisine failed");
            return;
        }
        report(state, *run->frf, run->frf->motionTimeS, 1);
    }
}

void BM_AdaptiveMultisine(benchmark::State& state)
{
    for (auto _ : state) {
        auto drive = connect({"sim:dd-table", 1});
        if (!drive) {
            state.SkipWithError(drive.error().detail.c_str());
            return;
        }
        AdaptiveFrfOptions o;
        o.timeBudgetS = static_cast<double>(state.range(0));
        auto res = runAdaptiveFrf(**drive, firstPass(), o);
        if (!res) {
            state.SkipWithError(res.error().detail.c_str());
            return;
        }
        report(state, res->measurement, res->motionTimeS, res->passes.size());
        if (std::getenv("AXISTUNE_BENCH_DUMP")) {
            for (const auto& p : res->passes)
                std::fprintf(stderr,
                             "pass: lines %zu bands %zu peak %.2f %% periods %d motion %.3f s shaped %d "
                             "voltage %d (peak %.1f V, predicted %.1f V) valid after %zu limited by '%s'\n",
                             p.lines, p.bands, p.peakPct, p.periods, p.motionTimeS, p.shaped ? 1 : 0,
                             p.voltageReached ? 1 : 0, p.voltagePeakV, p.voltagePredictedV, p.validAfter,
                             p.limitedBy.c_str());
            for (const auto& l : res->invalid)
                std::fprintf(stderr, "invalid %.1f Hz %s noise %.4f\n", l.freqHz, invalidReasonName(l.reason),
                             l.relativeNoise);
        }
    }
}

} // namespace

BENCHMARK(BM_PlainMultisine)->Arg(0)->Arg(16)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_AdaptiveMultisine)->Arg(5)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond)->Iterations(1);

BENCHMARK_MAIN();

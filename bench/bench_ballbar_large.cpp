// SPDX-License-Identifier: GPL-3.0-or-later
// A ball-bar file of N rows read and diagnosed (issue 21: a 10^6-row file hung `ballbar` for minutes,
// the cyclic-pitch scan being quadratic in the sample density). The trace: R 100 mm, one CCW turn,
// 4 µm lost-motion steps at the X and Y reversals, a 2 µm cyclic error of 20 mm pitch and a
// deterministic ±0.1 µm ripple, written as CSV text and parsed with readBallBarCsv, then analyzeRun.
// The time must grow about linearly with N. Figures and command: docs/robustness.md.
#include "core/io/BallBarCsv.h"
#include "core/tuning/BallBarDiagnostics.h"

#include <benchmark/benchmark.h>
#include <charconv>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

using namespace axistune;

namespace {

std::string ballBarText(std::size_t n)
{
    std::string s = "# radius_mm=100\n# feed_mm_min=1000\n# direction=ccw\nangle_deg,deviation_um\n";
    s.reserve(n * 30);
    char buf[64];
    for (std::size_t i = 0; i < n; ++i) {
        const double deg = 360.0 * static_cast<double>(i) / static_cast<double>(n);
        const double th = deg * std::numbers::pi / 180.0;
        const double x = 100.0 * std::cos(th); // mm
        double dev = 2.0 * std::sin(x / 20.0 * 2.0 * std::numbers::pi) * std::cos(th);
        dev += (std::sin(th) > 0.0 ? 2.0 : -2.0) * std::abs(std::cos(th)) +
               (std::cos(th) > 0.0 ? 2.0 : -2.0) * std::abs(std::sin(th));
        dev += 0.1 * std::sin(0.37 * static_cast<double>(i));
        auto p = std::to_chars(buf, buf + sizeof buf, deg).ptr;
        *p++ = ',';
        p = std::to_chars(p, buf + sizeof buf, dev).ptr;
        *p++ = '\n';
        s.append(buf, p);
    }
    return s;
}

void BM_BallBarReadAndDiagnose(benchmark::State& state)
{
    const std::string text = ballBarText(static_cast<std::size_t>(state.range(0)));
    double circularity = 0.0;
    for (auto _ : state) {
        std::istringstream in(text);
        auto t = io::readBallBarCsv(in, "bench.csv");
        if (!t) {
            state.SkipWithError(t.error().detail.c_str());
            return;
        }
        auto run = tuning::analyzeRun(*t);
        if (!run) {
            state.SkipWithError(run.error().detail.c_str());
            return;
        }
        circularity = run->circularityM;
        benchmark::DoNotOptimize(circularity);
    }
    state.counters["circularity_um"] = circularity * 1e6;
    state.SetComplexityN(state.range(0));
}

} // namespace

BENCHMARK(BM_BallBarReadAndDiagnose)
    ->Arg(10000)
    ->Arg(100000)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Complexity();

BENCHMARK_MAIN();

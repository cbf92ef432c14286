// SPDX-License-Identifier: GPL-3.0-or-later
// Resonance search of `axistune-cli notch` on dense FRFs (issue 21: 89 s on a 100,000-point FRF, the
// robust baseline refitted over every point's ±1 octave window). A velocity-loop open loop of a
// two-inertia axis (resonance near 400 Hz) sampled at N linearly spaced points from 1 Hz to 2 kHz with
// deterministic ±0.2 dB ripple; the time per search must grow about linearly with N.
// Figures and command: docs/robustness.md.
#include "core/dsp/FrequencyResponse.h"
#include "core/tuning/Resonance.h"

#include <benchmark/benchmark.h>
#include <cmath>
#include <complex>
#include <numbers>

using namespace axistune;

namespace {

dsp::FrequencyResponse denseFrf(std::size_t n)
{
    dsp::FrequencyResponse f;
    const double wr = 2.0 * std::numbers::pi * 400.0, wa = 2.0 * std::numbers::pi * 250.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double hz = 1.0 + 1999.0 * static_cast<double>(i) / static_cast<double>(n - 1);
        const std::complex<double> s(0.0, 2.0 * std::numbers::pi * hz);
        // K (s^2 + 2ζa wa s + wa^2) / (s^2 (s^2 + 2ζr wr s + wr^2)) · wr^2 / wa^2, ζ = 0.03 / 0.05.
        std::complex<double> h = 2.0e5 * (s * s + 2.0 * 0.05 * wa * s + wa * wa) /
                                 (s * s * (s * s + 2.0 * 0.03 * wr * s + wr * wr)) * (wr * wr / (wa * wa));
        h *= std::pow(10.0, 0.01 * std::sin(0.7 * static_cast<double>(i))); // ±0.2 dB, not random
        f.push(hz, h, 0.99, true);
    }
    return f;
}

void BM_FindResonances(benchmark::State& state)
{
    const auto frf = denseFrf(static_cast<std::size_t>(state.range(0)));
    std::size_t found = 0;
    for (auto _ : state) {
        auto r = tuning::findResonances(frf, {});
        if (!r) {
            state.SkipWithError(r.error().detail.c_str());
            return;
        }
        found = r->size();
        benchmark::DoNotOptimize(found);
    }
    state.counters["resonances"] = static_cast<double>(found);
    state.SetComplexityN(state.range(0));
}

} // namespace

BENCHMARK(BM_FindResonances)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->Complexity();

BENCHMARK_MAIN();

// SPDX-License-Identifier: GPL-3.0-or-later
// Welch H1 + coherence on 2^21 samples (fs 4 kHz, nperseg 4096, noverlap 2048, periodic Hann).
// Data: the capture written by `bench/welch_scipy.py --write FILE`, named by the environment variable
// AXISTUNE_WELCH_CSV (so that scipy and this benchmark see identical samples); without it, a
// deterministic pseudo-random signal of the same length. See docs/frequency-response.md.
#include "core/dsp/Welch.h"
#include "core/io/CaptureCsv.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

struct Data {
    std::vector<double> x, y;
};

const Data& data()
{
    static const Data d = [] {
        Data r;
        if (const char* path = std::getenv("AXISTUNE_WELCH_CSV")) {
            auto cap = axistune::io::readCaptureCsvFile(path);
            if (cap.ok() && cap->channels.size() >= 2) {
                r.x = cap->channels[0].data;
                r.y = cap->channels[1].data;
                return r;
            }
            std::fprintf(stderr, "cannot read %s, using synthetic data\n", path);
        }
        const std::size_t n = std::size_t{1} << 21;
        r.x.resize(n);
        r.y.resize(n);
        std::uint64_t s = 88172645463325252ull;
        double y1 = 0, y2 = 0;
        for (std::size_t i = 0; i < n; ++i) {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            r.x[i] = static_cast<double>(s >> 11) * 0x1.0p-53 - 0.5;
            const double y = 1.6 * y1 - 0.8 * y2 + r.x[i];  // a resonance
            y2 = y1;
            y1 = y;
            r.y[i] = y;
        }
        return r;
    }();
    return d;
}

void BM_WelchH1Coherence(benchmark::State& state)
{
    const auto& d = data();
    axistune::dsp::WelchOptions o;
    o.nperseg = 4096;
    for (auto _ : state) {
        auto frf = axistune::dsp::welchFrf(d.x, d.y, 4000.0, o, axistune::dsp::FrfEstimator::H1);
        benchmark::DoNotOptimize(frf.ok());
    }
    state.counters["samples"] = static_cast<double>(d.x.size());
}
BENCHMARK(BM_WelchH1Coherence)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();

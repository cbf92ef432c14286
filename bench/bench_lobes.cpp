// SPDX-License-Identifier: GPL-3.0-or-later
// Stability lobes: 200 spindle speeds (2000–5980 rpm), 2-DOF Table 1 tool, a_e/D = 7/12 down milling,
// 40 steps per period, 1 and 2 threads (DESIGN.md target: < 2 s). Peer: bench/lobes_numpy.py.
#include "core/machining/StabilityLobes.h"

#include <benchmark/benchmark.h>

using namespace axistune::machining;

static void BM_Lobes200(benchmark::State& state)
{
    const ModalParameters m{0.40, 83.0, 30.1e6};
    const ToolModes tool{{m}, {m}};
    CuttingConditions cut;
    cut.teeth = 4;
    cut.ktNPerM2 = 0.98e9;
    cut.krNPerM2 = 0.294e9;
    cut.radialImmersion = 7.0 / 12.0;
    std::vector<double> rpms;
    for (int i = 0; i < 200; ++i)
        rpms.push_back(2000.0 + 20.0 * i);
    LobeOptions o;
    o.stepsPerPeriod = 40;
    o.threads = static_cast<int>(state.range(0));
    for (auto _ : state) {
        auto r = stabilityLobes(tool, cut, rpms, o);
        benchmark::DoNotOptimize(r);
    }
}
BENCHMARK(BM_Lobes200)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

BENCHMARK_MAIN();

// SPDX-License-Identifier: GPL-3.0-or-later
// Real-time factor of the simulator: one axis, 16 kHz current loop (62.5 µs), all nonlinearities on,
// position mode with a moving command. Reported as the counter "realtime_factor" (simulated seconds
// per wall-clock second). Target (DESIGN.md): at least 200.
#include "core/sim/AxisSimulator.h"

#include <benchmark/benchmark.h>

#include <chrono>

using namespace axistune::sim;

static void BM_SimulateOneAxis(benchmark::State& state, const char* preset, const char* axis)
{
    auto def = loadPreset(preset);
    if (!def) {
        state.SkipWithError(def.error().detail.c_str());
        return;
    }
    auto created = AxisSimulator::create(*def->axis(axis), 1);
    if (!created) {
        state.SkipWithError(created.error().detail.c_str());
        return;
    }
    auto& sim = **created;
    const double simSeconds = 1.0;
    double wall = 0.0;
    for (auto _ : state) {
        sim.reset();
        sim.setControlMode(ControlMode::Position);
        MotionProfile p(0.0);
        p.move(def->axis(axis)->kind == AxisKind::Linear ? 0.005 : 0.5, 0.02, 1.0);
        p.move(def->axis(axis)->kind == AxisKind::Linear ? -0.005 : -0.5, 0.02, 1.0);
        sim.setPositionProfile(p);
        sim.startTrace();
        const auto t0 = std::chrono::steady_clock::now();
        sim.run(simSeconds);
        wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        benchmark::DoNotOptimize(sim.takeTrace());
    }
    state.counters["realtime_factor"] = simSeconds * static_cast<double>(state.iterations()) / wall;
}

BENCHMARK_CAPTURE(BM_SimulateOneAxis, vmc_X, "vmc", "X")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SimulateOneAxis, dd_table_C, "dd-table", "C")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SimulateOneAxis, two_inertia_A, "two-inertia", "A")->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of a simulated cut with chatter avoidance in the loop (core/avoidance/AvoidanceCut, issue 22): the
// milling process (5 µs steps, variable delay), the vmc X axis (16 kHz current loop) and the controller.
// Reported as the counter "realtime_factor" (simulated seconds per wall-clock second; the machining wizard
// needs at least 1 to stay interactive). Cases of docs/chatter-avoidance.md:
//   adaptive  Table 1 tool, a_e 7 mm, 1.5 mm from 2800 rpm, accelerometer (Table 3), 1 s
//   dob       the same with the feed-stage DOB (Table 4), 1 s
//   multimode two-mode tool, 2.0 mm from 2800 rpm (Table 5), 1 s
//   esc       Table 1 tool, a_e 9 mm, 2.5 mm from 1700 rpm, ESC from 0.2 s (Table 6), 1 s
//   none      the Table 1 cut at constant speed, 1 s
#include "core/avoidance/AvoidanceCut.h"
#include "core/sim/MachineDefinition.h"

#include <benchmark/benchmark.h>
#include <chrono>
#include <cmath>
#include <numbers>

using namespace axistune;

namespace {
avoidance::AvoidanceCutOptions options(const std::string& which)
{
    avoidance::AvoidanceCutOptions o;
    auto& s = o.cut.milling;
    s.modesX = s.modesY = {{0.40, 83.0, 30.1e6}};
    if (which == "multimode") // the cascade (5-1) as its modal sum (tests/data/chatter/cascade_tool.py)
        s.modesX = s.modesY = {{0.5346547242, 96.45171224, 43499722.22}, {-0.5346547242, -76.99028028, -76990280.28}};
    s.teeth = 4;
    s.ktNPerM2 = 0.980e9;
    s.krNPerM2 = 0.294e9;
    s.radialImmersion = which == "esc" ? 0.75 : 7.0 / 12.0;
    s.spindleRpm = which == "esc" ? 1700.0 : 2800.0;
    s.axialDepthM = which == "esc" ? 2.5e-3 : (which == "multimode" ? 2.0e-3 : 1.5e-3);
    s.feedPerToothM = 0.1e-3;
    o.cut.durationS = 1.0;
    o.cut.engageS = 0.1;
    o.sensor = machining::AvoidanceSensor::Accelerometer;
    if (which == "adaptive") {
        o.method = avoidance::Method::Adaptive;
        o.adaptive = machining::adaptiveTable3Accelerometer();
    } else if (which == "dob") {
        o.method = avoidance::Method::Adaptive;
        o.sensor = machining::AvoidanceSensor::Dob;
        o.adaptive = machining::adaptiveTable4Dob();
    } else if (which == "multimode") {
        o.method = avoidance::Method::MultiMode;
        o.adaptive = machining::multiModeTable5Accelerometer();
    } else if (which == "esc") {
        o.method = avoidance::Method::Esc;
        o.esc.startS = 0.2;
        o.esc.minRpm = 1200.0;
        o.esc.maxRpm = 2200.0;
        o.esc.curvature = 4e8;
    }
    return o;
}
} // namespace

static void BM_AvoidanceCut(benchmark::State& state, const char* which)
{
    auto def = sim::loadPreset("vmc");
    if (!def || !def->axis("X")) {
        state.SkipWithError("vmc preset");
        return;
    }
    const auto o = options(which);
    double wall = 0.0;
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        auto r = avoidance::runAvoidanceCut(*def->axis("X"), o);
        wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!r) {
            state.SkipWithError(r.error().detail.c_str());
            return;
        }
        benchmark::DoNotOptimize(r->capture);
    }
    state.counters["realtime_factor"] = o.cut.durationS * static_cast<double>(state.iterations()) / wall;
}

BENCHMARK_CAPTURE(BM_AvoidanceCut, none, "none")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AvoidanceCut, adaptive, "adaptive")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AvoidanceCut, dob, "dob")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AvoidanceCut, multimode, "multimode")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AvoidanceCut, esc, "esc")->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();

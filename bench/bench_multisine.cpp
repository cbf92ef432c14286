// SPDX-License-Identifier: GPL-3.0-or-later
// Simulated motion time of the three-phase multisine FRF against the multi-sweep sine stream on
// sim:dd-table at the same accuracy (issue 11, docs/multisine.md). Each benchmark runs one FRF test
// through the simulated drive and reports as counters: motion_s (machine time of the excitation,
// settling included), lines (measured frequencies), valid, and the worst magnitude / phase error
// from 20 Hz to 3.9 kHz against the independent lifted model (tests/core/sim/LiftedModel.h, divided
// by the injection-hold factor when the FRF is corrected). Wall time is the simulator's.
//
// Simulations: "linear" (sim::Nonlinearities all off), "noise" (current-detection noise of the
// preset only: quantization, friction, inductance drop, lost motion off), "noise_friction"
// (noise and Coulomb friction). Encoder quantization is off in every case (the figures date from the
// former 3.6e6 counts/rev encoder, which hid the kilohertz modes; the preset now has 2^29).
// AXISTUNE_BENCH_DUMP=1 prints every line to stderr: f, dB error, phase error, valid, σ_H/|H|, |T| [dB].
#include "core/device/SimulatedDrive.h"
#include "core/device/TestRunner.h"
#include "core/dsp/InjectionHold.h"

#include <benchmark/benchmark.h>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "tests/core/sim/LiftedModel.h"

using namespace axistune;
using namespace axistune::device;

namespace {

sim::Nonlinearities simulation(const std::string& kind)
{
    sim::Nonlinearities n{false, false, false, false, false};
    n.noise = kind != "linear";
    n.friction = kind == "noise_friction";
    return n;
}

struct Errors {
    double worstDb = 0.0, worstDeg = 0.0;
    std::size_t lines = 0, valid = 0, within = 0, validOutside = 0;
};

Errors compare(const FrfMeasurement& m, const simtest::LiftedInjectionLoop& model)
{
    Errors e;
    const bool corrected = dsp::isInjectionHoldCorrected(m.frf);
    for (std::size_t i = 0; i < m.frf.size(); ++i) {
        const double f = m.frf.freqHz[i];
        if (f < 20.0 || f > 3900.0)
            continue;
        std::complex<double> ref = model.closedLoop(f);
        if (corrected)
            ref /= dsp::injectionHoldFactor(f, model.currentPeriodS,
                                            static_cast<int>(std::lround(model.periodS / model.currentPeriodS)));
        const std::complex<double> r = m.frf.h[i] / ref;
        if (std::getenv("AXISTUNE_BENCH_DUMP"))
            std::fprintf(stderr, "%g %g %g %d %g %g\n", f, 20.0 * std::log10(std::abs(r)),
                         std::arg(r) * 180.0 / std::numbers::pi, int(m.frf.valid[i]),
                         m.relativeNoise.empty() ? -1.0 : m.relativeNoise[i], 20 * std::log10(std::abs(ref)));
        const double db = std::abs(20.0 * std::log10(std::abs(r))),
                     deg = std::abs(std::arg(r)) * 180.0 / std::numbers::pi;
        ++e.lines;
        e.valid += m.frf.valid[i] ? 1 : 0;
        e.within += db <= 0.5 && deg <= 3.0 ? 1 : 0;
        e.validOutside += m.frf.valid[i] && !(db <= 0.5 && deg <= 3.0) ? 1 : 0;
        e.worstDb = std::max(e.worstDb, db);
        e.worstDeg = std::max(e.worstDeg, deg);
    }
    return e;
}

/// Runs one FRF test on a fresh dd-table drive; `previous` (when not null) shapes a multisine by 1/|H|.
void runFrf(benchmark::State& state, const std::string& kind, const TestRequest& request,
            const TestRequest* first = nullptr, double rangeDb = 0.0)
{
    auto def = sim::loadPreset("dd-table");
    if (!def) {
        state.SkipWithError(def.error().detail.c_str());
        return;
    }
    const auto model = simtest::buildLiftedInjectionLoop(def->axes.front());
    FrfMeasurement last;
    double motion = 0.0;
    for (auto _ : state) {
        auto drive = SimulatedDrive::create(*def, 7);
        (*drive)->simulator("C")->setNonlinearities(simulation(kind));
        (*drive)->setSliceSeconds(1.0);
        auto once = [&](const TestRequest& r) -> bool {
            RunOptions o;
            o.readTrace = false;
            auto run = runTest(**drive, r, o);
            if (!run) {
                state.SkipWithError(run.error().detail.c_str());
                return false;
            }
            last = std::move(*run->frf);
            motion += last.motionTimeS;
            return true;
        };
        motion = 0.0;
        TestRequest r = request;
        if (first) {
            if (!once(*first))
                return;
            // The shape of capture --shape-from: 1/|H| of the valid lines, limited to rangeDb.
            auto& shape = r.frf().multisineShape;
            double top = 0.0;
            for (std::size_t i = 0; i < last.frf.size(); ++i) {
                if (last.frf.valid[i]) {
                    shape.emplace_back(last.frf.freqHz[i], 1.0 / std::abs(last.frf.h[i]));
                    top = std::max(top, shape.back().second);
                }
            }
            for (auto& [f, w] : shape)
                w = std::max(w, top * std::pow(10.0, -rangeDb / 20.0)) / top;
        }
        if (!once(r))
            return;
    }
    const Errors e = compare(last, model);
    state.counters["motion_s"] = motion;
    state.counters["lines"] = static_cast<double>(e.lines);
    state.counters["valid"] = static_cast<double>(e.valid);
    state.counters["within_0.5dB_3deg"] = static_cast<double>(e.within);
    state.counters["valid_outside"] = static_cast<double>(e.validOutside);
    state.counters["worst_dB"] = e.worstDb;
    state.counters["worst_deg"] = e.worstDeg;
}

TestRequest base(FrfMethod method, double amplitudePct)
{
    TestRequest r;
    r.axis = "C";
    auto& f = r.test.emplace<FrfTest>();
    f.method = method;
    f.fminHz = 20.0;
    f.fmaxHz = 3900.0;
    f.amplitudePct = amplitudePct;
    return r;
}

void BM_Multisine(benchmark::State& state, std::string kind, double amplitudePct, double spacingHz)
{
    TestRequest r = base(FrfMethod::Multisine, amplitudePct);
    r.frf().multisineSpacingHz = spacingHz;
    r.frf().multisinePeriods = static_cast<int>(state.range(0));
    runFrf(state, kind, r);
}

/// A flat multisine of two periods, then one shaped by 1/|H| of its result (range in dB).
void BM_MultisineShaped(benchmark::State& state, std::string kind, double amplitudePct, double rangeDb)
{
    TestRequest first = base(FrfMethod::Multisine, amplitudePct);
    first.frf().multisineSpacingHz = 10.0;
    first.frf().multisinePeriods = 2;
    TestRequest r = first;
    r.frf().multisinePeriods = static_cast<int>(state.range(0));
    runFrf(state, kind, r, &first, rangeDb);
}

void BM_MultiSweep(benchmark::State& state, std::string kind, double amplitudePct)
{
    TestRequest r = base(FrfMethod::MultiSweep, amplitudePct);
    r.frf().points = static_cast<int>(state.range(0));
    runFrf(state, kind, r);
}

} // namespace

// Linear loop: both exact; the motion time is the methods' structure (settle + windows).
BENCHMARK_CAPTURE(BM_Multisine, linear_5pct_10Hz, std::string("linear"), 5.0, 10.0)
    ->Arg(2)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_MultiSweep, linear_5pct, std::string("linear"), 5.0)
    ->Arg(60)
    ->Arg(388)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
// Current-detection noise: periods averaged by the multisine against the sine stream.
BENCHMARK_CAPTURE(BM_Multisine, noise_5pct_10Hz, std::string("noise"), 5.0, 10.0)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Multisine, noise_10pct_10Hz, std::string("noise"), 10.0, 10.0)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Arg(16)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_MultisineShaped, noise_5pct_20dB, std::string("noise"), 5.0, 20.0)
    ->Arg(2)
    ->Arg(4)
    ->Arg(8)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_MultiSweep, noise_5pct, std::string("noise"), 5.0)
    ->Arg(60)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
// Noise and Coulomb friction (0.5 N·m against the excitation).
BENCHMARK_CAPTURE(BM_Multisine, noise_friction_5pct_10Hz, std::string("noise_friction"), 5.0, 10.0)
    ->Arg(2)
    ->Arg(8)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Multisine, noise_friction_10pct_10Hz, std::string("noise_friction"), 10.0, 10.0)
    ->Arg(2)
    ->Arg(8)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_MultiSweep, noise_friction_5pct, std::string("noise_friction"), 5.0)
    ->Arg(60)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

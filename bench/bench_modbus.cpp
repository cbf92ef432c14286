// SPDX-License-Identifier: GPL-3.0-or-later
// Modbus TCP over loopback: trace readout throughput (float64 samples per second through the paged
// trace window, function code 23) and a whole step test (start, poll, read the trace) over Modbus
// and a whole multi-sweep FRF test versus the embedded simulated drive. The server runs in-process on its own thread.
#include "core/device/ModbusDrive.h"
#include "core/device/SimDriveServer.h"
#include "core/device/TestRunner.h"

#include <benchmark/benchmark.h>
#include <thread>

using namespace axistune;
using namespace axistune::device;

namespace {

struct Server {
    std::unique_ptr<SimDriveServer> server;
    std::thread thread;
    explicit Server(const std::string& preset = "vmc")
    {
        SimDriveServerOptions o;
        o.preset = preset;
        server = std::move(SimDriveServer::create(o)).value();
        thread = std::thread([this] { (void)server->serve(); });
    }
    ~Server()
    {
        server->requestStop();
        thread.join();
    }
    std::string uri() const { return "modbus://127.0.0.1:" + std::to_string(server->port()); }
};

TestRequest stepRequest(double recordS)
{
    TestRequest r;
    r.axis = "X";
    auto& s = r.test.emplace<StepTest>();
    s.velocityRadS = 20.0;
    s.recordS = recordS;
    return r;
}

bool runStep(Drive& d, double durationS)
{
    RunOptions o;
    o.readTrace = false; // the benchmarks read it themselves
    return runTest(d, stepRequest(durationS), o).ok();
}

void BM_TraceReadout(benchmark::State& state)
{
    Server srv;
    auto d = std::move(connectAny({srv.uri(), 1})).value();
    const double duration = static_cast<double>(state.range(0)) / 4000.0; // trace at 4 kHz
    if (!runStep(*d, duration)) {
        state.SkipWithError("test failed");
        return;
    }
    std::size_t samples = 0;
    for (auto _ : state) {
        auto t = d->readTrace();
        if (!t) {
            state.SkipWithError(t.error().detail.c_str());
            return;
        }
        samples = t->size() * t->channels.size();
        benchmark::DoNotOptimize(t->channels.front().data.data());
    }
    state.counters["samples"] = static_cast<double>(samples);
    state.counters["samples_per_s"] = benchmark::Counter(
        static_cast<double>(samples) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_TraceReadout)->Arg(400)->Arg(4000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_StepTest(benchmark::State& state, bool modbus)
{
    std::unique_ptr<Server> srv;
    if (modbus)
        srv = std::make_unique<Server>();
    auto d = std::move(connectAny({modbus ? srv->uri() : "sim:vmc", 1})).value();
    for (auto _ : state) {
        if (!runStep(*d, 1.0)) {
            state.SkipWithError("test failed");
            return;
        }
        auto t = d->readTrace();
        benchmark::DoNotOptimize(t.ok());
    }
}
BENCHMARK_CAPTURE(BM_StepTest, embedded, false)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_StepTest, modbus, true)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_MultiSweep(benchmark::State& state, bool modbus)
{
    // dd-table rotary axis, 60 points 10 Hz .. 3900 Hz, 5 % of rated torque (capture --test frf defaults).
    std::unique_ptr<Server> srv;
    if (modbus) {
        srv = std::make_unique<Server>("dd-table");
    }
    auto d = std::move(connectAny({modbus ? srv->uri() : "sim:dd-table", 1})).value();
    TestRequest r;
    r.axis = d->identify()->axes.front();
    r.test.emplace<FrfTest>().amplitudePct = 5.0;
    RunOptions o;
    o.readTrace = false;
    for (auto _ : state) {
        auto run = runTest(*d, r, o);
        if (!run) {
            state.SkipWithError(("FRF test failed: " + run.error().detail).c_str());
            return;
        }
        state.counters["motion_s"] = run->frf->motionTimeS;
    }
}
BENCHMARK_CAPTURE(BM_MultiSweep, embedded, false)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
BENCHMARK_CAPTURE(BM_MultiSweep, modbus, true)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

} // namespace

BENCHMARK_MAIN();

// SPDX-License-Identifier: GPL-3.0-or-later
// GUI event-loop latency during a capture (issue 8 "Measured", DESIGN.md: GUI responsive during
// capture, target under 50 ms). The app's real drive link (DriveController: worker thread owning the
// Drive) runs a multi-sweep FRF test on the simulated dd-table, exactly as the FRF wizard does,
// while the GUI thread runs a 5 ms QTimer and progress signals arrive. Each iteration is one whole
// test; the counters are the delays of the timer ticks beyond their 5 ms period: median, 99th
// percentile and maximum over every tick of the test [ms]. Figures and command: docs/gui.md.
#include "app/gui/DriveController.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

using namespace axistune;

namespace {

void BM_EventLoopLatencyDuringFrfCapture(benchmark::State& state)
{
    gui::DriveController drive;
    {
        QEventLoop loop;
        QObject::connect(&drive, &gui::DriveController::replied, &loop, &QEventLoop::quit);
        drive.connectTo("sim:dd-table");
        loop.exec();
    }
    if (!drive.isConnected()) {
        state.SkipWithError("sim:dd-table did not connect");
        return;
    }
    device::TestRequest req;
    req.axis = "C";
    auto& frf = req.test.emplace<device::FrfTest>();
    frf.method = device::FrfMethod::MultiSweep;
    frf.fminHz = 100.0;
    frf.fmaxHz = 3900.0;
    frf.points = static_cast<int>(state.range(0));
    frf.amplitudePct = 3.0;
    std::vector<double> lateMs;
    int progressSignals = 0;
    for (auto _ : state) {
        QEventLoop loop;
        QTimer tick;
        tick.setTimerType(Qt::PreciseTimer);
        tick.setInterval(5);
        QElapsedTimer clock;
        qint64 last = 0;
        QObject::connect(&tick, &QTimer::timeout, [&] {
            const qint64 now = clock.nsecsElapsed();
            lateMs.push_back(std::max(0.0, (double(now - last) * 1e-6) - 5.0));
            last = now;
        });
        auto p = QObject::connect(&drive, &gui::DriveController::progress, [&] { ++progressSignals; });
        bool ok = false;
        auto r = QObject::connect(&drive, &gui::DriveController::replied, [&](const gui::DriveReply& reply) {
            ok = reply.ok;
            loop.quit();
        });
        clock.start();
        tick.start();
        drive.runTest(req);
        loop.exec();
        tick.stop();
        QObject::disconnect(p);
        QObject::disconnect(r);
        if (!ok) {
            state.SkipWithError("the FRF test failed");
            return;
        }
    }
    std::sort(lateMs.begin(), lateMs.end());
    auto at = [&](double q) { return lateMs.empty() ? 0.0 : lateMs[std::size_t(q * double(lateMs.size() - 1))]; };
    state.counters["late_p50_ms"] = at(0.5);
    state.counters["late_p99_ms"] = at(0.99);
    state.counters["late_max_ms"] = lateMs.empty() ? 0.0 : lateMs.back();
    state.counters["ticks"] = double(lateMs.size());
    state.counters["progress_signals"] = double(progressSignals);
}
BENCHMARK(BM_EventLoopLatencyDuringFrfCapture)->Arg(60)->Arg(300)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace

int main(int argc, char** argv)
{
    qputenv("QT_QPA_PLATFORM", qgetenv("QT_QPA_PLATFORM").isEmpty() ? QByteArray("offscreen") : qgetenv("QT_QPA_PLATFORM"));
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

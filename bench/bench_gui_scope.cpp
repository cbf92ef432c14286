// SPDX-License-Identifier: GPL-3.0-or-later
// The GUI scope (docs/scope.md "Measured: the GUI scope"): redraw of the scope plot with 8 × 10⁶ points of
// roll history (8 channels × 10⁶ samples, the dock's default history), the live roll frame (snapshot of the
// shown window + plot + redraw), and the memory of a long roll on the embedded drive (sim:vmc, 8 channels at
// 4 kHz, history 10⁶ samples per channel, the dock's refresh every 200 ms of machine time): resident memory
// when the history has filled and at the end. Offscreen platform, widget 1600 × 900.
#include "app/gui/ScopeDock.h"
#include "core/device/Drive.h"
#include "core/device/ScopeHistory.h"
#include "widgets/TimeTracePlot.h"

#include <QApplication>

#include <benchmark/benchmark.h>
#include <chrono>
#include <cmath>
#include <fstream>
#include <string>

using namespace axistune;

namespace {

const std::vector<device::ScopeChannelInfo> kChannels = {
    {"velocity_cmd_rad_s", "rad/s", ""}, {"motor_vel_rad_s", "rad/s", ""},
    {"torque_cmd_Nm", "N·m", ""},        {"current_A", "A", ""},
    {"position_cmd_m", "m", ""},         {"table_pos_m", "m", ""},
    {"following_error_m", "m", ""},      {"load_vel_rad_s", "rad/s", ""}};
constexpr double kRateHz = 4000.0;

/// A full history: 8 channels × rows, a slow wave with a fast ripple (every pixel column has a real spread).
device::ScopeHistory filledHistory(std::size_t rows)
{
    device::ScopeHistory h;
    h.reset(kChannels, kRateHz, rows);
    device::ScopeRows r;
    const std::size_t block = 65536;
    for (std::size_t first = 0; first < rows + rows / 4; first += block) { // wraps once
        r.firstSample = first;
        r.rows = block;
        r.values.resize(block * kChannels.size());
        for (std::size_t i = 0; i < block; ++i) {
            const double t = static_cast<double>(first + i) / kRateHz;
            for (std::size_t k = 0; k < kChannels.size(); ++k)
                r.values[i * kChannels.size() + k] = std::sin(2 * 3.14159265358979 * 0.2 * t + double(k)) +
                                                     0.1 * std::sin(2 * 3.14159265358979 * 900 * t);
        }
        h.append(r);
    }
    return h;
}

long residentKiB()
{
    std::ifstream f("/proc/self/status");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind("VmRSS:", 0) == 0)
            return std::stol(line.substr(6));
    return -1;
}

/// Redraw of the whole history (range(0) = % of it visible), as the dock shows it after Stop.
void BM_ScopeRedraw8M(benchmark::State& state)
{
    const auto h = filledHistory(1000000);
    widgets::TimeTracePlot plot;
    plot.resize(1600, 900);
    plot.show();
    plot.setCapture(gui::scopePlotTable(h.snapshot()));
    const auto [t0, t1] = plot.visibleRange();
    plot.setVisibleRange(t0, t0 + (t1 - t0) * static_cast<double>(state.range(0)) / 100.0);
    QApplication::processEvents();
    for (auto _ : state)
        plot.replotNow();
    state.counters["points"] = double(h.size() * h.channelCount());
}
BENCHMARK(BM_ScopeRedraw8M)->Arg(100)->Arg(10)->Unit(benchmark::kMillisecond);

/// Stop after a roll: snapshot of the whole history into the plot (once per Stop).
void BM_ScopeShowWholeHistory(benchmark::State& state)
{
    const auto h = filledHistory(1000000);
    widgets::TimeTracePlot plot;
    plot.resize(1600, 900);
    plot.show();
    for (auto _ : state) {
        plot.setCapture(gui::scopePlotTable(h.snapshot()));
        plot.replotNow();
    }
}
BENCHMARK(BM_ScopeShowWholeHistory)->Unit(benchmark::kMillisecond)->Iterations(3);

/// One live roll frame: the newest 2 s (8000 rows × 8 channels) out of the full history, plotted and redrawn.
void BM_ScopeRollFrame(benchmark::State& state)
{
    const auto h = filledHistory(1000000);
    widgets::TimeTracePlot plot;
    plot.resize(1600, 900);
    plot.show();
    for (auto _ : state) {
        plot.setCapture(gui::scopePlotTable(h.snapshot(8000)));
        plot.replotNow();
    }
}
BENCHMARK(BM_ScopeRollFrame)->Unit(benchmark::kMillisecond);

/// A long roll on sim:vmc: range(0) seconds of machine time; counters: resident memory [MiB] when the
/// history is full and at the end, rows streamed, rows lost.
void BM_ScopeLongRollMemory(benchmark::State& state)
{
    const double seconds = static_cast<double>(state.range(0));
    for (auto _ : state) {
        auto d = device::connect({"sim:vmc", 7});
        if (!d) {
            state.SkipWithError(d.error().detail.c_str());
            return;
        }
        device::Drive& drive = **d;
        device::ScopeRequest r;
        r.axis = "X";
        for (const auto& c : kChannels)
            r.channels.push_back(c.name);
        r.mode = device::ScopeMode::Roll;
        if (auto st = drive.armScope(r); !st) {
            state.SkipWithError(st.error().detail.c_str());
            return;
        }
        device::ScopeHistory h;
        h.reset(kChannels, kRateHz, 1000000);
        widgets::TimeTracePlot plot;
        plot.resize(1600, 900);
        plot.show();
        std::uint64_t next = 0, polls = 0, streamed = 0;
        double fullMiB = -1.0;
        while (static_cast<double>(streamed) < seconds * kRateHz) {
            auto s = drive.pollScope(); // 50 ms of machine time
            auto rows = drive.readScopeRows(next, 1u << 20);
            if (!s || !rows) {
                state.SkipWithError("scope poll failed");
                return;
            }
            h.append(*rows);
            streamed += rows->rows;
            next = rows->firstSample + rows->rows;
            if (++polls % 4 == 0) { // the dock's roll refresh: every 200 ms
                plot.setCapture(gui::scopePlotTable(h.snapshot(8000)));
                plot.replotNow();
                QApplication::processEvents();
            }
            if (fullMiB < 0 && h.size() == h.capacity())
                fullMiB = double(residentKiB()) / 1024.0;
        }
        state.counters["rss_full_MiB"] = fullMiB;
        state.counters["rss_end_MiB"] = double(residentKiB()) / 1024.0;
        state.counters["history_MiB"] = double(h.bytes()) / (1024.0 * 1024.0);
        state.counters["rows"] = double(streamed);
        state.counters["lost"] = double(h.lostSamples());
    }
}
BENCHMARK(BM_ScopeLongRollMemory)->Arg(600)->Iterations(1)->Unit(benchmark::kSecond);

} // namespace

int main(int argc, char** argv)
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

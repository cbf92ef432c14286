// SPDX-License-Identifier: GPL-3.0-or-later
// Plot redraw benchmarks (DESIGN.md target: redraw of a 1,000,000-point trace under 30 ms). Each
// iteration is one full replot (layout, every layer, repaint of the shown widget) on the offscreen
// platform. Figures and command: docs/plots.md.
#include "core/dsp/FrequencyResponse.h"
#include "widgets/BodePlot.h"
#include "widgets/TimeTracePlot.h"

#include <QApplication>

#include <benchmark/benchmark.h>

#include <cmath>
#include <complex>
#include <memory>

using namespace axistune;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::shared_ptr<const model::Capture> capture(int channels, std::size_t samples)
{
    auto c = std::make_shared<model::Capture>();
    c->metadata.set("fs_Hz", 16000.0);
    const char* names[] = {"motor_vel_rad_s", "torque_cmd_Nm", "i_q_A", "load_pos_m"};
    for (int k = 0; k < channels; ++k) {
        model::Channel ch{names[k % 4], std::vector<double>(samples)};
        for (std::size_t i = 0; i < samples; ++i) {
            const double t = double(i) / 16000.0;
            // A slow wave with a fast ripple and some noise-like content: every pixel column has a
            // real min/max spread, the hard case for adaptive sampling.
            ch.data[i] = std::sin(2 * kPi * 0.5 * t + k) + 0.2 * std::sin(2 * kPi * 3300 * t) +
                         0.05 * std::sin(double(i) * 12.9898 * (k + 1));
        }
        c->channels.push_back(std::move(ch));
    }
    return c;
}

void BM_TraceReplot(benchmark::State& state)
{
    const int channels = static_cast<int>(state.range(0));
    const double visibleFraction = state.range(1) / 100.0;
    widgets::TimeTracePlot plot;
    plot.resize(1600, 900);
    plot.show();
    plot.setCapture(capture(channels, 1000000));
    plot.setVisibleRange(0.0, 62.5 * visibleFraction);
    QApplication::processEvents();
    for (auto _ : state)
        plot.replotNow();
    state.counters["points"] = double(channels) * 1e6;
}
// {channels, visible range in % of the 62.5 s capture}
BENCHMARK(BM_TraceReplot)->Args({1, 100})->Args({1, 10})->Args({4, 100})->Unit(benchmark::kMillisecond);

void BM_TracePan(benchmark::State& state)
{
    widgets::TimeTracePlot plot;
    plot.resize(1600, 900);
    plot.show();
    plot.setCapture(capture(1, 1000000));
    QApplication::processEvents();
    double t0 = 0.0;
    for (auto _ : state) {
        // What a drag does: move the range, redraw.
        t0 = t0 > 30.0 ? 0.0 : t0 + 0.5;
        plot.setVisibleRange(t0, t0 + 30.0);
        plot.replotNow();
    }
}
BENCHMARK(BM_TracePan)->Unit(benchmark::kMillisecond);

dsp::FrequencyResponse response(double f0, double zeta, std::size_t n)
{
    dsp::FrequencyResponse frf;
    for (std::size_t i = 0; i < n; ++i) {
        const double f = 5.0 * std::pow(8000.0 / 5.0, double(i) / double(n - 1));
        const std::complex<double> s(0.0, f / f0);
        frf.push(f, 1.0 / (1.0 + 2.0 * zeta * s + s * s), 1.0 - 0.5 * f / 8000.0, f < 4700 || f > 5300);
    }
    return frf;
}

void BM_BodeReplot(benchmark::State& state)
{
    widgets::BodePlot plot;
    plot.resize(1600, 900);
    plot.show();
    for (int k = 0; k < 4; ++k)
        plot.addResponse(response(400.0 + 900.0 * k, 0.05, 2000), QStringLiteral("response %1").arg(k));
    plot.addBand(2000.0, 8000.0, widgets::BodePlot::BandKind::MultiSweepOnly);
    plot.addBand(4700.0, 5300.0, widgets::BodePlot::BandKind::NotMeasurable);
    plot.addMarker(3100.0, widgets::BodePlot::MarkerKind::Resonance, QStringLiteral("3.1 kHz"));
    plot.addMarker(3150.0, widgets::BodePlot::MarkerKind::Notch, QStringLiteral("notch"));
    QApplication::processEvents();
    for (auto _ : state)
        plot.replotNow();
}
BENCHMARK(BM_BodeReplot)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv)
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

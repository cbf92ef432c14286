// SPDX-License-Identifier: GPL-3.0-or-later
// Plot widgets: what is plotted equals independently computed values (an analytic second-order
// response, a sampled sine), the CSV export of the visible range holds exactly the samples inside it,
// and images are written as real PNG/SVG/PDF files.
#include "core/dsp/FrequencyResponse.h"
#include "widgets/BodePlot.h"
#include "widgets/CurvePlot.h"
#include "widgets/PolarPlot.h"
#include "widgets/TimeTracePlot.h"

#include <QApplication>
#include <QFile>
#include <QMouseEvent>
#include <QImage>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include <qcustomplot.h>

using namespace axistune;
using widgets::BodePlot;

namespace {

constexpr double kPi = 3.14159265358979323846;

// 1 / (1 + 2ζ s/ω0 + s²/ω0²) at s = j2πf.
std::complex<double> secondOrder(double fHz, double f0Hz, double zeta)
{
    const std::complex<double> s(0.0, fHz / f0Hz);
    return 1.0 / (1.0 + 2.0 * zeta * s + s * s);
}

// Log-spaced grid from 10 Hz to 10 kHz that contains f0 exactly.
dsp::FrequencyResponse secondOrderFrf(double f0Hz, double zeta, double coherence)
{
    dsp::FrequencyResponse frf;
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
        double f = 10.0 * std::pow(1000.0, i / double(n - 1));
        if (std::abs(f - f0Hz) / f0Hz < 1.7e-3)
            f = f0Hz;
        if (!frf.freqHz.empty() && f <= frf.freqHz.back())
            continue;
        frf.push(f, secondOrder(f, f0Hz, zeta), coherence, true);
    }
    return frf;
}

QByteArray head(const QString& path, int n)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return f.read(n);
}

double sampleSignal(std::size_t i, double fs)
{
    const double t = double(i) / fs;
    return 0.8 * std::sin(2.0 * kPi * 7.0 * t) + 0.1 * std::cos(2.0 * kPi * 333.0 * t);
}

std::shared_ptr<model::Capture> millionSampleCapture(double fs)
{
    auto c = std::make_shared<model::Capture>();
    c->metadata.set("fs_Hz", fs);
    model::Channel vel{"motor_vel_rad_s", {}};
    model::Channel torque{"torque_cmd_Nm", {}};
    const std::size_t n = 1000000;
    vel.data.resize(n);
    torque.data.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        vel.data[i] = sampleSignal(i, fs);
        torque.data[i] = 2.5 - 1e-6 * double(i);
    }
    c->channels = {vel, torque};
    return c;
}

// Non-white pixels in the columns [x0, x1) of an image.
int inkInColumns(const QImage& img, int x0, int x1)
{
    int n = 0;
    for (int y = 0; y < img.height(); ++y) {
        for (int x = x0; x < x1; ++x) {
            if (qGray(img.pixel(x, y)) < 200)
                ++n;
        }
    }
    return n;
}

}  // namespace

class TestPlots : public QObject {
    Q_OBJECT
private slots:
    void bodeMagnitudeAtResonanceIsAnalytic()
    {
        const double f0 = 1000.0;
        const double zeta = 0.05;
        BodePlot plot;
        const int id = plot.addResponse(secondOrderFrf(f0, zeta, 0.95), "plant");
        // |H(j ω0)| = 1/(2ζ) = 10 -> +20 dB, arg = -90°.
        QVERIFY(std::abs(plot.magnitudeDbAt(id, f0) - 20.0 * std::log10(1.0 / (2.0 * zeta))) < 1e-9);
        QVERIFY(std::abs(plot.phaseDegAt(id, f0) - (-90.0)) < 1e-9);
        // Far below resonance the response is 1 (0 dB) to within the analytic 1e-3 dB.
        QVERIFY(std::abs(plot.magnitudeDbAt(id, 10.0)) < 1e-3);
        QCOMPARE(plot.responseCount(), 1);
        QCOMPARE(plot.responseNames(), QStringList{"plant"});
        QVERIFY(plot.coherenceVisible());
        QVERIFY(std::isnan(plot.magnitudeDbAt(id + 1, f0)));
    }

    void bodeInvalidPointsAreGaps()
    {
        auto frf = secondOrderFrf(500.0, 0.1, std::numeric_limits<double>::quiet_NaN());
        double invalidF = 0.0;
        for (std::size_t i = 0; i < frf.size(); ++i) {
            if (frf.freqHz[i] > 2000.0 && frf.freqHz[i] < 4000.0) {
                frf.valid[i] = false;
                invalidF = frf.freqHz[i];
            }
        }
        BodePlot plot;
        const int id = plot.addResponse(frf, "measured");
        QVERIFY(std::isnan(plot.magnitudeDbAt(id, invalidF)));
        QVERIFY(std::isfinite(plot.magnitudeDbAt(id, 1000.0)));
        QVERIFY(!plot.coherenceVisible());  // sine streams: coherence not defined
    }

    void bodeBandsMarkersAndResponses()
    {
        BodePlot plot;
        const int a = plot.addResponse(secondOrderFrf(800.0, 0.05, 1.0), "before");
        plot.addResponse(secondOrderFrf(900.0, 0.2, 1.0), "after", Qt::red, Qt::DashLine);
        plot.addBand(2000.0, 5000.0, BodePlot::BandKind::MultiSweepOnly);
        plot.addBand(5000.0, 10000.0, BodePlot::BandKind::NotMeasurable);
        plot.addMarker(800.0, BodePlot::MarkerKind::Resonance, "800 Hz");
        plot.addMarker(1200.0, BodePlot::MarkerKind::Notch, "notch 1");
        plot.addMarker(1500.0, BodePlot::MarkerKind::AntiResonance, "anti");
        QCOMPARE(plot.bandCount(), 2);
        QCOMPARE(plot.markerCount(), 3);
        QCOMPARE(plot.responseCount(), 2);
        plot.removeResponse(a);
        QCOMPARE(plot.responseNames(), QStringList{"after"});
        plot.setFrequencyRange(100.0, 3000.0);
        plot.addResponse(secondOrderFrf(700.0, 0.1, 1.0), "third");  // keeps the range set
        QCOMPARE(plot.frequencyRange().first, 100.0);
        QCOMPARE(plot.frequencyRange().second, 3000.0);
        plot.rescale();  // the grid of secondOrderFrf: 10 Hz .. 10 kHz
        QVERIFY(std::abs(plot.frequencyRange().first - 10.0) < 1e-9);
        QVERIFY(std::abs(plot.frequencyRange().second - 10000.0) < 1e-6);
        plot.setPhaseUnwrapped(true);
        QVERIFY(plot.phaseUnwrapped());
        plot.clear();
        QCOMPARE(plot.bandCount(), 0);
        QCOMPARE(plot.markerCount(), 0);
        QCOMPARE(plot.responseCount(), 0);
    }

    void bodeExportsImages()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        BodePlot plot;
        plot.addResponse(secondOrderFrf(1000.0, 0.05, 0.9), "plant");
        plot.addBand(3000.0, 10000.0, BodePlot::BandKind::MultiSweepOnly);
        const QString png = dir.filePath("bode.png");
        const QString svg = dir.filePath("bode.svg");
        const QString pdf = dir.filePath("bode.PDF");
        QVERIFY2(plot.exportImage(png, 800, 600), qPrintable(plot.lastError()));
        QVERIFY2(plot.exportImage(svg), qPrintable(plot.lastError()));
        QVERIFY2(plot.exportImage(pdf), qPrintable(plot.lastError()));
        QCOMPARE(head(png, 4), QByteArray("\x89PNG"));
        QVERIFY(head(svg, 400).contains("<svg"));
        QCOMPARE(head(pdf, 4), QByteArray("%PDF"));
        QVERIFY(!plot.exportImage(dir.filePath("bode.bmp")));
        QVERIFY(plot.lastError().contains("bode.bmp"));
        QVERIFY(!plot.exportImage(dir.filePath("no/such/folder/bode.png")));
        QVERIFY(plot.lastError().contains("does not exist"));
    }

    void unitLabelsFromChannelNames()
    {
        QCOMPARE(widgets::channelUnitLabel("motor_vel_rad_s"), QString("rad/s"));
        QCOMPARE(widgets::channelUnitLabel("torque_cmd_Nm"), QString::fromUtf8("N·m"));
        QCOMPARE(widgets::channelUnitLabel("load_pos_m"), QString("m"));
        QCOMPARE(widgets::channelUnitLabel("i_q_A"), QString("A"));
        QCOMPARE(widgets::channelUnitLabel("table_vel_m_s"), QString("m/s"));
        QCOMPARE(widgets::channelUnitLabel("accel_m_s2"), QString::fromUtf8("m/s²"));
        QCOMPARE(widgets::channelUnitLabel("counter"), QString());
    }

    void traceExportsExactlyTheVisibleSamples()
    {
        const double fs = 10000.0;
        auto capture = millionSampleCapture(fs);
        widgets::TimeTracePlot plot;
        plot.setCapture(capture);
        QCOMPARE(plot.seriesNames(), (QStringList{"motor_vel_rad_s", "torque_cmd_Nm"}));
        QCOMPARE(plot.stripCount(), 2);  // rad/s and N·m
        // Range boundaries half-way between samples: samples 123457 .. 125000 are inside.
        plot.setVisibleRange(12.34565, 12.50005);
        const std::size_t first = 123457, last = 125000;
        QTemporaryDir dir;
        const QString csv = dir.filePath("visible.csv");
        QVERIFY2(plot.exportVisibleCsv(csv), qPrintable(plot.lastError()));
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
        QCOMPARE(f.readLine().trimmed(), QByteArray("time_s,motor_vel_rad_s,torque_cmd_Nm"));
        std::size_t i = first;
        while (!f.atEnd()) {
            const QList<QByteArray> cols = f.readLine().trimmed().split(',');
            QCOMPARE(cols.size(), 3);
            QVERIFY(i <= last);
            QVERIFY(std::abs(cols[0].toDouble() - double(i) / fs) < 1e-12);
            QCOMPARE(cols[1].toDouble(), sampleSignal(i, fs));  // shortest round-trip text: exact
            QCOMPARE(cols[2].toDouble(), 2.5 - 1e-6 * double(i));
            ++i;
        }
        QCOMPARE(i - first, last - first + 1);
    }

    void longTraceSeenWholeIsDrawnFromItsEnvelope()
    {
        // 10⁶ samples with three one-sample spikes: seen whole, the trace is drawn from its min/max envelope (fast),
        // which holds every spike exactly (a glitch of one sample must not vanish) and the same extremes as the
        // samples; zoomed in to 1000 samples, the samples themselves are drawn.
        const double fs = 10000.0;
        auto capture = millionSampleCapture(fs);
        auto& vel = capture->channels[0].data;
        const std::vector<std::pair<std::size_t, double>> spikes = {{1234, 5.0}, {500001, -4.0}, {999998, 3.0}};
        for (const auto& [i, v] : spikes)
            vel[i] = v;
        widgets::TimeTracePlot plot;
        plot.resize(1600, 900);
        plot.show();
        plot.setCapture(capture, {"motor_vel_rad_s"});
        plot.replotNow();
        plot.replotNow(); // the first replot lays the axis rect out
        QVERIFY(plot.showsEnvelope("motor_vel_rad_s"));
        auto* qcp = plot.findChild<QCustomPlot*>();
        QVERIFY(qcp);
        QCOMPARE(qcp->graphCount(), 1);
        const auto drawn = qcp->graph(0)->data();
        QVERIFY(drawn->size() < 100000); // far fewer points than samples
        for (const auto& [i, v] : spikes) {
            const double key = double(i) / fs;
            const auto it = drawn->findBegin(key, false);
            QVERIFY(it != drawn->constEnd());
            QCOMPARE(it->key, key);
            QCOMPARE(it->value, v);
        }
        double lo = 1e9, hi = -1e9;
        for (auto it = drawn->constBegin(); it != drawn->constEnd(); ++it) {
            lo = std::min(lo, it->value);
            hi = std::max(hi, it->value);
        }
        QCOMPARE(lo, *std::min_element(vel.begin(), vel.end()));
        QCOMPARE(hi, *std::max_element(vel.begin(), vel.end()));
        plot.setVisibleRange(10.0, 10.1);
        plot.replotNow();
        QVERIFY(!plot.showsEnvelope("motor_vel_rad_s"));
        QCOMPARE(qcp->graph(0)->data()->size(), 1000000);
    }

    void cursorsReadTheSampledSignal()
    {
        const double fs = 10000.0;
        widgets::TimeTracePlot plot;
        plot.setCapture(millionSampleCapture(fs), {"motor_vel_rad_s"});
        QCOMPARE(plot.stripCount(), 1);
        plot.setCursors(4321.0 / fs, 98765.0 / fs);
        QCOMPARE(plot.cursorValue(0, "motor_vel_rad_s"), sampleSignal(4321, fs));
        QCOMPARE(plot.cursorValue(1, "motor_vel_rad_s"), sampleSignal(98765, fs));
        // Half-way between two samples: the mean of both (linear interpolation).
        plot.setCursors(100.5 / fs, 200.0 / fs);
        QVERIFY(std::abs(plot.cursorValue(0, "motor_vel_rad_s") -
                         0.5 * (sampleSignal(100, fs) + sampleSignal(101, fs))) < 1e-12);
        const QString readout = plot.cursorReadout();
        QVERIFY2(readout.contains(QString::fromUtf8("Δt = 0.00995 s")), qPrintable(readout));
        QVERIFY(std::isnan(plot.cursorValue(0, "no_such_channel")));
    }

    void cursorIsDraggedWithTheLeftButton()
    {
        auto c = std::make_shared<model::Capture>();
        c->channels = {{"t_s", {0.0, 0.5, 1.0, 1.5}}, {"pos_m", {0.0, 1.0, 4.0, 9.0}}};
        widgets::TimeTracePlot plot;
        plot.resize(800, 400);
        plot.setCapture(c);
        plot.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plot));
        plot.setCursors(0.5, 1.0);
        auto* cp = plot.findChild<QCustomPlot*>();
        QVERIFY(cp);
        cp->replot();
        QCPAxis* time = cp->axisRect(0)->axis(QCPAxis::atBottom);
        const QCPRange before = time->range();
        const double y = cp->axisRect(0)->center().y();
        auto send = [&](QEvent::Type type, double x, Qt::MouseButton button, Qt::MouseButtons buttons) {
            QMouseEvent e(type, QPointF(x, y), cp->mapToGlobal(QPointF(x, y)), button, buttons, Qt::NoModifier);
            QApplication::sendEvent(cp, &e);
        };
        // Grabbed 3 px beside cursor 1, dragged to where t = 0.75 is drawn.
        const double x0 = time->coordToPixel(0.5) + 3.0, x1 = time->coordToPixel(0.75);
        send(QEvent::MouseButtonPress, x0, Qt::LeftButton, Qt::LeftButton);
        send(QEvent::MouseMove, x1, Qt::NoButton, Qt::LeftButton);
        send(QEvent::MouseButtonRelease, x1, Qt::LeftButton, Qt::NoButton);
        const double pixel = (before.upper - before.lower) / cp->axisRect(0)->width();
        QVERIFY2(std::abs(plot.cursors().first - 0.75) <= pixel, qPrintable(QString::number(plot.cursors().first)));
        QCOMPARE(plot.cursors().second, 1.0);
        QCOMPARE(time->range().lower, before.lower);  // the drag moved the cursor, not the view
        QCOMPARE(time->range().upper, before.upper);
        // Away from the cursors the left button pans as before.
        const double xa = time->coordToPixel(1.3), xb = xa - 100.0;
        send(QEvent::MouseButtonPress, xa, Qt::LeftButton, Qt::LeftButton);
        send(QEvent::MouseMove, xb, Qt::NoButton, Qt::LeftButton);
        send(QEvent::MouseButtonRelease, xb, Qt::LeftButton, Qt::NoButton);
        QVERIFY(time->range().lower > before.lower);
        QCOMPARE(plot.cursors().second, 1.0);
    }

    void traceTimeChannelAndOverlays()
    {
        auto c = std::make_shared<model::Capture>();
        c->channels = {{"t_s", {0.0, 0.5, 1.0, 1.5}}, {"pos_m", {0.0, 1.0, 4.0, 9.0}}};
        widgets::TimeTracePlot plot;
        plot.setCapture(c);
        QCOMPARE(plot.seriesNames(), QStringList{"pos_m"});
        plot.setCursors(1.0, 1.5);
        QCOMPARE(plot.cursorValue(0, "pos_m"), 4.0);
        plot.addSeries("predicted", {0.0, 1.0, 2.0}, {0.0, 2.0, 4.0}, "m");
        QCOMPARE(plot.stripCount(), 1);  // same unit: same strip
        QCOMPARE(plot.cursorValue(1, "predicted"), 3.0);
        plot.addSeries("torque", {0.0, 1.0}, {0.0, 1.0}, "Nm");
        QCOMPARE(plot.stripCount(), 2);
        QTemporaryDir dir;
        QVERIFY(plot.exportImage(dir.filePath("trace.png")));
        QCOMPARE(head(dir.filePath("trace.png"), 4), QByteArray("\x89PNG"));
        plot.clear();
        QCOMPARE(plot.seriesNames(), QStringList{});
        QVERIFY(!plot.exportVisibleCsv(dir.filePath("empty.csv")));
    }

    void legendWrapsToThePlotWidth()
    {
        // Three entries of about 300 px each: one column fits 400 px, all three (the most asked for) 1400 px.
        widgets::CurvePlot plot;
        const QString longName = QString("Stability boundary with a long explanatory name %1");
        for (int i = 0; i < 3; ++i)
            plot.addCurve(longName.arg(i), {0.0, 1.0}, {0.0, 1.0});
        auto* cp = plot.findChild<QCustomPlot*>();
        QVERIFY(cp);
        int widest = 0;
        for (int i = 0; i < cp->legend->itemCount(); ++i)
            widest = std::max(widest, cp->legend->item(i)->minimumOuterSizeHint().width());
        QVERIFY(widest > 250);
        plot.resize(400, 300);
        plot.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plot));
        QCOMPARE(cp->legend->wrap(), 1);
        plot.resize(1400, 300);
        QTRY_COMPARE(cp->legend->wrap(), 3);
        plot.resize(2 * widest + 80, 300);
        QTRY_COMPARE(cp->legend->wrap(), 2);
    }

    void curvePlotCountsAndExport()
    {
        widgets::CurvePlot plot;
        plot.setAxes("k_p", "V/A", "k_i", "V/(A·s)", false, true);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        QCOMPARE(plot.addCurve("stability", {1, 2, nan, 4, 5}, {10, 20, 30, 40, 50}), 0);
        QCOMPARE(plot.addCurve("points", {1, 2, 3}, {5, 6, 7}, QColor(), Qt::SolidLine, true), 1);
        plot.addPoint(2.0, 15.0, "chosen");
        plot.addVerticalLine(3.0, "limit");
        QCOMPARE(plot.curveCount(), 2);
        QCOMPARE(plot.pointCount(), 1);
        QCOMPARE(plot.verticalLineCount(), 1);
        QCOMPARE(plot.curveNames(), (QStringList{"stability", "points"}));
        QTemporaryDir dir;
        QVERIFY2(plot.exportImage(dir.filePath("curve.svg"), 640, 480), qPrintable(plot.lastError()));
        QVERIFY(head(dir.filePath("curve.svg"), 400).contains("<svg"));
        plot.clear();
        QCOMPARE(plot.curveCount(), 0);
        QCOMPARE(plot.pointCount(), 0);
    }

    void polarPlotScaleAndExport()
    {
        widgets::PolarPlot plot;
        plot.setNominalRadius(0.1);
        std::vector<double> a, d;
        for (int i = 0; i <= 720; ++i) {
            a.push_back(2.0 * kPi * i / 720.0);
            d.push_back(20e-6 * std::cos(2.0 * a.back()));
        }
        QCOMPARE(plot.addTrace("ccw", a, d), 0);
        plot.addMarker(kPi / 2.0, "reversal Y");
        QCOMPARE(plot.traceCount(), 1);
        QCOMPARE(plot.markerCount(), 1);
        // Auto: the 20 µm peak spans a third of the 100 mm radius -> ×1666.7; 20/3 µm -> 10 µm/div.
        QVERIFY(std::abs(plot.magnification() - (0.1 / 3.0) / 20e-6) < 1e-6);
        QCOMPARE(plot.micrometresPerDivision(), 10.0);
        plot.setMagnification(500.0);
        QCOMPARE(plot.magnification(), 500.0);
        QVERIFY(plot.scaleText().contains(QString::fromUtf8("µm/div")));
        model::BallBarTrace t;
        t.radiusM = 0.05;
        t.angleRad = a;
        t.deviationM = d;
        QCOMPARE(plot.addTrace(t, "cw"), 1);
        QCOMPARE(plot.nominalRadius(), 0.05);
        QTemporaryDir dir;
        QVERIFY2(plot.exportImage(dir.filePath("polar.pdf")), qPrintable(plot.lastError()));
        QCOMPARE(head(dir.filePath("polar.pdf"), 4), QByteArray("%PDF"));
        plot.clear();
        QCOMPARE(plot.traceCount(), 0);
    }

    void emptyPlotsFillTheirWidth()
    {
        // An empty plot once drew its axes in a narrow strip at the left (an empty legend row).
        QTemporaryDir dir;
        BodePlot bode;
        widgets::TimeTracePlot trace;
        widgets::CurvePlot curve;
        const QString a = dir.filePath("a.png"), b = dir.filePath("b.png"), c = dir.filePath("c.png");
        QVERIFY(bode.exportImage(a, 600, 400));
        QVERIFY(trace.exportImage(b, 600, 400));
        QVERIFY(curve.exportImage(c, 600, 400));
        for (const QString& path : {a, b, c}) {
            const QImage img(path);
            QCOMPARE(img.width(), 600);
            QVERIFY2(inkInColumns(img, 400, 580) > 100, qPrintable(path));  // axis, ticks, labels
        }
    }

    void polarCircleIsRoundInAWideExport()
    {
        // Only the nominal circle (and the scale text at the top) is drawn darker than grey 80.
        widgets::PolarPlot plot;
        QTemporaryDir dir;
        const QString path = dir.filePath("wide.png");
        QVERIFY(plot.exportImage(path, 1000, 500));
        const QImage img(path);
        int left = img.width(), right = -1, top = img.height(), bottom = -1;
        for (int y = 40; y < img.height(); ++y) {
            for (int x = 0; x < img.width(); ++x) {
                if (qGray(img.pixel(x, y)) < 80) {
                    left = std::min(left, x);
                    right = std::max(right, x);
                    top = std::min(top, y);
                    bottom = std::max(bottom, y);
                }
            }
        }
        QVERIFY(right > left && bottom > top);
        const double w = right - left, h = bottom - top;
        QVERIFY2(std::abs(w / h - 1.0) < 0.03, qPrintable(QString("%1 x %2 px").arg(w).arg(h)));
    }
};

QTEST_MAIN(TestPlots)
#include "tst_plots.moc"

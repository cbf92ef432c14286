// SPDX-License-Identifier: GPL-3.0-or-later
// The scope dock of the main window on the embedded sim:vmc drive (docs/scope.md "The GUI scope"): a
// triggered capture during a back-and-forth jog from the dock's own jog panel shows the reversal; the
// capture saved into the store and exported as CSV reopens identical; roll mode keeps a bounded history;
// bad requests are refused naming the control. Screenshots with AXISTUNE_SCREENSHOT_DIR (docs/gui.md).
#include "app/gui/AppContext.h"
#include "app/gui/DriveController.h"
#include "app/gui/MainWindow.h"
#include "app/gui/ScopeDock.h"
#include "widgets/CurvePlot.h"
#include "widgets/TimeTracePlot.h"

#include <QDockWidget>
#include <QPointer>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numbers>

#include "tests/gui/DriveTestRequests.h"
#include "tests/gui/GuiTestUtil.h"

using axistune::device::ScopeCapture;
using axistune::device::ScopeEdge;
using axistune::gui::MainWindow;
using axistune::gui::ScopeDock;
using axistune::testing::waitUntil;

namespace {
// sim:vmc (resources/machines/vmc.json): velocity-loop rate 4 kHz (scope's fastest rate), screw lead 12 mm/rev.
constexpr double kRateHz = 4000.0;
constexpr double kLeadM = 0.012;

int column(const ScopeCapture& c, const std::string& name)
{
    for (std::size_t k = 0; k < c.channels.size(); ++k)
        if (c.channels[k].name == name)
            return static_cast<int>(k);
    return -1;
}

/// The same capture: sample numbers, channels and units, rate, trigger and every value bit for bit.
void compareCaptures(const ScopeCapture& a, const ScopeCapture& b)
{
    QCOMPARE(a.samples, b.samples);
    QCOMPARE(a.rateHz, b.rateHz);
    QCOMPARE(a.triggered, b.triggered);
    QCOMPARE(a.triggerSample, b.triggerSample);
    QCOMPARE(a.channels.size(), b.channels.size());
    for (std::size_t k = 0; k < a.channels.size(); ++k) {
        QCOMPARE(a.channels[k].name, b.channels[k].name);
        QCOMPARE(a.channels[k].unit, b.channels[k].unit);
        QCOMPARE(a.columns[k], b.columns[k]);
    }
}
} // namespace

class TestScopeDock : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QString m_lang;
    QString storePath() const { return m_dir.filePath("store.sqlite"); }

    /// A main window connected to sim:vmc with the scope dock floating at a readable size, axis X.
    bool open(MainWindow& w)
    {
        w.resize(1280, 900);
        w.show();
        w.connectSimulated("vmc");
        if (!waitUntil([&] { return w.context().drive().isConnected(); }, 20000))
            return false;
        w.showScope();
        w.scopeDock()->setFloating(true);
        w.scopeDock()->resize(1250, 720);
        ScopeDock* s = w.scope();
        return waitUntil([&] { return s->setAxis("X") && s->channelsKnown(); }, 10000);
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
        m_lang = axistune::testing::installLanguageFromEnv();
    }

    void triggeredCaptureDuringABackAndForthJogShowsTheReversal()
    {
        MainWindow w(storePath());
        QVERIFY(open(w));
        ScopeDock* s = w.scope();
        QVERIFY(s->selectChannels({"t_s", "velocity_cmd_rad_s", "motor_vel_rad_s", "following_error_m"}));
        // The return leg: the velocity command falls through -10 rad/s (the cruise is ±26.2 rad/s, see below).
        const double level = -10.0, pre = 40.0, lengthS = 0.2;
        s->setTrigger("velocity_cmd_rad_s", level, ScopeEdge::Falling, pre, lengthS);
        // 20 mm at 50 mm/s, 1000 mm/s², there and back: the motor cruises at 0.05 / 0.012 · 2π = 26.18 rad/s.
        s->setJog(20.0, 50.0, 1000.0, true);
        QSignalSpy shown(s, &ScopeDock::captureShown);
        QSignalSpy jogDone(s, &ScopeDock::jogFinished);
        s->runSingle();
        s->startJog(); // queued after the arm on the drive thread
        QVERIFY(s->running());
        QVERIFY(waitUntil([&] { return jogDone.count() == 1 && !s->running(); }, 30000));
        QVERIFY2(jogDone.first().at(0).toBool(), qPrintable(jogDone.first().at(1).toString()));
        QCOMPARE(shown.count(), 1);
        QVERIFY2(s->messageText().isEmpty(), qPrintable(s->messageText()));
        const auto cap = s->capture();
        QVERIFY(cap);
        QVERIFY(cap->triggered);

        // Length and trigger row: round(0.2 s · 4000 Hz) = 800 rows, the trigger at round(40 % · 800) = 320 (±1).
        const std::size_t rows = 800, preRow = 320;
        QCOMPARE(cap->rows(), rows);
        QCOMPARE(cap->rateHz, kRateHz);
        QVERIFY(std::llabs(static_cast<long long>(cap->triggerRow()) - static_cast<long long>(preRow)) <= 1);
        QCOMPARE(cap->missingSamples(), std::uint64_t{0});
        // The crossing found in the data, independently of the drive's trigger: the first row where the
        // command falls from above the level to it or below.
        const int vc = column(*cap, "velocity_cmd_rad_s"), vm = column(*cap, "motor_vel_rad_s"),
                  ts = column(*cap, "t_s");
        QVERIFY(vc >= 0 && vm >= 0 && ts >= 0);
        std::size_t crossing = rows;
        for (std::size_t i = 1; i < rows && crossing == rows; ++i)
            if (cap->columns[vc][i - 1] > level && cap->columns[vc][i] <= level)
                crossing = i;
        QVERIFY(std::llabs(static_cast<long long>(crossing) - static_cast<long long>(preRow)) <= 1);
        QCOMPARE(crossing, cap->triggerRow());
        // Machine time of every row is n / 4000 Hz (divider 1) within 1e-12 s.
        for (std::size_t i = 0; i < rows; ++i)
            QVERIFY(std::abs(cap->columns[ts][i] - static_cast<double>(cap->samples[i]) / kRateHz) <= 1e-12);
        // The reversal: the motor velocity changes sign within the capture, from the forward cruise before the
        // trigger to the return cruise after it (within 10 % of 26.18 rad/s: loop tracking and noise).
        const double cruise = 0.05 / kLeadM * 2.0 * std::numbers::pi;
        double maxBefore = -1e9, minAfter = 1e9;
        for (std::size_t i = 0; i < rows; ++i) {
            if (i < cap->triggerRow())
                maxBefore = std::max(maxBefore, cap->columns[vm][i]);
            else
                minAfter = std::min(minAfter, cap->columns[vm][i]);
        }
        QVERIFY2(maxBefore > 0.9 * cruise, qPrintable(QString::number(maxBefore)));
        QVERIFY2(minAfter < -0.9 * cruise, qPrintable(QString::number(minAfter)));
        // The plot shows every channel but the machine time, each with the drive's unit.
        QCOMPARE(s->plot()->seriesNames(), QStringList({"velocity_cmd_rad_s", "motor_vel_rad_s", "following_error_m"}));
        QCOMPARE(s->plot()->stripCount(), 2); // rad/s and m
        QVERIFY(s->plot()->cursorReadout().contains("1/Δt"));
        QVERIFY(s->plot()->cursorReadout().contains("rad/s"));
        // Cursors on the samples 10 rows either side of the trigger: Δt = 20 / 4000 Hz = 5 ms.
        const double t0 = -10.0 / kRateHz, t1 = 10.0 / kRateHz;
        s->plot()->setCursors(t0, t1);
        QVERIFY(std::abs(s->plot()->cursorValue(0, "motor_vel_rad_s") - cap->columns[vm][cap->triggerRow() - 10]) <=
                1e-9);
        axistune::testing::maybeScreenshot(w.scopeDock(), "scope-dock-reversal");

        // Saved into the store and reopened from it: identical.
        const ScopeCapture original = *cap;
        QSignalSpy saved(s, &ScopeDock::saved);
        QString error;
        QVERIFY2(s->saveToStore(&error), qPrintable(error));
        QVERIFY(waitUntil([&] { return saved.count() == 1; }, 20000));
        const qint64 id = saved.first().at(0).toLongLong();
        QVERIFY2(s->openFromStore(id, &error), qPrintable(error));
        QVERIFY(s->capture() != cap);
        compareCaptures(*s->capture(), original);
        // Exported as the scope CSV and reopened: identical.
        const QString csv = m_dir.filePath("reversal.csv");
        QVERIFY2(s->exportCsv(csv, &error), qPrintable(error));
        QVERIFY2(s->openCsv(csv, &error), qPrintable(error));
        compareCaptures(*s->capture(), original);
        // Images.
        for (const char* suffix : {"png", "svg", "pdf"})
            QVERIFY2(s->exportImage(m_dir.filePath(QString("reversal.") + suffix), &error), qPrintable(error));
        QVERIFY(QFileInfo(m_dir.filePath("reversal.png")).size() > 1000);
        // Math channel A − B: at the cursor it is the difference of the two samples there.
        s->plot()->setCursors(t0, t1);
        s->setMath(ScopeDock::Math::Difference, "motor_vel_rad_s", "velocity_cmd_rad_s");
        const QString diff = QString::fromUtf8("motor_vel_rad_s − velocity_cmd_rad_s");
        QCOMPARE(s->mathChannel(), diff);
        QVERIFY(s->plot()->seriesNames().contains(diff));
        const std::size_t r0 = original.triggerRow() - 10;
        QVERIFY(std::abs(s->plot()->cursorValue(0, diff) - (original.columns[vm][r0] - original.columns[vc][r0])) <=
                1e-9);
        // Spectrum of the visible window (the whole 0.2 s capture: 800 samples, 5 Hz bins).
        s->plot()->rescale();
        auto* spectrum = s->showSpectrum(&error);
        QVERIFY2(spectrum, qPrintable(error));
        QCOMPARE(spectrum->property("resolutionHz").toDouble(), kRateHz / 800.0);
        QCOMPARE(spectrum->curveCount(), 1);
        s->setMath(ScopeDock::Math::None, "motor_vel_rad_s", "velocity_cmd_rad_s");
        QVERIFY(s->mathChannel().isEmpty());
        // Display scaling: gain 2, offset 1 rad/s on the motor velocity; the plotted value at the cursor is
        // 2·v + 1 of the sample there, the capture itself keeps the drive's values; gain 1, offset 0: off again.
        s->setScale("motor_vel_rad_s", 2.0, 1.0);
        const QString scaled = QString::fromUtf8("motor_vel_rad_s ×2 +1");
        QCOMPARE(s->scaledChannel(), scaled);
        QVERIFY(std::abs(s->plot()->cursorValue(0, scaled) - (2.0 * original.columns[vm][r0] + 1.0)) <= 1e-9);
        QCOMPARE(s->capture()->columns[vm][r0], original.columns[vm][r0]);
        s->setScale("motor_vel_rad_s", 1.0, 0.0);
        QVERIFY(s->scaledChannel().isEmpty());
        // A reference overlay: every channel of the capture again, dashed, until cleared.
        const int before = static_cast<int>(s->plot()->seriesNames().size());
        s->keepReference();
        QCOMPARE(s->referenceCount(), 1);
        QCOMPARE(static_cast<int>(s->plot()->seriesNames().size()), before + 3);
        s->clearReferences();
        QCOMPARE(static_cast<int>(s->plot()->seriesNames().size()), before);
        // XY: the following error against the velocity command.
        s->setXy(true, "velocity_cmd_rad_s", "following_error_m");
        QCOMPARE(s->xyPlot()->curveCount(), 1);
        axistune::testing::maybeScreenshot(w.scopeDock(), "scope-dock-xy");
        s->setXy(false);
        // A session without a scope capture is refused by name.
        QVERIFY(!s->openFromStore(id + 1000, &error));
        QVERIFY(!error.isEmpty());
    }

    void xyOfTwoAxesDrawsTheCircle()
    {
        // A circle of X and Y (R 10 mm about (0, 0.1 m) at 3000 mm/min, as the ball-bar wizard runs it) while the
        // scope rolls X's table position and Y's (a companion channel of the X scope): X against Y is the circle.
        MainWindow w(storePath());
        QVERIFY(open(w));
        ScopeDock* s = w.scope();
        QVERIFY(s->selectChannels({"t_s", "table_pos_m", "Y.table_pos_m"}));
        s->setRollMode(true);
        s->setHistoryRows(100000);
        s->runNormal();
        QVERIFY(s->running());
        axistune::device::TestRequest t;
        t.axis = "X";
        auto& circle = t.test.emplace<axistune::device::CircleTest>();
        circle.secondAxis = "Y";
        circle.radiusM = 0.01;
        circle.feedMPerS = 0.05;
        circle.centerYM = 0.1;
        circle.dwellS = 0.1;
        bool done = false, ok = false;
        QObject::connect(w.context().drive().runTest(t), &axistune::gui::DriveRequest::finished,
                         [&](const axistune::gui::DriveReply& reply) {
                             done = true;
                             ok = reply.ok;
                         });
        QVERIFY(waitUntil([&] { return done; }, 60000));
        QVERIFY(ok);
        // The rows of the circle's end reach the dock with its next polls.
        QTest::qWait(500);
        s->stop();
        QVERIFY(!s->running());
        const auto cap = s->capture();
        QVERIFY(cap);
        QCOMPARE(cap->missingSamples(), std::uint64_t{0});
        const int kx = column(*cap, "table_pos_m"), ky = column(*cap, "Y.table_pos_m");
        QVERIFY(kx >= 0 && ky >= 0);
        // The rows on the circle (within 20 µm of R: the radial error of a 10 mm circle at 50 mm/s is a few µm on
        // vmc, docs/ballbar.md) cover the whole turn: every 10° sector of the angle about the centre holds rows.
        std::vector<int> sectors(36, 0);
        for (std::size_t i = 0; i < cap->rows(); ++i) {
            const double dx = cap->columns[kx][i], dy = cap->columns[ky][i] - 0.1;
            if (std::abs(std::hypot(dx, dy) - 0.01) > 20e-6)
                continue;
            const double deg = std::atan2(dy, dx) * 180.0 / std::numbers::pi + 180.0;
            ++sectors[static_cast<std::size_t>(std::min(35.0, deg / 10.0))];
        }
        for (std::size_t k = 0; k < sectors.size(); ++k)
            QVERIFY2(sectors[k] > 0, qPrintable(QString("no row on the circle in sector %1").arg(k)));
        s->setXy(true, "table_pos_m", "Y.table_pos_m");
        QCOMPARE(s->xyPlot()->curveCount(), 1);
        QVERIFY(s->xyPlot()->equalScales()); // both in m: one scale, the circle draws round
        axistune::testing::maybeScreenshot(w.scopeDock(), "scope-dock-xy-circle");
        s->setXy(true, "table_pos_m", "t_s");
        QVERIFY(!s->xyPlot()->equalScales());
    }

    void rollModeKeepsABoundedHistoryOfEverySample()
    {
        MainWindow w(storePath());
        QVERIFY(open(w));
        ScopeDock* s = w.scope();
        QVERIFY(s->selectChannels({"t_s", "motor_vel_rad_s", "following_error_m"}));
        s->setRollMode(true);
        s->setHistoryRows(1000);
        s->runNormal();
        QVERIFY(s->running());
        // The embedded drive runs 50 ms (200 rows) per poll: the 1000-row ring is full after 5 polls and
        // drops its oldest rows from then on.
        QVERIFY(waitUntil([&] { return s->history().droppedRows() > 400; }, 20000));
        const auto& h = s->history();
        QCOMPARE(h.size(), std::size_t{1000});
        QCOMPARE(h.capacity(), std::size_t{1000});
        QCOMPARE(h.bytes(), std::size_t{1000 * (3 * 8 + 8)});
        QCOMPARE(h.lostSamples(), std::uint64_t{0});
        QCOMPARE(h.repeatedRows(), std::uint64_t{0});
        s->stop();
        QVERIFY(!s->running());
        const auto cap = s->capture();
        QVERIFY(cap && !cap->triggered);
        QCOMPARE(cap->rows(), std::size_t{1000});
        QCOMPARE(cap->missingSamples(), std::uint64_t{0});
        QCOMPARE(cap->samples.back() + 1, h.nextSample());
        const int ts = column(*cap, "t_s");
        for (std::size_t i = 0; i < cap->rows(); ++i)
            QVERIFY(std::abs(cap->columns[ts][i] - static_cast<double>(cap->samples[i]) / kRateHz) <= 1e-12);
    }

    void scopeRequestsAreServedWhileATestRuns()
    {
        // The drive thread serves scope requests between the polls of a running test: a poll sent while a long
        // FRF test runs answers before the test ends, with the rows the scope took of the test's motion.
        axistune::gui::DriveController dc;
        dc.connectTo("sim:vmc", 7);
        QVERIFY(waitUntil([&] { return dc.isConnected(); }, 20000));
        axistune::device::ScopeRequest r;
        r.axis = "X";
        r.channels = {"t_s", "injection_Nm"};
        r.mode = axistune::device::ScopeMode::Roll;
        bool armed = false;
        QObject::connect(dc.armScope(r), &axistune::gui::DriveRequest::finished,
                         [&](const axistune::gui::DriveReply& reply) { armed = reply.ok; });
        QVERIFY(waitUntil([&] { return armed; }, 10000));
        QPointer<axistune::gui::DriveRequest> test = dc.runTest(axistune::testing::longFrf("X"));
        bool testDone = false, running = false;
        QObject::connect(test.data(), &axistune::gui::DriveRequest::progress,
                         [&](double fraction, const QString&) { running = running || fraction >= 0.2; });
        QObject::connect(test.data(), &axistune::gui::DriveRequest::finished, [&] { testDone = true; });
        QVERIFY(waitUntil([&] { return running; }, 20000));
        std::shared_ptr<const axistune::device::ScopeRows> rows;
        bool polled = false, testDoneAtPoll = true;
        QObject::connect(dc.pollScope(std::uint64_t{0}, 0), &axistune::gui::DriveRequest::finished,
                         [&](const axistune::gui::DriveReply& reply) {
                             polled = reply.ok;
                             rows = reply.scopeRows;
                             testDoneAtPoll = testDone;
                         });
        QVERIFY(waitUntil([&] { return polled || testDone; }, 20000));
        QVERIFY(polled);
        QVERIFY(!testDoneAtPoll);
        QVERIFY(rows && rows->rows > 0);
        // The scope sampled the test: the injected torque is not zero in the rows read.
        double peak = 0.0;
        for (std::size_t i = 0; i < rows->rows; ++i)
            peak = std::max(peak, std::abs(rows->values[i * 2 + 1]));
        QVERIFY2(peak > 0.0, "no injection seen by the scope during the FRF test");
        dc.abort();
        QVERIFY(waitUntil([&] { return testDone; }, 20000));
    }

    void badRequestsAreRefusedNamingTheControl()
    {
        MainWindow w(storePath());
        QVERIFY(open(w));
        ScopeDock* s = w.scope();
        QVERIFY(s->selectChannels({}));
        s->runSingle();
        QVERIFY(!s->running());
        QVERIFY(!s->messageText().isEmpty());
        if (m_lang == "en")
            QVERIFY2(s->messageText().startsWith("Channels:"), qPrintable(s->messageText()));
        QVERIFY(s->selectChannels({"motor_vel_rad_s"}));
        s->setTrigger("motor_vel_rad_s", 1.0, ScopeEdge::Rising, 50.0, 0.001); // 4 rows: fine
        QVERIFY(s->request(true).ok());
        s->setDivider(1000); // 4 Hz: 0.001 s is not two samples
        s->setTrigger("motor_vel_rad_s", 1.0, ScopeEdge::Rising, 50.0, 0.001);
        auto r = s->request(true);
        QVERIFY(!r.ok());
        if (m_lang == "en")
            QVERIFY2(r.error().detail.starts_with("Length: 0.001 s is shorter than two samples at 4 Hz"),
                     r.error().detail.c_str());
        QVERIFY(!s->selectChannels({"no_such_channel"}));
    }
};

QTEST_MAIN(TestScopeDock)
#include "tst_scopedock.moc"

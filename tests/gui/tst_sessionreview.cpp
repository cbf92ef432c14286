// SPDX-License-Identifier: GPL-3.0-or-later
// Session review on a store built by the test: two sessions with analytic FRFs (stored through
// store::frfAsCapture) and a trace, one aborted session. The list shows them (the aborted one marked),
// an opened session plots the stored values, two sessions overlay, and the CSV export re-reads to the
// same values.
#include "app/gui/AppContext.h"
#include "app/gui/SessionReview.h"
#include "app/gui/SessionReviewView.h"
#include "core/store/SessionRecord.h"
#include "tests/gui/GuiTestUtil.h"

#include "core/io/CaptureCsv.h"
#include "core/io/FrfCsv.h"
#include "core/store/FrfCapture.h"
#include "widgets/BodePlot.h"
#include "widgets/TimeTracePlot.h"

#include <QCoreApplication>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <numbers>
#include <nlohmann/json.hpp>

using axistune::gui::SessionReview;
using axistune::gui::SessionView;

namespace {
/// Second-order resonance H(f) = wn² / (wn² − w² + j·2ζ·wn·w): independent of the code under test.
std::complex<double> resonance(double fHz, double fnHz, double zeta)
{
    const double w = 2.0 * std::numbers::pi * fHz, wn = 2.0 * std::numbers::pi * fnHz;
    return wn * wn / std::complex<double>(wn * wn - w * w, 2.0 * zeta * wn * w);
}

axistune::dsp::FrequencyResponse analyticFrf(double fnHz, double zeta)
{
    axistune::dsp::FrequencyResponse frf;
    for (int i = 0; i < 200; ++i) {
        const double f = 10.0 * std::pow(10.0, 2.5 * i / 199.0);  // 10 Hz .. 3.16 kHz
        frf.push(f, resonance(f, fnHz, zeta), std::nan(""), f < 2000.0);  // above 2 kHz: not valid
    }
    frf.metadata.set("method", "analytic");
    return frf;
}

axistune::model::Capture stepTrace()
{
    axistune::model::Capture c;
    c.metadata.set("fs_Hz", 4000.0);
    axistune::model::Channel t{"t_s", {}}, v{"motor_vel_rad_s", {}};
    for (int i = 0; i < 400; ++i) {
        t.data.push_back(i / 4000.0);
        v.data.push_back(10.0 * (1.0 - std::exp(-i / 40.0)) + 1e-3 * std::sin(0.37 * i));
    }
    c.channels = {t, v};
    return c;
}
}  // namespace

class TestSessionReview : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    std::int64_t m_s1 = 0, m_s2 = 0, m_s3 = 0;
    std::unique_ptr<axistune::gui::AppContext> m_ctx;

private slots:
    void initTestCase()
    {
        axistune::testing::installLanguageFromEnv();
        QVERIFY(m_dir.isValid());
        const std::string path = m_dir.filePath("store.sqlite").toStdString();
        {
            auto opened = axistune::store::Database::open(path);
            QVERIFY(opened.ok());
            auto& db = opened.value();
            axistune::store::SessionRecord a;
            a.info.machine = "vmc";
            a.info.axis = "X";
            a.info.kind = "frf";
            a.info.operatorName = "tester";
            a.machineAxes = {"X", "Y", "Z"};
            a.inputs = {{"fmin_Hz", 10.0}, {"fmax_Hz", 3160.0}};
            a.captures.push_back({"measured", axistune::store::frfAsCapture(analyticFrf(600.0, 0.05))});
            a.captures.push_back({"step", stepTrace()});
            a.results.push_back({"resonances", nlohmann::json::array({600.0}), {}});
            auto id1 = db.recordSession(a);
            QVERIFY(id1.ok());
            m_s1 = *id1;

            axistune::store::SessionRecord b = a;
            b.captures = {{"measured", axistune::store::frfAsCapture(analyticFrf(800.0, 0.02))}};
            auto id2 = db.recordSession(b);
            QVERIFY(id2.ok());
            m_s2 = *id2;

            axistune::store::SessionRecord c;
            c.info.machine = "vmc";
            c.info.axis = "Y";
            c.info.kind = "notch";
            c.info.status = axistune::store::SessionStatus::Aborted;
            c.info.note = "connection lost during the verification";
            auto id3 = db.recordSession(c);
            QVERIFY(id3.ok());
            m_s3 = *id3;
        }
        m_ctx = std::make_unique<axistune::gui::AppContext>();
        QVERIFY(m_ctx->openDatabase(m_dir.filePath("store.sqlite")));
    }

    void cleanupTestCase() { m_ctx.reset(); }

    void listsTheSessionsAndMarksTheAbortedOne()
    {
        SessionReview review(*m_ctx);
        review.setMachine("vmc");
        QCOMPARE(review.machine(), QString("vmc"));
        const auto ids = review.sessionIds();
        QCOMPARE(ids.size(), 3);
        QVERIFY(ids.contains(m_s1) && ids.contains(m_s2) && ids.contains(m_s3));
        QVERIFY(review.isMarkedAborted(m_s3));
        QVERIFY(!review.isMarkedAborted(m_s1));
        QVERIFY(!review.isMarkedAborted(m_s2));
        // Counts and note in the row.
        QTreeWidget* list = review.sessionList();
        for (int i = 0; i < list->topLevelItemCount(); ++i) {
            auto* item = list->topLevelItem(i);
            if (item->text(SessionReview::ColId).toLongLong() == m_s1) {
                QCOMPARE(item->text(SessionReview::ColCaptures), QString("2"));
                QCOMPARE(item->text(SessionReview::ColResults), QString("1"));
                QCOMPARE(item->text(SessionReview::ColOperator), QString("tester"));
            }
            if (item->text(SessionReview::ColId).toLongLong() == m_s3)
                QVERIFY(item->text(SessionReview::ColNote).contains("connection lost"));
        }
    }

    void openedSessionPlotsTheStoredValues()
    {
        SessionReview review(*m_ctx);
        std::unique_ptr<SessionView> view(review.openSession(m_s1));
        QVERIFY(view);
        view->resize(1000, 700);
        view->show();
        QVERIFY(view->bodePlot());
        const int id = view->responseId("measured");
        QVERIFY(id >= 0);
        QCOMPARE(view->bodePlot()->responseCount(), 1);
        // At stored frequencies the curve is the analytic magnitude (tolerance: float formatting, 1e-6 dB).
        const auto frf = analyticFrf(600.0, 0.05);
        for (std::size_t i : {10u, 80u, 120u, 150u}) {
            const double f = frf.freqHz[i];
            const double expected = 20.0 * std::log10(std::abs(resonance(f, 600.0, 0.05)));
            QVERIFY2(std::abs(view->bodePlot()->magnitudeDbAt(id, f) - expected) < 1e-6,
                     qPrintable(QString("%1 Hz: %2 vs %3").arg(f).arg(view->bodePlot()->magnitudeDbAt(id, f)).arg(expected)));
        }
        // Near the resonance the peak is 1/(2ζ) = 10 (20 dB) within the grid's resolution.
        QVERIFY(std::abs(view->bodePlot()->magnitudeDbAt(id, 600.0) - 20.0) < 1.0);
        // The invalid points above 2 kHz are marked by a band; the trace has its own plot.
        QVERIFY(view->bodePlot()->bandCount() >= 1);
        QCOMPARE(view->tracePlots().size(), std::size_t(1));
        QVERIFY(view->tracePlots()[0]->seriesNames().contains("motor_vel_rad_s"));
        axistune::testing::maybeScreenshot(view.get(), "session-review");
    }

    void overlayOfTwoSessionsShowsBothResponses()
    {
        SessionReview review(*m_ctx);
        std::unique_ptr<axistune::gui::SessionOverlay> overlay(review.overlaySessions({m_s1, m_s2}));
        QVERIFY(overlay);
        const QStringList names = overlay->responseNames();
        QCOMPARE(names.size(), 2);
        // The legend text in the running language (AXISTUNE_LANG=ja for the Japanese screenshots).
        const QString legend = QCoreApplication::translate("axistune::gui::SessionOverlay", "session %1: %2");
        QCOMPARE(names[0], legend.arg(m_s1).arg("measured"));
        QCOMPARE(names[1], legend.arg(m_s2).arg("measured"));
        // Each curve is its own session's response: at the stored point nearest 800 Hz (the second
        // session's resonance, ζ = 0.02) the analytic magnitudes of 600 Hz and 800 Hz resonances.
        const auto grid = analyticFrf(800.0, 0.02).freqHz;
        const double f = *std::min_element(grid.begin(), grid.end(), [](double a, double b) {
            return std::abs(a - 800.0) < std::abs(b - 800.0);
        });
        QVERIFY(std::abs(overlay->bodePlot()->magnitudeDbAt(0, f) - 20.0 * std::log10(std::abs(resonance(f, 600.0, 0.05)))) < 1e-6);
        QVERIFY(std::abs(overlay->bodePlot()->magnitudeDbAt(1, f) - 20.0 * std::log10(std::abs(resonance(f, 800.0, 0.02)))) < 1e-6);
        overlay->resize(1000, 700);
        axistune::testing::maybeScreenshot(overlay.get(), "session-review-overlay");
    }

    void csvExportReReadsToTheSameValues()
    {
        SessionReview review(*m_ctx);
        std::unique_ptr<SessionView> view(review.openSession(m_s1));
        QVERIFY(view);
        QTemporaryDir out;
        QStringList files;
        QString err;
        QVERIFY2(view->exportCsv(out.path(), &files, &err), qPrintable(err));
        QCOMPARE(files.size(), 2);
        const QString stepFile = out.filePath(QString("session%1-step.csv").arg(m_s1));
        QVERIFY(files.contains(stepFile));
        auto back = axistune::io::readCaptureCsvFile(stepFile.toStdString());
        QVERIFY2(back.ok(), back.ok() ? "" : back.error().detail.c_str());
        const auto original = stepTrace();
        QCOMPARE(back->channels.size(), original.channels.size());
        for (std::size_t c = 0; c < original.channels.size(); ++c) {
            QCOMPARE(back->channels[c].name, original.channels[c].name);
            QCOMPARE(back->channels[c].data, original.channels[c].data);  // shortest round-trip text: exact
        }
        auto frf = axistune::io::readFrfCsvFile(out.filePath(QString("session%1-measured.csv").arg(m_s1)).toStdString());
        QVERIFY(frf.ok());
        const auto ref = analyticFrf(600.0, 0.05);
        QCOMPARE(frf->size(), ref.size());
        for (std::size_t i = 0; i < ref.size(); i += 37) {
            QCOMPARE(frf->freqHz[i], ref.freqHz[i]);
            QVERIFY(std::abs(frf->h[i] - ref.h[i]) <= 1e-12 * std::abs(ref.h[i]));
            QCOMPARE(static_cast<bool>(frf->valid[i]), static_cast<bool>(ref.valid[i]));
        }
        // Images of every plot.
        QStringList images;
        QVERIFY2(view->exportImages(out.path(), "png", &images, &err), qPrintable(err));
        QCOMPARE(images.size(), 2);
        for (const auto& f : images)
            QVERIFY(QFileInfo(f).size() > 1000);
    }
};

QTEST_MAIN(TestSessionReview)
#include "tst_sessionreview.moc"

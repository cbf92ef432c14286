// SPDX-License-Identifier: GPL-3.0-or-later
// The notch wizard end to end (issue 8 item 5, "What must be true"): on the simulated dd-table it
// measures, proposes one notch per preset mode (600 Hz, 1 kHz, 3.3 kHz), applies them (read back),
// verifies by a new measurement, stores the session, and the session reopens with the plotted curves;
// the same over Modbus against axistune-simdrive; a simdrive killed during the verification leaves an
// aborted session and a responsive GUI.
//
// The machine: the dd-table preset as it is (sim:dd-table, simdrive --preset dd-table) with all its
// nonlinearities: Coulomb friction, current noise, current-dependent inductance and the 2^29 counts/rev
// encoder (docs/notch.md "End to end on the simulated drive"; the CLI test NotchE2e runs the same
// preset). The wizard's defaults (multi-sweep, 10 Hz … 0.975 × 4 kHz, 240 points, 5 %) are used
// unchanged: with seeds 1, 7 and 42 the three notches land within 0.6 % of the modes and prediction
// and verification agree within 0.61 dB on the 224 points above the wizard's −50 dB floor.
#include "app/gui/AppContext.h"
#include "app/gui/NotchWizard.h"
#include "app/gui/WizardRegistry.h"
#include "tests/app/cli/SimDriveProcess.h"
#include "tests/gui/GuiTestUtil.h"

#include "core/store/Database.h"
#include "core/store/FrfCapture.h"
#include "core/tuning/FrfComparison.h"
#include "widgets/BodePlot.h"
#include "core/store/SessionRecord.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QListWidget>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include <cmath>
#include <csignal>
#include <set>

using axistune::gui::AppContext;
using axistune::gui::DriveReply;
using axistune::gui::NotchWizard;
using axistune::testing::maybeScreenshot;
using axistune::testing::waitUntil;

namespace {

constexpr double kModesHz[] = {600.0, 1000.0, 3300.0};  // resources/machines/dd-table.json "modes"

/// Reads parameters synchronously for the test (the wizard never does this).
axistune::model::ParameterValues readParams(AppContext& ctx, const QString& axis, const QStringList& keys)
{
    axistune::model::ParameterValues out;
    bool done = false;
    int id = 0;
    auto c = QObject::connect(&ctx.drive(), &axistune::gui::DriveController::replied, [&](const DriveReply& r) {
        if (r.id == id) {
            out = r.values;
            done = true;
        }
    });
    id = ctx.drive().readParameters(axis, keys)->id();
    waitUntil([&] { return done; }, 20000);
    QObject::disconnect(c);
    return out;
}

bool connectTo(AppContext& ctx, const QString& uri)
{
    ctx.drive().connectTo(uri);
    return waitUntil([&] { return ctx.drive().isConnected(); }, 20000);
}

void next(NotchWizard& w) { w.button(QWizard::NextButton)->click(); }

}  // namespace

class TestNotchWizard : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    axistune::dsp::FrequencyResponse m_firstMeasured;  ///< from the embedded run, for the kill test's hand-over

    /// Source → safety → measurement → proposal; returns false on a failed step (with QVERIFY output).
    bool measureAndPropose(NotchWizard& w, const QString& shotPrefix);
    bool applyNotches(NotchWizard& w, const QString& shotPrefix);

private slots:
    void initTestCase();
    void embeddedEndToEnd();
    void savedSessionSourceAndAbortRestores();
    void modbusEndToEnd();
    void simdriveKilledDuringVerification();
};

void TestNotchWizard::initTestCase()
{
    axistune::testing::installLanguageFromEnv();
    QVERIFY(m_dir.isValid());
    QVERIFY(axistune::gui::findWizard("notch") != nullptr);
    QCOMPARE(axistune::gui::findWizard("notch")->order, 20);
}

bool TestNotchWizard::measureAndPropose(NotchWizard& w, const QString& shot)
{
    const auto maybeScreenshot = [&shot](QWidget* wid, const QString& name) {
        if (!shot.isEmpty())
            axistune::testing::maybeScreenshot(wid, name);
    };
    w.show();
    if (!waitUntil([&] { return w.currentId() == NotchWizard::kSource; }, 5000))
        return false;
    w.sourcePage()->measureButton()->setChecked(true);
    // Modes are 15–20 dB above their baseline; the open loop L = T/(1−T) of this loop has a 6 dB
    // bump near 2.2 kHz where |L| ≈ −30 dB that the core's default 6 dB threshold finds or not
    // depending on the noise. 10 dB separates the two without doubt.
    w.proposePage()->minHeight()->setValue(10.0);
    maybeScreenshot(&w, shot + "-01-source");
    next(w);
    if (w.currentId() != NotchWizard::kSafety)
        return false;
    if (!waitUntil([&] { return !w.safetyPage()->axis().isEmpty(); }, 5000))
        return false;
    w.safetyPage()->confirmation()->setChecked(true);
    QTest::qWait(300);  // limits and trace rate read
    maybeScreenshot(&w, shot + "-02-safety");
    next(w);
    if (w.currentId() != NotchWizard::kMeasure)
        return false;
    if (!waitUntil([&] { return !w.measurePage()->isRunning(); }, 120000) || !w.measurePage()->succeeded()) {
        qWarning() << "measurement failed:" << w.measurePage()->failure();
        return false;
    }
    maybeScreenshot(&w, shot + "-03-measure");
    next(w);
    if (w.currentId() != NotchWizard::kPropose)
        return false;
    if (!waitUntil([&] { return w.proposePage()->isComplete(); }, 60000))
        return false;
    QTest::qWait(100);
    return true;
}

bool TestNotchWizard::applyNotches(NotchWizard& w, const QString& shot)
{
    const auto maybeScreenshot = [&shot](QWidget* wid, const QString& name) {
        if (!shot.isEmpty())
            axistune::testing::maybeScreenshot(wid, name);
    };
    next(w);
    if (w.currentId() != NotchWizard::kApply)
        return false;
    auto* apply = w.applyPage();
    if (!waitUntil([&] { return !apply->previousValues().empty(); }, 20000))
        return false;
    apply->confirmation()->setChecked(true);
    maybeScreenshot(&w, shot + "-05-apply");
    apply->applyButton()->click();
    if (!waitUntil([&] { return apply->applied(); }, 20000))
        return false;
    return true;
}

void TestNotchWizard::embeddedEndToEnd()
{
    const QString dbPath = m_dir.filePath("embedded.sqlite");
    AppContext ctx;
    QVERIFY(ctx.openDatabase(dbPath));
    QVERIFY(connectTo(ctx, "sim:dd-table"));
    NotchWizard w(ctx);
    QElapsedTimer t;
    t.start();
    QVERIFY(measureAndPropose(w, "notch"));
    qInfo() << "measured and proposed after" << t.elapsed() << "ms";
    m_firstMeasured = w.measured();

    // One notch per preset mode, three in all, each centre within 3 % of its mode.
    const auto rows = w.rows();
    QCOMPARE(static_cast<int>(rows.size()), 3);
    for (double f : kModesHz) {
        int near = 0;
        for (const auto& r : rows)
            near += std::abs(r.spec.centerHz - f) < 0.03 * f ? 1 : 0;
        QVERIFY2(near == 1, qPrintable(QString("mode %1 Hz has %2 notches").arg(f).arg(near)));
    }
    for (const auto& r : rows)
        QVERIFY(!r.rule.isEmpty());
    auto* table = w.proposePage()->notchTable();
    QCOMPARE(table->rowCount(), 3);
    QCOMPARE(w.proposePage()->marginsTable()->rowCount(), 3);
    QVERIFY(w.marginsBefore() && w.marginsPredicted());
    for (const auto& r : w.resonances())
        qInfo() << "resonance" << r.freqHz << "Hz," << r.peakDb << "dB";
    for (const auto& r : rows)
        qInfo() << "notch centre" << r.spec.centerHz << "Hz width" << r.spec.widthHz << "Hz depth" << r.spec.depth;
    qInfo() << "gain margin" << w.marginsBefore()->gainMarginDb << "->" << w.marginsPredicted()->gainMarginDb
            << "dB, peak sensitivity" << w.marginsBefore()->peakSensitivityDb << "->" << w.marginsPredicted()->peakSensitivityDb
            << "dB, phase margin" << w.marginsBefore()->phaseMarginDeg << "->" << w.marginsPredicted()->phaseMarginDeg << "deg";
    // The prediction lowers the peak sensitivity and raises the gain margin (docs/notch.md).
    QVERIFY(w.marginsPredicted()->peakSensitivityDb < w.marginsBefore()->peakSensitivityDb);
    maybeScreenshot(&w, "notch-04-propose");

    // Editing a depth recomputes the prediction: depth 1 (no notch) at the first row brings the
    // predicted peak at that centre back near the measured one (within 1.5 dB: the skirts of the two
    // other notches still act there, 1.1 dB at 1 kHz; with the notch it was more than 6 dB lower).
    const double c0 = rows[0].spec.centerHz;
    const double measuredPeak = axistune::tuning::peakMagnitudeDb(w.measured(), c0, 0.05);
    const double predictedPeak = axistune::tuning::peakMagnitudeDb(w.predicted(), c0, 0.05);
    QVERIFY(measuredPeak - predictedPeak > 6.0);
    table->item(0, 3)->setText("1");
    QCOMPARE(w.rows()[0].spec.depth, 1.0);
    const double undone = axistune::tuning::peakMagnitudeDb(w.predicted(), c0, 0.05);
    qInfo() << "notch at" << c0 << "Hz: measured peak" << measuredPeak << "predicted" << predictedPeak << "with depth 1" << undone;
    QVERIFY(undone > predictedPeak + 10.0);
    QVERIFY(std::abs(undone - measuredPeak) < 1.5);
    w.findChild<QPushButton*>("resetNotches")->click();
    QCOMPARE(w.rows()[0].spec.depth, rows[0].spec.depth);

    // Apply, then the drive's filter.notch* read back equal the proposed centres.
    QVERIFY(applyNotches(w, "notch"));
    QStringList keys;
    for (const auto& r : rows)
        keys << QString("filter.notch%1.center").arg(r.slot);
    const auto back = readParams(ctx, "C", keys);
    for (const auto& r : rows) {
        const auto it = back.find(QString("filter.notch%1.center").arg(r.slot).toStdString());
        QVERIFY(it != back.end());
        QVERIFY(std::abs(it->second - r.spec.centerHz) < 0.01 * r.spec.centerHz);
    }
    maybeScreenshot(&w, "notch-05-apply");

    // Verify: the safety page was confirmed already, so the verification run comes next.
    next(w);
    QCOMPARE(w.currentId(), static_cast<int>(NotchWizard::kVerifyRun));
    QVERIFY(waitUntil([&] { return !w.verifyRunPage()->isRunning(); }, 120000));
    QVERIFY2(w.verifyRunPage()->succeeded(), qPrintable(w.verifyRunPage()->failure()));
    maybeScreenshot(&w, "notch-06-verify-run");
    next(w);
    QCOMPARE(w.currentId(), static_cast<int>(NotchWizard::kVerify));
    maybeScreenshot(&w, "notch-07-verify");
    QVERIFY(w.findChild<QLabel*>("notchDeviation")->text().contains("dB"));
    // At each treated resonance the re-measured peak is lower than the first measurement's by at least
    // the drop the prediction gives, less 1 dB where the prediction is above −50 dB (issue 6: prediction
    // and re-measurement agree within 1 dB there) and less 3.5 dB below (docs/notch.md: the held torque
    // command's images make up to 3.2 dB there, which the single-frequency prediction does not model).
    for (const auto& r : rows) {
        const double f = r.spec.centerHz;
        const double before = axistune::tuning::peakMagnitudeDb(w.measured(), f, 0.05);
        const double pred = axistune::tuning::peakMagnitudeDb(w.predicted(), f, 0.05);
        const double after = axistune::tuning::peakMagnitudeDb(w.verification(), f, 0.05);
        const double tol = pred > -50.0 ? 1.0 : 3.5;
        qInfo() << "notch" << f << "Hz: before" << before << "predicted" << pred << "verified" << after << "dB";
        QVERIFY2(before - after >= (before - pred) - tol,
                 qPrintable(QString("%1 Hz: before %2, predicted %3, verified %4 dB").arg(f).arg(before).arg(pred).arg(after)));
        QVERIFY(after < before);
    }
    // Prediction vs verification within 1 dB (issue 6) on the points the wizard compares: those where
    // the prediction or the re-measurement is above −50 dB (NotchWizard, tuning::compareMagnitudes
    // floor, as NotchE2e); below it, around the notched 3.3 kHz mode, the held torque command's images
    // (not in the prediction) and the preset's noise make up to 3.2 dB (docs/notch.md). 224 of the 240
    // points are compared on the preset; more than 100 must be.
    QVERIFY(w.deviation().points > 100);
    QVERIFY2(w.deviation().maxAbsDb < 1.0, qPrintable(QString::number(w.deviation().maxAbsDb)));
    qInfo() << "prediction vs verification: max" << w.deviation().maxAbsDb << "dB at" << w.deviation().maxAtHz << "Hz, rms"
            << w.deviation().rmsDb << "dB over" << w.deviation().points << "points";

    next(w);
    QCOMPARE(w.currentId(), static_cast<int>(NotchWizard::kSave));
    QVERIFY(w.saved());
    QVERIFY(!w.savedAborted());
    maybeScreenshot(&w, "notch-08-save");
    qInfo() << "embedded run took" << t.elapsed() << "ms";

    // The stored session reopens with the curves the verification plot shows.
    auto db = axistune::store::Database::open(dbPath.toStdString());
    QVERIFY(static_cast<bool>(db));
    auto rec = db->loadSession(w.savedSessionId());
    QVERIFY(static_cast<bool>(rec));
    QCOMPARE(QString::fromStdString(rec->info.kind), QString("notch"));
    QCOMPARE(rec->info.status, axistune::store::SessionStatus::Completed);
    auto* plot = w.verifyPage()->plot();
    const std::map<std::string, int> ids{{"measured", w.verifyPage()->measuredId()},
                                         {"predicted", w.verifyPage()->predictedId()},
                                         {"verification", w.verifyPage()->verificationId()}};
    int found = 0;
    for (const auto& c : rec->captures) {
        const auto it = ids.find(c.name);
        if (it == ids.end())
            continue;
        ++found;
        auto frf = axistune::store::frfFromCapture(c.capture);
        QVERIFY(static_cast<bool>(frf));
        for (std::size_t i : {std::size_t{10}, frf->size() / 3, frf->size() / 2, frf->size() - 5}) {
            if (!frf->valid[i])
                continue;
            const double stored = axistune::dsp::magnitudeDb(frf->h[i]);
            const double shown = plot->magnitudeDbAt(it->second, frf->freqHz[i]);
            QVERIFY2(std::abs(stored - shown) < 1e-6,
                     qPrintable(QString("%1 at %2 Hz: stored %3, plotted %4").arg(c.name.c_str()).arg(frf->freqHz[i]).arg(stored).arg(shown)));
        }
    }
    QCOMPARE(found, 3);
    bool proposed = false, applied = false;
    for (const auto& ps : rec->parameterSets) {
        proposed |= ps.source == axistune::store::ParameterSource::Proposed && ps.values.size() == 9;
        applied |= ps.source == axistune::store::ParameterSource::Applied && ps.values.size() == 9;
    }
    QVERIFY(proposed && applied);
    QCOMPARE(static_cast<int>(rec->journal.size()), 9);
    std::set<std::string> results;
    for (const auto& r : rec->results)
        results.insert(r.name);
    for (const char* n : {"resonances", "notches", "margins", "verification"})
        QVERIFY2(results.count(n), n);
}

void TestNotchWizard::savedSessionSourceAndAbortRestores()
{
    // The FRF of the first test's session as the source; the operator aborts the verification:
    // the applied notches are restored (read back 0 = off) and the session is stored as aborted.
    AppContext ctx;
    QVERIFY(ctx.openDatabase(m_dir.filePath("embedded.sqlite")));
    QVERIFY(connectTo(ctx, "sim:dd-table"));
    NotchWizard w(ctx);
    w.proposePage()->minHeight()->setValue(10.0);
    w.show();
    w.sourcePage()->sessionButton()->setChecked(true);
    auto* list = w.sourcePage()->sessionList();
    int row = -1;
    for (int i = 0; i < list->count(); ++i)
        if (list->item(i)->text().contains("notch") && list->item(i)->text().endsWith(": measured"))
            row = i;
    QVERIFY2(row >= 0, qPrintable(QString::number(list->count())));
    list->setCurrentRow(row);
    next(w);
    QCOMPARE(w.currentId(), static_cast<int>(NotchWizard::kPropose));
    QVERIFY(waitUntil([&] { return w.proposePage()->isComplete(); }, 60000));
    QCOMPARE(static_cast<int>(w.rows().size()), 3);
    QCOMPARE(w.axis(), QString("C"));
    QVERIFY(applyNotches(w, QString()));
    next(w);
    QCOMPARE(w.currentId(), static_cast<int>(NotchWizard::kSafety));  // not confirmed yet in this run
    w.safetyPage()->confirmation()->setChecked(true);
    next(w);
    QCOMPARE(w.currentId(), static_cast<int>(NotchWizard::kVerifyRun));
    w.verifyRunPage()->abortButton()->click();
    QVERIFY(waitUntil([&] { return w.saved(); }, 30000));
    QVERIFY(w.savedAborted());
    QVERIFY2(w.abortReason().contains("restored"), qPrintable(w.abortReason()));
    QStringList keys;
    for (const auto& r : w.rows())
        keys << QString("filter.notch%1.center").arg(r.slot);
    const auto back = readParams(ctx, "C", keys);
    QCOMPARE(static_cast<int>(back.size()), 3);
    for (const auto& [k, v] : back)
        QCOMPARE(v, 0.0);
    auto db = axistune::store::Database::open(m_dir.filePath("embedded.sqlite").toStdString());
    auto rec = db->loadSession(w.savedSessionId());
    QVERIFY(static_cast<bool>(rec));
    QCOMPARE(rec->info.status, axistune::store::SessionStatus::Aborted);
    QCOMPARE(static_cast<int>(rec->journal.size()), 18);  // 9 written, 9 restored
    QVERIFY(rec->inputs.value("source_session", 0) > 0);
}

void TestNotchWizard::modbusEndToEnd()
{
    axistune::testing::SimDrive sd("--preset dd-table");
    QVERIFY2(sd.port() > 0, sd.log().c_str());
    const QString dbPath = m_dir.filePath("modbus.sqlite");
    AppContext ctx;
    QVERIFY(ctx.openDatabase(dbPath));
    QVERIFY(connectTo(ctx, QString::fromStdString(sd.uri())));
    NotchWizard w(ctx);
    QElapsedTimer t;
    t.start();
    QVERIFY(measureAndPropose(w, QString()));
    QCOMPARE(static_cast<int>(w.rows().size()), 3);
    for (double f : kModesHz) {
        bool near = false;
        for (const auto& r : w.rows())
            near |= std::abs(r.spec.centerHz - f) < 0.03 * f;
        QVERIFY(near);
    }
    QVERIFY(applyNotches(w, QString()));
    next(w);
    QCOMPARE(w.currentId(), static_cast<int>(NotchWizard::kVerifyRun));
    QVERIFY(waitUntil([&] { return !w.verifyRunPage()->isRunning(); }, 120000));
    QVERIFY2(w.verifyRunPage()->succeeded(), qPrintable(w.verifyRunPage()->failure()));
    next(w);
    QVERIFY(w.deviation().points > 100);
    QVERIFY2(w.deviation().maxAbsDb < 1.0, qPrintable(QString::number(w.deviation().maxAbsDb)));
    next(w);
    QVERIFY(w.saved() && !w.savedAborted());
    qInfo() << "Modbus run took" << t.elapsed() << "ms";
    auto db = axistune::store::Database::open(dbPath.toStdString());
    auto rec = db->loadSession(w.savedSessionId());
    QVERIFY(static_cast<bool>(rec));
    bool verification = false;
    for (const auto& c : rec->captures)
        verification |= c.name == "verification" && static_cast<bool>(axistune::store::frfFromCapture(c.capture));
    QVERIFY(verification);
}

void TestNotchWizard::simdriveKilledDuringVerification()
{
    QVERIFY(!m_firstMeasured.empty());
    // Real-time pace: the 53 s verification sweep is still running at the kill.
    axistune::testing::SimDrive sd("--preset dd-table --pace 1");
    QVERIFY2(sd.port() > 0, sd.log().c_str());
    const QString dbPath = m_dir.filePath("kill.sqlite");
    AppContext ctx;
    QVERIFY(ctx.openDatabase(dbPath));
    QVERIFY(connectTo(ctx, QString::fromStdString(sd.uri("timeout_ms=500"))));
    NotchWizard w(ctx);
    // Hand-over as from the FRF wizard: the wizard opens at the proposal.
    w.setSourceFrf(m_firstMeasured, "C", "frf wizard");
    w.proposePage()->minHeight()->setValue(10.0);
    w.show();
    QCOMPARE(w.currentId(), static_cast<int>(NotchWizard::kPropose));
    QVERIFY(waitUntil([&] { return w.proposePage()->isComplete(); }, 60000));
    QCOMPARE(static_cast<int>(w.rows().size()), 3);
    QVERIFY(applyNotches(w, QString()));
    next(w);  // → safety (not confirmed yet in this run)
    QCOMPARE(w.currentId(), static_cast<int>(NotchWizard::kSafety));
    w.safetyPage()->confirmation()->setChecked(true);
    next(w);
    QCOMPARE(w.currentId(), static_cast<int>(NotchWizard::kVerifyRun));
    QVERIFY(waitUntil([&] { return sd.log().find("started on axis C") != std::string::npos; }, 15000));
    QTest::qWait(300);
    QVERIFY(w.verifyRunPage()->isRunning());
    sd.stop(SIGKILL);

    QVERIFY(waitUntil([&] { return w.saved(); }, 20000));
    QVERIFY(w.savedAborted());
    QVERIFY(!w.verifyRunPage()->succeeded());
    QVERIFY2(w.verifyRunPage()->failure().contains("onnection", Qt::CaseInsensitive), qPrintable(w.verifyRunPage()->failure()));
    maybeScreenshot(&w, "notch-09-connection-lost");
    auto* note = w.findChild<QLabel*>("verifyAbortNote");
    QVERIFY(note && note->text().contains("aborted"));
    // Responsive: a 10 ms timer fires within 500 ms, and the wizard still reacts to input.
    QElapsedTimer lat;
    lat.start();
    bool fired = false;
    QTimer::singleShot(10, [&] { fired = true; });
    QVERIFY(waitUntil([&] { return fired; }, 500));
    qInfo() << "event loop answered after" << lat.elapsed() << "ms";
    QVERIFY(w.button(QWizard::CancelButton)->isEnabled());

    auto db = axistune::store::Database::open(dbPath.toStdString());
    auto list = db->listSessions("dd-table");
    QVERIFY(static_cast<bool>(list));
    bool found = false;
    for (const auto& s : *list)
        if (s.id == w.savedSessionId()) {
            found = true;
            QCOMPARE(s.status, axistune::store::SessionStatus::Aborted);
            QCOMPARE(QString::fromStdString(s.kind), QString("notch"));
            QVERIFY(QString::fromStdString(s.note).contains("onnection", Qt::CaseInsensitive));
        }
    QVERIFY(found);
    auto rec = db->loadSession(w.savedSessionId());
    QVERIFY(static_cast<bool>(rec));
    QCOMPARE(QString::fromStdString(rec->inputs.value("source", std::string())), QString("frf wizard"));
    int captures = 0;
    for (const auto& c : rec->captures)
        captures += (c.name == "measured" || c.name == "predicted") ? 1 : 0;
    QCOMPARE(captures, 2);
    QVERIFY(!rec->journal.empty());
    w.reject();  // closing after the abort does not save again
    QCOMPARE(db->listSessions("dd-table")->size(), list->size());
}

QTEST_MAIN(TestNotchWizard)
#include "tst_notchwizard.moc"

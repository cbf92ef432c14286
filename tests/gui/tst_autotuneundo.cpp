// SPDX-License-Identifier: GPL-3.0-or-later
// Undo of an applied one-button tune in the wizard (issue 18 item 5, "apply with diff, journal and undo";
// docs/tuning.md "Undo in the wizard"), on the embedded sim:vmc X as tst_autotunewizard (standard style, 6 s budget):
// (a) run, apply, read every parameter: the drive holds final.parameters; while another test runs (a dry run of the
// tuner) Undo is disabled; Undo shows the diff (applied → before, in each parameter's display unit) and, confirmed,
// every parameter of the axis equals its value before the tune, and the session "autotune-undo" journals each
// parameter applied → before; (b) a parameter the run applied is changed afterwards: Undo is refused naming that
// key, nothing is written (every parameter as after the change), the journal gains nothing; "Undo anyway" needs the
// box ticked and then writes every value before the tune, the changed one included.
#include "app/gui/AppContext.h"
#include "app/gui/AutoTuneWizard.h"
#include "core/model/Units.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QListWidget>
#include <QListWidget>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

#include "core/store/SessionRecord.h"
#include "tests/gui/AutoTuneTestUtil.h"
#include "tests/gui/GuiTestUtil.h"

using namespace axistune;
using namespace axistune::gui;
using axistune::testing::maybeScreenshot;
using axistune::testing::openOn;
using axistune::testing::readAll;
using axistune::testing::waitUntil;

namespace {

// The smallest budget that completes on vmc X (tst_autotunewizard, docs/tuning.md "The wizard").
constexpr double kBudgetS = 6.0;

std::vector<model::ParameterMeta> readMeta(AppContext& ctx, const QString& axis)
{
    std::vector<model::ParameterMeta> out;
    bool done = false;
    QObject::connect(ctx.drive().readMetadata(axis), &DriveRequest::finished, [&](const DriveReply& r) {
        out = r.metadata;
        done = true;
    });
    waitUntil([&] { return done; }, 20000);
    return out;
}

bool writeOne(AppContext& ctx, const QString& axis, const std::string& key, double value)
{
    bool done = false, ok = false;
    QObject::connect(ctx.drive().writeParameters(axis, {{key, value}}), &DriveRequest::finished,
                     [&](const DriveReply& r) {
                         ok = r.ok;
                         done = true;
                     });
    waitUntil([&] { return done; }, 20000);
    return ok;
}

/// Runs the tuner to its end on vmc X (applied) and shows the result page with Undo offered.
void tuneAndShowResult(AutoTuneWizard& w)
{
    w.resize(1100, 760);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    auto* c = w.choicePage();
    QVERIFY(waitUntil([&] { return c->axis()->findText("X") >= 0; }, 5000));
    c->axis()->setCurrentText("X");
    QVERIFY(c->styleButton(autotune::Style::Standard)->isChecked());
    c->timeBudget()->setValue(kBudgetS);
    c->confirmation()->setChecked(true);
    QVERIFY(c->isComplete());
    w.next();
    QVERIFY(waitUntil([&] { return w.runPage()->isComplete(); }, 60000));
    const auto r = w.data().result;
    QVERIFY(r);
    QVERIFY2(r->outcome == autotune::Outcome::Applied, r->reason.c_str());
    QVERIFY(r->final && !r->final->parameters.empty());
    w.next();
    QCOMPARE(w.currentId(), int(AutoTuneWizard::Result));
    auto* res = w.resultPage();
    QVERIFY(!res->undoButton()->isHidden());
    QVERIFY(res->undoAnywayButton()->isHidden());
    QVERIFY(waitUntil([&] { return res->undoButton()->isEnabled(); }, 10000)); // after the units arrived
    QVERIFY(waitUntil([&] { return w.data().sessionId > 0; }, 20000));
}

/// The first number of a cell ("0.0125", "-3e-05").
double cellNumber(QTableWidget* t, int row, int col)
{
    bool ok = false;
    const double v = t->item(row, col)->text().toDouble(&ok);
    return ok ? v : std::nan("");
}

/// Opens the confirmation with `button`, returns it.
QDialog* openConfirmation(AutoTuneResultPage* res, QPushButton* button)
{
    button->click();
    QDialog* d = nullptr;
    waitUntil(
        [&] {
            d = res->undoDialog();
            return d && d->isVisible();
        },
        5000);
    return d;
}

void pressOk(QDialog* d)
{
    auto* box = d->findChild<QDialogButtonBox*>("atUndoButtons");
    QVERIFY(box);
    QVERIFY(box->button(QDialogButtonBox::Ok)->isEnabled());
    box->button(QDialogButtonBox::Ok)->click();
}

/// The newest saved session, once `spy` has seen `count` saves.
store::SessionRecord savedSession(AppContext& ctx, QSignalSpy& spy, int count)
{
    waitUntil([&] { return spy.count() >= count; }, 20000);
    if (spy.count() < count)
        return {};
    auto s = ctx.database()->loadSession(spy.at(count - 1).at(0).toLongLong());
    return s ? *s : store::SessionRecord{};
}

} // namespace

class TestAutoTuneUndo : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { axistune::testing::installLanguageFromEnv(); }

    void undoPutsBackEveryParameterAndJournalsIt()
    {
        QTemporaryDir dir;
        AppContext ctx;
        model::ParameterValues before;
        openOn(dir, ctx, before);
        QVERIFY(!before.empty());
        const auto metas = readMeta(ctx, "X");
        AutoTuneWizard w(ctx);
        tuneAndShowResult(w);
        if (QTest::currentTestFailed())
            return;
        auto* res = w.resultPage();
        const auto r = w.data().result;
        const auto& applied = r->final->parameters;

        // Applied: every parameter read, final.parameters where the run wrote, its value before elsewhere. The
        // embedded simulator keeps doubles, so the values are exact (a Modbus drive stores float32: 1e-6 relative,
        // the drive link's read-back tolerance, kReadBackRel).
        const auto after = readAll(ctx, "X");
        QCOMPARE(after.size(), before.size());
        int changedByRun = 0;
        for (const auto& [k, v] : after) {
            const auto it = applied.find(k);
            QCOMPARE(v, it != applied.end() ? it->second : before.at(k));
            changedByRun += it != applied.end() && it->second != before.at(k);
        }
        QVERIFY(changedByRun > 0); // the undo has something to undo

        // Undo is disabled while a test runs (here a dry run of the tuner on the same axis; it restores what it
        // wrote) and enabled again after it.
        autotune::Options dry = w.data().options;
        dry.dryRun = true;
        bool dryDone = false;
        QObject::connect(ctx.drive().runAutoTune(dry), &DriveRequest::finished,
                         [&](const DriveReply&) { dryDone = true; });
        QVERIFY(ctx.drive().isTestRunning());
        QVERIFY(!res->undoButton()->isEnabled());
        QVERIFY(waitUntil([&] { return dryDone; }, 60000));
        QVERIFY(res->undoButton()->isEnabled());
        QCOMPARE(readAll(ctx, "X"), after);

        // The confirmation: one row per applied parameter, applied → before in its display unit (6 significant
        // digits shown: equal within half a unit of the 6th digit, 5e-6 relative), the unit's label.
        QSignalSpy saved(&ctx, &AppContext::sessionSaved);
        QDialog* d = openConfirmation(res, res->undoButton());
        QVERIFY(d);
        QVERIFY(!res->undoButton()->isEnabled()); // not twice
        auto* diff = d->findChild<QTableWidget*>("atUndoDiff");
        QVERIFY(diff);
        QCOMPARE(diff->rowCount(), int(applied.size()));
        QCOMPARE(diff->columnCount(), 4);
        int row = 0;
        for (const auto& [k, v] : applied) {
            const auto* m = model::findParameter(metas, k);
            QVERIFY2(m, k.c_str());
            QVERIFY2(diff->item(row, 0)->text().contains(QString::fromStdString(k)), k.c_str());
            const double shownApplied = *model::convertUnit(v, m->siUnit, m->displayUnit);
            const double shownBefore = *model::convertUnit(before.at(k), m->siUnit, m->displayUnit);
            QVERIFY2(std::abs(cellNumber(diff, row, 1) - shownApplied) <= 5e-6 * std::abs(shownApplied) + 1e-300,
                     qPrintable(diff->item(row, 1)->text()));
            QVERIFY2(std::abs(cellNumber(diff, row, 2) - shownBefore) <= 5e-6 * std::abs(shownBefore) + 1e-300,
                     qPrintable(diff->item(row, 2)->text()));
            QCOMPARE(diff->item(row, 3)->text(), QString::fromStdString(model::unitLabel(m->displayUnit)));
            ++row;
        }
        maybeScreenshot(d, "autotune-07-undo-confirm");
        axistune::testing::TickMeter ticks;
        pressOk(d);
        QVERIFY(waitUntil([&] { return !res->isUndoing(); }, 20000));
        ticks.stop();
        qInfo("undo: the GUI thread's longest stall while it ran: %lld ms", ticks.maxGapMs());
        QVERIFY2(res->isUndone(), qPrintable(res->undoState()->text()));
        QVERIFY(!res->undoButton()->isEnabled());
        QVERIFY(res->undoAnywayButton()->isHidden());

        // Every parameter of the axis equals its value before the tune (exact on the embedded simulator, see above).
        QCOMPARE(readAll(ctx, "X"), before);

        // The journal: a session "autotune-undo" with one entry per applied parameter, applied → before.
        const auto s = savedSession(ctx, saved, 1);
        QCOMPARE(QString::fromStdString(s.info.kind), QString("autotune-undo"));
        QCOMPARE(s.info.status, store::SessionStatus::Completed);
        QCOMPARE(s.inputs["undoes_session"].get<qint64>(), w.data().sessionId);
        QCOMPARE(s.journal.size(), applied.size());
        for (const auto& e : s.journal) {
            QVERIFY2(applied.count(e.key), e.key.c_str());
            QVERIFY(e.oldValue);
            QCOMPARE(*e.oldValue, applied.at(e.key));
            QCOMPARE(e.newValue, before.at(e.key));
        }
        // The store's journal of the machine: the run's entries and the undo's.
        auto journal = ctx.database()->journal(ctx.machine().toStdString());
        QVERIFY(journal.ok());
        QCOMPARE(journal->size(), 2 * applied.size());
        maybeScreenshot(&w, "autotune-08-undone");
    }

    // An earlier run, from its saved session in a new wizard: the first page lists it, the result page shows what it
    // applied (before → applied, from the session's result) and its Undo writes back every value before the run.
    void undoOfAnEarlierRunFromItsSession()
    {
        QTemporaryDir dir;
        AppContext ctx;
        model::ParameterValues before;
        openOn(dir, ctx, before);
        QVERIFY(!before.empty());
        qint64 session = 0;
        model::ParameterValues applied;
        {
            AutoTuneWizard w(ctx);
            tuneAndShowResult(w);
            if (QTest::currentTestFailed())
                return;
            session = w.data().sessionId;
            applied = w.data().result->final->parameters;
        }
        QVERIFY(readAll(ctx, "X") != before);

        AutoTuneWizard w(ctx);
        w.resize(1100, 760);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* c = w.choicePage();
        QVERIFY(c->undoEarlierButton()->isEnabled());
        c->undoEarlierButton()->click();
        QDialog* d = nullptr;
        QVERIFY(waitUntil(
            [&] {
                d = c->findChild<QDialog*>("atEarlierRuns");
                return d && d->isVisible();
            },
            5000));
        auto* list = d->findChild<QListWidget*>("atEarlierList");
        QVERIFY(list);
        QCOMPARE(list->count(), 1); // the one applied run
        QCOMPARE(list->item(0)->data(Qt::UserRole).value<qint64>(), session);
        maybeScreenshot(d, "autotune-11-earlier-runs");
        d->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Open)->click();
        QVERIFY(waitUntil([&] { return w.currentId() == int(AutoTuneWizard::Result); }, 5000));
        auto* res = w.resultPage();
        // One row per applied parameter, before → applied as the run wrote them.
        QCOMPARE(res->parameters()->rowCount(), int(applied.size()));
        QVERIFY(waitUntil([&] { return res->undoButton()->isEnabled(); }, 10000));
        maybeScreenshot(&w, "autotune-12-earlier-run");
        QSignalSpy saved(&ctx, &AppContext::sessionSaved);
        QDialog* confirm = openConfirmation(res, res->undoButton());
        QVERIFY(confirm);
        QCOMPARE(confirm->findChild<QTableWidget*>("atUndoDiff")->rowCount(), int(applied.size()));
        pressOk(confirm);
        QVERIFY(waitUntil([&] { return !res->isUndoing(); }, 20000));
        QVERIFY2(res->isUndone(), qPrintable(res->undoState()->text()));
        // Every parameter of the axis equals its value before the tune (exact on the embedded simulator).
        QCOMPARE(readAll(ctx, "X"), before);
        const auto s = savedSession(ctx, saved, 1);
        QCOMPARE(QString::fromStdString(s.info.kind), QString("autotune-undo"));
        QCOMPARE(s.inputs["undoes_session"].get<qint64>(), session);
        // Back to the first page: the earlier run is forgotten, a new run goes to the run page again.
        w.back();
        QCOMPARE(w.currentId(), int(AutoTuneWizard::Choice));
        QVERIFY(!w.data().stored);
        QCOMPARE(c->nextId(), int(AutoTuneWizard::Run));
    }

    void undoRefusesAChangedParameterThenUndoAnywayWrites()
    {
        QTemporaryDir dir;
        AppContext ctx;
        model::ParameterValues before;
        openOn(dir, ctx, before);
        QVERIFY(!before.empty());
        AutoTuneWizard w(ctx);
        tuneAndShowResult(w);
        if (QTest::currentTestFailed())
            return;
        auto* res = w.resultPage();
        const auto& applied = w.data().result->final->parameters;

        // A parameter the run changed is changed again by hand: half way back to its value before (inside the
        // drive's limits, since both ends are values the drive accepted).
        std::string key;
        for (const auto& [k, v] : applied)
            if (v != before.at(k)) {
                key = k;
                break;
            }
        QVERIFY(!key.empty());
        const double changedTo = 0.5 * (applied.at(key) + before.at(key));
        QVERIFY(writeOne(ctx, "X", key, changedTo));
        const auto changed = readAll(ctx, "X");
        QCOMPARE(changed.at(key), changedTo);

        // Undo: refused, the key named, nothing written.
        QSignalSpy saved(&ctx, &AppContext::sessionSaved);
        QDialog* d = openConfirmation(res, res->undoButton());
        QVERIFY(d);
        pressOk(d);
        QVERIFY(waitUntil([&] { return !res->isUndoing() && !res->undoDialog(); }, 20000));
        QVERIFY(!res->isUndone());
        const QString refusal = res->undoState()->text();
        QVERIFY2(refusal.contains(QString::fromStdString(key)), qPrintable(refusal));
        QVERIFY2(refusal.startsWith(AutoTuneResultPage::tr("Undo refused, nothing written: %1 is %2 %3 on the drive, "
                                                           "not the %4 %3 the run applied. It was changed after the "
                                                           "run, and undoing would overwrite that change.")
                                        .section(':', 0, 0)),
                 qPrintable(refusal));
        QCOMPARE(readAll(ctx, "X"), changed);
        const auto refused = savedSession(ctx, saved, 1);
        QCOMPARE(QString::fromStdString(refused.info.kind), QString("autotune-undo"));
        QCOMPARE(refused.info.status, store::SessionStatus::Failed);
        QVERIFY(refused.journal.empty());
        QCOMPARE(refused.result("undo")->at("changed").at(0).at("key").get<std::string>(), key);
        maybeScreenshot(&w, "autotune-09-undo-refused");

        // Undo anyway: offered now; its confirmation marks the changed key and needs the box ticked.
        QVERIFY(!res->undoAnywayButton()->isHidden());
        QVERIFY(res->undoAnywayButton()->isEnabled());
        d = openConfirmation(res, res->undoAnywayButton());
        QVERIFY(d);
        auto* diff = d->findChild<QTableWidget*>("atUndoDiff");
        QVERIFY(diff);
        QCOMPARE(diff->columnCount(), 5);
        auto* box = d->findChild<QDialogButtonBox*>("atUndoButtons");
        auto* overwrite = d->findChild<QCheckBox*>("atUndoOverwrite");
        QVERIFY(box && overwrite);
        QVERIFY(overwrite->text().contains(QString::fromStdString(key)));
        QVERIFY(!box->button(QDialogButtonBox::Ok)->isEnabled());
        overwrite->setChecked(true);
        maybeScreenshot(d, "autotune-10-undo-anyway");
        pressOk(d);
        QVERIFY(waitUntil([&] { return !res->isUndoing() && !res->undoDialog(); }, 20000));
        QVERIFY2(res->isUndone(), qPrintable(res->undoState()->text()));
        // Every parameter equals its value before the tune (exact: the embedded simulator keeps doubles).
        QCOMPARE(readAll(ctx, "X"), before);
        const auto forced = savedSession(ctx, saved, 2);
        QCOMPARE(forced.info.status, store::SessionStatus::Completed);
        QVERIFY(forced.inputs["force"].get<bool>());
        QCOMPARE(forced.journal.size(), applied.size());
        for (const auto& e : forced.journal) {
            QVERIFY(e.oldValue);
            QCOMPARE(*e.oldValue, e.key == key ? changedTo : applied.at(e.key));
            QCOMPARE(e.newValue, before.at(e.key));
        }
    }
};

QTEST_MAIN(TestAutoTuneUndo)
#include "tst_autotuneundo.moc"

// SPDX-License-Identifier: GPL-3.0-or-later
// The one-button tuning wizard on the embedded sim:vmc X (issue 18 item 5; docs/tuning.md "The wizard"):
// (a) the sequence to its end: the result page shows the re-measured margins of the core result (to the shown
// digit), they meet the standard style's acceptance (PM >= 45 deg, GM >= 6 dB; docs/tuning.md "Styles"), every
// parameter of the drive equals final.parameters where the run wrote it and its value before elsewhere, and the
// session "autotune" holds the result JSON; (b) Abort pressed when the progress first passes 30 % (the adaptive
// FRF, nothing written yet) and 70 % (after the gains were written): every parameter of the axis, all
// read before and after, equals its value before, and the pages say aborted. A time budget of 6 s of motion is the
// smallest that completes on vmc X (`axistune-cli autotune --connect sim:vmc --axis X --time-budget 4` refuses:
// the move would exceed it).
#include "app/gui/AppContext.h"
#include "app/gui/AutoTuneWizard.h"
#include "app/gui/WizardRegistry.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

#include "tests/gui/GuiTestUtil.h"

using namespace axistune;
using namespace axistune::gui;
using axistune::testing::maybeScreenshot;
using axistune::testing::waitUntil;

namespace {

constexpr double kBudgetS = 6.0;

model::ParameterValues readAll(AppContext& ctx, const QString& axis)
{
    model::ParameterValues out;
    bool done = false;
    auto* req = ctx.drive().readParameters(axis);
    QObject::connect(req, &DriveRequest::finished, [&](const DriveReply& r) {
        if (r.ok)
            out = r.values;
        done = true;
    });
    waitUntil([&] { return done; }, 20000);
    return out;
}

/// The number at the start of a shown figure ("52.3°", "8.1 dB").
double shownNumber(const QString& text)
{
    QString n;
    for (QChar c : text) {
        if (c.isDigit() || c == '.' || c == '-')
            n += c;
        else
            break;
    }
    bool ok = false;
    const double v = n.toDouble(&ok);
    return ok ? v : std::nan("");
}

QString figure(QTableWidget* t, const char* key)
{
    for (int r = 0; r < t->rowCount(); ++r)
        if (t->item(r, 1) && t->item(r, 1)->data(Qt::UserRole).toString() == QLatin1String(key))
            return t->item(r, 1)->text();
    return {};
}

/// A store in `dir`, the embedded sim:vmc connected, every parameter of X as found.
void openOnVmc(QTemporaryDir& dir, AppContext& ctx, model::ParameterValues& before)
{
    QVERIFY(ctx.openDatabase(dir.filePath("store.sqlite")));
    ctx.drive().connectTo("sim:vmc");
    QVERIFY(waitUntil([&] { return ctx.drive().isConnected(); }, 20000));
    before = readAll(ctx, "X");
}

void showWizard(AutoTuneWizard& w)
{
    w.resize(1100, 760);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
}

/// Choice page: axis X, standard, the budget, confirmed; Start.
void choose(AutoTuneWizard& w, bool screenshot)
{
    auto* c = w.choicePage();
    QVERIFY(waitUntil([&] { return c->axis()->findText("X") >= 0; }, 5000));
    c->axis()->setCurrentText("X");
    QVERIFY(c->styleButton(autotune::Style::Standard)->isChecked());
    c->timeBudget()->setValue(kBudgetS);
    QVERIFY(!c->isComplete()); // not before the confirmation
    c->confirmation()->setChecked(true);
    QVERIFY(c->isComplete());
    if (screenshot)
        maybeScreenshot(&w, "autotune-01-choice");
    w.next();
    QCOMPARE(w.currentId(), int(AutoTuneWizard::Run));
}

} // namespace

class TestAutoTuneWizard : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { axistune::testing::installLanguageFromEnv(); }

    void registered()
    {
        const WizardEntry* e = findWizard("autotune");
        QVERIFY(e);
        QVERIFY(e->needsDrive);
        QVERIFY(!wizardTitle(*e).isEmpty());
    }

    void runsToTheEndOnVmcX()
    {
        QTemporaryDir dir;
        AppContext ctx;
        model::ParameterValues before;
        openOnVmc(dir, ctx, before);
        QVERIFY(!before.empty());
        AutoTuneWizard w(ctx);
        showWizard(w);
        choose(w, true);
        auto* run = w.runPage();
        QVERIFY(!run->isComplete());
        QVERIFY(run->abortButton()->isEnabled());
        // The running page, once past half of the sequence (some steps done, one running).
        bool shot = false;
        connect(run->progress(), &QProgressBar::valueChanged, &w, [&](int v) {
            if (!shot && v >= 500) {
                shot = true;
                QTimer::singleShot(0, &w, [&] { maybeScreenshot(&w, "autotune-02-running"); });
            }
        });
        QVERIFY(waitUntil([&] { return run->isComplete(); }, 60000));
        const auto r = w.data().result;
        QVERIFY(r);
        QVERIFY2(r->outcome == autotune::Outcome::Applied, r->reason.c_str());
        QVERIFY(r->final);
        QCOMPARE(run->progress()->value(), 1000);
        for (int row = 0; row < run->steps()->rowCount(); ++row)
            QCOMPARE(run->steps()->item(row, 1)->text(), AutoTuneRunPage::tr("done"));
        QCOMPARE(r->steps.size(), autotune::stepNames().size());
        // Each finished step's rule is in the live text.
        for (const auto& s : r->steps)
            QVERIFY2(run->log()->toPlainText().contains(QString::fromStdString(s.rule)), s.name.c_str());

        w.next();
        QCOMPARE(w.currentId(), int(AutoTuneWizard::Result));
        auto* res = w.resultPage();
        const auto& f = *r->final;
        const double pmShown = shownNumber(figure(res->figures(), "phase_margin_deg"));
        const double gmShown = shownNumber(figure(res->figures(), "gain_margin_dB"));
        const double bwShown = shownNumber(figure(res->figures(), "velocity_bandwidth_Hz"));
        qInfo("PM %.3f deg (shown %.1f), GM %.3f dB (shown %.1f), velocity bandwidth %.2f Hz, position %.2f Hz, "
              "motion %.2f s",
              f.phaseMarginDeg, pmShown, f.gainMarginDb, gmShown, f.velocityBandwidthHz, f.positionBandwidthHz,
              f.motionTimeS);
        // Shown with one decimal: equal to the core result within half the last digit.
        QVERIFY(std::abs(pmShown - f.phaseMarginDeg) <= 0.05 + 1e-9);
        QVERIFY(std::abs(gmShown - f.gainMarginDb) <= 0.05 + 1e-9);
        QVERIFY(std::abs(bwShown - f.velocityBandwidthHz) <= 0.05 + 1e-9);
        QVERIFY(f.phaseMarginDeg >= 45.0);
        QVERIFY(f.gainMarginDb >= 6.0);
        QVERIFY(f.motionTimeS <= kBudgetS);
        QCOMPARE(res->figures()->rowCount(), 7);
        QCOMPARE(res->parameters()->rowCount(), int(f.parameters.size()));
        QVERIFY(!f.parameters.empty());

        // The drive holds final.parameters, and every other parameter as before.
        const auto after = readAll(ctx, "X");
        QCOMPARE(after.size(), before.size());
        for (const auto& [k, v] : after) {
            const auto it = f.parameters.find(k);
            const double want = it != f.parameters.end() ? it->second : before.at(k);
            // 1e-6 relative: the read-back tolerance of the drive link (float32 on Modbus; exact on sim:).
            QVERIFY2(std::abs(v - want) <= 1e-6 * std::max(1.0, std::abs(want)), k.c_str());
        }

        // The session: kind autotune, the result JSON with the figures shown.
        QVERIFY(waitUntil([&] { return w.data().sessionId > 0; }, 20000));
        auto s = ctx.database()->loadSession(w.data().sessionId);
        QVERIFY(s.ok());
        QCOMPARE(QString::fromStdString(s->info.kind), QString("autotune"));
        QCOMPARE(s->info.status, store::SessionStatus::Completed);
        const auto* j = s->result("autotune");
        QVERIFY(j);
        QCOMPARE((*j)["outcome"].get<std::string>(), std::string("applied"));
        QCOMPARE((*j)["final"]["phase_margin_deg"].get<double>(), f.phaseMarginDeg);
        QCOMPARE((*j)["steps"].size(), r->steps.size());
        QCOMPARE(s->journal.size(), f.parameters.size());
        res->initializePage(); // shows the session id now that the store answered
        maybeScreenshot(&w, "autotune-03-result");
    }

    void abortRestoresEveryParameter_data()
    {
        QTest::addColumn<int>("atPermille");
        QTest::newRow("30 % (adaptive FRF)") << 300;
        QTest::newRow("70 % (gains written)") << 700;
    }

    void abortRestoresEveryParameter()
    {
        QFETCH(int, atPermille);
        QTemporaryDir dir;
        AppContext ctx;
        model::ParameterValues before;
        openOnVmc(dir, ctx, before);
        QVERIFY(!before.empty());
        AutoTuneWizard w(ctx);
        showWizard(w);
        choose(w, false);
        auto* run = w.runPage();
        int pressedAt = -1;
        connect(run->progress(), &QProgressBar::valueChanged, &w, [&](int v) {
            if (pressedAt < 0 && v >= atPermille) {
                pressedAt = v;
                run->abortButton()->click();
            }
        });
        QVERIFY(waitUntil([&] { return run->isComplete(); }, 60000));
        QVERIFY(pressedAt >= atPermille);
        qInfo("Abort pressed at %.1f %%: %s", pressedAt / 10.0, w.data().result ? w.data().result->reason.c_str() : "");
        const auto r = w.data().result;
        QVERIFY(r);
        QVERIFY(r->outcome == autotune::Outcome::Refused);
        QVERIFY2(r->reasonCode == ErrorCode::Aborted, r->reason.c_str());
        QVERIFY(r->restored);
        QVERIFY(!r->final);
        if (atPermille == 700) // the velocity gains were written before the Abort
            QVERIFY(r->steps.size() >= 5);
        // One row says aborted, none is left running.
        int abortedRows = 0;
        for (int row = 0; row < run->steps()->rowCount(); ++row) {
            abortedRows += run->steps()->item(row, 1)->text() == AutoTuneRunPage::tr("aborted");
            QVERIFY(run->steps()->item(row, 1)->text() != AutoTuneRunPage::tr("running…"));
        }
        QCOMPARE(abortedRows, 1);
        QVERIFY(run->state()->text().startsWith(AutoTuneRunPage::tr("Aborted (%1): %2.").section('(', 0, 0)));

        const auto after = readAll(ctx, "X");
        QCOMPARE(after, before);

        w.next();
        auto* res = w.resultPage();
        QVERIFY(res->outcome()->text().startsWith(AutoTuneResultPage::tr("Aborted")));
        QVERIFY(res->outcome()->text().contains(
            AutoTuneResultPage::tr("%1: %2\nNothing was changed: every parameter was restored and read back equal.")
                .section('\n', 1)));
        QVERIFY(res->figures()->isHidden());
        QVERIFY(waitUntil([&] { return w.data().sessionId > 0; }, 20000));
        auto s = ctx.database()->loadSession(w.data().sessionId);
        QVERIFY(s.ok());
        QCOMPARE(s->info.status, store::SessionStatus::Aborted);
        if (atPermille == 300)
            maybeScreenshot(&w, "autotune-04-aborted");
    }

    void cancelWhileRunningAbortsAndClosesWhenRestored()
    {
        // Cancel (or closing the window) during the run is an Abort: the window stays until the sequence has
        // answered with every parameter restored, then closes.
        QTemporaryDir dir;
        AppContext ctx;
        model::ParameterValues before;
        openOnVmc(dir, ctx, before);
        QVERIFY(!before.empty());
        AutoTuneWizard w(ctx);
        showWizard(w);
        choose(w, false);
        bool cancelled = false;
        connect(w.runPage()->progress(), &QProgressBar::valueChanged, &w, [&](int v) {
            if (!cancelled && v >= 500) {
                cancelled = true;
                w.reject();
            }
        });
        QVERIFY(waitUntil([&] { return !w.isVisible(); }, 60000));
        QVERIFY(cancelled);
        const auto r = w.data().result;
        QVERIFY(r);
        QVERIFY2(r->reasonCode == ErrorCode::Aborted, r->reason.c_str());
        QVERIFY(r->restored);
        QCOMPARE(readAll(ctx, "X"), before);
    }
};

QTEST_MAIN(TestAutoTuneWizard)
#include "tst_autotunewizard.moc"

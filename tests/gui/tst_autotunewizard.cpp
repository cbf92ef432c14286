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
// Over the travel and the amplitude map (issue 18 items 3 and 4): (c) on sim:long-axis X with 3 positions and the
// required crossover 30 Hz (as the CLI test `autotune --positions 3 --min-bandwidth-hz 30`): the resonance map's
// plotted points are the core result's final.positions[] (position, first resonance; the height in the labels to
// the shown digit), the table holds every position's re-measured margins; Abort during the positions run (at 25 %
// and 75 %) leaves every parameter as before; (d) the choice page shows the core's refusals (a rotary axis without a
// travel window, amplitude lists checkAmplitudeList refuses, an amplitude map with positions); (e) vmc X with the
// amplitude map at 5, 10, 20 %: the plotted non-linear and linear lines are exactly the core's flags.
#include "app/gui/AppContext.h"
#include "app/gui/AutoTuneWizard.h"
#include "app/gui/WizardRegistry.h"
#include "core/autotune/AmplitudeMap.h"
#include "core/autotune/TravelChoice.h"
#include "widgets/CurvePlot.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <set>
#include <nlohmann/json.hpp>

#include "tests/gui/AutoTuneTestUtil.h"
#include "tests/gui/GuiTestUtil.h"
#include "core/store/SessionRecord.h"

using namespace axistune;
using namespace axistune::gui;
using axistune::testing::maybeScreenshot;
using axistune::testing::openOn;
using axistune::testing::readAll;
using axistune::testing::waitUntil;

namespace {

constexpr double kBudgetS = 6.0;

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

void openOnVmc(QTemporaryDir& dir, AppContext& ctx, model::ParameterValues& before)
{
    openOn(dir, ctx, before);
}

/// Choice page on sim:long-axis X: 3 positions, required crossover 30 Hz, confirmed; Start.
void chooseThreePositions(AutoTuneWizard& w, bool screenshot)
{
    auto* c = w.choicePage();
    QVERIFY(waitUntil([&] { return c->axis()->findText("X") >= 0; }, 5000));
    c->axis()->setCurrentText("X");
    QVERIFY(waitUntil([&] { return c->travelKnown(); }, 10000));
    QVERIFY2(c->positions()->isEnabled(), qPrintable(c->travelNote()->text()));
    // The preset's travel window is +-0.75 m (docs/simulator.md "Long axis"), shown in the axis's units.
    QVERIFY2(c->travelNote()->text().contains(QStringLiteral("0.75 m")), qPrintable(c->travelNote()->text()));
    c->positions()->setValue(3);
    // The budget follows the positions: 30 s of motion each, the CLI's default (docs/cli.md).
    QCOMPARE(c->timeBudget()->value(), 3 * 30.0);
    c->minBandwidth()->setValue(30.0);
    c->confirmation()->setChecked(true);
    QVERIFY2(c->isComplete(), qPrintable(c->choiceError()->text()));
    if (screenshot)
        maybeScreenshot(&w, "autotune-05-positions-choice");
    w.next();
    QCOMPARE(w.currentId(), int(AutoTuneWizard::Run));
}

/// Presses Abort when the progress first reaches `atPermille`, waits for the answer: refused as aborted, every
/// parameter restored and read back equal (the sequence's own check).
void abortAt(AutoTuneWizard& w, int atPermille, int timeoutMs)
{
    auto* run = w.runPage();
    int pressedAt = -1;
    QObject::connect(run->progress(), &QProgressBar::valueChanged, &w, [&](int v) {
        if (pressedAt < 0 && v >= atPermille) {
            pressedAt = v;
            run->abortButton()->click();
        }
    });
    QVERIFY(waitUntil([&] { return run->isComplete(); }, timeoutMs));
    QVERIFY(pressedAt >= atPermille);
    const auto r = w.data().result;
    QVERIFY(r);
    qInfo("Abort pressed at %.1f %% after %zu steps: %s", pressedAt / 10.0, r->steps.size(), r->reason.c_str());
    QVERIFY(r->outcome == autotune::Outcome::Refused);
    QVERIFY2(r->reasonCode == ErrorCode::Aborted, r->reason.c_str());
    QVERIFY(r->restored);
}

/// The number before `suffix` in `text` ("164.2 Hz, 12.3 dB" with " dB" → 12.3).
double numberBefore(const QString& text, const QString& suffix)
{
    const int end = text.indexOf(suffix);
    if (end < 0)
        return std::nan("");
    int start = end;
    while (start > 0 && (text[start - 1].isDigit() || text[start - 1] == '.' || text[start - 1] == '-'))
        --start;
    bool ok = false;
    const double v = text.mid(start, end - start).toDouble(&ok);
    return ok ? v : std::nan("");
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
        abortAt(w, atPermille, 60000);
        if (QTest::currentTestFailed())
            return;
        const auto r = w.data().result;
        QVERIFY(r);
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

    void positionsOnLongAxisPlotTheCoreResonanceMap()
    {
        QTemporaryDir dir;
        AppContext ctx;
        model::ParameterValues before;
        openOn(dir, ctx, before, "sim:long-axis");
        QVERIFY(!before.empty());
        AutoTuneWizard w(ctx);
        showWizard(w);
        chooseThreePositions(w, true);
        auto* run = w.runPage();
        QVERIFY(waitUntil([&] { return run->isComplete(); }, 120000));
        const auto r = w.data().result;
        QVERIFY(r);
        QVERIFY2(r->outcome == autotune::Outcome::Applied, r->reason.c_str());
        QVERIFY(r->final);
        const auto& pos = r->final->positions;
        QCOMPARE(int(pos.size()), 3);
        w.next();
        auto* res = w.resultPage();
        QVERIFY(!res->tabs()->isHidden());
        QVERIFY(res->tabs()->isTabVisible(AutoTuneResultPage::ResonanceTab));
        QVERIFY(!res->tabs()->isTabVisible(AutoTuneResultPage::AmplitudeTab));

        // The plotted map: one point per position with a resonance, at the core's position and frequency.
        auto* plot = res->resonanceMap();
        QCOMPARE(plot->curveCount(), 1);
        const auto pts = plot->curvePoints(0);
        std::vector<autotune::PositionFinal> withResonance;
        for (const auto& p : pos)
            if (p.firstResonanceHz)
                withResonance.push_back(p);
        QCOMPARE(pts.size(), withResonance.size());
        QCOMPARE(int(pts.size()), 3); // the preset has its screw mode in the band at every position
        QCOMPARE(plot->pointLabels().size(), qsizetype(pts.size()));
        for (std::size_t i = 0; i < pts.size(); ++i) {
            // The plot holds the doubles of the result JSON (no rounding on the way): exact.
            QCOMPARE(pts[i].first, withResonance[i].position);
            QCOMPARE(pts[i].second, *withResonance[i].firstResonanceHz);
            // The labels: frequency and height with one decimal, equal within half the last digit.
            const QString label = plot->pointLabels()[int(i)];
            QVERIFY2(std::abs(numberBefore(label, " Hz") - *withResonance[i].firstResonanceHz) <= 0.05 + 1e-9,
                     qPrintable(label));
            QVERIFY2(std::abs(numberBefore(label, " dB") - *withResonance[i].firstResonanceHeightDb) <= 0.05 + 1e-9,
                     qPrintable(label));
            qInfo("position %.3f m: first resonance %.1f Hz, %.1f dB; PM %.1f deg, GM %.1f dB", pts[i].first,
                  pts[i].second, *withResonance[i].firstResonanceHeightDb, withResonance[i].phaseMarginDeg,
                  withResonance[i].gainMarginDb);
        }
        // The positions span the travel window -0.75 ... +0.75 m less the move's servo lag v/K_p = 0.5 m/s / 30 1/s
        // at both ends (3 positions: the ends and the middle; docs/tuning.md "Over the travel"), and the resonance
        // falls by at least 25 % from one end to the other (the preset's design, docs/simulator.md).
        const double end = 0.75 - 0.5 / 30.0;
        QVERIFY(std::abs(pos.front().position + end) <= 1e-9);
        QVERIFY(std::abs(pos.back().position - end) <= 1e-9);
        QVERIFY(*pos.back().firstResonanceHz <= 0.75 * *pos.front().firstResonanceHz);

        // The table: every position's re-measured figures, shown to one decimal.
        auto* t = res->positionsTable();
        QCOMPARE(t->rowCount(), 3);
        QVERIFY(t->horizontalHeaderItem(0)->text().contains("[m]"));
        for (int row = 0; row < 3; ++row) {
            const auto& p = pos[std::size_t(row)];
            QVERIFY(std::abs(t->item(row, 0)->text().toDouble() - p.position) <= 0.5e-4 + 1e-12);
            QVERIFY(std::abs(t->item(row, 3)->text().toDouble() - p.phaseMarginDeg) <= 0.05 + 1e-9);
            QVERIFY(std::abs(t->item(row, 4)->text().toDouble() - p.gainMarginDb) <= 0.05 + 1e-9);
            QVERIFY(std::abs(t->item(row, 5)->text().toDouble() - p.velocityBandwidthHz) <= 0.05 + 1e-9);
            QVERIFY(std::abs(t->item(row, 6)->text().toDouble() - p.positionBandwidthHz) <= 0.05 + 1e-9);
            // The style's acceptance at every position (standard: 45 deg / 6 dB).
            QVERIFY(p.phaseMarginDeg >= 45.0);
            QVERIFY(p.gainMarginDb >= 6.0);
        }
        res->tabs()->setCurrentIndex(AutoTuneResultPage::ResonanceTab);
        maybeScreenshot(&w, "autotune-05-positions");
    }

    void abortDuringPositionsRestoresEveryParameter_data()
    {
        QTest::addColumn<int>("atPermille");
        QTest::newRow("25 % (moving and measuring along the travel)") << 250;
        QTest::newRow("75 % (gains written, verifying)") << 750;
    }

    void abortDuringPositionsRestoresEveryParameter()
    {
        QFETCH(int, atPermille);
        QTemporaryDir dir;
        AppContext ctx;
        model::ParameterValues before;
        openOn(dir, ctx, before, "sim:long-axis");
        QVERIFY(!before.empty());
        AutoTuneWizard w(ctx);
        showWizard(w);
        chooseThreePositions(w, false);
        abortAt(w, atPermille, 120000);
        if (QTest::currentTestFailed())
            return;
        const auto r = w.data().result;
        QVERIFY(r);
        if (atPermille == 750) // the velocity gains were written before the Abort
            QVERIFY(r->steps.size() >= 5);
        QCOMPARE(readAll(ctx, "X"), before);
        // Abort stops the axis where it stands; it is not moved back (and the reason says so).
        QVERIFY2(r->reason.find("not moved back") != std::string::npos, r->reason.c_str());
    }

    void choicePageShowsTheCoresRefusals()
    {
        QTemporaryDir dir;
        AppContext ctx;
        model::ParameterValues before;
        openOn(dir, ctx, before, "sim:dd-table", "C");
        AutoTuneWizard w(ctx);
        showWizard(w);
        auto* c = w.choicePage();
        QVERIFY(waitUntil([&] { return c->axis()->findText("C") >= 0; }, 5000));
        c->axis()->setCurrentText("C");
        QVERIFY(waitUntil([&] { return c->travelKnown(); }, 10000));
        c->confirmation()->setChecked(true);
        QVERIFY(c->isComplete());
        // A rotary axis of the presets has no travel window: off, disabled, with the core's reason.
        QVERIFY(!c->positions()->isEnabled());
        QCOMPARE(c->positions()->value(), 1);
        QVERIFY2(c->travelNote()->text().contains("travel window"), qPrintable(c->travelNote()->text()));

        // Amplitude lists: the core's messages, and Start stays disabled.
        c->amplitudes()->setText("5, 10");
        QVERIFY(!c->isComplete());
        QVERIFY2(c->choiceError()->text().contains(
                     QString::fromStdString(autotune::checkAmplitudeList({5.0, 10.0}).error().detail)),
                 qPrintable(c->choiceError()->text()));
        maybeScreenshot(&w, "autotune-01-choice-rotary");
        c->amplitudes()->setText("10, 5, 20");
        QVERIFY(!c->isComplete());
        QVERIFY(c->choiceError()->text().contains(
            QString::fromStdString(autotune::checkAmplitudeList({10.0, 5.0, 20.0}).error().detail)));
        c->amplitudes()->setText("5, ten, 20");
        QVERIFY(!c->isComplete());
        QVERIFY(c->choiceError()->text().contains("'ten'"));
        c->amplitudes()->setText("5 10,20");
        QVERIFY2(c->isComplete(), qPrintable(c->choiceError()->text()));
        QVERIFY(c->choiceError()->text().isEmpty());
        c->amplitudes()->clear();
        QVERIFY(c->isComplete());

        // On the long axis: positions and an amplitude map together are refused with checkChoices' reason.
        bool connected = false;
        connect(ctx.drive().connectTo("sim:long-axis"), &DriveRequest::finished, &w,
                [&](const DriveReply& r) { connected = r.ok; });
        QVERIFY(waitUntil([&] { return connected; }, 20000));
        QVERIFY(waitUntil([&] { return ctx.axes().contains("X"); }, 5000));
        c->initializePage();
        c->axis()->setCurrentText("X");
        QVERIFY(waitUntil([&] { return c->travelKnown(); }, 10000));
        QVERIFY(c->positions()->isEnabled());
        c->positions()->setValue(3);
        c->amplitudes()->setText("5, 10, 20");
        QVERIFY(!c->isComplete());
        autotune::Options both;
        both.axis = "X";
        both.positions = 3;
        both.amplitudeMapPct = {5.0, 10.0, 20.0};
        QVERIFY(c->choiceError()->text().contains(QString::fromStdString(autotune::checkChoices(both).error().detail)));
    }

    void amplitudeMapOnVmcXPlotsTheCoresFlags()
    {
        QTemporaryDir dir;
        AppContext ctx;
        model::ParameterValues before;
        openOnVmc(dir, ctx, before);
        AutoTuneWizard w(ctx);
        showWizard(w);
        auto* c = w.choicePage();
        QVERIFY(waitUntil([&] { return c->axis()->findText("X") >= 0; }, 5000));
        c->axis()->setCurrentText("X");
        c->amplitudes()->setText("5, 10, 20");
        c->confirmation()->setChecked(true);
        QVERIFY2(c->isComplete(), qPrintable(c->choiceError()->text()));
        w.next();
        auto* run = w.runPage();
        QVERIFY(waitUntil([&] { return run->isComplete(); }, 120000));
        const auto r = w.data().result;
        QVERIFY(r);
        QVERIFY2(r->outcome == autotune::Outcome::Applied, r->reason.c_str());
        // The core's map: the frf step's measured.amplitude_map.
        const nlohmann::json* map = nullptr;
        for (const auto& st : r->steps)
            if (st.name == "frf" && st.measured.contains("amplitude_map"))
                map = &st.measured["amplitude_map"];
        QVERIFY(map);
        std::set<std::pair<double, double>> coreNonlinear, coreLinear;
        for (const auto& l : (*map)["lines"])
            for (const auto& at : l["at"])
                (l["nonlinear"].get<bool>() ? coreNonlinear : coreLinear)
                    .insert({l["f_Hz"].get<double>(), at["amplitude_pct"].get<double>()});
        w.next();
        auto* res = w.resultPage();
        QVERIFY(res->tabs()->isTabVisible(AutoTuneResultPage::AmplitudeTab));
        QVERIFY(!res->tabs()->isTabVisible(AutoTuneResultPage::ResonanceTab));
        auto* plot = res->amplitudeMap();
        const QStringList names = plot->curveNames();
        const int iNon = int(names.indexOf(AutoTuneResultPage::tr("non-linear")));
        const int iLin = int(names.indexOf(AutoTuneResultPage::tr("linear")));
        const int iOff = int(names.indexOf(AutoTuneResultPage::tr("not compared")));
        QVERIFY(iNon >= 0 && iLin >= 0 && iOff >= 0);
        std::set<std::pair<double, double>> shownNonlinear, shownOther;
        for (const auto& p : plot->curvePoints(iNon))
            shownNonlinear.insert(p);
        for (int i : {iLin, iOff})
            for (const auto& p : plot->curvePoints(i))
                shownOther.insert(p);
        qInfo("amplitude map: %zu non-linear and %zu other (line, amplitude) points; %s of %s lines non-linear",
              coreNonlinear.size(), coreLinear.size(), (*map)["nonlinear_lines"].dump().c_str(),
              (*map)["lines_compared"].dump().c_str());
        // Exactly the core's flags (the doubles of the JSON: exact), both kinds present on vmc X (its friction flags
        // most lines below 1 kHz, not all: docs/tuning.md "What it shows on the simulator").
        QVERIFY(!coreNonlinear.empty());
        QVERIFY(!coreLinear.empty());
        QVERIFY(shownNonlinear == coreNonlinear);
        QVERIFY(shownOther == coreLinear);
        // The magnitude plot: one curve per amplitude and the non-linear lines.
        QCOMPARE(res->amplitudeMagnitude()->curveCount(), int((*map)["amplitudes"].size()) + 1);
        QVERIFY(
            res->amplitudeSummary()->text().contains(QString::number((*map)["nonlinear_lines"].get<double>(), 'g', 6)));
        res->tabs()->setCurrentIndex(AutoTuneResultPage::AmplitudeTab);
        maybeScreenshot(&w, "autotune-06-amplitude-map");
    }
};

QTEST_MAIN(TestAutoTuneWizard)
#include "tst_autotunewizard.moc"

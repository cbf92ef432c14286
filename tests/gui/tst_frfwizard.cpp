// SPDX-License-Identifier: GPL-3.0-or-later
// The frequency-response wizard end to end (issue 8 "What must be true", docs/wizards/frf.md):
// every page driven on the simulated dd-table, in process and over Modbus against axistune-simdrive;
// a killed simdrive during the run; Abort during the run; the adaptive multisine and its Abort.
//
// The machine is the dd-table preset as it is (sim:dd-table, simdrive --preset dd-table): Coulomb
// friction, current noise, current-dependent inductance and its 2^29 counts/rev encoder all on. The
// 2^29 encoder (11.7 nrad) resolves the kilohertz mode motion of a 3 % test, so the 3.3 kHz mode is
// found without switching anything off (docs/frequency-response-sim.md; found at 3.3 kHz within 2 %
// with simulator seeds 1, 7 and 42). The 3.3 kHz expected here is read from the preset's "modes"
// list, not from the code under test.
#include "app/gui/AppContext.h"
#include "app/gui/FrfWizard.h"
#include "app/gui/SessionReviewView.h"
#include "app/gui/NotchWizard.h"
#include "app/gui/WizardRegistry.h"

#include "core/device/FrfTest.h"
#include "core/store/FrfCapture.h"
#include "tests/app/cli/SimDriveProcess.h"
#include "tests/gui/GuiTestUtil.h"
#include "widgets/BodePlot.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QSignalSpy>
#include <QtTest>

#include <nlohmann/json.hpp>

#include <cmath>
#include <csignal>
#include <fstream>

using namespace axistune;
using axistune::gui::FrfWizard;
using axistune::testing::maybeScreenshot;
using axistune::testing::waitUntil;

namespace {

const std::string kResources = std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources";

struct Band {
    double fmin, fmax;
    int points;
    double amplitudePct;
};

// 3 % amplitude: at 5 % the current loop reaches its voltage limit near 2.1–2.9 kHz on dd-table
// (docs/frequency-response-sim.md). In process the whole band 100 Hz–3.9 kHz with 300 points (1.2 %
// spacing, all three modes; 30 s of machine time); over Modbus 2–3.9 kHz with 40 points (about 1.1 %
// spacing near 3.3 kHz, 3.4 s of machine time) to keep the test short.
constexpr Band kWideBand{100.0, 3900.0, 300, 3.0};
constexpr Band kResonanceBand{2000.0, 3900.0, 40, 3.0};

bool connectTo(gui::AppContext& ctx, const QString& uri)
{
    ctx.drive().connectTo(uri);
    return waitUntil([&] { return ctx.drive().isConnected(); }, 20000);
}

/// Every parameter of axis C as the drive holds it now.
model::ParameterValues readAllParameters(gui::AppContext& ctx)
{
    model::ParameterValues v;
    bool done = false;
    const int id = ctx.drive().readParameters("C")->id();
    auto c =
        QObject::connect(&ctx.drive(), &gui::DriveController::replied, &ctx.drive(), [&](const gui::DriveReply& r) {
            if (r.id == id) {
                v = r.values;
                done = true;
            }
        });
    waitUntil([&] { return done; }, 10000);
    QObject::disconnect(c);
    return v;
}

/// Presses Abort on a running run page: it ends within 1 s as Aborted, and every parameter of axis C reads as
/// `before`.
/// The part of a translated text before its first argument, as the running language (AXISTUNE_LANG) shows it: the
/// checks of message texts hold in Japanese too.
QString translatedHead(const char* context, const char* source)
{
    const QString t = QCoreApplication::translate(context, source);
    return t.left(t.indexOf(QStringLiteral("%1"))).trimmed();
}

/// The wizard's refusal style (dark red), whatever the language.
bool showsRefusal(const QLabel* label)
{
    return label->text().contains(QStringLiteral("color:#b00000"));
}

void abortAndCheckRestored(gui::AppContext& ctx, gui::TestRunPage* run, const model::ParameterValues& before)
{
    QVERIFY(run->isRunning());
    QElapsedTimer t;
    t.start();
    run->abortButton()->click();
    QVERIFY(waitUntil([&] { return !run->isRunning(); }, 5000));
    QVERIFY2(t.elapsed() < 1000, qPrintable(QString::number(t.elapsed())));
    QCOMPARE(run->failureCode(), ErrorCode::Aborted);
    const auto after = readAllParameters(ctx);
    QCOMPARE(after.size(), before.size());
    for (const auto& [k, v] : before)
        QVERIFY2(after.at(k) == v, k.c_str());
}

/// Sets the pages of a shown wizard up to the run page and presses Next into the run.
void configureAndStart(FrfWizard& w, const Band& b, bool screenshots,
                       device::FrfMethod method = device::FrfMethod::MultiSweep)
{
    auto* safety = w.safetyPage();
    QCOMPARE(w.currentId(), int(FrfWizard::SafetyId));
    // The rated torque read from the drive appears in the amplitude text (N·m).
    QVERIFY(waitUntil([&] { return safety->findChild<QLabel*>("frfAmplitudeText")->text().contains("N·m"); }, 20000));
    safety->amplitude()->setValue(b.amplitudePct);
    QVERIFY(!w.button(QWizard::NextButton)->isEnabled());  // the confirmation is required first
    safety->confirmation()->setChecked(true);
    QVERIFY(w.button(QWizard::NextButton)->isEnabled());
    if (screenshots)
        maybeScreenshot(&w, "frf-01-safety");
    w.next();
    QCOMPARE(w.currentId(), int(FrfWizard::ConfigId));
    auto* cfg = w.configPage();
    QCOMPARE(cfg->method()->currentIndex(), 0);  // multi-sweep is the default
    QCOMPARE(cfg->selectedMethod(), device::FrfMethod::MultiSweep);
    cfg->method()->setCurrentIndex(cfg->method()->findData(int(method)));
    QCOMPARE(cfg->selectedMethod(), method);
    cfg->fmin()->setValue(b.fmin);
    cfg->fmax()->setValue(b.fmax);
    cfg->points()->setValue(b.points);
    QVERIFY2(waitUntil([&] { return cfg->isComplete(); }, 20000),
             qPrintable(cfg->findChild<QLabel*>("frfEstimate")->text()));
    QVERIFY(std::isfinite(cfg->estimatedMotionS()) && cfg->estimatedMotionS() > 0.0);
    if (screenshots)
        maybeScreenshot(&w, "frf-02-method");
    w.next();
    QCOMPARE(w.currentId(), int(FrfWizard::RunId));
}

/// The 3.3 kHz mode of the preset (independent source of the expected value).
double presetModeNear3300()
{
    std::ifstream f(kResources + "/machines/dd-table.json");
    const auto j = nlohmann::json::parse(f);
    for (const auto& m : j["axes"][0]["modes"])
        if (m["frequency_Hz"].get<double>() > 3000.0)
            return m["frequency_Hz"].get<double>();
    return NAN;
}

/// Drives a complete wizard run and checks plot, resonances and the stored session.
void runCompleteWizard(gui::AppContext& ctx, const Band& band, bool screenshots)
{
    FrfWizard w(ctx);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    configureAndStart(w, band, screenshots);
    if (QTest::currentTestFailed())
        return;
    auto* run = w.runPage();
    QVERIFY(waitUntil([&] { return !run->isRunning(); }, 60000));
    QVERIFY2(run->succeeded(), qPrintable(run->failure()));
    if (screenshots)
        maybeScreenshot(&w, "frf-03-run");
    w.next();
    QCOMPARE(w.currentId(), int(FrfWizard::ResultId));
    auto* res = w.resultPage();
    QVERIFY(waitUntil([&] { return res->analysed(); }, 30000));
    if (screenshots)
        maybeScreenshot(&w, "frf-04-result");

    // The 3.3 kHz resonance within 2 % (issue 3/8), in the list and as a marker.
    const double mode = presetModeNear3300();
    QCOMPARE(mode, 3300.0);
    const auto& list = res->analysis().resonances;
    bool found = false;
    for (const auto& r : list)
        found = found || std::abs(r.freqHz - mode) <= 0.02 * mode;
    for (const auto& r : list)
        qInfo("resonance %.1f Hz", r.freqHz);
    QVERIFY2(found, qPrintable(QString("resonances: %1, error '%2'").arg(list.size()).arg(res->analysis().error)));
    QCOMPARE(res->resonanceTable()->rowCount(), int(list.size()));
    auto* plot = res->bodePlot();
    QCOMPARE(plot->markerCount(), int(list.size()));
    // fs = 4 kHz (trace.divider 1 × 250 µs): the band fs/2..fs is shaded "valid only by multi-sweep".
    QCOMPARE(res->traceRateHz(), 4000.0);
    QVERIFY(plot->bandCount() >= 1);
    QCOMPARE(plot->responseCount(), 1);

    // The plotted response is the measured one, point by point.
    const auto& measured = res->measured();
    QCOMPARE(int(measured.size()), band.points);
    int compared = 0;
    for (std::size_t i = 0; i < measured.size(); ++i) {
        if (!measured.valid[i])
            continue;
        QVERIFY(std::abs(plot->magnitudeDbAt(0, measured.freqHz[i]) - dsp::magnitudeDb(measured.h[i])) < 1e-6);
        ++compared;
    }
    QVERIFY(compared >= band.points - 5);

    w.next();
    QCOMPARE(w.currentId(), int(FrfWizard::SaveId));
    if (screenshots)
        maybeScreenshot(&w, "frf-05-save");
    QVERIFY(w.savePage()->openDocumentBox()->isChecked());
    QSignalSpy documents(&ctx, &gui::AppContext::documentRequested);
    w.button(QWizard::FinishButton)->click();
    QVERIFY(w.savedSessionId() > 0);
    // Finish leaves the measurement open as a document: the saved session's view.
    QCOMPARE(documents.count(), 1);
    std::unique_ptr<QWidget> doc(documents.front().front().value<QWidget*>());
    auto* view = qobject_cast<gui::SessionView*>(doc.get());
    QVERIFY(view);
    QCOMPARE(view->record().info.id, w.savedSessionId());

    auto loaded = ctx.database()->loadSession(w.savedSessionId());
    QVERIFY(loaded.ok());
    QCOMPARE(loaded->info.kind, std::string("frf"));
    QCOMPARE(loaded->info.status, store::SessionStatus::Completed);
    QCOMPARE(loaded->info.axis, std::string("C"));
    QCOMPARE(loaded->inputs.at("method").get<std::string>(), std::string("multisweep"));
    QCOMPARE(loaded->inputs.at("points").get<int>(), band.points);
    QCOMPARE(loaded->inputs.at("amplitude_pct").get<double>(), band.amplitudePct);
    const store::NamedCapture* cap = nullptr;
    for (const auto& c : loaded->captures)
        if (c.name == "measured")
            cap = &c;
    QVERIFY(cap);
    auto back = store::frfFromCapture(cap->capture);
    QVERIFY(back.ok());
    QCOMPARE(back->freqHz, measured.freqHz);
    QCOMPARE(back->valid, measured.valid);
    for (std::size_t i = 0; i < measured.size(); ++i)
        QVERIFY(std::abs(back->h[i] - measured.h[i]) <= 1e-12 * std::abs(measured.h[i]));
    bool stored3300 = false;
    for (const auto& r : loaded->results)
        if (r.name == "resonances")
            for (const auto& x : r.data.at("resonances"))
                stored3300 = stored3300 || std::abs(x.at("frequency_Hz").get<double>() - mode) <= 0.02 * mode;
    QVERIFY(stored3300);
}

}  // namespace

class TestFrfWizard : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_tmp;

private slots:
    void initTestCase()
    {
        axistune::testing::installLanguageFromEnv();
        QVERIFY(m_tmp.isValid());
    }

    void isRegistered()
    {
        const auto* e = gui::findWizard("frf");
        QVERIFY(e);
        QCOMPARE(e->order, 10);
    }

    void amplitudeAboveTheDriveMaximumIsRefused()
    {
        gui::AppContext ctx;
        QVERIFY(connectTo(ctx, "sim:dd-table"));
        FrfWizard w(ctx);
        w.show();
        auto* s = w.safetyPage();
        s->confirmation()->setChecked(true);
        QVERIFY(waitUntil([&] { return w.button(QWizard::NextButton)->isEnabled(); }, 10000));
        // The limit is the drive's own (Drive::limits), as the wizard read it.
        const double maxPct = s->driveInfo().maxAmplitudePct();
        QVERIFY(std::isfinite(maxPct) && maxPct > 0.0);
        s->amplitude()->setValue(maxPct + 1.0);
        QCOMPARE(s->amplitude()->value(), maxPct + 1.0); // not clamped ...
        s->confirmation()->setChecked(true);
        QVERIFY(!w.button(QWizard::NextButton)->isEnabled());  // ... but refused
        QVERIFY(showsRefusal(s->findChild<QLabel*>("frfAmplitudeText")));
    }

    void amplitudeLimitAndMotionTimeComeFromTheDrive()
    {
        // axistune-simdrive with a narrower excitation limit than the embedded simulator's: the wizard shows
        // and enforces the server's 20 %, and its motion time is the drive's own plan (plan_test).
        testing::SimDrive server("--preset dd-table --amplitude-limit 20");
        QVERIFY(server.port() > 0);
        gui::AppContext ctx;
        QVERIFY(connectTo(ctx, QString::fromStdString(server.uri())));
        FrfWizard w(ctx);
        w.show();
        auto* s = w.safetyPage();
        s->confirmation()->setChecked(true);
        QVERIFY(waitUntil([&] { return w.button(QWizard::NextButton)->isEnabled(); }, 10000));
        QCOMPARE(s->driveInfo().maxAmplitudePct(), 20.0); // the server's --amplitude-limit, exact over f64
        s->amplitude()->setValue(21.0);
        s->confirmation()->setChecked(true);
        QVERIFY(!w.button(QWizard::NextButton)->isEnabled());
        QVERIFY(s->findChild<QLabel*>("frfAmplitudeText")->text().contains("20"));
        s->amplitude()->setValue(5.0);
        s->confirmation()->setChecked(true);
        QVERIFY(waitUntil([&] { return w.button(QWizard::NextButton)->isEnabled(); }, 10000));
        w.next();
        auto* config = w.findChild<gui::FrfConfigPage*>();
        QVERIFY(config);
        QVERIFY(waitUntil([&] { return std::isfinite(config->estimatedMotionS()) && config->isComplete(); }, 10000));
        // The same request planned by the drive directly: the wizard shows exactly that number.
        auto drive = device::connect({server.uri(), 1});
        QVERIFY(drive.ok());
        auto plan = (*drive)->planTest(w.request());
        QVERIFY2(plan.ok(), plan.ok() ? "" : plan.error().detail.c_str());
        QCOMPARE(config->estimatedMotionS(), plan->motionTimeS);
    }

    void ddTableSimulatedEndToEnd()
    {
        QElapsedTimer t;
        t.start();
        gui::AppContext ctx;
        QVERIFY(ctx.openDatabase(m_tmp.filePath("sim.db")));
        QVERIFY(connectTo(ctx, "sim:dd-table"));
        runCompleteWizard(ctx, kWideBand, true);

        qInfo("simulated end to end: %lld ms wall", static_cast<long long>(t.elapsed()));
    }

    void singleSweepMethodsAreValidBelowHalfTheTraceRateOnly()
    {
        gui::AppContext ctx;
        QVERIFY(connectTo(ctx, "sim:dd-table"));
        {
            // Conventional up to 3.9 kHz: points at and above fs/2 = 2 kHz not valid (the drive's
            // rule); they lie in the shaded "valid only by multi-sweep" band and get no band of their own.
            FrfWizard w(ctx);
            w.show();
            configureAndStart(w, {1000.0, 3900.0, 12, 3.0}, false, device::FrfMethod::Conventional);
            QCOMPARE(w.configPage()->method()->count(), 4);
            QVERIFY(waitUntil([&] { return !w.runPage()->isRunning(); }, 60000));
            QVERIFY2(w.runPage()->succeeded(), qPrintable(w.runPage()->failure()));
            w.next();
            QVERIFY(waitUntil([&] { return w.resultPage()->analysed(); }, 30000));
            const auto& m = w.resultPage()->measured();
            int above = 0;
            for (std::size_t i = 0; i < m.size(); ++i) {
                QCOMPARE(bool(m.valid[i]), m.freqHz[i] < 2000.0);
                above += m.freqHz[i] >= 2000.0 ? 1 : 0;
            }
            QVERIFY(above >= 3);
            // fs/2..fs "valid only by multi-sweep" and above fs "not measurable" (the plot reaches 1.15 fmax).
            QCOMPARE(w.resultPage()->bodePlot()->bandCount(), 2);
            QVERIFY(!w.resultPage()->bodePlot()->coherenceVisible());  // sine streams: no coherence
        }
        {
            // PRBS: Welch coherence shown; fmax at or above fs/2 refused before anything moves.
            FrfWizard w(ctx);
            w.show();
            auto* cfg = w.configPage();
            w.safetyPage()->confirmation()->setChecked(true);
            QVERIFY(waitUntil([&] { return w.safetyPage()->isComplete(); }, 10000));
            w.next();
            cfg->method()->setCurrentIndex(cfg->method()->findData(int(device::FrfMethod::Prbs)));
            cfg->fmin()->setValue(100.0);
            cfg->fmax()->setValue(2500.0);
            QVERIFY(waitUntil([&] { return showsRefusal(cfg->findChild<QLabel*>("frfEstimate")); }, 20000));
            QVERIFY(!cfg->isComplete());
            QVERIFY(!w.button(QWizard::NextButton)->isEnabled());
            cfg->fmax()->setValue(1900.0);
            cfg->points()->setValue(30);
            QVERIFY(waitUntil([&] { return cfg->isComplete(); }, 20000));
            w.next();
            QVERIFY(waitUntil([&] { return !w.runPage()->isRunning(); }, 60000));
            QVERIFY2(w.runPage()->succeeded(), qPrintable(w.runPage()->failure()));
            w.next();
            QVERIFY(waitUntil([&] { return w.resultPage()->analysed(); }, 30000));
            QVERIFY(w.resultPage()->bodePlot()->coherenceVisible());
            QCOMPARE(w.resultPage()->measured().metadata.textOr("method", ""), std::string("prbs"));
        }
    }

    void ddTableOverModbusEndToEnd()
    {
        QElapsedTimer t;
        t.start();
        axistune::testing::SimDrive sd("--preset dd-table");
        QVERIFY(sd.port() > 0);
        gui::AppContext ctx;
        QVERIFY(ctx.openDatabase(m_tmp.filePath("modbus.db")));
        QVERIFY(connectTo(ctx, QString("modbus://127.0.0.1:%1").arg(sd.port())));
        runCompleteWizard(ctx, kResonanceBand, false);
        // The multisine over Modbus as well (all lines at once, 2–3.9 kHz).
        FrfWizard w(ctx);
        w.show();
        configureAndStart(w, {2000.0, 3900.0, 40, 3.0}, false, device::FrfMethod::Multisine);
        QVERIFY(waitUntil([&] { return !w.runPage()->isRunning(); }, 60000));
        QVERIFY2(w.runPage()->succeeded(), qPrintable(w.runPage()->failure()));
        w.next();
        QVERIFY(waitUntil([&] { return w.resultPage()->analysed(); }, 30000));
        QCOMPARE(w.resultPage()->measured().metadata.textOr("method", ""), std::string("multisine"));
        QVERIFY(w.resultPage()->measured().size() >= 40);  // at least `points` lines
        qInfo("Modbus end to end: %lld ms wall", static_cast<long long>(t.elapsed()));
    }

    void openInNotchWizardHandsOverTheSavedFrf()
    {
        gui::AppContext ctx;
        QVERIFY(ctx.openDatabase(m_tmp.filePath("handoff.db")));
        QVERIFY(connectTo(ctx, "sim:dd-table"));
        FrfWizard w(ctx);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        configureAndStart(w, kResonanceBand, false);
        QVERIFY(waitUntil([&] { return !w.runPage()->isRunning(); }, 60000));
        QVERIFY(w.runPage()->succeeded());
        w.next();
        QVERIFY(waitUntil([&] { return w.resultPage()->analysed(); }, 30000));
        w.next();
        QCOMPARE(w.currentId(), int(FrfWizard::SaveId));
        QPointer<QWizard> opened;
        connect(&w, &FrfWizard::notchWizardOpened, this, [&](QWizard* n) { opened = n; });
        w.savePage()->openNotchButton()->click();
        QVERIFY(w.savedSessionId() > 0);  // saved first
        QVERIFY(!w.isVisible());
        auto* notch = qobject_cast<gui::NotchWizard*>(opened.data());
        QVERIFY(notch);
        QCOMPARE(notch->measured().freqHz, w.resultPage()->measured().freqHz);
        QCOMPARE(notch->axis(), QString("C"));
        auto s = ctx.database()->loadSession(w.savedSessionId());
        QVERIFY(s.ok());
        QCOMPARE(s->info.status, store::SessionStatus::Completed);
        notch->close();
        QVERIFY(waitUntil([&] { return opened.isNull(); }, 5000));
    }

    void killedSimdriveShowsTheLostConnectionAndStoresAborted()
    {
        // Paced to 10 machine seconds per wall second, so that the run lasts about 1.4 s of wall time.
        axistune::testing::SimDrive sd("--preset dd-table --pace 10");
        QVERIFY(sd.port() > 0);
        gui::AppContext ctx;
        QVERIFY(ctx.openDatabase(m_tmp.filePath("kill.db")));
        QVERIFY(connectTo(ctx, QString("modbus://127.0.0.1:%1").arg(sd.port())));
        double progress = 0.0;
        connect(&ctx.drive(), &gui::DriveController::progress, this, [&](int, double f, const QString&) { progress = f; });
        FrfWizard w(ctx);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        configureAndStart(w, {10.0, 3900.0, 60, 3.0}, false);
        auto* run = w.runPage();
        QVERIFY(run->isRunning());
        // The event loop keeps serving a timer during the run and after the kill.
        QElapsedTimer gap;
        gap.start();
        qint64 worstGapMs = 0;
        int ticks = 0;
        QTimer timer;
        connect(&timer, &QTimer::timeout, this, [&] {
            worstGapMs = std::max(worstGapMs, gap.restart());
            ++ticks;
        });
        timer.start(20);
        QVERIFY(waitUntil([&] { return progress > 0.05 || !run->isRunning(); }, 30000));
        QVERIFY(run->isRunning());
        sd.stop(SIGKILL);
        QVERIFY(waitUntil([&] { return !run->isRunning(); }, 20000));
        timer.stop();
        QVERIFY(!run->succeeded());
        const QString lost = translatedHead("axistune::gui::TestRunPage", "Connection lost: %1");
        QVERIFY(!lost.isEmpty());
        QVERIFY2(run->failure().startsWith(lost), qPrintable(run->failure()));
        QVERIFY(ticks > 10);
        QVERIFY2(worstGapMs < 500, qPrintable(QString::number(worstGapMs)));
        QVERIFY(!ctx.drive().isConnected());
        QVERIFY(w.savedSessionId() > 0);
        auto s = ctx.database()->loadSession(w.savedSessionId());
        QVERIFY(s.ok());
        QCOMPARE(s->info.status, store::SessionStatus::Aborted);
        QCOMPARE(s->info.kind, std::string("frf"));
        QVERIFY2(QString::fromStdString(s->info.note).contains(lost), s->info.note.c_str());
    }

    // The adaptive multisine (device::runAdaptiveFrf, docs/multisine.md "Adaptive measurement") from the wizard on
    // the realistic dd-table, 20 Hz … 3.9 kHz every 10 Hz at 5 % (the CLI's adaptive run) with a 2.5 s budget:
    // offered with the multisine only, a budget shorter than the first pass refused before anything moves, one
    // progress over every pass, the passes and the lines left invalid (with their reasons) on the result page and
    // in the session; more lines valid than after the first pass.
    void adaptiveMultisineOnTheRealisticDdTable()
    {
        gui::AppContext ctx;
        QVERIFY(ctx.openDatabase(m_tmp.filePath("adaptive.db")));
        QVERIFY(connectTo(ctx, "sim:dd-table"));
        std::vector<double> progress;
        connect(&ctx.drive(), &gui::DriveController::progress, this,
                [&](int, double f, const QString&) { progress.push_back(f); });
        FrfWizard w(ctx);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* cfg = w.configPage();
        auto* box = cfg->adaptive();
        w.safetyPage()->amplitude()->setValue(5.0);
        w.safetyPage()->confirmation()->setChecked(true);
        w.next();
        QCOMPARE(w.currentId(), int(FrfWizard::ConfigId));
        QVERIFY(box->isHidden()); // multi-sweep: no adaptive option
        cfg->method()->setCurrentIndex(cfg->method()->findData(int(device::FrfMethod::Multisine)));
        QVERIFY(!box->isHidden());
        QVERIFY(cfg->timeBudget()->isHidden());
        cfg->fmin()->setValue(20.0);
        cfg->fmax()->setValue(3900.0);
        cfg->points()->setValue(388); // 10 Hz lines (min(fmin/2, band/points))
        box->setChecked(true);
        QVERIFY(!cfg->timeBudget()->isHidden());
        // The first pass (2 periods of 100 ms and the settling: 0.94 s, docs/multisine.md) does not fit in 0.5 s.
        cfg->timeBudget()->setValue(0.5);
        auto* estimate = cfg->findChild<QLabel*>("frfEstimate");
        QVERIFY(waitUntil([&] { return estimate->text().contains("0.5"); }, 20000));
        QVERIFY2(!cfg->isComplete(), qPrintable(estimate->text()));
        cfg->timeBudget()->setValue(2.5);
        QVERIFY2(waitUntil([&] { return cfg->isComplete(); }, 20000), qPrintable(estimate->text()));
        QVERIFY2(estimate->text().contains("2.5"), qPrintable(estimate->text()));
        QCOMPARE(cfg->adaptiveBudgetS().value_or(0.0), 2.5);
        maybeScreenshot(&w, "frf-06-adaptive-method");
        w.next();
        auto* run = w.runPage();
        QVERIFY(waitUntil([&] { return !run->isRunning(); }, 120000));
        QVERIFY2(run->succeeded(), qPrintable(run->failure()));
        QVERIFY(progress.size() >= 3);
        for (std::size_t i = 1; i < progress.size(); ++i)
            QVERIFY2(progress[i] >= progress[i - 1], qPrintable(QString::number(i)));
        QCOMPARE(progress.back(), 1.0);
        w.next();
        auto* res = w.resultPage();
        QVERIFY(waitUntil([&] { return res->analysed(); }, 30000));
        maybeScreenshot(&w, "frf-07-adaptive-result");
        const auto& measured = res->measured();
        // The three-phase grid (m + 1/3)·10 Hz (docs/multisine.md): 23.3, 33.3, … 3893.3 Hz.
        QCOMPARE(int(measured.size()), 388);
        std::size_t valid = 0;
        for (bool v : measured.valid)
            valid += v ? 1 : 0;
        QVERIFY(!res->adaptiveSummary()->isHidden());
        const QString summary = res->adaptiveSummary()->text();
        QVERIFY2(summary.contains(QString::number(valid)) && summary.contains(QStringLiteral("388")),
                 qPrintable(summary));
        w.next();
        w.button(QWizard::FinishButton)->click();
        QVERIFY(w.savedSessionId() > 0);
        auto loaded = ctx.database()->loadSession(w.savedSessionId());
        QVERIFY(loaded.ok());
        QCOMPARE(loaded->inputs.at("method").get<std::string>(), std::string("multisine"));
        QCOMPARE(loaded->inputs.at("adaptive").get<bool>(), true);
        QCOMPARE(loaded->inputs.at("time_budget_s").get<double>(), 2.5);
        const nlohmann::json* a = nullptr;
        for (const auto& r : loaded->results)
            if (r.name == "adaptive")
                a = &r.data;
        QVERIFY(a);
        QCOMPARE(a->at("valid_lines").get<std::size_t>(), valid);
        // Within the budget (the drive advances in current ticks of 62.5 µs); a second pass ran and helped.
        QVERIFY(a->at("motion_time_s").get<double>() <= 2.5 + 62.5e-6);
        const auto& passes = a->at("passes");
        QVERIFY(passes.size() >= 2);
        QVERIFY2(valid >= passes[0].at("valid_after").get<std::size_t>() + 39, qPrintable(summary)); // +10 % of lines
        std::size_t left = 0;
        for (const auto& [reason, n] : a->at("invalid_by_reason").items())
            left += n.get<std::size_t>();
        QCOMPARE(left + valid, std::size_t(388));
        QCOMPARE(a->at("invalid_lines").size(), left);

        // Abort in the second pass of a 40 s run: stopped at once, every parameter as before the run, the session kept
        // as aborted.
        const auto before = readAllParameters(ctx);
        FrfWizard w2(ctx);
        w2.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w2));
        w2.safetyPage()->amplitude()->setValue(5.0);
        w2.safetyPage()->confirmation()->setChecked(true);
        w2.next();
        auto* cfg2 = w2.configPage();
        cfg2->method()->setCurrentIndex(cfg2->method()->findData(int(device::FrfMethod::Multisine)));
        cfg2->fmin()->setValue(20.0);
        cfg2->points()->setValue(388);
        cfg2->adaptive()->setChecked(true);
        cfg2->timeBudget()->setValue(40.0); // 40 s of motion take about 1.5 s here: time to press Abort
        QVERIFY(waitUntil([&] { return cfg2->isComplete(); }, 20000));
        progress.clear();
        w2.next();
        auto* run2 = w2.runPage();
        // The first pass ends at 0.94 s of the 40 s budget: beyond 0.05 the second pass runs.
        QVERIFY(waitUntil([&] { return (!progress.empty() && progress.back() > 0.05) || !run2->isRunning(); }, 60000));
        abortAndCheckRestored(ctx, run2, before);
        if (QTest::currentTestFailed())
            return;
        auto aborted = ctx.database()->loadSession(w2.savedSessionId());
        QVERIFY(aborted.ok());
        QCOMPARE(aborted->info.status, store::SessionStatus::Aborted);
        QCOMPARE(aborted->inputs.at("adaptive").get<bool>(), true);
    }

    void abortEndsWithinOneSecondAndRestoresTheParameters()
    {
        gui::AppContext ctx;
        QVERIFY(ctx.openDatabase(m_tmp.filePath("abort.db")));
        QVERIFY(connectTo(ctx, "sim:dd-table"));
        const auto before = readAllParameters(ctx);
        QVERIFY(before.size() > 20);
        double progress = 0.0;
        connect(&ctx.drive(), &gui::DriveController::progress, this, [&](int, double f, const QString&) { progress = f; });
        FrfWizard w(ctx);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        // A long plan (low frequencies settle and measure for seconds of machine time) so that the
        // run is surely still going when Abort is pressed.
        configureAndStart(w, {0.5, 3900.0, 120, 3.0}, false);
        auto* run = w.runPage();
        QVERIFY(waitUntil([&] { return progress > 0.0 || !run->isRunning(); }, 30000));
        abortAndCheckRestored(ctx, run, before);
        if (QTest::currentTestFailed())
            return;
        QVERIFY(!w.button(QWizard::NextButton)->isEnabled());
        auto s = ctx.database()->loadSession(w.savedSessionId());
        QVERIFY(s.ok());
        QCOMPARE(s->info.status, store::SessionStatus::Aborted);
        QVERIFY(!s->info.note.empty());
    }
};

QTEST_MAIN(TestFrfWizard)
#include "tst_frfwizard.moc"

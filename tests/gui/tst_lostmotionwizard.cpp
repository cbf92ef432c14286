// SPDX-License-Identifier: GPL-3.0-or-later
// Lost-motion wizard end to end on the simulated vmc (issue 9), embedded and over Modbus against
// axistune-simdrive: circle tests at three table positions along Y run through the wizard (Circle
// tests of the drive through the DriveController), diagnostics, A/B fit, apply, a verification
// circle, and the stored session. A and B must lie within 10 % of the preset's Y values (resources/machines/vmc.json: A = 0.70 µm/(N·m),
// B = 17 µm/(N·m·m), x₀ = 200 mm), and the verification circle must show a smaller reversal step.
#include "app/gui/AppContext.h"
#include "app/gui/LostMotionWizard.h"
#include "app/gui/WizardPages.h"
#include "app/gui/WizardRegistry.h"
#include "core/sim/MachineDefinition.h"
#include "tests/app/cli/SimDriveProcess.h"
#include "tests/gui/GuiTestUtil.h"
#include "widgets/PolarPlot.h"
#include "core/store/SessionRecord.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>
#include <nlohmann/json.hpp>

using namespace axistune;
using namespace axistune::gui;
using axistune::testing::maybeScreenshot;
using axistune::testing::waitUntil;

namespace {
double presetY(const std::string& key)
{
    auto m = sim::loadPreset("vmc");
    return m->axis("Y")->values.at(key);
}

/// The wizard from the source page to the save on a connected vmc (embedded or over Modbus): circles
/// at Y = −150, 0, 150 mm, diagnostics, fit, apply, a verification circle; checks the stored session
/// (A and B within 10 % of the preset, the reversal step reduced) and returns the fitted A and B.
void runEndToEnd(AppContext& ctx, LostMotionWizard& w, bool screenshots, double& a, double& b)
{
    w.resize(1000, 700);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    auto* src = w.sourcePage();
    auto* machine = w.findChild<QRadioButton*>("lmMachine");
    QVERIFY(machine && machine->isEnabled());
    machine->setChecked(true);
    w.findChild<QLineEdit*>("lmCentres")->setText("-150, 0, 150");
    QVERIFY(src->isComplete());
    if (screenshots)
        maybeScreenshot(&w, "lost-motion-01-source");
    w.next();
    QCOMPARE(w.currentId(), int(LostMotionWizard::Safety));
    w.safetyPage()->confirmation()->setChecked(true);
    QVERIFY(waitUntil([&] { return w.safetyPage()->isComplete(); }, 5000));
    if (screenshots)
        maybeScreenshot(&w, "lost-motion-02-safety");
    w.next();
    QCOMPARE(w.currentId(), int(LostMotionWizard::Circles));
    QVERIFY(waitUntil([&] { return w.circlePage()->isComplete(); }, 60000));
    QCOMPARE(w.data().traces.size(), std::size_t(3));
    if (screenshots)
        maybeScreenshot(&w, "lost-motion-03-circles");
    w.next();
    QCOMPARE(w.currentId(), int(LostMotionWizard::Diagnostics));
    QVERIFY(waitUntil([&] { return w.diagnosticsPage()->isComplete(); }, 60000));
    QVERIFY(w.diagnosticsPage()->table()->rowCount() >= 5);
    QCOMPARE(w.diagnosticsPage()->plot()->traceCount(), 3);
    if (screenshots)
        maybeScreenshot(&w, "lost-motion-04-diagnostics");
    w.next();
    QCOMPARE(w.currentId(), int(LostMotionWizard::Fit));
    if (screenshots)
        maybeScreenshot(&w, "lost-motion-05-fit");
    w.next();
    QCOMPARE(w.currentId(), int(LostMotionWizard::Apply));
    ApplyPage* apply = w.applyPage();
    apply->confirmation()->setChecked(true);
    // The device values must have been read (the diff) before Apply does anything.
    QVERIFY(waitUntil([&] { return !apply->previousValues().empty() && apply->applyButton()->isEnabled(); }, 10000));
    if (screenshots)
        maybeScreenshot(&w, "lost-motion-06-apply");
    apply->applyButton()->click();
    QVERIFY(waitUntil([&] { return apply->applied(); }, 10000));
    w.next();
    QCOMPARE(w.currentId(), int(LostMotionWizard::Verify));
    QVERIFY(waitUntil([&] { return w.currentPage()->isComplete(); }, 60000));
    QVERIFY(w.data().verification.has_value());
    if (screenshots)
        maybeScreenshot(&w, "lost-motion-07-verify");
    w.next();
    QCOMPARE(w.currentId(), int(LostMotionWizard::Save));
    if (screenshots)
        maybeScreenshot(&w, "lost-motion-08-save");
    QVERIFY(w.savedSessionId() > 0);

    auto rec = ctx.database()->loadSession(w.savedSessionId());
    QVERIFY(rec.ok());
    QCOMPARE(QString::fromStdString(rec->info.kind), QString("lost-motion"));
    QCOMPARE(QString::fromStdString(rec->info.axis), QString("Y"));
    const nlohmann::json* fit = nullptr;
    const nlohmann::json* diag = nullptr;
    const nlohmann::json* verify = nullptr;
    for (const auto& r : rec->results) {
        if (r.name == "fit")
            fit = &r.data;
        if (r.name == "diagnostics")
            diag = &r.data;
        if (r.name == "verification")
            verify = &r.data;
    }
    QVERIFY(fit && diag && verify);
    const double aY = presetY("plant.lost_motion_A"), bY = presetY("plant.lost_motion_B");
    a = (*fit)["A_m_per_Nm"].get<double>();
    b = (*fit)["B_per_Nm"].get<double>();
    qInfo("A %.4f um/Nm (preset %.2f), B %.3f um/(Nm m) (preset %.1f), step %.3f -> %.3f um", a * 1e6, aY * 1e6,
          b * 1e6, bY * 1e6, (*verify)["step_before_m"].get<double>() * 1e6,
          (*verify)["step_after_m"].get<double>() * 1e6);
    QVERIFY2(std::abs(a - aY) <= 0.10 * aY, qPrintable(QString("A %1 preset %2").arg(a).arg(aY)));
    QVERIFY2(std::abs(b - bY) <= 0.10 * bY, qPrintable(QString("B %1 preset %2").arg(b).arg(bY)));
    QVERIFY((*diag)["findings"].size() >= 5);
    const double before = (*verify)["step_before_m"].get<double>();
    const double after = (*verify)["step_after_m"].get<double>();
    QVERIFY2(std::abs(after) < std::abs(before), qPrintable(QString("step %1 -> %2").arg(before).arg(after)));
    // The Y lost motion at the last position (cy = 150 mm): (A + B·(x₀ + cy))·ΔT, ΔT = 2 × 0.305 N·m.
    const double want = (aY + bY * (presetY("plant.screw_offset") + 0.15)) * 2.0 * presetY("plant.coulomb_motor");
    QVERIFY2(std::abs(before - want) <= 0.10 * want, qPrintable(QString("before %1 want %2").arg(before).arg(want)));
    // Captures: three traces and the verification; the model and both parameter sets.
    QCOMPARE(rec->captures.size(), std::size_t(4));
    bool model = false;
    for (const auto& m : rec->models)
        model = model || (m.kind == "lost_motion" && std::abs(m.data["A_m_per_Nm"].get<double>() - a) < 1e-15);
    QVERIFY(model);
    QCOMPARE(rec->parameterSets.size(), std::size_t(2));
    QVERIFY(!rec->journal.empty());
}

}  // namespace

class TestLostMotionWizard : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { axistune::testing::installLanguageFromEnv(); }

    void registeredAndWorksOffline()
    {
        const WizardEntry* e = findWizard("lost-motion");
        QVERIFY(e);
        QCOMPARE(e->order, 50);
        QVERIFY(!e->needsDrive);
    }

    void badFileIsReportedWithFileAndLine()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("bad.csv");
        {
            std::ofstream f(path.toStdString());
            f << "# radius_mm=50\n# feed_mm_min=1000\n# direction=ccw\nangle_deg,deviation_um\n0,1\n1,abc\n";
        }
        AppContext ctx;
        LostMotionWizard w(ctx);
        w.show();
        QVERIFY(!w.sourcePage()->addFiles({path}));
        const auto* label = w.findChild<QLabel*>("lmFileErrors");
        QVERIFY(label);
        QVERIFY2(label->text().contains("bad.csv") && label->text().contains("line 6"), qPrintable(label->text()));
        QVERIFY(!w.sourcePage()->isComplete());
    }

    void circlesOnVmcGivePresetAandB()
    {
        QTemporaryDir dir;
        AppContext ctx;
        QVERIFY(ctx.openDatabase(dir.filePath("store.sqlite")));
        ctx.drive().connectTo("sim:vmc");
        QVERIFY(waitUntil([&] { return ctx.drive().isConnected(); }, 20000));
        LostMotionWizard w(ctx);
        double a = 0.0, b = 0.0;
        runEndToEnd(ctx, w, true, a, b);
        if (QTest::currentTestFailed())
            return;

        // The same traces as ball-bar files, imported offline: same A and B, apply and verify skipped.
        QStringList files;
        for (std::size_t i = 0; i < w.data().traces.size(); ++i) {
            files << dir.filePath(QString("c%1.csv").arg(i));
            QVERIFY(io::writeBallBarCsvFile(files.back().toStdString(), w.data().traces[i]).ok());
        }
        AppContext offline;
        QVERIFY(offline.openDatabase(dir.filePath("offline.sqlite")));
        LostMotionWizard w2(offline);
        w2.show();
        QVERIFY(!w2.findChild<QRadioButton*>("lmMachine")->isEnabled());
        QVERIFY(w2.sourcePage()->addFiles(files));
        w2.next();
        QCOMPARE(w2.currentId(), int(LostMotionWizard::Diagnostics));
        QVERIFY(waitUntil([&] { return w2.diagnosticsPage()->isComplete(); }, 60000));
        w2.next();
        QCOMPARE(w2.currentId(), int(LostMotionWizard::Fit));
        w2.next();
        QCOMPARE(w2.currentId(), int(LostMotionWizard::Save));
        QVERIFY(w2.savedSessionId() > 0);
        QVERIFY(w2.findChild<QLabel*>("lmSummary")->text().contains("need a connection"));
        QVERIFY(std::abs(w2.data().fit->aMPerNm - a) < 1e-3 * a);
        QVERIFY(std::abs(w2.data().fit->bPerNm - b) < 1e-3 * b);
    }

    // The same wizard over Modbus against axistune-simdrive: every circle is a Circle test of the
    // drive (both axes move in the server), the traces come over the link.
    void circlesOverModbusGivePresetAandB()
    {
        axistune::testing::SimDrive sd("--preset vmc");
        QVERIFY2(sd.port() > 0, sd.log().c_str());
        QTemporaryDir dir;
        AppContext ctx;
        QVERIFY(ctx.openDatabase(dir.filePath("store.sqlite")));
        ctx.drive().connectTo(QString::fromStdString(sd.uri()));
        QVERIFY(waitUntil([&] { return ctx.drive().isConnected(); }, 20000));
        LostMotionWizard w(ctx);
        double a = 0.0, b = 0.0;
        runEndToEnd(ctx, w, false, a, b);
    }

    // Abort stops the running circle at once (not after it): no trace of it, the runner reports the
    // abort within a second, and the drive takes the next request.
    void abortStopsTheRunningCircle()
    {
        AppContext ctx;
        ctx.drive().connectTo("sim:vmc");
        QVERIFY(waitUntil([&] { return ctx.drive().isConnected(); }, 20000));
        CircleRunner runner(ctx);
        bool finished = false, ok = true, aborted = false;
        int lastDone = 0;
        connect(&runner, &CircleRunner::progress, this, [&](int done, int, const QString&) { lastDone = done; });
        connect(&runner, &CircleRunner::finished, this, [&](bool o, const QString&, bool ab) {
            finished = true;
            ok = o;
            aborted = ab;
        });
        sim::CircleTestOptions o;
        o.axisX = "X";
        o.axisY = "Y";
        o.feedMPerS = 200.0 / 60000.0;  // 200 mm/min: about 2 min of machine time per circle
        runner.start("XY", {o, o});
        QVERIFY(waitUntil([&] { return lastDone > 50; }, 20000));  // 5 % into the first circle
        QElapsedTimer t;
        t.start();
        runner.abort();
        QVERIFY(waitUntil([&] { return finished; }, 5000));
        qInfo("abort reported after %lld ms at %d/1000 of the first circle", static_cast<long long>(t.elapsed()), lastDone);
        QVERIFY(t.elapsed() < 1000);
        QVERIFY(!ok && aborted);
        QVERIFY(runner.traces().empty());
        QVERIFY(lastDone < 1000);
        // The drive is idle again: a parameter read answers.
        bool read = false;
        connect(&ctx.drive(), &DriveController::replied, this, [&](const DriveReply& r) {
            read = read || (r.ok && r.kind == DriveReply::Kind::ReadParameters);
        });
        ctx.drive().readParameters("Y", {"position.kp"});
        QVERIFY(waitUntil([&] { return read; }, 5000));
    }
};

QTEST_MAIN(TestLostMotionWizard)
#include "tst_lostmotionwizard.moc"

// SPDX-License-Identifier: GPL-3.0-or-later
// Velocity/position-loop wizard end to end on the simulated two-inertia bench (issue 9 item 2). The
// fitted model comes from a saved two-inertia session (written here with the preset's J_m, J_L, K, C,
// resources/machines/two-inertia.json); the wizard proposes the chapter 5 rule, which the test computes
// itself: K_P = k·√2·ω_l·J_m, K_I = k·ω_l²·J_m with k = 10 and a bandwidth ω_l = 2π·18 rad/s (the
// preset's loop has the thesis's 24 Hz, so before and after differ; spec
// lost-motion-and-two-inertia.md §2.8, corrected 5.13). Then: velocity step before, apply, read back,
// step after, the stored session.
#include "app/gui/AppContext.h"
#include "app/gui/VelocityLoopWizard.h"
#include "app/gui/WizardPages.h"
#include "app/gui/WizardRegistry.h"
#include "core/sim/MachineDefinition.h"
#include "core/store/FrfCapture.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QRadioButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <complex>
#include <numbers>

#include "core/store/SessionRecord.h"
#include "tests/gui/GuiTestUtil.h"

using namespace axistune;
using namespace axistune::gui;
using axistune::testing::maybeScreenshot;
using axistune::testing::waitUntil;

namespace {
double preset(const std::string& key)
{
    auto m = sim::loadPreset("two-inertia");
    return m->axis("A")->values.at(key);
}

} // namespace

class TestVelocityLoopWizard : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { axistune::testing::installLanguageFromEnv(); }

    void registered()
    {
        const WizardEntry* e = findWizard("velocity-loop");
        QVERIFY(e);
        QCOMPARE(e->order, 40);
    }

    void inertiaRuleOnTheTwoInertiaBench()
    {
        const double jm = preset("plant.inertia_motor");
        QTemporaryDir dir;
        AppContext ctx;
        QVERIFY(ctx.openDatabase(dir.filePath("store.sqlite")));
        ctx.drive().connectTo("sim:two-inertia");
        QVERIFY(waitUntil([&] { return ctx.drive().isConnected(); }, 20000));
        // A two-inertia session with the fitted model (here: the preset's values).
        store::SessionRecord fit;
        fit.info.kind = "two-inertia";
        fit.info.axis = "A";
        fit.results.push_back({"fit",
                               {{"Jm_kgm2", jm},
                                {"JL_kgm2", preset("plant.inertia_load")},
                                {"K_Nm_per_rad", preset("plant.coupling_stiffness")},
                                {"C_Nms_per_rad", preset("plant.coupling_damping")},
                                {"delay_s", 0.0}},
                               {}});
        auto fitId = ctx.saveSession(fit);
        QVERIFY(fitId.ok());

        const double k = 10.0, bandwidthHz = 18.0, wl = 2.0 * std::numbers::pi * bandwidthHz;
        const double wantKp = k * std::sqrt(2.0) * wl * jm, wantKi = k * wl * wl * jm;

        qint64 sessionId = 0;
        {
            VelocityLoopWizard w(ctx);
            w.resize(1000, 700);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            auto* src = w.sourcePage();
            QCOMPARE(src->modelSessions()->currentData().value<qint64>(), *fitId);
            QCOMPARE(src->inertia()->value(), jm);
            src->bandwidth()->setValue(bandwidthHz);
            src->gainFactor()->setValue(k);
            maybeScreenshot(&w, "velocity-loop-01-source");
            w.next();
            QCOMPARE(w.currentId(), int(VelocityLoopWizard::Safety));
            w.safetyPage()->confirmation()->setChecked(true);
            QVERIFY(waitUntil([&] { return w.safetyPage()->isComplete(); }, 5000));
            maybeScreenshot(&w, "velocity-loop-02-safety");
            w.next();
            QCOMPARE(w.currentId(), int(VelocityLoopWizard::Run));
            QVERIFY(waitUntil([&] { return w.runPage()->isComplete(); }, 60000));
            QVERIFY(w.runPage()->succeeded());
            w.next();
            QCOMPARE(w.currentId(), int(VelocityLoopWizard::Design));
            QVERIFY(waitUntil([&] { return w.designPage()->isComplete(); }, 20000));
            const auto& d = w.data();
            qInfo("proposed K_P %.6g (want %.6g), K_I %.6g (want %.6g); crossover %.2f Hz, PM %.1f deg, position "
                  "gain %.3g 1/s (limit %.3g)",
                  d.proposed.kpNmsPerRad, wantKp, d.proposed.kiNmPerRad, wantKi, d.marginsAfter.crossoverHz,
                  d.marginsAfter.phaseMarginDeg, d.position.recommendedPerS, d.position.limitPerS);
            QVERIFY(std::abs(d.proposed.kpNmsPerRad - wantKp) <= 1e-9 * wantKp);
            QVERIFY(std::abs(d.proposed.kiNmPerRad - wantKi) <= 1e-9 * wantKi);
            QVERIFY(d.stepBefore);
            QVERIFY(d.predictedAfter.has_value());
            QVERIFY(w.designPage()->table()->rowCount() >= 8);
            // The position gain is recommended but written only on request (the verification tests the velocity
            // loop only).
            auto* positionBox = w.designPage()->findChild<QCheckBox*>("vlApplyPositionGain");
            QVERIFY(positionBox && positionBox->isEnabled() && !positionBox->isChecked());
            maybeScreenshot(&w, "velocity-loop-03-design");
            w.next();
            QCOMPARE(w.currentId(), int(VelocityLoopWizard::Apply));
            ApplyPage* apply = w.applyPage();
            apply->confirmation()->setChecked(true);
            QVERIFY(waitUntil([&] { return !apply->previousValues().empty() && apply->applyButton()->isEnabled(); },
                              10000));
            QCOMPARE(apply->diffTable()->rowCount(), 2); // K_P and K_I, no position gain
            maybeScreenshot(&w, "velocity-loop-04-apply");
            apply->applyButton()->click();
            QVERIFY(waitUntil([&] { return apply->applied(); }, 10000));
            QVERIFY(!apply->readBack().count("position.kp"));
            QVERIFY(std::abs(apply->readBack().at("velocity.kp") - wantKp) <= 1e-9 * wantKp);
            QVERIFY(std::abs(apply->readBack().at("velocity.ki") - wantKi) <= 1e-9 * wantKi);
            w.next();
            QCOMPARE(w.currentId(), int(VelocityLoopWizard::VerifyRun));
            QVERIFY(waitUntil([&] { return w.verifyRunPage()->isComplete(); }, 60000));
            w.next();
            QCOMPARE(w.currentId(), int(VelocityLoopWizard::Verify));
            QVERIFY(w.data().stepAfter);
            maybeScreenshot(&w, "velocity-loop-05-verify");
            w.next();
            QCOMPARE(w.currentId(), int(VelocityLoopWizard::Save));
            maybeScreenshot(&w, "velocity-loop-06-save");
            sessionId = w.savedSessionId();
            QVERIFY(sessionId > 0);
        }

        auto rec = ctx.database()->loadSession(sessionId);
        QVERIFY(rec.ok());
        QCOMPARE(QString::fromStdString(rec->info.kind), QString("velocity-loop"));
        QCOMPARE(QString::fromStdString(rec->info.axis), QString("A"));
        const auto* prop = rec->result("proposal");
        QVERIFY(prop);
        QVERIFY(std::abs((*prop)["velocity_kp_Nms_per_rad"].get<double>() - wantKp) <= 1e-9 * wantKp);
        QVERIFY(std::abs((*prop)["velocity_ki_Nm_per_rad"].get<double>() - wantKi) <= 1e-9 * wantKi);
        bool applied = false, before = false, after = false;
        for (const auto& ps : rec->parameterSets)
            if (ps.source == store::ParameterSource::Applied) {
                applied = true;
                QVERIFY(std::abs(ps.values.at("velocity.kp") - wantKp) <= 1e-9 * wantKp);
            }
        for (const auto& c : rec->captures) {
            before = before || c.name == "step_before";
            after = after || c.name == "step_after";
        }
        QVERIFY(applied && before && after);
        QVERIFY(!rec->journal.empty());
    }

    void cancelAfterApplyRestoresTheGainsAndKeepsTheSessionAsAborted()
    {
        const double jm = preset("plant.inertia_motor");
        const double kpBefore = preset("velocity.kp"), kiBefore = preset("velocity.ki");
        QTemporaryDir dir;
        AppContext ctx;
        QVERIFY(ctx.openDatabase(dir.filePath("store.sqlite")));
        ctx.drive().connectTo("sim:two-inertia");
        QVERIFY(waitUntil([&] { return ctx.drive().isConnected(); }, 20000));
        VelocityLoopWizard w(ctx);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.sourcePage()->inertia()->setValue(jm);
        w.sourcePage()->bandwidth()->setValue(18.0); // the preset's gains follow from 24 Hz
        w.next();
        w.safetyPage()->confirmation()->setChecked(true);
        QVERIFY(waitUntil([&] { return w.safetyPage()->isComplete(); }, 5000));
        w.next();
        QVERIFY(waitUntil([&] { return w.runPage()->isComplete(); }, 60000));
        w.next();
        QVERIFY(waitUntil([&] { return w.designPage()->isComplete(); }, 20000));
        const double kpNew = w.data().proposed.kpNmsPerRad;
        QVERIFY(std::abs(kpNew - kpBefore) > 0.01 * kpBefore); // a real change to undo
        w.next();
        ApplyPage* apply = w.applyPage();
        apply->confirmation()->setChecked(true);
        QVERIFY(waitUntil([&] { return !apply->previousValues().empty() && apply->applyButton()->isEnabled(); }, 10000));
        apply->applyButton()->click();
        QVERIFY(waitUntil([&] { return apply->applied(); }, 10000));
        // Cancel instead of verifying: the gains from before come back and the session is kept as aborted.
        w.reject();
        QVERIFY(waitUntil([&] { return !w.isVisible(); }, 10000));
        model::ParameterValues back;
        const int id = ctx.drive().readParameters("A", {"velocity.kp", "velocity.ki"})->id();
        connect(&ctx.drive(), &DriveController::replied, this, [&](const DriveReply& r) {
            if (r.id == id)
                back = r.values;
        });
        QVERIFY(waitUntil([&] { return back.size() == 2; }, 10000));
        QCOMPARE(back.at("velocity.kp"), kpBefore);
        QCOMPARE(back.at("velocity.ki"), kiBefore);
        auto sessions = ctx.database()->listSessions();
        QVERIFY(sessions.ok());
        QCOMPARE(sessions->size(), std::size_t(1));
        const auto& s = sessions->front();
        QCOMPARE(QString::fromStdString(s.kind), QString("velocity-loop"));
        QCOMPARE(int(s.status), int(store::SessionStatus::Aborted));
        QVERIFY2(QString::fromStdString(s.note).contains("Cancelled by the operator") &&
                     QString::fromStdString(s.note).contains("restored"),
                 s.note.c_str());
        auto rec = ctx.database()->loadSession(s.id);
        QVERIFY(rec.ok());
        QVERIFY(rec->journal.size() >= 4); // the write and the restore of K_P and K_I
    }

    void marginsOnASavedPlantResponseOffline()
    {
        // An FRF session holding the plant 1/(jωJ) (no "measurement" tag: taken as the plant). For a
        // crossover ω_c with phase margin PM the PI must give |C| = ω_c J and arg C = −90° + PM:
        // K_P = ω_c J cos(90° − PM), K_I = ω_c² J sin(90° − PM) (independent of the core's solver).
        QTemporaryDir dir;
        AppContext ctx;
        QVERIFY(ctx.openDatabase(dir.filePath("store.sqlite")));
        const double j = 2e-3, fc = 40.0, pm = 50.0;
        dsp::FrequencyResponse plant;
        for (int i = 0; i < 200; ++i) {
            const double f = std::pow(10.0, 3.0 * i / 199.0);
            plant.push(f, 1.0 / std::complex<double>(0.0, 2.0 * std::numbers::pi * f * j), std::nan(""), true);
        }
        store::SessionRecord frf;
        frf.info.kind = "frf";
        frf.info.axis = "X";
        frf.captures.push_back({"measured", store::frfAsCapture(plant)});
        auto frfId = ctx.saveSession(frf);
        QVERIFY(frfId.ok());

        VelocityLoopWizard w(ctx);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.findChild<QRadioButton*>("vlFrfMethod")->setChecked(true);
        QVERIFY(w.findChild<QRadioButton*>("vlFromSession")->isChecked()); // offline: no measurement
        QComboBox* sessions = w.sourcePage()->frfSessions();
        const int idx = sessions->findData(QVariant::fromValue<qint64>(*frfId));
        QVERIFY(idx >= 0);
        sessions->setCurrentIndex(idx);
        w.findChild<QDoubleSpinBox*>("vlCrossover")->setValue(fc);
        w.findChild<QDoubleSpinBox*>("vlPhaseMargin")->setValue(pm);
        w.next();
        QCOMPARE(w.currentId(), int(VelocityLoopWizard::Design));
        QVERIFY(waitUntil([&] { return w.designPage()->isComplete(); }, 10000));
        const double wc = 2.0 * std::numbers::pi * fc, lag = (90.0 - pm) * std::numbers::pi / 180.0;
        const double wantKp = wc * j * std::cos(lag), wantKi = wc * wc * j * std::sin(lag);
        const auto& d = w.data();
        qInfo("margins: K_P %.6g (want %.6g), K_I %.6g (want %.6g), crossover %.3f Hz, PM %.2f deg",
              d.proposed.kpNmsPerRad, wantKp, d.proposed.kiNmPerRad, wantKi, d.marginsAfter.crossoverHz,
              d.marginsAfter.phaseMarginDeg);
        QVERIFY(std::abs(d.proposed.kpNmsPerRad - wantKp) <= 1e-3 * wantKp);
        QVERIFY(std::abs(d.proposed.kiNmPerRad - wantKi) <= 1e-3 * wantKi);
        QVERIFY(std::abs(d.marginsAfter.crossoverHz - fc) <= 0.01 * fc);
        w.next();
        QCOMPARE(w.currentId(), int(VelocityLoopWizard::Save));
        auto rec = ctx.database()->loadSession(w.savedSessionId());
        QVERIFY(rec.ok());
        QCOMPARE(rec->inputs["method"].get<std::string>(), std::string("margins"));
        QVERIFY(std::abs((*rec->result("proposal"))["velocity_kp_Nms_per_rad"].get<double>() - wantKp) <=
                1e-3 * wantKp);
    }
};

QTEST_MAIN(TestVelocityLoopWizard)
#include "tst_velocityloopwizard.moc"

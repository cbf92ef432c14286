// SPDX-License-Identifier: GPL-3.0-or-later
// The drive thread's undo of a position-PID tune (DriveController::undoPidTune, app/gui/DriveControllerPidTune.cpp),
// which the NC PID page journals (docs/storage.md "Journal"), on the embedded sim:vmc X, without HAL: refused with
// nothing written after a later change; forced, its reply carries what the drive held just before the undo wrote (the
// later change, not the value the tune applied), so the journal starts there; a notch the tune left as it was is
// neither read nor written; a notch to put back on a drive that is no HAL session refuses the undo. The notch itself
// on HAL: tests/gui/hal (GuiOnHal.VelocityWizardTunesThePositionPidAndUndoes, run by the HAL suite).
#include "app/gui/AppContext.h"
#include "core/autotune/PidTune.h"

#include <QTemporaryDir>
#include <QtTest>

#include "tests/gui/AutoTuneTestUtil.h"
#include "tests/gui/GuiTestUtil.h"

using namespace axistune;
using namespace axistune::gui;
using axistune::testing::openOn;
using axistune::testing::readAll;
using axistune::testing::waitUntil;

namespace {

DriveReply await(DriveRequest* r)
{
    DriveReply out;
    bool done = false;
    QObject::connect(r, &DriveRequest::finished, [&](const DriveReply& reply) {
        out = reply;
        done = true;
    });
    waitUntil([&] { return done; }, 20000);
    return out;
}

bool writeOne(AppContext& ctx, const std::string& key, double value)
{
    return await(ctx.drive().writeParameters("X", {{key, value}})).ok;
}

} // namespace

class TestPidTuneUndo : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { axistune::testing::installLanguageFromEnv(); }

    void aForcedUndoReportsWhatTheDriveHeldJustBefore()
    {
        QTemporaryDir dir;
        AppContext ctx;
        model::ParameterValues before;
        openOn(dir, ctx, before);
        const std::string key = "velocity.kp";
        QVERIFY(before.count(key));
        const double kp0 = before.at(key), applied = 1.05 * kp0, later = 1.1 * kp0;
        // The tune applied `applied`; someone wrote `later` since. The notch: the tune left it as it was.
        QVERIFY(writeOne(ctx, key, applied));
        QVERIFY(writeOne(ctx, key, later));
        autotune::AppliedTune tune{"X", {{key, kp0}}, {{key, applied}}};
        const tuning::BiquadNotch n{150.0, 1.0};
        const autotune::PidTuneNotchUndo notch{"X", n, n};

        const DriveReply refused = await(ctx.drive().undoPidTune(tune, notch, false));
        QVERIFY(!refused.ok);
        QCOMPARE(refused.code, ErrorCode::Safety);
        QCOMPARE(readAll(ctx, "X").at(key), later); // nothing written

        const DriveReply forced = await(ctx.drive().undoPidTune(tune, notch, true));
        QVERIFY2(forced.ok, qPrintable(forced.error));
        QCOMPARE(readAll(ctx, "X").at(key), kp0); // the embedded simulator keeps doubles: exact
        QCOMPARE(forced.undone.size(), std::size_t(1));
        QCOMPARE(forced.undone[0].applied, later);
        QCOMPARE(forced.undone[0].restored, kp0);
        QVERIFY(forced.pidNotchUndone);
        QVERIFY(!forced.pidNotchUndone->changed);
        // The page's journal of it: from the later change to the value before the tune, no notch entry.
        const auto writes = autotune::pidTuneUndoWrites(forced.undone, *forced.pidNotchUndone);
        QCOMPARE(writes.size(), std::size_t(1));
        QCOMPARE(writes[0].key, key);
        QCOMPARE(writes[0].from.value_or(NAN), later);
        QCOMPARE(writes[0].to, kp0);
    }

    void aNotchToPutBackOnADriveWithoutHalRefusesTheUndo()
    {
        QTemporaryDir dir;
        AppContext ctx;
        model::ParameterValues before;
        openOn(dir, ctx, before);
        // A notch-only tune (no gain) whose notch is to be removed: sim: has no HAL session to remove it from.
        const autotune::AppliedTune tune{"X", {}, {}};
        const autotune::PidTuneNotchUndo notch{"X", std::nullopt, tuning::BiquadNotch{107.33, 0.7}};
        const DriveReply r = await(ctx.drive().undoPidTune(tune, notch, true));
        QVERIFY(!r.ok);
        QVERIFY2(r.error.contains("HAL"), qPrintable(r.error));
        QVERIFY(!r.pidNotchUndone);
        QCOMPARE(readAll(ctx, "X"), before);
    }
};

QTEST_MAIN(TestPidTuneUndo)
#include "tst_pidtuneundo.moc"

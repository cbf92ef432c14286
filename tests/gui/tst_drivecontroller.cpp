// SPDX-License-Identifier: GPL-3.0-or-later
// DriveController (the GUI's drive link on its own thread) against the built-in sim:vmc and over
// Modbus against axistune-simdrive: connect, read, write with read-back, refused writes, a step test,
// Abort of a long FRF test (within 1 s, parameters restored), and a drive killed during a test (the
// reply fails, connectionLost, not connected, the GUI event loop kept running).
#include "app/gui/DriveController.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTimer>
#include <QtTest>

#include <optional>

#include "tests/app/cli/SimDriveProcess.h"
#include "tests/gui/DriveTestRequests.h"
#include "tests/gui/GuiTestUtil.h"

using axistune::gui::DriveController;
using axistune::gui::DriveReply;
using axistune::testing::longFrf;
using axistune::testing::waitUntil;

namespace {
/// Collects the reply with one id.
struct ReplyCatcher {
    explicit ReplyCatcher(DriveController& c)
    {
        QObject::connect(&c, &DriveController::replied, &c, [this](const DriveReply& r) { replies.push_back(r); });
    }
    std::optional<DriveReply> find(int id) const
    {
        for (const auto& r : replies)
            if (r.id == id)
                return r;
        return std::nullopt;
    }
    DriveReply wait(axistune::gui::DriveRequest* request, int ms = 30000) const { return wait(request->id(), ms); }
    DriveReply wait(int id, int ms = 30000) const
    {
        waitUntil([&] { return find(id).has_value(); }, ms);
        auto r = find(id);
        return r ? *r : DriveReply{};
    }
    std::vector<DriveReply> replies;
};

}  // namespace

class TestDriveController : public QObject {
    Q_OBJECT
private slots:
    void connectReadWriteAndRefuse()
    {
        DriveController c;
        ReplyCatcher rc(c);
        const DriveReply con = rc.wait(c.connectTo("sim:vmc"));
        QVERIFY2(con.ok, qPrintable(con.error));
        QVERIFY(c.isConnected());
        QVERIFY(con.identity.has_value());
        QCOMPARE(con.identity->axes, (std::vector<std::string>{"X", "Y", "Z"}));

        const DriveReply all = rc.wait(c.readParameters("X"));
        QVERIFY(all.ok);
        QVERIFY(all.values.size() > 20);
        QCOMPARE(all.values.at("current.period"), 62.5e-6);  // the vmc's current loop (DESIGN.md)

        // Write + read-back of a writable key.
        const DriveReply w = rc.wait(c.writeParameters("X", {{"velocity.kp", 0.95}}));
        QVERIFY2(w.ok, qPrintable(w.error));
        QCOMPARE(w.values.at("velocity.kp"), 0.95);
        const DriveReply back = rc.wait(c.readParameters("X", {"velocity.kp"}));
        QVERIFY(back.ok);
        QCOMPARE(back.values.at("velocity.kp"), 0.95);

        // Out of range (the limit is 1e5 N·m·s/rad): refused, the key named, nothing changed.
        const DriveReply bad = rc.wait(c.writeParameters("X", {{"velocity.kp", 1e9}}));
        QVERIFY(!bad.ok);
        QVERIFY2(bad.error.contains("velocity.kp"), qPrintable(bad.error));
        QCOMPARE(bad.code, axistune::ErrorCode::OutOfRange);
        const DriveReply after = rc.wait(c.readParameters("X", {"velocity.kp"}));
        QCOMPARE(after.values.at("velocity.kp"), 0.95);
        QVERIFY(c.isConnected());  // a refused request is not a lost link
    }

    void stepTestReturnsTheTrace()
    {
        DriveController c;
        ReplyCatcher rc(c);
        QVERIFY(rc.wait(c.connectTo("sim:vmc")).ok);
        axistune::device::TestRequest t;
        t.axis = "X";
        auto& step = t.test.emplace<axistune::device::StepTest>();
        step.velocityRadS = 10.0; // rad/s
        step.recordS = 0.1;
        const DriveReply r = rc.wait(c.runTest(t));
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.testState, axistune::device::TestState::Completed);
        QVERIFY(r.capture);
        for (const char* ch : {"t_s", "velocity_cmd_rad_s", "motor_vel_rad_s", "torque_cmd_Nm", "current_A"})
            QVERIFY2(r.capture->channel(ch), ch);
        // Length: duration × trace rate (metadata), ±1 sample.
        const auto fsHz = r.capture->metadata.number("fs_Hz");
        QVERIFY2(fsHz, fsHz ? "" : fsHz.error().detail.c_str());
        const double fs = *fsHz;
        QVERIFY(std::abs(static_cast<double>(r.capture->size()) - 0.1 * fs) <= 1.0);
        const auto& cmd = r.capture->channel("velocity_cmd_rad_s")->data;
        QCOMPARE(cmd.front(), 0.0);
        QCOMPARE(cmd.back(), 10.0);
    }

    void abortEndsALongFrfTestWithinOneSecond()
    {
        DriveController c;
        ReplyCatcher rc(c);
        QVERIFY(rc.wait(c.connectTo("sim:vmc")).ok);
        const DriveReply before = rc.wait(c.readParameters("X"));
        QVERIFY(before.ok);
        double lastProgress = 0.0;
        connect(&c, &DriveController::progress, this, [&](int, double f, const QString&) { lastProgress = f; });
        const int id = c.runTest(longFrf("X"))->id();
        QVERIFY(waitUntil([&] { return lastProgress > 0.01; }, 20000));
        QVERIFY2(!rc.find(id), "the test ended before Abort: make it longer");
        QElapsedTimer clock;
        clock.start();
        c.abort();
        QVERIFY(waitUntil([&] { return rc.find(id).has_value(); }, 5000));
        const qint64 ms = clock.elapsed();
        QVERIFY2(ms < 1000, qPrintable(QString("Abort took %1 ms").arg(ms)));
        const DriveReply r = *rc.find(id);
        QVERIFY(!r.ok);
        QCOMPARE(r.testState, axistune::device::TestState::Aborted);
        QCOMPARE(r.code, axistune::ErrorCode::Aborted);
        QVERIFY(c.isConnected());
        const DriveReply afterAbort = rc.wait(c.readParameters("X"));
        QVERIFY(afterAbort.ok);
        QCOMPARE(afterAbort.values, before.values);
    }

    void killedSimdriveDuringATestIsALostConnection()
    {
        axistune::testing::SimDrive sd("--preset vmc");
        QVERIFY(sd.port() > 0);
        DriveController c;
        ReplyCatcher rc(c);
        QSignalSpy lost(&c, &DriveController::connectionLost);
        const DriveReply con = rc.wait(c.connectTo(QString::fromStdString(sd.uri("timeout_ms=300"))));
        QVERIFY2(con.ok, qPrintable(con.error));
        QCOMPARE(con.identity->axes, (std::vector<std::string>{"X", "Y", "Z"}));
        const DriveReply p = rc.wait(c.readParameters("Y", {"velocity.kp"}));
        QVERIFY(p.ok);

        // The GUI thread's event loop: a timer ticking every 10 ms; the largest gap is measured.
        axistune::testing::TickMeter meter;

        double lastProgress = 0.0;
        connect(&c, &DriveController::progress, this, [&](int, double f, const QString&) { lastProgress = f; });
        const int id = c.runTest(longFrf("X"))->id();
        QVERIFY(waitUntil([&] { return lastProgress > 0.0; }, 30000));
        QVERIFY(!rc.find(id));
        const int ticksBefore = meter.ticks();
        sd.stop(SIGKILL);
        QVERIFY(waitUntil([&] { return rc.find(id).has_value(); }, 30000));
        const DriveReply r = *rc.find(id);
        QVERIFY(!r.ok);
        QVERIFY2(!r.error.isEmpty(), "the reply names the failure");
        QVERIFY(waitUntil([&] { return lost.count() > 0; }, 5000));
        QVERIFY(!c.isConnected());
        // The event loop kept running while the worker waited on the dead link.
        QVERIFY(meter.ticks() > ticksBefore + 5);
        QVERIFY2(meter.maxGapMs() < 500, qPrintable(QString("event loop stalled for %1 ms").arg(meter.maxGapMs())));
        // A request after the loss fails at once with a message, without hanging.
        const DriveReply again = rc.wait(c.readParameters("X"), 5000);
        QVERIFY(!again.ok);
    }
};

QTEST_MAIN(TestDriveController)
#include "tst_drivecontroller.moc"

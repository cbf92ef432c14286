// SPDX-License-Identifier: GPL-3.0-or-later
// The Connect dialog lists the registered drive backends and builds each settings form from the
// backend's description (core/device/DriveRegistry.h, docs/drive-seam.md): one choice per backend,
// fields by type with units, URIs from the forms, the labels translated (context "DriveRegistry"), a
// replayed capture connected through the dialog. Screenshots connect-dialog-*-en/ja.png.
#include "app/gui/AppContext.h"
#include "app/gui/ConnectDialog.h"
#include "core/device/DriveRegistry.h"
#include "core/io/CaptureCsv.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QLabel>
#include <QLineEdit>
#include <QRadioButton>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTranslator>
#include <QtTest>

#include "tests/gui/GuiTestUtil.h"

using namespace axistune;
using namespace axistune::testing;

class TstConnectDialog : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QCoreApplication::setOrganizationName("axistune-test-connect");
        QSettings().clear();  // the dialog remembers settings; every run starts from the defaults
        installLanguageFromEnv();
    }

    void listsEveryRegisteredBackend()
    {
        gui::AppContext ctx;
        gui::ConnectDialog d(ctx);
        const auto& backends = device::registeredBackends();
        QCOMPARE(d.findChildren<QRadioButton*>().size(), static_cast<qsizetype>(backends.size()));
        for (const auto& b : backends) {
            auto* radio = d.findChild<QRadioButton*>("backendRadio_" + gui::backendKey(b));
            QVERIFY2(radio, b.scheme.c_str());
            QCOMPARE(radio->text(), QCoreApplication::translate("DriveRegistry", b.label.c_str()));
            QVERIFY(d.selectBackend(QString::fromStdString(b.scheme)));
            QVERIFY(radio->isChecked());
        }
    }

    void formsAreBuiltFromTheSettings()
    {
        gui::AppContext ctx;
        gui::ConnectDialog d(ctx);
        d.show();
        // Modbus: host text, port and timeout spin boxes with range and unit, register map text.
        QVERIFY(d.selectBackend("modbus://"));
        auto* port = d.findChild<QSpinBox*>("setting_modbus_port");
        auto* timeout = d.findChild<QSpinBox*>("setting_modbus_timeout_ms");
        QVERIFY(port && timeout && d.findChild<QLineEdit*>("setting_modbus_host"));
        QCOMPARE(port->minimum(), 1);
        QCOMPARE(port->maximum(), 65535);
        QCOMPARE(timeout->suffix(), QStringLiteral(" ms"));
        d.setModbus("10.0.0.5", 1502);
        QCOMPARE(d.uri(), QStringLiteral("modbus://10.0.0.5:1502"));
        timeout->setValue(250);
        QCOMPARE(d.uri(), QStringLiteral("modbus://10.0.0.5:1502?timeout_ms=250"));
        d.findChild<QLineEdit*>("setting_modbus_host")->clear();
        QVERIFY(d.uri().isEmpty());
        d.startConnect(); // refused before anything is sent, with the translated label
        QVERIFY(d.errorText().contains(QCoreApplication::translate("DriveRegistry", "Host")));
        maybeScreenshot(&d, "connect-dialog-modbus");
        // Simulated machine: the presets as a list, the seed. The Modbus form's refusal does not follow.
        d.setSimulated("dd-table", 3);
        QVERIFY(d.errorText().isEmpty());
        auto* preset = d.findChild<QComboBox*>("setting_sim_preset");
        QVERIFY(preset);
        QVERIFY(preset->count() >= 3);
        QCOMPARE(d.uri(), QStringLiteral("sim:dd-table"));
        QCOMPARE(d.seed(), quint64(3));
        maybeScreenshot(&d, "connect-dialog-sim");
        // Replay: a file field with a Browse button; no seed (it would mean nothing).
        QVERIFY(d.selectBackend("replay:"));
        QVERIFY(d.findChild<QLineEdit*>("setting_replay_file"));
        QVERIFY(d.findChild<QWidget*>("setting_replay_file_browse"));
        QVERIFY(!d.findChild<QSpinBox*>("seed_replay"));
        QVERIFY(d.uri().isEmpty()); // the file is required
        QVERIFY(d.setSetting("file", "/data/step.csv"));
        QCOMPARE(d.uri(), QStringLiteral("replay:/data/step.csv"));
        maybeScreenshot(&d, "connect-dialog-replay");
        // LinuxCNC HAL: nothing to fill in (the running HAL session), no seed.
        QVERIFY(d.selectBackend("hal:"));
        QVERIFY(!d.findChild<QSpinBox*>("seed_hal"));
        QCOMPARE(d.uri(), QStringLiteral("hal:"));
        maybeScreenshot(&d, "connect-dialog-hal");
    }

    void labelsAreTranslated()
    {
        QTranslator ja;
        QVERIFY(ja.load(":/i18n/axistune_ja.qm"));
        QCoreApplication::installTranslator(&ja);
        gui::AppContext ctx;
        gui::ConnectDialog d(ctx);
        QCOMPARE(d.findChild<QRadioButton*>("backendRadio_replay")->text(), QStringLiteral("記録したキャプチャの再生"));
        QCOMPARE(d.findChild<QRadioButton*>("backendRadio_modbus")->text(),
                 QStringLiteral("Modbus TCP 経由のサーボアンプ"));
        // Every label, hint and description of every backend has its Japanese.
        for (const auto& b : device::registeredBackends()) {
            std::vector<std::string> texts{b.label, b.description};
            for (const auto& s : b.settings) {
                texts.push_back(s.label);
                if (!s.hint.empty())
                    texts.push_back(s.hint);
            }
            for (const auto& t : texts)
                QVERIFY2(QCoreApplication::translate("DriveRegistry", t.c_str()) != QString::fromStdString(t),
                         t.c_str());
        }
        QCoreApplication::removeTranslator(&ja);
    }

    void connectsToAReplayedCapture()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath("hold.csv");
        model::Capture cap;
        cap.metadata = {{"test", "hold"}, {"axis", "X"}, {"fs_Hz", 1000.0}, {"machine", "vmc"}};
        cap.channels = {{"t_s", {0.0, 0.001, 0.002}}, {"motor_vel_rad_s", {0.0, 0.0, 0.0}}};
        QVERIFY(io::writeCaptureCsvFile(file.toStdString(), cap).ok());
        gui::AppContext ctx;
        gui::ConnectDialog d(ctx);
        QVERIFY(d.selectBackend("replay:"));
        QVERIFY(d.setSetting("file", file));
        d.startConnect();
        QVERIFY(waitUntil([&] { return !d.isConnecting(); }, 10000));
        QVERIFY2(d.errorText().isEmpty(), qPrintable(d.errorText()));
        QVERIFY(ctx.drive().isConnected());
        QCOMPARE(QString::fromStdString(ctx.drive().identity()->model), QStringLiteral("replay"));
    }
};

QTEST_MAIN(TstConnectDialog)
#include "tst_connectdialog.moc"

// SPDX-License-Identifier: GPL-3.0-or-later
// The "Identify from motion" dialog (app/gui/IdentifyDialog) on the EMPS records: the parameters it
// shows equal the independent reference (tests/data/ident/emps_reference.json) within 0.5 %, the
// validation on the pulses record is shown and plotted, the saved file is a model the simulator reads,
// a cutoff above the Nyquist frequency is refused with the reason, and the connection dialog builds the
// sim:PRESET?model=…&axis=… URI. Screenshot for docs.
#include "app/gui/AppContext.h"
#include "app/gui/ConnectDialog.h"
#include "app/gui/IdentifyDialog.h"
#include "core/ident/IdentificationJson.h"
#include "widgets/TimeTracePlot.h"

#include <QComboBox>
#include <QLineEdit>
#include <QDoubleSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/gui/GuiTestUtil.h"

using namespace axistune;

class TstIdentifyDialog : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { testing::installLanguageFromEnv(); }

    void identifiesAndValidatesEmps()
    {
        const QString real = QStringLiteral(AXISTUNE_REAL_DATA_DIR);
        QVERIFY2(QFile::exists(real + "/emps_DATA_EMPS.csv"), qPrintable(real + ": real data missing"));
        gui::IdentifyDialog d;
        d.show();
        QVERIFY(d.loadEstimation(real + "/emps_DATA_EMPS.csv"));
        QVERIFY(d.loadValidation(real + "/emps_DATA_EMPS_PULSES.csv"));
        d.selectColumns("q_motor", "u_voltage", "q_ref", "pulses_N");
        d.forceScaleBox()->setValue(35.15065188);
        QVERIFY(d.loadController(QStringLiteral(AXISTUNE_TEST_DATA_DIR) + "/ident/emps_controller.json"));
        QVERIFY2(d.identify(), qPrintable(d.statusText()));

        std::ifstream rf(std::string(AXISTUNE_TEST_DATA_DIR) + "/ident/emps_reference.json");
        const auto ref = nlohmann::json::parse(rf);
        QCOMPARE(d.resultTable()->rowCount(), 4);
        for (int i = 0; i < 4; ++i) {
            const double shown = d.resultTable()->item(i, 1)->text().toDouble();
            const double expected = ref["symmetric"]["theta"][i].get<double>();
            QVERIFY2(std::abs(shown - expected) <= 0.005 * std::abs(expected),
                     qPrintable(QString("row %1: %2 vs %3").arg(i).arg(shown).arg(expected)));
        }
        QCOMPARE(d.resultTable()->item(0, 4)->text(), QStringLiteral("kg"));
        QVERIFY(!d.validationText().isEmpty());
        QCOMPARE(d.plot()->seriesNames().size(), 3);
        const double rms = (*d.result())["validation"][0]["position_error_rms"].get<double>();
        const double refRms = ref["validation"]["identified"]["position_error_rms_m"].get<double>();
        QVERIFY2(std::abs(rms - refRms) <= 0.02 * refRms, qPrintable(QString::number(rms)));
        d.resize(1100, 960);
        testing::maybeScreenshot(&d, "identify-dialog");

        QTemporaryDir dir;
        QString error;
        QVERIFY2(d.saveTo(dir.filePath("r.json"), &error), qPrintable(error));
        auto m = ident::readIdentifiedModelFile(dir.filePath("r.json").toStdString());
        QVERIFY2(m.ok(), m.ok() ? "" : m.error().detail.c_str());
        QCOMPARE(m->motion, ident::AxisMotion::Linear);
    }

    void refusesWithTheReason()
    {
        const QString real = QStringLiteral(AXISTUNE_REAL_DATA_DIR);
        gui::IdentifyDialog d;
        QVERIFY(!d.identify()); // nothing loaded
        QVERIFY(d.loadEstimation(real + "/emps_DATA_EMPS.csv"));
        d.selectColumns("q_motor", "u_voltage");
        d.findChild<QDoubleSpinBox*>("identifyCutoff")->setValue(600.0); // above Nyquist (500 Hz)
        QVERIFY(!d.identify());
        QVERIFY2(d.statusText().contains("Nyquist"), qPrintable(d.statusText()));
        QCOMPARE(d.resultTable()->rowCount(), 0);
        QVERIFY(!d.result().has_value());
    }

    // The connection dialog puts a saved result in as the plant of a simulated axis.
    void connectDialogCarriesTheModel()
    {
        gui::AppContext ctx;
        gui::ConnectDialog d(ctx);
        d.setSimulated("vmc");
        QCOMPARE(d.uri(), QStringLiteral("sim:vmc"));
        d.findChild<QLineEdit*>("setting_sim_model")->setText("/tmp/result.json");
        d.findChild<QLineEdit*>("setting_sim_axis")->setText("X");
        QCOMPARE(d.uri(), QStringLiteral("sim:vmc?model=/tmp/result.json&axis=X"));
    }
};

QTEST_MAIN(TstIdentifyDialog)
#include "tst_identifydialog.moc"

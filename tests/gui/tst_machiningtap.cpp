// SPDX-License-Identifier: GPL-3.0-or-later
// The machining wizard's tap-test page on the real impact record of shared/data/real.
#include "app/gui/AppContext.h"
#include "app/gui/MachiningTapPage.h"
#include "app/gui/MachiningWizard.h"
#include "core/machining/ToolModel.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QLabel>
#include <QListWidget>
#include <QSpinBox>
#include <QTableWidget>
#include <QtTest>

#include <cmath>
#include <cstdlib>

#include "tests/gui/GuiTestUtil.h"

using namespace axistune;
using axistune::gui::AppContext;
using axistune::gui::MachiningWizard;
using axistune::testing::maybeScreenshot;

namespace {

QString realData(const QString& name)
{
    return QString(AXISTUNE_REAL_DATA_DIR) + "/" + name;
}

} // namespace

class TestMachiningTap : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { axistune::testing::installLanguageFromEnv(); }

    void tapTestFromTheToolPage()
    {
        AppContext ctx;
        MachiningWizard w(ctx);
        w.resize(1000, 760);
        w.show();
        QCOMPARE(w.currentId(), int(MachiningWizard::ToolId));
        auto* tapButton = w.button(QWizard::CustomButton1);
        QVERIFY(tapButton->isVisible());
        tapButton->click();
        QCOMPARE(w.currentId(), int(MachiningWizard::TapId));
        QVERIFY(!w.button(QWizard::CustomButton1)->isVisible());
        auto* tap = w.tapPage();
        // no record: refused with a message
        QVERIFY(!tap->compute());
        QVERIFY(!tap->errorLabel()->text().isEmpty());
        QVERIFY(!tap->addRecord(realData("missing.csv")));
        QVERIFY(tap->errorLabel()->text().contains("missing.csv"));
        QVERIFY2(tap->addRecord(realData("impact_test_raw_time.csv")), qPrintable(tap->errorLabel()->text()));
        QCOMPARE(tap->forceColumn()->currentText(), QString("force_N"));
        QCOMPARE(tap->responseColumn()->currentText(), QString("accel_m_s2"));
        QVERIFY2(tap->compute(), qPrintable(tap->errorLabel()->text()));
        // the receptance peak of the record: 6.76e-7 m/N at 1056 Hz (the data author's H11: 6.776e-7 m/N)
        const auto& r = *tap->result();
        double peak = 0.0, peakHz = 0.0;
        for (std::size_t i = 0; i < r.frf.size(); ++i) {
            if (r.frf.valid[i] && std::abs(r.frf.h[i]) > peak) {
                peak = std::abs(r.frf.h[i]);
                peakHz = r.frf.freqHz[i];
            }
        }
        QVERIFY(std::abs(peak / 6.776e-7 - 1.0) < 0.05);
        QVERIFY(std::abs(peakHz - 1056.0) < 2.0);
        QVERIFY(tap->summary()->text().contains("1056"));
        maybeScreenshot(&w, "machining-tap");
        // used for both directions: the tool page fits the modes and comes back
        tap->modes()->setValue(1);
        const bool used = tap->useAsToolFrf("xy");
        QVERIFY2(used, qPrintable(tap->errorLabel()->text()));
        QCOMPARE(w.currentId(), int(MachiningWizard::ToolId));
        QVERIFY(w.toolPage()->source().contains("tap-"));
        auto tool = w.toolPage()->tool();
        QVERIFY(tool.ok());
        QCOMPARE(tool->modesX.size(), std::size_t(1));
        // the Next button continues to the cut page, the tap page is out of the linear order
        w.next();
        QCOMPARE(w.currentId(), int(MachiningWizard::CutId));
    }
};

QTEST_MAIN(TestMachiningTap)
#include "tst_machiningtap.moc"

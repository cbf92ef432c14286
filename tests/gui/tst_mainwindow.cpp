// SPDX-License-Identifier: GPL-3.0-or-later
// The main window offscreen: the machine tree from the store plus the connected machine, the parameter
// inspector (device / profile / proposed with highlights), the Wizards menu from the registry, and the
// language switch retranslating the menus.
#include "app/gui/AppContext.h"
#include "app/gui/LogPanel.h"
#include "app/gui/MainWindow.h"
#include "app/gui/ParameterInspector.h"
#include "app/gui/SettingsDialog.h"
#include "app/gui/WizardRegistry.h"
#include "core/store/SessionRecord.h"
#include "tests/app/cli/SimDriveProcess.h"
#include "tests/gui/GuiTestUtil.h"

#include "core/store/Database.h"

#include <QAction>
#include <QLabel>
#include <QMenu>
#include <QPlainTextEdit>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>

using axistune::gui::MainWindow;
using axistune::gui::ParameterInspector;
using axistune::testing::waitUntil;

namespace {
QTreeWidgetItem* topItem(QTreeWidget* tree, const QString& name)
{
    for (int i = 0; i < tree->topLevelItemCount(); ++i)
        if (tree->topLevelItem(i)->text(0) == name)
            return tree->topLevelItem(i);
    return nullptr;
}
}  // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QString storePath() const { return m_dir.filePath("store.sqlite"); }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
        // A store holding another machine (with a session) and a profile value for vmc X.
        auto opened = axistune::store::Database::open(storePath().toStdString());
        QVERIFY(opened.ok());
        axistune::store::Database& db = opened.value();
        axistune::store::SessionRecord rec;
        rec.info.machine = "bench-mill";
        rec.info.kind = "frf";
        rec.machineAxes = {"A1", "A2"};
        QVERIFY(db.recordSession(rec).ok());
        QVERIFY(db.ensureMachine("vmc", {"X", "Y", "Z"}).ok());
        axistune::store::ParameterSet set;
        set.axis = "X";
        set.source = axistune::store::ParameterSource::Applied;
        set.values = {{"velocity.kp", 0.5}};  // the simulated vmc has 0.8 on the drive
        QVERIFY(db.saveParameterSet("vmc", set).ok());
    }

    void treeShowsTheStoreAndTheConnectedMachine()
    {
        MainWindow w(storePath());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTreeWidget* tree = w.machineTree();
        // Before connecting: the two machines of the store.
        QCOMPARE(tree->topLevelItemCount(), 2);
        QTreeWidgetItem* bench = topItem(tree, "bench-mill");
        QVERIFY(bench);
        QCOMPARE(bench->childCount(), 2);
        QVERIFY(bench->text(1).contains("1"));  // one session

        w.connectSimulated("vmc");
        QVERIFY(waitUntil([&] { return w.context().drive().isConnected(); }, 20000));
        QVERIFY(waitUntil([&] { return topItem(tree, "vmc") && topItem(tree, "vmc")->text(1).contains("connected"); }, 5000));
        QCOMPARE(tree->topLevelItemCount(), 2);  // vmc is in the store: one entry, marked connected
        QTreeWidgetItem* vmc = topItem(tree, "vmc");
        QCOMPARE(vmc->childCount(), 3);
        QCOMPARE(vmc->child(0)->text(0), QString("X"));
        QCOMPARE(vmc->child(1)->text(0), QString("Y"));
        QCOMPARE(vmc->child(2)->text(0), QString("Z"));
        QVERIFY(!topItem(tree, "bench-mill")->text(1).contains("connected"));
        QVERIFY(w.connectionText().contains("sim:vmc"));
    }

    void connectedMachineNotInTheStoreIsAdded()
    {
        MainWindow w(storePath());
        w.connectSimulated("dd-table");
        QVERIFY(waitUntil([&] { return w.context().drive().isConnected(); }, 20000));
        QVERIFY(waitUntil([&] { return topItem(w.machineTree(), "dd-table") != nullptr; }, 5000));
        QCOMPARE(w.machineTree()->topLevelItemCount(), 3);
        QVERIFY(topItem(w.machineTree(), "dd-table")->text(1).contains("connected"));
    }

    void inspectorShowsDeviceProfileAndProposedWithHighlights()
    {
        MainWindow w(storePath());
        w.connectSimulated("vmc");
        QVERIFY(waitUntil([&] { return w.context().drive().isConnected(); }, 20000));
        w.showAxis("X");
        ParameterInspector* insp = w.inspector();
        QVERIFY(waitUntil([&] { return insp->axis() == "X" && insp->deviceValuesShown() && !insp->cellText("velocity.kp", ParameterInspector::ColDevice).isEmpty(); }, 10000));
        QVERIFY(w.parameterTable()->rowCount() > 20);
        // 62.5e-6 s shown in µs (display unit of the metadata).
        QCOMPARE(insp->cellText("current.period", ParameterInspector::ColDevice), QString("62.5"));
        QCOMPARE(insp->cellText("current.period", ParameterInspector::ColUnit), QString::fromUtf8("µs"));
        // Device 0.8, profile 0.5: the profile cell is highlighted.
        QCOMPARE(insp->cellText("velocity.kp", ParameterInspector::ColDevice), QString("0.8"));
        QCOMPARE(insp->cellText("velocity.kp", ParameterInspector::ColProfile), QString("0.5"));
        QVERIFY(insp->isHighlighted("velocity.kp", ParameterInspector::ColProfile));
        QVERIFY(!insp->isHighlighted("current.period", ParameterInspector::ColProfile));

        // A proposal: one value different from the device, one equal.
        w.context().setProposed("X", {{"velocity.kp", 1.2}, {"position.kp", 30.0}});
        QCOMPARE(insp->cellText("velocity.kp", ParameterInspector::ColProposed), QString("1.2"));
        QVERIFY(insp->isHighlighted("velocity.kp", ParameterInspector::ColProposed));
        QCOMPARE(insp->cellText("position.kp", ParameterInspector::ColDevice), QString("30"));
        QCOMPARE(insp->cellText("position.kp", ParameterInspector::ColProposed), QString("30"));
        QVERIFY(!insp->isHighlighted("position.kp", ParameterInspector::ColProposed));
        QVERIFY(insp->cellText("current.kp", ParameterInspector::ColProposed).isEmpty());
    }

    void wizardsMenuListsTheRegisteredWizards()
    {
        MainWindow w(storePath());
        const auto entries = axistune::gui::registeredWizards();
        const auto& actions = w.wizardActions();
        QCOMPARE(actions.size(), entries.size());
        for (std::size_t i = 0; i < entries.size(); ++i) {
            QCOMPARE(actions[i]->data().toString(), entries[i].id);
            QCOMPARE(actions[i]->text(), axistune::gui::wizardTitle(entries[i]));
            // Not connected: the wizards that need the drive are disabled.
            QCOMPARE(actions[i]->isEnabled(), !entries[i].needsDrive);
        }
        w.connectSimulated("vmc");
        QVERIFY(waitUntil([&] { return w.context().drive().isConnected(); }, 20000));
        QVERIFY(waitUntil([&] {
            return std::all_of(actions.begin(), actions.end(), [](QAction* a) { return a->isEnabled(); });
        }, 2000));
    }

    void languageSwitchRetranslatesTheMenus()
    {
        MainWindow w(storePath());
        auto titles = [&] {
            QStringList t;
            for (QMenu* m : w.menus())
                t << m->title();
            return t;
        };
        const QStringList english = titles();
        QCOMPARE(english, QStringList({"&Machine", "&Wizards", "&Sessions", "Se&ttings", "&Help"}));
        QVERIFY(axistune::gui::setApplicationLanguage("ja"));
        QVERIFY(waitUntil([&] { return titles() != english; }, 2000));
        const QStringList japanese = titles();
        // Every menu title is rebuilt through the translator (titles the lead has not translated yet
        // stay English), and the first one, translated since the first release, is Japanese.
        const char* sources[] = {"&Machine", "&Wizards", "&Sessions", "Se&ttings", "&Help"};
        for (int i = 0; i < japanese.size(); ++i)
            QCOMPARE(japanese[i], QCoreApplication::translate("axistune::gui::MainWindow", sources[i]));
        QVERIFY2(std::any_of(japanese[0].begin(), japanese[0].end(), [](QChar c) { return c.unicode() >= 0x3000; }),
                 qPrintable(japanese[0]));
        QVERIFY(axistune::gui::setApplicationLanguage("en"));
        QVERIFY(waitUntil([&] { return titles() == english; }, 2000));
    }

    void lostConnectionIsShownAndTheWindowStaysResponsive()
    {
        axistune::testing::SimDrive sd("--preset vmc");
        QVERIFY(sd.port() > 0);
        MainWindow w(storePath());
        w.show();
        w.connectTo(QString::fromStdString(sd.uri("timeout_ms=300")));
        QVERIFY(waitUntil([&] { return w.context().drive().isConnected(); }, 20000));
        QVERIFY(waitUntil([&] { return w.inspector()->deviceValuesShown(); }, 10000));
        sd.stop(SIGKILL);
        w.inspector()->refresh();  // a read on the dead link
        QVERIFY(waitUntil([&] { return !w.context().drive().isConnected(); }, 20000));
        QVERIFY(waitUntil([&] { return w.connectionText().contains("CONNECTION LOST"); }, 5000));
        QVERIFY(w.logPanel()->logView()->toPlainText().contains("Connection lost"));
        for (QAction* a : w.wizardActions())
            QCOMPARE(a->isEnabled(), !a->property("needsDrive").toBool());
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"

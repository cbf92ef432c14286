// SPDX-License-Identifier: GPL-3.0-or-later
// The app starts offscreen on the built-in vmc and shows its three axes and their parameters.
#include "app/gui/MainWindow.h"

#include <QTableWidget>
#include <QTreeWidget>
#include <QtTest>

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void showsTheThreeAxesOfVmc()
    {
        axistune::gui::MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.connectSimulated("vmc"));
        QTreeWidget* tree = w.machineTree();
        QCOMPARE(tree->topLevelItemCount(), 1);
        QTreeWidgetItem* machine = tree->topLevelItem(0);
        QCOMPARE(machine->text(0), QString("vmc"));
        QCOMPARE(machine->childCount(), 3);
        QCOMPARE(machine->child(0)->text(0), QString("X"));
        QCOMPARE(machine->child(1)->text(0), QString("Y"));
        QCOMPARE(machine->child(2)->text(0), QString("Z"));
    }

    void showsParametersWithDisplayUnits()
    {
        axistune::gui::MainWindow w;
        QVERIFY(w.connectSimulated("vmc"));
        w.showAxis("Y");
        QTableWidget* t = w.parameterTable();
        QVERIFY(t->rowCount() > 20);
        bool found = false;
        for (int r = 0; r < t->rowCount(); ++r) {
            if (t->item(r, 1)->text() == "current.period") {
                // 62.5e-6 s shown in µs (display unit of the metadata)
                QCOMPARE(t->item(r, 2)->text(), QString("62.5"));
                QCOMPARE(t->item(r, 3)->text(), QString::fromUtf8("µs"));
                found = true;
            }
        }
        QVERIFY(found);
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"

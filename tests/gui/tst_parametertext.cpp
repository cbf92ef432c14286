// SPDX-License-Identifier: GPL-3.0-or-later
// Every drive-parameter label of the simulated axes and of LinuxCNC's pid pins is in the GUI's translation list, and
// the Japanese translation shows it in Japanese.
// clang-format off
// First: HAL's headers use the name "signals", which Qt defines as a macro.
#include "core/device/hal/HalDrive.h"
// clang-format on
#include "app/gui/ParameterText.h"
#include "core/sim/AxisParameters.h"

#include <QTranslator>
#include <QtTest>

class TestParameterText : public QObject {
    Q_OBJECT
private slots:
    void everyLabelIsTranslatable()
    {
        using namespace axistune::sim;
        for (auto kind : {AxisKind::Linear, AxisKind::Rotary}) {
            for (const auto& m : axisParameterMetas(kind)) {
                if (isPlantParameter(m.key))
                    continue;
                QVERIFY2(axistune::gui::hasParameterLabel(m.label), m.label.c_str());
            }
        }
        for (const auto& m : axistune::device::hal::pidParameterMetadata())
            QVERIFY2(axistune::gui::hasParameterLabel(m.label), m.label.c_str());
    }
    void japaneseTranslationApplies()
    {
        QTranslator tr;
        QVERIFY(tr.load(":/i18n/axistune_ja.qm"));
        QCoreApplication::installTranslator(&tr);
        QCOMPARE(axistune::gui::parameterLabel("PI ratio α"), QString::fromUtf8("PI率 α"));
        QCOMPARE(axistune::gui::parameterLabel("Dead time"), QString::fromUtf8("むだ時間"));
        QCOMPARE(axistune::gui::parameterLabel("Proportional gain P"), QString::fromUtf8("比例ゲイン P"));
        QCoreApplication::removeTranslator(&tr);
    }
};

QTEST_MAIN(TestParameterText)
#include "tst_parametertext.moc"

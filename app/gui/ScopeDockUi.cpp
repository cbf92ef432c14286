// SPDX-License-Identifier: GPL-3.0-or-later
// The scope dock's widgets and their texts (ScopeDock.h, docs/scope.md "The GUI scope").
#include "app/gui/AppContext.h"
#include "app/gui/DriveController.h"
#include "app/gui/ScopeDock.h"
#include "app/gui/WidgetUtil.h"
#include "core/device/ScopeMath.h"
#include "core/io/CaptureCsv.h"
#include "core/io/ScopeCsv.h"
#include "core/model/Number.h"
#include "widgets/CurvePlot.h"
#include "widgets/TimeTracePlot.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QSplitter>
#include <QStackedWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

namespace axistune {
namespace gui {

void ScopeDock::buildUi()
{
    auto* controls = new QWidget;
    auto* cl = new QVBoxLayout(controls);
    cl->setContentsMargins(0, 0, 0, 0);
    auto* axisRow = new QHBoxLayout;
    m_axisLabel = new QLabel;
    m_axis = new QComboBox;
    m_axis->setObjectName("scopeAxis");
    axisRow->addWidget(m_axisLabel);
    axisRow->addWidget(m_axis, 1);
    cl->addLayout(axisRow);
    m_channels = new QListWidget;
    m_channels->setObjectName("scopeChannels");
    m_channels->setMinimumHeight(120);
    cl->addWidget(m_channels, 1);

    m_triggerBox = new QGroupBox;
    auto* tf = new QFormLayout(m_triggerBox);
    m_trigChannelLabel = new QLabel;
    m_trigChannel = new QComboBox;
    m_trigChannel->setObjectName("scopeTriggerChannel");
    tf->addRow(m_trigChannelLabel, m_trigChannel);
    m_levelLabel = new QLabel;
    m_level = spin(this, -1e9, 1e9, 0.0, 6, QString(), "scopeTriggerLevel");
    tf->addRow(m_levelLabel, m_level);
    m_edgeLabel = new QLabel;
    m_edge = new QComboBox;
    m_edge->setObjectName("scopeEdge");
    m_edge->addItems({QString(), QString(), QString()});
    tf->addRow(m_edgeLabel, m_edge);
    m_preLabel = new QLabel;
    m_pre = spin(this, 0.0, 100.0, 25.0, 1, QStringLiteral(" %"), "scopePreTrigger");
    tf->addRow(m_preLabel, m_pre);
    m_lengthLabel = new QLabel;
    m_length = spin(this, 0.001, 3600.0, 0.2, 3, QStringLiteral(" s"), "scopeLength");
    tf->addRow(m_lengthLabel, m_length);
    m_dividerLabel = new QLabel;
    m_divider = new QSpinBox;
    m_divider->setObjectName("scopeDivider");
    m_divider->setRange(1, 1);
    tf->addRow(m_dividerLabel, m_divider);
    m_rate = new QLabel;
    m_rate->setObjectName("scopeRate");
    tf->addRow(m_rate);
    cl->addWidget(m_triggerBox);

    m_rollBox = new QGroupBox;
    auto* rf = new QFormLayout(m_rollBox);
    m_roll = new QCheckBox;
    m_roll->setObjectName("scopeRoll");
    rf->addRow(m_roll);
    m_historyLabel = new QLabel;
    m_historyRows = new QSpinBox;
    m_historyRows->setObjectName("scopeHistory");
    m_historyRows->setRange(1000, 8000000);
    m_historyRows->setSingleStep(100000);
    m_historyRows->setValue(kDefaultHistoryRows);
    m_historyRows->setGroupSeparatorShown(true);
    rf->addRow(m_historyLabel, m_historyRows);
    m_windowLabel = new QLabel;
    m_window = spin(this, 0.01, 3600.0, 2.0, 2, QStringLiteral(" s"), "scopeWindow");
    rf->addRow(m_windowLabel, m_window);
    cl->addWidget(m_rollBox);

    m_mathBox = new QGroupBox;
    auto* mf = new QFormLayout(m_mathBox);
    m_mathLabel = new QLabel;
    m_mathOp = new QComboBox;
    m_mathOp->setObjectName("scopeMathOp");
    m_mathOp->addItems({QString(), QString(), QString()});
    mf->addRow(m_mathLabel, m_mathOp);
    m_mathALabel = new QLabel(QStringLiteral("A:"));
    m_mathA = new QComboBox;
    m_mathA->setObjectName("scopeMathA");
    mf->addRow(m_mathALabel, m_mathA);
    m_mathBLabel = new QLabel(QStringLiteral("B:"));
    m_mathB = new QComboBox;
    m_mathB->setObjectName("scopeMathB");
    mf->addRow(m_mathBLabel, m_mathB);
    m_spectrum = new QPushButton;
    m_spectrum->setObjectName("scopeSpectrum");
    mf->addRow(m_spectrum);
    m_xy = new QCheckBox;
    m_xy->setObjectName("scopeXy");
    mf->addRow(m_xy);
    m_xLabel = new QLabel(QStringLiteral("X:"));
    m_xChannel = new QComboBox;
    m_xChannel->setObjectName("scopeXChannel");
    mf->addRow(m_xLabel, m_xChannel);
    m_yLabel = new QLabel(QStringLiteral("Y:"));
    m_yChannel = new QComboBox;
    m_yChannel->setObjectName("scopeYChannel");
    mf->addRow(m_yLabel, m_yChannel);
    // Display scaling of one channel (gain, offset).
    m_scaleLabel = new QLabel;
    m_scaleChannel = new QComboBox;
    m_scaleChannel->setObjectName("scopeScaleChannel");
    m_scaleChannel->addItem(QString()); // "none", named in retranslateUi()
    m_scaleGain = new QDoubleSpinBox;
    m_scaleGain->setObjectName("scopeScaleGain");
    m_scaleGain->setDecimals(6);
    m_scaleGain->setRange(-1e9, 1e9);
    m_scaleGain->setValue(1.0);
    m_scaleGain->setPrefix(QStringLiteral("× "));
    m_scaleOffset = new QDoubleSpinBox;
    m_scaleOffset->setObjectName("scopeScaleOffset");
    m_scaleOffset->setDecimals(6);
    m_scaleOffset->setRange(-1e9, 1e9);
    m_scaleOffset->setPrefix(QStringLiteral("+ "));
    auto* scaleRow = new QHBoxLayout;
    scaleRow->addWidget(m_scaleChannel, 2);
    scaleRow->addWidget(m_scaleGain, 1);
    scaleRow->addWidget(m_scaleOffset, 1);
    mf->addRow(m_scaleLabel, scaleRow);
    auto* refRow = new QHBoxLayout;
    m_keepRef = new QPushButton;
    m_keepRef->setObjectName("scopeKeepReference");
    m_clearRefs = new QPushButton;
    m_clearRefs->setObjectName("scopeClearReferences");
    refRow->addWidget(m_keepRef);
    refRow->addWidget(m_clearRefs);
    mf->addRow(refRow);
    cl->addWidget(m_mathBox);

    m_jogBox = new QGroupBox;
    auto* jf = new QFormLayout(m_jogBox);
    m_jogDistanceLabel = new QLabel;
    m_jogDistance = spin(this, -1e6, 1e6, 20.0, 3, QString(), "jogDistance");
    jf->addRow(m_jogDistanceLabel, m_jogDistance);
    m_jogSpeedLabel = new QLabel;
    m_jogSpeed = spin(this, 0.001, 1e6, 50.0, 3, QString(), "jogSpeed");
    jf->addRow(m_jogSpeedLabel, m_jogSpeed);
    m_jogAccelLabel = new QLabel;
    m_jogAccel = spin(this, 0.001, 1e8, 1000.0, 1, QString(), "jogAcceleration");
    jf->addRow(m_jogAccelLabel, m_jogAccel);
    m_jogReturn = new QCheckBox;
    m_jogReturn->setObjectName("jogReturn");
    m_jogReturn->setChecked(true);
    jf->addRow(m_jogReturn);
    auto* jogButtons = new QHBoxLayout;
    m_jogButton = new QPushButton;
    m_jogButton->setObjectName("jogButton");
    m_jogStop = new QPushButton;
    m_jogStop->setObjectName("jogStop");
    jogButtons->addWidget(m_jogButton);
    jogButtons->addWidget(m_jogStop);
    jf->addRow(jogButtons);
    cl->addWidget(m_jogBox);

    auto* scroll = new QScrollArea;
    scroll->setWidget(controls);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setMinimumWidth(360);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);

    auto* right = new QWidget;
    auto* rl = new QVBoxLayout(right);
    rl->setContentsMargins(0, 0, 0, 0);
    auto* runRow = new QHBoxLayout;
    m_run = new QPushButton;
    m_run->setObjectName("scopeRun");
    m_single = new QPushButton;
    m_single->setObjectName("scopeSingle");
    m_stop = new QPushButton;
    m_stop->setObjectName("scopeStop");
    m_state = new QLabel;
    m_state->setObjectName("scopeState");
    runRow->addWidget(m_run);
    runRow->addWidget(m_single);
    runRow->addWidget(m_stop);
    runRow->addWidget(m_state, 1);
    rl->addLayout(runRow);
    m_message = new QLabel;
    m_message->setObjectName("scopeMessage");
    m_message->setWordWrap(true);
    m_message->setVisible(false);
    rl->addWidget(m_message);
    m_plot = new widgets::TimeTracePlot;
    m_plot->setObjectName("scopePlot");
    m_plot->setMinimumSize(420, 260);
    m_xyPlot = new widgets::CurvePlot;
    m_xyPlot->setObjectName("scopeXyPlot");
    m_plots = new QStackedWidget;
    m_plots->addWidget(m_plot);
    m_plots->addWidget(m_xyPlot);
    rl->addWidget(m_plots, 1);
    auto* fileRow = new QHBoxLayout;
    m_exportCsv = new QPushButton;
    m_exportCsv->setObjectName("scopeExportCsv");
    m_exportImage = new QPushButton;
    m_exportImage->setObjectName("scopeExportImage");
    m_save = new QPushButton;
    m_save->setObjectName("scopeSave");
    m_openStore = new QPushButton;
    m_openStore->setObjectName("scopeOpenStore");
    m_openCsv = new QPushButton;
    m_openCsv->setObjectName("scopeOpenCsv");
    for (auto* b : {m_exportCsv, m_exportImage, m_save, m_openStore, m_openCsv})
        fileRow->addWidget(b);
    fileRow->addStretch(1);
    rl->addLayout(fileRow);

    auto* split = new QSplitter(Qt::Horizontal);
    split->addWidget(scroll);
    split->addWidget(right);
    split->setStretchFactor(1, 1);
    split->setSizes({380, 900});
    auto* top = new QVBoxLayout(this);
    top->setContentsMargins(2, 2, 2, 2);
    top->addWidget(split);

    connect(m_axis, &QComboBox::currentTextChanged, this, [this](const QString&) { requestChannels(); });
    connect(m_channels, &QListWidget::itemChanged, this, [this] { updateTriggerChannels(); });
    connect(m_trigChannel, &QComboBox::currentTextChanged, this, [this] { updateUnits(); });
    connect(m_divider, &QSpinBox::valueChanged, this, [this] { updateRate(); });
    connect(m_roll, &QCheckBox::toggled, this, [this] { updateButtons(); });
    connect(m_run, &QPushButton::clicked, this, &ScopeDock::runNormal);
    connect(m_single, &QPushButton::clicked, this, &ScopeDock::runSingle);
    connect(m_stop, &QPushButton::clicked, this, &ScopeDock::stop);
    connect(m_exportCsv, &QPushButton::clicked, this, &ScopeDock::exportCsvInteractive);
    connect(m_exportImage, &QPushButton::clicked, this, &ScopeDock::exportImageInteractive);
    connect(m_save, &QPushButton::clicked, this, [this] {
        QString e;
        if (!saveToStore(&e))
            setMessage(e, true);
    });
    connect(m_openStore, &QPushButton::clicked, this, &ScopeDock::openFromStoreInteractive);
    connect(m_openCsv, &QPushButton::clicked, this, &ScopeDock::openCsvInteractive);
    for (auto* c : {m_mathOp, m_mathA, m_mathB, m_scaleChannel})
        connect(c, &QComboBox::currentIndexChanged, this, [this] { redraw(); });
    for (auto* sb : {m_scaleGain, m_scaleOffset})
        connect(sb, &QDoubleSpinBox::valueChanged, this, [this] { redraw(); });
    for (auto* c : {m_xChannel, m_yChannel})
        connect(c, &QComboBox::currentIndexChanged, this, [this] { updateXyPlot(); });
    connect(m_xy, &QCheckBox::toggled, this, [this](bool on) {
        m_plots->setCurrentIndex(on ? 1 : 0);
        updateXyPlot();
    });
    connect(m_spectrum, &QPushButton::clicked, this, [this] {
        QString e;
        if (!showSpectrum(&e))
            setMessage(e, true);
    });
    connect(m_keepRef, &QPushButton::clicked, this, &ScopeDock::keepReference);
    connect(m_clearRefs, &QPushButton::clicked, this, &ScopeDock::clearReferences);
    connect(m_jogButton, &QPushButton::clicked, this, &ScopeDock::startJog);
    connect(m_jogStop, &QPushButton::clicked, this, &ScopeDock::stopJog);
}

void ScopeDock::retranslateUi()
{
    m_axisLabel->setText(tr("Axis:"));
    m_triggerBox->setTitle(tr("Trigger"));
    m_trigChannelLabel->setText(tr("Channel:"));
    m_levelLabel->setText(tr("Level:"));
    m_edgeLabel->setText(tr("Edge:"));
    m_edge->setItemText(0, tr("rising"));
    m_edge->setItemText(1, tr("falling"));
    m_edge->setItemText(2, tr("either"));
    m_preLabel->setText(tr("Pre-trigger:"));
    m_lengthLabel->setText(tr("Length:"));
    m_dividerLabel->setText(tr("Divider:"));
    m_rollBox->setTitle(tr("Roll mode"));
    m_roll->setText(tr("Roll (continuous, no trigger)"));
    m_historyLabel->setText(tr("History:"));
    m_historyRows->setSuffix(tr(" samples per channel"));
    m_windowLabel->setText(tr("Shown while rolling:"));
    m_mathBox->setTitle(tr("Math, spectrum and XY"));
    m_mathLabel->setText(tr("Math channel:"));
    m_mathOp->setItemText(0, tr("none"));
    m_mathOp->setItemText(1, tr("A − B"));
    m_mathOp->setItemText(2, tr("d/dt A"));
    m_scaleLabel->setText(tr("Scale:"));
    m_scaleChannel->setToolTip(tr("Shows this channel as gain × value + offset (the offset in the channel's unit); "
                                  "exports and the store keep the drive's values"));
    m_scaleChannel->setItemText(0, tr("none"));
    m_spectrum->setText(tr("Spectrum of A (visible window)"));
    m_xy->setText(tr("XY plot (Y against X)"));
    m_keepRef->setText(tr("Keep as reference"));
    m_keepRef->setToolTip(tr("Overlays the capture shown, dashed, under the next captures"));
    m_clearRefs->setText(tr("Clear references"));
    m_jogBox->setTitle(tr("Jog"));
    m_jogDistanceLabel->setText(tr("Distance:"));
    m_jogSpeedLabel->setText(tr("Speed:"));
    m_jogAccelLabel->setText(tr("Acceleration:"));
    m_jogReturn->setText(tr("Back and forth (return to the start)"));
    m_jogButton->setText(tr("Jog"));
    m_jogStop->setText(tr("Stop jog"));
    m_run->setText(tr("Run"));
    m_run->setToolTip(tr("Triggered captures one after the other (normal mode), or roll mode when it is ticked"));
    m_single->setText(tr("Single"));
    m_single->setToolTip(tr("One triggered capture, then the scope stops"));
    m_stop->setText(tr("Stop"));
    m_exportCsv->setText(tr("Export CSV…"));
    m_exportImage->setText(tr("Export image…"));
    m_save->setText(tr("Save to store"));
    m_openStore->setText(tr("Open saved…"));
    m_openCsv->setText(tr("Open CSV…"));
    for (int i = 0; i < m_channels->count(); ++i) {
        auto* item = m_channels->item(i);
        item->setToolTip(item->data(Qt::UserRole + 2).toString());
    }
    updateUnits();
    updateRate();
    m_state->setText(stateText());
    setMessage(m_messageText, m_messageError);
}

} // namespace gui
} // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
// The scope dock (ScopeDock.h, docs/scope.md "The GUI scope").
#include "app/gui/ScopeDock.h"

#include "app/gui/AppContext.h"
#include "app/gui/DriveController.h"
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

namespace {
constexpr int kPollMs = 100;        ///< poll period while armed or rolling
constexpr qint64 kRollDrawMs = 200; ///< redraw period of the roll window
constexpr std::size_t kMaxRowsPerPoll = 262144;
constexpr const char* kStoreCapture = "scope";

} // namespace

// A scope capture as a plot table (ScopeDock.h).
std::shared_ptr<model::Capture> scopePlotTable(const device::ScopeCapture& c)
{
    auto t = std::make_shared<model::Capture>();
    model::setMetadataNumber(t->metadata, "fs_Hz", c.rateHz);
    model::Channel time{"time_s", {}};
    time.data.reserve(c.rows());
    for (const auto n : c.samples) {
        const double rel =
            c.triggered ? static_cast<double>(static_cast<std::int64_t>(n - c.triggerSample)) : static_cast<double>(n);
        time.data.push_back(rel / c.rateHz);
    }
    t->channels.push_back(std::move(time));
    for (std::size_t k = 0; k < c.channels.size() && k < c.columns.size(); ++k) {
        if (c.channels[k].name == "t_s" || c.channels[k].name == "time_s")
            continue;
        t->metadata["unit." + c.channels[k].name] = c.channels[k].unit;
        t->channels.push_back({c.channels[k].name, c.columns[k]});
    }
    return t;
}

ScopeDock::ScopeDock(AppContext& ctx, QWidget* parent) : QWidget(parent), m_ctx(ctx)
{
    setObjectName("scopeDock");
    buildUi();
    m_timer = new QTimer(this);
    m_timer->setInterval(kPollMs);
    connect(m_timer, &QTimer::timeout, this, &ScopeDock::poll);
    connect(&m_ctx.drive(), &DriveController::connectionChanged, this,
            [this](bool connected, const QString&) { onConnectionChanged(connected); });
    connect(&m_ctx.drive(), &DriveController::connectionLost, this, [this](const QString& reason) {
        setRunning(false);
        setMessage(tr("Connection lost: %1").arg(reason), true);
    });
    m_stateKey = "idle";
    retranslateUi();
    onConnectionChanged(m_ctx.drive().isConnected());
}

ScopeDock::~ScopeDock() = default;

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

void ScopeDock::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

// ------------------------------------------------------------------------------------------------
// Axis and channels

void ScopeDock::onConnectionChanged(bool connected)
{
    if (!connected) {
        m_timer->stop();
        m_running = m_rollRunning = false;
        m_pollInFlight = false;
        m_caps.reset();
        m_capsAxis.clear();
        if (m_stateKey != "offline")
            m_stateKey = "idle";
    }
    refillAxes();
    updateButtons();
}

void ScopeDock::refillAxes()
{
    const QString current = m_axis->currentText();
    const QSignalBlocker block(m_axis);
    m_axis->clear();
    if (m_ctx.drive().isConnected())
        m_axis->addItems(m_ctx.axes());
    if (const int i = m_axis->findText(current); i >= 0)
        m_axis->setCurrentIndex(i);
    requestChannels();
}

bool ScopeDock::setAxis(const QString& axis)
{
    const int i = m_axis->findText(axis);
    if (i < 0)
        return false;
    m_axis->setCurrentIndex(i);
    if (m_capsAxis != axis)
        requestChannels();
    return true;
}

QString ScopeDock::axis() const
{
    return m_axis->currentText();
}

void ScopeDock::requestChannels()
{
    const QString axis = m_axis->currentText();
    if (axis.isEmpty() || !m_ctx.drive().isConnected()) {
        m_caps.reset();
        m_capsAxis.clear();
        m_channels->clear();
        updateTriggerChannels();
        return;
    }
    if (axis == m_capsAxis && m_caps)
        return;
    m_caps.reset();
    m_capsAxis = axis;
    m_capsRequest = connectReply(m_ctx.drive().scopeCapabilities(axis), this, &ScopeDock::onChannels);
}

void ScopeDock::onChannels(const DriveReply& reply)
{
    if (reply.id != m_capsRequest)
        return;
    m_channels->clear();
    if (!reply.ok || !reply.scopeCaps) {
        m_caps.reset();
        setMessage(tr("The drive offers no scope on axis %1: %2").arg(reply.axis, reply.error), true);
        updateTriggerChannels();
        updateButtons();
        return;
    }
    m_caps = reply.scopeCaps;
    const QSignalBlocker block(m_channels);
    for (const auto& ch : m_caps->channels) {
        const QString unit = qs(ch.unit);
        auto* item =
            new QListWidgetItem(unit.isEmpty() ? qs(ch.name) : QStringLiteral("%1 [%2]").arg(qs(ch.name), unit));
        item->setData(Qt::UserRole, qs(ch.name));
        item->setData(Qt::UserRole + 1, unit);
        item->setData(Qt::UserRole + 2, qs(ch.description));
        item->setToolTip(qs(ch.description));
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        // A useful first choice: commanded and measured velocity and the following error.
        const bool preset = ch.name == "velocity_cmd_rad_s" || ch.name == "motor_vel_rad_s" ||
                            ch.name == "following_error_m" || ch.name == "following_error_rad";
        item->setCheckState(preset ? Qt::Checked : Qt::Unchecked);
        m_channels->addItem(item);
    }
    if (selectedChannels().isEmpty() && m_channels->count() > 0)
        m_channels->item(0)->setCheckState(Qt::Checked);
    m_divider->setRange(1, std::max(1, m_caps->maxDivider));
    updateTriggerChannels();
    updateRate();
    updateButtons();
    if (m_messageError && !m_running)
        setMessage(QString(), false);
}

QStringList ScopeDock::selectedChannels() const
{
    QStringList out;
    for (int i = 0; i < m_channels->count(); ++i) {
        if (m_channels->item(i)->checkState() == Qt::Checked)
            out << m_channels->item(i)->data(Qt::UserRole).toString();
    }
    return out;
}

bool ScopeDock::selectChannels(const QStringList& names)
{
    QStringList found;
    {
        const QSignalBlocker block(m_channels);
        for (int i = 0; i < m_channels->count(); ++i) {
            auto* item = m_channels->item(i);
            const QString n = item->data(Qt::UserRole).toString();
            const bool on = names.contains(n);
            item->setCheckState(on ? Qt::Checked : Qt::Unchecked);
            if (on)
                found << n;
        }
    }
    updateTriggerChannels();
    return found.size() == names.size();
}

QString ScopeDock::channelUnit(const QString& channel) const
{
    if (m_caps) {
        for (const auto& ch : m_caps->channels)
            if (qs(ch.name) == channel)
                return qs(ch.unit);
    }
    return {};
}

bool ScopeDock::linearAxis() const
{
    // The drive's position channels are in m on a linear axis and in rad on a rotary one (docs/scope.md).
    if (m_caps) {
        for (const auto& ch : m_caps->channels)
            if (ch.unit == "rad" && ch.name.find("pos") != std::string::npos)
                return false;
    }
    return true;
}

void ScopeDock::updateTriggerChannels()
{
    const QString current = m_trigChannel->currentText();
    const QSignalBlocker block(m_trigChannel);
    m_trigChannel->clear();
    m_trigChannel->addItems(selectedChannels());
    if (const int i = m_trigChannel->findText(current); i >= 0)
        m_trigChannel->setCurrentIndex(i);
    updateUnits();
    updateButtons();
}

void ScopeDock::updateUnits()
{
    const QString unit = channelUnit(m_trigChannel->currentText());
    m_level->setSuffix(unit.isEmpty() ? QString() : QStringLiteral(" ") + unit);
    const bool linear = linearAxis();
    m_jogDistance->setSuffix(linear ? tr(" mm") : tr(" deg"));
    m_jogSpeed->setSuffix(linear ? tr(" mm/s") : tr(" deg/s"));
    m_jogAccel->setSuffix(linear ? tr(" mm/s²") : tr(" deg/s²"));
}

void ScopeDock::updateRate()
{
    if (!m_caps) {
        m_rate->setText(tr("Sample rate: (no scope)"));
        return;
    }
    const double rate = m_caps->fastestRateHz / m_divider->value();
    m_rate->setText(tr("Sample rate: %1 Hz (drive's fastest %2 Hz / %3)")
                        .arg(qs(model::formatNumber(rate, 6)), qs(model::formatNumber(m_caps->fastestRateHz, 6)))
                        .arg(m_divider->value()));
}

void ScopeDock::setTrigger(const QString& channel, double level, device::ScopeEdge edge, double prePct, double lengthS)
{
    m_trigChannel->setCurrentIndex(m_trigChannel->findText(channel));
    m_level->setValue(level);
    m_edge->setCurrentIndex(static_cast<int>(edge));
    m_pre->setValue(prePct);
    m_length->setValue(lengthS);
}

void ScopeDock::setDivider(int divider)
{
    m_divider->setValue(divider);
}
void ScopeDock::setRollMode(bool roll)
{
    m_roll->setChecked(roll);
}
void ScopeDock::setHistoryRows(int rows)
{
    m_historyRows->setValue(rows);
}

void ScopeDock::setJog(double distance, double speed, double acceleration, bool backAndForth)
{
    m_jogDistance->setValue(distance);
    m_jogSpeed->setValue(speed);
    m_jogAccel->setValue(acceleration);
    m_jogReturn->setChecked(backAndForth);
}

// ------------------------------------------------------------------------------------------------
// Run, poll, stop

Result<device::ScopeRequest> ScopeDock::request(bool single) const
{
    if (!m_caps)
        return makeError(ErrorCode::BadInput,
                         tr("The drive's scope channels are not known yet (axis %1)").arg(axis()).toStdString());
    device::ScopeRequest r;
    r.axis = axis().toStdString();
    for (const auto& c : selectedChannels())
        r.channels.push_back(c.toStdString());
    if (r.channels.empty())
        return makeError(ErrorCode::BadInput, tr("Channels: tick at least one channel").toStdString());
    r.divider = m_divider->value();
    const double rate = m_caps->fastestRateHz / r.divider;
    if (m_roll->isChecked() && !single) {
        r.mode = device::ScopeMode::Roll;
    } else {
        r.mode = single ? device::ScopeMode::Single : device::ScopeMode::Normal;
        r.triggerChannel = m_trigChannel->currentText().toStdString();
        if (r.triggerChannel.empty())
            return makeError(ErrorCode::BadInput,
                             tr("Trigger channel: choose one of the ticked channels").toStdString());
        r.triggerLevel = m_level->value();
        r.edge = static_cast<device::ScopeEdge>(std::clamp(m_edge->currentIndex(), 0, 2));
        r.preTriggerPct = m_pre->value();
        const double rows = std::round(m_length->value() * rate);
        if (!(rows >= 2.0))
            return makeError(
                ErrorCode::BadInput,
                tr("Length: %1 s is shorter than two samples at %2 Hz").arg(m_length->value()).arg(rate).toStdString());
        r.lengthSamples = static_cast<std::uint64_t>(rows);
    }
    if (auto ok = device::checkScopeRequest(r, *m_caps); !ok)
        return ok.error();
    return r;
}

void ScopeDock::runNormal()
{
    start(false);
}
void ScopeDock::runSingle()
{
    start(true);
}

void ScopeDock::start(bool single)
{
    auto r = request(single);
    if (!r) {
        setMessage(qs(r.error().detail), true);
        return;
    }
    setMessage(QString(), false);
    m_armed = *r;
    m_rollRunning = r->mode == device::ScopeMode::Roll;
    m_knownCaptures = 0;
    m_pollInFlight = true;
    setRunning(true);
    m_armRequest = connectReply(m_ctx.drive().armScope(*r), this, &ScopeDock::onArmed);
    m_ctx.log(tr("Scope armed on axis %1: %2, %3 channels")
                  .arg(axis(), m_rollRunning ? tr("roll mode") : (single ? tr("single capture") : tr("normal mode")))
                  .arg(r->channels.size()));
}

void ScopeDock::onArmed(const DriveReply& reply)
{
    if (reply.id != m_armRequest)
        return;
    m_pollInFlight = false;
    if (!reply.ok) {
        setRunning(false);
        setMessage(tr("The drive refused the scope: %1").arg(reply.error), true);
        m_ctx.log(tr("Scope: %1").arg(reply.error));
        return;
    }
    if (m_rollRunning && m_armed && m_caps) {
        std::vector<device::ScopeChannelInfo> infos;
        for (const auto& name : m_armed->channels)
            for (const auto& ch : m_caps->channels)
                if (ch.name == name)
                    infos.push_back(ch);
        m_history.reset(std::move(infos), reply.scopeStatus->rateHz, static_cast<std::size_t>(m_historyRows->value()));
        m_nextSample = reply.scopeStatus->oldestSample;
        m_lostAtStart = 0;
        m_captureAxis = qs(m_armed->axis);
        m_captureSource = m_ctx.drive().uri();
    }
    if (reply.scopeStatus) {
        m_stateKey = qs(device::scopeStateName(reply.scopeStatus->state));
        m_state->setText(stateText());
    }
    m_timer->start();
}

void ScopeDock::poll()
{
    if (!m_running || m_pollInFlight)
        return;
    if (!m_ctx.drive().isConnected()) {
        setRunning(false);
        return;
    }
    m_pollInFlight = true;
    std::optional<std::uint64_t> from;
    if (m_rollRunning)
        from = m_nextSample;
    connectReply(m_ctx.drive().pollScope(from, m_knownCaptures, kMaxRowsPerPoll), this, &ScopeDock::onPolled);
}

void ScopeDock::onPolled(const DriveReply& reply)
{
    m_pollInFlight = false;
    if (!m_running)
        return;
    if (!reply.ok) {
        setRunning(false);
        setMessage(tr("Scope stopped: %1").arg(reply.error), true);
        m_ctx.log(tr("Scope stopped: %1").arg(reply.error));
        return;
    }
    const auto& st = *reply.scopeStatus;
    m_stateKey = qs(device::scopeStateName(st.state));
    if (reply.scopeRows) {
        const auto& rows = *reply.scopeRows;
        if (m_history.size() == 0 && rows.rows > 0 && rows.firstSample > m_nextSample)
            m_lostAtStart += rows.firstSample - m_nextSample;
        m_history.append(rows);
        if (rows.rows > 0)
            m_nextSample = rows.firstSample + rows.rows;
        const std::uint64_t lost = m_history.lostSamples() + m_lostAtStart;
        if (lost > 0)
            setMessage(tr("%1 samples were lost (overwritten in the drive before they were read); the gaps are in "
                          "the sample numbers")
                           .arg(lost),
                       true);
        const qint64 now = QDateTime::currentMSecsSinceEpoch();
        if (now - m_lastRollDraw >= kRollDrawMs) {
            m_lastRollDraw = now;
            refreshRoll();
        }
        if (rows.rows >= kMaxRowsPerPoll)
            QTimer::singleShot(0, this, &ScopeDock::poll); // a backlog: read on at once
    }
    if (reply.scopeCapture) {
        m_knownCaptures = std::max<std::uint64_t>(st.captures, reply.scopeCapture->number);
        m_captureAxis = m_armed ? qs(m_armed->axis) : axis();
        m_captureSource = m_ctx.drive().uri();
        show(reply.scopeCapture);
        m_ctx.log(tr("Scope capture %1 on axis %2: %3 samples, trigger at sample %4")
                      .arg(reply.scopeCapture->number)
                      .arg(m_captureAxis)
                      .arg(reply.scopeCapture->rows())
                      .arg(reply.scopeCapture->triggerSample));
    }
    if (st.state == device::ScopeState::Done || st.state == device::ScopeState::Idle) {
        if (!reply.scopeCapture && st.captures > m_knownCaptures) {
            poll(); // the capture completed between the status and its readout: read it
            return;
        }
        setRunning(false);
    }
    m_state->setText(stateText());
}

void ScopeDock::refreshRoll()
{
    const auto rows = static_cast<std::size_t>(std::max(2.0, std::round(m_window->value() * m_history.rateHz())));
    show(std::make_shared<const device::ScopeCapture>(m_history.snapshot(rows)));
}

void ScopeDock::stop()
{
    const bool wasRoll = m_rollRunning;
    if (m_running && m_ctx.drive().isConnected())
        m_ctx.drive().stopScope();
    setRunning(false);
    if (wasRoll && m_history.size() > 0) {
        // Stopped: the whole history for review (pan and zoom over it).
        show(std::make_shared<const device::ScopeCapture>(m_history.snapshot()));
    }
}

void ScopeDock::setRunning(bool running)
{
    const bool was = m_running;
    m_running = running;
    if (!running) {
        m_timer->stop();
        if (m_stateKey != "done" && m_stateKey != "offline")
            m_stateKey = "idle";
        m_rollRunning = m_rollRunning && running;
    }
    m_state->setText(stateText());
    updateButtons();
    if (was && !running)
        emit stopped();
}

void ScopeDock::updateButtons()
{
    const bool connected = m_ctx.drive().isConnected();
    const bool ready = connected && m_caps && !selectedChannels().isEmpty();
    m_run->setEnabled(ready && !m_running);
    m_single->setEnabled(ready && !m_running && !m_roll->isChecked());
    m_stop->setEnabled(m_running);
    m_channels->setEnabled(!m_running);
    m_axis->setEnabled(!m_running);
    m_triggerBox->setEnabled(!m_running && !m_roll->isChecked());
    m_rollBox->setEnabled(!m_running);
    m_jogButton->setEnabled(connected && !axis().isEmpty() && m_jog.isNull());
    m_jogStop->setEnabled(!m_jog.isNull());
    const bool have = m_capture != nullptr;
    m_exportCsv->setEnabled(have);
    m_exportImage->setEnabled(have);
    m_spectrum->setEnabled(have);
    m_keepRef->setEnabled(have);
    m_save->setEnabled(have && m_ctx.database() != nullptr);
    m_openStore->setEnabled(m_ctx.database() != nullptr);
}

QString ScopeDock::stateLabel(const QString& key)
{
    if (key == "idle")
        return tr("Stopped");
    if (key == "filling")
        return tr("Armed: filling the pre-trigger");
    if (key == "waiting")
        return tr("Waiting for the trigger");
    if (key == "triggered")
        return tr("Triggered");
    if (key == "done")
        return tr("Capture complete");
    if (key == "rolling")
        return tr("Rolling");
    if (key == "offline")
        return tr("Offline review");
    return key;
}

QString ScopeDock::stateText() const
{
    return stateLabel(m_stateKey);
}
QString ScopeDock::messageText() const
{
    return m_messageText;
}

void ScopeDock::setMessage(const QString& text, bool error)
{
    m_messageText = text;
    m_messageError = error;
    m_message->setText(text);
    m_message->setStyleSheet(error ? QStringLiteral("color: #c00000; font-weight: bold;") : QString());
    m_message->setVisible(!text.isEmpty());
}

// ------------------------------------------------------------------------------------------------
// The capture shown, files and the store

void ScopeDock::show(std::shared_ptr<const device::ScopeCapture> capture)
{
    m_capture = std::move(capture);
    updateAnalysisChannels();
    redraw();
    updateButtons();
    emit captureShown();
}

void ScopeDock::redraw()
{
    m_mathName.clear();
    if (!m_capture) {
        m_plot->setCapture(nullptr);
        updateXyPlot();
        return;
    }
    auto table = scopePlotTable(*m_capture);
    const auto op = static_cast<Math>(std::clamp(m_mathOp->currentIndex(), 0, 2));
    const std::string a = m_mathA->currentText().toStdString(), b = m_mathB->currentText().toStdString();
    if (op != Math::None && !a.empty()) {
        auto m =
            op == Math::Difference ? device::scopeDifference(*m_capture, a, b) : device::scopeDerivative(*m_capture, a);
        if (m) {
            m_mathName = qs(m->info.name);
            table->metadata["unit." + m->info.name] = m->info.unit;
            table->channels.push_back({m->info.name, std::move(m->values)});
        } else {
            setMessage(qs(m.error().detail), true);
        }
    }
    m_scaledName.clear();
    const double gain = m_scaleGain->value(), offset = m_scaleOffset->value();
    if (m_scaleChannel->currentIndex() > 0 && (gain != 1.0 || offset != 0.0)) {
        const std::string name = m_scaleChannel->currentText().toStdString();
        for (auto& ch : table->channels) {
            if (ch.name != name)
                continue;
            for (double& v : ch.data)
                v = gain * v + offset;
            const std::string shown = name + " ×" + model::formatShortest(gain) +
                                      (offset != 0.0 ? " +" + model::formatShortest(offset) : std::string());
            if (auto u = table->metadata.find("unit." + name); u != table->metadata.end()) {
                table->metadata["unit." + shown] = u->second;
                table->metadata.erase(u);
            }
            ch.name = shown;
            m_scaledName = qs(shown);
        }
    }
    const bool keepCursors = !m_plot->cursorReadout().isEmpty();
    m_plot->setCapture(table);
    if (!keepCursors && m_capture->rows() >= 2) {
        const auto [lo, hi] = m_plot->visibleRange();
        m_plot->setCursors(lo + 0.25 * (hi - lo), lo + 0.75 * (hi - lo));
    }
    updateXyPlot();
}

void ScopeDock::updateAnalysisChannels()
{
    QStringList names;
    if (m_capture)
        for (const auto& ch : m_capture->channels)
            names << qs(ch.name);
    {
        // Scale: "none" first, then the channels; the choice kept while it exists.
        QStringList have;
        for (int i = 1; i < m_scaleChannel->count(); ++i)
            have << m_scaleChannel->itemText(i);
        if (have != names) {
            const QString current = m_scaleChannel->currentIndex() > 0 ? m_scaleChannel->currentText() : QString();
            const QSignalBlocker block(m_scaleChannel);
            while (m_scaleChannel->count() > 1)
                m_scaleChannel->removeItem(1);
            m_scaleChannel->addItems(names);
            const int i = current.isEmpty() ? -1 : m_scaleChannel->findText(current);
            m_scaleChannel->setCurrentIndex(i > 0 ? i : 0);
        }
    }
    for (auto* c : {m_mathA, m_mathB, m_xChannel, m_yChannel}) {
        QStringList have;
        for (int i = 0; i < c->count(); ++i)
            have << c->itemText(i);
        if (have == names)
            continue;
        const QString current = c->currentText();
        const QSignalBlocker block(c);
        c->clear();
        c->addItems(names);
        // Keep the choice; else the first channel that is not the machine time (B and Y: the next one).
        const int skip = names.isEmpty() || names.front() != QLatin1String("t_s") ? 0 : 1;
        if (const int i = c->findText(current); i >= 0)
            c->setCurrentIndex(i);
        else
            c->setCurrentIndex(std::min(skip + ((c == m_mathB || c == m_yChannel) ? 1 : 0), c->count() - 1));
    }
}

void ScopeDock::updateXyPlot()
{
    if (!m_xy->isChecked())
        return;
    m_xyPlot->clear();
    if (!m_capture)
        return;
    int kx = -1, ky = -1;
    for (std::size_t k = 0; k < m_capture->channels.size(); ++k) {
        if (qs(m_capture->channels[k].name) == m_xChannel->currentText())
            kx = static_cast<int>(k);
        if (qs(m_capture->channels[k].name) == m_yChannel->currentText())
            ky = static_cast<int>(k);
    }
    if (kx < 0 || ky < 0)
        return;
    m_xyPlot->setAxes(m_xChannel->currentText(), qs(m_capture->channels[kx].unit), m_yChannel->currentText(),
                      qs(m_capture->channels[ky].unit));
    // Two quantities of one unit (X against Y of a circle) get one scale, so the plot shows their true shape.
    m_xyPlot->setEqualScales(m_capture->channels[kx].unit == m_capture->channels[ky].unit);
    m_xyPlot->addCurve(tr("capture"), m_capture->columns[kx], m_capture->columns[ky]);
    m_xyPlot->rescale();
}

void ScopeDock::setScale(const QString& channel, double gain, double offset)
{
    const QSignalBlocker b1(m_scaleChannel), b2(m_scaleGain), b3(m_scaleOffset);
    const int i = channel.isEmpty() ? 0 : m_scaleChannel->findText(channel);
    m_scaleChannel->setCurrentIndex(i > 0 ? i : 0);
    m_scaleGain->setValue(gain);
    m_scaleOffset->setValue(offset);
    redraw();
}

void ScopeDock::setMath(Math op, const QString& a, const QString& b)
{
    m_mathA->setCurrentIndex(m_mathA->findText(a));
    m_mathB->setCurrentIndex(m_mathB->findText(b));
    m_mathOp->setCurrentIndex(static_cast<int>(op));
    redraw();
}

void ScopeDock::setXy(bool on, const QString& x, const QString& y)
{
    if (!x.isEmpty())
        m_xChannel->setCurrentIndex(m_xChannel->findText(x));
    if (!y.isEmpty())
        m_yChannel->setCurrentIndex(m_yChannel->findText(y));
    m_xy->setChecked(on);
    updateXyPlot();
}

void ScopeDock::keepReference()
{
    if (!m_capture)
        return;
    ++m_references;
    const auto table = scopePlotTable(*m_capture);
    const auto& time = table->channels.front().data;
    for (std::size_t k = 1; k < table->channels.size(); ++k) {
        const auto& ch = table->channels[k];
        const auto u = table->metadata.find("unit." + ch.name);
        m_plot->addSeries(tr("ref %1: %2").arg(m_references).arg(qs(ch.name)), time, ch.data,
                          u == table->metadata.end() ? QString() : qs(u->second), QColor(150, 150, 150), Qt::DashLine);
    }
}

void ScopeDock::clearReferences()
{
    m_references = 0;
    m_plot->clear();
    redraw();
}

widgets::CurvePlot* ScopeDock::showSpectrum(QString* error)
{
    auto fail = [&](const QString& e) -> widgets::CurvePlot* {
        if (error)
            *error = e;
        return nullptr;
    };
    if (!m_capture)
        return fail(tr("No capture shown"));
    const QString channel = m_mathA->currentText();
    // The rows inside the visible time window (time as the plot shows it).
    const auto table = scopePlotTable(*m_capture);
    const auto& t = table->channels.front().data;
    const auto [lo, hi] = m_plot->visibleRange();
    const auto first = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), lo) - t.begin());
    const auto last = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), hi) - t.begin());
    auto s = device::scopeSpectrum(*m_capture, channel.toStdString(), first, last > first ? last - first : 0);
    if (!s)
        return fail(qs(s.error().detail));
    QString unit;
    for (const auto& ch : m_capture->channels)
        if (qs(ch.name) == channel)
            unit = qs(ch.unit);
    auto* plot = new widgets::CurvePlot;
    plot->setAxes(tr("Frequency"), QStringLiteral("Hz"), tr("Amplitude"), unit);
    plot->addCurve(channel, s->freqHz, s->amplitude);
    plot->rescale();
    plot->setProperty("resolutionHz", s->resolutionHz);
    m_ctx.showDocument(plot, tr("Spectrum of %1 (%2 samples, %3 Hz resolution)")
                                 .arg(channel)
                                 .arg(last - first)
                                 .arg(qs(model::formatNumber(s->resolutionHz, 4))));
    return plot;
}

std::map<std::string, std::string> ScopeDock::captureMetadata() const
{
    std::map<std::string, std::string> m{{"connection", m_captureSource.toStdString()}};
    if (m_armed && m_capture && m_capture->triggered) {
        m["divider"] = std::to_string(m_armed->divider);
        m["trigger"] = m_armed->triggerChannel + ":" + model::formatNumber(m_armed->triggerLevel, 17) + ":" +
                       device::scopeEdgeName(m_armed->edge);
        m["pre_trigger_pct"] = model::formatNumber(m_armed->preTriggerPct, 17);
        m["capture_number"] = std::to_string(m_capture->number);
    }
    return m;
}

bool ScopeDock::exportCsv(const QString& path, QString* error) const
{
    if (!m_capture) {
        if (error)
            *error = tr("No capture to export");
        return false;
    }
    const auto table = device::scopeCaptureToTable(*m_capture, m_captureAxis.toStdString(), captureMetadata());
    if (auto st = io::writeCaptureCsvFile(path.toStdString(), table); !st) {
        if (error)
            *error = qs(st.error().detail);
        return false;
    }
    return true;
}

bool ScopeDock::exportImage(const QString& path, QString* error) const
{
    if (!m_plot->exportImage(path)) {
        if (error)
            *error = m_plot->lastError();
        return false;
    }
    return true;
}

void ScopeDock::exportCsvInteractive()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the capture as CSV"),
                                                      QStringLiteral("scope.csv"), tr("Scope CSV (*.csv)"));
    if (path.isEmpty())
        return;
    QString e;
    if (exportCsv(path, &e))
        setMessage(tr("Written: %1").arg(path), false);
    else
        setMessage(e, true);
}

void ScopeDock::exportImageInteractive()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the plot"), QStringLiteral("scope.png"),
                                                      tr("Images (*.png *.svg *.pdf)"));
    if (path.isEmpty())
        return;
    QString e;
    if (exportImage(path, &e))
        setMessage(tr("Written: %1").arg(path), false);
    else
        setMessage(e, true);
}

bool ScopeDock::saveToStore(QString* error)
{
    if (!m_capture) {
        if (error)
            *error = tr("No capture to save");
        return false;
    }
    if (!m_ctx.database()) {
        if (error)
            *error = tr("No store is open (Settings → Preferences)");
        return false;
    }
    store::SessionRecord rec;
    rec.info.kind = "scope";
    rec.info.axis = m_captureAxis.toStdString();
    rec.info.note = m_capture->triggered ? "scope: triggered capture" : "scope: roll record";
    nlohmann::json in = nlohmann::json::object();
    for (const auto& [k, v] : captureMetadata())
        in[k] = v;
    in["mode"] = m_capture->triggered ? "triggered" : "roll";
    rec.inputs = in;
    rec.captures.push_back({kStoreCapture, device::scopeCaptureToTable(*m_capture, rec.info.axis, captureMetadata())});
    m_ctx.saveSessionAsync(std::move(rec), this, [this](Result<std::int64_t> id) {
        if (id) {
            setMessage(tr("Capture saved in the store as session %1").arg(*id), false);
            emit saved(*id);
        } else {
            setMessage(tr("The capture was not saved: %1").arg(qs(id.error().detail)), true);
        }
    });
    return true;
}

bool ScopeDock::openFromStore(qint64 sessionId, QString* error)
{
    auto fail = [&](const QString& e) {
        if (error)
            *error = e;
        return false;
    };
    if (!m_ctx.database())
        return fail(tr("No store is open (Settings → Preferences)"));
    auto s = m_ctx.database()->loadSession(sessionId);
    if (!s)
        return fail(qs(s.error().detail));
    for (const auto& c : s->captures) {
        if (c.name != kStoreCapture)
            continue;
        auto cap = device::scopeCaptureFromTable(c.capture);
        if (!cap)
            return fail(tr("Session %1: %2").arg(sessionId).arg(qs(cap.error().detail)));
        if (m_running)
            stop();
        m_armed.reset();
        m_captureAxis = qs(s->info.axis);
        m_captureSource = tr("store session %1").arg(sessionId);
        m_stateKey = "offline";
        show(std::make_shared<const device::ScopeCapture>(std::move(cap).value()));
        setMessage(tr("Session %1 (%2, axis %3) from the store").arg(sessionId).arg(qs(s->info.started), m_captureAxis),
                   false);
        m_state->setText(stateText());
        return true;
    }
    return fail(tr("Session %1 holds no scope capture").arg(sessionId));
}

void ScopeDock::openFromStoreInteractive()
{
    if (!m_ctx.database())
        return;
    auto list = m_ctx.database()->listSessions();
    if (!list) {
        setMessage(qs(list.error().detail), true);
        return;
    }
    QStringList items;
    std::vector<qint64> ids;
    for (const auto& s : *list) {
        if (s.kind != "scope")
            continue;
        items << tr("Session %1: %2, axis %3, %4").arg(s.id).arg(qs(s.machine), qs(s.axis), qs(s.started));
        ids.push_back(s.id);
    }
    if (items.isEmpty()) {
        setMessage(tr("The store holds no scope capture"), false);
        return;
    }
    bool ok = false;
    const QString choice =
        QInputDialog::getItem(this, tr("Open a saved capture"), tr("Capture:"), items, 0, false, &ok);
    if (!ok)
        return;
    QString e;
    if (!openFromStore(ids[static_cast<std::size_t>(items.indexOf(choice))], &e))
        setMessage(e, true);
}

bool ScopeDock::openCsv(const QString& path, QString* error)
{
    auto t = io::readScopeCsvFile(path.toStdString());
    if (!t) {
        if (error)
            *error = qs(t.error().detail);
        return false;
    }
    auto cap = device::scopeCaptureFromTable(t->capture);
    if (!cap) {
        if (error)
            *error = path + QStringLiteral(": ") + qs(cap.error().detail);
        return false;
    }
    if (m_running)
        stop();
    m_armed.reset();
    const auto a = t->capture.metadata.find("axis");
    m_captureAxis = a == t->capture.metadata.end() ? QString() : qs(a->second);
    m_captureSource = path;
    m_stateKey = "offline";
    show(std::make_shared<const device::ScopeCapture>(std::move(cap).value()));
    setMessage(tr("Opened %1").arg(path), false);
    m_state->setText(stateText());
    return true;
}

void ScopeDock::openCsvInteractive()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open a scope CSV"), QString(), tr("Scope CSV (*.csv)"));
    if (path.isEmpty())
        return;
    QString e;
    if (!openCsv(path, &e))
        setMessage(e, true);
}

// ------------------------------------------------------------------------------------------------
// Jog

void ScopeDock::startJog()
{
    if (!m_jog.isNull())
        return;
    if (!m_ctx.drive().isConnected() || axis().isEmpty()) {
        setMessage(tr("Jog: not connected"), true);
        return;
    }
    // The panel shows mm or deg; the drive takes m or rad.
    const double scale = linearAxis() ? 1e-3 : std::numbers::pi / 180.0;
    device::TestRequest t;
    t.axis = axis().toStdString();
    t.type = device::TestType::Jog;
    t.distance = m_jogDistance->value() * scale;
    t.velocity = m_jogSpeed->value() * scale;
    t.acceleration = m_jogAccel->value() * scale;
    t.returnToStart = m_jogReturn->isChecked();
    t.durationS = 0.1;
    m_jog = m_ctx.drive().runTest(t);
    connect(m_jog.data(), &DriveRequest::finished, this, &ScopeDock::onJogDone);
    m_ctx.log(tr("Jog on axis %1: %2 at %3%4")
                  .arg(axis(), m_jogDistance->text(), m_jogSpeed->text(),
                       m_jogReturn->isChecked() ? tr(", back and forth") : QString()));
    updateButtons();
}

void ScopeDock::stopJog()
{
    if (!m_jog.isNull())
        m_jog->abort();
}

void ScopeDock::onJogDone(const DriveReply& reply)
{
    m_jog.clear();
    updateButtons();
    if (reply.ok) {
        emit jogFinished(true, QString());
        return;
    }
    setMessage(tr("Jog: %1").arg(reply.error), true);
    emit jogFinished(false, reply.error);
}

} // namespace gui
} // namespace axistune

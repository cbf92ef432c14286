// SPDX-License-Identifier: GPL-3.0-or-later
// The scope dock (ScopeDock.h, docs/scope.md "The GUI scope").
#include "app/gui/ScopeDock.h"

#include "app/gui/AppContext.h"
#include "app/gui/DriveController.h"
#include "app/gui/WidgetUtil.h"
#include "core/device/ScopeMath.h"
#include "core/io/CaptureCsv.h"
#include "core/io/ScopeCsv.h"
#include "core/model/MetadataKeys.h"
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

} // namespace

// A scope capture as a plot table (ScopeDock.h).
std::shared_ptr<model::Capture> scopePlotTable(const device::ScopeCapture& c)
{
    auto t = std::make_shared<model::Capture>();
    t->metadata.set(model::meta::kFsHz, c.rateHz);
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
        t->metadata.set("unit." + c.channels[k].name, c.channels[k].unit);
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
    auto& j = t.test.emplace<device::JogTest>();
    j.distance = m_jogDistance->value() * scale;
    j.velocity = m_jogSpeed->value() * scale;
    j.acceleration = m_jogAccel->value() * scale;
    j.returnToStart = m_jogReturn->isChecked();
    j.dwellS = 0.1;
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

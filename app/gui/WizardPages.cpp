// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/WizardPages.h"

#include "app/gui/AppContext.h"
#include "app/gui/ParameterText.h"

#include "core/model/Units.h"
#include "core/store/FrfCapture.h"
#include "core/store/SessionRecord.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QWizard>

#include <cmath>

namespace axistune {
namespace gui {

namespace {
QString qs(const std::string& s) { return QString::fromStdString(s); }
const model::ParameterMeta* findMeta(const std::vector<model::ParameterMeta>& metas, const std::string& key)
{
    for (const auto& m : metas)
        if (m.key == key)
            return &m;
    return nullptr;
}
QTableWidget* makeTable(QWidget* parent, const QStringList& headers)
{
    auto* t = new QTableWidget(parent);
    t->setColumnCount(static_cast<int>(headers.size()));
    t->setHorizontalHeaderLabels(headers);
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    t->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    t->verticalHeader()->hide();
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->setWordWrap(false);
    return t;
}
QString testName(const device::TestRequest& r)
{
    switch (r.type()) {
    case device::TestType::Step:
        return QCoreApplication::translate("TestRunPage", "velocity step");
    case device::TestType::Jog:
        return QCoreApplication::translate("TestRunPage", "jog");
    case device::TestType::Hold:
        return QCoreApplication::translate("TestRunPage", "position hold");
    case device::TestType::Frf:
        return QCoreApplication::translate("TestRunPage", "frequency response (%1)")
            .arg(qs(device::frfMethodName(r.frf().method)));
    case device::TestType::Circle:
        return QCoreApplication::translate("TestRunPage", "circle of %1 and %2")
            .arg(qs(r.axis), qs(r.circle().secondAxis));
    case device::TestType::CurrentStep:
        return QCoreApplication::translate("TestRunPage", "current step");
    }
    return {};
}
}  // namespace

QString displayParameterValue(const model::ParameterMeta& meta, double si)
{
    auto v = model::convertUnit(si, meta.siUnit, meta.displayUnit);
    return QString::number(v ? *v : si, 'g', 6);
}

Result<SessionFrf> loadSessionFrf(AppContext& ctx, qint64 sessionId)
{
    auto fail = [](const QString& text) { return makeError(ErrorCode::BadInput, text.toStdString()); };
    if (!ctx.database())
        return fail(QCoreApplication::translate("SessionFrf", "Loading session %1 failed: %2")
                        .arg(sessionId)
                        .arg(QCoreApplication::translate("SessionFrf", "no store is open")));
    auto rec = ctx.database()->loadSession(sessionId);
    if (!rec)
        return fail(QCoreApplication::translate("SessionFrf", "Loading session %1 failed: %2")
                        .arg(sessionId)
                        .arg(qs(rec.error().detail)));
    const store::NamedCapture* pick = nullptr;
    for (const auto& c : rec->captures)
        if (store::isFrfCapture(c.capture) && (!pick || c.name == "measured"))
            pick = &c;
    if (!pick)
        return fail(QCoreApplication::translate("SessionFrf", "Session %1 holds no frequency response.").arg(sessionId));
    auto frf = store::frfFromCapture(pick->capture);
    if (!frf)
        return fail(QCoreApplication::translate("SessionFrf", "Session %1, capture %2: %3")
                        .arg(sessionId)
                        .arg(qs(pick->name), qs(frf.error().detail)));
    return SessionFrf{std::move(frf).value(), qs(rec->info.axis), qs(pick->name)};
}

void checkNcPositionPid(AppContext& ctx, const QString& axis, QObject* receiver,
                        std::function<void(bool ncPid, const QString& outputSignal)> done)
{
    if (!ctx.drive().isConnected() || axis.isEmpty()) {
        done(false, {});
        return;
    }
    auto* req = ctx.drive().describeAxis(axis);
    const int id = req->id();
    QObject::connect(req, &DriveRequest::finished, receiver, [id, done](const DriveReply& r) {
        if (r.id != id)
            return;
        if (!r.ok || !r.capabilities || !device::isNcPositionPid(*r.capabilities))
            done(false, {});
        else
            done(true, QString::fromStdString(r.capabilities->frfOutputSignal));
    });
}

// ---------------------------------------------------------------------------------------------
// SafetyPage

SafetyPage::SafetyPage(AppContext& ctx, QWidget* parent) : QWizardPage(parent), m_ctx(ctx)
{
    setTitle(tr("Safety"));
    setSubTitle(tr("Check the axis and its limits before anything moves."));
    auto* lay = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_axis = new QComboBox(this);
    form->addRow(tr("Axis:"), m_axis);
    lay->addLayout(form);
    m_motion = new QLabel(this);
    m_motion->setWordWrap(true);
    lay->addWidget(m_motion);
    m_limits = makeTable(this, {tr("Parameter"), tr("Value"), tr("Limits"), tr("Unit")});
    lay->addWidget(m_limits, 1);
    m_state = new QLabel(this);
    m_state->setWordWrap(true);
    lay->addWidget(m_state);
    m_confirm = new QCheckBox(tr("The axis is free to move over the whole test, nobody is inside the machine, "
                                 "and the emergency stop is within reach."),
                              this);
    lay->addWidget(m_confirm);
    registerField("axis", m_axis, "currentText", SIGNAL(currentTextChanged(QString)));
    connect(m_confirm, &QCheckBox::toggled, this, &QWizardPage::completeChanged);
    connect(m_axis, &QComboBox::currentTextChanged, this, [this] {
        showLimits();
        emit completeChanged();
    });
    connect(&m_ctx.drive(), &DriveController::connectionChanged, this, [this] { initializePage(); });
}

void SafetyPage::onReply(const DriveReply& r)
{
    if (r.id == m_metaRequest && r.ok) {
        m_metas = r.metadata;
        // Only the keys this drive has (a LinuxCNC pid has none of a servo drive's, and the other way round).
        QStringList keys;
        for (const auto& k : m_limitKeys)
            if (findMeta(m_metas, k.toStdString()))
                keys << k;
        if (keys.isEmpty())
            return;
        m_readRequest = connectReply(m_ctx.drive().readParameters(r.axis, keys), this, &SafetyPage::onReply);
    } else if (r.id == m_readRequest && r.ok) {
        m_limits->setRowCount(0);
        for (const auto& k : m_limitKeys) {
            const auto* m = findMeta(m_metas, k.toStdString());
            const auto it = r.values.find(k.toStdString());
            if (!m || it == r.values.end())
                continue;
            const int row = m_limits->rowCount();
            m_limits->insertRow(row);
            m_limits->setItem(row, 0, new QTableWidgetItem(parameterLabel(m->label)));
            m_limits->setItem(row, 1, new QTableWidgetItem(displayParameterValue(*m, it->second)));
            m_limits->setItem(row, 2,
                              new QTableWidgetItem(tr("%1 … %2").arg(displayParameterValue(*m, m->minSi),
                                                                     displayParameterValue(*m, m->maxSi))));
            m_limits->setItem(row, 3, new QTableWidgetItem(qs(model::unitLabel(m->displayUnit))));
        }
    } else if ((r.id == m_metaRequest || r.id == m_readRequest) && !r.ok) {
        m_state->setText(tr("Reading the limits failed: %1").arg(r.error));
    }
}

void SafetyPage::setMotionDescription(const QString& text) { m_motion->setText(text); }
void SafetyPage::setLimitKeys(const QStringList& keys) { m_limitKeys = keys; }
void SafetyPage::setAxes(const QStringList& axes) { m_axes = axes; }
QString SafetyPage::axis() const { return m_axis->currentText(); }

void SafetyPage::initializePage()
{
    const QString keep = m_axis->currentText();
    m_axis->blockSignals(true);
    m_axis->clear();
    const QStringList axes = m_axes.isEmpty() ? m_ctx.axes() : m_axes;
    m_axis->addItems(axes);
    if (axes.contains(keep))
        m_axis->setCurrentText(keep);
    m_axis->blockSignals(false);
    if (!m_ctx.drive().isConnected())
        m_state->setText(tr("Not connected: connect to a machine first (Machine ▸ Connect)."));
    else
        m_state->setText(tr("Machine %1, connected through %2.").arg(m_ctx.machine(), m_ctx.drive().uri()));
    showLimits();
    emit completeChanged();
}

void SafetyPage::showLimits()
{
    m_limits->setRowCount(0);
    if (m_ctx.drive().isConnected() && !m_axis->currentText().isEmpty() && !m_limitKeys.isEmpty())
        m_metaRequest = connectReply(m_ctx.drive().readMetadata(m_axis->currentText()), this, &SafetyPage::onReply);
}

bool SafetyPage::isComplete() const
{
    return m_ctx.drive().isConnected() && !m_axis->currentText().isEmpty() && m_confirm->isChecked();
}

// ---------------------------------------------------------------------------------------------
// TestRunPage

TestRunPage::TestRunPage(AppContext& ctx, QWidget* parent) : QWizardPage(parent), m_ctx(ctx)
{
    setTitle(tr("Run"));
    setSubTitle(tr("The axis moves now. Abort stops the motion at once and restores the parameters."));
    auto* lay = new QVBoxLayout(this);
    m_label = new QLabel(this);
    m_label->setWordWrap(true);
    lay->addWidget(m_label);
    m_bar = new QProgressBar(this);
    m_bar->setRange(0, 1000);
    m_bar->setTextVisible(false);
    lay->addWidget(m_bar);
    auto* buttons = new QHBoxLayout;
    m_abort = new QPushButton(tr("Abort"), this);
    m_abort->setStyleSheet("QPushButton { color: #b00000; font-weight: bold; }");
    m_retry = new QPushButton(tr("Run again"), this);
    buttons->addWidget(m_abort);
    buttons->addWidget(m_retry);
    buttons->addStretch(1);
    lay->addLayout(buttons);
    m_log = new QPlainTextEdit(this);
    m_log->setReadOnly(true);
    lay->addWidget(m_log, 1);
    connect(m_abort, &QPushButton::clicked, this, &TestRunPage::abortRun);
    connect(m_retry, &QPushButton::clicked, this, &TestRunPage::start);
    connect(&m_ctx.drive(), &DriveController::connectionLost, this, [this](const QString& why) {
        m_log->appendPlainText(tr("Connection lost: %1").arg(why));
        if (m_running)
            finish(false, tr("Connection lost: %1").arg(why), ErrorCode::Device);
    });
    m_abort->setEnabled(false);
    m_retry->setEnabled(false);
}

void TestRunPage::setRequestFactory(std::function<std::vector<device::TestRequest>()> factory)
{
    m_factory = std::move(factory);
}

void TestRunPage::initializePage() { start(); }

void TestRunPage::cleanupPage()
{
    if (m_running)
        abortRun();
}

bool TestRunPage::isComplete() const { return m_succeeded && !m_running; }

void TestRunPage::start()
{
    if (m_running)
        return;
    m_replies.clear();
    m_index = 0;
    m_succeeded = false;
    m_failure.clear();
    m_requests = m_factory ? m_factory() : std::vector<device::TestRequest>{};
    m_bar->setValue(0);
    if (m_requests.empty()) {
        const QString why = m_emptyReason ? m_emptyReason() : QString();
        finish(false, why.isEmpty() ? tr("Nothing to run.") : why, ErrorCode::BadInput);
        return;
    }
    if (!m_ctx.drive().isConnected()) {
        finish(false, tr("Not connected."), ErrorCode::Device);
        return;
    }
    m_running = true;
    m_abort->setEnabled(true);
    m_retry->setEnabled(false);
    if (wizard())
        wizard()->button(QWizard::BackButton)->setEnabled(false);
    emit completeChanged();
    next();
}

void TestRunPage::next()
{
    const auto& r = m_requests[m_index];
    const QString what = tr("Test %1 of %2 on axis %3: %4")
                             .arg(m_index + 1)
                             .arg(m_requests.size())
                             .arg(qs(r.axis), testName(r));
    m_label->setText(what);
    m_log->appendPlainText(what);
    m_ctx.log(what);
    DriveRequest* req = m_runner ? m_runner(r) : m_ctx.drive().runTest(r);
    m_request = connectReply(req, this, &TestRunPage::onReply);
    connect(req, &DriveRequest::progress, this, [this](double f, const QString&) {
        if (m_requests.empty())
            return;
        const double total = (static_cast<double>(m_index) + f) / static_cast<double>(m_requests.size());
        m_bar->setValue(static_cast<int>(std::lround(1000.0 * total)));
    });
}

void TestRunPage::abortRun()
{
    if (!m_running)
        return;
    m_log->appendPlainText(tr("Abort requested"));
    m_ctx.drive().abort();
}

void TestRunPage::onReply(const DriveReply& r)
{
    if (!m_running || r.id != m_request)
        return;
    if (!r.ok) {
        finish(false, r.error, r.code);
        return;
    }
    m_replies.push_back(r);
    if (++m_index < m_requests.size()) {
        next();
        return;
    }
    m_bar->setValue(1000);
    finish(true, {}, ErrorCode::Internal);
}

void TestRunPage::finish(bool ok, const QString& why, ErrorCode code)
{
    m_running = false;
    m_succeeded = ok;
    m_failure = why;
    m_failureCode = code;
    m_abort->setEnabled(false);
    m_retry->setEnabled(!ok);
    if (wizard())
        wizard()->button(QWizard::BackButton)->setEnabled(true);
    const QString text = ok ? tr("Completed.") : code == ErrorCode::Aborted ? tr("Aborted: %1").arg(why)
                                                                            : tr("Failed: %1").arg(why);
    m_label->setText(text);
    m_log->appendPlainText(text);
    m_ctx.log(text);
    emit completeChanged();
    emit runFinished(ok);
}

// ---------------------------------------------------------------------------------------------
// ApplyPage

ApplyPage::ApplyPage(AppContext& ctx, QWidget* parent) : QWizardPage(parent), m_ctx(ctx)
{
    setTitle(tr("Apply"));
    setSubTitle(tr("The parameters below change on the drive. Every value is read back after the write."));
    auto* lay = new QVBoxLayout(this);
    m_table = makeTable(this, {tr("Parameter"), tr("Key"), tr("Device"), tr("Proposed"), tr("Read back"), tr("Unit")});
    lay->addWidget(m_table, 1);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    lay->addWidget(m_status);
    m_confirm = new QCheckBox(tr("Write these values to the drive"), this);
    m_skip = new QCheckBox(tr("Do not apply now (keep the proposal in the session only)"), this);
    lay->addWidget(m_confirm);
    lay->addWidget(m_skip);
    auto* buttons = new QHBoxLayout;
    m_apply = new QPushButton(tr("Apply"), this);
    m_restore = new QPushButton(tr("Restore previous values"), this);
    buttons->addWidget(m_apply);
    buttons->addWidget(m_restore);
    buttons->addStretch(1);
    lay->addLayout(buttons);
    m_apply->setEnabled(false);
    m_restore->setEnabled(false);
    // Apply only once the device values are known (they are the diff's left side and the restore).
    connect(m_confirm, &QCheckBox::toggled, this,
            [this](bool on) { m_apply->setEnabled(on && !m_applied && !m_previous.empty()); });
    connect(m_skip, &QCheckBox::toggled, this, [this](bool on) {
        m_confirm->setEnabled(!on && !m_applied);
        emit completeChanged();
    });
    connect(m_apply, &QPushButton::clicked, this, &ApplyPage::apply);
    connect(m_restore, &QPushButton::clicked, this, &ApplyPage::restore);
}

void ApplyPage::setProposal(const QString& axis, const model::ParameterValues& proposed)
{
    m_axis = axis;
    m_proposed = proposed;
    m_applied = false;
    m_previous.clear();
    m_readBack.clear();
    m_journal.clear();
}

void ApplyPage::initializePage()
{
    m_confirm->setChecked(false);
    m_confirm->setEnabled(!m_applied);
    m_restore->setEnabled(m_applied);
    m_ctx.setProposed(m_axis, m_proposed);
    fillTable();
    if (m_applied)
        return;
    if (!m_ctx.drive().isConnected()) {
        m_status->setText(tr("Not connected: the proposal can only be kept in the session."));
        return;
    }
    m_status->setText(tr("Reading the device values…"));
    m_metaRequest = connectReply(m_ctx.drive().readMetadata(m_axis), this, &ApplyPage::onReply);
}

bool ApplyPage::isComplete() const { return m_applied || m_skip->isChecked(); }

void ApplyPage::fillTable()
{
    m_table->setRowCount(static_cast<int>(m_proposed.size()));
    int row = 0;
    for (const auto& [key, value] : m_proposed) {
        const auto* m = findMeta(m_metas, key);
        auto text = [&](double si) { return m ? displayParameterValue(*m, si) : QString::number(si, 'g', 6); };
        const auto prev = m_previous.find(key);
        const auto back = m_readBack.find(key);
        m_table->setItem(row, 0, new QTableWidgetItem(m ? parameterLabel(m->label) : qs(key)));
        m_table->setItem(row, 1, new QTableWidgetItem(qs(key)));
        m_table->setItem(row, 2, new QTableWidgetItem(prev != m_previous.end() ? text(prev->second) : QString()));
        auto* prop = new QTableWidgetItem(text(value));
        const bool changed = prev == m_previous.end() || std::abs(prev->second - value) > 1e-12 * std::max(1.0, std::abs(value));
        if (changed) {
            prop->setBackground(QColor(255, 236, 160));
            prop->setToolTip(tr("Changed"));
        }
        m_table->setItem(row, 3, prop);
        m_table->setItem(row, 4, new QTableWidgetItem(back != m_readBack.end() ? text(back->second) : QString()));
        m_table->setItem(row, 5, new QTableWidgetItem(m ? qs(model::unitLabel(m->displayUnit)) : QString()));
        ++row;
    }
}

void ApplyPage::apply()
{
    if (m_applied || !m_confirm->isChecked())
        return;
    if (m_previous.empty()) {
        m_status->setText(tr("The device values are not read yet: wait, then Apply."));
        return;
    }
    m_apply->setEnabled(false);
    m_status->setText(tr("Writing…"));
    m_writeRequest = connectReply(m_ctx.drive().writeParameters(m_axis, m_proposed), this, &ApplyPage::onReply);
}

void ApplyPage::restore()
{
    if (!m_applied || m_previous.empty())
        return;
    m_restore->setEnabled(false);
    m_status->setText(tr("Restoring the previous values…"));
    m_restoreRequest = connectReply(m_ctx.drive().writeParameters(m_axis, m_previous), this, &ApplyPage::onReply);
}

std::vector<store::JournalEntry> ApplyPage::journal() const { return m_journal; }

void ApplyPage::addJournal(const model::ParameterValues& before, const model::ParameterValues& after)
{
    for (const auto& [key, value] : after) {
        store::JournalEntry e;
        e.axis = m_axis.toStdString();
        e.key = key;
        if (const auto it = before.find(key); it != before.end())
            e.oldValue = it->second;
        e.newValue = value;
        m_journal.push_back(e);
    }
}

void ApplyPage::onReply(const DriveReply& r)
{
    if (r.id == m_metaRequest) {
        if (!r.ok) {
            m_status->setText(tr("Reading the parameters failed: %1").arg(r.error));
            return;
        }
        m_metas = r.metadata;
        QStringList keys;
        for (const auto& [k, v] : m_proposed)
            keys << qs(k);
        m_readRequest = connectReply(m_ctx.drive().readParameters(m_axis, keys), this, &ApplyPage::onReply);
    } else if (r.id == m_readRequest) {
        if (!r.ok) {
            m_status->setText(tr("Reading the parameters failed: %1").arg(r.error));
            return;
        }
        m_previous = r.values;
        m_status->setText(tr("Changed values are highlighted. Confirm, then Apply."));
        fillTable();
        m_apply->setEnabled(m_confirm->isChecked());
    } else if (r.id == m_writeRequest) {
        if (!r.ok) {
            m_status->setText(tr("The write failed; the drive keeps its values: %1").arg(r.error));
            m_apply->setEnabled(true);
            return;
        }
        m_applied = true;
        m_readBack = r.values;
        addJournal(m_previous, m_readBack);
        m_status->setText(tr("Applied and read back."));
        m_confirm->setEnabled(false);
        m_restore->setEnabled(true);
        fillTable();
        m_ctx.log(tr("Axis %1: %2 parameters applied and read back").arg(m_axis).arg(m_readBack.size()));
        emit m_ctx.parametersApplied(m_axis);
        emit appliedChanged(true);
        emit completeChanged();
    } else if (r.id == m_restoreRequest) {
        if (!r.ok) {
            m_status->setText(tr("Restoring failed: %1").arg(r.error));
            m_restore->setEnabled(true);
            emit restoreFailed(r.error);
            return;
        }
        addJournal(m_readBack, r.values);
        m_applied = false;
        m_readBack.clear();
        m_status->setText(tr("The previous values are back on the drive."));
        m_confirm->setEnabled(true);
        m_confirm->setChecked(false);
        fillTable();
        m_ctx.log(tr("Axis %1: previous parameters restored").arg(m_axis));
        emit m_ctx.parametersApplied(m_axis);
        emit appliedChanged(false);
        emit completeChanged();
    }
}

}  // namespace gui
}  // namespace axistune

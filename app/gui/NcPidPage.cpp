// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/NcPidPage.h"

#include "app/gui/AppContext.h"
#include "app/gui/WidgetUtil.h"
#include "core/device/FrfQuantityName.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/store/Database.h"
#include "core/store/FrfCapture.h"
#include "core/store/SessionRecord.h"
#include "widgets/BodePlot.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {
namespace {

QString num(double x, int digits = 4)
{
    return std::isfinite(x) ? QString::fromStdString(model::formatNumber(x, digits)) : QStringLiteral("∞");
}

/// The open loop at the measured lines as an FRF (for the plot and the session). With a notch: the lines it takes
/// 60 dB or more out of the loop (its zero sits on the resonance's line) are left out, as the design leaves them
/// out, so the plot is not scaled to a −300 dB spike of the prediction.
dsp::FrequencyResponse loopFrf(const autotune::PidLoopMeasurement& m, const std::vector<std::complex<double>>& l,
                               const std::optional<tuning::BiquadNotch>& notch = std::nullopt)
{
    dsp::FrequencyResponse r;
    for (std::size_t k = 0; k < m.freqHz.size(); ++k)
        if (!notch || std::abs(tuning::biquadNotchResponse(*notch, 1.0 / m.servoRateHz, m.freqHz[k])) >= 1e-3)
            r.push(m.freqHz[k], l[k], NAN, true);
    r.metadata.set(model::meta::kQuantity, std::string(device::frfQuantityMetadataName(device::FrfQuantity::OpenLoop)));
    return r;
}

} // namespace

NcPidPage::NcPidPage(AppContext& ctx, autotune::PidTuneScope scope, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_scope(scope)
{
    setObjectName("ncPidPage");
    setTitle(scope == autotune::PidTuneScope::NotchOnly ? tr("Notch for a position PID the NC closes")
                                                        : tr("Position PID the NC closes"));
    auto* lay = new QVBoxLayout(this);
    m_intro = new QLabel(this);
    m_intro->setWordWrap(true);
    lay->addWidget(m_intro);
    // Two columns of settings, so the table and the plot keep the height.
    auto* form = new QFormLayout;
    auto* form2 = new QFormLayout;
    m_axisBox = new QComboBox(this);
    m_axisBox->setObjectName("ncPidAxis");
    form->addRow(tr("Axis:"), m_axisBox);
    m_amplitude = spin(this, 0.5, 50.0, 5.0, 1, tr(" % of maxoutput"), "ncPidAmplitude");
    form->addRow(tr("Excitation peak (multisine at the PID output):"), m_amplitude);
    m_input = new QComboBox(this);
    m_input->setObjectName("ncPidDriveInput");
    m_input->addItem(tr("from the measured slope"));
    m_input->addItem(tr("torque or current"));
    m_input->addItem(tr("velocity"));
    form2->addRow(tr("Drive input (what the PID output commands):"), m_input);
    m_pm = spin(this, 30.0, 80.0, 50.0, 1, QString::fromUtf8(" °"), "ncPidPhaseMargin");
    form2->addRow(tr("Phase margin asked:"), m_pm);
    m_gm = spin(this, 3.0, 20.0, 8.0, 1, tr(" dB"), "ncPidGainMargin");
    form2->addRow(tr("Gain margin asked:"), m_gm);
    m_notch = new QCheckBox(tr("Propose LinuxCNC's biquad notch when it lets the crossover rise"), this);
    m_notch->setObjectName("ncPidNotch");
    m_notch->setChecked(true);
    m_notch->setVisible(scope == autotune::PidTuneScope::GainsAndNotch);

    auto* columns = new QHBoxLayout;
    columns->addLayout(form, 1);
    columns->addSpacing(16);
    columns->addLayout(form2, 1);
    lay->addLayout(columns);
    if (scope == autotune::PidTuneScope::GainsAndNotch)
        lay->addWidget(m_notch);
    m_confirm = new QCheckBox(tr("The axis is free to move over the whole test, nobody is inside the machine, "
                                 "and the emergency stop is within reach."),
                              this);
    m_confirm->setObjectName("ncPidConfirm");
    lay->addWidget(m_confirm);
    auto* buttons = new QHBoxLayout;
    m_measure = new QPushButton(tr("Measure and propose"), this);
    m_measure->setObjectName("ncPidMeasure");
    m_apply = new QPushButton(
        scope == autotune::PidTuneScope::NotchOnly ? tr("Insert the notch and verify") : tr("Apply and verify"), this);
    m_apply->setObjectName("ncPidApply");
    m_undo = new QPushButton(tr("Undo"), this);
    m_undo->setObjectName("ncPidUndo");
    m_abort = new QPushButton(tr("Abort"), this);
    m_abort->setObjectName("ncPidAbort");
    m_undoAnyway = new QPushButton(tr("Undo anyway"), this);
    m_undoAnyway->setObjectName("ncPidUndoAnyway");
    for (auto* b : {m_measure, m_apply, m_undo, m_abort})
        buttons->addWidget(b);
    buttons->addStretch(1);
    lay->addLayout(buttons);
    // After a refused Undo: the second confirmation is this box; then Undo anyway.
    auto* anyway = new QHBoxLayout;
    m_overwrite = new QCheckBox(tr("Overwrite what changed in HAL since the apply with what ran before"), this);
    m_overwrite->setObjectName("ncPidOverwrite");
    anyway->addWidget(m_overwrite);
    anyway->addWidget(m_undoAnyway);
    anyway->addStretch(1);
    lay->addLayout(anyway);
    m_bar = new QProgressBar(this);
    m_bar->setRange(0, 1000);
    lay->addWidget(m_bar);
    m_status = new QLabel(this);
    m_status->setObjectName("ncPidStatus");
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    lay->addWidget(m_status);
    m_table =
        makeTable(this, {tr("Quantity"), tr("Running"), tr("Proposed"), tr("Verified"), tr("Rule")}, "ncPidTable");
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_table);
    m_plot = new widgets::BodePlot(this);
    m_plot->setObjectName("ncPidPlot");
    m_plot->setMagnitudeTitle(tr("Open loop L [dB]"));
    split->addWidget(m_plot);
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 3);
    lay->addWidget(split, 1);
    m_table->setWordWrap(true);
    m_table->horizontalHeader()->setSectionResizeMode(4, QHeaderView::Stretch);
    setMinimumSize(1100, 820);
    connect(m_measure, &QPushButton::clicked, this, &NcPidPage::measure);
    connect(m_apply, &QPushButton::clicked, this, &NcPidPage::applyProposal);
    connect(m_undo, &QPushButton::clicked, this, &NcPidPage::undo);
    connect(m_undoAnyway, &QPushButton::clicked, this, &NcPidPage::undoAnyway);
    connect(m_overwrite, &QCheckBox::toggled, this, &NcPidPage::updateButtons);
    connect(m_abort, &QPushButton::clicked, this, &NcPidPage::abortRun);
    connect(m_confirm, &QCheckBox::toggled, this, &NcPidPage::updateButtons);
    connect(m_axisBox, &QComboBox::currentTextChanged, this, [this](const QString& axis) {
        if (axis.isEmpty() || axis == m_axis)
            return;
        // Another axis: what was measured belongs to the old one.
        m_axis = axis;
        clearResult();
        m_status->clear();
        showIntro();
        updateButtons();
    });
    updateButtons();
}

NcPidPage::~NcPidPage()
{
    if (m_request)
        m_request->abort();
}

void NcPidPage::initializePage()
{
    {
        const QSignalBlocker block(m_axisBox);
        m_axisBox->clear();
        m_axisBox->addItems(m_ctx.axes());
        if (m_axis.isEmpty() && m_axisBox->count() > 0)
            m_axis = m_axisBox->itemText(0);
        m_axisBox->setCurrentText(m_axis);
    }
    showIntro();
    updateButtons();
}

void NcPidPage::showIntro()
{
    const QString uri = m_ctx.drive().uri();
    m_intro->setText(
        m_scope == autotune::PidTuneScope::NotchOnly
            ? tr("Axis %1 is a position loop the NC closes with a PID (%2): it has no drive filter slots. Its notch "
                 "is LinuxCNC's biquad component (a notch with 0.5 ≤ Q ≤ 2), inserted after the PID output. This page "
                 "measures the open loop with the gains that run, proposes a notch at the plant's strongest resonance "
                 "when it raises the gain margin, inserts it and verifies it by measuring again; the gains are not "
                 "changed.")
                  .arg(m_axis, uri)
            : tr("Axis %1 is a position loop the NC closes with a PID (%2): there is no drive velocity loop. This "
                 "page measures the open loop with the gains that run, proposes P, I, D, FF1 and FF2 (and a biquad "
                 "notch after the PID output when it lets the crossover rise) for the margins asked, with the rule "
                 "behind each number, applies them live and verifies them by measuring again. A loop that misses the "
                 "margins gets back what ran before.")
                  .arg(m_axis, uri));
}

void NcPidPage::cleanupPage()
{
    abortRun();
}

bool NcPidPage::isComplete() const
{
    return !m_request;
}

autotune::PidTuneRequest NcPidPage::request() const
{
    autotune::PidTuneRequest r;
    r.axis = m_axis.toStdString();
    r.amplitudePct = m_amplitude->value();
    if (m_input->currentIndex() == 1)
        r.driveInput = tuning::DriveInput::Torque;
    else if (m_input->currentIndex() == 2)
        r.driveInput = tuning::DriveInput::Velocity;
    r.phaseMarginDeg = m_pm->value();
    r.gainMarginDb = m_gm->value();
    r.notch = m_notch->isChecked();
    r.scope = m_scope;
    return r;
}

void NcPidPage::updateButtons()
{
    const bool idle = !m_request;
    const bool connected = m_ctx.drive().isConnected() && !m_axis.isEmpty();
    const bool appliedNow = m_applied && m_applied->applied && !m_undone;
    m_measure->setEnabled(idle && connected && m_confirm->isChecked() && !appliedNow);
    m_apply->setEnabled(idle && connected && m_confirm->isChecked() && m_proposal && m_proposal->changesSomething() &&
                        !m_applied);
    m_undo->setEnabled(idle && connected && appliedNow);
    m_overwrite->setVisible(m_undoRefused && appliedNow);
    m_undoAnyway->setVisible(m_undoRefused && appliedNow);
    m_undoAnyway->setEnabled(idle && connected && appliedNow && m_overwrite->isChecked());
    m_abort->setEnabled(!idle);
    for (QWidget* w : std::initializer_list<QWidget*>{m_axisBox, m_amplitude, m_input, m_pm, m_gm, m_notch})
        w->setEnabled(idle && !appliedNow);
    emit completeChanged();
}

void NcPidPage::setStatus(const QString& text, bool error)
{
    m_status->setText(error ? QStringLiteral("<span style='color:#b00000'>%1</span>").arg(text.toHtmlEscaped())
                            : text.toHtmlEscaped());
}

void NcPidPage::track(DriveRequest* r)
{
    m_request = r;
    m_bar->setValue(0);
    connect(r, &DriveRequest::progress, this, [this](double f, const QString& detail) {
        m_bar->setValue(static_cast<int>(std::lround(1000.0 * f)));
        if (!detail.isEmpty())
            m_bar->setFormat(QStringLiteral("%p % — ") + detail);
    });
    updateButtons();
}

void NcPidPage::clearResult()
{
    m_measured.reset();
    m_proposal.reset();
    m_applied.reset();
    m_undone = false;
    m_undoRefused = false;
    m_undoWrites.clear();
    m_overwrite->setChecked(false);
    m_table->setRowCount(0);
    m_plot->clearResponses();
}

void NcPidPage::measure()
{
    m_asked = request();
    clearResult();
    setStatus(tr("Measuring the open loop of %1 with the gains that run…").arg(m_axis));
    auto* r = m_ctx.drive().measurePidTune(m_asked);
    connect(r, &DriveRequest::finished, this, &NcPidPage::onMeasured);
    track(r);
}

void NcPidPage::onMeasured(const DriveReply& r)
{
    m_request = nullptr;
    m_measured = r.pidLoop;
    m_proposal = r.pidProposal;
    m_bar->setFormat(QStringLiteral("%p %"));
    if (!r.ok) {
        setStatus(
            r.code == ErrorCode::Aborted
                ? tr("Aborted: the excitation stopped and what AxisTune inserted was removed. %1").arg(r.error)
                : (m_measured ? tr("Measured, but no proposal: %1") : tr("The measurement failed: %1")).arg(r.error),
            true);
        showTable();
        showPlot();
        saveSession(r.error,
                    r.code == ErrorCode::Aborted ? store::SessionStatus::Aborted : store::SessionStatus::Failed);
        updateButtons();
        return;
    }
    m_bar->setValue(1000);
    if (!m_proposal->changesSomething())
        setStatus(tr("Nothing to change: %1").arg(qs(m_proposal->notchRule)));
    else
        setStatus(m_scope == autotune::PidTuneScope::NotchOnly
                      ? tr("Proposed: a notch at %1 Hz, Q %2. Nothing was written yet.")
                            .arg(num(m_proposal->notch->f0Hz), num(m_proposal->notch->q, 3))
                      : tr("Proposed below with the predicted margins. Nothing was written yet."));
    showTable();
    showPlot();
    saveSession(tr("proposed, not applied"), store::SessionStatus::Completed);
    updateButtons();
}

void NcPidPage::applyProposal()
{
    if (!m_measured || !m_proposal)
        return;
    setStatus(m_scope == autotune::PidTuneScope::NotchOnly
                  ? tr("Inserting the notch and measuring the open loop again…")
                  : tr("Writing the gains (read back) and measuring the open loop again…"));
    auto* r = m_ctx.drive().applyPidTune(m_asked, m_measured, m_proposal);
    connect(r, &DriveRequest::finished, this, &NcPidPage::onApplied);
    track(r);
}

void NcPidPage::onApplied(const DriveReply& r)
{
    m_request = nullptr;
    m_bar->setFormat(QStringLiteral("%p %"));
    if (!r.ok) {
        setStatus(tr("Not applied: %1. Nothing was left changed.").arg(r.error), true);
        updateButtons();
        return;
    }
    m_applied = r.pidApplied;
    if (m_applied->applied)
        setStatus(tr("Applied and verified: the measured margins are in the table. Undo puts back what ran before."));
    else
        setStatus(tr("Not kept: %1").arg(qs(m_applied->refusal)), true);
    showTable();
    showPlot();
    saveSession(m_applied->applied ? tr("applied and verified") : qs(m_applied->refusal),
                store::SessionStatus::Completed);
    updateButtons();
}

void NcPidPage::undo()
{
    startUndo(false);
}

void NcPidPage::undoAnyway()
{
    if (m_overwrite->isChecked())
        startUndo(true);
}

void NcPidPage::startUndo(bool force)
{
    if (!m_applied || !m_applied->applied)
        return;
    autotune::AppliedTune tune;
    tune.axis = m_axis.toStdString();
    for (const auto& [k, v] : m_applied->written) {
        tune.applied[k] = v;
        tune.before[k] = m_applied->before.at(k);
    }
    setStatus(force ? tr("Putting back what ran before, over the later change…") : tr("Putting back what ran before…"));
    autotune::PidTuneNotchUndo notch{tune.axis, m_applied->notchBefore, m_proposal->notch};
    m_undoForced = force;
    auto* r = m_ctx.drive().undoPidTune(tune, notch, force);
    connect(r, &DriveRequest::finished, this, &NcPidPage::onUndone);
    m_request = r;
    updateButtons();
}

void NcPidPage::onUndone(const DriveReply& r)
{
    m_request = nullptr;
    if (!r.ok) {
        m_undoRefused = r.code == ErrorCode::Safety;
        setStatus(m_undoRefused ? tr("Undo refused: %1. To put back what ran before all the same, tick the box below and "
                                     "press Undo anyway.")
                                      .arg(r.error)
                                : tr("Undo refused: %1").arg(r.error),
                  true);
    } else {
        m_undone = true;
        m_undoRefused = false;
        m_undoWrites = autotune::pidTuneUndoWrites(r.undone, r.pidNotchUndone ? *r.pidNotchUndone
                                                                              : autotune::PidTuneNotchUndone{});
        saveSession(m_undoForced ? tr("undone anyway (over a later change)") : tr("undone"),
                    store::SessionStatus::Completed);
        const auto& before = m_applied->notchBefore;
        const bool notchChanged = m_proposal && m_proposal->notchChanges();
        const QString notch =
            !notchChanged ? QString()
            : before      ? tr("the notch from before (%1 Hz, Q %2) is back").arg(num(before->f0Hz), num(before->q, 3))
                          : tr("the notch was removed");
        setStatus(m_scope == autotune::PidTuneScope::NotchOnly
                      ? tr("Undone: %1.").arg(notch)
                      : tr("Undone: the gains that ran before are back (read back)%1.")
                            .arg(notch.isEmpty() ? QString() : tr(", and %1").arg(notch)));
    }
    updateButtons();
}

void NcPidPage::abortRun()
{
    if (m_request)
        m_request->abort();
}

void NcPidPage::showTable()
{
    m_table->setRowCount(0);
    if (!m_measured)
        return;
    const auto& run = m_measured->running;
    const auto* p = m_proposal.get();
    const bool verified = m_applied && m_applied->measuredOk;
    // The design's rules begin with the gain they chose ("P = …", "FF1 = FF2 = 0: …"; PositionPid.cpp).
    const auto ruleFor = [&](const std::string& gain) {
        if (p)
            for (const auto& r : p->rules)
                if (r.rfind(gain + " =", 0) == 0 || (gain == "FF2" && r.rfind("FF1 = FF2", 0) == 0))
                    return qs(r);
        return QString();
    };
    const auto gainRow = [&](const QString& name, double running, double proposed, const std::string& gain) {
        addRow(m_table, {name, num(running), p ? num(proposed) : QString(), QString(), ruleFor(gain)});
    };
    const tuning::PositionPid none;
    const auto& g = p ? p->gains : none;
    gainRow(QStringLiteral("Pgain"), run.p, g.p, "P");
    gainRow(QStringLiteral("Igain"), run.i, g.i, "I");
    gainRow(QStringLiteral("Dgain"), run.d, g.d, "D");
    gainRow(QStringLiteral("FF1"), run.ff1, g.ff1, "FF1");
    gainRow(QStringLiteral("FF2"), run.ff2, g.ff2, "FF2");
    if (p) {
        const auto& was = p->runningNotch;
        addRow(m_table, {tr("Notch f0 [Hz]"), was ? num(was->f0Hz) : tr("none"),
                         p->notch ? num(p->notch->f0Hz) : tr("none"), QString(), qs(p->notchRule)});
        addRow(m_table, {tr("Notch Q"), was ? num(was->q, 3) : QString(), p->notch ? num(p->notch->q, 3) : QString(),
                         QString(), QString()});
        addRow(m_table, {tr("Drive input"), QString(),
                         p->input == tuning::DriveInput::Torque ? tr("torque or current") : tr("velocity"), QString(),
                         qs(p->inputRule)});
    }
    const auto marginRow = [&](const QString& name, auto field) {
        addRow(m_table, {name, p ? num(field(p->runningMargins)) : QString(), p ? num(field(p->predicted)) : QString(),
                         verified ? num(field(m_applied->measured)) : QString(),
                         name == tr("Crossover [Hz]") && p && !p->rules.empty() &&
                                 m_scope == autotune::PidTuneScope::GainsAndNotch
                             ? qs(p->rules.front())
                             : QString()});
    };
    marginRow(tr("Crossover [Hz]"), [](const tuning::PositionLoopMargins& m) { return m.crossoverHz; });
    marginRow(tr("Phase margin [°]"), [](const tuning::PositionLoopMargins& m) { return m.phaseMarginDeg; });
    marginRow(tr("Gain margin [dB]"), [](const tuning::PositionLoopMargins& m) { return m.gainMarginDb; });
    addRow(m_table, {tr("Motion time [s]"), num(m_measured->motionTimeS, 3), QString(),
                     verified ? num(m_applied->motionTimeS, 3) : QString(), QString()});
    for (int c = 0; c < 4; ++c)
        m_table->resizeColumnToContents(c);
    m_table->resizeRowsToContents();
}

void NcPidPage::showPlot()
{
    m_plot->clearResponses();
    if (!m_measured)
        return;
    m_plot->addResponse(loopFrf(*m_measured, m_measured->loop), tr("measured, running gains"));
    if (m_proposal && m_proposal->changesSomething())
        m_plot->addResponse(loopFrf(*m_measured, m_proposal->predictedLoop, m_proposal->notch), tr("predicted"),
                            QColor(), Qt::DashLine);
    if (m_applied && m_applied->frf)
        m_plot->addResponse(m_applied->frf->frf, tr("verified (measured after applying)"));
    m_plot->rescale();
}

void NcPidPage::saveSession(const QString& note, store::SessionStatus status)
{
    if (!m_ctx.database())
        return;
    store::SessionRecord rec;
    rec.info.kind = "pid-tune";
    rec.info.axis = m_axis.toStdString();
    rec.info.note = note.toStdString();
    rec.info.status = status;
    if (m_ctx.drive().identity())
        rec.machineAxes = m_ctx.drive().identity()->axes;
    rec.inputs = {{"connection", m_ctx.drive().uri().toStdString()},
                  {"axis", m_asked.axis},
                  {"scope", m_scope == autotune::PidTuneScope::NotchOnly ? "notch" : "gains-and-notch"},
                  {"amplitude_pct", m_asked.amplitudePct},
                  {"phase_margin_deg", m_asked.phaseMarginDeg},
                  {"gain_margin_dB", m_asked.gainMarginDb}};
    if (m_measured && m_measured->frf)
        rec.captures.push_back({"open loop, running gains", store::frfAsCapture(m_measured->frf->frf)});
    if (m_applied && m_applied->frf)
        rec.captures.push_back({"open loop, verified", store::frfAsCapture(m_applied->frf->frf)});
    if (m_measured && m_proposal) {
        rec.captures.push_back(
            {"open loop, predicted",
             store::frfAsCapture(loopFrf(*m_measured, m_proposal->predictedLoop, m_proposal->notch))});
        auto j = autotune::pidTuneJson(m_asked, *m_measured, *m_proposal, m_applied.get());
        j["connection"] = rec.inputs["connection"];
        rec.results.push_back({"pid-tune", j, {}});
        rec.parameterSets.push_back({0,
                                     m_asked.axis,
                                     store::ParameterSource::Read,
                                     {},
                                     "position PID page: before",
                                     m_measured->runningValues});
    } else {
        rec.results.push_back({"error", {{"message", note.toStdString()}}, {}});
    }
    // The journal: the gains and the notch an apply changed, or what an undo put back over what HAL held just before
    // it (after Undo anyway, the later change it overwrote).
    std::vector<autotune::PidTuneWrite> writes;
    if (m_undone) {
        writes = m_undoWrites;
        // The gains read back after the undo are the axis's parameters again (as the autotune wizard's undo saves).
        model::ParameterValues restored;
        for (const auto& w : writes)
            if (m_applied->written.count(w.key))
                restored[w.key] = w.to;
        if (!restored.empty())
            rec.parameterSets.push_back(
                {0, m_asked.axis, store::ParameterSource::Applied, {}, "position PID page: undo", restored});
        if (!rec.results.empty() && rec.results.front().name == "pid-tune")
            rec.results.front().data["undo_journal"] = autotune::pidTuneWritesJson(writes);
    } else if (m_applied && m_applied->applied && m_proposal) {
        if (!m_applied->written.empty())
            rec.parameterSets.push_back(
                {0, m_asked.axis, store::ParameterSource::Applied, {}, "position PID page", m_applied->written});
        writes = autotune::pidTuneAppliedWrites(*m_applied, *m_proposal);
    }
    for (const auto& w : writes) {
        store::JournalEntry e;
        e.axis = m_asked.axis;
        e.key = w.key;
        e.oldValue = w.from;
        e.newValue = w.to;
        rec.journal.push_back(e);
    }
    QPointer<NcPidPage> self(this);
    ++m_pendingSaves;
    m_ctx.saveSessionAsync(std::move(rec), this, [self](Result<std::int64_t> id) {
        if (!self)
            return;
        --self->m_pendingSaves;
        if (id)
            self->m_sessionId = *id;
    });
}

} // namespace gui
} // namespace axistune

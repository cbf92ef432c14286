// SPDX-License-Identifier: GPL-3.0-or-later
// The one-button tuning wizard (AutoTuneWizard.h; docs/tuning.md "The wizard"): choices, the run with its steps,
// the session of kind "autotune"; the result page is in AutoTuneResultPage.cpp.
#include "app/gui/AutoTuneWizard.h"

#include "app/gui/AppContext.h"
#include "app/gui/AutoTuneWizardText.h"
#include "app/gui/WizardRegistry.h"
#include "core/autotune/TravelChoice.h"
#include "core/store/SessionRecord.h"
#include "widgets/CurvePlot.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

using autotunetext::item;
using autotunetext::qs;
using autotunetext::wasAborted;

namespace {

const WizardRegistrar kRegistrar{
    "autotune", QT_TRANSLATE_NOOP("Wizards", "Automatic tuning (one button)…"), 5,
    [](AppContext& ctx, QWidget* parent) -> QWizard* { return new AutoTuneWizard(ctx, parent); }};

/// A JSON value as short text: numbers with 4 significant digits (locale-free), also inside arrays and objects.
QString valueText(const nlohmann::json& v)
{
    if (v.is_number())
        return QString::number(v.get<double>(), 'g', 4);
    if (v.is_string())
        return qs(v.get<std::string>());
    if (v.is_boolean())
        return v.get<bool>() ? QStringLiteral("true") : QStringLiteral("false");
    if (v.is_null())
        return QStringLiteral("–");
    QStringList parts;
    if (v.is_array())
        for (const auto& x : v)
            parts << valueText(x);
    else
        for (const auto& [k, x] : v.items())
            parts << qs(k) + QStringLiteral(" = ") + valueText(x);
    QString s = (v.is_array() ? QStringLiteral("[") : QStringLiteral("{")) + parts.join(QStringLiteral(", ")) +
                (v.is_array() ? QStringLiteral("]") : QStringLiteral("}"));
    if (s.size() > 400)
        s = s.left(400) + QStringLiteral("…");
    return s;
}

/// "key = value; key = value" of a JSON object.
QString objectText(const nlohmann::json& o)
{
    QStringList parts;
    if (o.is_object())
        for (const auto& [k, v] : o.items())
            parts << qs(k) + QStringLiteral(" = ") + valueText(v);
    return parts.isEmpty() ? QStringLiteral("–") : parts.join(QStringLiteral("; "));
}

/// "5, 10, 20" of the amplitude map's peaks.
QString amplitudeListText(const autotune::Options& o)
{
    QStringList parts;
    for (double a : o.amplitudeMapPct)
        parts << QString::number(a, 'g', 4);
    return parts.join(QStringLiteral(", "));
}

} // namespace

QString autoTuneStepTitle(const QString& name)
{
    if (name == "safety-envelope")
        return AutoTuneWizard::tr("1. Safety envelope");
    if (name == "current-loop")
        return AutoTuneWizard::tr("2. Current loop");
    if (name == "frf")
        return AutoTuneWizard::tr("3. Adaptive frequency response");
    if (name == "notches")
        return AutoTuneWizard::tr("4. Notch filters");
    if (name == "velocity-pi")
        return AutoTuneWizard::tr("5. Velocity PI");
    if (name == "position")
        return AutoTuneWizard::tr("6. Position gain and feedforward");
    if (name == "move")
        return AutoTuneWizard::tr("7. Move evaluation");
    if (name == "verify")
        return AutoTuneWizard::tr("8. Verify");
    if (name == "apply")
        return AutoTuneWizard::tr("9. Apply or roll back");
    return name;
}

// ---------------------------------------------------------------------------------------------------------------
// Choices

AutoTuneChoicePage::AutoTuneChoicePage(AppContext& ctx, AutoTuneData& shared, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared)
{
    setTitle(tr("Automatic tuning"));
    setSubTitle(tr("One run through the wizards' steps: safety envelope, current loop, adaptive frequency response, "
                   "notch filters, velocity PI, position gain and feedforward, move evaluation, verify, then apply "
                   "or roll back. Each step shows what it measured, what it chose and the rule that chose it. A "
                   "refusal or Abort restores every parameter."));
    auto* lay = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_axis = new QComboBox(this);
    m_axis->setObjectName("atAxis");
    form->addRow(tr("Axis:"), m_axis);

    auto styleText = [](autotune::Style s) {
        const auto t = autotune::styleTargets(s);
        return tr("designed for phase margin ≥ %1°, gain margin ≥ %2 dB, velocity crossover at least %3 Hz; the "
                  "re-measured loop must keep ≥ %4° and ≥ %5 dB or the run rolls back")
            .arg(t.phaseMarginDeg, 0, 'f', 0)
            .arg(t.gainMarginDb, 0, 'f', 1)
            .arg(t.minBandwidthHz, 0, 'f', 0)
            .arg(t.acceptPhaseMarginDeg, 0, 'f', 0)
            .arg(t.acceptGainMarginDb, 0, 'f', 1);
    };
    auto* styles = new QVBoxLayout;
    auto* group = new QButtonGroup(this);
    auto addStyle = [&](QRadioButton*& b, const QString& name, const QString& when, autotune::Style s,
                        const char* objectName) {
        b = new QRadioButton(name, this);
        b->setObjectName(objectName);
        group->addButton(b);
        styles->addWidget(b);
        auto* l = new QLabel(when + QStringLiteral(" — ") + styleText(s), this);
        l->setWordWrap(true);
        l->setContentsMargins(24, 0, 0, 4);
        styles->addWidget(l);
    };
    addStyle(m_gentle, tr("Gentle"), tr("large margins for heavy or changing loads and little overshoot"),
             autotune::Style::Gentle, "atGentle");
    addStyle(m_standard, tr("Standard"), tr("the wizards' defaults"), autotune::Style::Standard, "atStandard");
    addStyle(m_stiff, tr("Stiff"), tr("the highest bandwidth, for rigid axes"), autotune::Style::Stiff, "atStiff");
    m_standard->setChecked(true);
    form->addRow(tr("Style:"), styles);

    m_budget = new QDoubleSpinBox(this);
    m_budget->setObjectName("atBudget");
    m_budget->setRange(1.0, 600.0);
    m_budget->setDecimals(1);
    m_budget->setValue(30.0);
    m_budget->setSuffix(tr(" s"));
    m_budget->setToolTip(tr("Seconds of motion for the whole sequence; a step that would go beyond it stops the run "
                            "and nothing is changed."));
    form->addRow(tr("Time budget (motion):"), m_budget);
    auto* budgetNote = new QLabel(m_budget->toolTip(), this);
    budgetNote->setWordWrap(true);
    form->addRow(QString(), budgetNote);

    m_minBandwidth = new QDoubleSpinBox(this);
    m_minBandwidth->setObjectName("atMinBandwidth");
    m_minBandwidth->setRange(0.0, 5000.0);
    m_minBandwidth->setDecimals(1);
    m_minBandwidth->setSuffix(tr(" Hz"));
    m_minBandwidth->setSpecialValueText(tr("the style's"));
    m_minBandwidth->setToolTip(tr("The velocity crossover the design must reach; a resonance within a factor 3 of it "
                                  "is refused. The style's value unless set."));
    form->addRow(tr("Required velocity crossover:"), m_minBandwidth);

    m_positions = new QSpinBox(this);
    m_positions->setObjectName("atPositions");
    m_positions->setRange(1, 9);
    m_positions->setSpecialValueText(tr("off (where the axis stands)"));
    m_positions->setSuffix(tr(" positions"));
    m_positions->setToolTip(tr("Measure, design and verify at N positions spread evenly over the travel window; the "
                               "gains must keep the margins at every one. The drive moves the axis between them."));
    form->addRow(tr("Over the travel:"), m_positions);
    m_travelNote = new QLabel(this);
    m_travelNote->setObjectName("atTravelNote");
    m_travelNote->setWordWrap(true);
    form->addRow(QString(), m_travelNote);

    m_amplitudes = new QLineEdit(this);
    m_amplitudes->setObjectName("atAmplitudes");
    m_amplitudes->setPlaceholderText(tr("optional, e.g. 5, 10, 20"));
    m_amplitudes->setToolTip(tr("Amplitude map: the closed velocity loop measured at three or more increasing "
                                "multisine peaks [% of rated torque]; lines whose response changes beyond the noise "
                                "are marked non-linear, and the tuner designs from the amplitude nearest the torque "
                                "of a move. One position only."));
    form->addRow(tr("Amplitude map: amplitudes in % of rated torque:"), m_amplitudes);
    m_choiceError = new QLabel(this);
    m_choiceError->setObjectName("atChoiceError");
    m_choiceError->setWordWrap(true);
    m_choiceError->setStyleSheet(QStringLiteral("color: #b00020;"));
    form->addRow(QString(), m_choiceError);

    m_dryRun = new QCheckBox(tr("Dry run: measure and design everything, then restore every parameter (nothing is "
                                "applied)"),
                             this);
    m_dryRun->setObjectName("atDryRun");
    form->addRow(QString(), m_dryRun);
    lay->addLayout(form);

    m_confirm = new QCheckBox(tr("The axis may move: it is free within its travel window, and I can stop it "
                                 "(emergency stop at hand)."),
                              this);
    m_confirm->setObjectName("atConfirm");
    lay->addWidget(m_confirm);
    lay->addStretch(1);
    auto* earlier = new QHBoxLayout;
    m_undoEarlier = new QPushButton(tr("Undo an earlier run…"), this);
    m_undoEarlier->setObjectName("atUndoEarlier");
    m_undoEarlier->setToolTip(tr("Puts back the parameters an earlier applied run of this wizard changed, from its "
                                 "saved session (a run of axistune-cli autotune: its --undo RESULT.json)"));
    earlier->addWidget(m_undoEarlier);
    earlier->addStretch(1);
    lay->addLayout(earlier);
    connect(m_undoEarlier, &QPushButton::clicked, this, &AutoTuneChoicePage::chooseEarlierRun);
    connect(m_confirm, &QCheckBox::toggled, this, &QWizardPage::completeChanged);
    connect(m_axis, &QComboBox::currentTextChanged, this, &AutoTuneChoicePage::queryTravel);
    connect(m_budget, &QDoubleSpinBox::valueChanged, this, [this] {
        m_budgetEdited = true;
        updateChoices();
    });
    connect(m_positions, &QSpinBox::valueChanged, this, [this](int n) {
        if (!m_budgetEdited) { // the default budget follows the positions (30 s each, as the CLI's)
            const QSignalBlocker block(m_budget);
            m_budget->setValue(autotune::defaultTimeBudgetS(n));
        }
        updateChoices();
    });
    connect(m_amplitudes, &QLineEdit::textChanged, this, &AutoTuneChoicePage::updateChoices);
    connect(m_minBandwidth, &QDoubleSpinBox::valueChanged, this, &AutoTuneChoicePage::updateChoices);
    {
        const QSignalBlocker block(m_budget);
        m_budget->setValue(autotune::defaultTimeBudgetS(1));
    }
    setCommitPage(true);
    setButtonText(QWizard::CommitButton, tr("Start"));
}

QRadioButton* AutoTuneChoicePage::styleButton(autotune::Style s) const
{
    return s == autotune::Style::Gentle ? m_gentle : s == autotune::Style::Stiff ? m_stiff : m_standard;
}

void AutoTuneChoicePage::initializePage()
{
    m_d.stored.reset();
    m_undoEarlier->setEnabled(m_ctx.drive().isConnected() && m_ctx.database());
    const QString keep = m_axis->currentText();
    {
        const QSignalBlocker block(m_axis);
        m_axis->clear();
        m_axis->addItems(m_ctx.axes());
        if (m_ctx.axes().contains(keep))
            m_axis->setCurrentText(keep);
    }
    queryTravel();
}

void AutoTuneChoicePage::queryTravel()
{
    // Whether the axis can be tuned over its travel: asked of the drive on its thread (nothing moves).
    m_travelKnown = false;
    m_travelPossible = false;
    m_positions->setEnabled(false);
    const QString axis = m_axis->currentText();
    const int query = ++m_travelQuery;
    if (axis.isEmpty() || !m_ctx.drive().isConnected()) {
        m_travelNote->setText(QString());
        updateChoices();
        return;
    }
    m_travelNote->setText(tr("Asking the drive for the travel window…"));
    auto* req = m_ctx.drive().autoTuneTravel(axis);
    connect(req, &DriveRequest::finished, this, [this, query](const DriveReply& r) {
        if (query != m_travelQuery)
            return; // an answer for an axis no longer chosen
        m_travelKnown = true;
        if (!r.ok || !r.travel) {
            m_travelNote->setText(tr("Over the travel not available: %1").arg(r.error));
        } else if (!r.travel->refusal.empty()) {
            m_travelNote->setText(tr("Over the travel not available: %1").arg(qs(r.travel->refusal)));
        } else {
            m_travelPossible = true;
            const QString w = QString::number(r.travel->window, 'g', 4);
            const QString unit = r.travel->units.empty() ? tr("m or rad") : qs(r.travel->units);
            const double inset = r.travel->inset;
            if (std::isfinite(inset) && inset > 0.0 && inset < r.travel->window)
                m_travelNote->setText(
                    tr("Travel window −%1 … +%1 %2: the positions are spread evenly from −%3 to +%3 %2, inside "
                       "its ends by the servo lag of the moves between them (%4 %2: jog speed / position gain); the "
                       "axis returns to where it stood.")
                        .arg(w, unit, QString::number(r.travel->window - inset, 'g', 4),
                             QString::number(inset, 'g', 3)));
            else
                m_travelNote->setText(tr("Travel window −%1 … +%1 %2: the positions are spread evenly from one end "
                                         "to the other; the axis returns to where it stood.")
                                          .arg(w, unit));
        }
        m_positions->setEnabled(m_travelPossible);
        if (!m_travelPossible && m_positions->value() > 1)
            m_positions->setValue(1);
        updateChoices();
    });
    updateChoices();
}

autotune::Options AutoTuneChoicePage::collect(QString* why) const
{
    autotune::Options o;
    o.axis = m_axis->currentText().toStdString();
    o.style = m_gentle->isChecked()  ? autotune::Style::Gentle
              : m_stiff->isChecked() ? autotune::Style::Stiff
                                     : autotune::Style::Standard;
    o.timeBudgetS = m_budget->value();
    o.dryRun = m_dryRun->isChecked();
    o.minBandwidthHz = m_minBandwidth->value();
    o.positions = m_positions->value();
    QString reason;
    if (auto a = autotune::parseAmplitudeList(m_amplitudes->text().toStdString()); !a)
        reason = qs(a.error().detail);
    else
        o.amplitudeMapPct = *a;
    if (reason.isEmpty())
        if (auto st = autotune::checkChoices(o); !st)
            reason = qs(st.error().detail);
    if (reason.isEmpty() && o.positions > 1 && !m_travelPossible)
        reason = m_travelNote->text();
    if (why)
        *why = reason;
    return o;
}

void AutoTuneChoicePage::updateChoices()
{
    QString why;
    collect(&why);
    m_choiceError->setText(why.isEmpty() ? QString() : tr("Cannot start: %1").arg(why));
    emit completeChanged();
}

bool AutoTuneChoicePage::isComplete() const
{
    QString why;
    collect(&why);
    return m_ctx.drive().isConnected() && !m_axis->currentText().isEmpty() && m_confirm->isChecked() && why.isEmpty();
}

bool AutoTuneChoicePage::validatePage()
{
    if (m_d.stored)
        return true; // an earlier run to undo: nothing runs
    QString why;
    m_d.options = collect(&why);
    return why.isEmpty();
}

// ---------------------------------------------------------------------------------------------------------------
// Run

AutoTuneRunPage::AutoTuneRunPage(AppContext& ctx, AutoTuneData& shared, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared)
{
    setTitle(tr("Running the sequence"));
    setSubTitle(tr("Abort stops the motion at once; every parameter the run wrote is restored and read back."));
    auto* lay = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    m_steps = new QTableWidget(0, 2, this);
    m_steps->setObjectName("atSteps");
    m_steps->setHorizontalHeaderLabels({tr("Step"), tr("State")});
    m_steps->verticalHeader()->hide();
    m_steps->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_steps->horizontalHeader()->setStretchLastSection(true);
    m_steps->setSelectionMode(QAbstractItemView::NoSelection);
    for (const auto& n : autotune::stepNames()) {
        const int row = m_steps->rowCount();
        m_steps->insertRow(row);
        m_steps->setItem(row, 0, item(autoTuneStepTitle(qs(n))));
        m_steps->setItem(row, 1, item(QString()));
    }
    m_steps->setMinimumWidth(330);
    top->addWidget(m_steps, 0);
    m_log = new QPlainTextEdit(this);
    m_log->setObjectName("atLog");
    m_log->setReadOnly(true);
    m_log->setPlaceholderText(tr("What each finished step measured, what it chose and the rule."));
    top->addWidget(m_log, 1);
    lay->addLayout(top, 1);
    auto* bottom = new QHBoxLayout;
    m_progress = new QProgressBar(this);
    m_progress->setObjectName("atProgress");
    m_progress->setRange(0, 1000);
    m_progress->setFormat(QStringLiteral("%p %"));
    bottom->addWidget(m_progress, 1);
    m_abort = new QPushButton(tr("Abort"), this);
    m_abort->setObjectName("atAbort");
    m_abort->setIcon(style()->standardIcon(QStyle::SP_BrowserStop));
    bottom->addWidget(m_abort);
    lay->addLayout(bottom);
    m_state = new QLabel(this);
    m_state->setObjectName("atState");
    m_state->setWordWrap(true);
    lay->addWidget(m_state);
    connect(m_abort, &QPushButton::clicked, this, &AutoTuneRunPage::abort);
    // No way back into a finished run: Back and Next would start the sequence again.
    setCommitPage(true);
    setButtonText(QWizard::CommitButton, tr("Result >"));
}

void AutoTuneRunPage::initializePage()
{
    start();
}

void AutoTuneRunPage::cleanupPage()
{
    abort();
}

bool AutoTuneRunPage::isComplete() const
{
    return !m_d.running && (m_d.result || !m_d.error.isEmpty());
}

void AutoTuneRunPage::setRowState(int row, const QString& state, int icon)
{
    if (row < 0 || row >= m_steps->rowCount())
        return;
    m_steps->item(row, 1)->setText(state);
    m_steps->item(row, 0)->setIcon(icon < 0 ? QIcon() : style()->standardIcon(QStyle::StandardPixmap(icon)));
}

void AutoTuneRunPage::start()
{
    m_d.result.reset();
    m_d.error.clear();
    m_d.abortPressed = false;
    m_d.sessionId = 0;
    m_log->clear();
    m_progress->setValue(0);
    m_runningRow = -1;
    for (int r = 0; r < m_steps->rowCount(); ++r)
        setRowState(r, tr("waiting"), -1);
    m_state->setStyleSheet(QString());
    m_state->setText(
        tr("Axis %1, style %2, time budget %3 s%4.")
            .arg(qs(m_d.options.axis), m_d.options.style == autotune::Style::Gentle ? AutoTuneChoicePage::tr("Gentle")
                                       : m_d.options.style == autotune::Style::Stiff
                                           ? AutoTuneChoicePage::tr("Stiff")
                                           : AutoTuneChoicePage::tr("Standard"))
            .arg(m_d.options.timeBudgetS, 0, 'f', 1)
            .arg(m_d.options.dryRun ? tr(", dry run") : QString()) +
        (m_d.options.positions > 1 ? tr(" Over the travel: %1 positions.").arg(m_d.options.positions) : QString()) +
        (m_d.options.amplitudeMapPct.empty()
             ? QString()
             : tr(" Amplitude map at %1 % of rated torque.").arg(amplitudeListText(m_d.options))));
    m_d.running = true;
    m_abort->setEnabled(true);
    m_request = m_ctx.drive().runAutoTune(m_d.options);
    connect(m_request, &DriveRequest::progress, this,
            [this](double f, const QString&) { m_progress->setValue(int(std::lround(1000.0 * f))); });
    connect(m_request, &DriveRequest::stepStarted, this, &AutoTuneRunPage::onStepStarted);
    connect(m_request, &DriveRequest::stepFinished, this, &AutoTuneRunPage::onStepFinished);
    connectReply(m_request.data(), this, &AutoTuneRunPage::onReply);
    m_ctx.log(tr("Automatic tuning of axis %1 started").arg(qs(m_d.options.axis)));
    emit completeChanged();
}

void AutoTuneRunPage::abort()
{
    if (!m_d.running || !m_request)
        return;
    m_d.abortPressed = true;
    m_request->abort();
    m_abort->setEnabled(false);
    m_state->setText(tr("Aborting: stopping the motion and restoring every parameter…"));
}

void AutoTuneRunPage::onStepStarted(const QString& name)
{
    const auto& names = autotune::stepNames();
    const int row = int(std::find(names.begin(), names.end(), name.toStdString()) - names.begin());
    m_runningRow = row;
    // A second design attempt runs steps 5 to 8 again: the later ones wait again.
    for (int r = row + 1; r < m_steps->rowCount(); ++r)
        if (!m_steps->item(r, 1)->text().isEmpty())
            setRowState(r, tr("waiting"), -1);
    setRowState(row, tr("running…"), QStyle::SP_MediaPlay);
}

void AutoTuneRunPage::onStepFinished(const QString& name, const QString& json)
{
    const auto& names = autotune::stepNames();
    const int row = int(std::find(names.begin(), names.end(), name.toStdString()) - names.begin());
    setRowState(row, tr("done"), QStyle::SP_DialogApplyButton);
    const auto j = nlohmann::json::parse(json.toStdString(), nullptr, false);
    if (j.is_discarded())
        return;
    QString text = autoTuneStepTitle(name);
    const double motion = j.value("motion_time_s", 0.0);
    if (motion > 0.0)
        text += tr(" (%1 s of motion)").arg(motion, 0, 'f', 2);
    text += "\n  " + tr("Measured: %1").arg(objectText(j["measured"]));
    text += "\n  " + tr("Chosen: %1").arg(objectText(j["chosen"]));
    text += "\n  " + tr("Rule: %1").arg(qs(j.value("rule", std::string()))) + "\n";
    m_log->appendPlainText(text);
}

void AutoTuneRunPage::onReply(const DriveReply& reply)
{
    m_d.running = false;
    m_abort->setEnabled(false);
    if (!reply.ok || !reply.autotune) {
        m_d.error = reply.error.isEmpty() ? tr("no answer from the drive") : reply.error;
        m_state->setStyleSheet(QStringLiteral("color: #b00020;"));
        m_state->setText(tr("The run could not start: %1. Nothing was changed.").arg(m_d.error));
    } else {
        m_d.result = reply.autotune;
        const auto& r = *m_d.result;
        if (r.outcome == autotune::Outcome::Refused) {
            setRowState(m_runningRow, wasAborted(r) ? tr("aborted") : tr("refused"), QStyle::SP_MessageBoxCritical);
            m_state->setStyleSheet(QStringLiteral("color: #b00020;"));
            const QString restored = r.restored ? tr("every parameter restored and read back equal")
                                                : tr("RESTORING THE PARAMETERS FAILED: check the drive");
            m_state->setText(
                (wasAborted(r) ? tr("Aborted (%1): %2.") : tr("Refused (%1): %2.")).arg(restored, qs(r.reason)));
        } else {
            m_progress->setValue(1000);
            m_state->setText(r.outcome == autotune::Outcome::DryRun
                                 ? tr("Finished (dry run): every parameter restored; see the result.")
                                 : tr("Finished: the parameters are applied; see the result."));
        }
    }
    m_ctx.log(m_state->text());
    saveSession();
    emit completeChanged();
    emit runFinished();
}

void AutoTuneRunPage::saveSession()
{
    store::SessionRecord rec;
    rec.info.kind = "autotune";
    rec.info.axis = m_d.options.axis;
    rec.inputs = {{"connection", m_ctx.drive().uri().toStdString()},
                  {"axis", m_d.options.axis},
                  {"style", autotune::styleName(m_d.options.style)},
                  {"time_budget_s", m_d.options.timeBudgetS},
                  {"dry_run", m_d.options.dryRun},
                  {"positions", m_d.options.positions},
                  {"amplitudes_pct", m_d.options.amplitudeMapPct},
                  {"min_bandwidth_Hz", m_d.options.minBandwidthHz}};
    if (!m_d.result) {
        rec.info.status = store::SessionStatus::Failed;
        rec.info.note = m_d.error.toStdString();
        rec.results.push_back({"error", {{"message", m_d.error.toStdString()}}, {}});
    } else {
        const auto& r = *m_d.result;
        rec.info.status = r.outcome != autotune::Outcome::Refused ? store::SessionStatus::Completed
                          : wasAborted(r)                         ? store::SessionStatus::Aborted
                                                                  : store::SessionStatus::Failed;
        rec.info.note = r.reason;
        auto j = autotune::resultJson(r, m_d.options);
        j["connection"] = rec.inputs["connection"];
        rec.results.push_back({"autotune", j, {}});
        rec.parameterSets.push_back({0,
                                     r.before.empty() ? std::string() : m_d.options.axis,
                                     store::ParameterSource::Read,
                                     {},
                                     "autotune wizard: before",
                                     r.before});
        if (r.outcome == autotune::Outcome::Applied && r.final) {
            rec.parameterSets.push_back(
                {0, m_d.options.axis, store::ParameterSource::Applied, {}, "autotune wizard", r.final->parameters});
            for (const auto& [k, v] : r.final->parameters) {
                store::JournalEntry e;
                e.axis = m_d.options.axis;
                e.key = k;
                if (const auto it = r.before.find(k); it != r.before.end())
                    e.oldValue = it->second;
                e.newValue = v;
                rec.journal.push_back(e);
            }
        }
    }
    if (!m_ctx.database())
        return;
    QPointer<AutoTuneRunPage> self(this);
    m_ctx.saveSessionAsync(std::move(rec), this, [self](Result<std::int64_t> id) {
        if (self && id)
            self->m_d.sessionId = *id;
    });
}

// ---------------------------------------------------------------------------------------------------------------
// Wizard

AutoTuneWizard::AutoTuneWizard(AppContext& ctx, QWidget* parent) : QWizard(parent)
{
    setWindowTitle(tr("Automatic tuning"));
    setObjectName("autoTuneWizard");
    setWizardStyle(QWizard::ClassicStyle);
    m_choice = new AutoTuneChoicePage(ctx, m_data, this);
    m_run = new AutoTuneRunPage(ctx, m_data, this);
    m_result = new AutoTuneResultPage(ctx, m_data, this);
    setPage(Choice, m_choice);
    setPage(Run, m_run);
    setPage(Result, m_result);
    connect(m_run, &AutoTuneRunPage::runFinished, this, [this] {
        if (m_closeWhenDone)
            QWizard::reject();
    });
    connect(m_result, &AutoTuneResultPage::undoFinished, this, [this] {
        if (m_closeWhenDone)
            QWizard::reject();
    });
    resize(1000, 700);
}

void AutoTuneWizard::reject()
{
    if (m_data.running) {
        m_closeWhenDone = true;
        m_run->abort();
        return;
    }
    if (m_result->isUndoing()) { // the undo's answer (and its journal) first; the write itself is not interrupted
        m_closeWhenDone = true;
        return;
    }
    QWizard::reject();
}

} // namespace gui
} // namespace axistune

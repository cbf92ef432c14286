// SPDX-License-Identifier: GPL-3.0-or-later
// The one-button tuning wizard (AutoTuneWizard.h; docs/tuning.md "The wizard"): choices, the run with its steps,
// the result; the session of kind "autotune".
#include "app/gui/AutoTuneWizard.h"

#include "app/gui/AppContext.h"
#include "app/gui/WizardRegistry.h"
#include "core/autotune/TravelChoice.h"
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

namespace {

const WizardRegistrar kRegistrar{
    "autotune", QT_TRANSLATE_NOOP("Wizards", "Automatic tuning (one button)…"), 5,
    [](AppContext& ctx, QWidget* parent) -> QWizard* { return new AutoTuneWizard(ctx, parent); }};

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

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

bool wasAborted(const autotune::AutoTuneResult& r)
{
    return r.outcome == autotune::Outcome::Refused && r.reasonCode == ErrorCode::Aborted;
}

QTableWidgetItem* item(const QString& text)
{
    auto* it = new QTableWidgetItem(text);
    it->setFlags(it->flags() & ~Qt::ItemIsEditable);
    return it;
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
            m_travelNote->setText(tr("Travel window −%1 … +%1 %2: the positions are spread evenly from one end to the "
                                     "other; the axis returns to where it stood.")
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
// Result

AutoTuneResultPage::AutoTuneResultPage(AutoTuneData& shared, QWidget* parent) : QWizardPage(parent), m_d(shared)
{
    setTitle(tr("Result"));
    auto* lay = new QVBoxLayout(this);
    m_outcome = new QLabel(this);
    m_outcome->setObjectName("atOutcome");
    m_outcome->setWordWrap(true);
    m_outcome->setTextInteractionFlags(Qt::TextSelectableByMouse);
    lay->addWidget(m_outcome);
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName("atResultTabs");

    auto* figuresTab = new QWidget(m_tabs);
    auto* fl = new QVBoxLayout(figuresTab);
    m_figures = new QTableWidget(0, 2, figuresTab);
    m_figures->setObjectName("atFigures");
    m_figures->setHorizontalHeaderLabels({tr("Figure"), tr("Value")});
    m_figures->verticalHeader()->hide();
    m_figures->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_figures->horizontalHeader()->setStretchLastSection(true);
    fl->addWidget(m_figures, 1);
    m_parametersTitle = new QLabel(figuresTab);
    fl->addWidget(m_parametersTitle);
    m_parameters = new QTableWidget(0, 3, figuresTab);
    m_parameters->setObjectName("atParameters");
    m_parameters->setHorizontalHeaderLabels({tr("Parameter"), tr("Before"), tr("After")});
    m_parameters->verticalHeader()->hide();
    m_parameters->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_parameters->horizontalHeader()->setStretchLastSection(true);
    fl->addWidget(m_parameters, 1);
    m_tabs->addTab(figuresTab, tr("Figures and parameters"));

    auto* resTab = new QWidget(m_tabs);
    auto* rl = new QVBoxLayout(resTab);
    m_resonancePlot = new widgets::CurvePlot(resTab);
    m_resonancePlot->setObjectName("atResonanceMap");
    m_resonancePlot->setMinimumHeight(260);
    rl->addWidget(m_resonancePlot, 3);
    m_positionsTable = new QTableWidget(0, 9, resTab);
    m_positionsTable->setObjectName("atPositionsTable");
    m_positionsTable->verticalHeader()->hide();
    m_positionsTable->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_positionsTable->horizontalHeader()->setStretchLastSection(true);
    rl->addWidget(m_positionsTable, 2);
    m_tabs->addTab(resTab, tr("Resonance map over the travel"));

    auto* ampTab = new QWidget(m_tabs);
    auto* al = new QVBoxLayout(ampTab);
    m_ampSummary = new QLabel(ampTab);
    m_ampSummary->setObjectName("atAmplitudeSummary");
    m_ampSummary->setWordWrap(true);
    al->addWidget(m_ampSummary);
    auto* plots = new QHBoxLayout;
    m_ampMap = new widgets::CurvePlot(ampTab);
    m_ampMap->setObjectName("atAmplitudeMap");
    plots->addWidget(m_ampMap, 1);
    m_ampMagnitude = new widgets::CurvePlot(ampTab);
    m_ampMagnitude->setObjectName("atAmplitudeMagnitude");
    plots->addWidget(m_ampMagnitude, 1);
    al->addLayout(plots, 1);
    m_tabs->addTab(ampTab, tr("Amplitude map"));
    lay->addWidget(m_tabs, 1);

    m_session = new QLabel(this);
    m_session->setObjectName("atSession");
    lay->addWidget(m_session);
    lay->addStretch(0); // takes the room of the hidden tables after a refusal
    setFinalPage(true);
}

void AutoTuneResultPage::showResonanceMap(const nlohmann::json& j, bool linear)
{
    // From the result JSON (resultJson: resonance_map[] and final.positions[]), as the CLI writes it.
    const QString unit = linear ? QStringLiteral("m") : QStringLiteral("rad");
    m_resonancePlot->clear();
    m_resonancePlot->setAxes(tr("Position"), unit, tr("First resonance"), tr("Hz"));
    std::vector<double> x, f;
    for (const auto& m : j["resonance_map"]) {
        const double pos = m.value("position", std::numeric_limits<double>::quiet_NaN());
        if (!m.contains("frequency_Hz") || !m["frequency_Hz"].is_number())
            continue;
        x.push_back(pos);
        f.push_back(m["frequency_Hz"].get<double>());
    }
    m_resonancePlot->addCurve(tr("first resonance (labels: frequency, height above the baseline)"), x, f,
                              QColor(0, 90, 181));
    std::size_t k = 0;
    for (const auto& m : j["resonance_map"]) {
        if (!m.contains("frequency_Hz") || !m["frequency_Hz"].is_number())
            continue;
        const double h =
            m.contains("height_dB") && m["height_dB"].is_number() ? m["height_dB"].get<double>() : std::nan("");
        m_resonancePlot->addPoint(x[k], f[k], tr("%1 Hz, %2 dB").arg(f[k], 0, 'f', 1).arg(h, 0, 'f', 1));
        ++k;
    }
    m_resonancePlot->rescale();
    // Room for the labels right of and above the points.
    if (!x.empty()) {
        const auto [x0, x1] = std::minmax_element(x.begin(), x.end());
        const auto [f0, f1] = std::minmax_element(f.begin(), f.end());
        const double dx = std::max(*x1 - *x0, 1e-3 * std::max(1.0, std::abs(*x0)));
        const double df = std::max(*f1 - *f0, 0.05 * *f1);
        m_resonancePlot->setXRange(*x0 - 0.08 * dx, *x1 + 0.25 * dx);
        m_resonancePlot->setYRange(*f0 - 0.15 * df, *f1 + 0.2 * df);
    }

    m_positionsTable->setRowCount(0);
    m_positionsTable->setHorizontalHeaderLabels({tr("Position\n[%1]").arg(unit), tr("First resonance\n[Hz]"),
                                                 tr("Height\n[dB]"), tr("Phase margin\n[°]"), tr("Gain margin\n[dB]"),
                                                 tr("Velocity bandwidth\n[Hz]"), tr("Position bandwidth\n[Hz]"),
                                                 tr("Predicted phase\nmargin [°]"), tr("Predicted gain\nmargin [dB]")});
    const auto& map = j["resonance_map"];
    const nlohmann::json none = nlohmann::json::array();
    const auto& per = j.contains("final") && j["final"].contains("positions") ? j["final"]["positions"] : none;
    auto num = [](const nlohmann::json& o, const char* key, int decimals) {
        return o.contains(key) && o[key].is_number() ? QString::number(o[key].get<double>(), 'f', decimals)
                                                     : QStringLiteral("–");
    };
    for (std::size_t i = 0; i < map.size(); ++i) {
        const auto& m = map[i];
        const int row = m_positionsTable->rowCount();
        m_positionsTable->insertRow(row);
        m_positionsTable->setItem(row, 0, item(num(m, "position", 4)));
        const bool has = m.contains("frequency_Hz") && m["frequency_Hz"].is_number();
        m_positionsTable->setItem(row, 1, item(has ? num(m, "frequency_Hz", 1) : tr("none in the band")));
        m_positionsTable->setItem(row, 2, item(has ? num(m, "height_dB", 1) : QStringLiteral("–")));
        const nlohmann::json p = i < per.size() ? per[i] : nlohmann::json::object();
        m_positionsTable->setItem(row, 3, item(num(p, "phase_margin_deg", 1)));
        m_positionsTable->setItem(row, 4, item(num(p, "gain_margin_dB", 1)));
        m_positionsTable->setItem(row, 5, item(num(p, "velocity_bandwidth_Hz", 1)));
        m_positionsTable->setItem(row, 6, item(num(p, "position_bandwidth_Hz", 1)));
        m_positionsTable->setItem(row, 7, item(num(p, "predicted_phase_margin_deg", 1)));
        m_positionsTable->setItem(row, 8, item(num(p, "predicted_gain_margin_dB", 1)));
    }
}

void AutoTuneResultPage::showAmplitudeMap(const nlohmann::json& map)
{
    // From the frf step's measured.amplitude_map (autotune::inUseJson): every line at every amplitude it was
    // measured at, coloured by the core's verdict.
    m_ampMap->clear();
    m_ampMagnitude->clear();
    m_ampMap->setAxes(tr("Frequency"), tr("Hz"), tr("Multisine peak"), tr("% of rated torque"), true, true);
    m_ampMagnitude->setAxes(tr("Frequency"), tr("Hz"), tr("Closed velocity loop |T|"), tr("dB"), true, false);
    std::vector<double> fl, al, fn, an, fo, ao, fnMag, nMag;
    std::map<double, std::pair<std::vector<double>, std::vector<double>>> perAmplitude;
    double fmin = std::numeric_limits<double>::infinity(), fmax = 0.0;
    for (const auto& line : map.value("lines", nlohmann::json::array())) {
        const double f = line.value("f_Hz", std::nan(""));
        const bool nonlinear = line.value("nonlinear", false);
        const bool compared = line.value("compared", false);
        double top = -std::numeric_limits<double>::infinity();
        for (const auto& at : line.value("at", nlohmann::json::array())) {
            const double a = at.value("amplitude_pct", std::nan(""));
            const double db = at.value("magnitude_dB", std::nan(""));
            (nonlinear ? fn : compared ? fl : fo).push_back(f);
            (nonlinear ? an : compared ? al : ao).push_back(a);
            perAmplitude[a].first.push_back(f);
            perAmplitude[a].second.push_back(db);
            top = std::max(top, db);
        }
        if (nonlinear && std::isfinite(top)) {
            fnMag.push_back(f);
            nMag.push_back(top);
        }
        if (std::isfinite(f)) {
            fmin = std::min(fmin, f);
            fmax = std::max(fmax, f);
        }
    }
    if (map.contains("design_amplitude_pct") && map["design_amplitude_pct"].is_number() && fmax > fmin) {
        const double a = map["design_amplitude_pct"].get<double>();
        m_ampMap->addCurve(tr("designed from %1 %").arg(a, 0, 'g', 4), {fmin, fmax}, {a, a}, QColor(40, 140, 40),
                           Qt::DashLine);
    }
    // The few linear lines over the many non-linear ones (vmc X: 14 of 388), so that they show.
    m_ampMap->addCurve(tr("non-linear"), fn, an, QColor(200, 0, 30), Qt::SolidLine, true);
    m_ampMap->addCurve(tr("linear"), fl, al, QColor(0, 90, 181), Qt::SolidLine, true);
    m_ampMap->addCurve(tr("not compared"), fo, ao, QColor(170, 170, 170), Qt::SolidLine, true);
    m_ampMap->rescale();
    if (!perAmplitude.empty()) // the amplitudes' rows with room above and below (log axis)
        m_ampMap->setYRange(perAmplitude.begin()->first / 1.4, perAmplitude.rbegin()->first * 1.4);
    for (const auto& [a, fx] : perAmplitude)
        m_ampMagnitude->addCurve(tr("%1 % of rated torque").arg(a, 0, 'g', 4), fx.first, fx.second);
    m_ampMagnitude->addCurve(tr("non-linear lines"), fnMag, nMag, QColor(200, 0, 30), Qt::SolidLine, true);
    m_ampMagnitude->rescale();
    const auto count = [&](const char* key) {
        return map.contains(key) && map[key].is_number() ? QString::number(map[key].get<double>(), 'g', 6)
                                                         : QStringLiteral("–");
    };
    m_ampSummary->setText(
        tr("%1 of %2 compared lines non-linear (a line is non-linear when two amplitudes differ by more than %3 "
           "combined standard errors). Peak torque of the move with the running gains: %4 % of rated torque; "
           "designed from the amplitude %5 % of rated torque.")
            .arg(count("nonlinear_lines"), count("lines_compared"), count("threshold_sigmas"),
                 map.contains("use_torque_pct") && map["use_torque_pct"].is_number()
                     ? QString::number(map["use_torque_pct"].get<double>(), 'f', 1)
                     : QStringLiteral("–"),
                 count("design_amplitude_pct")));
}

void AutoTuneResultPage::initializePage()
{
    m_figures->setRowCount(0);
    m_parameters->setRowCount(0);
    const auto* r = m_d.result.get();
    const bool refused = !r || r->outcome == autotune::Outcome::Refused || !r->final;
    m_figures->setVisible(!refused);
    m_parameters->setVisible(!refused);
    m_parametersTitle->setVisible(!refused);
    // The maps, also after a refusal when the run measured them (what the frf step found).
    static const std::vector<autotune::Step> kNoSteps;
    const auto& steps = r ? r->steps : kNoSteps;
    bool linear = true;
    for (const auto& st : steps)
        if (st.name == "safety-envelope") {
            const auto& from = st.chosen.contains("axis_units") ? st.chosen : st.measured;
            linear = from.value("axis_units", std::string("m")) == "m";
        }
    nlohmann::json j = r ? autotune::resultJson(*r, m_d.options) : nlohmann::json::object();
    const bool hasMap = j.contains("resonance_map") && !j["resonance_map"].empty();
    const nlohmann::json* amp = nullptr;
    for (const auto& st : steps)
        if (st.name == "frf" && st.measured.contains("amplitude_map"))
            amp = &st.measured["amplitude_map"];
    if (hasMap)
        showResonanceMap(j, linear);
    if (amp)
        showAmplitudeMap(*amp);
    m_tabs->setTabVisible(FiguresTab, !refused);
    m_tabs->setTabVisible(ResonanceTab, hasMap);
    m_tabs->setTabVisible(AmplitudeTab, amp != nullptr);
    m_tabs->setVisible(!refused || hasMap || amp);
    m_tabs->setCurrentIndex(!refused ? FiguresTab : hasMap ? ResonanceTab : AmplitudeTab);
    if (auto* box = qobject_cast<QBoxLayout*>(layout()))
        box->setStretch(box->count() - 1, m_tabs->isVisibleTo(this) ? 0 : 1);
    m_session->setText(m_d.sessionId > 0 ? tr("Saved as session %1.").arg(m_d.sessionId)
                                         : tr("The session is saved to the store when one is open."));
    if (refused) {
        m_outcome->setStyleSheet(QStringLiteral("color: #b00020;"));
        if (!r)
            m_outcome->setText(tr("The run could not start: %1.\nNothing was changed.").arg(m_d.error));
        else if (!r->restored)
            m_outcome->setText(tr("%1: %2\nRESTORING THE PARAMETERS FAILED: check the drive's parameters.")
                                   .arg(wasAborted(*r) ? tr("Aborted") : tr("Refused"), qs(r->reason)));
        else
            m_outcome->setText(tr("%1: %2\nNothing was changed: every parameter was restored and read back equal.")
                                   .arg(wasAborted(*r) ? tr("Aborted") : tr("Refused"), qs(r->reason)));
        return;
    }
    m_outcome->setStyleSheet(QString());
    const auto& f = *r->final;
    m_outcome->setText((r->outcome == autotune::Outcome::DryRun
                            ? tr("Dry run finished: every parameter was restored; the values below were not applied.")
                            : tr("Applied: the parameters below are written and read back equal.")) +
                       (f.positions.empty()
                            ? QString()
                            : QStringLiteral("\n") + tr("Over %1 positions: the figures are the worst position's; "
                                                        "every position is in the resonance map's table.")
                                                         .arg(f.positions.size())));
    auto add = [&](const QString& name, const QString& value, const char* objectName) {
        const int row = m_figures->rowCount();
        m_figures->insertRow(row);
        m_figures->setItem(row, 0, item(name));
        auto* v = item(value);
        v->setData(Qt::UserRole, QString::fromLatin1(objectName));
        m_figures->setItem(row, 1, v);
    };
    add(tr("Phase margin (re-measured)"), tr("%1°").arg(f.phaseMarginDeg, 0, 'f', 1), "phase_margin_deg");
    add(tr("Gain margin (re-measured)"), tr("%1 dB").arg(f.gainMarginDb, 0, 'f', 1), "gain_margin_dB");
    add(tr("Velocity bandwidth (−3 dB)"), tr("%1 Hz").arg(f.velocityBandwidthHz, 0, 'f', 1), "velocity_bandwidth_Hz");
    add(tr("Position bandwidth (−3 dB)"), tr("%1 Hz").arg(f.positionBandwidthHz, 0, 'f', 1), "position_bandwidth_Hz");
    add(tr("Settling time of the move"),
        f.settlingTimeS ? tr("%1 ms").arg(1e3 * *f.settlingTimeS, 0, 'f', 1) : tr("not settled within the record"),
        "settling_time_s");
    add(tr("Peak following error"),
        linear ? tr("%1 µm").arg(1e6 * f.peakFollowingError, 0, 'f', 2)
               : tr("%1 mrad").arg(1e3 * f.peakFollowingError, 0, 'f', 3),
        "peak_following_error");
    add(tr("Motion time of the sequence"), tr("%1 s").arg(f.motionTimeS, 0, 'f', 2), "motion_time_s");
    m_parametersTitle->setText(r->outcome == autotune::Outcome::DryRun ? tr("Parameters it would apply (not applied):")
                                                                       : tr("Parameters applied (old → new):"));
    for (const auto& [k, v] : f.parameters) {
        const int row = m_parameters->rowCount();
        m_parameters->insertRow(row);
        m_parameters->setItem(row, 0, item(qs(k)));
        const auto it = r->before.find(k);
        m_parameters->setItem(row, 1,
                              item(it == r->before.end() ? QStringLiteral("–") : QString::number(it->second, 'g', 6)));
        m_parameters->setItem(row, 2, item(QString::number(v, 'g', 6)));
    }
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
    m_result = new AutoTuneResultPage(m_data, this);
    setPage(Choice, m_choice);
    setPage(Run, m_run);
    setPage(Result, m_result);
    connect(m_run, &AutoTuneRunPage::runFinished, this, [this] {
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
    QWizard::reject();
}

} // namespace gui
} // namespace axistune

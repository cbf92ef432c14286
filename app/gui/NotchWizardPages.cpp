// SPDX-License-Identifier: GPL-3.0-or-later
// Pages of the notch wizard: source, propose (resonances, editable notches with their rules,
// prediction and margins), verify (measurement against prediction) and save. docs/wizards/notch.md.
#include "app/gui/AppContext.h"
#include "app/gui/NcPidPage.h"
#include "app/gui/NotchWizard.h"
#include "core/model/MetadataKeys.h"
#include "core/store/FrfCapture.h"
#include "core/store/SessionRecord.h"
#include "widgets/BodePlot.h"

#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QTextBrowser>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>

namespace axistune {
namespace gui {

namespace {
/// Why the drive-slot proposal does not apply to a position PID the NC closes, and where Next goes instead.
QString ncPidNotchRefusal(const QString& axis, const QString& uri, const QString& output)
{
    return QCoreApplication::translate(
               "axistune::gui::NotchProposePage",
               "Axis %1 is a position loop the NC closes with a PID (%2): it has no drive filter slots for this "
               "proposal. Next measures its open loop with the gains that run and proposes LinuxCNC's biquad notch "
               "after the PID output (net %3).")
        .arg(axis, uri, output);
}
} // namespace

namespace {

QString num(double v, int prec = 1) { return std::isfinite(v) ? QString::number(v, 'f', prec) : QString::fromUtf8("—"); }

QTableWidget* table(QWidget* parent, const QStringList& headers, const QString& name)
{
    auto* t = new QTableWidget(parent);
    t->setObjectName(name);
    t->setColumnCount(static_cast<int>(headers.size()));
    t->setHorizontalHeaderLabels(headers);
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    t->horizontalHeader()->setStretchLastSection(true);
    t->verticalHeader()->hide();
    t->verticalHeader()->setDefaultSectionSize(22);
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->setWordWrap(false);
    return t;
}

QTableWidgetItem* item(const QString& text, bool editable = false)
{
    auto* it = new QTableWidgetItem(text);
    if (!editable)
        it->setFlags(it->flags() & ~Qt::ItemIsEditable);
    return it;
}

QString ruleText(const tuning::ProposedNotch& n, const tuning::Resonance& r, const tuning::NotchOptions& o)
{
    const double fN = 0.5 * o.execRateHz;
    return QCoreApplication::translate(
               "NotchProposePage",
               "Slot %1 at %2 Hz: resonance %3 dB above its baseline, −3 dB width %4 Hz, open-loop gain %5 dB. "
               "Depth %6 = the smaller of %7 (peak back to its baseline) and %8 (open-loop gain down to %9 dB). "
               "Digital −3 dB width %10 Hz = resonance width / depth (the notch zeros on the mode's poles), "
               "kept between %4 Hz and %11 Hz; drive width parameter %12 Hz (pre-warped at %13 Hz).")
        .arg(n.slot)
        .arg(num(n.spec.centerHz), num(r.peakDb), num(r.widthHz), num(r.levelDb), num(n.spec.depth, 3),
             num(std::pow(10.0, -r.peakDb / 20.0), 3), num(std::pow(10.0, o.targetOpenLoopDb / 20.0) / std::pow(10.0, r.levelDb / 20.0), 3),
             num(o.targetOpenLoopDb, 0))
        .arg(num(n.digitalWidthHz), num(std::min(n.spec.centerHz, 2.0 * (fN - n.spec.centerHz))), num(n.spec.widthHz),
             num(o.execRateHz, 0));
}

QString marginText(const std::optional<dsp::LoopMargins>& m, int which)
{
    if (!m)
        return {};
    switch (which) {
    case 0:
        return std::isfinite(m->gainMarginDb)
                   ? QCoreApplication::translate("NotchWizard", "%1 dB at %2 Hz").arg(num(m->gainMarginDb), num(m->gainMarginFreqHz, 0))
                   : QCoreApplication::translate("NotchWizard", "no phase crossover in the band");
    case 1:
        return std::isfinite(m->phaseMarginDeg)
                   ? QCoreApplication::translate("NotchWizard", "%1° at %2 Hz").arg(num(m->phaseMarginDeg), num(m->phaseMarginFreqHz, 1))
                   : QCoreApplication::translate("NotchWizard", "no gain crossover in the band");
    default:
        return QCoreApplication::translate("NotchWizard", "%1 dB at %2 Hz").arg(num(m->peakSensitivityDb, 2), num(m->peakSensitivityFreqHz, 0));
    }
}

void fillMargins(QTableWidget* t, const std::vector<std::optional<dsp::LoopMargins>>& cols)
{
    const QStringList rows{QCoreApplication::translate("NotchWizard", "Gain margin"),
                           QCoreApplication::translate("NotchWizard", "Phase margin"),
                           QCoreApplication::translate("NotchWizard", "Peak sensitivity")};
    t->setRowCount(3);
    for (int r = 0; r < 3; ++r) {
        t->setItem(r, 0, item(rows[r]));
        for (std::size_t c = 0; c < cols.size(); ++c)
            t->setItem(r, static_cast<int>(c) + 1, item(marginText(cols[c], r)));
    }
}

void addValidityBand(widgets::BodePlot* plot, const dsp::FrequencyResponse& frf)
{
    // Only a band on the plot: a missing or unreadable rate draws none.
    const auto parsed = frf.metadata.number(model::meta::kFsHz);
    if (!parsed || frf.empty())
        return;
    const double fs = *parsed;
    if (fs > 0.0 && frf.freqHz.back() > 0.5 * fs)
        plot->addBand(0.5 * fs, std::min(fs, frf.freqHz.back() * 1.05), widgets::BodePlot::BandKind::MultiSweepOnly);
}

}  // namespace

NotchAnalysis analyseNotchFrf(const dsp::FrequencyResponse& measured, const tuning::LoopForm& form,
                              const tuning::ResonanceOptions& resonanceOptions, const tuning::NotchOptions& notchOptions,
                              const std::map<int, dsp::NotchSpec>& existing)
{
    // The analysis is core's (tuning::analyseNotches); here only the rules are put into words.
    NotchAnalysis a;
    auto core = tuning::analyseNotches(measured, form, resonanceOptions, notchOptions, existing);
    if (!core) {
        a.error = QString::fromStdString(core.error().detail);
        return a;
    }
    a.resonances = core->resonances;
    a.proposal = core->proposal;
    a.prediction = core->prediction;
    for (const auto& n : core->notches) {
        const tuning::Resonance* r = nullptr;
        for (const auto& c : a.resonances)
            if (std::abs(c.freqHz - n.resonanceHz) < 1e-9)
                r = &c;
        NotchRow row;
        row.slot = n.slot;
        row.spec = n.spec;
        row.resonanceHz = n.resonanceHz;
        row.rule = r ? ruleText(n, *r, notchOptions) : QString();
        a.rows.push_back(row);
    }
    return a;
}

// ---------------------------------------------------------------------------------------------
// NotchSourcePage

NotchSourcePage::NotchSourcePage(NotchWizard& wizard, AppContext& ctx) : QWizardPage(&wizard), m_wizard(wizard), m_ctx(ctx)
{
    setObjectName("notchSourcePage");
    setTitle(tr("Frequency response"));
    setSubTitle(tr("The notches are placed on a measured velocity-loop frequency response: measure a new one, or "
                   "take one from a saved session of this machine."));
    auto* lay = new QVBoxLayout(this);
    m_measure = new QRadioButton(tr("New measurement (multi-sweep, up to just below the trace rate)"), this);
    m_measure->setObjectName("sourceMeasure");
    m_session = new QRadioButton(tr("Frequency response from a saved session"), this);
    m_session->setObjectName("sourceSession");
    m_measure->setChecked(true);
    lay->addWidget(m_measure);
    auto* box = new QGroupBox(tr("Measurement"), this);
    auto* form = new QFormLayout(box);
    m_fmin = new QDoubleSpinBox(box);
    m_fmin->setObjectName("fminHz");
    m_fmin->setRange(1.0, 1000.0);
    m_fmin->setValue(10.0);
    m_fmin->setSuffix(" Hz");
    m_fmax = new QDoubleSpinBox(box);
    m_fmax->setObjectName("fmaxHz");
    m_fmax->setRange(0.0, 50000.0);
    m_fmax->setValue(0.0);
    m_fmax->setSuffix(" Hz");
    m_fmax->setSpecialValueText(tr("0.975 × trace rate"));
    m_points = new QSpinBox(box);
    m_points->setObjectName("points");
    m_points->setRange(20, 2000);
    m_points->setValue(240);
    m_amplitude = new QDoubleSpinBox(box);
    m_amplitude->setObjectName("amplitudePct");
    m_amplitude->setRange(0.5, 50.0);
    m_amplitude->setValue(5.0);
    m_amplitude->setSuffix(tr(" % of rated torque"));
    form->addRow(tr("Lowest frequency:"), m_fmin);
    form->addRow(tr("Highest frequency:"), m_fmax);
    form->addRow(tr("Frequencies (log-spaced):"), m_points);
    form->addRow(tr("Amplitude:"), m_amplitude);
    lay->addWidget(box);
    lay->addWidget(m_session);
    m_sessions = new QListWidget(this);
    m_sessions->setObjectName("sourceSessions");
    lay->addWidget(m_sessions, 1);
    m_note = new QLabel(this);
    m_note->setWordWrap(true);
    lay->addWidget(m_note);
    connect(m_measure, &QRadioButton::toggled, this, [this, box](bool on) {
        box->setEnabled(on);
        m_sessions->setEnabled(!on);
        emit completeChanged();
    });
    m_sessions->setEnabled(false);
    connect(m_sessions, &QListWidget::currentRowChanged, this, &QWizardPage::completeChanged);
}

void NotchSourcePage::initializePage()
{
    fillSessions();
    m_measure->setEnabled(true);
    const QStringList axes = m_ctx.axes();
    if (!m_ctx.drive().isConnected() || axes.isEmpty())
        return;
    // A position PID the NC closes (hal:, linuxcnc:) has no notch slots: a new measurement goes to the NC PID page,
    // which proposes LinuxCNC's biquad; say so here, before anything is measured.
    const QString axis = axes.front();
    checkNcPositionPid(m_ctx, axis, this, [this, axis](bool ncPid, const QString& output) {
        m_wizard.setNcPidRefusal(ncPid ? ncPidNotchRefusal(axis, m_ctx.drive().uri(), output) : QString());
        if (!ncPid)
            return;
        m_wizard.ncPidPage()->setAxis(axis);
        m_measure->setChecked(true);
        m_note->setText(tr("Axis %1 is a position loop the NC closes with a PID (%2). A new measurement measures its "
                           "open loop and proposes LinuxCNC's biquad notch after the PID output (net %3) for the "
                           "gains that run.")
                            .arg(axis, m_ctx.drive().uri(), output));
        emit completeChanged();
    });
}

void NotchSourcePage::fillSessions()
{
    m_sessions->clear();
    auto* db = m_ctx.database();
    if (!db) {
        m_note->setText(tr("No store is open: only a new measurement is possible."));
        return;
    }
    auto list = db->listSessions(m_ctx.machine().toStdString());
    if (!list) {
        m_note->setText(tr("Reading the sessions failed: %1").arg(QString::fromStdString(list.error().detail)));
        return;
    }
    for (const auto& s : *list) {
        if (s.captureCount == 0 || s.status != store::SessionStatus::Completed)
            continue;
        auto rec = db->loadSession(s.id);
        if (!rec)
            continue;
        for (const auto& c : rec->captures) {
            if (!store::isFrfCapture(c.capture))
                continue;
            auto* it = new QListWidgetItem(tr("Session %1 (%2, axis %3, %4): %5")
                                               .arg(s.id)
                                               .arg(QString::fromStdString(s.kind), QString::fromStdString(s.axis),
                                                    QString::fromStdString(s.started), QString::fromStdString(c.name)));
            it->setData(Qt::UserRole, QVariant::fromValue<qint64>(s.id));
            it->setData(Qt::UserRole + 1, QString::fromStdString(c.name));
            it->setData(Qt::UserRole + 2, QString::fromStdString(s.axis));
            m_sessions->addItem(it);
        }
    }
    m_note->setText(m_sessions->count() ? QString() : tr("No saved session of this machine holds a frequency response."));
}

bool NotchSourcePage::fromSession() const { return m_session->isChecked(); }
double NotchSourcePage::fminHz() const { return m_fmin->value(); }
double NotchSourcePage::fmaxHz() const { return m_fmax->value(); }
int NotchSourcePage::points() const { return m_points->value(); }
double NotchSourcePage::amplitudePct() const { return m_amplitude->value(); }

bool NotchSourcePage::isComplete() const { return !fromSession() || m_sessions->currentItem(); }

bool NotchSourcePage::validatePage()
{
    if (!fromSession()) {
        m_wizard.setMeasured({}, QStringLiteral("measurement"));
        return true;
    }
    auto* it = m_sessions->currentItem();
    if (!it || !m_ctx.database())
        return false;
    const qint64 id = it->data(Qt::UserRole).value<qint64>();
    const std::string name = it->data(Qt::UserRole + 1).toString().toStdString();
    auto rec = m_ctx.database()->loadSession(id);
    if (!rec) {
        m_note->setText(tr("Reading session %1 failed: %2").arg(id).arg(QString::fromStdString(rec.error().detail)));
        return false;
    }
    for (const auto& c : rec->captures) {
        if (c.name != name)
            continue;
        auto frf = store::frfFromCapture(c.capture);
        if (!frf) {
            m_note->setText(tr("Session %1, %2: %3").arg(id).arg(QString::fromStdString(name), QString::fromStdString(frf.error().detail)));
            return false;
        }
        m_wizard.setAxis(it->data(Qt::UserRole + 2).toString());
        m_wizard.setMeasured(*frf, QStringLiteral("session"), id);
        return true;
    }
    return false;
}

int NotchSourcePage::nextId() const
{
    if (fromSession())
        return NotchWizard::kPropose;
    return m_wizard.ncPidRefusal().isEmpty() ? NotchWizard::kSafety : NotchWizard::kNcPid;
}

// ---------------------------------------------------------------------------------------------
// NotchProposePage

NotchProposePage::NotchProposePage(NotchWizard& wizard, AppContext& ctx) : QWizardPage(&wizard), m_wizard(wizard), m_ctx(ctx)
{
    setObjectName("notchProposePage");
    setTitle(tr("Resonances and proposed notches"));
    setSubTitle(tr("One notch per resonance, within the execution rate's limits; existing filters stay as they are. "
                   "Edit centre, width or depth: the prediction and the margins follow."));
    auto* lay = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    auto* bottom = new QHBoxLayout;
    auto* left = new QVBoxLayout;
    auto* opts = new QFormLayout;
    m_minHeight = new QDoubleSpinBox(this);
    m_minHeight->setObjectName("minHeightDb");
    m_minHeight->setRange(1.0, 40.0);
    m_minHeight->setDecimals(1);
    m_minHeight->setValue(wizard.resonanceOptions().minHeightDb);
    m_minHeight->setSuffix(" dB");
    opts->addRow(tr("Smallest resonance height:"), m_minHeight);
    left->addLayout(opts);
    m_status = new QLabel(this);
    m_status->setObjectName("notchStatus");
    m_status->setWordWrap(true);
    left->addWidget(m_status);
    m_resonances = table(this, {tr("Resonance [Hz]"), tr("Height [dB]"), tr("Width [Hz]"), tr("Open loop [dB]")}, "resonanceTable");
    m_resonances->setFixedHeight(125);
    left->addWidget(m_resonances, 1);
    m_table = table(this, {tr("Slot"), tr("Centre [Hz]"), tr("Width [Hz]"), tr("Depth")}, "notchTable");
    m_table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                             QAbstractItemView::AnyKeyPressed);
    m_table->setFixedHeight(125);
    left->addWidget(m_table, 1);
    auto* buttons = new QHBoxLayout;
    m_remove = new QPushButton(tr("Remove notch"), this);
    m_remove->setObjectName("removeNotch");
    m_reset = new QPushButton(tr("Back to the proposal"), this);
    m_reset->setObjectName("resetNotches");
    buttons->addWidget(m_remove);
    buttons->addWidget(m_reset);
    buttons->addStretch(1);
    left->addLayout(buttons);
    m_plot = new widgets::BodePlot(this);
    m_plot->setObjectName("notchPlot");
    m_plot->setMinimumSize(480, 300);
    top->addLayout(left, 2);
    top->addWidget(m_plot, 3);
    m_margins = table(this, {tr("Margin"), tr("Measured"), tr("Predicted")}, "notchMarginsTable");
    m_rules = new QTextBrowser(this);
    m_rules->setObjectName("notchRules");
    m_margins->setFixedHeight(100);
    m_rules->setFixedHeight(160);
    bottom->addWidget(m_margins, 2, Qt::AlignTop);
    bottom->addWidget(m_rules, 3);
    left->addStretch(1);
    lay->addLayout(top, 1);
    lay->addLayout(bottom, 0);

    connect(&m_watcher, &QFutureWatcher<NotchAnalysis>::finished, this, [this] {
        m_busy = false;
        m_wizard.setAnalysis(m_watcher.result());
        showAnalysis();
    });
    connect(m_table, &QTableWidget::itemChanged, this, [this] {
        if (!m_filling)
            onEdited();
    });
    connect(m_remove, &QPushButton::clicked, this, [this] {
        const int r = m_table->currentRow();
        auto rows = m_wizard.rows();
        if (r < 0 || r >= static_cast<int>(rows.size()))
            return;
        rows.erase(rows.begin() + r);
        QString why;
        m_wizard.setRows(rows, &why);
        fillTable();
        updatePrediction();
    });
    connect(m_reset, &QPushButton::clicked, this, [this] {
        QString why;
        m_wizard.setRows(m_wizard.proposedRows(), &why);
        fillTable();
        updatePrediction();
    });
    connect(m_minHeight, &QDoubleSpinBox::valueChanged, this, [this](double v) {
        m_wizard.setMinHeightDb(v);
        if (isVisible() && !m_busy && m_readRequest == 0)
            startAnalysis();
    });
}

void NotchProposePage::initializePage()
{
    m_resonances->setRowCount(0);
    m_table->setRowCount(0);
    m_margins->setRowCount(0);
    m_plot->clearResponses();
    m_plot->clearMarkers();
    m_plot->clearBands();
    m_measuredId = m_predictedId = -1;
    if (!m_wizard.hasMeasured()) {
        m_status->setText(tr("No frequency response to analyse."));
        return;
    }
    if (m_wizard.axis().isEmpty())
        m_wizard.setAxis(field("axis").toString());
    if (m_ctx.drive().isConnected() && !m_ctx.axes().isEmpty()) {
        // First what the axis is: a position PID the NC closes (hal:) gets no proposal to apply, and says why.
        const QString axis = m_ctx.axes().contains(m_wizard.axis()) ? m_wizard.axis() : m_ctx.axes().front();
        m_status->setText(tr("Asking the drive what axis %1 is…").arg(axis));
        m_busy = true;
        emit completeChanged();
        checkNcPositionPid(m_ctx, axis, this, [this, axis](bool ncPid, const QString& output) {
            if (!ncPid) {
                m_wizard.setNcPidRefusal({});
                readDrive();
                return;
            }
            const QString why = ncPidNotchRefusal(axis, m_ctx.drive().uri(), output);
            m_wizard.setNcPidRefusal(why);
            m_wizard.ncPidPage()->setAxis(axis);
            showRefusal(why);
        });
        return;
    }
    if (m_ctx.drive().isConnected())
        readDrive();
    else
        startOffline();
}

void NotchProposePage::showRefusal(const QString& why)
{
    m_busy = false;
    m_status->setText(QStringLiteral("<span style='color:#b00000'>%1</span>")
                          .arg(tr("Axis %1: this wizard applies no notch here; why, and what to use instead, is below.")
                                   .arg(m_wizard.axis())
                                   .toHtmlEscaped()));
    m_rules->setHtml(QStringLiteral("<p style='color:#b00000'>%1</p>").arg(why.toHtmlEscaped()));
    m_measuredId = m_plot->addResponse(m_wizard.measured(), tr("Measured"));
    emit completeChanged();
}

void NotchProposePage::readDrive()
{
    if (!m_ctx.axes().contains(m_wizard.axis())) {
        startOffline();
        return;
    }
    m_status->setText(tr("Reading the existing filters and the execution rate of axis %1…").arg(m_wizard.axis()));
    m_readRequest = connectReply(m_ctx.drive().readParameters(m_wizard.axis()), this, &NotchProposePage::onParameters);
    m_busy = true;
    emit completeChanged();
}

void NotchProposePage::startOffline()
{
    m_status->setText(tr("Not connected to axis %1: execution rate %2 Hz assumed, existing filters unknown.")
                          .arg(m_wizard.axis())
                          .arg(m_wizard.execRateHz()));
    startAnalysis();
}

void NotchProposePage::onParameters(const DriveReply& r)
{
    if (r.id != m_readRequest || m_readRequest == 0)
        return;
    m_readRequest = 0;
    if (!r.ok) {
        m_busy = false;
        m_status->setText(tr("Reading the parameters failed: %1").arg(r.error));
        emit completeChanged();
        return;
    }
    const auto get = [&](const std::string& k, double dflt) {
        const auto it = r.values.find(k);
        return it == r.values.end() ? dflt : it->second;
    };
    const double h = get("current.period", 62.5e-6);
    int slotTotal = 0;
    std::map<int, dsp::NotchSpec> existing;
    while (r.values.count("filter.notch" + std::to_string(slotTotal + 1) + ".center")) {
        ++slotTotal;
        const std::string k = "filter.notch" + std::to_string(slotTotal);
        const dsp::NotchSpec n{get(k + ".center", 0.0), get(k + ".width", 0.0), get(k + ".depth", 0.0)};
        if (n.centerHz > 0.0)
            existing[slotTotal] = n;
    }
    m_wizard.setDriveContext(1.0 / h, slotTotal, existing);
    startAnalysis();
}

void NotchProposePage::startAnalysis()
{
    m_busy = true;
    emit completeChanged();
    m_status->setText(tr("Analysing…"));
    const auto measured = m_wizard.measured();
    const auto form = m_wizard.loopForm();
    const auto ro = m_wizard.resonanceOptions();
    const auto no = m_wizard.notchOptions();
    const auto existing = m_wizard.existingNotches();
    m_watcher.setFuture(QtConcurrent::run([=] { return analyseNotchFrf(measured, form, ro, no, existing); }));
}

void NotchProposePage::showAnalysis()
{
    const auto& res = m_wizard.resonances();
    m_resonances->setRowCount(static_cast<int>(res.size()));
    for (std::size_t i = 0; i < res.size(); ++i) {
        const int r = static_cast<int>(i);
        m_resonances->setItem(r, 0, item(num(res[i].freqHz)));
        m_resonances->setItem(r, 1, item(num(res[i].peakDb)));
        m_resonances->setItem(r, 2, item(num(res[i].widthHz)));
        m_resonances->setItem(r, 3, item(num(res[i].levelDb)));
    }
    m_plot->clearResponses();
    m_plot->clearBands();
    m_measuredId = m_plot->addResponse(m_wizard.measured(), tr("Measured"), QColor(0, 90, 200));
    addValidityBand(m_plot, m_wizard.measured());
    fillTable();
    updatePrediction();
    emit completeChanged();
}

void NotchProposePage::fillTable()
{
    m_filling = true;
    const auto& rows = m_wizard.rows();
    m_table->setRowCount(static_cast<int>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const int r = static_cast<int>(i);
        m_table->setItem(r, 0, item(QString::number(rows[i].slot)));
        m_table->setItem(r, 1, item(QString::number(rows[i].spec.centerHz, 'f', 1), true));
        m_table->setItem(r, 2, item(QString::number(rows[i].spec.widthHz, 'f', 1), true));
        m_table->setItem(r, 3, item(QString::number(rows[i].spec.depth, 'f', 3), true));
    }
    m_filling = false;
}

void NotchProposePage::onEdited()
{
    auto rows = m_wizard.rows();
    for (int r = 0; r < m_table->rowCount() && r < static_cast<int>(rows.size()); ++r) {
        bool ok[3] = {false, false, false};
        const double c = m_table->item(r, 1)->text().toDouble(&ok[0]);
        const double w = m_table->item(r, 2)->text().toDouble(&ok[1]);
        const double d = m_table->item(r, 3)->text().toDouble(&ok[2]);
        if (!ok[0] || !ok[1] || !ok[2]) {
            m_status->setText(tr("Row %1: not a number.").arg(r + 1));
            return;
        }
        if (c != rows[r].spec.centerHz || w != rows[r].spec.widthHz || d != rows[r].spec.depth) {
            rows[r].spec = {c, w, d};
            rows[r].rule = tr("Slot %1: edited by the operator (centre %2 Hz, width %3 Hz, depth %4).")
                               .arg(rows[r].slot)
                               .arg(num(c), num(w), num(d, 3));
        }
    }
    QString why;
    if (!m_wizard.setRows(rows, &why)) {
        m_status->setText(tr("Not realisable at %1 Hz: %2").arg(m_wizard.execRateHz()).arg(why));
        m_status->setStyleSheet("QLabel { color: #b00000; }");
        return;
    }
    m_status->setStyleSheet(QString());
    updatePrediction();
}

void NotchProposePage::updatePrediction()
{
    if (m_predictedId >= 0)
        m_plot->removeResponse(m_predictedId);
    m_predictedId = -1;
    m_plot->clearMarkers();
    for (const auto& r : m_wizard.resonances()) {
        bool notched = false;
        for (const auto& n : m_wizard.rows())
            notched |= std::abs(n.spec.centerHz - r.freqHz) < 0.02 * r.freqHz;
        if (!notched)
            m_plot->addMarker(r.freqHz, widgets::BodePlot::MarkerKind::Resonance, tr("%1 Hz").arg(num(r.freqHz, 0)));
    }
    for (const auto& r : m_wizard.rows())
        m_plot->addMarker(r.spec.centerHz, widgets::BodePlot::MarkerKind::Notch, tr("N%1 %2 Hz").arg(r.slot).arg(num(r.spec.centerHz, 0)));
    if (!m_wizard.rows().empty())
        m_predictedId = m_plot->addResponse(m_wizard.predicted(), tr("Predicted"), QColor(230, 120, 0), Qt::DashLine);
    m_plot->rescale();
    fillMargins(m_margins, {m_wizard.marginsBefore(), m_wizard.marginsPredicted()});
    showRules();
    const auto& a = m_wizard.proposedRows();
    m_status->setText(tr("%1 resonances found, %2 notches proposed for axis %3 (execution rate %4 Hz, %5 of %6 slots free).")
                          .arg(m_wizard.resonances().size())
                          .arg(a.size())
                          .arg(m_wizard.axis())
                          .arg(m_wizard.execRateHz())
                          .arg(m_wizard.slotCount() - static_cast<int>(m_wizard.existingNotches().size()))
                          .arg(m_wizard.slotCount()));
}

void NotchProposePage::showRules()
{
    QString html;
    for (const auto& r : m_wizard.rows())
        html += "<p>" + r.rule.toHtmlEscaped() + "</p>";
    for (const auto& [slot, n] : m_wizard.existingNotches())
        html += "<p>" + tr("Slot %1 keeps its filter (centre %2 Hz, width %3 Hz, depth %4): existing filters are never removed.")
                            .arg(slot)
                            .arg(num(n.centerHz), num(n.widthHz), num(n.depth, 3))
                            .toHtmlEscaped() +
                "</p>";
    for (const auto& s : m_wizard.analysis().proposal.skipped)
        html += "<p>" + tr("No notch at %1 Hz: %2").arg(num(s.freqHz)).arg(QString::fromStdString(s.reason)).toHtmlEscaped() + "</p>";
    if (!m_wizard.analysis().error.isEmpty())
        html += "<p>" + tr("Analysis failed: %1").arg(m_wizard.analysis().error).toHtmlEscaped() + "</p>";
    m_rules->setHtml(html);
}

bool NotchProposePage::isComplete() const
{
    // A position PID the NC closes: no drive slots here; Next goes to the NC PID page (a new measurement there).
    if (!m_wizard.ncPidRefusal().isEmpty())
        return !m_busy;
    return !m_busy && !m_wizard.rows().empty();
}

bool NotchProposePage::validatePage()
{
    if (!m_wizard.ncPidRefusal().isEmpty())
        return true;
    m_wizard.applyPage()->setProposal(m_wizard.axis(), m_wizard.proposedValues());
    return true;
}

int NotchProposePage::nextId() const
{
    return m_wizard.ncPidRefusal().isEmpty() ? NotchWizard::kApply : NotchWizard::kNcPid;
}

// ---------------------------------------------------------------------------------------------
// NotchVerifyPage

NotchVerifyPage::NotchVerifyPage(NotchWizard& wizard) : QWizardPage(&wizard), m_wizard(wizard)
{
    setObjectName("notchVerifyPage");
    setTitle(tr("Verification"));
    setSubTitle(tr("The new measurement with the notches, overlaid on the prediction and on the first measurement."));
    auto* lay = new QVBoxLayout(this);
    m_deviation = new QLabel(this);
    m_deviation->setObjectName("notchDeviation");
    m_deviation->setWordWrap(true);
    lay->addWidget(m_deviation);
    m_plot = new widgets::BodePlot(this);
    m_plot->setObjectName("notchVerifyPlot");
    m_plot->setMinimumSize(480, 300);
    lay->addWidget(m_plot, 3);
    auto* bottom = new QHBoxLayout;
    m_peaks = table(this, {tr("Notch [Hz]"), tr("Before [dB]"), tr("Predicted [dB]"), tr("Measured [dB]")}, "notchPeaksTable");
    bottom->addWidget(m_peaks, 1);
    m_margins = table(this, {tr("Margin"), tr("Before"), tr("Predicted"), tr("Measured")}, "verifyMarginsTable");
    bottom->addWidget(m_margins, 1);
    lay->addLayout(bottom, 1);
}

void NotchVerifyPage::initializePage()
{
    m_plot->clearResponses();
    m_plot->clearMarkers();
    m_plot->clearBands();
    m_ids[0] = m_plot->addResponse(m_wizard.measured(), tr("Before"), QColor(0, 90, 200));
    m_ids[1] = m_plot->addResponse(m_wizard.predicted(), tr("Predicted"), QColor(230, 120, 0), Qt::DashLine);
    m_ids[2] = m_plot->addResponse(m_wizard.verification(), tr("After"), QColor(0, 150, 60));
    addValidityBand(m_plot, m_wizard.verification());
    for (const auto& r : m_wizard.rows())
        m_plot->addMarker(r.spec.centerHz, widgets::BodePlot::MarkerKind::Notch, tr("N%1").arg(r.slot));
    m_plot->rescale();
    const auto& d = m_wizard.deviation();
    m_deviation->setText(
        d.points == 0 ? tr("No point of the verification could be compared with the prediction.")
                      : tr("Prediction against measurement: largest deviation %1 dB at %2 Hz, rms %3 dB, over %4 valid "
                           "points from %5 Hz to %6 Hz (points where both lie below −50 dB are left out).")
                            .arg(num(d.maxAbsDb, 2), num(d.maxAtHz, 0), num(d.rmsDb, 2))
                            .arg(d.points)
                            .arg(num(d.fminHz, 0), num(d.fmaxHz, 0)));
    const auto& rows = m_wizard.rows();
    m_peaks->setRowCount(static_cast<int>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const double f = rows[i].spec.centerHz;
        const int r = static_cast<int>(i);
        m_peaks->setItem(r, 0, item(num(f)));
        m_peaks->setItem(r, 1, item(num(tuning::peakMagnitudeDb(m_wizard.measured(), f, 0.05))));
        m_peaks->setItem(r, 2, item(num(tuning::peakMagnitudeDb(m_wizard.predicted(), f, 0.05))));
        m_peaks->setItem(r, 3, item(num(tuning::peakMagnitudeDb(m_wizard.verification(), f, 0.05))));
    }
    fillMargins(m_margins, {m_wizard.marginsBefore(), m_wizard.marginsPredicted(), m_wizard.marginsVerified()});
}

// ---------------------------------------------------------------------------------------------
// NotchSavePage

NotchSavePage::NotchSavePage(NotchWizard& wizard) : QWizardPage(&wizard), m_wizard(wizard)
{
    setObjectName("notchSavePage");
    setTitle(tr("Save"));
    setSubTitle(tr("The session keeps the measured, predicted and verification responses, the resonances, the notches "
                   "with their rules, the margins, the parameter sets and the journal."));
    auto* lay = new QVBoxLayout(this);
    m_summary = new QLabel(this);
    m_summary->setObjectName("notchSaveSummary");
    m_summary->setWordWrap(true);
    lay->addWidget(m_summary);
    lay->addStretch(1);
}

void NotchSavePage::initializePage()
{
    m_wizard.saveCompleted();
    QString text = m_wizard.saved() ? tr("Session %1 saved (kind “notch”).").arg(m_wizard.savedSessionId())
                                    : tr("The session could not be saved (see the log).");
    text += "\n" + (m_wizard.applyPage()->applied()
                        ? tr("%1 notches applied to axis %2 and read back.").arg(m_wizard.rows().size()).arg(m_wizard.axis())
                        : tr("The notches were not applied; the proposal is kept in the session."));
    m_summary->setText(text);
}

}  // namespace gui
}  // namespace axistune

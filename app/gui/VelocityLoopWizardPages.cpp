// SPDX-License-Identifier: GPL-3.0-or-later
// Pages of the velocity/position-loop wizard (VelocityLoopWizard.h; docs/wizards/velocity-loop.md):
// source and rule, design with prediction, verification. Method: spec/lost-motion-and-two-inertia.md
// §2.8 (corrected 5.13), TI-5 §4.12 (margins), §4.11 (position gain).
#include "app/gui/AppContext.h"
#include "app/gui/NcPidPage.h"
#include "app/gui/ParameterLookup.h"
#include "app/gui/VelocityLoopWizard.h"
#include "app/gui/WidgetUtil.h"
#include "app/gui/WizardPages.h"
#include "core/model/Constants.h"
#include "core/store/FrfCapture.h"
#include "core/tuning/VelocityLoopDesign.h"
#include "widgets/BodePlot.h"
#include "widgets/CurvePlot.h"
#include "core/store/SessionRecord.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QRadioButton>
#include <QSignalBlocker>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace axistune {
namespace gui {

namespace {

void addRow(QTableWidget* t, const QString& a, const QString& b, const QString& c)
{
    const int r = t->rowCount();
    t->insertRow(r);
    t->setItem(r, 0, new QTableWidgetItem(a));
    t->setItem(r, 1, new QTableWidgetItem(b));
    t->setItem(r, 2, new QTableWidgetItem(c));
}

QString overshootText(const tuning::NormalisedStep& s)
{
    const auto pct = tuning::stepOvershootPct(s);
    return pct ? QString::number(*pct, 'f', 1) + " %" : QCoreApplication::translate("VelocityLoopWizard", "–");
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Source

VelocityLoopSourcePage::VelocityLoopSourcePage(AppContext& ctx, VelocityLoopData& shared, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared)
{
    setTitle(tr("Velocity loop: rule and data"));
    setSubTitle(tr("The velocity PI from the fitted motor-side inertia (chapter 5 rule) or from the margins on a "
                   "measured response; the position gain follows with its stability limit."));
    auto* lay = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    m_axis = new QComboBox(this);
    m_axis->setObjectName("vlAxis");
    top->addWidget(new QLabel(tr("Axis:"), this));
    top->addWidget(m_axis, 1);
    lay->addLayout(top);
    m_ncPidLabel = new QLabel(this);
    m_ncPidLabel->setObjectName("vlNcPid");
    m_ncPidLabel->setWordWrap(true);
    m_ncPidLabel->setStyleSheet("color: #1f4e9a");
    m_ncPidLabel->hide();
    lay->addWidget(m_ncPidLabel);
    connect(m_axis, &QComboBox::currentTextChanged, this, [this] { checkAxis(); });
    auto* methods = new QButtonGroup(this);
    m_inertiaMethod = new QRadioButton(tr("From the fitted inertia: K_P = k·√2·ω_l·J_m, K_I = k·ω_l²·J_m"), this);
    m_inertiaMethod->setObjectName("vlInertiaMethod");
    m_frfMethod = new QRadioButton(tr("From margins on a measured response (crossover and phase margin)"), this);
    m_frfMethod->setObjectName("vlFrfMethod");
    methods->addButton(m_inertiaMethod);
    methods->addButton(m_frfMethod);
    m_inertiaMethod->setChecked(true);
    auto* cols = new QHBoxLayout;
    auto* ig = new QGroupBox(this);
    m_choices << ig;
    auto* il = new QVBoxLayout(ig);
    il->addWidget(m_inertiaMethod);
    auto* iform = new QFormLayout;
    m_modelSessions = new QComboBox(ig);
    m_modelSessions->setObjectName("vlModelSessions");
    m_jm = spin(ig, 1e-7, 1e3, 1e-3, 7, QString::fromUtf8(" kg·m²"), "vlJm");
    m_wl = spin(ig, 0.1, 1000, 24.0, 2, " Hz", "vlOmegaL");
    m_k = spin(ig, 0.01, 1000, 10.0, 2, "", "vlK");
    iform->addRow(tr("Fitted model from:"), m_modelSessions);
    iform->addRow(tr("Motor-side inertia J_m:"), m_jm);
    iform->addRow(tr("Bandwidth ω_l/2π (for k = 1):"), m_wl);
    iform->addRow(tr("Gain factor k:"), m_k);
    il->addLayout(iform);
    cols->addWidget(ig, 1);
    auto* fg = new QGroupBox(this);
    m_choices << fg;
    auto* fl = new QVBoxLayout(fg);
    fl->addWidget(m_frfMethod);
    auto* sources = new QButtonGroup(this);
    m_measure = new QRadioButton(tr("Measure on the machine (torque injection, multi-sweep)"), fg);
    m_measure->setObjectName("vlMeasure");
    m_session = new QRadioButton(tr("From a saved session"), fg);
    m_session->setObjectName("vlFromSession");
    sources->addButton(m_measure);
    sources->addButton(m_session);
    m_measure->setChecked(true);
    fl->addWidget(m_measure);
    fl->addWidget(m_session);
    m_frfSessions = new QComboBox(fg);
    m_frfSessions->setObjectName("vlFrfSessions");
    fl->addWidget(m_frfSessions);
    auto* fform = new QFormLayout;
    m_crossover = spin(fg, 0.1, 5000, 40.0, 1, " Hz", "vlCrossover");
    m_pm = spin(fg, 5, 89, 50.0, 1, QString::fromUtf8(" °"), "vlPhaseMargin");
    fform->addRow(tr("Crossover frequency:"), m_crossover);
    fform->addRow(tr("Phase margin:"), m_pm);
    fl->addLayout(fform);
    cols->addWidget(fg, 1);
    lay->addLayout(cols);
    auto* sform = new QFormLayout;
    m_step = spin(this, 0.1, 600, 10.0, 1, tr(" rad/s"), "vlStep");
    m_choices << m_step;
    sform->addRow(tr("Velocity step before and after (motor):"), m_step);
    lay->addLayout(sform);
    m_note = new QLabel(this);
    m_note->setWordWrap(true);
    lay->addWidget(m_note);
    lay->addStretch(1);
    for (auto* b : {m_inertiaMethod, m_frfMethod, m_measure, m_session})
        connect(b, &QRadioButton::toggled, this, &QWizardPage::completeChanged);
    connect(m_frfSessions, &QComboBox::currentIndexChanged, this, &QWizardPage::completeChanged);
    connect(m_modelSessions, &QComboBox::currentIndexChanged, this, &VelocityLoopSourcePage::modelSessionChosen);
}

void VelocityLoopSourcePage::checkAxis()
{
    m_ncPid = false;
    m_ncPidLabel->hide();
    m_checking = true;
    emit completeChanged();
    // A position PID the NC closes (hal:, linuxcnc:) has no drive velocity loop: its PID is tuned on NcPidPage.
    const QString axis = m_axis->currentText();
    checkNcPositionPid(m_ctx, axis, this, [this, axis](bool ncPid, const QString&) {
        if (axis != m_axis->currentText())
            return; // another axis was chosen meanwhile
        m_checking = false;
        m_ncPid = ncPid;
        m_ncPidLabel->setText(tr("Axis %1 is a position loop the NC closes with a PID (%2): there is no drive "
                                 "velocity loop to tune. Next measures its open loop and proposes P, I, D, FF1, FF2 "
                                 "and a notch for it; the choices below do not apply.")
                                  .arg(axis, m_ctx.drive().uri()));
        m_ncPidLabel->setVisible(ncPid);
        for (QWidget* w : m_choices) // the drive velocity loop's choices: not for a PID the NC closes
            w->setEnabled(!ncPid);
        emit completeChanged();
    });
}

void VelocityLoopSourcePage::initializePage()
{
    {
        const QSignalBlocker block(m_axis);
        m_axis->clear();
        m_axis->addItems(m_ctx.axes());
    }
    checkAxis();
    const QSignalBlocker b(m_modelSessions);
    m_modelSessions->clear();
    m_modelSessions->addItem(tr("entered below"), QVariant::fromValue<qint64>(0));
    m_frfSessions->clear();
    if (auto* db = m_ctx.database()) {
        if (auto list = db->listSessions()) {
            for (auto it = list->rbegin(); it != list->rend(); ++it) {
                const QString text = tr("Session %1: %2, %3 axis %4, %5")
                                         .arg(it->id)
                                         .arg(qs(it->kind), qs(it->machine), qs(it->axis), qs(it->started));
                if (it->kind == "two-inertia" && it->resultCount > 0)
                    m_modelSessions->addItem(text, QVariant::fromValue<qint64>(it->id));
                if ((it->kind == "frf" || it->kind == "two-inertia" || it->kind == "velocity-loop" ||
                     it->kind == "notch") &&
                    it->captureCount > 0)
                    m_frfSessions->addItem(text, QVariant::fromValue<qint64>(it->id));
            }
        }
    }
    if (m_modelSessions->count() > 1) {
        m_modelSessions->setCurrentIndex(1);
        modelSessionChosen();
    }
    m_measure->setEnabled(m_ctx.drive().isConnected());
    if (!m_ctx.drive().isConnected())
        m_session->setChecked(true);
    m_note->setText(m_ctx.drive().isConnected()
                        ? tr("Before and after applying, a velocity step of the set size is run on the drive.")
                        : tr("Not connected: the proposal and prediction only; the steps, apply and verify need a "
                             "connection."));
}

void VelocityLoopSourcePage::modelSessionChosen()
{
    m_d.model.reset();
    m_d.modelSession = m_modelSessions->currentData().value<qint64>();
    if (m_d.modelSession == 0 || !m_ctx.database())
        return;
    auto rec = m_ctx.database()->loadSession(m_d.modelSession);
    if (!rec)
        return;
    for (const auto& r : rec->results)
        if (r.name == "fit" && r.data.contains("Jm_kgm2")) {
            tuning::TwoInertiaParams p;
            p.jmKgm2 = r.data.value("Jm_kgm2", 0.0);
            p.jlKgm2 = r.data.value("JL_kgm2", 0.0);
            p.kNmPerRad = r.data.value("K_Nm_per_rad", 0.0);
            p.cNmsPerRad = r.data.value("C_Nms_per_rad", 0.0);
            p.delayS = r.data.value("delay_s", 0.0);
            m_d.model = p;
            m_jm->setValue(p.jmKgm2);
            m_note->setText(tr("Session %1: fitted J_m %2 kg·m², J_L %3 kg·m², K %4 N·m/rad; the prediction uses this "
                               "two-inertia model.")
                                .arg(m_d.modelSession)
                                .arg(p.jmKgm2, 0, 'g', 5)
                                .arg(p.jlKgm2, 0, 'g', 5)
                                .arg(p.kNmPerRad, 0, 'g', 5));
        }
}

QString VelocityLoopSourcePage::ncPidNote() const { return m_ncPid ? m_ncPidLabel->text() : QString(); }

bool VelocityLoopSourcePage::isComplete() const
{
    if (m_checking)
        return false;
    if (m_ncPid)
        return true;
    if (m_frfMethod->isChecked())
        return m_measure->isChecked() ? m_ctx.drive().isConnected() : m_frfSessions->currentIndex() >= 0;
    return true;
}

bool VelocityLoopSourcePage::validatePage()
{
    m_d.axis = m_axis->currentText();
    if (m_ncPid && m_ncPidPage) {
        m_ncPidPage->setAxis(m_d.axis);
        return true;
    }
    m_d.method = m_frfMethod->isChecked() ? VelocityLoopData::Method::Frf : VelocityLoopData::Method::Inertia;
    m_d.frfSource =
        m_session->isChecked() ? VelocityLoopData::FrfSource::Session : VelocityLoopData::FrfSource::Measure;
    m_d.jmKgm2 = m_jm->value();
    if (m_d.model && std::abs(m_d.model->jmKgm2 - m_d.jmKgm2) > 1e-12 * m_d.jmKgm2)
        m_d.model->jmKgm2 = m_d.jmKgm2; // edited: the rule and the model use the entered J_m
    m_d.omegaLHz = m_wl->value();
    m_d.k = m_k->value();
    m_d.crossoverHz = m_crossover->value();
    m_d.phaseMarginDeg = m_pm->value();
    m_d.stepRadS = m_step->value();
    m_d.measured.reset();
    if (m_d.method != VelocityLoopData::Method::Frf || m_d.frfSource != VelocityLoopData::FrfSource::Session)
        return true;
    m_d.frfSession = m_frfSessions->currentData().value<qint64>();
    auto loaded = loadSessionFrf(m_ctx, m_d.frfSession);
    if (!loaded) {
        m_note->setText(qs(loaded.error().detail));
        return false;
    }
    m_d.measured = std::move(loaded->frf);
    if (m_d.axis.isEmpty())
        m_d.axis = loaded->axis;
    return true;
}

int VelocityLoopSourcePage::nextId() const
{
    if (m_ncPid)
        return VelocityLoopWizard::NcPid;
    return m_ctx.drive().isConnected() && m_axis->count() > 0 ? VelocityLoopWizard::Safety : VelocityLoopWizard::Design;
}

// ---------------------------------------------------------------------------------------------
// Design

VelocityLoopDesignPage::VelocityLoopDesignPage(AppContext& ctx, VelocityLoopData& shared, TestRunPage* run,
                                               ApplyPage* apply, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared), m_run(run), m_apply(apply)
{
    setTitle(tr("Velocity loop: proposal and prediction"));
    setSubTitle(tr("Predicted open loop L = C·P and closed loop T = L/(1 + L) with the proposed PI, the margins before "
                   "and after, the position gain with its stability limit, and the predicted velocity step."));
    auto* lay = new QVBoxLayout(this);
    auto* split = new QSplitter(Qt::Horizontal, this);
    auto* left = new QSplitter(Qt::Vertical, split);
    m_bode = new widgets::BodePlot(left);
    m_bode->setObjectName("vlBode");
    m_step = new widgets::CurvePlot(left);
    m_step->setObjectName("vlStepPrediction");
    m_step->setAxes(tr("Time from the step"), "ms", tr("Motor velocity / step"), "1");
    left->addWidget(m_bode);
    left->addWidget(m_step);
    m_table = new QTableWidget(0, 3, split);
    m_table->setObjectName("vlTable");
    m_table->setHorizontalHeaderLabels({tr("Quantity"), tr("Before"), tr("Proposed")});
    m_table->verticalHeader()->setVisible(false);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->horizontalHeader()->setStretchLastSection(true);
    split->addWidget(left);
    split->addWidget(m_table);
    split->setSizes({600, 380});
    lay->addWidget(split, 1);
    m_status = new QLabel(this);
    m_status->setObjectName("vlStatus");
    m_status->setWordWrap(true);
    lay->addWidget(m_status);
    m_applyPositionGain = new QCheckBox(tr("Also apply the recommended position gain K_p (the verification step "
                                           "tests the velocity loop only)"),
                                        this);
    m_applyPositionGain->setObjectName("vlApplyPositionGain");
    lay->addWidget(m_applyPositionGain);
    connect(m_applyPositionGain, &QCheckBox::toggled, this, [this](bool on) {
        m_d.applyPositionGain = on;
        updateProposal();
    });
}

void VelocityLoopDesignPage::initializePage()
{
    m_done = false;
    m_d.error.clear();
    m_d.stepBefore.reset();
    if (m_run->succeeded())
        for (const auto& r : m_run->replies()) {
            if (r.frf)
                m_d.measured = r.frf->frf;
            if (r.capture)
                m_d.stepBefore = r.capture;
        }
    if (m_ctx.drive().isConnected() && m_ctx.axes().contains(m_d.axis)) {
        auto* req = m_ctx.drive().readParameters(
            m_d.axis, {"velocity.kp", "velocity.ki", "velocity.period", "current.period", "position.kp"});
        m_readRequest = req->id();
        connect(req, &DriveRequest::finished, this, [this](const DriveReply& r) {
            if (r.id != m_readRequest)
                return;
            m_readRequest = 0;
            if (r.ok) {
                auto get = [&](const char* k, double fallback) { return parameterOr(r.values, k, fallback); };
                m_d.before = {get("velocity.kp", m_d.before.kpNmsPerRad), get("velocity.ki", m_d.before.kiNmPerRad)};
                m_d.positionKpBefore = get("position.kp", 0.0);
                m_d.velocityPeriodS = get("velocity.period", m_d.velocityPeriodS);
                m_d.currentPeriodS = get("current.period", m_d.currentPeriodS);
            }
            analyse();
        });
    } else
        analyse();
    emit completeChanged();
}

void VelocityLoopDesignPage::analyse()
{
    auto& d = m_d;
    m_bode->clearResponses();
    m_step->clear();
    m_table->setRowCount(0);
    // The design is core's (tuning::designVelocityLoop); the page shows it and says which rule chose it.
    d.design.reset();
    if (d.method == VelocityLoopData::Method::Frf && !d.measured)
        d.error = tr("No measured response.");
    if (d.error.isEmpty()) {
        tuning::VelocityLoopRequest req;
        req.method = d.method == VelocityLoopData::Method::Frf ? tuning::VelocityLoopRequest::Method::Frf
                                                               : tuning::VelocityLoopRequest::Method::Inertia;
        req.jmKgm2 = d.jmKgm2;
        req.omegaLHz = d.omegaLHz;
        req.k = d.k;
        req.model = d.model;
        req.crossoverHz = d.crossoverHz;
        req.phaseMarginDeg = d.phaseMarginDeg;
        req.measured = d.measured;
        req.running = d.before;
        req.positionKpRunning = d.positionKpBefore;
        req.velocityPeriodS = d.velocityPeriodS;
        req.currentPeriodS = d.currentPeriodS;
        req.stepRadS = d.stepRadS;
        req.stepDurationS = d.stepDurationS;
        auto design = tuning::designVelocityLoop(req);
        if (design)
            d.design = std::move(design).value();
        else
            d.error = qs(design.error().detail);
    }
    if (!d.error.isEmpty()) {
        m_status->setText(tr("No proposal: %1").arg(d.error));
        m_done = true;
        emit completeChanged();
        return;
    }
    const auto& g = *d.design;
    d.proposed = g.proposed;
    d.plant = g.plant;
    d.position = g.position;
    d.predictedBefore = g.predictedBefore;
    d.predictedAfter = g.predictedAfter;
    d.marginsBefore = g.marginsBefore;
    d.marginsAfter = g.marginsAfter;
    d.fHz = g.fHz;
    d.openLoop = g.openLoop;
    d.closedLoop = g.closedLoop;
    if (d.method == VelocityLoopData::Method::Inertia)
        d.rule = tr("Chapter 5 rule (corrected 5.13): K_P = k·√2·ω_l·J_m = %1·√2·2π·%2 Hz·%3 kg·m², K_I = k·ω_l²·J_m.")
                     .arg(d.k, 0, 'g', 4)
                     .arg(d.omegaLHz, 0, 'g', 4)
                     .arg(d.jmKgm2, 0, 'g', 5);
    else
        d.rule = tr("Margins on the measured plant: |C·P| = 1 and arg(C·P) = −180° + %1° at %2 Hz.")
                     .arg(d.phaseMarginDeg, 0, 'f', 1)
                     .arg(d.crossoverHz, 0, 'f', 1);
    dsp::FrequencyResponse lf, tf, pf;
    for (std::size_t i = 0; i < g.fHz.size(); ++i) {
        lf.push(g.fHz[i], g.openLoop[i], std::nan(""), true);
        tf.push(g.fHz[i], g.closedLoop[i], std::nan(""), true);
        pf.push(g.fHz[i], g.plantH[i], std::nan(""), true);
    }
    m_bode->addResponse(lf, tr("Open loop L (proposed)"), QColor(0, 90, 180));
    m_bode->addResponse(tf, tr("Closed loop T (proposed)"), QColor(200, 90, 0));
    m_bode->addResponse(pf, g.plant ? tr("Plant P (measured)") : tr("Plant P (model)"), QColor(120, 120, 120),
                        Qt::DashLine);
    if (d.marginsAfter.crossoverHz > 0.0)
        m_bode->addMarker(d.marginsAfter.crossoverHz, widgets::BodePlot::MarkerKind::Other,
                          tr("crossover %1 Hz").arg(d.marginsAfter.crossoverHz, 0, 'f', 1));
    m_bode->rescale();
    tuning::NormalisedStep before, sb, sa;
    if (d.stepBefore) {
        before = tuning::normalisedStep(*d.stepBefore, d.stepRadS);
        m_step->addCurve(tr("Measured before"), before.tMs, before.y, QColor(90, 90, 90));
    }
    if (d.predictedBefore) {
        sb = tuning::normalisedStep(*d.predictedBefore, d.stepRadS, g.stepTimeS);
        m_step->addCurve(tr("Predicted before"), sb.tMs, sb.y, QColor(90, 90, 90), Qt::DashLine);
    }
    if (d.predictedAfter) {
        sa = tuning::normalisedStep(*d.predictedAfter, d.stepRadS, g.stepTimeS);
        m_step->addCurve(tr("Predicted with the proposal"), sa.tMs, sa.y, QColor(0, 90, 180));
    }
    m_step->rescale();
    auto num = [](double v, int prec, const QString& unit) {
        return std::isfinite(v) ? QString::number(v, 'g', prec) + " " + unit : QObject::tr("none");
    };
    const auto& mb = d.marginsBefore;
    const auto& ma = d.marginsAfter;
    addRow(m_table, tr("K_P"), num(d.before.kpNmsPerRad, 5, tr("N·m·s/rad")),
           num(d.proposed.kpNmsPerRad, 5, tr("N·m·s/rad")));
    addRow(m_table, tr("K_I"), num(d.before.kiNmPerRad, 5, tr("N·m/rad")),
           num(d.proposed.kiNmPerRad, 5, tr("N·m/rad")));
    addRow(m_table, tr("Gain crossover"), num(mb.crossoverHz, 4, "Hz"), num(ma.crossoverHz, 4, "Hz"));
    addRow(m_table, tr("Phase margin"), num(mb.phaseMarginDeg, 3, "°"), num(ma.phaseMarginDeg, 3, "°"));
    addRow(m_table, tr("Gain margin"), num(mb.gainMarginDb, 3, "dB"), num(ma.gainMarginDb, 3, "dB"));
    addRow(m_table, tr("Peak sensitivity"), num(mb.peakSensitivityDb, 3, "dB"), num(ma.peakSensitivityDb, 3, "dB"));
    addRow(m_table, tr("Step overshoot (predicted)"), overshootText(sb), overshootText(sa));
    if (!before.y.empty())
        addRow(m_table, tr("Step overshoot (measured)"), overshootText(before), tr("after applying"));
    addRow(m_table, tr("Position gain K_p"), num(d.positionKpBefore, 4, "1/s"),
           num(d.position.recommendedPerS, 4, "1/s"));
    addRow(m_table, tr("Position gain stability limit"), QString(),
           std::isfinite(d.position.limitPerS)
               ? tr("%1 1/s at %2 Hz").arg(d.position.limitPerS, 0, 'g', 4).arg(d.position.limitFrequencyHz, 0, 'f', 1)
               : tr("none on the model"));
    m_table->resizeColumnsToContents();
    QString status =
        d.rule + "\n" +
        tr("Position gain: recommended min(limit·10^(−%1/20), crossover·2π/5); %2.")
            .arg(tuning::kPositionGainMarginDb, 0, 'f', 0)
            .arg(g.rigidModel
                     ? tr("rigid model J_m with a delay of 1.5 velocity periods — fit a two-inertia "
                          "model for the resonance")
                     : tr("two-inertia model of session %1 with a delay of 1.5 velocity periods").arg(d.modelSession));
    m_status->setText(status);
    const bool positionGain = std::isfinite(d.position.recommendedPerS) && d.position.recommendedPerS > 0.0;
    m_applyPositionGain->setEnabled(positionGain);
    if (!positionGain)
        m_applyPositionGain->setChecked(false);
    updateProposal();
    m_done = true;
    emit completeChanged();
}

void VelocityLoopDesignPage::updateProposal()
{
    auto& d = m_d;
    if (!d.design)
        return;
    const model::ParameterValues v = tuning::velocityLoopParameters(*d.design, d.applyPositionGain);
    if (m_ctx.drive().isConnected() && !d.axis.isEmpty()) {
        m_apply->setProposal(d.axis, v);
        m_ctx.setProposed(d.axis, v);
    }
}

bool VelocityLoopDesignPage::isComplete() const
{
    return m_done && m_readRequest == 0 && m_d.error.isEmpty();
}

int VelocityLoopDesignPage::nextId() const
{
    return m_ctx.drive().isConnected() && m_ctx.axes().contains(m_d.axis) ? VelocityLoopWizard::Apply
                                                                          : VelocityLoopWizard::Save;
}

// ---------------------------------------------------------------------------------------------
// Verify

VelocityLoopVerifyPage::VelocityLoopVerifyPage(VelocityLoopData& shared, TestRunPage* run, QWidget* parent)
    : QWizardPage(parent), m_d(shared), m_run(run)
{
    setTitle(tr("Velocity loop: verification"));
    setSubTitle(tr("The velocity step measured before and after applying, with the prediction."));
    auto* lay = new QVBoxLayout(this);
    m_plot = new widgets::CurvePlot(this);
    m_plot->setObjectName("vlVerifyPlot");
    m_plot->setAxes(tr("Time from the step"), "ms", tr("Motor velocity / step"), "1");
    lay->addWidget(m_plot, 1);
    m_text = new QLabel(this);
    m_text->setObjectName("vlVerifyText");
    m_text->setWordWrap(true);
    lay->addWidget(m_text);
}

void VelocityLoopVerifyPage::initializePage()
{
    m_plot->clear();
    m_d.stepAfter.reset();
    if (m_run->succeeded() && !m_run->replies().empty())
        m_d.stepAfter = m_run->replies().front().capture;
    const double t0 = 0.01 * m_d.stepDurationS;
    tuning::NormalisedStep before, after, pred;
    if (m_d.stepBefore) {
        before = tuning::normalisedStep(*m_d.stepBefore, m_d.stepRadS);
        m_plot->addCurve(tr("Measured before"), before.tMs, before.y, QColor(120, 120, 120));
    }
    if (m_d.stepAfter) {
        after = tuning::normalisedStep(*m_d.stepAfter, m_d.stepRadS);
        m_plot->addCurve(tr("Measured after"), after.tMs, after.y, QColor(200, 90, 0));
    }
    if (m_d.predictedAfter) {
        pred = tuning::normalisedStep(*m_d.predictedAfter, m_d.stepRadS, t0);
        m_plot->addCurve(tr("Predicted after"), pred.tMs, pred.y, QColor(0, 90, 180), Qt::DashLine);
    }
    m_plot->rescale();
    m_text->setText(m_d.stepAfter ? tr("Overshoot: before %1 (measured), after %2 (measured), %3 predicted.")
                                        .arg(overshootText(before), overshootText(after), overshootText(pred))
                                  : tr("No step after applying: %1").arg(m_run->failure()));
}

} // namespace gui
} // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
// Pages of the two-inertia wizard (TwoInertiaWizard.h; docs/wizards/two-inertia.md): source, fit,
// filter and prediction, verification. Method: spec/lost-motion-and-two-inertia.md §2.2–2.10, TI-1..TI-6.
#include "app/gui/AppContext.h"
#include "app/gui/ParameterLookup.h"
#include "app/gui/TwoInertiaWizard.h"
#include "app/gui/WidgetUtil.h"
#include "app/gui/WizardPages.h"
#include "core/model/Constants.h"
#include "core/model/MetadataKeys.h"
#include "core/store/FrfCapture.h"
#include "core/tuning/VelocityLoopDesign.h"
#include "widgets/BodePlot.h"
#include "widgets/CurvePlot.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QRadioButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <cmath>
#include <numbers>

namespace axistune {
namespace gui {

namespace {

using model::kDegPerRad;
using model::kTwoPi;

bool isFrfSessionKind(const std::string& k)
{
    return k == "frf" || k == "two-inertia" || k == "notch" || k == "velocity-loop";
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Source

TwoInertiaSourcePage::TwoInertiaSourcePage(AppContext& ctx, TwoInertiaData& shared, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared)
{
    setTitle(tr("Two-inertia: low-frequency response"));
    setSubTitle(tr("Measure the response of the velocity loop in the low band (torque injection, multi-sweep) or take "
                   "a response from a saved session. The fit needs the anti-resonance and the resonance inside the "
                   "band (thesis: 5–300 Hz)."));
    auto* lay = new QVBoxLayout(this);
    auto* group = new QButtonGroup(this);
    m_measure = new QRadioButton(tr("Measure on the machine"), this);
    m_measure->setObjectName("tiMeasure");
    m_session = new QRadioButton(tr("From a saved session"), this);
    m_session->setObjectName("tiFromSession");
    group->addButton(m_measure);
    group->addButton(m_session);
    m_measure->setChecked(true);
    lay->addWidget(m_measure);
    auto* mf = new QFormLayout;
    m_fmin = spin(this, 0.5, 1000, 5, 1, " Hz");
    m_fmax = spin(this, 10, 2000, 300, 1, " Hz");
    m_points = new QSpinBox(this);
    m_points->setRange(10, 400);
    m_points->setValue(60);
    m_amplitude = spin(this, 0.5, 20, 5, 1, " %");
    mf->addRow(tr("Band from:"), m_fmin);
    mf->addRow(tr("to:"), m_fmax);
    mf->addRow(tr("Frequencies (log-spaced):"), m_points);
    mf->addRow(tr("Injection amplitude (of rated torque):"), m_amplitude);
    lay->addLayout(mf);
    lay->addWidget(m_session);
    m_sessions = new QComboBox(this);
    m_sessions->setObjectName("tiSessions");
    lay->addWidget(m_sessions);
    auto* pi = new QGroupBox(tr("Velocity loop of the measurement (read from the drive when connected)"), this);
    auto* pf = new QFormLayout(pi);
    m_kp = spin(pi, 0, 1e5, 11.24, 4, QString::fromUtf8(" N·m·s/rad"));
    m_ki = spin(pi, 0, 1e8, 1198, 2, QString::fromUtf8(" N·m/rad"));
    pf->addRow(tr("K_P:"), m_kp);
    pf->addRow(tr("K_I:"), m_ki);
    lay->addWidget(pi);
    m_note = new QLabel(this);
    m_note->setWordWrap(true);
    lay->addWidget(m_note);
    lay->addStretch(1);
    connect(m_measure, &QRadioButton::toggled, this, &QWizardPage::completeChanged);
    connect(m_sessions, &QComboBox::currentIndexChanged, this, &QWizardPage::completeChanged);
}

void TwoInertiaSourcePage::initializePage()
{
    m_sessions->clear();
    if (auto* db = m_ctx.database()) {
        if (auto list = db->listSessions()) {
            for (auto it = list->rbegin(); it != list->rend(); ++it) {
                if (!isFrfSessionKind(it->kind) || it->captureCount == 0)
                    continue;
                m_sessions->addItem(tr("Session %1: %2, %3 axis %4, %5")
                                        .arg(it->id)
                                        .arg(qs(it->kind), qs(it->machine), qs(it->axis), qs(it->started)),
                                    QVariant::fromValue<qint64>(it->id));
            }
        }
    }
    m_measure->setEnabled(m_ctx.drive().isConnected());
    if (!m_ctx.drive().isConnected())
        m_session->setChecked(true);
    m_note->setText(m_ctx.drive().isConnected() ? QString()
                                                : tr("Not connected: only saved responses can be used; apply and "
                                                     "verify need a connection."));
}

bool TwoInertiaSourcePage::isComplete() const
{
    return m_measure->isChecked() ? m_ctx.drive().isConnected() : m_sessions->currentIndex() >= 0;
}

bool TwoInertiaSourcePage::validatePage()
{
    m_d.fromSession = m_session->isChecked();
    m_d.fminHz = m_fmin->value();
    m_d.fmaxHz = m_fmax->value();
    m_d.points = m_points->value();
    m_d.amplitudePct = m_amplitude->value();
    m_d.fitOptions.fminHz = m_fmin->value();
    m_d.fitOptions.fmaxHz = m_fmax->value();
    m_d.loopPi = {m_kp->value(), m_ki->value()};
    m_d.measured.reset();
    if (!m_d.fromSession)
        return true;
    m_d.sourceSession = m_sessions->currentData().value<qint64>();
    auto loaded = loadSessionFrf(m_ctx, m_d.sourceSession);
    if (!loaded) {
        m_note->setText(qs(loaded.error().detail));
        return false;
    }
    m_d.measured = std::move(loaded->frf);
    m_d.axis = loaded->axis;
    return true;
}

int TwoInertiaSourcePage::nextId() const
{
    return m_session->isChecked() ? TwoInertiaWizard::Fit : TwoInertiaWizard::Safety;
}

// ---------------------------------------------------------------------------------------------
// Fit

TwoInertiaFitPage::TwoInertiaFitPage(AppContext& ctx, TwoInertiaData& shared, TestRunPage* run, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared), m_run(run)
{
    setTitle(tr("Two-inertia model"));
    setSubTitle(tr("Torque → motor velocity P_m with the fitted model (5.1) over it: anti-resonance f₀ = √(K/J_L)/2π "
                   "(zero), resonance f_p = √(K(1/J_m + 1/J_L))/2π (pole), and the residual model/measured."));
    auto* lay = new QVBoxLayout(this);
    auto* split = new QSplitter(Qt::Horizontal, this);
    auto* left = new QSplitter(Qt::Vertical, split);
    m_bode = new widgets::BodePlot(left);
    m_bode->setObjectName("tiBode");
    m_residual = new widgets::CurvePlot(left);
    m_residual->setObjectName("tiResidual");
    m_residual->setAxes(tr("Frequency"), "Hz", tr("Residual model/measured"), tr("dB, °"), true, false);
    left->addWidget(m_bode);
    left->addWidget(m_residual);
    left->setStretchFactor(0, 3);
    left->setStretchFactor(1, 1);
    m_table = makeTable(split, {tr("Quantity"), tr("Value")});
    m_table->setObjectName("tiModelTable");
    split->addWidget(left);
    split->addWidget(m_table);
    split->setSizes({620, 360});
    lay->addWidget(split, 1);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    lay->addWidget(m_status);
}

void TwoInertiaFitPage::initializePage()
{
    m_bode->clearResponses();
    m_bode->clearMarkers();
    m_residual->clear();
    m_table->setRowCount(0);
    m_d.fit.reset();
    m_d.plant.reset();
    m_d.error.clear();
    if (!m_d.fromSession && m_run->succeeded() && !m_run->replies().empty() && m_run->replies().front().frf) {
        m_d.measured = m_run->replies().front().frf->frf;
        m_d.axis = m_run->replies().front().axis;
    }
    if (!m_d.measured) {
        m_status->setText(tr("No response to fit."));
        return;
    }
    m_busy = true;
    emit completeChanged();
    m_status->setText(tr("Fitting…"));
    // The loop the response was measured in: recorded with the response (a wizard measurement), else
    // from the drive when it has this axis (its values may have changed since), else as entered.
    const auto& md = m_d.measured->metadata;
    auto num = [&](const char* key, double& out) {
        const auto* v = md.find(key);
        const auto x = v ? v->number() : std::nullopt;
        if (!x)
            return false;
        out = *x;
        return true;
    };
    double kp = 0, ki = 0, tv = 0, h = 0;
    if (num("loop_kp_Nms_per_rad", kp) && num("loop_ki_Nm_per_rad", ki) && num("velocity_period_s", tv) &&
        num("current_period_s", h)) {
        m_d.loopPi = {kp, ki};
        m_d.velocityPeriodS = tv;
        m_d.currentPeriodS = h;
        analyse();
    } else if (m_ctx.drive().isConnected() && m_ctx.axes().contains(m_d.axis)) {
        auto* req =
            m_ctx.drive().readParameters(m_d.axis, {"velocity.kp", "velocity.ki", "velocity.period", "current.period"});
        m_readRequest = req->id();
        connect(req, &DriveRequest::finished, this, [this](const DriveReply& r) {
            if (r.id != m_readRequest)
                return;
            m_readRequest = 0;
            if (r.ok) {
                auto get = [&](const char* k, double fallback) { return parameterOr(r.values, k, fallback); };
                m_d.loopPi = {get("velocity.kp", m_d.loopPi.kpNmsPerRad), get("velocity.ki", m_d.loopPi.kiNmPerRad)};
                m_d.velocityPeriodS = get("velocity.period", m_d.velocityPeriodS);
                m_d.currentPeriodS = get("current.period", m_d.currentPeriodS);
                if (!m_d.fromSession && m_d.measured) {
                    auto& meta = m_d.measured->metadata;
                    meta.set("loop_kp_Nms_per_rad", m_d.loopPi.kpNmsPerRad);
                    meta.set("loop_ki_Nm_per_rad", m_d.loopPi.kiNmPerRad);
                    meta.set(model::meta::kVelocityPeriodS, m_d.velocityPeriodS);
                    meta.set(model::meta::kCurrentPeriodS, m_d.currentPeriodS);
                }
            }
            analyse();
        });
    } else
        analyse();
}

void TwoInertiaFitPage::analyse()
{
    struct Out {
        std::optional<dsp::FrequencyResponse> plant;
        std::optional<tuning::TwoInertiaFit> fit;
        QString error;
    };
    const auto measured = *m_d.measured;
    const auto pi = m_d.loopPi;
    const double tv = m_d.velocityPeriodS, h = m_d.currentPeriodS;
    const auto opts = m_d.fitOptions;
    auto* watcher = new QFutureWatcher<Out>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] {
        const Out out = watcher->result();
        watcher->deleteLater();
        m_d.plant = out.plant;
        m_d.fit = out.fit;
        m_d.error = out.error;
        m_busy = false;
        showResults();
        emit completeChanged();
    });
    watcher->setFuture(QtConcurrent::run([measured, pi, tv, h, opts]() {
        Out out;
        // One parser of loop measurements (core/tuning/VelocityLoopDesign.h): no key is a plant FRF.
        auto kind = tuning::loopMeasurementOf(measured, tuning::LoopMeasurementKind::Plant);
        auto p = kind ? tuning::plantFromMeasurement(measured, *kind, pi, tv, h)
                      : Result<dsp::FrequencyResponse>(kind.error());
        if (!p) {
            out.error = qs(p.error().detail);
            return out;
        }
        const dsp::FrequencyResponse plant = std::move(p).value();
        out.plant = plant;
        auto fit = tuning::fitTwoInertia(plant, opts);
        if (!fit)
            out.error = qs(fit.error().detail);
        else
            out.fit = *fit;
        return out;
    }));
}

void TwoInertiaFitPage::showResults()
{
    if (m_d.plant)
        m_bode->addResponse(*m_d.plant, tr("measured P_m"), QColor(0, 90, 200));
    if (!m_d.fit) {
        m_status->setText(tr("Fit failed: %1").arg(m_d.error));
        return;
    }
    const auto& p = m_d.fit->params;
    dsp::FrequencyResponse model;
    std::vector<double> rf, rMag, rPh;
    for (std::size_t i = 0; i < m_d.plant->size(); ++i) {
        const double f = m_d.plant->freqHz[i];
        const auto hm = tuning::motorVelocityResponse(p, f);
        model.push(f, hm, std::nan(""), true);
        if (m_d.plant->valid[i] && f >= m_d.fitOptions.fminHz && f <= m_d.fitOptions.fmaxHz) {
            const auto ratio = hm / m_d.plant->h[i];
            rf.push_back(f);
            rMag.push_back(20.0 * std::log10(std::abs(ratio)));
            rPh.push_back(std::arg(ratio) * kDegPerRad);
        }
    }
    m_bode->addResponse(model, tr("two-inertia model"), QColor(200, 60, 0), Qt::DashLine);
    const double f0 = tuning::antiresonanceRadS(p) / kTwoPi, fp = tuning::resonanceRadS(p) / kTwoPi;
    const double z0 = tuning::zetaZero(p), zp = tuning::zetaPole(p);
    m_bode->addMarker(f0, widgets::BodePlot::MarkerKind::AntiResonance,
                      tr("f₀ %1 Hz, ζ₀ %2").arg(f0, 0, 'f', 2).arg(z0, 0, 'f', 3));
    m_bode->addMarker(fp, widgets::BodePlot::MarkerKind::Resonance,
                      tr("f_p %1 Hz, ζ_p %2").arg(fp, 0, 'f', 2).arg(zp, 0, 'f', 3));
    m_bode->rescale();
    m_residual->addCurve(tr("magnitude [dB]"), rf, rMag, QColor(0, 90, 200));
    m_residual->addCurve(tr("phase [°]"), rf, rPh, QColor(200, 60, 0));
    m_residual->rescale();
    addRow(m_table, {tr("Anti-resonance f₀"), tr("%1 Hz").arg(f0, 0, 'f', 3)});
    addRow(m_table, {tr("Zero damping ζ₀"), QString::number(z0, 'f', 4)});
    addRow(m_table, {tr("Resonance f_p"), tr("%1 Hz").arg(fp, 0, 'f', 3)});
    addRow(m_table, {tr("Pole damping ζ_p"), QString::number(zp, 'f', 4)});
    addRow(m_table, {tr("Motor inertia J_m"), QString::fromUtf8("%1 kg·m²").arg(p.jmKgm2, 0, 'g', 5)});
    addRow(m_table, {tr("Load inertia J_L"), QString::fromUtf8("%1 kg·m²").arg(p.jlKgm2, 0, 'g', 5)});
    addRow(m_table, {tr("Stiffness K"), QString::fromUtf8("%1 N·m/rad").arg(p.kNmPerRad, 0, 'g', 5)});
    addRow(m_table, {tr("Damping C"), QString::fromUtf8("%1 N·m·s/rad").arg(p.cNmsPerRad, 0, 'g', 4)});
    addRow(m_table, {tr("Delay"), QString::fromUtf8("%1 µs").arg(p.delayS * 1e6, 0, 'f', 0)});
    addRow(m_table, {tr("Fit error (rms relative)"), QString::number(m_d.fit->fitError, 'f', 4)});
    addRow(m_table, {tr("Check f_p/f₀ = √(1 + J_L/J_m)"),
                     tr("%1 = %2").arg(fp / f0, 0, 'f', 3).arg(std::sqrt(1.0 + p.jlKgm2 / p.jmKgm2), 0, 'f', 3)});
    m_table->resizeColumnsToContents();
    m_status->setText(tr("Fit over %1–%2 Hz, %3 points, %4 iterations. The response was converted from the closed "
                         "velocity loop with K_P %5 N·m·s/rad, K_I %6 N·m/rad when it was one.")
                          .arg(m_d.fitOptions.fminHz)
                          .arg(m_d.fitOptions.fmaxHz)
                          .arg(m_d.fit->pointsUsed)
                          .arg(m_d.fit->iterations)
                          .arg(m_d.loopPi.kpNmsPerRad)
                          .arg(m_d.loopPi.kiNmPerRad));
}

bool TwoInertiaFitPage::isComplete() const { return !m_busy && m_d.fit.has_value(); }

// ---------------------------------------------------------------------------------------------
// Filter and prediction

TwoInertiaFilterPage::TwoInertiaFilterPage(AppContext& ctx, TwoInertiaData& shared, ApplyPage* apply, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared), m_apply(apply)
{
    setTitle(tr("Suppression filter and predicted load error"));
    setSubTitle(tr("Semi-closed: F_m = (s² + 2ζω₀s + ω₀²)/(2ζω₀s + ω₀²) on the position command (5.7). Full-closed: "
                   "F_L = F_m/(τs + 1) on the velocity command (5.9). Start values from the model: f₀ and the zero "
                   "damping ζ₀ (not ζ_p). The drive's position.feedback decides which filter it runs."));
    auto* lay = new QHBoxLayout(this);
    auto* left = new QVBoxLayout;
    auto* form = new QFormLayout;
    m_mode = new QComboBox(this);
    m_mode->setObjectName("tiMode");
    m_mode->addItems({tr("Semi-closed (F_m)"), tr("Full-closed (F_L)")});
    m_tau = spin(this, 0, 1000, 0, 2, " ms");
    m_tau->setToolTip(tr("0: high-frequency gain 1/(2ζω₀τ) = 2.5"));
    m_vmax = spin(this, 0.1, 1000, 10, 2, " rev/s");
    m_accel = spin(this, 1, 1e5, 200, 1, QString::fromUtf8(" rev/s²"));
    m_jerk = spin(this, 10, 1e8, 20000, 0, QString::fromUtf8(" rev/s³"));
    form->addRow(tr("Feedback:"), m_mode);
    form->addRow(tr("F_L time constant τ:"), m_tau);
    form->addRow(tr("Profile speed:"), m_vmax);
    form->addRow(tr("Acceleration:"), m_accel);
    form->addRow(tr("Jerk:"), m_jerk);
    left->addLayout(form);
    m_table = makeTable(this, {tr("Setting"), tr("Value")});
    m_table->setObjectName("tiFilterTable");
    left->addWidget(m_table, 1);
    lay->addLayout(left, 2);
    auto* right = new QVBoxLayout;
    m_plot = new widgets::CurvePlot(this);
    m_plot->setObjectName("tiLoadError");
    m_plot->setAxes(tr("Time"), "s", tr("Load error y_L − y*"), QString::fromUtf8("°"));
    right->addWidget(m_plot, 1);
    m_result = new QLabel(this);
    m_result->setObjectName("tiPrediction");
    m_result->setWordWrap(true);
    right->addWidget(m_result);
    lay->addLayout(right, 3);
    for (auto* s : {m_tau, m_vmax, m_accel, m_jerk})
        connect(s, &QDoubleSpinBox::valueChanged, this, &TwoInertiaFilterPage::update);
    connect(m_mode, &QComboBox::currentIndexChanged, this, &TwoInertiaFilterPage::update);
}

void TwoInertiaFilterPage::initializePage()
{
    m_mode->setEnabled(true);
    m_mode->setToolTip(QString());
    m_d.feedback = -1;
    if (m_ctx.drive().isConnected() && m_ctx.axes().contains(m_d.axis)) {
        // all: position.feedback, and the axis kind
        auto* req = m_ctx.drive().readParameters(m_d.axis);
        m_readRequest = req->id();
        connect(req, &DriveRequest::finished, this, [this](const DriveReply& r) {
            if (r.id != m_readRequest)
                return;
            m_readRequest = 0;
            m_d.linearAxis = r.ok && r.values.count("lostmotion.mode") > 0;
            auto it = r.values.find("position.feedback");
            if (r.ok && it != r.values.end()) {
                // The filter must match the feedback (the drive refuses F_m with full-closed and F_L with
                // semi-closed feedback), so the mode follows the axis.
                m_d.feedback = it->second >= 1.0 ? 1 : 0;
                m_mode->setCurrentIndex(m_d.feedback);
                m_mode->setEnabled(false);
                m_mode->setToolTip(tr("Set by the axis's position.feedback"));
            }
            update();
            emit completeChanged();
        });
    }
    update();
}

bool TwoInertiaFilterPage::isComplete() const { return m_readRequest == 0 && m_d.fit.has_value(); }

void TwoInertiaFilterPage::update()
{
    if (!m_d.fit)
        return;
    const auto& p = m_d.fit->params;
    const auto mode = m_mode->currentIndex() == 1 ? tuning::SuppressionMode::Full : tuning::SuppressionMode::Semi;
    m_d.tauS = m_tau->value() * 1e-3;
    // The proposal is core's (tuning::twoInertiaProposal): filter, thesis PI, feedforward.
    const auto proposal = tuning::twoInertiaProposal(p, mode, m_d.tauS);
    m_d.filter = proposal.filter;
    m_d.profile.vMax = m_vmax->value() * kTwoPi;
    m_d.profile.aMax = m_accel->value() * kTwoPi;
    m_d.profile.jerk = m_jerk->value() * kTwoPi;
    // The load error under ideal motor tracking with F_m (the full-closed F_L acts inside the loop).
    const auto semi = tuning::suppressionFilterFromModel(p, tuning::SuppressionMode::Semi, 0.0);
    m_d.loadError = tuning::loadErrorTraces(p, semi, m_d.profile, 1e-3);
    double maxWithout = 0.0, maxWith = 0.0;
    std::vector<double> a, b;
    for (std::size_t i = 0; i < m_d.loadError.tS.size(); ++i) {
        a.push_back(m_d.loadError.withoutFilter[i] * kDegPerRad);
        b.push_back(m_d.loadError.withFilter[i] * kDegPerRad);
        maxWithout = std::max(maxWithout, std::abs(a.back()));
        maxWith = std::max(maxWith, std::abs(b.back()));
    }
    m_plot->clear();
    m_plot->addCurve(tr("without filter"), m_d.loadError.tS, a, QColor(200, 60, 0));
    m_plot->addCurve(tr("with F_m"), m_d.loadError.tS, b, QColor(0, 150, 60));
    m_plot->rescale();
    m_d.proposedPi = proposal.pi;
    m_d.proposal = proposal.parameters;
    m_table->setRowCount(0);
    addRow(m_table, {tr("Filter frequency f₀"), tr("%1 Hz").arg(m_d.filter.f0Hz, 0, 'f', 3)});
    addRow(m_table, {tr("Filter damping ζ"), QString::number(m_d.filter.zeta, 'f', 4)});
    if (mode == tuning::SuppressionMode::Full)
        addRow(m_table, {tr("Time constant τ"), tr("%1 ms").arg(m_d.filter.tauS * 1e3, 0, 'f', 2)});
    addRow(m_table, {tr("First-order lag T₁ = 2ζ/ω₀"), tr("%1 ms").arg(2.0 * m_d.filter.zeta / (kTwoPi * m_d.filter.f0Hz) * 1e3, 0, 'f', 3)});
    addRow(m_table, {tr("Velocity K_P (TI-5, ω_l 24 Hz, k 10)"),
                     QString::fromUtf8("%1 N·m·s/rad").arg(m_d.proposedPi.kpNmsPerRad, 0, 'f', 3)});
    addRow(m_table, {tr("Velocity K_I (TI-5)"), QString::fromUtf8("%1 N·m/rad").arg(m_d.proposedPi.kiNmPerRad, 0, 'f', 1)});
    addRow(m_table, {tr("Drive filter suppression.mode"),
                     mode == tuning::SuppressionMode::Full ? tr("2 (full-closed F_L)") : tr("1 (semi-closed F_m)")});
    addRow(m_table, {tr("Torque feedforward inertia J_m + J_L"),
                     QString::fromUtf8("%1 kg·m²").arg(p.jmKgm2 + p.jlKgm2, 0, 'g', 5)});
    m_table->resizeColumnsToContents();
    QString text = tr("Predicted maximum load error: %1° without the filter, %2° with F_m (ideal motor tracking, "
                      "load through (5.6)).")
                       .arg(maxWithout, 0, 'f', 3)
                       .arg(maxWith, 0, 'f', 3);
    if (mode == tuning::SuppressionMode::Full)
        text += " " + tr("F_L acts inside the full-closed loop: the prediction with the filter is the semi-closed one.");
    text += " " + tr("The proposal writes the filter to the drive (suppression.mode, f0, zeta%1), the velocity PI of the "
                     "thesis rule K_P = k√2·ω_l·J_m, K_I = k·ω_l²·J_m on the fitted J_m, and the velocity and torque "
                     "feedforward the method needs. The profile runs once before and once after the change.")
                      .arg(mode == tuning::SuppressionMode::Full ? QStringLiteral(", tau") : QString());
    if (m_d.feedback < 0)
        text += " " + tr("Not connected to the axis: the mode is chosen here, and the settings are only stored.");
    m_result->setText(text);
    if (m_ctx.drive().isConnected() && m_ctx.axes().contains(m_d.axis)) {
        m_apply->setProposal(m_d.axis, m_d.proposal);
        m_ctx.setProposed(m_d.axis, m_d.proposal);
    }
}

int TwoInertiaFilterPage::nextId() const
{
    if (!m_ctx.drive().isConnected() || !m_ctx.axes().contains(m_d.axis))
        return TwoInertiaWizard::Save;
    // A response from a session skipped the safety page: confirm the profile's motion there first.
    return m_d.fromSession ? TwoInertiaWizard::Safety : TwoInertiaWizard::BeforeRun;
}

// ---------------------------------------------------------------------------------------------
// Verify

TwoInertiaVerifyPage::TwoInertiaVerifyPage(TwoInertiaData& shared, TestRunPage* before, TestRunPage* run,
                                           QWidget* parent)
    : QWizardPage(parent), m_d(shared), m_before(before), m_run(run)
{
    setTitle(tr("Verify with the profile"));
    setSubTitle(tr("The same profile as before the change, now with the filter: the measured load error y_L − y* "
                   "against the prediction with and without the filter (ideal motor tracking), and the load − motor "
                   "angle against the model's prediction from the measured motor motion (5.6)."));
    auto* lay = new QVBoxLayout(this);
    m_plot = new widgets::CurvePlot(this);
    m_plot->setObjectName("tiVerifyPlot");
    m_plot->setAxes(tr("Time from the start of the move"), "s", tr("Load error y_L − y*"), QString::fromUtf8("°"));
    lay->addWidget(m_plot, 1);
    m_result = new QLabel(this);
    m_result->setObjectName("tiVerifyResult");
    m_result->setWordWrap(true);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    lay->addWidget(m_result);
}

namespace {

/// The load error of a profile jog's trace, with the time shifted to the start of the move.
tuning::MeasuredLoadError jogLoadError(const model::Capture& c, double dwellS)
{
    const auto* t = c.channel("t_s");
    const auto* cmd = c.channel("position_cmd_rad");
    const auto* yl = c.channel("table_pos_rad");
    if (!t || !cmd || !yl)
        return {};
    auto e = tuning::measuredLoadError(t->data, cmd->data, yl->data);
    for (double& x : e.tS)
        x -= dwellS;
    return e;
}

std::vector<double> degrees(const std::vector<double>& rad)
{
    std::vector<double> out;
    out.reserve(rad.size());
    for (double v : rad)
        out.push_back(v * kDegPerRad);
    return out;
}

}  // namespace

void TwoInertiaVerifyPage::loadError()
{
    auto params = m_d.fit->params;
    params.delayS = 0.0;
    tuning::SuppressionFilter fm = m_d.filter;
    fm.mode = tuning::SuppressionMode::Semi;
    const auto pred = tuning::predictLoadError(params, fm, m_d.profile);
    m_d.predictedLoadWithout = pred.maxErrorWithoutFilter;
    m_d.predictedLoadWith = pred.maxErrorWithFilter;
    m_d.loadAfter = jogLoadError(*m_d.jog, m_d.profile.settleS);
    m_d.loadBefore = {};
    m_d.beforeJog.reset();
    if (m_before->succeeded() && !m_before->replies().empty() && m_before->replies().front().capture) {
        m_d.beforeJog = m_before->replies().front().capture;
        m_d.loadBefore = jogLoadError(*m_d.beforeJog, m_d.profile.settleS);
    }
    const auto& pe = m_d.loadError;  // the filter page's prediction of the same profile
    m_plot->addCurve(tr("predicted without the filter"), pe.tS, degrees(pe.withoutFilter), QColor(200, 60, 0),
                     Qt::DashLine);
    m_plot->addCurve(tr("predicted with the filter"), pe.tS, degrees(pe.withFilter), QColor(0, 150, 60), Qt::DashLine);
    if (m_d.beforeJog)
        m_plot->addCurve(tr("measured before the change"), m_d.loadBefore.tS, degrees(m_d.loadBefore.error),
                         QColor(160, 120, 0));
    m_plot->addCurve(tr("measured with the filter"), m_d.loadAfter.tS, degrees(m_d.loadAfter.error),
                     QColor(0, 90, 200));
    m_plot->rescale();
}

void TwoInertiaVerifyPage::initializePage()
{
    m_plot->clear();
    m_d.jog.reset();
    m_d.verifyT.clear();
    m_d.measuredTwist.clear();
    m_d.predictedTwist.clear();
    m_d.measuredMaxTwist = m_d.predictedMaxTwist = 0.0;
    m_d.loadAfter = m_d.loadBefore = {};
    if (!m_run->succeeded() || m_run->replies().empty() || !m_run->replies().front().capture || !m_d.fit) {
        m_result->setText(tr("No verification run."));
        return;
    }
    m_d.jog = m_run->replies().front().capture;
    const auto* t = m_d.jog->channel("t_s");
    const auto* ym = m_d.jog->channel("motor_pos_rad");
    const auto* vm = m_d.jog->channel("motor_vel_rad_s");
    const auto* yl = m_d.jog->channel("table_pos_rad");
    if (!t || !ym || !vm || !yl || !m_d.jog->channel("position_cmd_rad")) {
        m_result->setText(tr("The trace lacks t_s, position_cmd_rad, motor_pos_rad, motor_vel_rad_s or table_pos_rad "
                             "(a rotary axis with a load encoder is needed)."));
        return;
    }
    loadError();
    auto params = m_d.fit->params;
    params.delayS = 0.0;
    const auto pred = tuning::predictLoadFromMotor(params, t->data, ym->data, vm->data);
    const double off = yl->data.front() - ym->data.front();
    for (std::size_t i = 0; i < t->data.size(); ++i) {
        m_d.verifyT.push_back(t->data[i] - t->data.front());
        m_d.measuredTwist.push_back(yl->data[i] - ym->data[i] - off);
        m_d.predictedTwist.push_back(pred.empty() ? 0.0 : pred[i] - ym->data[i]);
        m_d.measuredMaxTwist = std::max(m_d.measuredMaxTwist, std::abs(m_d.measuredTwist.back()));
        m_d.predictedMaxTwist = std::max(m_d.predictedMaxTwist, std::abs(m_d.predictedTwist.back()));
    }
    // Load − motor under ideal motor tracking of the motor command (y* without the filter).
    const auto semi = tuning::suppressionFilterFromModel(params, tuning::SuppressionMode::Semi, 0.0);
    m_d.idealMaxTwist = tuning::predictLoadError(params, semi, m_d.profile).maxErrorWithoutFilter;
    QString text = tr("Maximum load error y_L − y* of the profile: measured with the filter %1°; predicted (ideal "
                      "motor tracking) %2° without and %3° with the filter.")
                       .arg(m_d.loadAfter.maxAbs * kDegPerRad, 0, 'f', 3)
                       .arg(m_d.predictedLoadWithout * kDegPerRad, 0, 'f', 3)
                       .arg(m_d.predictedLoadWith * kDegPerRad, 0, 'f', 3);
    if (m_d.beforeJog)
        text +=
            " " + tr("Measured before the change: %1° (ratio with/before %2).")
                      .arg(m_d.loadBefore.maxAbs * kDegPerRad, 0, 'f', 3)
                      .arg(m_d.loadBefore.maxAbs > 0.0 ? m_d.loadAfter.maxAbs / m_d.loadBefore.maxAbs : 0.0, 0, 'f', 3);
    if (m_d.predictedLoadWithout > 0.0)
        text += " " + tr("Measured with the filter / predicted without: %1 (the thesis reached 0.086, its criterion "
                         "for a working filter is at most 0.2).")
                          .arg(m_d.loadAfter.maxAbs / m_d.predictedLoadWithout, 0, 'f', 3);
    text += "\n" + tr("Maximum load − motor angle: measured %1°, predicted from the measured motor motion %2°.")
                       .arg(m_d.measuredMaxTwist * kDegPerRad, 0, 'f', 3)
                       .arg(m_d.predictedMaxTwist * kDegPerRad, 0, 'f', 3);
    m_result->setText(text);
}

}  // namespace gui
}  // namespace axistune

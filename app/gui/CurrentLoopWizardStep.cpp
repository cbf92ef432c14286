// SPDX-License-Identifier: GPL-3.0-or-later
// Step pages of the current-loop wizard (CurrentLoopWizard.h; docs/wizards/current-loop.md): the
// predicted steps (delay-free design model (2.14)–(2.15) and the discrete delay-inclusive prediction,
// spec/current-loop-and-multisweep-frf.md §2.8) with the settings of the current step measured on the
// drive, and the verification: gains read back, the measured step (TestType::CurrentStep) over both
// predictions with the 10–90 % rise time and overshoot of each and their difference.
#include "app/gui/AppContext.h"
#include "app/gui/CurrentLoopWizard.h"
#include "app/gui/WizardPages.h"
#include "core/model/MetadataKeys.h"
#include "widgets/CurvePlot.h"

#include <QCheckBox>
#include <QColor>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace axistune {
namespace gui {

namespace {

/// Share of V_max the largest early voltage of the default step may take.
constexpr double kStepVoltageShare = 0.8;
/// Largest default step as a share of I_max (the inductance falls by δ times this at most).
constexpr double kStepCurrentShare = 0.1;

std::vector<double> scaled(const std::vector<double>& v, double k)
{
    std::vector<double> out(v.size());
    std::transform(v.begin(), v.end(), out.begin(), [k](double x) { return x * k; });
    return out;
}

QString stepSummary(const std::vector<double>& t, const std::vector<double>& y)
{
    const auto f = tuning::stepFigures(t, y);
    return QCoreApplication::translate("CurrentLoopWizard", "overshoot %1 %, 10–90 % rise time %2 µs")
        .arg(f.overshoot * 100.0, 0, 'f', 1)
        .arg(f.riseTimeS * 1e6, 0, 'f', 1);
}

/// Voltage per ampere of step in the last period before the current can respond: with d periods of dead
/// time the error stays i* for d + 1 periods, so v = (α k_p + (d + 1) k_i T)·i*. Kept inside the clamp,
/// the measured loop is the linear one the prediction describes.
double earlyVoltagePerAmp(const CurrentLoopData& d, const tuning::AlphaOptimum& c)
{
    const double dead = d.drivePeriodS > 0.0 ? std::round(d.driveDeadTimeS / d.drivePeriodS) : 0.0;
    return c.alpha * c.gains.kpVPerA + (dead + 1.0) * c.gains.kiVPerAs * d.drivePeriodS;
}

/// Length of the predicted response after the step [s].
double predictionLength(const tuning::AlphaOptimum& c, double periodS)
{
    return std::max(20.0 * c.riseTimeS, 40.0 * periodS);
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Step responses

CurrentLoopStepPage::CurrentLoopStepPage(AppContext& ctx, CurrentLoopData& shared, ApplyPage* apply, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared), m_apply(apply)
{
    setTitle(tr("Current loop: step responses"));
    setSubTitle(tr("The delay-free design model against the prediction with the drive's current-loop period "
                   "(zero-order hold) and dead time; a current step is measured on the drive before and after "
                   "applying."));
    auto* lay = new QVBoxLayout(this);
    m_plot = new widgets::CurvePlot(this);
    m_plot->setObjectName("clStepPlot");
    m_plot->setAxes(tr("Time"), QString::fromUtf8("µs"), tr("Current / command"), "1");
    lay->addWidget(m_plot, 1);
    m_text = new QLabel(this);
    m_text->setObjectName("clStepText");
    m_text->setWordWrap(true);
    lay->addWidget(m_text);
    auto* box = new QGroupBox(tr("Current step on the drive, before and after applying"), this);
    m_measureBox = box;
    auto* form = new QFormLayout(box);
    m_measure = new QCheckBox(tr("Measure a current step (velocity loop open, then the axis holds its position)"), box);
    m_measure->setObjectName("clMeasure");
    m_measure->setChecked(true);
    form->addRow(m_measure);
    m_amp = new QDoubleSpinBox(box);
    m_amp->setObjectName("clStepAmp");
    m_amp->setRange(0.01, 1000.0);
    m_amp->setDecimals(2);
    m_amp->setSuffix(" A");
    form->addRow(tr("Step of the q-axis current command:"), m_amp);
    m_record = new QDoubleSpinBox(box);
    m_record->setObjectName("clStepRecord");
    m_record->setRange(0.1, 1000.0);  // narrowed to the drive's limit when it is read (showLimits)
    m_record->setDecimals(2);
    m_record->setSuffix(" ms");
    form->addRow(tr("Recording (the step comes 10 % in):"), m_record);
    m_measureNote = new QLabel(box);
    m_measureNote->setObjectName("clStepNote");
    m_measureNote->setWordWrap(true);
    form->addRow(m_measureNote);
    lay->addWidget(box);
    connect(m_measure, &QCheckBox::toggled, this, [this](bool on) {
        m_amp->setEnabled(on);
        m_record->setEnabled(on);
    });
}

double CurrentLoopStepPage::defaultStepAmplitude(const CurrentLoopData& d)
{
    const auto* c = d.chosen();
    if (!c)
        return 0.0;
    const double perAmp = earlyVoltagePerAmp(d, *c);
    double amp = kStepCurrentShare * d.motor.maxCurrentA;
    if (perAmp > 0.0)
        amp = std::min(amp, kStepVoltageShare * d.motor.maxVoltageV / perAmp);
    return std::floor(amp * 10.0) / 10.0; // a round figure below the bound
}

void CurrentLoopStepPage::initializePage()
{
    m_plot->clear();
    const auto* c = m_d.chosen();
    if (!c)
        return;
    const auto& s = m_d.step;
    const auto tUs = scaled(s.timeS, 1e6);
    m_plot->addCurve(tr("Delay-free design"), scaled(m_d.fineTimeS, 1e6), m_d.fineDelayFree, QColor(0, 90, 180));
    m_plot->addCurve(tr("Prediction: period %1 µs + dead time %2 µs")
                         .arg(m_d.drivePeriodS * 1e6, 0, 'f', 1)
                         .arg(m_d.driveDeadTimeS * 1e6, 0, 'f', 1),
                     tUs, s.discrete, QColor(200, 90, 0));
    m_plot->rescale();
    const bool connected = m_ctx.drive().isConnected() && !m_d.axis.isEmpty();
    m_text->setText(tr("Delay-free: %1. With the delay: %2.")
                        .arg(stepSummary(m_d.fineTimeS, m_d.fineDelayFree), stepSummary(s.timeS, s.discrete)));
    m_measureBox->setVisible(connected);
    if (connected) {
        model::ParameterValues v{
            {"current.kp", c->gains.kpVPerA}, {"current.ki", c->gains.kiVPerAs}, {"current.alpha", c->alpha}};
        m_apply->setProposal(m_d.axis, v);
        m_ctx.setProposed(m_d.axis, v);
        const double amp = defaultStepAmplitude(m_d);
        m_amp->setValue(amp);
        m_record->setValue(std::ceil(predictionLength(*c, m_d.drivePeriodS) / 0.9 * 1e4) / 10.0);
        const double first = earlyVoltagePerAmp(m_d, *c) * amp;
        m_noteDefault =
            tr("Default %1 A: at most %2 % of I_max, and the voltage before the current can respond, (α k_p + "
               "(d + 1)·k_i T)·i* = %3 V with d dead-time periods, stays within %4 % of V_max (%5 V), so no voltage "
               "clamp acts and the inductance falls by only δ·i*/I_max = %6 %.")
                .arg(amp, 0, 'f', 1)
                .arg(kStepCurrentShare * 100.0, 0, 'f', 0)
                .arg(first, 0, 'f', 1)
                .arg(kStepVoltageShare * 100.0, 0, 'f', 0)
                .arg(m_d.motor.maxVoltageV, 0, 'f', 1)
                .arg(m_d.motor.inductanceDropAtMax * amp / m_d.motor.maxCurrentA * 100.0, 0, 'f', 2);
        // The current step's limits are the drive's own (Drive::limits, docs/drive-seam.md).
        m_limits.reset();
        m_measureNote->setText(m_noteDefault + " " + tr("Reading the drive's limits…"));
        auto* req = m_ctx.drive().describeAxis(m_d.axis);
        m_limitsRequest = req->id();
        connect(req, &DriveRequest::finished, this, [this](const DriveReply& r) {
            if (r.id == m_limitsRequest)
                showLimits(r);
        });
    }
}

void CurrentLoopStepPage::showLimits(const DriveReply& r)
{
    m_limitsRequest = -1;
    if (!r.ok || !r.limits) {
        m_measureNote->setText(m_noteDefault + " " +
                               tr("<span style='color:#b00000'>The drive does not state its current-step limits: %1</span>")
                                   .arg(r.error.toHtmlEscaped()));
        m_measure->setChecked(false);
        m_measure->setEnabled(false);
        return;
    }
    m_limits = r.limits;
    m_measure->setEnabled(true);
    // The spin boxes end at the drive's limits; a default beyond them is brought inside.
    m_amp->setMaximum(m_limits->currentStepMaxA);
    m_record->setMaximum(m_limits->currentStepMaxS * 1e3);
    m_measureNote->setText(m_noteDefault + " " +
                           tr("The drive refuses a step above %1 A, a recording beyond %2 ms and a step that would take "
                              "the motor beyond %3 rad/s.")
                               .arg(m_limits->currentStepMaxA, 0, 'g', 4)
                               .arg(m_limits->currentStepMaxS * 1e3, 0, 'g', 4)
                               .arg(m_limits->currentStepMaxSpeedRadS, 0, 'g', 4));
}

bool CurrentLoopStepPage::validatePage()
{
    m_d.measure = !m_measureBox->isHidden() && m_measure->isChecked();
    m_d.stepAmplitudeA = m_amp->value();
    m_d.stepRecordS = m_record->value() * 1e-3;
    if (auto* safety = qobject_cast<SafetyPage*>(wizard()->page(CurrentLoopWizard::Safety))) {
        safety->setAxes({m_d.axis});
        safety->setMotionDescription(
            tr("A q-axis current step of %1 A recorded for %2 ms, twice: now with the gains the drive holds, and "
               "after applying the proposed ones. The velocity and position loops are open while it lasts: the "
               "motor accelerates freely, then the axis holds its position again.")
                .arg(m_d.stepAmplitudeA, 0, 'f', 2)
                .arg(m_d.stepRecordS * 1e3, 0, 'f', 2));
    }
    return true;
}

int CurrentLoopStepPage::nextId() const
{
    if (!m_ctx.drive().isConnected() || m_d.axis.isEmpty())
        return CurrentLoopWizard::Save;
    return !m_measureBox->isHidden() && m_measure->isChecked() ? CurrentLoopWizard::Safety : CurrentLoopWizard::Apply;
}

// ---------------------------------------------------------------------------------------------
// Verify

CurrentLoopVerifyPage::CurrentLoopVerifyPage(AppContext& ctx, CurrentLoopData& shared, ApplyPage* apply,
                                             QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared), m_apply(apply)
{
    setTitle(tr("Current loop: verification"));
    setSubTitle(tr("The gains read back from the drive, the step predicted with them (period and dead time of the "
                   "drive) and the design, against the current step measured on the drive."));
    auto* lay = new QVBoxLayout(this);
    m_plot = new widgets::CurvePlot(this);
    m_plot->setObjectName("clVerifyPlot");
    m_plot->setAxes(tr("Time since the step"), QString::fromUtf8("µs"), tr("Current / command"), "1");
    lay->addWidget(m_plot, 1);
    m_text = new QLabel(this);
    m_text->setObjectName("clVerifyText");
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    lay->addWidget(m_text);
}

void CurrentLoopVerifyPage::initializePage()
{
    m_plot->clear();
    m_d.verified = false;
    if (!m_ctx.drive().isConnected() || m_d.axis.isEmpty()) {
        m_text->setText(tr("Not connected: nothing to verify."));
        return;
    }
    // Read back even without apply: the measured step ran with the gains the drive holds.
    m_text->setText(tr("Reading back…"));
    auto* req = m_ctx.drive().readParameters(
        m_d.axis, {"current.kp", "current.ki", "current.alpha", "current.period", "current.dead_time"});
    m_readRequest = req->id();
    connect(req, &DriveRequest::finished, this, [this](const DriveReply& r) {
        if (r.id != m_readRequest)
            return;
        m_readRequest = 0;
        if (!r.ok) {
            m_text->setText(tr("Reading back failed: %1").arg(r.error));
            emit completeChanged();
            return;
        }
        auto get = [&](const char* k) {
            auto it = r.values.find(k);
            return it == r.values.end() ? std::nan("") : it->second;
        };
        m_d.readKp = get("current.kp");
        m_d.readKi = get("current.ki");
        m_d.readAlpha = get("current.alpha");
        m_d.drivePeriodS = get("current.period");
        m_d.driveDeadTimeS = get("current.dead_time");
        m_d.verified = true;
        showResult();
        emit completeChanged();
    });
}

void CurrentLoopVerifyPage::showResult()
{
    const auto* c = m_d.chosen();
    if (!c)
        return;
    m_d.measured.reset();
    if (m_d.measuredCapture) {
        auto m = tuning::currentStepFromCapture(*m_d.measuredCapture);
        if (m)
            m_d.measured = std::move(m).value();
        else
            m_d.measureError = QString::fromStdString(m.error().detail);
    }
    m_d.before.reset();
    if (m_d.beforeCapture) {
        if (auto b = tuning::currentStepFromCapture(*m_d.beforeCapture); b) {
            m_d.before = std::move(b).value();
            m_d.beforeFigures = tuning::stepFigures(m_d.before->tS, m_d.before->normalised);
        }
    }
    const double dur = m_d.measured ? m_d.measured->tS.back() : predictionLength(*c, m_d.drivePeriodS);
    m_d.verifyStep = tuning::stepResponses(m_d.motor, m_d.readAlpha, {m_d.readKi, m_d.readKp}, m_d.driveDeadTimeS,
                                           m_d.drivePeriodS, dur);
    const auto& s = m_d.verifyStep;
    m_d.predictedFigures = tuning::stepFigures(s.timeS, s.discrete);
    m_d.designFigures = tuning::stepFigures(m_d.fineTimeS, m_d.fineDelayFree);
    m_d.verifyOvershoot = m_d.predictedFigures.overshoot;
    m_d.verifyRiseS = m_d.predictedFigures.riseTimeS;
    m_plot->addCurve(tr("Design (delay-free, proposed gains)"), scaled(m_d.fineTimeS, 1e6), m_d.fineDelayFree,
                     QColor(0, 90, 180));
    m_plot->addCurve(tr("Prediction with the read-back gains (period + dead time)"), scaled(s.timeS, 1e6), s.discrete,
                     QColor(200, 90, 0));
    const bool same = std::abs(m_d.readKp - c->gains.kpVPerA) <= 1e-6 * std::abs(c->gains.kpVPerA) + 1e-9 &&
                      std::abs(m_d.readKi - c->gains.kiVPerAs) <= 1e-6 * std::abs(c->gains.kiVPerAs) + 1e-9 &&
                      std::abs(m_d.readAlpha - c->alpha) <= 1e-9;
    QString text = tr("Read back: k_p %1 V/A, k_i %2 V/(A·s), α %3 — %4.")
                       .arg(m_d.readKp, 0, 'f', 3)
                       .arg(m_d.readKi, 0, 'g', 6)
                       .arg(m_d.readAlpha, 0, 'f', 2)
                       .arg(same ? tr("as proposed") : tr("NOT as proposed"));
    if (!m_apply->applied())
        text += " " + tr("Not applied: the drive kept its own gains, and the measurement is of those.");
    if (m_d.before)
        m_plot->addCurve(tr("Measured before applying (gains before)"), scaled(m_d.before->tS, 1e6),
                         m_d.before->normalised, QColor(150, 150, 150), Qt::DashLine);
    if (m_d.measured) {
        m_plot->addCurve(tr("Measured on the drive (%1 A step)").arg(m_d.measured->amplitudeA, 0, 'f', 2),
                         scaled(m_d.measured->tS, 1e6), m_d.measured->normalised, QColor(0, 0, 0));
        text += "\n" + compareMeasured();
    } else {
        text += "\n" + tr("Predicted step with them: %1.").arg(stepSummary(s.timeS, s.discrete));
        text += "\n" + (m_d.measure ? tr("No measured current step: %1").arg(m_d.measureError)
                                    : tr("No current step was measured (not chosen on the step page)."));
    }
    m_plot->rescale();
    m_text->setText(text);
}

QString CurrentLoopVerifyPage::compareMeasured()
{
    const auto& m = *m_d.measured;
    m_d.measuredPrediction = m_d.verifyStep;
    m_d.measuredFigures = tuning::stepFigures(m.tS, m.normalised);
    m_d.difference = tuning::compareSteps(m.normalised, m_d.verifyStep.discrete);
    const auto& mf = m_d.measuredFigures;
    const auto& pf = m_d.predictedFigures;
    const auto& df = m_d.designFigures;
    auto us = [](double s) { return QString::number(s * 1e6, 'f', 1); };
    auto pct = [](double x) { return QString::number(x * 100.0, 'f', 1); };
    constexpr double kAgree = 0.05; // of the step: well above noise and the inductance drop at the default step
    m_d.measuredVerdict =
        m_d.difference.maxAbs <= kAgree
            ? tr("The measured step agrees with the delay-inclusive prediction within %1 % of the step.")
                  .arg(kAgree * 100.0, 0, 'f', 0)
            : tr("The measured step differs from the delay-inclusive prediction by more than %1 % of "
                 "the step: check R_a, L_q and the dead time, or use a smaller step.")
                  .arg(kAgree * 100.0, 0, 'f', 0);
    QString text = tr("Current step of %1 A measured on the drive (%2 samples at %3 µs):")
                       .arg(m.amplitudeA, 0, 'f', 2)
                       .arg(m.tS.size())
                       .arg(m.periodS * 1e6, 0, 'f', 2);
    text += "\n" + tr("• measured: 10–90 % rise time %1 µs, overshoot %2 %").arg(us(mf.riseTimeS), pct(mf.overshoot));
    text +=
        "\n" + tr("• design (delay-free): rise time %1 µs, overshoot %2 %").arg(us(df.riseTimeS), pct(df.overshoot));
    text += "\n" + tr("• prediction (period + dead time, read-back gains): rise time %1 µs, overshoot %2 %")
                       .arg(us(pf.riseTimeS), pct(pf.overshoot));
    if (m_d.before)
        text += "\n" + tr("• measured before applying (gains before): rise time %1 µs, overshoot %2 %")
                           .arg(us(m_d.beforeFigures.riseTimeS), pct(m_d.beforeFigures.overshoot));
    text += "\n" + tr("Measured − predicted: rise time %1 µs, overshoot %2 percentage points; largest difference %3 % "
                      "of the step, rms %4 % over %5 samples.")
                       .arg(us(mf.riseTimeS - pf.riseTimeS), pct(mf.overshoot - pf.overshoot),
                            pct(m_d.difference.maxAbs), pct(m_d.difference.rms))
                       .arg(m_d.difference.samples);
    if (m_d.measuredCapture) {
        const auto* clamped = m_d.measuredCapture->metadata.find(model::meta::kVoltageClampedTicks);
        if (clamped && *clamped != "0")
            text += "\n" + tr("The voltage clamp acted in %1 current periods: the measured step is not the linear loop "
                              "the prediction describes; use a smaller step.")
                               .arg(QString::fromStdString(clamped->text()));
    }
    return text + "\n" + m_d.measuredVerdict;
}

bool CurrentLoopVerifyPage::isComplete() const
{
    return m_readRequest == 0;
}

} // namespace gui
} // namespace axistune

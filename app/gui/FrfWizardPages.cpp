// SPDX-License-Identifier: GPL-3.0-or-later
// Pages of the frequency-response wizard (FrfWizard.h, docs/wizards/frf.md). The maths lives in
// core: the amplitude limit and the motion time come from the drive itself (Drive::limits and
// Drive::planTest through DriveController, docs/drive-seam.md), the open loop from
// dsp::openLoopFromClosedLoop and the resonances from tuning::findResonances
// (spec/current-loop-and-multisweep-frf.md §4.3 step 7).
#include "app/gui/AppContext.h"
#include "app/gui/FrfWizard.h"
#include "core/device/FrfQuantityName.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/model/Constants.h"
#include "core/model/MetadataKeys.h"
#include "core/tuning/PositionPid.h"
#include "widgets/BodePlot.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <cmath>
#include <complex>
#include <limits>

namespace axistune {
namespace gui {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Whether a measured FRF's `quantity` metadata (FrfResultPage::quantity) names `q`.
bool isQuantity(const QString& name, device::FrfQuantity q)
{
    return name.toStdString() == device::frfQuantityMetadataName(q);
}

double valueOr(const model::ParameterValues& v, const char* key, double fallback)
{
    const auto it = v.find(key);
    return it == v.end() ? fallback : it->second;
}

QString hz(double f) { return QCoreApplication::translate("FrfResultPage", "%1 Hz").arg(f, 0, 'f', f < 100 ? 1 : 0); }
}  // namespace

double FrfDriveInfo::ratedTorqueNm() const
{
    return model::ratedTorqueNm(valueOr(values, "motor.rated_current", kNaN),
                                valueOr(values, "motor.torque_constant", kNaN));
}

double FrfDriveInfo::maxAmplitudePct() const
{
    return limits ? limits->frfAmplitudeMaxPct : kNaN;
}

double FrfDriveInfo::maxPeak() const
{
    return limits && limits->frfPeakMax > 0.0 ? limits->frfPeakMax : kNaN;
}

QString FrfDriveInfo::outputSignal() const
{
    return capabilities ? QString::fromStdString(capabilities->frfOutputSignal) : QString();
}

double FrfDriveInfo::traceRateHz() const
{
    const double fs = 1.0 / (valueOr(values, "trace.divider", kNaN) * valueOr(values, "velocity.period", kNaN));
    if (std::isfinite(fs))
        return fs;
    // A drive without those parameters (hal:: the servo thread's rate) states its trace rate itself.
    return capabilities && capabilities->traceRateHz > 0.0 ? capabilities->traceRateHz : kNaN;
}

// ---------------------------------------------------------------------------------------------
// FrfSafetyPage

FrfSafetyPage::FrfSafetyPage(AppContext& ctx, QWidget* parent) : SafetyPage(ctx, parent), m_ctx(ctx)
{
    setObjectName("frfSafetyPage");
    // The keys a drive has are shown (a LinuxCNC pid has the second row's).
    setLimitKeys({"motor.rated_current", "motor.torque_constant", "motor.max_current", "drive.max_voltage",
                  "velocity.kp", "velocity.ki", "velocity.inertia", "trace.divider", "maxoutput", "maxerror", "Pgain",
                  "Igain", "Dgain"});
    setMotionDescription(
        tr("The axis holds velocity 0 in velocity mode while a small torque disturbance is added to the "
           "velocity-controller output. The axis vibrates with small amplitude at each test frequency; it does "
           "not travel. Abort stops the excitation at once and restores the parameters."));
    auto* row = new QWidget(this);
    auto* form = new QFormLayout(row);
    m_form = form;
    form->setContentsMargins(0, 0, 0, 0);
    m_amplitude = new QDoubleSpinBox(row);
    m_amplitude->setObjectName("frfAmplitude");
    m_amplitude->setRange(0.1, 100.0);  // above the drive's maximum: refused with a message, not clamped
    m_amplitude->setDecimals(1);
    m_amplitude->setSingleStep(0.5);
    m_amplitude->setValue(5.0);
    m_amplitude->setSuffix(tr(" % of rated torque"));
    form->addRow(tr("Excitation amplitude:"), m_amplitude);
    m_peak = new QDoubleSpinBox(row);
    m_peak->setObjectName("frfAmplitudePeak");
    m_peak->setRange(0.0, 1e9); // above the drive's maximum: refused with a message, not clamped
    m_peak->setDecimals(4);
    m_peak->setSingleStep(0.01);
    m_peak->setValue(0.0); // set from the drive's limit when it is read
    form->addRow(tr("Excitation peak:"), m_peak);
    form->setRowVisible(m_peak, false);
    m_amplitudeText = new QLabel(row);
    m_amplitudeText->setObjectName("frfAmplitudeText");
    m_amplitudeText->setWordWrap(true);
    form->addRow(QString(), m_amplitudeText);
    // Above the confirmation, so that the confirmation covers the amplitude.
    if (auto* lay = qobject_cast<QVBoxLayout*>(layout()))
        lay->insertWidget(lay->count() - 1, row);
    registerField("amplitudePct", m_amplitude, "value", SIGNAL(valueChanged(double)));
    registerField("amplitudePeak", m_peak, "value", SIGNAL(valueChanged(double)));
    auto amplitudeChanged = [this] {
        confirmation()->setChecked(false);  // a new amplitude needs a new confirmation
        showAmplitude();
        emit completeChanged();
    };
    connect(m_amplitude, &QDoubleSpinBox::valueChanged, this, amplitudeChanged);
    connect(m_peak, &QDoubleSpinBox::valueChanged, this, amplitudeChanged);
    if (auto* axisBox = findChild<QComboBox*>())
        connect(axisBox, &QComboBox::currentTextChanged, this, [this] { readInfo(); });
    showAmplitude();
}

void FrfSafetyPage::initializePage()
{
    SafetyPage::initializePage();
    readInfo();
}

void FrfSafetyPage::readInfo()
{
    m_info = {};
    showAmplitude();
    m_infoPending = m_ctx.drive().isConnected() && !axis().isEmpty();
    if (m_infoPending) {
        // The drive's values and its own limits (the wizard never assumes the simulator's).
        m_answersPending = 2;
        auto onAnswer = [this](const DriveReply& r) {
            if (!m_infoPending || (r.id != m_request && r.id != m_describeRequest))
                return;
            m_info.axis = r.axis;
            if (r.id == m_request) {
                m_info.values = r.ok ? r.values : model::ParameterValues{};
            } else {
                m_info.limits = r.ok ? r.limits : std::nullopt;
                m_info.capabilities = r.ok ? r.capabilities : std::nullopt;
                m_info.limitsError = r.ok ? QString() : r.error;
            }
            if (--m_answersPending > 0)
                return;
            m_infoPending = false;
            showAmplitudeMode();
            showAmplitude();
            emit driveInfoChanged();
            emit completeChanged();
        };
        auto* read = m_ctx.drive().readParameters(axis());
        m_request = read->id();
        connect(read, &DriveRequest::finished, this, onAnswer);
        auto* describe = m_ctx.drive().describeAxis(axis());
        m_describeRequest = describe->id();
        connect(describe, &DriveRequest::finished, this, onAnswer);
    }
    emit completeChanged();
}

void FrfSafetyPage::showAmplitudeMode()
{
    const bool peak = m_info.peakInOutputUnits();
    m_form->setRowVisible(m_amplitude, !peak);
    m_form->setRowVisible(m_peak, peak);
    if (!peak) {
        setMotionDescription(
            tr("The axis holds velocity 0 in velocity mode while a small torque disturbance is added to the "
               "velocity-controller output. The axis vibrates with small amplitude at each test frequency; it does "
               "not travel. Abort stops the excitation at once and restores the parameters."));
        return;
    }
    const QString signal = m_info.outputSignal();
    m_peak->setSuffix(tr(" (units of %1)").arg(signal));
    const double maxPeak = m_info.maxPeak();
    // A fifth of the drive's limit to start with (hal:: a tenth of maxoutput), in the output's own units.
    if (std::isfinite(maxPeak) && (m_peak->value() <= 0.0 || m_peak->value() > maxPeak)) {
        const QSignalBlocker block(m_peak);
        m_peak->setDecimals(std::clamp(3 - static_cast<int>(std::floor(std::log10(maxPeak))), 2, 9));
        const double v = 0.2 * maxPeak;
        const double step = std::pow(10.0, std::floor(std::log10(v)) - 1.0); // two significant digits
        m_peak->setValue(std::floor(v / step) * step);
    }
    setMotionDescription(tr("The NC keeps closing its position loop while a small multisine is added to %1, the "
                            "drive's input, at every servo period. The axis vibrates with small amplitude about "
                            "where it stands; it does not travel. A following error above the limit or Abort stops "
                            "the excitation at once, and what AxisTune inserted into the machine is removed.")
                             .arg(signal));
}

void FrfSafetyPage::showAmplitude()
{
    if (m_info.peakInOutputUnits()) {
        const double peak = m_peak->value();
        const double maxPeak = m_info.maxPeak();
        const QString signal = m_info.outputSignal();
        if (!std::isfinite(maxPeak)) {
            m_amplitudeText->setText(tr("<span style='color:#b00000'>The drive states no limit for the peak in the "
                                        "units of %1: no test.</span>")
                                         .arg(signal.toHtmlEscaped()));
        } else if (!(peak > 0.0)) {
            m_amplitudeText->setText(tr("<span style='color:#b00000'>Refused: the peak must be above 0.</span>"));
        } else if (peak > maxPeak) {
            m_amplitudeText->setText(tr("<span style='color:#b00000'>Refused: the drive allows a peak of at most %1 "
                                        "in the units of %2.</span>")
                                         .arg(maxPeak, 0, 'g', 4)
                                         .arg(signal.toHtmlEscaped()));
        } else {
            m_amplitudeText->setText(tr("Peak %1 of the injected signal, in the units of %2 (the drive allows at "
                                        "most %3, %4 % of its output limit).")
                                         .arg(peak, 0, 'g', 4)
                                         .arg(signal)
                                         .arg(maxPeak, 0, 'g', 4)
                                         .arg(m_info.maxAmplitudePct(), 0, 'g', 3));
        }
        return;
    }
    const double pct = m_amplitude->value();
    const double maxPct = m_info.maxAmplitudePct();
    if (!m_infoPending && !m_info.axis.isEmpty() && !std::isfinite(maxPct)) {
        m_amplitudeText->setText(tr("<span style='color:#b00000'>The drive does not state its amplitude limit: "
                                    "%1</span>")
                                     .arg(m_info.limitsError.toHtmlEscaped()));
        return;
    }
    if (!std::isfinite(maxPct)) {
        m_amplitudeText->setText(tr("%1 % of rated torque (reading the drive's limit…).").arg(pct));
        return;
    }
    if (pct > maxPct) {
        m_amplitudeText->setText(tr("<span style='color:#b00000'>Refused: the drive allows at most %1 % of rated "
                                    "torque.</span>")
                                     .arg(maxPct));
        return;
    }
    const double rated = m_info.ratedTorqueNm();
    if (!std::isfinite(rated)) {
        m_amplitudeText->setText(tr("%1 % of rated torque (at most %2 %).").arg(pct).arg(maxPct));
        return;
    }
    m_amplitudeText->setText(tr("%1 % of the rated torque %2 N·m = %3 N·m peak of the injected torque (at most %4 %).")
                                 .arg(pct)
                                 .arg(rated, 0, 'g', 4)
                                 .arg(model::torqueNmFromRatedPct(pct, rated), 0, 'g', 4)
                                 .arg(maxPct));
}

bool FrfSafetyPage::isComplete() const
{
    // An unknown limit (NaN) fails the comparison: the drive must state it before the test is offered.
    if (m_info.peakInOutputUnits())
        return SafetyPage::isComplete() && !m_infoPending && m_peak->value() > 0.0 &&
               m_peak->value() <= m_info.maxPeak();
    return SafetyPage::isComplete() && !m_infoPending && m_amplitude->value() <= m_info.maxAmplitudePct();
}

// ---------------------------------------------------------------------------------------------
// FrfConfigPage

FrfConfigPage::FrfConfigPage(AppContext& ctx, const FrfSafetyPage& safety, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_safety(safety)
{
    setObjectName("frfConfigPage");
    setTitle(tr("Method and band"));
    setSubTitle(tr("How the axis is excited and which frequencies are measured."));
    auto* lay = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_method = new QComboBox(this);
    m_method->setObjectName("frfMethod");
    form->addRow(tr("Method:"), m_method);
    m_quantity = new QComboBox(this);
    m_quantity->setObjectName("frfQuantity");
    m_quantityLabel = new QLabel(tr("Measured quantity:"), this);
    form->addRow(m_quantityLabel, m_quantity);
    offerMethods();
    m_fmin = new QDoubleSpinBox(this);
    m_fmin->setObjectName("frfFmin");
    m_fmin->setRange(0.1, 100000.0);
    m_fmin->setDecimals(1);
    m_fmin->setValue(10.0);
    m_fmin->setSuffix(tr(" Hz"));
    form->addRow(tr("Lowest frequency:"), m_fmin);
    m_fmax = new QDoubleSpinBox(this);
    m_fmax->setObjectName("frfFmax");
    m_fmax->setRange(0.1, 100000.0);
    m_fmax->setDecimals(1);
    m_fmax->setValue(3900.0);
    m_fmax->setSuffix(tr(" Hz"));
    form->addRow(tr("Highest frequency:"), m_fmax);
    m_points = new QSpinBox(this);
    m_points->setObjectName("frfPoints");
    m_points->setRange(1, 5000);
    m_points->setValue(60);
    form->addRow(tr("Frequencies (log-spaced):"), m_points);
    m_adaptive = new QCheckBox(tr("Adaptive: excite the lines not yet valid again"), this);
    m_adaptive->setToolTip(tr("After the first multisine, the lines not yet valid are excited again (shaped by 1/|H| "
                              "and their noise, more periods where needed) until every line is valid or the time "
                              "budget is spent."));
    m_adaptive->setObjectName("frfAdaptive");
    form->addRow(QString(), m_adaptive);
    m_budget = new QDoubleSpinBox(this);
    m_budget->setObjectName("frfTimeBudget");
    m_budget->setRange(0.5, 120.0);
    m_budget->setDecimals(1);
    m_budget->setValue(5.0);
    m_budget->setSuffix(tr(" s"));
    m_budgetLabel = new QLabel(tr("Motion time of all passes, at most:"), this);
    form->addRow(m_budgetLabel, m_budget);
    lay->addLayout(form);
    m_validity = new QLabel(this);
    m_validity->setWordWrap(true);
    lay->addWidget(m_validity);
    m_estimate = new QLabel(this);
    m_estimate->setObjectName("frfEstimate");
    m_estimate->setWordWrap(true);
    lay->addWidget(m_estimate);
    lay->addStretch(1);
    registerField("method", m_method);
    registerField("fminHz", m_fmin, "value", SIGNAL(valueChanged(double)));
    registerField("fmaxHz", m_fmax, "value", SIGNAL(valueChanged(double)));
    registerField("points", m_points);

    auto changed = [this] {
        ++m_generation;
        m_planOk = false;
        emit completeChanged();
        updateEstimate();
    };
    connect(m_method, &QComboBox::currentIndexChanged, this, changed);
    connect(m_quantity, &QComboBox::currentIndexChanged, this, changed);
    connect(m_fmin, &QDoubleSpinBox::valueChanged, this, changed);
    connect(m_fmax, &QDoubleSpinBox::valueChanged, this, changed);
    connect(m_points, &QSpinBox::valueChanged, this, changed);
    connect(m_adaptive, &QCheckBox::toggled, this, [this, changed] {
        offerAdaptive();
        changed();
    });
    connect(m_budget, &QDoubleSpinBox::valueChanged, this, changed);
    connect(m_method, &QComboBox::currentIndexChanged, this, [this] { offerAdaptive(); });
    offerAdaptive();
    connect(&m_safety, &FrfSafetyPage::driveInfoChanged, this, [this, changed] {
        offerMethods();
        if (wizard() && wizard()->currentPage() == this)
            changed();
    });
}

device::FrfMethod FrfConfigPage::selectedMethod() const
{
    return static_cast<device::FrfMethod>(m_method->currentData().toInt());
}

std::optional<double> FrfConfigPage::adaptiveBudgetS() const
{
    if (m_adaptive->isHidden() || !m_adaptive->isChecked() || selectedMethod() != device::FrfMethod::Multisine)
        return std::nullopt;
    return m_budget->value();
}

void FrfConfigPage::offerAdaptive()
{
    // The passes are shaped on the host from the drive's plan in % of rated torque (device::runAdaptiveFrf): not on
    // a drive that measures in its output's own units (hal:, linuxcnc:).
    if (!m_adaptive)
        return; // offerMethods() in the constructor, before the box exists
    const bool offered = selectedMethod() == device::FrfMethod::Multisine && !m_safety.driveInfo().peakInOutputUnits();
    m_adaptive->setVisible(offered);
    const bool budget = offered && m_adaptive->isChecked();
    m_budget->setVisible(budget);
    m_budgetLabel->setVisible(budget);
}

device::FrfQuantity FrfConfigPage::selectedQuantity() const
{
    return m_quantity->count() > 0 ? static_cast<device::FrfQuantity>(m_quantity->currentData().toInt())
                                   : device::FrfQuantity::Default;
}

void FrfConfigPage::offerMethods()
{
    // The methods and quantities the drive advertises (Drive::capabilities); all methods while they are unknown.
    const auto& caps = m_safety.driveInfo().capabilities;
    const QSignalBlocker blockMethod(m_method);
    const QSignalBlocker blockQuantity(m_quantity);
    const int keep = m_method->currentIndex() >= 0 ? m_method->currentData().toInt() : -1;
    m_method->clear();
    const std::pair<device::FrfMethod, QString> methods[] = {
        {device::FrfMethod::MultiSweep, tr("Multi-sweep sine stream (valid up to the trace rate)")},
        {device::FrfMethod::Conventional, tr("Conventional sine stream (valid up to half the trace rate)")},
        {device::FrfMethod::Prbs, tr("PRBS with Welch averaging and coherence (up to half the trace rate)")},
        {device::FrfMethod::Multisine, tr("Multisine, all lines at once (valid up to the trace rate)")},
    };
    for (const auto& [m, text] : methods)
        if (!caps || caps->offers(m))
            m_method->addItem(text, int(m));
    if (const int i = m_method->findData(keep); i >= 0)
        m_method->setCurrentIndex(i);
    const int keepQuantity = m_quantity->currentIndex() >= 0 ? m_quantity->currentData().toInt() : -1;
    m_quantity->clear();
    if (caps)
        for (auto q : caps->frfQuantities) {
            if (q == device::FrfQuantity::Plant)
                m_quantity->addItem(tr("Plant: feedback / drive input"), int(q));
            else if (q == device::FrfQuantity::OpenLoop)
                m_quantity->addItem(tr("Open loop with the running gains: −controller output / drive input"), int(q));
        }
    if (const int i = m_quantity->findData(keepQuantity); i >= 0)
        m_quantity->setCurrentIndex(i);
    m_quantity->setVisible(m_quantity->count() > 0);
    m_quantityLabel->setVisible(m_quantity->count() > 0);
    offerAdaptive();
}

void FrfConfigPage::initializePage()
{
    offerMethods();
    const double fs = m_safety.driveInfo().traceRateHz();
    const double frfMax = m_safety.driveInfo().frfMaxHz();
    if (frfMax > 0.0) {
        // The drive's own limit (hal:: lines below half the servo rate): the default band ends at 90 % of it.
        m_validity->setText(tr("Trace rate fs = %1 Hz. This drive measures lines below %2 Hz only; the band must end "
                               "below that.")
                                .arg(fs, 0, 'f', 0)
                                .arg(frfMax, 0, 'f', 0));
        if (m_fmax->value() >= frfMax)
            m_fmax->setValue(std::floor(0.9 * frfMax));
        if (m_method->count() == 0)
            m_validity->setText(m_validity->text() + QLatin1Char(' ') +
                                tr("<span style='color:#b00000'>The drive offers no FRF method on this axis.</span>"));
    } else if (std::isfinite(fs)) {
        m_validity->setText(tr("Trace rate fs = %1 Hz. The multi-sweep and multisine methods measure up to fs; the "
                               "conventional sine stream and PRBS only up to fs/2 = %2 Hz (points above are marked "
                               "not valid).")
                                .arg(fs, 0, 'f', 0)
                                .arg(fs / 2.0, 0, 'f', 0));
        if (m_fmax->value() >= fs)
            m_fmax->setValue(std::floor(0.975 * fs));
    } else {
        m_validity->setText(tr("The trace rate of the drive is unknown."));
    }
    ++m_generation;
    m_planOk = false;
    updateEstimate();
}

void FrfConfigPage::updateEstimate()
{
    if (m_pendingGeneration >= 0)
        return;  // one computation at a time; the finished handler starts the next
    auto* w = qobject_cast<FrfWizard*>(wizard());
    if (!w)
        return;
    if (!m_ctx.drive().isConnected()) {
        m_estimate->setText(
            tr("<span style='color:#b00000'>The drive would refuse this test: %1</span>").arg(tr("not connected")));
        return;
    }
    m_estimate->setText(tr("Estimating the motion time…"));
    m_pendingGeneration = m_generation;
    // The drive plans the test (Drive::planTest): its motion time, or its reason to refuse the request.
    auto* req = m_ctx.drive().planTest(w->request());
    m_planRequest = req->id();
    connect(req, &DriveRequest::finished, this, [this](const DriveReply& r) {
        if (r.id != m_planRequest)
            return;
        m_planRequest = -1;
        const bool stale = m_pendingGeneration != m_generation;
        m_pendingGeneration = -1;
        if (stale) {  // the settings changed meanwhile
            updateEstimate();
            return;
        }
        m_planOk = r.ok && r.plan.has_value();
        m_motionS = m_planOk ? r.plan->motionTimeS : kNaN;
        const auto budget = adaptiveBudgetS();
        if (!m_planOk)
            m_estimate->setText(tr("<span style='color:#b00000'>The drive would refuse this test: %1</span>")
                                    .arg(r.error.toHtmlEscaped()));
        else if (budget && m_motionS > *budget) {
            // device::runAdaptiveFrf refuses a first pass longer than the budget.
            m_planOk = false;
            m_estimate->setText(tr("<span style='color:#b00000'>The first pass takes %1 s of motion, more than the "
                                   "time budget of %2 s.</span>")
                                    .arg(m_motionS, 0, 'f', 2)
                                    .arg(*budget, 0, 'f', 1));
        } else if (budget)
            m_estimate->setText(tr("Estimated motion time of the first pass: %1 s (settling included); with the "
                                   "passes after it at most %2 s.")
                                    .arg(m_motionS, 0, 'f', 1)
                                    .arg(*budget, 0, 'f', 1));
        else
            m_estimate->setText(tr("Estimated motion time: %1 s (settling included).").arg(m_motionS, 0, 'f', 1));
        emit completeChanged();
    });
}

bool FrfConfigPage::isComplete() const { return m_planOk && m_pendingGeneration < 0; }

// ---------------------------------------------------------------------------------------------
// FrfResultPage

FrfResultPage::FrfResultPage(QWidget* parent) : QWizardPage(parent)
{
    setObjectName("frfResultPage");
    setTitle(tr("Frequency response"));
    setSubTitle(tr("The measured closed velocity loop, where it is valid, and the resonances found."));
    auto* lay = new QVBoxLayout(this);
    auto* split = new QSplitter(Qt::Vertical, this);
    m_plot = new widgets::BodePlot(split);
    m_plot->setObjectName("frfBodePlot");
    m_plot->setMinimumHeight(300);
    auto* bottom = new QWidget(split);
    auto* bl = new QVBoxLayout(bottom);
    bl->setContentsMargins(0, 0, 0, 0);
    m_summary = new QLabel(bottom);
    m_summary->setObjectName("frfSummary");
    m_summary->setWordWrap(true);
    bl->addWidget(m_summary);
    m_adaptiveText = new QLabel(bottom);
    m_adaptiveText->setObjectName("frfAdaptiveSummary");
    m_adaptiveText->setWordWrap(true);
    m_adaptiveText->hide();
    bl->addWidget(m_adaptiveText);
    m_table = new QTableWidget(bottom);
    m_table->setObjectName("resonanceTable");
    m_table->setColumnCount(4);
    m_table->setHorizontalHeaderLabels({tr("Frequency [Hz]"), tr("Peak [dB]"), tr("Width (−3 dB) [Hz]"),
                                        tr("Open-loop gain [dB]")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    bl->addWidget(m_table);
    split->addWidget(m_plot);
    split->addWidget(bottom);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 1);
    lay->addWidget(split);
    m_watcher = new QFutureWatcher<FrfAnalysis>(this);
    connect(m_watcher, &QFutureWatcherBase::finished, this, [this] {
        m_analysis = m_watcher->result();
        m_done = true;
        showAnalysis();
        emit completeChanged();
    });
}

void FrfResultPage::setMeasurement(const dsp::FrequencyResponse& frf, device::FrfMethod method, double frfMaxHz,
                                   const QString& outputSignal)
{
    m_frf = frf;
    m_method = method;
    m_frfMaxHz = frfMaxHz;
    m_outputSignal = outputSignal;
    m_quantity = QString::fromStdString(frf.metadata.textOr(model::meta::kQuantity, ""));
    m_done = false;
    m_analysis = {};
    // The rate only draws the validity bands and the note under the plot: 0 (unknown) when unreadable.
    const auto fs = frf.metadata.number(model::meta::kFsHz);
    m_fsHz = fs ? *fs : 0.0;
}

void FrfResultPage::setAdaptiveSummary(const QString& text)
{
    m_adaptiveText->setText(text);
    m_adaptiveText->setVisible(!text.isEmpty());
}

void FrfResultPage::initializePage()
{
    m_plot->clearResponses();
    m_plot->clearBands();
    m_plot->clearMarkers();
    m_table->setRowCount(0);
    if (m_frf.empty()) {
        m_summary->setText(tr("No frequency response was measured."));
        return;
    }
    // The quantity and its units as the drive's metadata name them (hal:: the plant or the open position loop).
    const QString signal = m_outputSignal.isEmpty() ? tr("the drive input") : m_outputSignal;
    if (isQuantity(m_quantity, device::FrfQuantity::Plant)) {
        setSubTitle(tr("The measured plant: feedback per unit of drive input (%1 plus the injection), where it is "
                       "valid, and the resonances found.")
                        .arg(signal));
        m_plot->setMagnitudeTitle(tr("Plant [dB]"));
    } else if (isQuantity(m_quantity, device::FrfQuantity::OpenLoop)) {
        setSubTitle(tr("The measured open position loop with the running gains: −controller output / drive input "
                       "(dimensionless), where it is valid, and the resonances found."));
        m_plot->setMagnitudeTitle(tr("Open loop |L| [dB]"));
    } else {
        setSubTitle(tr("The measured closed velocity loop, where it is valid, and the resonances found."));
        m_plot->setMagnitudeTitle(QString());
    }
    m_table->setHorizontalHeaderItem(3, new QTableWidgetItem(m_quantity.isEmpty()
                                                                 ? tr("Open-loop gain [dB]")
                                                                 : tr("Level of the analysed response [dB]")));
    m_plot->addResponse(m_frf, isQuantity(m_quantity, device::FrfQuantity::Plant)      ? tr("Measured plant")
                               : isQuantity(m_quantity, device::FrfQuantity::OpenLoop) ? tr("Measured open loop")
                                                                                       : tr("Measured"));
    addBands();
    m_plot->setFrequencyRange(m_frf.freqHz.front() / 1.15, m_frf.freqHz.back() * 1.15);
    m_summary->setText(tr("Analysing…"));
    if (m_done) {
        showAnalysis();
        return;
    }
    const dsp::FrequencyResponse frf = m_frf;
    m_watcher->setFuture(QtConcurrent::run([frf] {
        FrfAnalysis a;
        const auto* m = frf.metadata.find(model::meta::kMeasurement);
        const bool complementary = m && *m == "complementary";
        const auto form = complementary ? dsp::openLoopFromClosedLoop(frf, dsp::LoopMeasurement::Complementary) : frf;
        a.analysedForm = complementary
                             ? QCoreApplication::translate("FrfResultPage", "the open loop L = T/(1−T) of the measured T")
                             : QCoreApplication::translate("FrfResultPage", "the measured response");
        const auto* q = frf.metadata.find(model::meta::kQuantity);
        if (q && *q == device::frfQuantityMetadataName(device::FrfQuantity::Plant)) {
            // A plant falls as its rigid body (f⁻² under torque, f⁻¹ under a velocity command), with an anti-resonance
            // before each resonance: its resonance is the peak of |P|·ω^order above the median of the band, as
            // pid-tune reads it (tuning::plantResonance), not an outlier of a local baseline.
            std::vector<double> f;
            std::vector<std::complex<double>> h;
            for (std::size_t i = 0; i < frf.size(); ++i)
                if (i >= frf.valid.size() || frf.valid[i]) {
                    f.push_back(frf.freqHz[i]);
                    h.push_back(frf.h[i]);
                }
            auto input = tuning::driveInputFromSlope(f, h);
            if (!input) {
                a.error = QString::fromStdString(input.error().detail);
                return a;
            }
            a.analysedForm = *input == tuning::DriveInput::Torque
                                 ? QCoreApplication::translate("FrfResultPage",
                                                               "|plant|·ω² (flat for the rigid body of a torque drive; "
                                                               "its peak at least 6 dB above its median)")
                                 : QCoreApplication::translate(
                                       "FrfResultPage", "|plant|·ω (flat for a velocity drive; its peak at least "
                                                        "6 dB above its median)");
            if (auto r = tuning::plantResonance(f, h, *input, 0.0))
                a.resonances.push_back(*r);
            return a;
        }
        tuning::ResonanceOptions o;
        o.fminHz = frf.freqHz.front();
        o.fmaxHz = frf.freqHz.back();
        auto r = tuning::findResonances(form, o);
        if (r)
            a.resonances = *r;
        else
            a.error = QString::fromStdString(r.error().detail);
        return a;
    }));
}

bool FrfResultPage::isComplete() const { return m_done; }

void FrfResultPage::addBands()
{
    const auto& f = m_frf.freqHz;
    const double top = f.back() * 1.15;
    if (m_frfMaxHz > 0.0) {
        // The drive measures nothing from its own limit up (hal:: half the servo rate), by any method.
        if (top > m_frfMaxHz)
            m_plot->addBand(m_frfMaxHz, std::max(top, 2.0 * m_frfMaxHz), widgets::BodePlot::BandKind::NotMeasurable);
    } else if (m_fsHz > 0.0) {
        if (top > m_fsHz / 2.0)
            m_plot->addBand(m_fsHz / 2.0, m_fsHz, widgets::BodePlot::BandKind::MultiSweepOnly);
        if (top > m_fsHz)
            m_plot->addBand(m_fsHz, std::max(top, 2.0 * m_fsHz), widgets::BodePlot::BandKind::NotMeasurable);
    }
    // Runs of points the method could not measure (voltage limit, above fs/2 for the single-sweep
    // methods). Above fs/2 the single-sweep methods are already explained by the multi-sweep band.
    const bool halfBand = m_method == device::FrfMethod::Conventional || m_method == device::FrfMethod::Prbs;
    const std::size_t n = f.size();
    for (std::size_t i = 0; i < n;) {
        if (m_frf.valid[i]) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j + 1 < n && !m_frf.valid[j + 1])
            ++j;
        const double from = i > 0 ? std::sqrt(f[i - 1] * f[i]) : f[i] / 1.05;
        const double to = j + 1 < n ? std::sqrt(f[j] * f[j + 1]) : f[j] * 1.05;
        if (!(halfBand && m_fsHz > 0.0 && f[i] >= m_fsHz / 2.0))
            m_plot->addBand(from, to, widgets::BodePlot::BandKind::NotMeasurable);
        i = j + 1;
    }
}

void FrfResultPage::showAnalysis()
{
    m_plot->clearMarkers();
    m_table->setRowCount(0);
    std::size_t valid = 0;
    for (bool v : m_frf.valid)
        valid += v ? 1 : 0;
    QString text = tr("%1 of %2 points valid.").arg(valid).arg(m_frf.size());
    const QString signal = m_outputSignal.isEmpty() ? tr("the drive input") : m_outputSignal;
    if (isQuantity(m_quantity, device::FrfQuantity::Plant))
        text = tr("Plant in the feedback's position units per unit of %1 (the configuration's units, e.g. mm per "
                  "N·m).")
                   .arg(signal) +
               QLatin1Char(' ') + text;
    else if (isQuantity(m_quantity, device::FrfQuantity::OpenLoop))
        text = tr("Open position loop, dimensionless (controller output per unit of %1).").arg(signal) +
               QLatin1Char(' ') + text;
    if (m_fsHz > 0.0)
        text += QLatin1Char(' ') + tr("Trace rate fs = %1 Hz.").arg(m_fsHz, 0, 'f', 0);
    if (!m_analysis.error.isEmpty()) {
        text += QLatin1Char(' ') + tr("No resonance list: %1").arg(m_analysis.error);
    } else if (m_analysis.resonances.empty()) {
        text += QLatin1Char(' ') + tr("No resonance found in %1.").arg(m_analysis.analysedForm);
    } else {
        text += QLatin1Char(' ') + tr("%n resonance(s) found in %1:", nullptr, static_cast<int>(m_analysis.resonances.size()))
                                       .arg(m_analysis.analysedForm);
    }
    m_summary->setText(text);
    for (const auto& r : m_analysis.resonances) {
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        m_table->setItem(row, 0, new QTableWidgetItem(QString::number(r.freqHz, 'f', 1)));
        m_table->setItem(row, 1, new QTableWidgetItem(QString::number(r.peakDb, 'f', 1)));
        auto* w = new QTableWidgetItem(QString::number(r.widthHz, 'f', 1));
        if (r.widthOneSided)
            w->setToolTip(tr("Only one −3 dB crossing inside the band: twice the half width."));
        m_table->setItem(row, 2, w);
        m_table->setItem(row, 3, new QTableWidgetItem(QString::number(r.levelDb, 'f', 1)));
        m_plot->addMarker(r.freqHz, widgets::BodePlot::MarkerKind::Resonance, hz(r.freqHz));
    }
}

// ---------------------------------------------------------------------------------------------
// FrfSavePage

FrfSavePage::FrfSavePage(QWidget* parent) : QWizardPage(parent)
{
    setObjectName("frfSavePage");
    setTitle(tr("Save"));
    setSubTitle(tr("Finish stores the measurement as a session of this machine."));
    auto* lay = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_note = new QLineEdit(this);
    m_note->setObjectName("frfNote");
    m_note->setPlaceholderText(tr("e.g. before notch tuning, table empty"));
    form->addRow(tr("Note:"), m_note);
    lay->addLayout(form);
    m_status = new QLabel(this);
    m_status->setObjectName("frfSaveStatus");
    m_status->setWordWrap(true);
    lay->addWidget(m_status);
    m_openDocument = new QCheckBox(tr("Show the saved session as a document (its Bode plot stays open after Finish)"),
                                   this);
    m_openDocument->setObjectName("frfOpenDocument");
    m_openDocument->setChecked(true);
    lay->addWidget(m_openDocument);
    m_openNotch = new QPushButton(tr("Save and open in the notch wizard"), this);
    m_openNotch->setObjectName("frfOpenNotch");
    m_openNotch->setToolTip(tr("Stores the session, then proposes notch filters for the resonances of this "
                               "measurement."));
    auto* row = new QHBoxLayout;
    row->addWidget(m_openNotch);
    row->addStretch(1);
    lay->addLayout(row);
    lay->addStretch(1);
}

void FrfSavePage::showSaved(const QString& text) { m_status->setText(text); }

}  // namespace gui
}  // namespace axistune

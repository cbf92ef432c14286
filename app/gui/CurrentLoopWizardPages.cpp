// SPDX-License-Identifier: GPL-3.0-or-later
// Pages of the current-loop wizard (CurrentLoopWizard.h; docs/wizards/current-loop.md): motor data,
// design (k_p–k_i plane, rise time against α, schedule), step responses, verification.
// Method: spec/current-loop-and-multisweep-frf.md chapter 2 (core/tuning/CurrentLoop.h).
#include "app/gui/AppContext.h"
#include "app/gui/ParameterLookup.h"
#include "app/gui/WidgetUtil.h"
#include "app/gui/CurrentLoopWizard.h"
#include "app/gui/WizardPages.h"
#include "core/store/Database.h"
#include "widgets/CurvePlot.h"
#include "core/io/Profile.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

namespace {

constexpr int kCurvePoints = 60;

/// Boundary curve with k_i = 0 (no admissible k_i) as gaps.
std::vector<double> gapsAtZero(const std::vector<double>& ki)
{
    std::vector<double> out = ki;
    for (double& v : out)
        if (!(v > 0.0))
            v = std::nan("");
    return out;
}

double maxOf(const std::vector<double>& v)
{
    double m = 0.0;
    for (double x : v)
        if (std::isfinite(x))
            m = std::max(m, x);
    return m;
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Motor data

CurrentLoopMotorPage::CurrentLoopMotorPage(AppContext& ctx, CurrentLoopData& shared, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared)
{
    setTitle(tr("Current loop: motor data"));
    setSubTitle(tr("Enter the motor data or read them from the drive's motor parameters. Maximum current and maximum "
                   "voltage must use the same convention (both peak or both rms): only their ratio enters the "
                   "voltage constraint."));
    auto* lay = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    m_axis = new QComboBox(this);
    m_axis->setObjectName("clAxis");
    m_read = new QPushButton(tr("Read from drive"), this);
    m_read->setObjectName("clReadDrive");
    top->addWidget(new QLabel(tr("Axis:"), this));
    top->addWidget(m_axis, 1);
    top->addWidget(m_read);
    m_fromProfile = new QPushButton(tr("From profile"), this);
    m_fromProfile->setObjectName("clFromProfile");
    m_fromProfile->setToolTip(tr("The motor model of this axis in the machine's profile (saved by an earlier "
                                 "current-loop session or imported)"));
    top->addWidget(m_fromProfile);
    lay->addLayout(top);
    m_source = new QLabel(this);
    m_source->setObjectName("clSource");
    m_source->setWordWrap(true);
    lay->addWidget(m_source);

    auto* cols = new QHBoxLayout;
    auto* motor = new QGroupBox(tr("Motor"), this);
    auto* mf = new QFormLayout(motor);
    // Defaults: the rotary motor of Table 2.2 (rms values).
    m_r = spin(motor, 0, 1000, 0.32, 4, QString::fromUtf8(" Ω"), "clR");
    m_l = spin(motor, 0.001, 10000, 2.19, 4, " mH", "clL");
    m_imax = spin(motor, 0.01, 5000, 56.57, 2, " A", "clImax");
    m_vmax = spin(motor, 1, 5000, 200.0, 1, " V", "clVmax");
    m_delta = spin(motor, 0, 0.95, 0.24, 3, "", "clDelta");
    m_rated = spin(motor, 0, 5000, 10.82, 2, " A", "clRated");
    m_emf = spin(motor, 0, 10000, 43.53, 2, tr(" V(rms)/1000 min⁻¹"), "clEmf");
    m_speed = spin(motor, 0, 100000, 300, 0, tr(" min⁻¹"), "clSpeed");
    mf->addRow(tr("Armature resistance R_a:"), m_r);
    mf->addRow(tr("q-axis inductance L_q:"), m_l);
    mf->addRow(tr("Maximum current I_max:"), m_imax);
    mf->addRow(tr("Maximum voltage V_max:"), m_vmax);
    mf->addRow(tr("Inductance drop at I_max δ:"), m_delta);
    mf->addRow(tr("Rated current (0: not given):"), m_rated);
    mf->addRow(tr("Back-EMF constant, line-to-line (0: not given):"), m_emf);
    mf->addRow(tr("Contouring speed:"), m_speed);
    cols->addWidget(motor, 3);
    auto* set = new QGroupBox(tr("Design"), this);
    auto* sf = new QFormLayout(set);
    m_tau = spin(set, 0, 1000, 62.5, 3, QString::fromUtf8(" µs"), "clTau");
    m_gm = spin(set, 0, 20, tuning::kPaperGainMarginDb, 4, " dB", "clGm");
    m_os = spin(set, 0.1, 100, 10, 1, " %", "clOvershoot");
    m_ripple = spin(set, 0.1, 100, 5, 1, " %", "clRipple");
    sf->addRow(tr("Dead time τ of the design:"), m_tau);
    sf->addRow(tr("Gain margin:"), m_gm);
    sf->addRow(tr("Step overshoot limit:"), m_os);
    sf->addRow(tr("Current ripple of the voltage check (of I_max):"), m_ripple);
    cols->addWidget(set, 2);
    lay->addLayout(cols);
    m_check = new QLabel(this);
    m_check->setObjectName("clBackEmf");
    m_check->setWordWrap(true);
    lay->addWidget(m_check);
    lay->addStretch(1);

    for (auto* s : {m_r, m_l, m_imax, m_vmax, m_delta, m_rated, m_emf, m_speed})
        connect(s, &QDoubleSpinBox::valueChanged, this, [this] {
            updateCheck();
            emit completeChanged();
        });
    connect(m_read, &QPushButton::clicked, this, &CurrentLoopMotorPage::readFromDrive);
    connect(m_fromProfile, &QPushButton::clicked, this, &CurrentLoopMotorPage::takeFromProfile);
    updateCheck();
}

void CurrentLoopMotorPage::initializePage()
{
    m_axis->clear();
    m_axis->addItems(m_ctx.axes());
    const bool connected = m_ctx.drive().isConnected() && m_axis->count() > 0;
    m_read->setEnabled(connected);
    m_fromProfile->setEnabled(m_ctx.database() && !m_ctx.machine().isEmpty());
    if (connected)
        readFromDrive();
    else
        m_source->setText(tr("Not connected: enter the motor data (defaults: the rotary motor of Table 2.2, rms "
                             "values). Apply needs a connection."));
}

void CurrentLoopMotorPage::readFromDrive()
{
    if (m_axis->currentText().isEmpty() || !m_ctx.drive().isConnected())
        return;
    m_read->setEnabled(false);
    QStringList keys;
    for (const auto& k : tuning::motorParameterKeys())
        keys << QString::fromStdString(k);
    auto* req = m_ctx.drive().readParameters(m_axis->currentText(), keys);
    m_readRequest = req->id();
    connect(req, &DriveRequest::finished, this, [this](const DriveReply& r) {
        if (r.id != m_readRequest)
            return;
        m_readRequest = 0;
        m_read->setEnabled(true);
        if (!r.ok) {
            m_source->setText(tr("Reading the motor parameters failed: %1").arg(r.error));
            emit completeChanged();
            return;
        }
        auto get = [&](const char* k, double fallback) { return parameterOr(r.values, k, fallback); };
        // The drive offers the ratings and k_t (k_e = k_t/1.5); R_a, L_q and δ stay as entered (motor data sheet).
        setMotor(tuning::motorFromDriveParameters(r.values, motorFromFields()));
        m_d.drivePeriodS = get("current.period", m_d.drivePeriodS);
        m_d.driveDeadTimeS = get("current.dead_time", m_d.driveDeadTimeS);
        // The paper designs with τ = the current-control period.
        m_tau->setValue(m_d.drivePeriodS * 1e6);
        m_d.fromDrive = true;
        m_source->setText(
            tr("Read from axis %1 of the drive (peak values): maximum current, maximum voltage, rated "
               "current, current-loop period %2 µs, dead time %3 µs; the back-EMF constant from the torque "
               "constant (k_e = k_t/1.5, amplitude-invariant dq). The drive does not offer R_a, L_q and δ: "
               "enter them from the motor data sheet.")
                .arg(r.axis)
                .arg(m_d.drivePeriodS * 1e6, 0, 'f', 3)
                .arg(m_d.driveDeadTimeS * 1e6, 0, 'f', 3));
        emit completeChanged();
    });
    emit completeChanged();
}

void CurrentLoopMotorPage::takeFromProfile()
{
    const QString machine = m_ctx.machine(), axis = m_axis->currentText();
    if (!m_ctx.database() || machine.isEmpty() || axis.isEmpty()) {
        m_source->setText(tr("No machine profile: open a store and connect to (or choose) a machine first."));
        return;
    }
    auto profile = m_ctx.database()->loadProfile(machine.toStdString());
    const io::AxisProfile* ax = profile ? profile->axis(axis.toStdString()) : nullptr;
    const auto model = ax ? ax->models.find("motor") : std::map<std::string, nlohmann::json>::const_iterator{};
    if (!profile || !ax || model == ax->models.end() || !model->second.is_object()) {
        m_source->setText(profile ? tr("The profile of machine %1 has no motor model for axis %2: enter the data, or "
                                       "save a current-loop session first.")
                                        .arg(machine, axis)
                                  : tr("The profile of machine %1 could not be read: %2")
                                        .arg(machine, QString::fromStdString(profile.error().detail)));
        return;
    }
    const nlohmann::json& j = model->second;
    tuning::MotorData m = motorFromFields();
    QStringList used, missing;
    auto take = [&](const char* key, const QString& label, double scale, double& field) {
        if (auto it = j.find(key); it != j.end() && it->is_number() && std::isfinite(it->get<double>())) {
            field = it->get<double>() * scale;
            used << label;
        } else {
            missing << label;
        }
    };
    take("resistance_ohm", tr("R_a"), 1.0, m.resistanceOhm);
    take("inductance_q_H", tr("L_q"), 1.0, m.inductanceQH);
    take("inductance_drop_at_max", tr("δ"), 1.0, m.inductanceDropAtMax);
    take("max_current_A", tr("I_max"), 1.0, m.maxCurrentA);
    take("max_voltage_V", tr("V_max"), 1.0, m.maxVoltageV);
    take("rated_current_A", tr("rated current"), 1.0, m.ratedCurrentA);
    take("back_emf_constant_V_s_per_rad", tr("back-EMF constant"), kKeToVPerKrpm, m.backEmfVPerKrpm);
    setMotor(m);
    m_d.fromProfile = true;
    m_source->setText(tr("Taken from the profile of machine %1, axis %2: %3.").arg(machine, axis, used.join(", ")) +
                      (missing.isEmpty() ? QString()
                                         : " " + tr("Not in the profile, kept as shown: %1.").arg(missing.join(", "))));
    emit completeChanged();
}

void CurrentLoopMotorPage::setMotor(const tuning::MotorData& m)
{
    m_r->setValue(m.resistanceOhm);
    m_l->setValue(m.inductanceQH * 1e3);
    m_imax->setValue(m.maxCurrentA);
    m_vmax->setValue(m.maxVoltageV);
    m_delta->setValue(m.inductanceDropAtMax);
    m_rated->setValue(m.ratedCurrentA);
    m_emf->setValue(m.backEmfVPerKrpm);
    m_speed->setValue(m.contouringSpeedRpm);
    updateCheck();
}

tuning::MotorData CurrentLoopMotorPage::motorFromFields() const
{
    tuning::MotorData m;
    m.resistanceOhm = m_r->value();
    m.inductanceQH = m_l->value() * 1e-3;
    m.maxCurrentA = m_imax->value();
    m.maxVoltageV = m_vmax->value();
    m.inductanceDropAtMax = m_delta->value();
    m.ratedCurrentA = m_rated->value();
    m.backEmfVPerKrpm = m_emf->value();
    m.contouringSpeedRpm = m_speed->value();
    return m;
}

void CurrentLoopMotorPage::updateCheck()
{
    const tuning::MotorData m = motorFromFields();
    const auto st = tuning::validateMotor(m, "motor data");
    m_d.backEmfOk = st.ok();
    if (m.backEmfVPerKrpm > 0.0) {
        const double e = tuning::backEmfV(m.backEmfVPerKrpm, m.contouringSpeedRpm);
        // Peak per phase = line-to-line rms · √2/√3, comparable with a peak V_max.
        const double ePeak = e * std::sqrt(2.0 / 3.0);
        m_d.backEmfText = tr("Back-EMF check at the contouring speed %1 min⁻¹: %2 V(rms, line-to-line) = %3 V peak per "
                             "phase, %4 % of V_max = %5 V (peak comparison; with rms values %6 %). The design neglects "
                             "the back-EMF, which holds when it is small against V_max.")
                              .arg(m.contouringSpeedRpm, 0, 'f', 0)
                              .arg(e, 0, 'f', 2)
                              .arg(ePeak, 0, 'f', 2)
                              .arg(100.0 * ePeak / m.maxVoltageV, 0, 'f', 1)
                              .arg(m.maxVoltageV, 0, 'f', 1)
                              .arg(100.0 * e / m.maxVoltageV, 0, 'f', 1);
    } else {
        m_d.backEmfText = tr("No back-EMF constant given: the back-EMF at the contouring speed is not checked.");
    }
    if (!st.ok())
        m_d.backEmfText += "\n" + tr("Not usable: %1").arg(QString::fromStdString(st.error().detail));
    m_check->setText(m_d.backEmfText);
}

bool CurrentLoopMotorPage::isComplete() const
{
    return m_readRequest == 0 && tuning::validateMotor(motorFromFields(), "motor data").ok();
}

bool CurrentLoopMotorPage::validatePage()
{
    m_d.axis = m_axis->currentText();
    m_d.motor = motorFromFields();
    m_d.settings.deadTimeS = m_tau->value() * 1e-6;
    m_d.settings.gainMarginDb = m_gm->value();
    m_d.settings.overshootMax = m_os->value() / 100.0;
    m_d.settings.rippleFraction = m_ripple->value() / 100.0;
    if (!m_d.fromDrive) {
        m_d.drivePeriodS = m_d.settings.deadTimeS;
        m_d.driveDeadTimeS = m_d.settings.deadTimeS;
    }
    return tuning::validateSettings(m_d.settings).ok();
}

// ---------------------------------------------------------------------------------------------
// Design

CurrentLoopDesignPage::CurrentLoopDesignPage(AppContext& ctx, CurrentLoopData& shared, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared)
{
    setTitle(tr("Current loop: design"));
    setSubTitle(
        tr("For each PI ratio α the gains with the shortest rise time inside the dead-time stability boundary "
           "(gain margin), the voltage envelope and the overshoot limit; α* has the shortest rise time of all."));
    auto* lay = new QVBoxLayout(this);
    auto* bar = new QHBoxLayout;
    m_alpha = new QComboBox(this);
    m_alpha->setObjectName("clAlpha");
    m_alpha->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_all = new QCheckBox(tr("Show the boundaries of every α"), this);
    m_all->setObjectName("clAllAlphas");
    bar->addWidget(new QLabel(tr("Chosen α:"), this));
    bar->addWidget(m_alpha);
    bar->addWidget(m_all);
    bar->addStretch(1);
    lay->addLayout(bar);
    auto* split = new QSplitter(Qt::Horizontal, this);
    m_plane = new widgets::CurvePlot(split);
    m_plane->setObjectName("clPlane");
    m_plane->setAxes(tr("k_p"), tr("V/A"), tr("k_i"), tr("V/(A·s)"));
    auto* tabs = new QTabWidget(split);
    m_rise = new widgets::CurvePlot(tabs);
    m_rise->setObjectName("clRise");
    m_rise->setAxes(tr("α"), "1", tr("Rise time 10–90 %"), QString::fromUtf8("µs"));
    m_table = makeTable(tabs,
                        {tr("α"), tr("k_p [V/A]"), tr("k_i [V/(A·s)]"), tr("Rise time [µs]"), tr("Overshoot [%]"),
                         tr("Active constraints")},
                        "clTable");
    auto* sched = new QWidget(tabs);
    auto* sl = new QVBoxLayout(sched);
    m_schedule = new widgets::CurvePlot(sched);
    m_schedule->setObjectName("clSchedule");
    m_schedule->setAxes(tr("Current |i|"), "A", tr("k_p"), tr("V/A"));
    m_scheduleTable =
        makeTable(sched, {tr("Current [A]"), tr("Factor"), tr("k_p [V/A]"), tr("k_i [V/(A·s)]")}, "clScheduleTable");
    sl->addWidget(m_schedule, 3);
    sl->addWidget(m_scheduleTable, 2);
    tabs->addTab(m_rise, tr("Rise time against α"));
    tabs->addTab(m_table, tr("α table"));
    tabs->addTab(sched, tr("Gain schedule"));
    split->addWidget(m_plane);
    split->addWidget(tabs);
    split->setSizes({560, 420});
    lay->addWidget(split, 1);
    m_status = new QLabel(this);
    m_status->setObjectName("clDesignStatus");
    m_status->setWordWrap(true);
    lay->addWidget(m_status);
    connect(m_alpha, &QComboBox::currentIndexChanged, this, [this] {
        if (m_alpha->currentIndex() >= 0)
            m_d.chosenRow = m_alpha->currentData().toInt();
        drawPlane();
    });
    connect(m_all, &QCheckBox::toggled, this, [this] { drawPlane(); });
}

void CurrentLoopDesignPage::initializePage()
{
    struct Out {
        std::optional<tuning::CurrentLoopDesign> design;
        QString error;
        tuning::BoundaryCurve stability;
        std::vector<tuning::BoundaryCurve> voltage, overshoot;
    };
    m_busy = true;
    m_d.design.reset();
    m_d.chosenRow = -1;
    m_status->setText(tr("Designing…"));
    emit completeChanged();
    const auto motor = m_d.motor;
    const auto settings = m_d.settings;
    auto* watcher = new QFutureWatcher<Out>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher] {
        Out out = watcher->result();
        watcher->deleteLater();
        m_d.design = std::move(out.design);
        m_d.error = out.error;
        m_d.stability = std::move(out.stability);
        m_d.voltage = std::move(out.voltage);
        m_d.overshoot = std::move(out.overshoot);
        m_busy = false;
        showDesign();
        emit completeChanged();
    });
    watcher->setFuture(QtConcurrent::run([motor, settings]() {
        Out out;
        auto d = tuning::designCurrentLoop(motor, settings);
        if (!d) {
            out.error = QString::fromStdString(d.error().detail);
            return out;
        }
        out.stability = tuning::stabilityBoundary(motor, settings, kCurvePoints);
        for (const auto& row : d->table) {
            out.voltage.push_back(tuning::voltageEnvelope(motor, settings, row.alpha, kCurvePoints));
            out.overshoot.push_back(tuning::overshootCurve(motor, settings, row.alpha, kCurvePoints));
        }
        out.design = std::move(d).value();
        return out;
    }));
}

void CurrentLoopDesignPage::showDesign()
{
    m_table->setRowCount(0);
    m_rise->clear();
    const QSignalBlocker block(m_alpha);
    m_alpha->clear();
    if (!m_d.design) {
        m_status->setText(tr("The design failed: %1").arg(m_d.error));
        return;
    }
    const auto& d = *m_d.design;
    std::vector<double> a, tr_;
    for (int i = 0; i < int(d.table.size()); ++i) {
        const auto& row = d.table[i];
        QStringList active;
        for (const auto& c : row.activeConstraints)
            active << QString::fromStdString(c);
        if (row.feasible) {
            addRow(m_table, {QString::number(row.alpha, 'f', 2), QString::number(row.gains.kpVPerA, 'f', 2),
                             QString::number(row.gains.kiVPerAs, 'g', 4), QString::number(row.riseTimeS * 1e6, 'f', 1),
                             QString::number(row.overshoot * 100.0, 'f', 1), active.join(", ")});
            a.push_back(row.alpha);
            tr_.push_back(row.riseTimeS * 1e6);
            m_alpha->addItem(QString::number(row.alpha, 'f', 2) +
                                 (std::abs(row.alpha - d.alpha) < 1e-12 ? tr(" (optimum α*)") : QString()),
                             i);
            if (std::abs(row.alpha - d.alpha) < 1e-12) {
                m_d.chosenRow = i;
                m_alpha->setCurrentIndex(m_alpha->count() - 1);
            }
        } else {
            addRow(m_table, {QString::number(row.alpha, 'f', 2), "–", "–", "–", "–", tr("infeasible")});
        }
    }
    m_rise->addCurve(tr("Rise time of the optimum per α"), a, tr_, QColor(0, 90, 180));
    m_rise->addPoint(d.alpha, d.riseTimeS * 1e6, tr("α* = %1").arg(d.alpha, 0, 'f', 2));
    m_rise->rescale();
    m_status->setText(tr("Optimum α* = %1: k_p = %2 V/A, k_i = %3 V/(A·s), rise time %4 µs (delay-free design model).")
                          .arg(d.alpha, 0, 'f', 2)
                          .arg(d.gains.kpVPerA, 0, 'f', 2)
                          .arg(d.gains.kiVPerAs, 0, 'g', 4)
                          .arg(d.riseTimeS * 1e6, 0, 'f', 1));
    drawPlane();
}

void CurrentLoopDesignPage::drawPlane()
{
    m_plane->clear();
    m_schedule->clear();
    m_scheduleTable->setRowCount(0);
    const auto* c = m_d.chosen();
    if (!c)
        return;
    const auto& st = m_d.stability;
    m_plane->addCurve(tr("Stability boundary (gain margin %1 dB)").arg(m_d.settings.gainMarginDb, 0, 'f', 2),
                      st.kpVPerA, gapsAtZero(st.kiVPerAs), QColor(200, 0, 0));
    const auto& table = m_d.design->table;
    for (int i = 0; i < int(table.size()); ++i) {
        const bool isChosen = i == m_d.chosenRow;
        if (!isChosen && !m_all->isChecked())
            continue;
        const QString a = QString::number(table[i].alpha, 'f', 1);
        const QColor vc = isChosen ? QColor(0, 120, 0) : QColor(120, 190, 120);
        const QColor oc = isChosen ? QColor(0, 70, 200) : QColor(140, 160, 220);
        m_plane->addCurve(tr("Voltage envelope α = %1").arg(a), m_d.voltage[i].kpVPerA,
                          gapsAtZero(m_d.voltage[i].kiVPerAs), vc, isChosen ? Qt::SolidLine : Qt::DotLine);
        m_plane->addCurve(tr("Overshoot %1 % α = %2").arg(m_d.settings.overshootMax * 100.0, 0, 'f', 0).arg(a),
                          m_d.overshoot[i].kpVPerA, gapsAtZero(m_d.overshoot[i].kiVPerAs), oc,
                          isChosen ? Qt::DashLine : Qt::DotLine);
    }
    m_plane->addPoint(c->gains.kpVPerA, c->gains.kiVPerAs,
                      tr("α = %1: k_p %2 V/A, k_i %3 V/(A·s)")
                          .arg(c->alpha, 0, 'f', 2)
                          .arg(c->gains.kpVPerA, 0, 'f', 2)
                          .arg(c->gains.kiVPerAs, 0, 'g', 4));
    m_plane->rescale();
    m_plane->setYRange(0.0, 1.3 * maxOf(st.kiVPerAs));
    // The schedule (2.16) for the chosen gains: factor (I_max − δ|i|)/I_max at the design's currents.
    std::vector<double> i, kp;
    for (const auto& p : m_d.design->schedule) {
        const double f = tuning::scheduleFactor(m_d.motor, p.currentA);
        i.push_back(p.currentA);
        kp.push_back(f * c->gains.kpVPerA);
        addRow(m_scheduleTable,
               {QString::number(p.currentA, 'f', 2), QString::number(f, 'f', 3),
                QString::number(f * c->gains.kpVPerA, 'f', 2), QString::number(f * c->gains.kiVPerAs, 'g', 4)});
    }
    m_schedule->addCurve(tr("k_p over current (k_i in the same ratio)"), i, kp, QColor(0, 90, 180));
    m_schedule->rescale();
    m_schedule->setYRange(0.0, 1.1 * c->gains.kpVPerA);
}

bool CurrentLoopDesignPage::isComplete() const
{
    return !m_busy && m_d.chosen() != nullptr;
}

bool CurrentLoopDesignPage::validatePage()
{
    const auto* c = m_d.chosen();
    if (!c)
        return false;
    const double dur = std::max(20.0 * c->riseTimeS, 40.0 * m_d.drivePeriodS);
    m_d.step = tuning::stepResponses(m_d.motor, c->alpha, c->gains, m_d.driveDeadTimeS, m_d.drivePeriodS, dur);
    m_d.fineTimeS.clear();
    m_d.fineDelayFree.clear();
    for (int k = 0; k <= 400; ++k) {
        const double t = dur * k / 400.0;
        m_d.fineTimeS.push_back(t);
        m_d.fineDelayFree.push_back(tuning::delayFreeStep(m_d.motor, c->alpha, c->gains, t));
    }
    return true;
}

} // namespace gui
} // namespace axistune

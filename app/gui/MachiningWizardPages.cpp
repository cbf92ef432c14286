// SPDX-License-Identifier: GPL-3.0-or-later
// The machining wizard's lobes, advice and cut-analysis pages (docs/wizards/machining.md). Lobes by
// semi-discretization (spec/chatter-stability-and-spindle-speed.md §2), the stable-pocket rule (§3.0.2),
// the Kalman AR chatter-frequency estimate (§3.0.1), the cutting force observer (seed 003) and the
// correlation chatter detection (seed 004, spec/cutting-force-observer-and-chatter-detection.md) — all in
// core/machining; the cut simulation is core/sim/Milling on the vmc X axis, coupled as in
// `axistune-cli simulate-cut`.
#include "app/gui/MachiningWizard.h"
#include "core/io/CaptureCsv.h"
#include "core/machining/ChatterFrequencyEstimator.h"
#include "core/machining/StageJson.h"
#include "core/sim/AxisSimulator.h"
#include "core/sim/MachineDefinition.h"
#include "core/sim/Milling.h"
#include "core/sim/MotionProfile.h"
#include "widgets/CurvePlot.h"
#include "widgets/TimeTracePlot.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QProgressBar>
#include <QPromise>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <algorithm>
#include <cmath>
#include <limits>

namespace axistune {
namespace gui {

namespace {

QString g(double v, int digits = 4)
{
    return QLocale().toString(v, 'g', digits);
}
QString f(double v, int decimals)
{
    return QLocale().toString(v, 'f', decimals);
}

/// Lobe curve for the plot in mm (speeds stable up to the search limit are shown at the limit).
void addLobeCurve(widgets::CurvePlot* plot, const std::vector<machining::LobePoint>& lobes, double depthMaxM)
{
    std::vector<double> x, y;
    for (const auto& p : lobes) {
        x.push_back(p.rpm);
        y.push_back((std::isinf(p.limitDepthM) ? depthMaxM : p.limitDepthM) * 1e3);
    }
    plot->addCurve(QObject::tr("limit depth"), x, y, QColor(0, 90, 180));
}

constexpr double kDepthMaxM = 0.05;

} // namespace

// ---------------------------------------------------------------------------------------------- lobe page

MachiningLobesPage::MachiningLobesPage(const MachiningToolPage& tool, const MachiningCutPage& cut, QWidget* parent)
    : QWizardPage(parent), m_toolPage(tool), m_cutPage(cut)
{
    setTitle(tr("Stability lobes"));
    setSubTitle(tr("Limit axial depth against spindle speed by semi-discretization: below the curve the cut is "
                   "stable, above it chatters."));
    m_plot = new widgets::CurvePlot(this);
    m_plot->setObjectName("machLobePlot");
    m_plot->setAxes(tr("Spindle speed"), tr("min⁻¹"), tr("Limit depth"), tr("mm"));
    m_progress = new QProgressBar(this);
    m_progress->setObjectName("machLobeProgress");
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName("machLobeCancel");
    m_again = new QPushButton(tr("Compute again"), this);
    m_again->setObjectName("machLobeAgain");
    m_status = new QLabel(this);
    m_status->setObjectName("machLobeStatus");
    m_status->setWordWrap(true);
    auto* row = new QHBoxLayout;
    row->addWidget(m_progress, 1);
    row->addWidget(m_cancel);
    row->addWidget(m_again);
    auto* lay = new QVBoxLayout(this);
    lay->addWidget(m_plot, 1);
    lay->addLayout(row);
    lay->addWidget(m_status);

    m_watcher = new QFutureWatcher<LobeResult>(this);
    connect(m_watcher, &QFutureWatcherBase::progressRangeChanged, m_progress, &QProgressBar::setRange);
    connect(m_watcher, &QFutureWatcherBase::progressValueChanged, m_progress, &QProgressBar::setValue);
    connect(m_watcher, &QFutureWatcherBase::finished, this, &MachiningLobesPage::finished);
    connect(m_cancel, &QPushButton::clicked, this, [this] {
        if (m_watcher->isRunning())
            m_watcher->cancel();
    });
    connect(m_again, &QPushButton::clicked, this, &MachiningLobesPage::start);
}

MachiningLobesPage::~MachiningLobesPage()
{
    m_watcher->cancel();
    m_watcher->waitForFinished();
}

void MachiningLobesPage::initializePage()
{
    start();
}

void MachiningLobesPage::cleanupPage()
{
    m_restart = false;
    if (m_watcher->isRunning())
        m_watcher->cancel();
}

void MachiningLobesPage::start()
{
    if (m_watcher->isRunning()) {
        // Back and Next again while the previous data are still computed: restart when that run has stopped.
        m_restart = true;
        m_watcher->cancel();
        return;
    }
    auto tool = m_toolPage.tool();
    auto in = m_cutPage.inputs();
    m_done = false;
    m_result = {};
    m_plot->clear();
    m_plot->replotNow();
    if (!tool || !in) {
        m_status->setText(tr("The tool or cut data are not valid."));
        emit completeChanged();
        return;
    }
    auto grid = machining::rpmGrid(in->rpmMin, in->rpmMax, in->rpmStep);
    if (!grid) {
        m_status->setText(QString::fromStdString(grid.error().detail));
        emit completeChanged();
        return;
    }
    m_status->setText(
        tr("Computing %1 spindle speeds (%2 steps per tooth period)…").arg(grid->size()).arg(in->stepsPerPeriod));
    m_cancel->setEnabled(true);
    m_again->setEnabled(false);
    m_progress->setRange(0, static_cast<int>(grid->size()) + 1);
    m_progress->setValue(0);
    const auto t = *tool;
    const auto c = *in;
    const auto speeds = *grid;
    m_watcher->setFuture(QtConcurrent::run([t, c, speeds](QPromise<LobeResult>& promise) {
        LobeResult r;
        machining::LobeOptions opt;
        opt.stepsPerPeriod = c.stepsPerPeriod;
        opt.depthMaxM = kDepthMaxM;
        opt.threads = 2;
        promise.setProgressRange(0, static_cast<int>(speeds.size()) + 1);
        // Chunks of a few speeds: cancellation and progress between them (the core call has no cancel).
        constexpr std::size_t kChunk = 6;
        for (std::size_t i = 0; i < speeds.size(); i += kChunk) {
            if (promise.isCanceled())
                return;
            const std::vector<double> part(speeds.begin() + static_cast<std::ptrdiff_t>(i),
                                           speeds.begin() +
                                               static_cast<std::ptrdiff_t>(std::min(speeds.size(), i + kChunk)));
            auto lobes = machining::stabilityLobes(t, c.cut, part, opt);
            if (!lobes) {
                r.error = QString::fromStdString(lobes.error().detail);
                promise.addResult(r);
                return;
            }
            r.lobes.insert(r.lobes.end(), lobes->begin(), lobes->end());
            promise.setProgressValue(static_cast<int>(r.lobes.size()));
        }
        if (promise.isCanceled())
            return;
        auto now = machining::limitDepth(t, c.cut, c.rpm, opt);
        if (!now)
            r.error = QString::fromStdString(now.error().detail);
        else
            r.limitAtCurrentM = *now;
        promise.setProgressValue(static_cast<int>(speeds.size()) + 1);
        promise.addResult(r);
    }));
    emit completeChanged();
}

void MachiningLobesPage::finished()
{
    if (m_restart) {
        m_restart = false;
        start();
        return;
    }
    m_cancel->setEnabled(false);
    m_again->setEnabled(true);
    if (m_watcher->isCanceled() || m_watcher->future().resultCount() == 0) {
        m_status->setText(tr("Cancelled: no lobe diagram. Press Compute again."));
        emit completeChanged();
        return;
    }
    m_result = m_watcher->result();
    if (!m_result.error.isEmpty()) {
        m_status->setText(tr("The lobes could not be computed: %1").arg(m_result.error));
        emit completeChanged();
        return;
    }
    auto in = m_cutPage.inputs();
    m_done = in.ok();
    if (!m_done) {
        emit completeChanged();
        return;
    }
    addLobeCurve(m_plot, m_result.lobes, kDepthMaxM);
    const bool stable = in->depthM < m_result.limitAtCurrentM;
    const QString limit = std::isinf(m_result.limitAtCurrentM)
                              ? tr("stable up to the search limit %1 mm").arg(g(kDepthMaxM * 1e3))
                              : tr("limit %1 mm").arg(f(m_result.limitAtCurrentM * 1e3, 3));
    m_plot->addPoint(in->rpm, in->depthM * 1e3, stable ? tr("current: stable") : tr("current: unstable"));
    m_plot->rescale();
    double ymax = 0.0;
    for (const auto& p : m_result.lobes)
        if (std::isfinite(p.limitDepthM))
            ymax = std::max(ymax, p.limitDepthM * 1e3);
    m_plot->setYRange(0.0, std::max(ymax, in->depthM * 1e3) * 1.15 + 0.1);
    m_plot->replotNow();
    m_status->setText(tr("Current point %1 min⁻¹, %2 mm: %3 (%4 at this speed).")
                          .arg(g(in->rpm, 6), f(in->depthM * 1e3, 3),
                               stable ? tr("STABLE") : tr("UNSTABLE (chatter expected)"), limit));
    emit completeChanged();
}

double MachiningLobesPage::limitAt(double rpm) const
{
    const auto& l = m_result.lobes;
    if (!m_done || l.empty() || rpm < l.front().rpm || rpm > l.back().rpm)
        return std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i + 1 < l.size(); ++i) {
        if (rpm <= l[i + 1].rpm) {
            const double w = (rpm - l[i].rpm) / (l[i + 1].rpm - l[i].rpm);
            return l[i].limitDepthM + w * (l[i + 1].limitDepthM - l[i].limitDepthM);
        }
    }
    return l.back().limitDepthM;
}

bool MachiningLobesPage::isComplete() const
{
    return m_done && !m_watcher->isRunning();
}

// -------------------------------------------------------------------------------------------- advice page

MachiningAdvicePage::MachiningAdvicePage(const MachiningCutPage& cut, const MachiningLobesPage& lobes, QWidget* parent)
    : QWizardPage(parent), m_cutPage(cut), m_lobesPage(lobes)
{
    setTitle(tr("Spindle speed advice"));
    setSubTitle(tr("From the chatter frequency heard or measured at the current speed: the stable pocket where the "
                   "tooth passing frequency divides the chatter frequency by a whole number."));
    m_chatter = new QLineEdit(this);
    m_chatter->setObjectName("machChatterHz");
    m_chatter->setPlaceholderText(tr("e.g. 1450"));
    auto* estimate = new QPushButton(tr("Estimate from a capture…"), this);
    estimate->setObjectName("machEstimate");
    m_estimate = new QLabel(this);
    m_estimate->setWordWrap(true);
    m_text = new QLabel(this);
    m_text->setObjectName("machAdviceText");
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_plot = new widgets::CurvePlot(this);
    m_plot->setObjectName("machAdvicePlot");
    m_plot->setAxes(tr("Spindle speed"), tr("min⁻¹"), tr("Limit depth"), tr("mm"));
    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(tr("Chatter frequency [Hz]"), this));
    row->addWidget(m_chatter);
    row->addWidget(estimate);
    auto* lay = new QVBoxLayout(this);
    lay->addLayout(row);
    lay->addWidget(m_estimate);
    lay->addWidget(m_text);
    lay->addWidget(m_plot, 1);
    connect(m_chatter, &QLineEdit::textChanged, this, [this] {
        m_estimateSource = tr("entered");
        update();
    });
    connect(estimate, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Capture with chatter"), QString(),
                                                          tr("Capture CSV (*.csv);;All files (*)"));
        if (!path.isEmpty())
            estimateFromCapture(path);
    });
}

void MachiningAdvicePage::initializePage()
{
    update();
}

bool MachiningAdvicePage::estimateFromCapture(const QString& path)
{
    auto cap = io::readCaptureCsvFile(path.toStdString());
    if (!cap) {
        m_estimate->setText(QString::fromStdString(cap.error().detail));
        return false;
    }
    const model::Channel* ch = cap->channel("tool_x_m");
    if (!ch)
        ch = cap->channel("cutting_force_N");
    for (const auto& c : cap->channels)
        if (!ch && c.name != "t_s" && c.name != "time_s")
            ch = &c;
    const auto* t = cap->channel("t_s");
    double ts = 0.0;
    if (t && t->data.size() >= 2)
        ts = (t->data.back() - t->data.front()) / static_cast<double>(t->data.size() - 1);
    else if (cap->metadata.count("fs_Hz"))
        ts = 1.0 / std::atof(cap->metadata.at("fs_Hz").c_str());
    if (!ch || !(ts > 0.0)) {
        m_estimate->setText(tr("%1: no signal channel or no sample rate (t_s or fs_Hz)").arg(path));
        return false;
    }
    // The last half of the record (after the tool entered the material).
    std::vector<double> sig(ch->data.begin() + static_cast<std::ptrdiff_t>(ch->data.size() / 2), ch->data.end());
    // Unit RMS: the estimator's noise covariances (R_w = 0.3) are set for a signal of order one.
    double mean = 0.0, ms = 0.0;
    for (double v : sig)
        mean += v / static_cast<double>(sig.size());
    for (double v : sig)
        ms += (v - mean) * (v - mean) / static_cast<double>(sig.size());
    if (ms > 0.0)
        for (double& v : sig)
            v = (v - mean) / std::sqrt(ms);
    // Table 4(a) of seed 000 (spec §3.0.1): R_v = 1e-6, R_w = 0.3, P[0] = 1e3 — a fast start from θ = 0.
    auto fr = machining::estimateChatterFrequencies(sig, ts, machining::KalmanAROptions{2, 1e-6, 0.3, 1e3});
    if (!fr || fr->empty() || !(fr->front() > 0.0)) {
        m_estimate->setText(tr("%1: no chatter frequency estimated%2")
                                .arg(path, fr ? QString() : ": " + QString::fromStdString(fr.error().detail)));
        return false;
    }
    {
        QSignalBlocker block(m_chatter);
        m_chatter->setText(QLocale().toString(fr->front(), 'f', 1));
    }
    m_estimateSource = QFileInfo(path).fileName() + " / " + QString::fromStdString(ch->name);
    m_estimate->setText(tr("Estimated %1 Hz from channel %2 of %3 (Kalman AR model, last half of the record).")
                            .arg(f(fr->front(), 1), QString::fromStdString(ch->name), QFileInfo(path).fileName()));
    update();
    return true;
}

void MachiningAdvicePage::update()
{
    m_advice.reset();
    m_plot->clear();
    auto in = m_cutPage.inputs();
    const auto& lobes = m_lobesPage.result().lobes;
    if (m_lobesPage.done())
        addLobeCurve(m_plot, lobes, kDepthMaxM);
    if (in)
        m_plot->addPoint(in->rpm, in->depthM * 1e3, tr("current"));
    const auto fc = machiningNumber(m_chatter->text());
    if (!in || m_chatter->text().trimmed().isEmpty()) {
        m_text->setText(tr("Enter the chatter frequency (or estimate it from a capture) for the advice; this step is "
                           "optional."));
    } else if (!fc) {
        m_text->setText(tr("Chatter frequency: '%1' is not a number").arg(m_chatter->text()));
    } else {
        auto a = machining::pocketAdvice(*fc, in->rpm, in->cut.teeth);
        if (!a) {
            m_text->setText(QString::fromStdString(a.error().detail));
        } else {
            m_advice = *a;
            QStringList others;
            for (const auto& cand : a->candidates)
                if (cand.lobe != a->lobe)
                    others << tr("lobe %1: %2 min⁻¹").arg(cand.lobe).arg(f(cand.rpm, 0));
            m_text->setText(
                tr("Rule: the tooth passing frequency f_TPE = N_t·n/60 = %1 × %2 / 60 = %3 Hz; the chatter frequency "
                   "is %4 × f_TPE. Rounded, lobe number ρ = %5. The stable pocket puts a whole number of chatter "
                   "waves in one tooth period: n = 60·f_chat/(ρ·N_t) = 60 × %6 / (%5 × %1) = %7 min⁻¹.%8")
                    .arg(in->cut.teeth)
                    .arg(f(in->rpm, 0), f(a->toothPassingHz, 2), f(a->ratio, 3))
                    .arg(a->lobe)
                    .arg(f(*fc, 1), f(a->rpm, 0))
                    .arg(others.isEmpty() ? QString() : tr(" Neighbouring pockets: %1.").arg(others.join(", "))));
            m_plot->addVerticalLine(a->rpm, tr("advised %1 min⁻¹").arg(f(a->rpm, 0)));
            const double lim = m_lobesPage.limitAt(a->rpm);
            if (std::isfinite(lim))
                m_text->setText(m_text->text() + " " + tr("The lobe diagram gives %1 mm there.").arg(f(lim * 1e3, 3)));
        }
    }
    m_plot->rescale();
    if (m_lobesPage.done()) {
        double ymax = in ? in->depthM * 1e3 : 0.0;
        for (const auto& p : lobes)
            if (std::isfinite(p.limitDepthM))
                ymax = std::max(ymax, p.limitDepthM * 1e3);
        m_plot->setYRange(0.0, ymax * 1.15 + 0.1);
    }
    m_plot->replotNow();
}

// ------------------------------------------------------------------------------------------ analysis page

namespace {

std::string num(double v)
{
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", v);
    return b;
}

/// The stage of a simulated machine's axis (like `axistune-cli chatter-detect` without --stage).
Result<machining::StageDescription> stageOfPreset(const std::string& machine, const std::string& axis)
{
    auto def = sim::loadPreset(machine);
    if (!def)
        return def.error();
    const auto* a = def->axis(axis);
    if (!a)
        return makeError(ErrorCode::NotFound, "machine " + machine + " has no axis " + axis);
    const auto v = [a](const char* k) { return a->values.at(k); };
    machining::StageDescription d;
    d.leadMPerRev = v("plant.screw_lead") * 2.0 * 3.14159265358979323846;
    d.torqueConstantNmPerA = v("motor.torque_constant");
    d.motor = {v("plant.inertia_motor"), v("plant.viscous_motor"), v("plant.coulomb_motor")};
    d.load = {v("plant.inertia_load"), v("plant.viscous_load"), v("plant.coulomb_load")};
    d.couplingStiffnessNmPerRad = v("plant.coupling_stiffness");
    d.couplingDampingNmsPerRad = v("plant.coupling_damping");
    d.hasCoupling = d.couplingStiffnessNmPerRad > 0.0;
    // A cut at constant feed is no identification opportunity (docs/machining.md): the nominal observer.
    d.rls.method = machining::RlsMethod::Fixed;
    return d;
}

/// Simulated cut on the vmc X axis (the coupling of `axistune-cli simulate-cut`).
Result<model::Capture> simulateVmcCut(const machining::ToolModes& tool, const MachiningCutInputs& in, double durationS)
{
    auto def = sim::loadPreset("vmc");
    if (!def)
        return def.error();
    const auto* axisDef = def->axis("X");
    if (!axisDef)
        return makeError(ErrorCode::NotFound, "vmc: no X axis");
    sim::MillingSetup ms;
    for (const auto& m : tool.modesX)
        ms.modesX.push_back({m.massKg, m.dampingNsPerM, m.stiffnessNPerM});
    for (const auto& m : tool.modesY)
        ms.modesY.push_back({m.massKg, m.dampingNsPerM, m.stiffnessNPerM});
    ms.teeth = in.cut.teeth;
    ms.ktNPerM2 = in.cut.ktNPerM2;
    ms.krNPerM2 = in.cut.krNPerM2;
    ms.radialImmersion = in.cut.radialImmersion;
    ms.upMilling = in.cut.milling == machining::MillingDirection::Up;
    ms.spindleRpm = in.rpm;
    ms.axialDepthM = in.depthM;
    ms.feedPerToothM = 0.1e-3;
    auto proc = sim::MillingProcess::create(ms);
    if (!proc)
        return proc.error();
    auto created = sim::AxisSimulator::create(*axisDef, 3);
    if (!created)
        return created.error();
    auto& axis = *created.value();
    auto process = std::make_shared<sim::MillingProcess>(proc.value());
    const double engage = 0.2;
    const double feed = ms.feedPerToothM * ms.teeth * in.rpm / 60.0;
    sim::MotionProfile profile(0.0);
    profile.move(feed * (durationS + 1.0), std::max(feed, 1e-9), std::max(feed / (0.5 * engage + 1e-6), 1e-6));
    sim::Nonlinearities nl = axis.nonlinearities();
    nl.lostMotion = false; // as simulate-cut: the quasi-static lost motion swamps the vibration-mode force
    axis.setNonlinearities(nl);
    axis.reset(0.0);
    axis.setControlMode(sim::ControlMode::Position);
    axis.setPositionProfile(profile);
    const double lead = axis.parameter("plant.screw_lead");
    const double h = axis.currentPeriod();
    auto forces = std::make_shared<std::vector<double>>();
    auto tools = std::make_shared<std::vector<double>>();
    axis.setLoadTorque([process, forces, tools, lead, h, engage](double t) {
        double tableForce = 0.0;
        if (t + h > engage)
            tableForce = -process->advanceTo(t + h - engage);
        forces->push_back(tableForce);
        tools->push_back(process->toolX());
        return lead * tableForce;
    });
    axis.startTrace();
    axis.run(durationS);
    model::Capture cap = axis.takeTrace();
    const auto* t = cap.channel("t_s");
    if (!t)
        return makeError(ErrorCode::Internal, "trace without t_s");
    model::Channel cf{"cutting_force_N", {}}, tv{"tool_x_m", {}};
    for (double ti : t->data) {
        const auto k = static_cast<std::size_t>(std::llround(ti / h));
        cf.data.push_back(k < forces->size() ? (*forces)[k] : 0.0);
        tv.data.push_back(k < tools->size() ? (*tools)[k] : 0.0);
    }
    cap.channels.push_back(std::move(cf));
    cap.channels.push_back(std::move(tv));
    cap.metadata["machine"] = "vmc";
    cap.metadata["axis"] = "X";
    cap.metadata["test"] = "simulate-cut";
    cap.metadata["spindle_rpm"] = num(in.rpm);
    cap.metadata["axial_depth_m"] = num(in.depthM);
    cap.metadata["teeth"] = std::to_string(ms.teeth);
    cap.metadata["engage_s"] = num(engage);
    return cap;
}

/// The cutting-force observer and the chatter detection on a capture.
CutAnalysis analyseCut(model::Capture cap, const QString& source, const QString& stagePath)
{
    CutAnalysis out;
    out.source = source;
    Result<machining::StageDescription> stage = makeError(ErrorCode::BadInput, "");
    if (!stagePath.isEmpty()) {
        stage = machining::readStageJsonFile(stagePath.toStdString());
        out.stageSource = stagePath;
    } else {
        const auto m = cap.metadata.find("machine"), a = cap.metadata.find("axis");
        if (m == cap.metadata.end() || a == cap.metadata.end()) {
            out.error = QObject::tr("%1: no stage.json given and the capture names no simulated machine/axis "
                                    "(metadata 'machine=' and 'axis=')")
                            .arg(source);
            return out;
        }
        stage = stageOfPreset(m->second, a->second);
        out.stageSource = QObject::tr("axis parameters of %1 %2")
                              .arg(QString::fromStdString(m->second), QString::fromStdString(a->second));
    }
    if (!stage) {
        out.error = QString::fromStdString(stage.error().detail);
        return out;
    }
    const auto* t = cap.channel("t_s");
    const auto* current = cap.channel("current_A");
    const auto* torque = current ? nullptr : cap.channel("torque_Nm");
    if (!current && !torque)
        torque = cap.channel("torque_cmd_Nm");
    const auto* wm = cap.channel("motor_vel_rad_s");
    const auto* xt = cap.channel("table_pos_m");
    const auto* xm = cap.channel("motor_pos_m");
    const auto* iref = cap.channel("current_cmd_A");
    if (!t || t->data.size() < 3 || !(t->data.back() > t->data.front()) || (!current && !torque) || !wm || !xt || !xm) {
        out.error = QObject::tr("%1: needs the columns t_s, current_A (or torque_Nm), motor_vel_rad_s, motor_pos_m, "
                                "table_pos_m")
                        .arg(source);
        return out;
    }
    const std::size_t n = t->data.size();
    const double ts = (t->data.back() - t->data.front()) / static_cast<double>(n - 1);
    const double r = stage->leadMPerRad();
    // Cutting force observer (seed 003 eqs. (2), (3)) with the stage's RLS settings.
    auto obs = machining::CuttingForceObserver::create(stage->motor, stage->load, stage->observer, ts);
    auto rls = machining::SwitchingRls::create(stage->load, stage->rls, ts);
    if (!obs || !rls) {
        out.error = QString::fromStdString(!obs ? obs.error().detail : rls.error().detail);
        return out;
    }
    auto motorSide = obs.value();
    auto adaptive = rls.value();
    out.timeS = t->data;
    out.forceEstimateN.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double tm = current ? stage->torqueConstantNmPerA * current->data[i] : torque->data[i];
        const double omegaL = i > 0 ? (xt->data[i] - xt->data[i - 1]) / (ts * r) : 0.0;
        const auto s = adaptive.step(motorSide.torsionTorque(tm, wm->data[i]), omegaL);
        out.forceEstimateN[i] = -s.forceHat / r;
    }
    // Chatter detection (seed 004) on the current reference, the motor and the table position.
    if (stage->hasCoupling) {
        auto mode = machining::vibrationModeOf(stage->twoMass());
        if (!mode) {
            out.error = QString::fromStdString(mode.error().detail);
            return out;
        }
        std::vector<double> fm(n);
        for (std::size_t i = 0; i < n; ++i)
            fm[i] = (iref ? stage->torqueConstantNmPerA * iref->data[i]
                          : (current ? stage->torqueConstantNmPerA * current->data[i] : torque->data[i])) /
                    r;
        machining::ChatterDetectOptions opt = stage->chatter;
        // The air cut before the tool enters the material sets the force-energy floor (CD-2 gate).
        if (auto e = cap.metadata.find("engage_s"); e != cap.metadata.end() && opt.baselineS <= 0.0)
            opt.baselineS = 0.75 * std::atof(e->second.c_str());
        auto res = machining::detectChatter(t->data, fm, xm->data, xt->data, 1.0 / ts, *mode, opt);
        if (!res) {
            out.error = source + ": " + QString::fromStdString(res.error().detail);
            return out;
        }
        out.chatter = std::move(*res);
    }
    out.capture = std::make_shared<const model::Capture>(std::move(cap));
    return out;
}

} // namespace

MachiningAnalysisPage::MachiningAnalysisPage(const MachiningToolPage& tool, const MachiningCutPage& cut,
                                             QWidget* parent)
    : QWizardPage(parent), m_toolPage(tool), m_cutPage(cut)
{
    setTitle(tr("Analysis of a cut"));
    setSubTitle(tr("Load a captured cut or simulate this cut on the vmc X axis: the cutting force estimated by the "
                   "observer and the chatter intervals found by the correlation detector."));
    m_load = new QPushButton(tr("Load capture CSV…"), this);
    m_load->setObjectName("machLoadCapture");
    m_simulate = new QPushButton(tr("Simulate this cut (vmc X)"), this);
    m_simulate->setObjectName("machSimulate");
    m_duration = new QLineEdit(QLocale().toString(1.2), this);
    m_duration->setObjectName("machDuration");
    m_duration->setMaximumWidth(80);
    m_stage = new QLineEdit(this);
    m_stage->setObjectName("machStage");
    m_stage->setPlaceholderText(tr("empty: the axis parameters of the simulated machine named in the capture"));
    auto* browse = new QPushButton(tr("stage.json…"), this);
    m_busy = new QProgressBar(this);
    m_busy->setRange(0, 0);
    m_busy->setVisible(false);
    m_plot = new widgets::TimeTracePlot(this);
    m_plot->setObjectName("machForcePlot");
    m_table = new QTableWidget(0, 4, this);
    m_table->setObjectName("machIntervals");
    m_table->setHorizontalHeaderLabels({tr("Start [s]"), tr("End [s]"), tr("Frequency [Hz]"), tr("Score")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->verticalHeader()->setVisible(false);
    m_table->setMaximumHeight(110);
    m_summary = new QLabel(this);
    m_summary->setObjectName("machAnalysisSummary");
    m_summary->setWordWrap(true);

    auto* row = new QHBoxLayout;
    row->addWidget(m_load);
    row->addWidget(m_simulate);
    row->addWidget(new QLabel(tr("duration [s]"), this));
    row->addWidget(m_duration);
    row->addStretch();
    auto* stageRow = new QHBoxLayout;
    stageRow->addWidget(new QLabel(tr("Stage"), this));
    stageRow->addWidget(m_stage, 1);
    stageRow->addWidget(browse);
    auto* lay = new QVBoxLayout(this);
    lay->addLayout(row);
    lay->addLayout(stageRow);
    lay->addWidget(m_busy);
    lay->addWidget(m_plot, 1);
    lay->addWidget(m_table);
    lay->addWidget(m_summary);

    m_watcher = new QFutureWatcher<CutAnalysis>(this);
    connect(m_watcher, &QFutureWatcherBase::finished, this, [this] {
        m_analysis = m_watcher->result();
        show();
    });
    connect(m_load, &QPushButton::clicked, this, [this] {
        const QString path =
            QFileDialog::getOpenFileName(this, tr("Captured cut"), QString(), tr("Capture CSV (*.csv);;All files (*)"));
        if (!path.isEmpty())
            loadCapture(path);
    });
    connect(m_simulate, &QPushButton::clicked, this, &MachiningAnalysisPage::simulateCut);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString path =
            QFileDialog::getOpenFileName(this, tr("Stage"), QString(), tr("Stage JSON (*.json);;All files (*)"));
        if (!path.isEmpty())
            m_stage->setText(path);
    });
}

MachiningAnalysisPage::~MachiningAnalysisPage()
{
    m_watcher->waitForFinished();
}

bool MachiningAnalysisPage::busy() const
{
    return m_running;
}

void MachiningAnalysisPage::run(std::function<CutAnalysis()> job)
{
    if (busy())
        return;
    m_busy->setVisible(true);
    m_load->setEnabled(false);
    m_simulate->setEnabled(false);
    m_summary->setText(tr("Working…"));
    m_running = true;
    m_watcher->setFuture(QtConcurrent::run(std::move(job)));
    emit completeChanged();
}

void MachiningAnalysisPage::loadCapture(const QString& path)
{
    const QString stage = m_stage->text().trimmed();
    run([path, stage] {
        auto cap = io::readCaptureCsvFile(path.toStdString());
        if (!cap) {
            CutAnalysis a;
            a.source = path;
            a.error = QString::fromStdString(cap.error().detail);
            return a;
        }
        return analyseCut(std::move(*cap), path, stage);
    });
}

void MachiningAnalysisPage::simulateCut()
{
    auto tool = m_toolPage.tool();
    auto in = m_cutPage.inputs();
    const auto dur = machiningNumber(m_duration->text());
    if (!tool || !in || !dur || !(*dur > 0.3) || *dur > 10.0) {
        m_summary->setText(!tool || !in ? tr("The tool or cut data are not valid.")
                                        : tr("duration: a number of seconds in (0.3, 10]"));
        return;
    }
    const QString stage = m_stage->text().trimmed();
    const QString source = tr("simulated cut on vmc X, %1 min⁻¹, %2 mm").arg(f(in->rpm, 0), f(in->depthM * 1e3, 3));
    run([t = *tool, c = *in, d = *dur, stage, source] {
        auto cap = simulateVmcCut(t, c, d);
        if (!cap) {
            CutAnalysis a;
            a.source = source;
            a.error = QString::fromStdString(cap.error().detail);
            return a;
        }
        return analyseCut(std::move(*cap), source, stage);
    });
}

void MachiningAnalysisPage::show()
{
    m_running = false;
    m_busy->setVisible(false);
    m_load->setEnabled(true);
    m_simulate->setEnabled(true);
    m_plot->clear();
    m_table->setRowCount(0);
    if (!m_analysis.error.isEmpty()) {
        m_summary->setText(tr("Not analysed: %1").arg(m_analysis.error));
        emit completeChanged();
        return;
    }
    const auto& a = m_analysis;
    if (const auto* truth = a.capture->channel("cutting_force_N"))
        m_plot->addSeries(tr("cutting force (in the capture)"), a.timeS, truth->data, "N", QColor(170, 170, 170));
    m_plot->addSeries(tr("cutting force (observer)"), a.timeS, a.forceEstimateN, "N", QColor(0, 90, 180));
    if (const auto* tool = a.capture->channel("tool_x_m")) {
        std::vector<double> um(tool->data.size());
        std::transform(tool->data.begin(), tool->data.end(), um.begin(), [](double v) { return v * 1e6; });
        m_plot->addSeries(tr("tool vibration x"), a.timeS, um, QString::fromUtf8("µm"), QColor(120, 60, 0));
    }
    int count = 0;
    if (a.chatter) {
        // The chatter intervals as a marker strip: 1 inside an interval, 0 outside.
        std::vector<double> flag(a.timeS.size(), 0.0);
        for (const auto& iv : a.chatter->intervals) {
            for (std::size_t i = 0; i < a.timeS.size(); ++i)
                if (a.timeS[i] >= iv.startS && a.timeS[i] <= iv.endS)
                    flag[i] = 1.0;
            const int r = m_table->rowCount();
            m_table->insertRow(r);
            m_table->setItem(r, 0, new QTableWidgetItem(f(iv.startS, 3)));
            m_table->setItem(r, 1, new QTableWidgetItem(f(iv.endS, 3)));
            m_table->setItem(r, 2, new QTableWidgetItem(f(iv.frequencyHz, 1)));
            m_table->setItem(r, 3, new QTableWidgetItem(f(iv.score, 3)));
            ++count;
        }
        m_plot->addSeries(tr("chatter detected"), a.timeS, flag, tr("flag"), QColor(200, 0, 0));
    }
    m_plot->rescale();
    m_plot->replotNow();
    QString text = tr("%1 (stage: %2). ").arg(a.source, a.stageSource);
    if (!a.chatter)
        text += tr("No chatter detection: the stage has no coupling stiffness.");
    else if (count == 0)
        text += tr("No chatter detected (vibration mode %1 Hz, %2 % of the valid windows flagged).")
                    .arg(f(a.chatter->vibrationModeHz, 1), f(100.0 * a.chatter->flaggedFraction, 1));
    else
        text += tr("CHATTER: %n interval(s) detected (vibration mode %1 Hz).", "", count)
                    .arg(f(a.chatter->vibrationModeHz, 1));
    m_summary->setText(text);
    emit completeChanged();
}

bool MachiningAnalysisPage::isComplete() const
{
    return !busy();
}

} // namespace gui
} // namespace axistune

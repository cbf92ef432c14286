// SPDX-License-Identifier: GPL-3.0-or-later
// The machining wizard's cut-analysis page (docs/wizards/machining.md): a captured cut (capture CSV) or a cut
// simulated with core/sim/Milling on the vmc X axis (the coupling of `axistune-cli simulate-cut`), then the
// cutting force observer (seed 003, spec/cutting-force-observer-and-chatter-detection.md §1) and the
// correlation chatter detection (seed 004, same spec §2) of core/machining, off the GUI thread.
#include "app/gui/MachiningWizard.h"
#include "core/io/CaptureCsv.h"
#include "core/machining/StageFromParameters.h"
#include "core/machining/StageJson.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Units.h"
#include "core/sim/CutSimulation.h"
#include "core/sim/MachineDefinition.h"
#include "widgets/TimeTracePlot.h"

#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

namespace {

QString f(double v, int decimals)
{
    return QLocale().toString(v, 'f', decimals);
}

} // namespace
// ------------------------------------------------------------------------------------------ analysis page

namespace {

/// The stage of a simulated machine's axis (like `axistune-cli chatter-detect` without --stage).
Result<machining::StageDescription> stageOfPreset(const std::string& machine, const std::string& axis)
{
    auto def = sim::loadPreset(machine);
    if (!def)
        return def.error();
    const auto* a = def->axis(axis);
    if (!a)
        return makeError(ErrorCode::NotFound, "machine " + machine + " has no axis " + axis);
    auto d = machining::stageFromAxisParameters(a->values);
    if (!d)
        return d.error();
    // A cut at constant feed is no identification opportunity (docs/machining.md): the nominal observer.
    d.value().rls.method = machining::RlsMethod::Fixed;
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
    sim::CutSimulationOptions opt;
    opt.milling = ms;
    opt.durationS = durationS;
    opt.engageS = 0.2;
    opt.lostMotion = false;  // as simulate-cut: the quasi-static lost motion swamps the vibration-mode force
    opt.seed = 3;
    auto simulated = sim::simulateCut(*axisDef, opt);
    if (!simulated)
        return simulated.error();
    model::Capture cap = std::move(simulated).value();
    cap.metadata.set(model::meta::kMachine, "vmc");
    cap.metadata.set(model::meta::kAxis, "X");
    cap.metadata.set(model::meta::kSpindleRpm, in.rpm);
    cap.metadata.set(model::meta::kAxialDepthM, in.depthM);
    cap.metadata.set(model::meta::kEngageS, opt.engageS);
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
        const auto m = cap.metadata.text(model::meta::kMachine), a = cap.metadata.text(model::meta::kAxis);
        if (!m || !a) {
            out.error = QObject::tr("%1: no stage.json given and the capture names no simulated machine/axis "
                                    "(metadata 'machine=' and 'axis=')")
                            .arg(source);
            return out;
        }
        stage = stageOfPreset(*m, *a);
        out.stageSource =
            QObject::tr("axis parameters of %1 %2").arg(QString::fromStdString(*m), QString::fromStdString(*a));
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
        if (opt.baselineS <= 0.0) {
            const auto engage = cap.metadata.optionalNumber(model::meta::kEngageS);
            if (!engage) {
                out.error = source + ": " + QString::fromStdString(engage.error().detail);
                return out;
            }
            if (engage->has_value())
                opt.baselineS = 0.75 * **engage;
        }
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

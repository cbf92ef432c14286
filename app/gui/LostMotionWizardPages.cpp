// SPDX-License-Identifier: GPL-3.0-or-later
// Pages of the lost-motion wizard (LostMotionWizard.h; docs/wizards/lost-motion.md): source,
// diagnostics, fit and prediction. The circle runs and the verification: LostMotionWizardRuns.cpp.
#include "app/gui/AppContext.h"
#include "app/gui/BallBarText.h"
#include "app/gui/LostMotionWizard.h"
#include "app/gui/WidgetUtil.h"
#include "app/gui/WizardPages.h"
#include "core/model/Constants.h"
#include "core/model/Units.h"
#include "core/sim/MachineDefinition.h"
#include "widgets/CurvePlot.h"
#include "widgets/PolarPlot.h"

#include <QApplication>
#include <QButtonGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QRadioButton>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <cmath>
#include <numbers>

namespace axistune {
namespace gui {

namespace {

using model::kRadPerDeg;

QString um(double m, int prec = 3) { return QString::number(m * 1e6, 'f', prec); }

}  // namespace

// ---------------------------------------------------------------------------------------------
// Source page

LostMotionSourcePage::LostMotionSourcePage(AppContext& ctx, LostMotionData& shared, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared)
{
    setTitle(tr("Lost motion: ball-bar traces"));
    setSubTitle(tr("Import ball-bar files or run circle tests at two or more table positions. The spring length x "
                   "of each reversal is x₀ + s·(circle centre ± R) along the identified axis."));
    auto* lay = new QVBoxLayout(this);
    auto* group = new QButtonGroup(this);
    m_importRadio = new QRadioButton(tr("Import ball-bar files (CSV)"), this);
    m_machineRadio = new QRadioButton(tr("Run circle tests on the machine"), this);
    m_importRadio->setObjectName("lmImport");
    m_machineRadio->setObjectName("lmMachine");
    group->addButton(m_importRadio);
    group->addButton(m_machineRadio);
    m_importRadio->setChecked(true);
    lay->addWidget(m_importRadio);
    lay->addWidget(m_machineRadio);

    m_importBox = new QWidget(this);
    auto* il = new QVBoxLayout(m_importBox);
    il->setContentsMargins(20, 0, 0, 0);
    m_fileList = new QListWidget(m_importBox);
    m_fileList->setObjectName("lmFiles");
    m_fileList->setMaximumHeight(90);
    il->addWidget(m_fileList);
    auto* fb = new QHBoxLayout;
    auto* add = new QPushButton(tr("Add files…"), m_importBox);
    auto* clear = new QPushButton(tr("Clear"), m_importBox);
    fb->addWidget(add);
    fb->addWidget(clear);
    fb->addStretch(1);
    il->addLayout(fb);
    m_fileErrors = new QLabel(m_importBox);
    m_fileErrors->setObjectName("lmFileErrors");
    m_fileErrors->setWordWrap(true);
    m_fileErrors->setStyleSheet("color: #b00000;");
    il->addWidget(m_fileErrors);
    lay->addWidget(m_importBox);

    m_machineBox = new QWidget(this);
    auto* ml = new QFormLayout(m_machineBox);
    ml->setContentsMargins(20, 0, 0, 0);
    m_radius = new QDoubleSpinBox(m_machineBox);
    m_radius->setRange(5, 500);
    m_radius->setValue(50);
    m_radius->setSuffix(" mm");
    m_feed = new QDoubleSpinBox(m_machineBox);
    m_feed->setRange(10, 20000);
    m_feed->setValue(1000);
    m_feed->setSuffix(" mm/min");
    m_centres = new QLineEdit("-150, 0, 150", m_machineBox);
    m_centres->setObjectName("lmCentres");
    ml->addRow(tr("Circle radius R:"), m_radius);
    ml->addRow(tr("Feed:"), m_feed);
    ml->addRow(tr("Circle centres along the identified axis [mm]:"), m_centres);
    m_machineNote = new QLabel(m_machineBox);
    m_machineNote->setWordWrap(true);
    ml->addRow(m_machineNote);
    lay->addWidget(m_machineBox);

    auto* common = new QGroupBox(tr("Model of the axis"), this);
    auto* cl = new QFormLayout(common);
    m_axisRole = new QComboBox(common);
    m_axisRole->setObjectName("lmAxisRole");
    m_axisRole->addItems({tr("First plane axis (X)"), tr("Second plane axis (Y)")});
    m_axisRole->setCurrentIndex(1);
    m_offset = new QDoubleSpinBox(common);
    m_offset->setObjectName("lmScrewOffset");
    m_offset->setRange(-10000, 10000);
    m_offset->setDecimals(1);
    m_offset->setValue(200);
    m_offset->setSuffix(" mm");
    m_sign = new QComboBox(common);
    m_sign->addItems({"+1", "−1"});
    m_exclude = new QDoubleSpinBox(common);
    m_exclude->setRange(0.5, 30);
    m_exclude->setValue(8.0);
    m_exclude->setSuffix(QString::fromUtf8(" °"));
    m_exclude->setToolTip(tr("Half-width of the zone around each reversal left out of the step fit: the friction "
                             "spike must not count as lost motion (±8° at 1000 mm/min, R 50 mm)."));
    cl->addRow(tr("Axis to identify:"), m_axisRole);
    cl->addRow(tr("Screw length offset x₀ (coupling to load point at table 0):"), m_offset);
    cl->addRow(tr("Sign s (spring length grows with the coordinate: +1):"), m_sign);
    cl->addRow(tr("Reversal zone ±:"), m_exclude);
    lay->addWidget(common);
    lay->addStretch(1);

    connect(m_importRadio, &QRadioButton::toggled, this, [this] { updateMode(); });
    connect(add, &QPushButton::clicked, this, [this] {
        addFiles(QFileDialog::getOpenFileNames(this, tr("Ball-bar files"), {}, tr("Ball-bar CSV (*.csv);;All files (*)")));
    });
    connect(clear, &QPushButton::clicked, this, [this] {
        m_d.files.clear();
        m_d.traces.clear();
        m_fileList->clear();
        m_fileErrors->clear();
        emit completeChanged();
    });
    connect(m_centres, &QLineEdit::textChanged, this, &QWizardPage::completeChanged);
    updateMode();
}

bool LostMotionSourcePage::addFiles(const QStringList& paths)
{
    QStringList errors;
    for (const auto& p : paths) {
        auto t = io::readBallBarCsvFile(p.toStdString());
        if (!t) {
            errors << qs(t.error().detail);
            continue;
        }
        m_d.files << p;
        m_d.traces.push_back(std::move(t).value());
        const auto& tr0 = m_d.traces.back();
        m_fileList->addItem(tr("%1 — R %2 mm, centre (%3, %4) mm, %5 samples")
                                .arg(QFileInfo(p).fileName())
                                .arg(tr0.radiusM * 1e3)
                                .arg(tr0.centerXM * 1e3)
                                .arg(tr0.centerYM * 1e3)
                                .arg(tr0.size()));
    }
    m_fileErrors->setText(errors.join("\n"));
    emit completeChanged();
    return errors.isEmpty();
}

void LostMotionSourcePage::initializePage()
{
    CircleRunner probe(m_ctx);
    const QString why = probe.unavailableReason();
    m_machineRadio->setEnabled(why.isEmpty());
    m_machineNote->setText(why.isEmpty() ? tr("Circle tests run on %1 with the drive's current parameters; both plane "
                                              "axes move.")
                                               .arg(m_ctx.machine())
                                         : why);
    if (!why.isEmpty())
        m_importRadio->setChecked(true);
    updateMode();
}

void LostMotionSourcePage::updateMode()
{
    m_importBox->setEnabled(m_importRadio->isChecked());
    m_machineBox->setEnabled(m_machineRadio->isChecked());
    emit completeChanged();
}

static std::vector<double> parseCentres(const QString& text, bool* ok)
{
    std::vector<double> out;
    *ok = true;
    for (const auto& part : text.split(',', Qt::SkipEmptyParts)) {
        bool good = false;
        const double v = part.trimmed().toDouble(&good);
        if (!good) {
            *ok = false;
            return {};
        }
        out.push_back(v * 1e-3);
    }
    return out;
}

bool LostMotionSourcePage::isComplete() const
{
    if (m_importRadio->isChecked())
        return !m_d.traces.empty();
    bool ok = false;
    const auto c = parseCentres(m_centres->text(), &ok);
    return ok && c.size() >= 2;
}

bool LostMotionSourcePage::validatePage()
{
    m_d.fromMachine = m_machineRadio->isChecked();
    m_d.axisRole = m_axisRole->currentIndex();
    m_d.screwOffsetM = m_offset->value() * 1e-3;
    m_d.screwSign = m_sign->currentIndex() == 0 ? 1.0 : -1.0;
    m_d.options.excludeDeg = m_exclude->value();
    m_d.radiusM = m_radius->value() * 1e-3;
    m_d.feedMPerS = m_feed->value() / 60000.0;
    bool ok = false;
    m_d.centresM = parseCentres(m_centres->text(), &ok);
    if (m_d.fromMachine) {
        m_d.traces.clear();
        m_d.files.clear();
    } else if (!m_d.traces.empty()) {
        m_d.plane = qs(m_d.traces.front().plane);
    }
    return true;
}

int LostMotionSourcePage::nextId() const
{
    return m_machineRadio->isChecked() ? LostMotionWizard::Safety : LostMotionWizard::Diagnostics;
}

// ---------------------------------------------------------------------------------------------
// Diagnostics page

LostMotionDiagnosticsPage::LostMotionDiagnosticsPage(LostMotionData& shared, QWidget* parent)
    : QWizardPage(parent), m_d(shared)
{
    setTitle(tr("Ball-bar diagnostics"));
    setSubTitle(tr("Measured traces over the nominal circle (deviation magnified), reversal markers, and every "
                   "finding with the rule that decided it."));
    auto* lay = new QVBoxLayout(this);
    auto* split = new QSplitter(Qt::Horizontal, this);
    m_plot = new widgets::PolarPlot(split);
    m_plot->setObjectName("lmPolar");
    m_table = makeTable(split, {tr("Finding"), tr("Value"), tr("Rule")});
    m_table->setObjectName("lmDiagnostics");
    split->addWidget(m_plot);
    split->addWidget(m_table);
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 3);
    lay->addWidget(split, 1);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    lay->addWidget(m_status);
    m_watcher = new QFutureWatcher<LostMotionData>(this);
    connect(m_watcher, &QFutureWatcherBase::finished, this, [this] {
        // Only the analysis results are taken over (the inputs are the page's own copy).
        const LostMotionData r = m_watcher->result();
        m_d.report = r.report;
        m_d.points = r.points;
        m_d.fit = r.fit;
        m_d.conventionalBacklashM = r.conventionalBacklashM;
        m_d.predictions = r.predictions;
        m_d.analysisError = r.analysisError;
        m_done = true;
        showResults();
        emit completeChanged();
    });
}

void LostMotionDiagnosticsPage::initializePage()
{
    m_done = false;
    m_plot->clear();
    m_table->setRowCount(0);
    m_d.report.reset();
    m_d.fit.reset();
    m_d.points.clear();
    m_d.predictions.clear();
    m_d.analysisError.clear();
    m_status->setText(tr("Analysing %1 traces…").arg(m_d.traces.size()));
    emit completeChanged();
    // The analysis works on a copy: the wizard may go back or close while it runs.
    m_watcher->setFuture(QtConcurrent::run([in = m_d]() mutable {
        LostMotionData* d = &in;
        auto rep = tuning::analyzeBallBar(d->traces, d->options);
        if (rep)
            d->report = std::move(rep).value();
        else
            d->analysisError = qs(rep.error().detail);
        const tuning::LostMotionSetup setup{d->axisRole, d->screwOffsetM, d->screwSign};
        for (const auto& t : d->traces) {
            auto pts = tuning::extractLostMotionPoints(t, setup, d->options);
            if (!pts) {
                d->analysisError = qs(pts.error().detail);
                return in;
            }
            d->points.insert(d->points.end(), pts->begin(), pts->end());
        }
        auto fit = tuning::fitLostMotion(d->points);
        if (!fit) {
            d->analysisError = qs(fit.error().detail);
            return in;
        }
        d->fit = *fit;
        double xbl = 0.0;
        for (const auto& p : d->points)
            xbl += p.dxM / static_cast<double>(d->points.size());
        d->conventionalBacklashM = xbl;
        for (const auto& t : d->traces) {
            auto p = tuning::predictCompensation(t, setup, *fit, xbl, d->options);
            if (!p) {
                d->analysisError = qs(p.error().detail);
                return in;
            }
            d->predictions.push_back(std::move(p).value());
        }
        return in;
    }));
}

void LostMotionDiagnosticsPage::showResults()
{
    for (std::size_t i = 0; i < m_d.traces.size(); ++i) {
        const auto& t = m_d.traces[i];
        const double c = m_d.axisRole == 0 ? t.centerXM : t.centerYM;
        m_plot->addTrace(t, tr("%1 = %2 mm").arg(m_d.axisName()).arg(c * 1e3));
    }
    m_plot->addMarker(0.0, tr("X rev."));
    m_plot->addMarker(std::numbers::pi, tr("X rev."));
    m_plot->addMarker(std::numbers::pi / 2, tr("Y rev."));
    m_plot->addMarker(3 * std::numbers::pi / 2, tr("Y rev."));
    if (m_d.report) {
        for (const auto& f : m_d.report->findings)
            addRow(m_table, {BallBarText::findingName(f.name),
                             QString("%1 %2").arg(f.value, 0, 'g', 4).arg(qs(model::unitLabel(f.unit))),
                             BallBarText::rule(f)});
        for (const auto& r : m_d.report->refused)
            addRow(m_table, {tr("not computed"), QString(), BallBarText::rule(r)});
    }
    m_table->setColumnWidth(0, 150);
    m_table->setColumnWidth(1, 90);
    m_table->resizeRowsToContents();
    m_status->setText(m_d.analysisError.isEmpty() ? tr("%1 traces, %2 reversal events of axis %3.")
                                                         .arg(m_d.traces.size())
                                                         .arg(m_d.points.size())
                                                         .arg(m_d.axisName())
                                                   : tr("Analysis failed: %1").arg(m_d.analysisError));
}

bool LostMotionDiagnosticsPage::isComplete() const { return m_done && m_d.fit.has_value(); }

// ---------------------------------------------------------------------------------------------
// Fit and prediction page

LostMotionFitPage::LostMotionFitPage(AppContext& ctx, LostMotionData& shared, ApplyPage* apply, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared), m_apply(apply)
{
    setTitle(tr("A/B fit and predicted compensation"));
    setSubTitle(tr("Δx = (A + B·x)·ΔT (spec eq. 4.12): each reversal gives a point Δx/ΔT at its spring length x; "
                   "the line is A + B·x. The torque-synchronous compensation (A + B·x)·T_m is predicted on the "
                   "measured trace, next to the conventional step of the mean lost motion."));
    auto* lay = new QVBoxLayout(this);
    m_result = new QLabel(this);
    m_result->setObjectName("lmFitResult");
    m_result->setWordWrap(true);
    lay->addWidget(m_result);
    auto* split = new QSplitter(Qt::Horizontal, this);
    m_fitPlot = new widgets::CurvePlot(split);
    m_fitPlot->setObjectName("lmFitPlot");
    m_fitPlot->setAxes(tr("Spring length x"), "mm", tr("Δx/ΔT"), QString::fromUtf8("µm/(N·m)"));
    m_predPlot = new widgets::PolarPlot(split);
    m_predPlot->setObjectName("lmPrediction");
    split->addWidget(m_fitPlot);
    split->addWidget(m_predPlot);
    lay->addWidget(split, 1);
    m_predTable = makeTable(this, {tr("Trace"), tr("Circularity measured / proposed / conventional"),
                                   tr("Cut-in measured / proposed / conventional")});
    m_predTable->setObjectName("lmPredTable");
    m_predTable->setMaximumHeight(110);
    lay->addWidget(m_predTable);
}

void LostMotionFitPage::initializePage()
{
    m_fitPlot->clear();
    m_predPlot->clear();
    m_predTable->setRowCount(0);
    if (!m_d.fit)
        return;
    const auto& fit = *m_d.fit;
    std::vector<double> x, y;
    double xmin = 1e9, xmax = -1e9;
    for (const auto& p : m_d.points) {
        x.push_back(p.xM * 1e3);
        y.push_back(p.dxM / p.dTNm * 1e6);
        xmin = std::min(xmin, p.xM);
        xmax = std::max(xmax, p.xM);
    }
    m_fitPlot->addCurve(tr("reversals"), x, y, QColor(0, 90, 200), Qt::SolidLine, true);
    const double lo = std::min(0.0, xmin), hi = xmax + 0.05;
    m_fitPlot->addCurve(tr("A + B·x"), {lo * 1e3, hi * 1e3},
                        {(fit.aMPerNm + fit.bPerNm * lo) * 1e6, (fit.aMPerNm + fit.bPerNm * hi) * 1e6},
                        QColor(200, 60, 0));
    m_fitPlot->rescale();
    QString text = tr("A = %1 µm/(N·m), B = %2 µm/(N·m·m) (%3, %4 points, residual rms %5 µm).")
                       .arg(fit.aMPerNm * 1e6, 0, 'f', 3)
                       .arg(fit.bPerNm * 1e6, 0, 'f', 2)
                       .arg(qs(tuning::lostMotionMethodName(fit.method)))
                       .arg(m_d.points.size())
                       .arg(fit.residualRmsM * 1e6, 0, 'f', 3);
    if (fit.aStdErr && fit.bStdErr)
        text += " " + tr("Standard errors: A ±%1, B ±%2.").arg(*fit.aStdErr * 1e6, 0, 'f', 3).arg(*fit.bStdErr * 1e6, 0, 'f', 2);
    for (const auto& w : fit.warnings)
        text += "\n" + tr("Warning: %1").arg(qs(w));
    text += "\n" + tr("Rule: least squares on the regressors [ΔT, x·ΔT] over all reversals (two points: the general "
                      "two-point form); conventional step for comparison x_bl = %1 µm (mean measured lost motion).")
                       .arg(um(m_d.conventionalBacklashM, 2));
    m_result->setText(text);
    // The prediction on the trace with the largest lost motion (the last table position).
    if (!m_d.predictions.empty()) {
        const std::size_t k = m_d.predictions.size() - 1;
        const auto& p = m_d.predictions[k];
        m_predPlot->setNominalRadius(m_d.traces[k].radiusM);
        m_predPlot->addTrace(tr("measured"), p.angleRad, p.measuredM, QColor(0, 90, 200));
        m_predPlot->addTrace(tr("predicted, proposed"), p.angleRad, p.proposedM, QColor(0, 150, 60));
        m_predPlot->addTrace(tr("predicted, conventional"), p.angleRad, p.conventionalM, QColor(200, 60, 0), Qt::DashLine);
        const QString ax = m_d.axisName();
        m_predPlot->addMarker(m_d.axisRole == 0 ? 0.0 : std::numbers::pi / 2, tr("%1 rev.").arg(ax));
        m_predPlot->addMarker(m_d.axisRole == 0 ? std::numbers::pi : 3 * std::numbers::pi / 2, tr("%1 rev.").arg(ax));
    }
    auto opt = [](const std::optional<double>& v) { return v ? um(*v, 2) : QString("–"); };
    for (std::size_t k = 0; k < m_d.predictions.size(); ++k) {
        const auto& p = m_d.predictions[k];
        addRow(m_predTable, {qs(m_d.traces[k].source),
                             tr("%1 / %2 / %3 µm").arg(opt(p.measuredCircularityM), opt(p.proposedCircularityM),
                                                       opt(p.conventionalCircularityM)),
                             tr("%1 / %2 / %3 µm").arg(um(p.measuredCutInM, 2), um(p.proposedCutInM, 2),
                                                       um(p.conventionalCutInM, 2))});
    }
    m_predTable->setColumnWidth(0, 220);
    m_predTable->setColumnWidth(1, 360);
    // The proposal: torque-synchronous compensation (mode 2) with A, B and x₀ on the identified axis.
    const model::ParameterValues proposal{{"lostmotion.mode", 2.0},
                                          {"lostmotion.A", fit.aMPerNm},
                                          {"lostmotion.B", fit.bPerNm},
                                          {"lostmotion.screw_offset", m_d.screwOffsetM}};
    if (m_ctx.drive().isConnected()) {
        m_apply->setProposal(m_d.axisName(), proposal);
        m_ctx.setProposed(m_d.axisName(), proposal);
    }
}

bool LostMotionFitPage::isComplete() const { return m_d.fit.has_value(); }

int LostMotionFitPage::nextId() const
{
    return m_ctx.drive().isConnected() && m_ctx.axes().contains(m_d.axisName()) ? LostMotionWizard::Apply
                                                                                : LostMotionWizard::Save;
}

}  // namespace gui
}  // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
// Circle tests of the lost-motion wizard (LostMotionWizard.h "Circle tests"; docs/wizards/lost-motion.md):
// the runner, the circle page and the verification page.
#include "app/gui/AppContext.h"
#include "app/gui/DriveController.h"
#include "app/gui/LostMotionWizard.h"
#include "app/gui/WidgetUtil.h"
#include "app/gui/WizardPages.h"
#include "core/device/CircleDriveTest.h"
#include "core/model/Constants.h"
#include "core/model/Units.h"
#include "core/sim/CircleRun.h"
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

#include <algorithm>
#include <cmath>
#include <numbers>

namespace axistune {
namespace gui {

namespace {

using model::kRadPerDeg;
constexpr int kProgressSteps = 1000;  ///< progress units per circle

QString um(double m, int prec = 3) { return QString::number(m * 1e6, 'f', prec); }

/// Deviation of a trace as a new trace (the prediction drawn as a ball-bar trace).
io::BallBarTrace withDeviation(const io::BallBarTrace& t, const std::vector<double>& dev)
{
    io::BallBarTrace out = t;
    out.deviationM = dev;
    return out;
}

/// The mean reversal step of one axis over the reversals a trace covers.
std::optional<double> meanStep(const io::BallBarTrace& t, int axis, const tuning::BallBarOptions& opt)
{
    auto run = tuning::analyzeRun(t, opt);
    if (!run)
        return std::nullopt;
    double sum = 0.0;
    int n = 0;
    for (const auto& e : run->events) {
        if (e.axis == axis) {
            sum += e.stepM;
            ++n;
        }
    }
    return n > 0 ? std::optional<double>(sum / n) : std::nullopt;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// CircleRunner

CircleRunner::CircleRunner(AppContext& ctx, QObject* parent)
    : QObject(parent), m_ctx(ctx), m_abort(std::make_shared<std::atomic<bool>>(false))
{
}

QString CircleRunner::unavailableReason() const
{
    if (!m_ctx.drive().isConnected())
        return tr("Not connected: circle tests need a connection to a machine.");
    return {};
}

void CircleRunner::start(const QString& plane, std::vector<sim::CircleTestOptions> circles)
{
    if (m_running)
        return;
    m_plane = plane;
    m_circles = std::move(circles);
    m_traces.clear();
    m_currentId = 0;
    m_abort->store(false);
    if (const QString why = unavailableReason(); !why.isEmpty()) {
        emit finished(false, why, false);
        return;
    }
    m_running = true;
    runNext();
}

void CircleRunner::abort()
{
    if (!m_running)
        return;
    m_abort->store(true);
    m_ctx.drive().abort();  // stops the running circle at once; the drive restores both axes' parameters
    if (m_currentId == 0)
        finish(false, {}, true);
}

void CircleRunner::runNext()
{
    const int n = static_cast<int>(m_circles.size());
    const int i = static_cast<int>(m_traces.size());
    if (m_abort->load())
        return finish(false, {}, true);
    if (i >= n)
        return finish(true, {}, false);
    emit progress(i * kProgressSteps, n * kProgressSteps, tr("Circle %1 of %2").arg(i + 1).arg(n));
    auto* req = m_ctx.drive().runTest(device::circleRequestOf(m_circles[static_cast<std::size_t>(i)]));
    m_currentId = req->id();
    connect(req, &DriveRequest::finished, this, [this](const DriveReply& r) {
        if (!m_running || r.id != m_currentId)
            return;
        m_currentId = 0;
        onCircle(r);
    });
    connect(req, &DriveRequest::progress, this, [this](double fraction, const QString&) {
        if (!m_running)
            return;
        const int total = static_cast<int>(m_circles.size());
        const int done = static_cast<int>(m_traces.size());
        emit progress(done * kProgressSteps +
                          static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * kProgressSteps)),
                      total * kProgressSteps, tr("Circle %1 of %2").arg(done + 1).arg(total));
    });
}

void CircleRunner::onCircle(const DriveReply& r)
{
    if (!r.ok || !r.capture) {
        const bool aborted = r.code == ErrorCode::Aborted || m_abort->load();
        return finish(false, aborted ? QString() : tr("Circle %1 failed: %2").arg(m_traces.size() + 1).arg(r.error),
                      aborted);
    }
    auto evaluated = sim::ballBarFromCircleTrace(*r.capture);
    if (!evaluated)
        return finish(false,
                      tr("Circle %1 could not be evaluated: %2").arg(m_traces.size() + 1).arg(qs(evaluated.error().detail)),
                      false);
    io::BallBarTrace bb = std::move(evaluated).value();
    const auto& o = m_circles[m_traces.size()];
    const bool alongX = o.centerYM == 0.0 && o.centerXM != 0.0;
    bb.source = QString("circle %1 = %2 mm")
                     .arg(qs(alongX ? o.axisX : o.axisY))
                     .arg((alongX ? o.centerXM : o.centerYM) * 1e3)
                     .toStdString();
    m_traces.push_back(std::move(bb));
    runNext();
}

void CircleRunner::finish(bool ok, const QString& error, bool aborted)
{
    m_running = false;
    m_currentId = 0;
    if (aborted)
        emit finished(false, tr("Aborted by the operator after %1 of %2 circles.").arg(m_traces.size()).arg(m_circles.size()),
                      true);
    else
        emit finished(ok, error, false);
}

// ---------------------------------------------------------------------------------------------
// Circle page

LostMotionCirclePage::LostMotionCirclePage(AppContext& ctx, LostMotionData& shared, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared)
{
    setTitle(tr("Circle tests"));
    setSubTitle(tr("Both plane axes move on circles at the table positions chosen. Abort stops the running "
                   "circle at once; the drive restores the parameters of both axes."));
    auto* lay = new QVBoxLayout(this);
    m_label = new QLabel(this);
    m_label->setWordWrap(true);
    lay->addWidget(m_label);
    m_bar = new QProgressBar(this);
    m_bar->setTextVisible(false);
    lay->addWidget(m_bar);
    auto* b = new QHBoxLayout;
    m_abort = new QPushButton(tr("Abort"), this);
    m_abort->setObjectName("lmCircleAbort");
    m_abort->setStyleSheet("QPushButton { color: #b00000; font-weight: bold; }");
    m_retry = new QPushButton(tr("Run again"), this);
    b->addWidget(m_abort);
    b->addWidget(m_retry);
    b->addStretch(1);
    lay->addLayout(b);
    lay->addStretch(1);
    m_runner = new CircleRunner(ctx, this);
    connect(m_abort, &QPushButton::clicked, m_runner, &CircleRunner::abort);
    connect(m_retry, &QPushButton::clicked, this, &LostMotionCirclePage::start);
    connect(m_runner, &CircleRunner::progress, this, [this](int done, int total, const QString& text) {
        m_bar->setRange(0, total);
        m_bar->setValue(done);
        m_label->setText(text);
    });
    connect(m_runner, &CircleRunner::finished, this, [this](bool ok, const QString& error, bool aborted) {
        m_ok = ok;
        m_d.traces = m_runner->traces();
        m_abort->setEnabled(false);
        m_retry->setEnabled(!ok);
        m_bar->setValue(static_cast<int>(m_d.traces.size()) * kProgressSteps);
        m_label->setText(ok ? tr("Completed: %1 circles.").arg(m_d.traces.size())
                            : (aborted ? tr("Aborted: %1") : tr("Failed: %1")).arg(error));
        m_ctx.log(m_label->text());
        if (!ok)
            emit runFailed(error);
        emit completeChanged();
    });
}

void LostMotionCirclePage::start()
{
    std::vector<sim::CircleTestOptions> circles;
    int i = 0;
    for (double c : m_d.centresM) {
        sim::CircleTestOptions o;
        o.axisX = m_d.plane.mid(0, 1).toStdString();
        o.axisY = m_d.plane.mid(1, 1).toStdString();
        o.radiusM = m_d.radiusM;
        o.feedMPerS = m_d.feedMPerS;
        (m_d.axisRole == 0 ? o.centerXM : o.centerYM) = c;
        o.seed = static_cast<std::uint64_t>(++i);
        circles.push_back(o);
    }
    m_ok = false;
    m_abort->setEnabled(true);
    m_retry->setEnabled(false);
    emit completeChanged();
    m_runner->start(m_d.plane, circles);
}

void LostMotionCirclePage::initializePage() { start(); }

void LostMotionCirclePage::cleanupPage()
{
    if (m_runner->isRunning())
        m_runner->abort();
}

bool LostMotionCirclePage::isComplete() const { return m_ok && !m_runner->isRunning(); }

// ---------------------------------------------------------------------------------------------
// Verify page

LostMotionVerifyPage::LostMotionVerifyPage(AppContext& ctx, LostMotionData& shared, ApplyPage* apply, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared), m_apply(apply)
{
    setTitle(tr("Verify with a new circle"));
    setSubTitle(tr("A circle at the last table position with the compensation applied: measured against the "
                   "prediction and against the trace before."));
    auto* lay = new QVBoxLayout(this);
    m_label = new QLabel(this);
    m_label->setWordWrap(true);
    lay->addWidget(m_label);
    auto* row = new QHBoxLayout;
    m_bar = new QProgressBar(this);
    m_bar->setTextVisible(false);
    m_abort = new QPushButton(tr("Abort"), this);
    m_abort->setStyleSheet("QPushButton { color: #b00000; font-weight: bold; }");
    row->addWidget(m_bar, 1);
    row->addWidget(m_abort);
    lay->addLayout(row);
    auto* split = new QSplitter(Qt::Horizontal, this);
    m_plot = new widgets::PolarPlot(split);
    m_plot->setObjectName("lmVerifyPlot");
    m_table = makeTable(split, {tr("Quantity"), tr("Before"), tr("Predicted"), tr("Measured")});
    m_table->setObjectName("lmVerifyTable");
    split->addWidget(m_plot);
    split->addWidget(m_table);
    lay->addWidget(split, 1);
    m_runner = new CircleRunner(ctx, this);
    connect(m_abort, &QPushButton::clicked, m_runner, &CircleRunner::abort);
    connect(m_runner, &CircleRunner::progress, this, [this](int done, int total, const QString& text) {
        m_bar->setRange(0, total);
        m_bar->setValue(done);
        m_label->setText(text);
    });
    connect(m_runner, &CircleRunner::finished, this, [this](bool ok, const QString& error, bool aborted) {
        m_abort->setEnabled(false);
        m_bar->setRange(0, 1);
        m_bar->setValue(1);
        if (!ok || m_runner->traces().empty()) {
            m_label->setText((aborted ? tr("Aborted: %1") : tr("Failed: %1")).arg(error));
            m_done = true;
            emit completeChanged();
            emit runFailed(tr("The verification circle failed: %1").arg(error));
            return;
        }
        m_d.verification = m_runner->traces().front();
        evaluate();
        m_done = true;
        emit completeChanged();
    });
}

void LostMotionVerifyPage::initializePage()
{
    m_done = false;
    m_plot->clear();
    m_table->setRowCount(0);
    m_d.verification.reset();
    if (!m_apply->applied()) {
        m_label->setText(tr("The compensation was not applied: nothing to verify."));
        m_abort->setEnabled(false);
        m_done = true;
        return;
    }
    if (const QString why = m_runner->unavailableReason(); !why.isEmpty()) {
        m_label->setText(why + " " + tr("Verify with a new ball-bar measurement and compare it in the session review."));
        m_abort->setEnabled(false);
        m_done = true;
        return;
    }
    sim::CircleTestOptions o;
    o.axisX = m_d.plane.mid(0, 1).toStdString();
    o.axisY = m_d.plane.mid(1, 1).toStdString();
    o.radiusM = m_d.radiusM;
    o.feedMPerS = m_d.feedMPerS;
    const auto& last = m_d.traces.back();
    o.radiusM = last.radiusM;
    o.feedMPerS = last.feedMPerS;
    o.centerXM = last.centerXM;
    o.centerYM = last.centerYM;
    o.seed = 101;
    m_bar->setRange(0, 0);
    m_abort->setEnabled(true);
    m_runner->start(m_d.plane, {o});
}

void LostMotionVerifyPage::evaluate()
{
    const auto& before = m_d.traces.back();
    const auto& after = *m_d.verification;
    const auto& pred = m_d.predictions.back();
    const io::BallBarTrace predicted = withDeviation(before, pred.proposedM);
    m_d.stepBeforeM = meanStep(before, m_d.axisRole, m_d.options);
    m_d.stepAfterM = meanStep(after, m_d.axisRole, m_d.options);
    m_d.predictedStepAfterM = meanStep(predicted, m_d.axisRole, m_d.options);
    m_d.circularityBeforeM = pred.measuredCircularityM;
    m_d.predictedCircularityM = pred.proposedCircularityM;
    if (auto c = tuning::circularityOf(after.angleRad, after.deviationM))
        m_d.circularityAfterM = *c;
    m_plot->addTrace(before, tr("before"), QColor(0, 90, 200));
    m_plot->addTrace(predicted, tr("predicted"), QColor(0, 150, 60), Qt::DashLine);
    m_plot->addTrace(after, tr("measured after"), QColor(200, 0, 120));
    auto opt = [](const std::optional<double>& v) { return v ? um(*v, 2) + QString::fromUtf8(" µm") : QString("–"); };
    addRow(m_table, {tr("Reversal step of %1").arg(m_d.axisName()), opt(m_d.stepBeforeM), opt(m_d.predictedStepAfterM),
                     opt(m_d.stepAfterM)});
    addRow(m_table, {tr("Circularity"), opt(m_d.circularityBeforeM), opt(m_d.predictedCircularityM),
                     opt(m_d.circularityAfterM)});
    const bool better = m_d.stepBeforeM && m_d.stepAfterM && std::abs(*m_d.stepAfterM) < std::abs(*m_d.stepBeforeM);
    m_label->setText(better ? tr("The reversal step fell from %1 to %2. If the result is worse than predicted, "
                                 "restore the previous values on the apply page (Back).")
                                  .arg(opt(m_d.stepBeforeM), opt(m_d.stepAfterM))
                            : tr("The reversal step did not fall (%1 → %2): check x₀ and the sign, or restore the "
                                 "previous values on the apply page (Back).")
                                  .arg(opt(m_d.stepBeforeM), opt(m_d.stepAfterM)));
}

void LostMotionVerifyPage::cleanupPage()
{
    if (m_runner->isRunning())
        m_runner->abort();
}

bool LostMotionVerifyPage::isComplete() const { return m_done && !m_runner->isRunning(); }

}  // namespace gui
}  // namespace axistune

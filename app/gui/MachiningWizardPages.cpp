// SPDX-License-Identifier: GPL-3.0-or-later
// The machining wizard's lobes and advice pages (docs/wizards/machining.md): lobes by semi-discretization
// (spec/chatter-stability-and-spindle-speed.md §2), the stable-pocket rule (§3.0.2) and the Kalman AR
// chatter-frequency estimate (§3.0.1), all in core/machining. The cut analysis is MachiningWizardAnalysis.cpp.
#include "app/gui/MachiningWizard.h"
#include "core/io/CaptureCsv.h"
#include "core/machining/ChatterFrequencyEstimator.h"
#include "widgets/CurvePlot.h"

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
    m_estimate->setObjectName("machEstimateText");
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
    else if (const auto fromFs = cap->metadata.samplePeriodS(); !fromFs) {
        m_estimate->setText(path + QStringLiteral(": ") + QString::fromStdString(fromFs.error().detail));
        return false;
    } else {
        ts = fromFs->value_or(0.0);
    }
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

} // namespace gui
} // namespace axistune

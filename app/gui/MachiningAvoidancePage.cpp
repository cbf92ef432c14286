// SPDX-License-Identifier: GPL-3.0-or-later
// Machining wizard: chatter avoidance in the loop on the simulated cut (MachiningAvoidancePage.h).
#include "app/gui/MachiningAvoidancePage.h"

#include "app/gui/MachiningWizard.h"
#include "core/dsp/Welch.h"
#include "core/model/MetadataKeys.h"
#include "core/sim/MachineDefinition.h"
#include "widgets/CurvePlot.h"
#include "widgets/TimeTracePlot.h"

#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSlider>
#include <QSplitter>
#include <QTimer>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <algorithm>
#include <cmath>

namespace axistune {
namespace gui {

namespace {

QString fmt(double v, int decimals)
{
    return QLocale().toString(v, 'f', decimals);
}

std::vector<double> channelOf(const model::Capture& c, const std::string& name)
{
    const auto* ch = c.channel(name);
    return ch ? ch->data : std::vector<double>{};
}

/// Welch PSD of the tool acceleration over [t0, t1] (1024-point Hann segments at the trace rate).
void addSpectrum(widgets::CurvePlot* plot, const model::Capture& c, double t0, double t1, const QString& name,
                 const QColor& color)
{
    const auto* t = c.channel("t_s");
    const auto* a = c.channel("tool_accel_y_m_s2");
    if (!t || !a || t->data.size() < 2)
        return;
    std::vector<double> x;
    for (std::size_t i = 0; i < t->data.size(); ++i)
        if (t->data[i] >= t0 && t->data[i] <= t1)
            x.push_back(a->data[i]);
    const double fs = 1.0 / (t->data[1] - t->data[0]);
    dsp::WelchOptions o;
    o.nperseg = std::min<std::size_t>(1024, x.size());
    if (o.nperseg < 16)
        return;
    auto s = dsp::crossSpectra(x, x, fs, o);
    if (!s)
        return;
    plot->addCurve(name, s->freqHz, s->pxx, color);
}

} // namespace

MachiningAvoidancePage::MachiningAvoidancePage(const MachiningToolPage& tool, const MachiningCutPage& cut,
                                               const MachiningLobesPage& lobes, QWidget* parent)
    : QWizardPage(parent), m_toolPage(tool), m_cutPage(cut), m_lobesPage(lobes)
{
    setTitle(tr("Chatter avoidance in the loop"));
    setSubTitle(tr("Runs this cut on the simulated vmc X axis while an avoidance method changes the spindle speed: "
                   "the adaptive stable-pocket rule, the multi-resonance search or extremum seeking."));
    m_method = new QComboBox(this);
    m_method->setObjectName("avoidMethod");
    m_method->addItem(tr("none (constant speed)"), "none");
    m_method->addItem(tr("adaptive (stable pocket)"), "adaptive");
    m_method->addItem(tr("multimode (J_chat search)"), "multimode");
    m_method->addItem(tr("ESC (extremum seeking)"), "esc");
    m_method->setCurrentIndex(1);
    m_sensor = new QComboBox(this);
    m_sensor->setObjectName("avoidSensor");
    m_sensor->addItem(tr("accelerometer on the spindle"), "accel");
    m_sensor->addItem(tr("feed-stage disturbance observer"), "dob");
    m_duration = new QLineEdit(fmt(1.0, 1), this);
    m_duration->setObjectName("avoidDuration");
    m_duration->setMaximumWidth(70);
    m_escStart = new QLineEdit(fmt(0.5, 1), this);
    m_escStart->setObjectName("avoidEscStart");
    m_escMin = new QLineEdit(this);
    m_escMin->setObjectName("avoidEscMin");
    m_escMax = new QLineEdit(this);
    m_escMax->setObjectName("avoidEscMax");
    m_escCurv = new QLineEdit(QStringLiteral("1e5"), this);
    m_escCurv->setObjectName("avoidEscCurvature");
    m_escCurv->setToolTip(tr("Assumed curvature f'' of the cost near its minimum. The cost scales with the feed "
                             "squared: the seed's 1e5 is for its 0.5 mm/s table feed; this page cuts with f_z "
                             "0.1 mm"));
    m_sigmaTh = new QLineEdit(this);
    m_sigmaTh->setObjectName("avoidSigmaTh");
    m_sigmaTh->setMaximumWidth(80);
    m_sigmaTh->setPlaceholderText(tr("table"));
    m_sigmaTh->setToolTip(tr("Trigger threshold on the squared filtered signal ((m/s²)² or N²); empty: the table "
                             "value (Table 3/4/5). Table 4's 1e4 N² was set for a 3.5 mm cut"));
    for (auto* e : {m_escStart, m_escMin, m_escMax, m_escCurv})
        e->setMaximumWidth(80);
    m_run = new QPushButton(tr("Run cut"), this);
    m_run->setObjectName("avoidRun");
    m_abort = new QPushButton(tr("Abort"), this);
    m_abort->setObjectName("avoidAbort");
    m_abort->setEnabled(false);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 100);
    m_progress->setValue(0);
    m_trace = new widgets::TimeTracePlot(this);
    m_trace->setObjectName("avoidTrace");
    m_spectrum = new widgets::CurvePlot(this);
    m_spectrum->setObjectName("avoidSpectrum");
    m_spectrum->setAxes(tr("Frequency"), tr("Hz"), tr("PSD of the acceleration"), tr("(m/s²)²/Hz"), false, true);
    m_lobes = new widgets::CurvePlot(this);
    m_lobes->setObjectName("avoidLobes");
    m_lobes->setAxes(tr("Spindle speed"), tr("min⁻¹"), tr("Limit depth"), tr("mm"));
    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setObjectName("avoidTime");
    m_slider->setRange(0, 1000);
    m_slider->setValue(1000);
    m_slider->setToolTip(tr("Moves the operating point on the lobes through the cut"));
    m_summary = new QLabel(this);
    m_summary->setObjectName("avoidSummary");
    m_summary->setWordWrap(true);

    auto* grid = new QGridLayout;
    grid->addWidget(new QLabel(tr("Method"), this), 0, 0);
    grid->addWidget(m_method, 0, 1);
    grid->addWidget(new QLabel(tr("Sensor"), this), 0, 2);
    grid->addWidget(m_sensor, 0, 3);
    grid->addWidget(new QLabel(tr("duration [s]"), this), 0, 4);
    grid->addWidget(m_duration, 0, 5);
    grid->addWidget(new QLabel(tr("ESC from [s]"), this), 1, 0);
    grid->addWidget(m_escStart, 1, 1);
    grid->addWidget(new QLabel(tr("ESC bounds [min⁻¹]"), this), 1, 2);
    auto* bounds = new QHBoxLayout;
    bounds->addWidget(m_escMin);
    bounds->addWidget(new QLabel(QStringLiteral("–"), this));
    bounds->addWidget(m_escMax);
    grid->addLayout(bounds, 1, 3);
    grid->addWidget(new QLabel(tr("ESC f''"), this), 1, 4);
    grid->addWidget(m_escCurv, 1, 5);
    grid->addWidget(new QLabel(tr("trigger σ_th"), this), 2, 0);
    grid->addWidget(m_sigmaTh, 2, 1);
    auto* runRow = new QHBoxLayout;
    runRow->addWidget(m_run);
    runRow->addWidget(m_abort);
    runRow->addWidget(m_progress, 1);
    auto* right = new QWidget(this);
    auto* rightLay = new QVBoxLayout(right);
    rightLay->setContentsMargins(0, 0, 0, 0);
    rightLay->addWidget(m_spectrum, 1);
    rightLay->addWidget(m_lobes, 1);
    rightLay->addWidget(m_slider);
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(m_trace);
    split->addWidget(right);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    auto* lay = new QVBoxLayout(this);
    lay->addLayout(grid);
    lay->addLayout(runRow);
    lay->addWidget(split, 1);
    lay->addWidget(m_summary);

    m_watcher = new QFutureWatcher<AvoidanceRun>(this);
    connect(m_watcher, &QFutureWatcherBase::finished, this, &MachiningAvoidancePage::finished);
    m_poll = new QTimer(this);
    m_poll->setInterval(100);
    connect(m_poll, &QTimer::timeout, this,
            [this] { m_progress->setValue(static_cast<int>(std::lround(100.0 * m_done->load()))); });
    connect(m_run, &QPushButton::clicked, this, &MachiningAvoidancePage::start);
    connect(m_abort, &QPushButton::clicked, this, &MachiningAvoidancePage::abort);
    connect(m_slider, &QSlider::valueChanged, this, &MachiningAvoidancePage::showLobes);
    connect(m_method, &QComboBox::currentIndexChanged, this, &MachiningAvoidancePage::updateMethodFields);
    updateMethodFields();
}

MachiningAvoidancePage::~MachiningAvoidancePage()
{
    m_stop->store(true);
    m_watcher->waitForFinished();
}

void MachiningAvoidancePage::updateMethodFields()
{
    const bool esc = m_method->currentData().toString() == "esc";
    for (auto* e : {m_escStart, m_escMin, m_escMax, m_escCurv})
        e->setEnabled(esc);
    m_sensor->setEnabled(m_method->currentData().toString() != "none");
    m_sigmaTh->setEnabled(m_method->currentData().toString() == "adaptive" ||
                          m_method->currentData().toString() == "multimode");
}

void MachiningAvoidancePage::initializePage()
{
    if (auto in = m_cutPage.inputs()) {
        if (m_escMin->text().isEmpty())
            m_escMin->setText(fmt(0.7 * in->rpm, 0));
        if (m_escMax->text().isEmpty())
            m_escMax->setText(fmt(1.3 * in->rpm, 0));
    }
    showLobes();
}

void MachiningAvoidancePage::abort()
{
    m_stop->store(true);
}

void MachiningAvoidancePage::start()
{
    if (m_running)
        return;
    auto tool = m_toolPage.tool();
    auto in = m_cutPage.inputs();
    if (!tool || !in) {
        m_summary->setText(tr("The tool or cut data are not valid."));
        return;
    }
    const auto dur = machiningNumber(m_duration->text());
    if (!dur || !(*dur >= 0.3) || *dur > 20.0) {
        m_summary->setText(tr("duration: a number of seconds in [0.3, 20]"));
        return;
    }
    avoidance::AvoidanceCutOptions o;
    auto& ms = o.cut.milling;
    for (const auto& m : tool->modesX)
        ms.modesX.push_back({m.massKg, m.dampingNsPerM, m.stiffnessNPerM});
    for (const auto& m : tool->modesY)
        ms.modesY.push_back({m.massKg, m.dampingNsPerM, m.stiffnessNPerM});
    ms.teeth = in->cut.teeth;
    ms.ktNPerM2 = in->cut.ktNPerM2;
    ms.krNPerM2 = in->cut.krNPerM2;
    ms.radialImmersion = in->cut.radialImmersion;
    ms.upMilling = in->cut.milling == machining::MillingDirection::Up;
    ms.spindleRpm = in->rpm;
    ms.axialDepthM = in->depthM;
    ms.feedPerToothM = 0.1e-3;
    ms.spindleTimeConstantS = in->cut.spindleTimeConstantS;
    ms.spindleMinRpm = in->cut.spindleMinRpm;
    ms.spindleMaxRpm = in->cut.spindleMaxRpm;
    o.cut.durationS = *dur;
    o.cut.engageS = 0.1;
    o.cut.seed = 3;
    const QString method = m_method->currentData().toString();
    const bool dob = m_sensor->currentData().toString() == "dob";
    avoidance::applyMethodDefaults(o, avoidance::parseMethod(method.toStdString()).value(),
                                   dob ? machining::AvoidanceSensor::Dob : machining::AvoidanceSensor::Accelerometer);
    if ((o.method == avoidance::Method::Adaptive || o.method == avoidance::Method::MultiMode) &&
        !m_sigmaTh->text().trimmed().isEmpty()) {
        const auto th = machiningNumber(m_sigmaTh->text());
        if (!th || !(*th > 0.0)) {
            m_summary->setText(tr("trigger σ_th: a number > 0, or empty for the table value"));
            return;
        }
        o.adaptive.thresholdPower = *th;
    }
    if (o.method == avoidance::Method::Esc) {
        const auto lo = machiningNumber(m_escMin->text()), hi = machiningNumber(m_escMax->text());
        const auto st = machiningNumber(m_escStart->text()), cv = machiningNumber(m_escCurv->text());
        if (!lo || !hi || !st || !cv || !(*st < *dur)) {
            m_summary->setText(tr("ESC: the start time (before the end of the cut), both speed bounds and f'' "
                                  "must be numbers"));
            return;
        }
        o.esc.minRpm = *lo;
        o.esc.maxRpm = *hi;
        o.esc.startS = *st;
        o.esc.curvature = *cv;
    }
    m_durationRun = *dur;
    m_done->store(0.0);
    m_stop->store(false);
    m_running = true;
    m_run->setEnabled(false);
    m_abort->setEnabled(true);
    m_progress->setValue(0);
    m_summary->setText(tr("Running…"));
    m_poll->start();
    emit completeChanged();
    auto done = m_done;
    auto stop = m_stop;
    m_watcher->setFuture(QtConcurrent::run([o, done, stop]() mutable {
        AvoidanceRun out;
        auto def = sim::loadPreset("vmc");
        if (!def || !def->axis("X")) {
            out.error = QObject::tr("the vmc preset has no X axis");
            return out;
        }
        const double total = o.cut.durationS;
        // 1: the same cut at constant speed (the reference of the vibration figures), 2: with avoidance.
        auto constant = o;
        constant.method = avoidance::Method::None;
        constant.cut.progress = [done, stop, total](double t) {
            done->store(0.3 * t / total);
            return !stop->load();
        };
        o.cut.progress = [done, stop, total](double t) {
            done->store(0.3 + 0.7 * t / total);
            return !stop->load();
        };
        auto ref = avoidance::runAvoidanceCut(*def->axis("X"), constant);
        if (ref) {
            auto r = avoidance::channelRms(ref->capture, "tool_accel_y_m_s2", std::max(0.1, total - 0.3), total);
            out.constantRmsLast = r ? *r : 0.0;
        }
        auto res =
            ref ? avoidance::runAvoidanceCut(*def->axis("X"), o) : Result<avoidance::AvoidanceCutResult>(ref.error());
        if (!res) {
            out.aborted = res.error().code == ErrorCode::Aborted;
            out.error = QString::fromStdString(res.error().detail);
            return out;
        }
        out.result = std::make_shared<const avoidance::AvoidanceCutResult>(std::move(res).value());
        done->store(1.0);
        return out;
    }));
}

void MachiningAvoidancePage::finished()
{
    m_poll->stop();
    m_running = false;
    m_run->setEnabled(true);
    m_abort->setEnabled(false);
    m_run_ = m_watcher->result();
    m_progress->setValue(m_run_.result ? 100 : m_progress->value());
    emit completeChanged();
    m_trace->clear();
    m_spectrum->clear();
    if (!m_run_.result) {
        m_summary->setText(m_run_.aborted ? tr("Aborted: %1").arg(m_run_.error) : tr("Error: %1").arg(m_run_.error));
        showLobes();
        return;
    }
    const auto& r = *m_run_.result;
    const auto& c = r.capture;
    const auto t = channelOf(c, "t_s");
    m_trace->addSeries(tr("tool acceleration y"), t, channelOf(c, "tool_accel_y_m_s2"), QStringLiteral("m/s²"),
                       QColor(120, 60, 0));
    m_trace->addSeries(tr("spindle speed"), t, channelOf(c, "spindle_speed_rpm"), tr("min⁻¹"), QColor(0, 90, 180));
    m_trace->addSeries(tr("spindle speed command"), t, channelOf(c, "spindle_speed_cmd_rpm"), tr("min⁻¹"),
                       QColor(150, 150, 150), Qt::DashLine);
    if (c.channel("chatter_frequency_Hz") && r.capture.metadata.text(model::meta::kAvoid) != "esc")
        m_trace->addSeries(tr("estimated chatter frequency"), t, channelOf(c, "chatter_frequency_Hz"), tr("Hz"),
                           QColor(200, 0, 0));
    if (c.channel("avoid_power")) {
        const bool esc = r.capture.metadata.text(model::meta::kAvoid) == "esc";
        m_trace->addSeries(esc ? tr("cost (signal squared)") : tr("self-excited power"), t, channelOf(c, "avoid_power"),
                           QString::fromStdString(c.metadata.textOr(model::meta::kAvoidPowerUnit, "")),
                           QColor(0, 140, 60));
    }
    m_trace->rescale();
    m_trace->replotNow();
    const double end = m_durationRun;
    const double onset = r.triggerTimeS >= 0.0 ? r.triggerTimeS : 0.1;
    addSpectrum(m_spectrum, c, 0.1, std::min(end, std::max(onset, 0.1) + 0.1), tr("start of the cut"),
                QColor(200, 0, 0));
    addSpectrum(m_spectrum, c, std::max(0.1, end - 0.3), end, tr("last 0.3 s"), QColor(0, 90, 180));
    m_spectrum->rescale();
    m_spectrum->replotNow();
    m_slider->setValue(1000);
    showLobes();
    const auto rms = avoidance::channelRms(c, "tool_accel_y_m_s2", std::max(0.1, end - 0.3), end);
    const auto n = channelOf(c, "spindle_speed_rpm");
    QString text = tr("Final spindle speed %1 min⁻¹.").arg(fmt(n.empty() ? 0.0 : n.back(), 0));
    if (rms && m_run_.constantRmsLast > 0.0)
        text += QLatin1Char(' ') + tr("Acceleration RMS over the last 0.3 s: %1 m/s² (constant speed %2 m/s², %3 % "
                                      "lower).")
                                       .arg(fmt(*rms, 0), fmt(m_run_.constantRmsLast, 0),
                                            fmt(100.0 * (1.0 - *rms / m_run_.constantRmsLast), 0));
    if (r.triggerTimeS >= 0.0)
        text += QLatin1Char(' ') +
                tr("Triggered at %1 s; %n adaptation step(s).", nullptr, static_cast<int>(r.steps.size()))
                    .arg(fmt(r.triggerTimeS, 3));
    else if (c.metadata.text(model::meta::kAvoid) == "adaptive" || c.metadata.text(model::meta::kAvoid) == "multimode")
        text += QLatin1Char(' ') + tr("Never triggered: the filtered signal squared stayed below σ_th (set a lower "
                                      "trigger σ_th for this cut).");
    if (c.metadata.text(model::meta::kAvoid) == "esc")
        text += QLatin1Char(' ') + tr("ESC: dither %1 Hz, h_c %2 Hz, k_c %3 1/s; %4 samples held at a bound.")
                                       .arg(fmt(r.escDesign.omegaPRadS / (2.0 * M_PI), 2),
                                            fmt(r.escDesign.hcRadS / (2.0 * M_PI), 3), fmt(r.escDesign.kcPerS, 1))
                                       .arg(static_cast<qulonglong>(r.escBoundHits));
    m_summary->setText(text);
}

void MachiningAvoidancePage::showLobes()
{
    m_lobes->clear();
    const auto& lr = m_lobesPage.result();
    std::vector<double> x, y;
    for (const auto& p : lr.lobes)
        if (std::isfinite(p.limitDepthM)) {
            x.push_back(p.rpm);
            y.push_back(p.limitDepthM * 1e3);
        }
    if (!x.empty())
        m_lobes->addCurve(tr("limit depth"), x, y, QColor(0, 90, 180));
    auto in = m_cutPage.inputs();
    const double depthMm = in ? in->depthM * 1e3 : 0.0;
    if (m_run_.result) {
        const auto& c = m_run_.result->capture;
        const auto t = channelOf(c, "t_s");
        const auto n = channelOf(c, "spindle_speed_rpm");
        if (!n.empty()) {
            m_lobes->addCurve(tr("operating point path"), n, std::vector<double>(n.size(), depthMm), QColor(200, 0, 0));
            const auto i = std::min(
                n.size() - 1, static_cast<std::size_t>(m_slider->value() / 1000.0 * static_cast<double>(n.size() - 1)));
            m_lobes->addPoint(n[i], depthMm, tr("%1 s").arg(fmt(t[i], 2)));
        }
    } else if (in) {
        m_lobes->addPoint(in->rpm, depthMm, tr("now"));
    }
    m_lobes->rescale();
    m_lobes->replotNow();
}

} // namespace gui
} // namespace axistune

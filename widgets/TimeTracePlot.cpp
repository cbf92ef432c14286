// SPDX-License-Identifier: GPL-3.0-or-later
// Time traces on QCustomPlot. Speed with 1,000,000 points per channel comes from QCPGraph's adaptive
// sampling (each pixel column draws min/max of its samples) over data handed over already sorted;
// each channel is copied once into a QVector<QCPGraphData> that the graph shares (implicit sharing),
// and cursors and the CSV export read that same vector (or the capture itself).
#include "widgets/TimeTracePlot.h"

#include "core/io/AtomicFile.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Units.h"
#include "widgets/PlotCommon.h"
#include "widgets/PlotExport.h"

#include <QLabel>
#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string>

namespace axistune {
namespace widgets {

namespace {

constexpr int kEnvelopeMinSamples = 100000;     ///< traces this long get a min/max envelope (chooseEnvelopes)
constexpr int kEnvelopeBlocks = 16384;          ///< blocks of the envelope (two points each)
constexpr double kEnvelopeBlocksPerPixel = 4.0; ///< the envelope is drawn while a pixel column spans this many

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool isTimeChannel(const std::string& name)
{
    return name == "t_s" || name == "time_s";
}

// The unit label of a unit token or label; the text itself when unknown.
QString unitLabelOf(const QString& unit)
{
    if (unit.isEmpty())
        return unit;
    const std::string token = unit.toStdString();
    if (model::findUnit(token).ok())
        return QString::fromStdString(model::unitLabel(token));
    QString slashed = unit;
    slashed.replace(QLatin1Char('_'), QLatin1Char('/'));
    if (model::findUnit(slashed.toStdString()).ok())
        return QString::fromStdString(model::unitLabel(slashed.toStdString()));
    if (slashed.endsWith(QLatin1String("/s2"))) // accelerations, not in the unit table
        return slashed.chopped(1) + QStringLiteral("²");
    return unit;
}

void appendNumber(std::string& out, double v)
{
    char buf[32];
    const auto res = std::to_chars(buf, buf + sizeof(buf), v);
    out.append(buf, res.ptr);
}

// Linear interpolation in a sorted graph data vector; exact at a sample time.
double interpolate(const QVector<QCPGraphData>& data, double t)
{
    if (data.isEmpty() || !std::isfinite(t))
        return kNaN;
    auto it =
        std::lower_bound(data.begin(), data.end(), t, [](const QCPGraphData& d, double key) { return d.key < key; });
    if (it == data.end())
        return kNaN;
    if (it->key == t)
        return it->value;
    if (it == data.begin())
        return kNaN;
    const auto prev = it - 1;
    const double u = (t - prev->key) / (it->key - prev->key);
    return prev->value + u * (it->value - prev->value);
}

QString formatValue(double v)
{
    return std::isfinite(v) ? QString::number(v, 'g', 6) : QStringLiteral("–");
}

} // namespace

namespace {

// Number of trailing '_'-separated parts of a channel name that form its unit token (0: none), and
// the unit label.
std::pair<int, QString> unitSuffix(const QString& channelName)
{
    const QStringList parts = channelName.split(QLatin1Char('_'));
    for (int k = std::min<int>(3, static_cast<int>(parts.size()) - 1); k >= 1; --k) {
        const QString token = parts.mid(parts.size() - k).join(QLatin1Char('/'));
        if (token == QLatin1String("1"))
            continue;
        if (model::findUnit(token.toStdString()).ok())
            return {k, QString::fromStdString(model::unitLabel(token.toStdString()))};
        if (token.endsWith(QLatin1String("/s2")) && model::findUnit(token.chopped(1).toStdString()).ok())
            return {k, QString::fromStdString(model::unitLabel(token.chopped(1).toStdString())) + QStringLiteral("²")};
    }
    return {0, QString()};
}

// "motor_vel_rad_s" -> "motor_vel".
QString channelBaseName(const QString& channelName)
{
    const int k = unitSuffix(channelName).first;
    if (k == 0)
        return channelName;
    const QStringList parts = channelName.split(QLatin1Char('_'));
    return parts.mid(0, parts.size() - k).join(QLatin1Char('_'));
}

} // namespace

QString channelUnitLabel(const QString& channelName)
{
    return unitSuffix(channelName).second;
}

QString TimeTracePlot::quantityOf(const QString& unit)
{
    if (unit == QLatin1String("rad/s") || unit == QLatin1String("m/s") || unit == QStringLiteral("min⁻¹"))
        return tr("Velocity");
    if (unit.endsWith(QStringLiteral("²")))
        return tr("Acceleration");
    if (unit == QStringLiteral("N·m"))
        return tr("Torque");
    if (unit == QLatin1String("N"))
        return tr("Force");
    if (unit == QLatin1String("A"))
        return tr("Current");
    if (unit == QLatin1String("V"))
        return tr("Voltage");
    if (unit == QLatin1String("m") || unit == QLatin1String("mm") || unit == QStringLiteral("µm"))
        return tr("Position");
    if (unit == QLatin1String("rad") || unit == QLatin1String("deg"))
        return tr("Angle");
    return tr("Value");
}

struct TimeTracePlot::Trace {
    QString name;
    QString unit; // label, e.g. "rad/s"
    bool fromCapture = false;
    QColor color;
    Qt::PenStyle style = Qt::SolidLine;
    QVector<QCPGraphData> data; // the one copy, shared with the graph
    QCPGraph* graph = nullptr;
    // Long traces (a scope's roll history): the samples' minimum and maximum per block of `block` samples, in time
    // order, drawn instead of the samples while every pixel column spans at least kEnvelopeBlocksPerPixel blocks.
    QSharedPointer<QCPGraphDataContainer> full, envelope;
    int block = 0;
    bool showingEnvelope = false;
};

struct TimeTracePlot::Strip {
    QString unit;
    QCPAxisRect* rect = nullptr;
    QStringList names;
    QCPItemStraightLine* cursor[2] = {nullptr, nullptr};
    QCPItemText* cursorLabel[2] = {nullptr, nullptr}; // "1", "2" at the top of the first strip
};

TimeTracePlot::TimeTracePlot(QWidget* parent)
    : QWidget(parent), m_plot(new QCustomPlot(this)), m_readout(new QLabel(this)), m_cursorT{kNaN, kNaN}
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(m_plot, 1);
    layout->addWidget(m_readout);
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_readout->setVisible(false);
    detail::applyBaseStyle(*m_plot);
    detail::placeLegendBelow(*m_plot, 4);
    // The strips are created per unit; the default axis rect is not used.
    m_plot->plotLayout()->remove(m_plot->axisRect());
    m_plot->plotLayout()->simplify();
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    connect(m_plot, &QCustomPlot::mousePress, this, &TimeTracePlot::onPlotMousePress);
    connect(m_plot, &QCustomPlot::mouseMove, this, &TimeTracePlot::onPlotMouseMove);
    connect(m_plot, &QCustomPlot::mouseRelease, this, &TimeTracePlot::onPlotMouseRelease);
    connect(m_plot, &QCustomPlot::mouseDoubleClick, this, [this](QMouseEvent* event) {
        if (event->button() == Qt::LeftButton)
            rescale();
    });
    connect(m_plot, &QCustomPlot::beforeReplot, this, &TimeTracePlot::chooseEnvelopes);
    rebuild();
}

// A graph's adaptive sampling draws, per pixel column, the minimum and maximum of the samples in it: it reads every
// visible sample on every redraw (8 × 10⁶ of a full scope history took 30 ms). The minimum and maximum per block of
// samples, taken once, give every pixel column the same extremes while a column spans whole blocks; a block across
// a column's edge puts its extreme into one of the two neighbours (one pixel). So the envelope is drawn while a
// column spans at least kEnvelopeBlocksPerPixel blocks, the samples themselves below that (zoomed in).
void TimeTracePlot::chooseEnvelopes()
{
    for (auto& t : m_traces) {
        if (!t.graph || !t.envelope)
            continue;
        const QCPAxis* x = t.graph->keyAxis();
        const double widthPx = std::max(1, x->axisRect()->width());
        const auto lo = std::lower_bound(t.data.cbegin(), t.data.cend(), x->range().lower,
                                         [](const QCPGraphData& d, double k) { return d.key < k; });
        const auto hi = std::upper_bound(lo, t.data.cend(), x->range().upper,
                                         [](double k, const QCPGraphData& d) { return k < d.key; });
        const double blocksPerPixel = static_cast<double>(hi - lo) / t.block / widthPx;
        const bool envelope = blocksPerPixel >= kEnvelopeBlocksPerPixel;
        if (envelope != t.showingEnvelope) {
            t.graph->setData(envelope ? t.envelope : t.full);
            t.showingEnvelope = envelope;
        }
    }
}

bool TimeTracePlot::showsEnvelope(const QString& name) const
{
    for (const auto& t : m_traces)
        if (t.name == name)
            return t.showingEnvelope;
    return false;
}

TimeTracePlot::~TimeTracePlot() = default;

void TimeTracePlot::setCapture(std::shared_ptr<const model::Capture> capture, const QStringList& channels)
{
    m_traces.erase(std::remove_if(m_traces.begin(), m_traces.end(), [](const Trace& t) { return t.fromCapture; }),
                   m_traces.end());
    m_capture = std::move(capture);
    std::vector<Trace> fresh;
    if (m_capture && m_capture->size() > 0) {
        const std::size_t n = m_capture->size();
        const model::Channel* time = nullptr;
        for (const auto& c : m_capture->channels) {
            if (isTimeChannel(c.name) && c.data.size() == n)
                time = &c;
        }
        double fs = 1.0;
        if (const auto* stated = m_capture->metadata.find(model::meta::kFsHz)) {
            if (const auto v = stated->number(); v && *v > 0 && std::isfinite(*v))
                fs = *v;
        }
        int colour = 0;
        for (const auto& c : m_capture->channels) {
            const QString name = QString::fromStdString(c.name);
            const bool wanted = channels.isEmpty() ? !isTimeChannel(c.name) : channels.contains(name);
            if (!wanted || c.data.size() != n)
                continue;
            Trace t;
            t.name = name;
            // The unit the capture states (metadata unit.CHANNEL, as the drive's scope gives it), else the
            // one of the name's suffix.
            const auto stated = m_capture->metadata.text("unit." + c.name);
            t.unit = stated && !stated->empty() ? unitLabelOf(QString::fromStdString(*stated)) : channelUnitLabel(name);
            t.fromCapture = true;
            t.color = detail::paletteColor(colour++);
            t.data.resize(static_cast<int>(n));
            QCPGraphData* out = t.data.data();
            for (std::size_t i = 0; i < n; ++i) {
                out[i].key = time ? time->data[i] : static_cast<double>(i) / fs;
                out[i].value = c.data[i];
            }
            fresh.push_back(std::move(t));
        }
    }
    // Capture channels first, overlays after them.
    m_traces.insert(m_traces.begin(), std::make_move_iterator(fresh.begin()), std::make_move_iterator(fresh.end()));
    rebuild();
    rescale();
}

void TimeTracePlot::addSeries(const QString& name, const std::vector<double>& t, const std::vector<double>& y,
                              const QString& unit, const QColor& color, Qt::PenStyle style)
{
    Trace tr;
    tr.name = name;
    tr.unit = unitLabelOf(unit);
    tr.color = color.isValid() ? color : detail::paletteColor(static_cast<int>(m_traces.size()));
    tr.style = style;
    const std::size_t n = std::min(t.size(), y.size());
    tr.data.resize(static_cast<int>(n));
    for (std::size_t i = 0; i < n; ++i)
        tr.data[static_cast<int>(i)] = QCPGraphData(t[i], y[i]);
    if (!std::is_sorted(tr.data.begin(), tr.data.end(), qcpLessThanSortKey<QCPGraphData>))
        std::stable_sort(tr.data.begin(), tr.data.end(), qcpLessThanSortKey<QCPGraphData>);
    const bool first = m_traces.empty();
    m_traces.push_back(std::move(tr));
    rebuild();
    if (first)
        rescale();
}

void TimeTracePlot::clear()
{
    m_capture.reset();
    m_traces.clear();
    m_cursorsShown = false;
    rebuild();
}

TimeTracePlot::Strip& TimeTracePlot::stripFor(const QString& unit)
{
    for (auto& s : m_strips) {
        if (s.unit == unit)
            return s;
    }
    Strip s;
    s.unit = unit;
    s.rect = new QCPAxisRect(m_plot);
    const int row = static_cast<int>(m_strips.size());
    m_plot->plotLayout()->insertRow(row);
    m_plot->plotLayout()->addElement(row, 0, s.rect);
    m_plot->plotLayout()->setRowStretchFactor(row, 1.0);
    s.rect->axis(QCPAxis::atLeft)->grid()->setSubGridVisible(false);
    m_strips.push_back(s);
    return m_strips.back();
}

void TimeTracePlot::rebuild()
{
    // The strips are made anew; the value ranges the user has stay for the units that remain.
    std::vector<std::pair<QString, QCPRange>> oldRanges;
    for (auto& s : m_strips)
        oldRanges.emplace_back(s.unit, s.rect->axis(QCPAxis::atLeft)->range());
    const bool hadTraces = m_plot->graphCount() > 0;
    const auto [t0, t1] = visibleRange();
    m_plot->clearGraphs();
    m_plot->clearItems();
    for (auto& s : m_strips)
        m_plot->plotLayout()->remove(s.rect);
    m_plot->plotLayout()->simplify();
    m_strips.clear();
    for (auto& t : m_traces) {
        Strip& s = stripFor(t.unit);
        s.names << t.name;
        addTraceGraph(t, s);
    }
    if (m_strips.empty()) // an empty plot still shows its time axis
        stripFor(QString());
    delete m_margins; // the removed strips left it
    m_margins = new QCPMarginGroup(m_plot);
    for (std::size_t i = 0; i < m_strips.size(); ++i) {
        Strip& s = m_strips[i];
        const bool bottom = i + 1 == m_strips.size();
        QCPAxis* x = s.rect->axis(QCPAxis::atBottom);
        x->setTickLabels(bottom);
        x->setLabel(bottom ? detail::axisTitle(tr("Time"), tr("s")) : QString());
        // One channel: its name; several: the quantity of their unit (the legend names them).
        QString title = s.names.size() == 1 ? channelBaseName(s.names.front()) : quantityOf(s.unit);
        if (title.size() > 28)
            title = title.left(27) + QStringLiteral("…");
        s.rect->axis(QCPAxis::atLeft)->setLabel(detail::axisTitle(title, s.unit));
        s.rect->setMarginGroup(QCP::msLeft | QCP::msRight, m_margins);
        s.rect->setRangeDrag(m_zoomY ? Qt::Horizontal | Qt::Vertical : Qt::Horizontal);
        s.rect->setRangeZoom(m_zoomY ? Qt::Horizontal | Qt::Vertical : Qt::Horizontal);
        connect(x, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this,
                [this](const QCPRange& r) { syncTimeAxes(r.lower, r.upper); });
        for (int c = 0; c < 2; ++c) {
            auto* line = new QCPItemStraightLine(m_plot);
            line->setClipAxisRect(s.rect);
            for (QCPItemPosition* p : {line->point1, line->point2}) {
                p->setAxes(x, s.rect->axis(QCPAxis::atLeft));
                p->setAxisRect(s.rect);
                p->setTypeX(QCPItemPosition::ptPlotCoords);
                p->setTypeY(QCPItemPosition::ptAxisRectRatio);
            }
            line->setPen(QPen(QColor(40, 40, 40), 1.0, c == 0 ? Qt::SolidLine : Qt::DashLine));
            line->setSelectable(false);
            s.cursor[c] = line;
            if (i == 0) {
                auto* label = new QCPItemText(m_plot);
                label->setClipAxisRect(s.rect);
                label->position->setAxes(x, s.rect->axis(QCPAxis::atLeft));
                label->position->setAxisRect(s.rect);
                label->position->setTypeX(QCPItemPosition::ptPlotCoords);
                label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
                label->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
                label->setText(QString::number(c + 1));
                label->setPadding(QMargins(3, 1, 3, 1));
                label->setBrush(QColor(255, 255, 255, 210));
                s.cursorLabel[c] = label;
            }
        }
    }
    if (hadTraces) {
        syncTimeAxes(t0, t1);
        for (auto& s : m_strips) {
            auto old =
                std::find_if(oldRanges.begin(), oldRanges.end(), [&](const auto& o) { return o.first == s.unit; });
            if (old != oldRanges.end())
                s.rect->axis(QCPAxis::atLeft)->setRange(old->second);
            else
                rescaleValues(s);
        }
    }
    detail::updateLegendVisibility(*m_plot);
    updateCursorItems();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void TimeTracePlot::addTraceGraph(Trace& t, Strip& s)
{
    QCPGraph* g = m_plot->addGraph(s.rect->axis(QCPAxis::atBottom), s.rect->axis(QCPAxis::atLeft));
    g->setName(t.unit.isEmpty() ? t.name : QStringLiteral("%1 [%2]").arg(t.name, t.unit));
    // A 1-pixel pen without antialiasing: a wide or antialiased pen makes Qt stroke the zig-zag line
    // of adaptive sampling as one self-overlapping outline, twenty times slower for dense signals. Dense
    // already from a few points per pixel: 8000 samples of a zig-zag drawn antialiased took 340 ms
    // (bench_gui_scope, the scope's 2 s roll window at 4 kHz), without antialiasing under 10 ms.
    const bool dense = t.data.size() > 2000;
    g->setPen(QPen(t.color, dense ? 1.0 : 1.3, t.style));
    g->setAntialiased(!dense);
    g->setAdaptiveSampling(true);
    g->data()->set(t.data, true); // shares t.data: no copy
    t.graph = g;
    t.full = g->data();
    t.envelope.reset();
    t.showingEnvelope = false;
    if (t.data.size() >= kEnvelopeMinSamples) {
        t.block = std::max(16, static_cast<int>(t.data.size() / kEnvelopeBlocks));
        QVector<QCPGraphData> env;
        env.reserve(2 * (t.data.size() / t.block + 1));
        for (int b = 0; b < t.data.size(); b += t.block) {
            const int e = std::min<int>(t.data.size(), b + t.block);
            int iMin = b, iMax = b;
            for (int i = b + 1; i < e; ++i) {
                if (t.data[i].value < t.data[iMin].value)
                    iMin = i;
                if (t.data[i].value > t.data[iMax].value)
                    iMax = i;
            }
            env << t.data[std::min(iMin, iMax)];
            if (iMax != iMin)
                env << t.data[std::max(iMin, iMax)];
        }
        t.envelope = QSharedPointer<QCPGraphDataContainer>::create();
        t.envelope->set(env, true);
    }
}

void TimeTracePlot::syncTimeAxes(double lower, double upper)
{
    if (m_syncing)
        return;
    m_syncing = true;
    for (auto& s : m_strips)
        s.rect->axis(QCPAxis::atBottom)->setRange(lower, upper);
    m_syncing = false;
}

QStringList TimeTracePlot::seriesNames() const
{
    QStringList names;
    for (const auto& t : m_traces)
        names << t.name;
    return names;
}

int TimeTracePlot::stripCount() const
{
    return m_traces.empty() ? 0 : static_cast<int>(m_strips.size());
}

void TimeTracePlot::setVisibleRange(double t0, double t1)
{
    if (!(t1 > t0) || !std::isfinite(t0) || !std::isfinite(t1) || m_strips.empty())
        return;
    syncTimeAxes(t0, t1);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

std::pair<double, double> TimeTracePlot::visibleRange() const
{
    if (m_strips.empty())
        return {0.0, 1.0};
    const QCPRange r = m_strips.front().rect->axis(QCPAxis::atBottom)->range();
    return {r.lower, r.upper};
}

void TimeTracePlot::rescale()
{
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const auto& t : m_traces) {
        if (!t.data.isEmpty()) {
            lo = std::min(lo, t.data.front().key);
            hi = std::max(hi, t.data.back().key);
        }
    }
    if (!(hi > lo)) {
        lo = 0.0;
        hi = 1.0;
    }
    syncTimeAxes(lo, hi);
    for (auto& s : m_strips)
        rescaleValues(s);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void TimeTracePlot::rescaleValues(Strip& s)
{
    bool first = true;
    for (const auto& t : m_traces) {
        if (t.graph && t.graph->valueAxis() == s.rect->axis(QCPAxis::atLeft)) {
            t.graph->rescaleValueAxis(!first, false);
            first = false;
        }
    }
    if (first)
        return;
    QCPAxis* y = s.rect->axis(QCPAxis::atLeft);
    const double span = y->range().size();
    const double pad = span > 0 ? 0.05 * span : 0.05 * std::abs(y->range().center()) + 1e-9;
    y->setRange(y->range().lower - pad, y->range().upper + pad);
}

void TimeTracePlot::setZoomY(bool enabled)
{
    m_zoomY = enabled;
    for (auto& s : m_strips) {
        s.rect->setRangeDrag(enabled ? Qt::Horizontal | Qt::Vertical : Qt::Horizontal);
        s.rect->setRangeZoom(enabled ? Qt::Horizontal | Qt::Vertical : Qt::Horizontal);
    }
}

void TimeTracePlot::setCursors(double t1, double t2)
{
    m_cursorT[0] = t1;
    m_cursorT[1] = t2;
    m_cursorsShown = std::isfinite(t1) && std::isfinite(t2);
    updateCursorItems();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void TimeTracePlot::hideCursors()
{
    m_cursorsShown = false;
    updateCursorItems();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void TimeTracePlot::updateCursorItems()
{
    for (auto& s : m_strips) {
        for (int c = 0; c < 2; ++c) {
            s.cursor[c]->setVisible(m_cursorsShown);
            if (s.cursorLabel[c])
                s.cursorLabel[c]->setVisible(m_cursorsShown);
            if (m_cursorsShown) {
                s.cursor[c]->point1->setCoords(m_cursorT[c], 0.0);
                s.cursor[c]->point2->setCoords(m_cursorT[c], 1.0);
                if (s.cursorLabel[c])
                    s.cursorLabel[c]->position->setCoords(m_cursorT[c], 0.0);
            }
        }
    }
    updateReadout();
}

double TimeTracePlot::cursorValue(int cursor, const QString& name) const
{
    if (cursor < 0 || cursor > 1 || !m_cursorsShown)
        return kNaN;
    for (const auto& t : m_traces) {
        if (t.name == name)
            return interpolate(t.data, m_cursorT[cursor]);
    }
    return kNaN;
}

QString TimeTracePlot::cursorReadout() const
{
    if (!m_cursorsShown)
        return {};
    const double dt = m_cursorT[1] - m_cursorT[0];
    QStringList lines;
    QString head = tr("t1 = %1 s   t2 = %2 s   Δt = %3 s")
                       .arg(formatValue(m_cursorT[0]), formatValue(m_cursorT[1]), formatValue(dt));
    if (dt != 0.0)
        head += tr("   1/Δt = %1 Hz").arg(formatValue(1.0 / std::abs(dt)));
    lines << head;
    for (const auto& t : m_traces) {
        const double v1 = interpolate(t.data, m_cursorT[0]);
        const double v2 = interpolate(t.data, m_cursorT[1]);
        const QString unit = t.unit.isEmpty() ? QString() : QStringLiteral(" ") + t.unit;
        lines
            << tr("%1: %2%5 | %3%5 | Δ %4%5").arg(t.name, formatValue(v1), formatValue(v2), formatValue(v2 - v1), unit);
    }
    return lines.join(QLatin1Char('\n'));
}

void TimeTracePlot::updateReadout()
{
    const QString text = cursorReadout();
    m_readout->setText(text);
    m_readout->setVisible(!text.isEmpty());
}

void TimeTracePlot::onPlotMousePress(QMouseEvent* event)
{
    QCPAxisRect* rect = m_plot->axisRectAt(event->position());
    if (!rect)
        return;
    QCPAxis* time = rect->axis(QCPAxis::atBottom);
    if (event->button() == Qt::LeftButton && m_cursorsShown) {
        // Grab a cursor within 6 px: drag it instead of panning.
        constexpr double kGrabPx = 6.0;
        for (int c = 0; c < 2; ++c) {
            if (std::abs(time->coordToPixel(m_cursorT[c]) - event->position().x()) <= kGrabPx) {
                m_dragCursor = c;
                m_plot->setInteraction(QCP::iRangeDrag, false);
                return;
            }
        }
    }
    if (event->button() != Qt::RightButton)
        return;
    const double t = time->pixelToCoord(event->position().x());
    if (!m_cursorsShown) {
        const auto [lo, hi] = visibleRange();
        setCursors(t, std::min(hi, t + 0.1 * (hi - lo)));
        return;
    }
    // Moves the nearer cursor.
    if (std::abs(t - m_cursorT[0]) <= std::abs(t - m_cursorT[1]))
        setCursors(t, m_cursorT[1]);
    else
        setCursors(m_cursorT[0], t);
}

void TimeTracePlot::onPlotMouseMove(QMouseEvent* event)
{
    if (m_dragCursor < 0 || !(event->buttons() & Qt::LeftButton) || m_strips.empty())
        return;
    QCPAxisRect* rect = m_plot->axisRectAt(event->position());
    QCPAxis* time = rect ? rect->axis(QCPAxis::atBottom) : m_plot->axisRect(0)->axis(QCPAxis::atBottom);
    const double t = time->pixelToCoord(event->position().x());
    if (m_dragCursor == 0)
        setCursors(t, m_cursorT[1]);
    else
        setCursors(m_cursorT[0], t);
}

void TimeTracePlot::onPlotMouseRelease(QMouseEvent*)
{
    if (m_dragCursor < 0)
        return;
    m_dragCursor = -1;
    m_plot->setInteraction(QCP::iRangeDrag, true);
}

bool TimeTracePlot::exportVisibleCsv(const QString& path) const
{
    std::vector<const Trace*> columns;
    for (const auto& t : m_traces) {
        if (t.fromCapture)
            columns.push_back(&t);
    }
    if (columns.empty()) {
        for (const auto& t : m_traces)
            columns.push_back(&t);
        for (const Trace* t : columns) {
            const bool sameBase =
                t->data.size() == columns.front()->data.size() &&
                std::equal(t->data.begin(), t->data.end(), columns.front()->data.begin(),
                           [](const QCPGraphData& a, const QCPGraphData& b) { return a.key == b.key; });
            if (!sameBase) {
                m_lastError = tr("%1: the series have different time bases; export them one by one").arg(path);
                return false;
            }
        }
    }
    if (columns.empty()) {
        m_lastError = tr("%1: nothing to export: the plot is empty").arg(path);
        return false;
    }
    const auto [t0, t1] = visibleRange();
    const QVector<QCPGraphData>& base = columns.front()->data;
    const auto lessKey = [](const QCPGraphData& d, double key) { return d.key < key; };
    const auto begin = std::lower_bound(base.begin(), base.end(), t0, lessKey) - base.begin();
    const auto end =
        std::upper_bound(base.begin(), base.end(), t1, [](double key, const QCPGraphData& d) { return key < d.key; }) -
        base.begin();
    std::string text = "time_s";
    for (const Trace* c : columns) {
        text += ',';
        text += c->name.toStdString();
    }
    text += '\n';
    text.reserve(text.size() +
                 static_cast<std::size_t>(std::max<qsizetype>(0, end - begin)) * 24 * (columns.size() + 1));
    for (auto i = begin; i < end; ++i) {
        appendNumber(text, base[i].key);
        for (const Trace* c : columns) {
            text += ',';
            appendNumber(text, c->data[i].value);
        }
        text += '\n';
    }
    if (auto st = io::writeFileAtomic(path.toStdString(), text); !st) {
        m_lastError = tr("%1: cannot write the file (%2)").arg(path, QString::fromStdString(st.error().detail));
        return false;
    }
    return true;
}

bool TimeTracePlot::exportImage(const QString& path, int width, int height)
{
    return exportPlotImage(*m_plot, path, width, height, &m_lastError);
}

void TimeTracePlot::replotNow()
{
    m_plot->replot(QCustomPlot::rpImmediateRefresh);
}

} // namespace widgets
} // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
// Bode plot on QCustomPlot: three stacked axis rects (magnitude, phase, coherence) whose logarithmic
// frequency axes follow each other; bands are QCPItemRects spanning the full height of each rect
// (x in Hz, y as a fraction of the rect); markers are QCPItemStraightLines with a QCPItemText.
#include "widgets/BodePlot.h"

#include "widgets/PlotCommon.h"
#include "widgets/PlotExport.h"

#include <QVBoxLayout>

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace axistune {
namespace widgets {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

QColor bandColor(BodePlot::BandKind kind)
{
    return kind == BodePlot::BandKind::MultiSweepOnly ? QColor(255, 176, 0, 55) : QColor(110, 110, 110, 70);
}

QColor markerColor(BodePlot::MarkerKind kind)
{
    switch (kind) {
    case BodePlot::MarkerKind::Resonance:
        return QColor(190, 0, 0);
    case BodePlot::MarkerKind::Notch:
        return QColor(0, 80, 190);
    case BodePlot::MarkerKind::AntiResonance:
        return QColor(0, 130, 60);
    case BodePlot::MarkerKind::Other:
        break;
    }
    return QColor(90, 90, 90);
}

// Value of a graph at key (linear in log key between its neighbours); NaN at gaps and outside.
double interpolateLogKey(const QCPGraph* graph, double key)
{
    if (!graph || !(key > 0))
        return kNaN;
    const auto data = graph->data();
    if (data->isEmpty())
        return kNaN;
    auto it = data->findBegin(key, false);  // first point with key >= key
    if (it == data->constEnd())
        return kNaN;
    if (it->key == key)
        return it->value;
    if (it == data->constBegin())
        return kNaN;
    const auto prev = it - 1;
    const double u = (std::log(key) - std::log(prev->key)) / (std::log(it->key) - std::log(prev->key));
    return prev->value + u * (it->value - prev->value);
}

// Builds graph data; points with keep[i] false become NaN (a gap). With breakJumps, a jump of more
// than 180 between consecutive values (a wrapped phase) gets a NaN point between them so no vertical
// stroke connects +180 and -180.
QVector<QCPGraphData> toGraphData(const std::vector<double>& f, const std::vector<double>& v,
                                  const std::vector<bool>* keep, bool breakJumps)
{
    QVector<QCPGraphData> out;
    out.reserve(static_cast<int>(f.size() + f.size() / 8));
    double lastF = kNaN;
    double lastV = kNaN;
    for (std::size_t i = 0; i < f.size(); ++i) {
        if (!(f[i] > 0) || !std::isfinite(f[i]))
            continue;  // a logarithmic axis cannot show f <= 0
        const double value = (keep && !(*keep)[i]) ? kNaN : v[i];
        if (breakJumps && std::isfinite(value) && std::isfinite(lastV) && std::abs(value - lastV) > 180.0)
            out.push_back(QCPGraphData(std::sqrt(lastF * f[i]), kNaN));
        out.push_back(QCPGraphData(f[i], std::isfinite(value) ? value : kNaN));
        lastF = f[i];
        lastV = value;
    }
    return out;
}

std::pair<double, double> finiteRange(const std::vector<double>& v)
{
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (double x : v) {
        if (std::isfinite(x)) {
            lo = std::min(lo, x);
            hi = std::max(hi, x);
        }
    }
    return {lo, hi};
}

}  // namespace

struct BodePlot::Response {
    int id = 0;
    QString name;
    QColor color;
    Qt::PenStyle style = Qt::SolidLine;
    std::vector<double> f, magDb, phaseWrapped, phaseUnwrapped, coherence;
    std::vector<bool> valid;
    bool anyInvalid = false;
    bool anyCoherence = false;
    QCPGraph* mag = nullptr;
    QCPGraph* phase = nullptr;
    QCPGraph* magFaint = nullptr;
    QCPGraph* phaseFaint = nullptr;
    QCPGraph* coh = nullptr;
};

struct BodePlot::Band {
    double fromHz = 0;
    double toHz = 0;
    BandKind kind = BandKind::MultiSweepOnly;
    std::vector<QCPItemRect*> rects;  // magnitude, phase, coherence
};

struct BodePlot::Marker {
    double fHz = 0;
    MarkerKind kind = MarkerKind::Other;
    QString label;
    std::vector<QCPAbstractItem*> items;
};

BodePlot::BodePlot(QWidget* parent) : QWidget(parent), m_plot(new QCustomPlot(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    setupAxes();
    rescale();
}

BodePlot::~BodePlot() = default;

void BodePlot::setupAxes()
{
    detail::applyBaseStyle(*m_plot);
    m_magRect = m_plot->axisRect();
    m_phaseRect = new QCPAxisRect(m_plot);
    m_cohRect = new QCPAxisRect(m_plot);
    m_plot->plotLayout()->addElement(1, 0, m_phaseRect);
    m_plot->plotLayout()->addElement(2, 0, m_cohRect);
    m_margins = new QCPMarginGroup(m_plot);
    for (QCPAxisRect* r : {m_magRect, m_phaseRect, m_cohRect}) {
        r->setMarginGroup(QCP::msLeft | QCP::msRight, m_margins);
        r->setRangeDrag(Qt::Horizontal);
        r->setRangeZoom(Qt::Horizontal);
        detail::makeLogAxis(*r->axis(QCPAxis::atBottom));
        r->axis(QCPAxis::atLeft)->grid()->setSubGridVisible(false);
        r->axis(QCPAxis::atBottom)->grid()->setSubGridVisible(true);
        // One frequency axis for all three strips.
        connect(r->axis(QCPAxis::atBottom), qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this,
                [this](const QCPRange& range) {
                    for (QCPAxisRect* other : {m_magRect, m_phaseRect, m_cohRect})
                        other->axis(QCPAxis::atBottom)->setRange(range);
                });
    }
    m_magRect->axis(QCPAxis::atLeft)->setLabel(detail::axisTitle(tr("Magnitude"), tr("dB")));
    m_phaseRect->axis(QCPAxis::atLeft)->setLabel(detail::axisTitle(tr("Phase"), tr("deg")));
    m_cohRect->axis(QCPAxis::atLeft)->setLabel(detail::axisTitle(tr("Coherence"), tr("0–1")));
    QSharedPointer<QCPAxisTickerFixed> phaseTicker(new QCPAxisTickerFixed);
    phaseTicker->setTickStep(90.0);
    phaseTicker->setScaleStrategy(QCPAxisTickerFixed::ssMultiples);
    m_phaseRect->axis(QCPAxis::atLeft)->setTicker(phaseTicker);
    m_cohRect->axis(QCPAxis::atLeft)->setRange(0.0, 1.05);
    QSharedPointer<QCPAxisTickerFixed> cohTicker(new QCPAxisTickerFixed);
    cohTicker->setTickStep(0.5);
    m_cohRect->axis(QCPAxis::atLeft)->setTicker(cohTicker);
    m_plot->plotLayout()->setRowStretchFactor(0, 3.0);
    m_plot->plotLayout()->setRowStretchFactor(1, 2.0);
    m_plot->plotLayout()->setRowStretchFactor(2, 0.9);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    connect(m_plot, &QCustomPlot::afterLayout, this, &BodePlot::alignMarkerLabels);
    detail::placeLegendBelow(*m_plot, 4);
    updateCoherenceStrip();
}

int BodePlot::addResponse(const dsp::FrequencyResponse& frf, const QString& name, const QColor& color,
                          Qt::PenStyle style)
{
    Response r;
    r.id = m_nextId++;
    r.name = name;
    r.color = color.isValid() ? color : detail::paletteColor(m_colorIndex);
    ++m_colorIndex;
    r.style = style;
    r.f = frf.freqHz;
    r.magDb = dsp::magnitudeDb(frf);
    r.phaseWrapped = dsp::phaseDeg(frf);
    r.phaseUnwrapped = dsp::unwrappedPhaseDeg(frf);
    r.coherence = frf.coherence;
    r.coherence.resize(r.f.size(), kNaN);
    r.valid = frf.valid;
    r.valid.resize(r.f.size(), true);
    r.anyInvalid = std::find(r.valid.begin(), r.valid.end(), false) != r.valid.end();
    r.anyCoherence = std::any_of(r.coherence.begin(), r.coherence.end(), [](double c) { return std::isfinite(c); });

    auto makeGraph = [&](QCPAxisRect* rect, bool faint) {
        QCPGraph* g = m_plot->addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
        QColor c = r.color;
        if (faint)
            c.setAlpha(70);
        // 1-pixel pens: Qt strokes wider antialiased lines as outlines, five times slower here.
        g->setPen(QPen(c, 1.0, faint ? Qt::SolidLine : r.style));
        // Adaptive sampling would merge the NaN gaps (invalid points, phase wraps) into neighbouring
        // pixel columns; a few thousand points per response draw fast enough without it.
        g->setAdaptiveSampling(false);
        g->removeFromLegend();
        return g;
    };
    r.magFaint = makeGraph(m_magRect, true);
    r.phaseFaint = makeGraph(m_phaseRect, true);
    r.mag = makeGraph(m_magRect, false);
    r.phase = makeGraph(m_phaseRect, false);
    r.coh = makeGraph(m_cohRect, false);
    r.mag->setName(name);
    r.mag->addToLegend();
    rebuildResponse(r);
    m_responses.push_back(std::move(r));
    updateCoherenceStrip();
    // Every response is in view, except that a frequency range set by the caller stays.
    const auto range = frequencyRange();
    const bool keep = m_userRange;
    rescale();
    if (keep)
        setFrequencyRange(range.first, range.second);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
    return m_responses.back().id;
}

void BodePlot::rebuildResponse(Response& r)
{
    const auto& phase = m_unwrapped ? r.phaseUnwrapped : r.phaseWrapped;
    r.mag->data()->set(toGraphData(r.f, r.magDb, &r.valid, false), true);
    r.phase->data()->set(toGraphData(r.f, phase, &r.valid, !m_unwrapped), true);
    r.coh->data()->set(toGraphData(r.f, r.coherence, nullptr, false), true);
    // The faint copy shows the invalid stretches; without any it would only double the valid line.
    r.magFaint->data()->set(r.anyInvalid ? toGraphData(r.f, r.magDb, nullptr, false) : QVector<QCPGraphData>(),
                            true);
    r.phaseFaint->data()->set(r.anyInvalid ? toGraphData(r.f, phase, nullptr, !m_unwrapped)
                                           : QVector<QCPGraphData>(),
                              true);
}

void BodePlot::removeResponse(int id)
{
    auto it = std::find_if(m_responses.begin(), m_responses.end(), [id](const Response& r) { return r.id == id; });
    if (it == m_responses.end())
        return;
    for (QCPGraph* g : {it->mag, it->phase, it->magFaint, it->phaseFaint, it->coh})
        m_plot->removeGraph(g);
    m_responses.erase(it);
    updateCoherenceStrip();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void BodePlot::clearResponses()
{
    while (!m_responses.empty())
        removeResponse(m_responses.back().id);
    m_colorIndex = 0;
}

void BodePlot::clear()
{
    clearMarkers();
    clearBands();
    clearResponses();
}

int BodePlot::responseCount() const
{
    return static_cast<int>(m_responses.size());
}

QStringList BodePlot::responseNames() const
{
    QStringList names;
    for (const auto& r : m_responses)
        names << r.name;
    return names;
}

void BodePlot::addBand(double fromHz, double toHz, BandKind kind)
{
    if (!(fromHz > 0) || !(toHz > fromHz))
        return;
    Band b;
    b.fromHz = fromHz;
    b.toHz = toHz;
    b.kind = kind;
    for (QCPAxisRect* rect : {m_magRect, m_phaseRect, m_cohRect}) {
        auto* item = new QCPItemRect(m_plot);
        item->setLayer(QStringLiteral("grid"));
        item->setClipAxisRect(rect);
        for (QCPItemPosition* p : {item->topLeft, item->bottomRight}) {
            p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
            p->setAxisRect(rect);
            p->setTypeX(QCPItemPosition::ptPlotCoords);
            p->setTypeY(QCPItemPosition::ptAxisRectRatio);
        }
        item->topLeft->setCoords(fromHz, 0.0);
        item->bottomRight->setCoords(toHz, 1.0);
        item->setPen(Qt::NoPen);
        item->setBrush(bandColor(kind));
        item->setSelectable(false);
        b.rects.push_back(item);
    }
    m_bands.push_back(std::move(b));
    updateBandLegend();
    updateCoherenceStrip();  // also the legend's visibility
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void BodePlot::clearBands()
{
    for (auto& b : m_bands) {
        for (auto* item : b.rects)
            m_plot->removeItem(item);
    }
    m_bands.clear();
    updateBandLegend();
    updateCoherenceStrip();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

int BodePlot::bandCount() const
{
    return static_cast<int>(m_bands.size());
}

void BodePlot::updateBandLegend()
{
    for (QCPGraph* g : m_bandLegendGraphs)
        m_plot->removeGraph(g);
    m_bandLegendGraphs.clear();
    for (BandKind kind : {BandKind::MultiSweepOnly, BandKind::NotMeasurable}) {
        if (std::none_of(m_bands.begin(), m_bands.end(), [kind](const Band& b) { return b.kind == kind; }))
            continue;
        // An empty graph whose legend icon shows the band's fill.
        QCPGraph* g = m_plot->addGraph(m_magRect->axis(QCPAxis::atBottom), m_magRect->axis(QCPAxis::atLeft));
        QColor c = bandColor(kind);
        c.setAlpha(std::min(255, c.alpha() * 2));
        g->setPen(QPen(c, 8.0));
        g->setName(kind == BandKind::MultiSweepOnly
                       ? tr("above the observation Nyquist: valid only by multi-sweep or multisine")
                       : tr("not measurable"));
        m_bandLegendGraphs.push_back(g);
    }
}

void BodePlot::addMarker(double fHz, MarkerKind kind, const QString& label)
{
    if (!(fHz > 0))
        return;
    Marker m;
    m.fHz = fHz;
    m.kind = kind;
    m.label = label;
    m_markers.push_back(std::move(m));
    rebuildMarkers();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void BodePlot::rebuildMarkers()
{
    for (auto& m : m_markers) {
        for (auto* item : m.items)
            m_plot->removeItem(item);
        m.items.clear();
    }
    int index = 0;
    for (auto& m : m_markers) {
        const QColor color = markerColor(m.kind);
        for (QCPAxisRect* rect : {m_magRect, m_phaseRect}) {
            auto* line = new QCPItemStraightLine(m_plot);
            line->setClipAxisRect(rect);
            for (QCPItemPosition* p : {line->point1, line->point2}) {
                p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
                p->setAxisRect(rect);
                p->setTypeX(QCPItemPosition::ptPlotCoords);
                p->setTypeY(QCPItemPosition::ptAxisRectRatio);
            }
            line->point1->setCoords(m.fHz, 0.0);
            line->point2->setCoords(m.fHz, 1.0);
            line->setPen(QPen(color, 1.0, Qt::DashLine));
            m.items.push_back(line);
        }
        if (!m.label.isEmpty()) {
            auto* text = new QCPItemText(m_plot);
            text->setClipAxisRect(m_magRect);
            text->position->setAxes(m_magRect->axis(QCPAxis::atBottom), m_magRect->axis(QCPAxis::atLeft));
            text->position->setAxisRect(m_magRect);
            text->position->setTypeX(QCPItemPosition::ptPlotCoords);
            text->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
            // Staggered so that labels of close markers do not print over each other.
            text->position->setCoords(m.fHz, 0.01 + 0.075 * (index % 3));
            text->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
            text->setText(m.label);
            text->setColor(color);
            text->setBrush(QColor(255, 255, 255, 200));
            text->setPadding(QMargins(3, 1, 3, 1));
            QFont font = text->font();
            font.setPointSizeF(font.pointSizeF() * 0.9);
            text->setFont(font);
            m.items.push_back(text);
        }
        ++index;
    }
}

void BodePlot::alignMarkerLabels()
{
    // A label in the right quarter of the axis grows to the left of its line so it is never cut.
    const QCPRange range = m_magRect->axis(QCPAxis::atBottom)->range();
    if (!(range.lower > 0) || !(range.upper > range.lower))
        return;
    const double split = range.lower * std::pow(range.upper / range.lower, 0.72);
    for (auto& m : m_markers) {
        for (auto* item : m.items) {
            if (auto* text = qobject_cast<QCPItemText*>(item))
                text->setPositionAlignment((m.fHz > split ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignTop);
        }
    }
}

void BodePlot::clearMarkers()
{
    for (auto& m : m_markers) {
        for (auto* item : m.items)
            m_plot->removeItem(item);
    }
    m_markers.clear();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

int BodePlot::markerCount() const
{
    return static_cast<int>(m_markers.size());
}

void BodePlot::setMagnitudeTitle(const QString& title)
{
    m_magRect->axis(QCPAxis::atLeft)->setLabel(title.isEmpty() ? detail::axisTitle(tr("Magnitude"), tr("dB")) : title);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

QString BodePlot::magnitudeTitle() const
{
    return m_magRect->axis(QCPAxis::atLeft)->label();
}

void BodePlot::setPhaseUnwrapped(bool unwrapped)
{
    if (unwrapped == m_unwrapped)
        return;
    m_unwrapped = unwrapped;
    for (auto& r : m_responses)
        rebuildResponse(r);
    rescale();
}

void BodePlot::updateCoherenceStrip()
{
    const bool show = std::any_of(m_responses.begin(), m_responses.end(),
                                  [](const Response& r) { return r.anyCoherence; });
    QCPLayoutGrid* layout = m_plot->plotLayout();
    const bool shown = layout->hasElement(2, 0) && layout->element(2, 0) == m_cohRect;
    if (show && !shown) {
        layout->insertRow(2);
        layout->addElement(2, 0, m_cohRect);
        layout->setRowStretchFactor(2, 0.9);
        m_cohRect->setMarginGroup(QCP::msLeft | QCP::msRight, m_margins);
    } else if (!show && shown) {
        layout->take(m_cohRect);
        layout->simplify();
        // Its never-updated margins would otherwise squeeze the other strips.
        m_cohRect->setMarginGroup(QCP::msLeft | QCP::msRight, nullptr);
    }
    detail::updateLegendVisibility(*m_plot);
    // A rect outside the layout keeps stale geometry: hide it and its bands.
    m_cohRect->setVisible(show);
    for (auto& b : m_bands)
        b.rects.back()->setVisible(show);
    // Only the lowest strip carries the frequency labels.
    QCPAxis* bottom = (show ? m_cohRect : m_phaseRect)->axis(QCPAxis::atBottom);
    for (QCPAxisRect* r : {m_magRect, m_phaseRect, m_cohRect}) {
        QCPAxis* x = r->axis(QCPAxis::atBottom);
        x->setTickLabels(x == bottom);
        x->setLabel(x == bottom ? detail::axisTitle(tr("Frequency"), tr("Hz")) : QString());
    }
}

bool BodePlot::coherenceVisible() const
{
    return m_cohRect->visible();
}

void BodePlot::setFrequencyRange(double fminHz, double fmaxHz)
{
    if (!(fminHz > 0) || !(fmaxHz > fminHz))
        return;
    m_magRect->axis(QCPAxis::atBottom)->setRange(fminHz, fmaxHz);
    m_userRange = true;
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

std::pair<double, double> BodePlot::frequencyRange() const
{
    const QCPRange r = m_magRect->axis(QCPAxis::atBottom)->range();
    return {r.lower, r.upper};
}

void BodePlot::rescale()
{
    m_userRange = false;
    double fLo = std::numeric_limits<double>::infinity();
    double fHi = 0.0;
    double mLo = fLo, mHi = -fLo, pLo = fLo, pHi = -fLo;
    for (const auto& r : m_responses) {
        for (double f : r.f) {
            if (f > 0 && std::isfinite(f)) {
                fLo = std::min(fLo, f);
                fHi = std::max(fHi, f);
            }
        }
        const auto [a, b] = finiteRange(r.magDb);
        mLo = std::min(mLo, a);
        mHi = std::max(mHi, b);
        const auto [c, d] = finiteRange(m_unwrapped ? r.phaseUnwrapped : r.phaseWrapped);
        pLo = std::min(pLo, c);
        pHi = std::max(pHi, d);
    }
    if (!(fHi > fLo)) {
        fLo = 1.0;
        fHi = 10000.0;
    }
    if (!(mHi >= mLo)) {
        mLo = -60.0;
        mHi = 20.0;
    }
    const double mPad = std::max(1.0, 0.06 * (mHi - mLo));
    m_magRect->axis(QCPAxis::atBottom)->setRange(fLo, fHi);
    m_magRect->axis(QCPAxis::atLeft)->setRange(mLo - mPad, mHi + mPad);
    if (!m_unwrapped || !(pHi >= pLo))
        m_phaseRect->axis(QCPAxis::atLeft)->setRange(-190.0, 190.0);
    else
        m_phaseRect->axis(QCPAxis::atLeft)->setRange(pLo - 10.0, pHi + 10.0);
    m_cohRect->axis(QCPAxis::atLeft)->setRange(0.0, 1.05);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

const BodePlot::Response* BodePlot::findResponse(int id) const
{
    for (const auto& r : m_responses) {
        if (r.id == id)
            return &r;
    }
    return nullptr;
}

double BodePlot::magnitudeDbAt(int id, double fHz) const
{
    const Response* r = findResponse(id);
    return r ? interpolateLogKey(r->mag, fHz) : kNaN;
}

double BodePlot::phaseDegAt(int id, double fHz) const
{
    const Response* r = findResponse(id);
    return r ? interpolateLogKey(r->phase, fHz) : kNaN;
}

bool BodePlot::exportImage(const QString& path, int width, int height)
{
    return exportPlotImage(*m_plot, path, width, height, &m_lastError);
}

void BodePlot::replotNow()
{
    m_plot->replot(QCustomPlot::rpImmediateRefresh);
}

}  // namespace widgets
}  // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
// Ball-bar polar plot on QCustomPlot. Display coordinates are in units of the nominal radius: a
// point at angle θ with deviation d is drawn at radius 1 + M·d/R (M the magnification). Rings every
// division around the nominal circle; the axes are hidden and their ranges set after each layout
// pass so that one unit is as long in x as in y (also in exports of any size).
#include "widgets/PolarPlot.h"

#include "core/model/Constants.h"
#include "widgets/PlotCommon.h"
#include "widgets/PlotExport.h"

#include <QVBoxLayout>
#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace axistune {
namespace widgets {

namespace {

using model::kPi;
constexpr double kHalfSpan = 0.42;  // rings and deviations stay within 1 ± kHalfSpan
constexpr double kExtent = 1.62;    // half-width of the drawing in display units

// The smallest 1-2-5 number >= v.
double niceCeil(double v)
{
    if (!(v > 0))
        return 1.0;
    const double p = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * p >= v * (1.0 - 1e-12))
            return m * p;
    }
    return 10.0 * p;
}

QCPCurve* circle(QCustomPlot* plot, double r, const QPen& pen)
{
    auto* c = new QCPCurve(plot->xAxis, plot->yAxis);
    QVector<QCPCurveData> d;
    const int n = 240;
    d.reserve(n + 1);
    for (int i = 0; i <= n; ++i) {
        const double a = 2.0 * kPi * i / n;
        d.push_back(QCPCurveData(i, r * std::cos(a), r * std::sin(a)));
    }
    c->data()->set(d, true);
    c->setPen(pen);
    c->removeFromLegend();
    c->setSelectable(QCP::stNone);
    return c;
}

}  // namespace

PolarPlot::PolarPlot(QWidget* parent) : QWidget(parent), m_plot(new QCustomPlot(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    detail::applyBaseStyle(*m_plot);
    detail::placeLegendBelow(*m_plot, 3);
    for (QCPAxis* a : m_plot->axisRect()->axes()) {
        a->setVisible(false);
        a->grid()->setVisible(false);
    }
    m_plot->axisRect()->setAutoMargins(QCP::msNone);
    m_plot->axisRect()->setMargins(QMargins(4, 4, 4, 4));
    connect(m_plot, &QCustomPlot::afterLayout, this, &PolarPlot::keepEqualAspect);
    rebuild();
}

PolarPlot::~PolarPlot() = default;

void PolarPlot::setNominalRadius(double radiusM)
{
    if (radiusM > 0 && std::isfinite(radiusM)) {
        m_radiusM = radiusM;
        rebuild();
    }
}

int PolarPlot::addTrace(const QString& name, const std::vector<double>& angleRad, const std::vector<double>& deviationM,
                        const QColor& color, Qt::PenStyle style)
{
    Trace t;
    t.name = name;
    const std::size_t n = std::min(angleRad.size(), deviationM.size());
    t.angleRad.assign(angleRad.begin(), angleRad.begin() + static_cast<std::ptrdiff_t>(n));
    t.deviationM.assign(deviationM.begin(), deviationM.begin() + static_cast<std::ptrdiff_t>(n));
    t.color = color.isValid() ? color : detail::paletteColor(m_colorIndex);
    ++m_colorIndex;
    t.style = style;
    m_traces.push_back(std::move(t));
    rebuild();
    return static_cast<int>(m_traces.size()) - 1;
}

int PolarPlot::addTrace(const model::BallBarTrace& trace, const QString& name, const QColor& color, Qt::PenStyle style)
{
    if (trace.radiusM > 0 && std::isfinite(trace.radiusM))
        m_radiusM = trace.radiusM;
    return addTrace(name, trace.angleRad, trace.deviationM, color, style);
}

void PolarPlot::addMarker(double angleRad, const QString& label)
{
    m_markers.push_back({angleRad, label});
    rebuild();
}

void PolarPlot::clear()
{
    m_traces.clear();
    m_markers.clear();
    m_colorIndex = 0;
    rebuild();
}

void PolarPlot::setMagnification(double factor)
{
    m_setMagnification = (factor > 0 && std::isfinite(factor)) ? factor : 0.0;
    rebuild();
}

double PolarPlot::maxAbsDeviation() const
{
    double m = 0.0;
    for (const auto& t : m_traces) {
        for (double d : t.deviationM) {
            if (std::isfinite(d))
                m = std::max(m, std::abs(d));
        }
    }
    return m;
}

double PolarPlot::magnification() const
{
    if (m_setMagnification > 0)
        return m_setMagnification;
    const double dev = maxAbsDeviation();
    // The largest deviation spans a third of the radius; 10 µm full scale when there is none.
    return (m_radiusM / 3.0) / (dev > 0 ? dev : 10e-6);
}

double PolarPlot::micrometresPerDivision() const
{
    // About three divisions across a third of the radius.
    const double fullScaleM = (m_radiusM / 3.0) / magnification();
    return niceCeil(fullScaleM / 3.0 * 1e6);
}

QString PolarPlot::scaleText() const
{
    return tr("Scale: %1 µm/div, magnification ×%2, radius %3 mm")
        .arg(QString::number(micrometresPerDivision(), 'g', 4), QString::number(magnification(), 'f', 0),
             QString::number(m_radiusM * 1e3, 'g', 6));
}

void PolarPlot::rebuild()
{
    m_plot->clearPlottables();
    m_plot->clearItems();
    const double mag = magnification();
    const double divDisplay = mag * micrometresPerDivision() * 1e-6 / m_radiusM;  // one division on screen
    const int rings = divDisplay > 0 ? static_cast<int>(std::floor(kHalfSpan / divDisplay + 1e-9)) : 0;
    const QPen ringPen(QColor(200, 200, 200), 1.0);
    for (int k = -rings; k <= rings; ++k) {
        if (k != 0)
            circle(m_plot, 1.0 + k * divDisplay, ringPen);
    }
    circle(m_plot, 1.0, QPen(QColor(60, 60, 60), 1.4));
    // Spokes every 30° and the angle labels.
    const double inner = 1.0 - rings * divDisplay;
    const double outer = 1.0 + rings * divDisplay;
    for (int deg = 0; deg < 360; deg += 30) {
        const double a = deg * model::kRadPerDeg;
        auto* spoke = new QCPItemLine(m_plot);
        spoke->start->setCoords(inner * std::cos(a), inner * std::sin(a));
        spoke->end->setCoords(outer * std::cos(a), outer * std::sin(a));
        spoke->setPen(ringPen);
        spoke->setLayer(QStringLiteral("grid"));
        if (deg % 90 == 0) {
            auto* text = new QCPItemText(m_plot);
            const double r = outer + 0.1;
            text->position->setCoords(r * std::cos(a), r * std::sin(a));
            text->setText(QStringLiteral("%1°").arg(deg));
            text->setColor(QColor(90, 90, 90));
        }
    }
    for (const auto& t : m_traces) {
        auto* c = new QCPCurve(m_plot->xAxis, m_plot->yAxis);
        QVector<QCPCurveData> d;
        d.reserve(static_cast<int>(t.angleRad.size()));
        for (std::size_t i = 0; i < t.angleRad.size(); ++i) {
            if (!std::isfinite(t.angleRad[i]) || !std::isfinite(t.deviationM[i]))
                continue;
            const double r = std::max(0.0, 1.0 + mag * t.deviationM[i] / m_radiusM);
            d.push_back(QCPCurveData(static_cast<double>(d.size()), r * std::cos(t.angleRad[i]),
                                     r * std::sin(t.angleRad[i])));
        }
        c->data()->set(d, true);
        c->setPen(QPen(t.color, 1.6, t.style));
        c->setName(t.name);
    }
    for (const auto& m : m_markers) {
        const double a = m.angleRad;
        auto* tick = new QCPItemLine(m_plot);
        tick->start->setCoords((inner - 0.04) * std::cos(a), (inner - 0.04) * std::sin(a));
        tick->end->setCoords((outer + 0.04) * std::cos(a), (outer + 0.04) * std::sin(a));
        tick->setPen(QPen(QColor(170, 0, 120), 1.4, Qt::DashLine));
        if (!m.label.isEmpty()) {
            auto* text = new QCPItemText(m_plot);
            const double r = inner - 0.08;
            text->position->setCoords(r * std::cos(a), r * std::sin(a));
            text->setText(m.label);
            text->setColor(QColor(170, 0, 120));
            text->setBrush(QColor(255, 255, 255, 200));
        }
    }
    auto* scale = new QCPItemText(m_plot);
    scale->position->setType(QCPItemPosition::ptAxisRectRatio);
    scale->position->setCoords(0.0, 0.0);
    scale->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
    scale->setTextAlignment(Qt::AlignLeft);
    scale->setText(scaleText());
    scale->setPadding(QMargins(4, 2, 4, 2));
    detail::updateLegendVisibility(*m_plot);
    keepEqualAspect();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void PolarPlot::keepEqualAspect()
{
    const QRect rect = m_plot->axisRect()->rect();
    const double w = std::max(1, rect.width());
    const double h = std::max(1, rect.height());
    const double pxPerUnit = std::min(w, h) / (2.0 * kExtent);
    m_plot->xAxis->setRange(-0.5 * w / pxPerUnit, 0.5 * w / pxPerUnit);
    m_plot->yAxis->setRange(-0.5 * h / pxPerUnit, 0.5 * h / pxPerUnit);
}

void PolarPlot::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    keepEqualAspect();
}

bool PolarPlot::exportImage(const QString& path, int width, int height)
{
    return exportPlotImage(*m_plot, path, width, height, &m_lastError);
}

void PolarPlot::replotNow()
{
    m_plot->replot(QCustomPlot::rpImmediateRefresh);
}

}  // namespace widgets
}  // namespace axistune

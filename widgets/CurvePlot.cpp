// SPDX-License-Identifier: GPL-3.0-or-later
// General x–y plot on QCustomPlot. Curves are QCPCurves (parametric: x need not increase, e.g. a
// closed stability boundary); a NaN in x or y splits a curve into segments so that the line breaks.
#include "widgets/CurvePlot.h"

#include "widgets/PlotCommon.h"
#include "widgets/PlotExport.h"

#include <QVBoxLayout>
#include <qcustomplot.h>

#include <cmath>
#include <limits>

namespace axistune {
namespace widgets {

CurvePlot::CurvePlot(QWidget* parent) : QWidget(parent), m_plot(new QCustomPlot(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot);
    detail::applyBaseStyle(*m_plot);
    detail::placeLegendBelow(*m_plot, 3);
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    setAxes(tr("x"), QString(), tr("y"), QString());
}

CurvePlot::~CurvePlot() = default;

void CurvePlot::setAxes(const QString& xLabel, const QString& xUnit, const QString& yLabel, const QString& yUnit,
                        bool logX, bool logY)
{
    m_logX = logX;
    m_logY = logY;
    m_plot->xAxis->setLabel(detail::axisTitle(xLabel, xUnit));
    m_plot->yAxis->setLabel(detail::axisTitle(yLabel, yUnit));
    for (auto [axis, log] : {std::pair{m_plot->xAxis, logX}, std::pair{m_plot->yAxis, logY}}) {
        if (log) {
            detail::makeLogAxis(*axis);
        } else {
            axis->setScaleType(QCPAxis::stLinear);
            axis->setTicker(QSharedPointer<QCPAxisTicker>(new QCPAxisTicker));
        }
        axis->grid()->setSubGridVisible(log);
    }
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

int CurvePlot::addCurve(const QString& name, const std::vector<double>& x, const std::vector<double>& y,
                        const QColor& color, Qt::PenStyle style, bool scatter)
{
    Curve curve;
    curve.name = name;
    const QColor c = color.isValid() ? color : detail::paletteColor(static_cast<int>(m_curves.size()));
    auto usable = [this](double vx, double vy) {
        return std::isfinite(vx) && std::isfinite(vy) && (!m_logX || vx > 0) && (!m_logY || vy > 0);
    };
    auto newSegment = [&]() {
        auto* seg = new QCPCurve(m_plot->xAxis, m_plot->yAxis);
        seg->setPen(scatter ? QPen(Qt::NoPen) : QPen(c, 1.6, style));
        if (scatter) {
            seg->setLineStyle(QCPCurve::lsNone);
            seg->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, c, c, 5));
        }
        seg->setName(name);
        if (curve.segments.empty())
            seg->addToLegend();
        else
            seg->removeFromLegend();
        curve.segments.push_back(seg);
        return seg;
    };
    const std::size_t n = std::min(x.size(), y.size());
    QVector<QCPCurveData> piece;
    auto flush = [&]() {
        if (!piece.isEmpty() || curve.segments.empty())
            newSegment()->data()->set(piece, true);
        piece.clear();
    };
    for (std::size_t i = 0; i < n; ++i) {
        if (usable(x[i], y[i]))
            piece.push_back(QCPCurveData(static_cast<double>(piece.size()), x[i], y[i]));
        else if (!piece.isEmpty())
            flush();
    }
    flush();
    m_curves.push_back(std::move(curve));
    detail::updateLegendVisibility(*m_plot);
    rescale();
    return static_cast<int>(m_curves.size()) - 1;
}

void CurvePlot::addPoint(double x, double y, const QString& label)
{
    auto* dot = new QCPItemTracer(m_plot);
    dot->setStyle(QCPItemTracer::tsCircle);
    dot->setSize(9);
    dot->setPen(QPen(Qt::black, 1.5));
    dot->setBrush(QColor(255, 220, 0));
    dot->position->setCoords(x, y);
    if (!label.isEmpty()) {
        auto* text = new QCPItemText(m_plot);
        text->position->setParentAnchor(dot->position);
        text->position->setCoords(8, -6); // pixels right of and above the point
        text->setPositionAlignment(Qt::AlignLeft | Qt::AlignBottom);
        text->setText(label);
        text->setBrush(QColor(255, 255, 255, 210));
        text->setPadding(QMargins(3, 1, 3, 1));
    }
    m_points.emplace_back(x, y);
    m_pointLabels << label;
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void CurvePlot::addVerticalLine(double x, const QString& label)
{
    auto* line = new QCPItemStraightLine(m_plot);
    line->point1->setTypeY(QCPItemPosition::ptAxisRectRatio);
    line->point2->setTypeY(QCPItemPosition::ptAxisRectRatio);
    line->point1->setCoords(x, 0.0);
    line->point2->setCoords(x, 1.0);
    line->setPen(QPen(QColor(90, 90, 90), 1.0, Qt::DashLine));
    if (!label.isEmpty()) {
        auto* text = new QCPItemText(m_plot);
        text->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
        text->position->setCoords(x, 0.01 + 0.07 * (m_lineCount % 3));
        text->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
        text->setText(label);
        text->setColor(QColor(60, 60, 60));
        text->setBrush(QColor(255, 255, 255, 210));
        text->setPadding(QMargins(3, 1, 3, 1));
    }
    ++m_lineCount;
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void CurvePlot::clear()
{
    m_plot->clearPlottables();
    m_plot->clearItems();
    m_curves.clear();
    m_points.clear();
    m_pointLabels.clear();
    m_lineCount = 0;
    detail::updateLegendVisibility(*m_plot);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

int CurvePlot::curveCount() const
{
    return static_cast<int>(m_curves.size());
}

std::vector<std::pair<double, double>> CurvePlot::curvePoints(int index) const
{
    std::vector<std::pair<double, double>> out;
    if (index < 0 || index >= curveCount())
        return out;
    for (const auto* seg : m_curves[static_cast<std::size_t>(index)].segments)
        for (auto it = seg->data()->constBegin(); it != seg->data()->constEnd(); ++it)
            out.emplace_back(it->key, it->value);
    return out;
}

QStringList CurvePlot::curveNames() const
{
    QStringList names;
    for (const auto& c : m_curves)
        names << c.name;
    return names;
}

void CurvePlot::rescale()
{
    m_plot->rescaleAxes(false);
    for (const auto& [x, y] : m_points) {
        if (std::isfinite(x) && std::isfinite(y)) {
            m_plot->xAxis->setRange(m_plot->xAxis->range().expanded(x));
            m_plot->yAxis->setRange(m_plot->yAxis->range().expanded(y));
        }
    }
    // A little air so that lines on the border and point labels stay readable.
    for (auto [axis, log] : {std::pair{m_plot->xAxis, m_logX}, std::pair{m_plot->yAxis, m_logY}}) {
        const QCPRange r = axis->range();
        if (log && r.lower > 0)
            axis->setRange(r.lower / std::pow(r.upper / r.lower, 0.04), r.upper * std::pow(r.upper / r.lower, 0.04));
        else if (!log && r.size() > 0)
            axis->setRange(r.lower - 0.04 * r.size(), r.upper + 0.04 * r.size());
    }
    if (m_equalScales && !m_logX && !m_logY) {
        const QRect rect = m_plot->axisRect()->rect();
        if (rect.width() > 0 && rect.height() > 0) {
            const double perPixelX = m_plot->xAxis->range().size() / rect.width();
            const double perPixelY = m_plot->yAxis->range().size() / rect.height();
            if (perPixelX > perPixelY)
                m_plot->yAxis->setScaleRatio(m_plot->xAxis, 1.0);
            else
                m_plot->xAxis->setScaleRatio(m_plot->yAxis, 1.0);
        }
    }
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void CurvePlot::setXRange(double lower, double upper)
{
    m_plot->xAxis->setRange(lower, upper);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void CurvePlot::setYRange(double lower, double upper)
{
    m_plot->yAxis->setRange(lower, upper);
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

bool CurvePlot::exportImage(const QString& path, int width, int height)
{
    return exportPlotImage(*m_plot, path, width, height, &m_lastError);
}

void CurvePlot::replotNow()
{
    m_plot->replot(QCustomPlot::rpImmediateRefresh);
}

} // namespace widgets
} // namespace axistune

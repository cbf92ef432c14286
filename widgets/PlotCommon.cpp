// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/PlotCommon.h"

#include <QEvent>
#include <QLocale>
#include <QVector>

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace axistune {
namespace widgets {
namespace detail {

namespace {

constexpr const char* kLegendHolder = "axistuneLegendHolder";

// Decade ticks labelled 1, 10, 100, 1k, 10k (no "1·10³" in a frequency axis); when less than about
// two decades are visible, 1-2-5 ticks so that a zoomed-in axis still has labels.
class FriendlyLogTicker : public QCPAxisTickerLog {
protected:
    QString getTickLabel(double tick, const QLocale& locale, QChar, int) override
    {
        const double a = std::abs(tick);
        if (a >= 1e6)
            return locale.toString(tick / 1e6, 'g', 4) + QStringLiteral("M");
        if (a >= 1e3)
            return locale.toString(tick / 1e3, 'g', 4) + QStringLiteral("k");
        return locale.toString(tick, 'g', 4);
    }
    int getSubTickCount(double tickStep) override
    {
        return m_fine ? 0 : QCPAxisTickerLog::getSubTickCount(tickStep);
    }
    QVector<double> createTickVector(double tickStep, const QCPRange& range) override
    {
        m_fine = range.lower > 0 && range.upper / range.lower < 100.0;
        if (!m_fine)
            return QCPAxisTickerLog::createTickVector(tickStep, range);
        QVector<double> ticks;
        const int k0 = static_cast<int>(std::floor(std::log10(range.lower))) - 1;
        const int k1 = static_cast<int>(std::ceil(std::log10(range.upper))) + 1;
        for (int k = k0; k <= k1; ++k) {
            for (double m : {1.0, 2.0, 5.0})
                ticks.push_back(m * std::pow(10.0, k));
        }
        return ticks;
    }

private:
    bool m_fine = false;
};

/// Keeps the legend's column count to what the plot's width holds (at most the count asked for), so that
/// entries wrap onto more rows instead of being cut at narrow widths.
class LegendFitter : public QObject {
public:
    LegendFitter(QCustomPlot& plot, int maxColumns) : QObject(&plot), m_plot(plot), m_max(std::max(1, maxColumns))
    {
        plot.installEventFilter(this);
    }
    void fit()
    {
        QCPLegend* legend = m_plot.legend;
        const int n = legend->itemCount();
        if (n == 0)
            return;
        int widest = 0;
        for (int i = 0; i < n; ++i)
            if (QCPAbstractLegendItem* item = legend->item(i))
                widest = std::max(widest, item->minimumOuterSizeHint().width());
        const int available = m_plot.width() - 24;  // the holder's margins and some air
        const int fits = widest > 0 ? (available + legend->columnSpacing()) / (widest + legend->columnSpacing()) : m_max;
        const int columns = std::clamp(fits, 1, m_max);
        if (columns != legend->wrap()) {
            legend->setWrap(columns);
            legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);  // re-flow the entries
        }
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (watched == &m_plot && event->type() == QEvent::Resize)
            fit();
        return false;
    }

private:
    QCustomPlot& m_plot;
    int m_max;
};

constexpr const char* kLegendFitter = "axistuneLegendFitter";

}  // namespace

QColor paletteColor(int n)
{
    // Tableau 10: distinguishable for most colour vision and in print.
    static const QColor kColors[] = {QColor(31, 119, 180),  QColor(214, 39, 40),  QColor(44, 160, 44),
                                     QColor(255, 127, 14),  QColor(148, 103, 189), QColor(140, 86, 75),
                                     QColor(227, 119, 194), QColor(127, 127, 127), QColor(188, 189, 34),
                                     QColor(23, 190, 207)};
    const int count = static_cast<int>(sizeof(kColors) / sizeof(kColors[0]));
    return kColors[((n % count) + count) % count];
}

QString axisTitle(const QString& label, const QString& unit)
{
    if (unit.isEmpty())
        return label;
    return QStringLiteral("%1 [%2]").arg(label, unit);
}

void applyBaseStyle(QCustomPlot& plot)
{
    plot.setNoAntialiasingOnDrag(true);
    plot.setAntialiasedElements(QCP::aeNone);
    plot.setNotAntialiasedElements(QCP::aeAll);
    plot.setAntialiasedElement(QCP::aePlottables, true);
    plot.setAntialiasedElement(QCP::aeItems, true);
    plot.setMinimumSize(240, 180);
}

QCPLegend* placeLegendBelow(QCustomPlot& plot, int columns)
{
    QCPLegend* legend = plot.legend;
    legend->setVisible(true);
    if (QCPLayoutInset* inset = plot.axisRect()->insetLayout()) {
        for (int i = 0; i < inset->elementCount(); ++i) {
            if (inset->elementAt(i) == legend) {
                inset->take(legend);
                break;
            }
        }
    }
    auto* row = new QCPLayoutGrid;
    plot.plotLayout()->addElement(plot.plotLayout()->rowCount(), 0, row);
    row->setMargins(QMargins(6, 0, 6, 4));
    row->addElement(0, 0, legend);
    legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    legend->setWrap(columns);
    legend->setBorderPen(Qt::NoPen);
    legend->setBrush(Qt::NoBrush);
    legend->setIconSize(24, 15);  // tall enough that underscores in names are not clipped
    legend->setRowSpacing(2);
    legend->setColumnSpacing(12);
    plot.plotLayout()->setRowStretchFactor(plot.plotLayout()->rowCount() - 1, 0.001);
    plot.plotLayout()->simplify();
    plot.setProperty(kLegendHolder, QVariant::fromValue<QObject*>(row));
    plot.setProperty(kLegendFitter, QVariant::fromValue<QObject*>(new LegendFitter(plot, columns)));
    updateLegendVisibility(plot);
    return legend;
}

void updateLegendVisibility(QCustomPlot& plot)
{
    QCPLegend* legend = plot.legend;
    const bool wanted = legend->itemCount() > 0;
    legend->setVisible(wanted);
    if (auto* fitter = dynamic_cast<LegendFitter*>(plot.property(kLegendFitter).value<QObject*>()))
        fitter->fit();
    // An empty legend (a grid without columns) reports a maximum width of zero, which squeezes the
    // whole plot column: its row leaves the layout while the legend is empty.
    auto* holder = qobject_cast<QCPLayoutGrid*>(plot.property(kLegendHolder).value<QObject*>());
    if (!holder)
        return;
    QCPLayoutGrid* layout = plot.plotLayout();
    const bool inside = holder->layout() == layout;
    if (wanted && !inside) {
        const int row = layout->elementCount() == 0 ? 0 : layout->rowCount();
        layout->addElement(row, 0, holder);
        layout->setRowStretchFactor(row, 0.001);
    } else if (!wanted && inside) {
        layout->take(holder);
        layout->simplify();
    }
}

void makeLogAxis(QCPAxis& axis)
{
    axis.setScaleType(QCPAxis::stLogarithmic);
    QSharedPointer<QCPAxisTicker> ticker(new FriendlyLogTicker);
    axis.setTicker(ticker);
}

}  // namespace detail
}  // namespace widgets
}  // namespace axistune

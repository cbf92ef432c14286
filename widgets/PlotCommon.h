// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Look shared by the plot widgets (internal to widgets/): palette, axis titles with units, the
// legend row above the plots and the frequency/log axis setup.

#include <QColor>
#include <QString>

class QCustomPlot;
class QCPAxis;
class QCPLegend;

namespace axistune {
namespace widgets {
namespace detail {

/// The n-th colour of the palette (distinguishable, also in grey print).
QColor paletteColor(int n);
/// "label [unit]", or "label" when unit is empty.
QString axisTitle(const QString& label, const QString& unit);
/// Common font sizes, margins and interactions of a fresh QCustomPlot.
void applyBaseStyle(QCustomPlot& plot);
/// Moves the plot's legend into its own row below the axis rects (it never covers data); columns
/// fill first and wrap after `columns` entries. Returns the legend.
QCPLegend* placeLegendBelow(QCustomPlot& plot, int columns = 4);
/// Shows the legend only when it has entries (an empty legend row upsets the layout's widths).
void updateLegendVisibility(QCustomPlot& plot);
/// Turns an axis logarithmic with decade ticks (labels 1, 10, 100, 1k, ...).
void makeLogAxis(QCPAxis& axis);

}  // namespace detail
}  // namespace widgets
}  // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one image export of every plot widget: PNG, SVG or PDF chosen by the file suffix.

#include <QString>

class QCustomPlot;

namespace axistune {
namespace widgets {

/// Writes the plot to `path` as PNG, SVG or PDF (by suffix, case-insensitive). width/height in pixels
/// (PDF/SVG: points); 0 uses the plot's current size (or 1000×700 when the widget was never laid out).
/// On failure returns false and, if `error` is given, a sentence naming the file and the cause.
bool exportPlotImage(QCustomPlot& plot, const QString& path, int width, int height, QString* error);

/// The file suffixes exportPlotImage understands ("png", "svg", "pdf").
QStringList plotImageSuffixes();

}  // namespace widgets
}  // namespace axistune

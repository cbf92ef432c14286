// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A general x–y plot for the wizards: the k_p–k_i plane with its boundaries, rise time vs α, step
// responses, stability lobes, trends. Curves need not be monotonic in x; NaN in x or y breaks a line.
// Marked points and vertical lines carry labels; a legend names the curves. Wheel zooms, drag pans.

#include <QColor>
#include <QString>
#include <QWidget>

#include <vector>

class QCustomPlot;
class QCPCurve;

namespace axistune {
namespace widgets {

class CurvePlot : public QWidget {
    Q_OBJECT
public:
    explicit CurvePlot(QWidget* parent = nullptr);
    ~CurvePlot() override;

    /// Axis titles and units (shown as "label [unit]"); logarithmic axes ignore values <= 0.
    void setAxes(const QString& xLabel, const QString& xUnit, const QString& yLabel, const QString& yUnit,
                 bool logX = false, bool logY = false);
    /// Adds a curve (a line, or markers when `scatter`); returns its index (0, 1, ...).
    int addCurve(const QString& name, const std::vector<double>& x, const std::vector<double>& y,
                 const QColor& color = QColor(), Qt::PenStyle style = Qt::SolidLine, bool scatter = false);
    /// A marked point with a label (e.g. the chosen k_p/k_i).
    void addPoint(double x, double y, const QString& label);
    /// A vertical line across the plot with a label at the top.
    void addVerticalLine(double x, const QString& label);
    /// Removes curves, points and lines (the axes stay).
    void clear();
    int curveCount() const;
    int pointCount() const { return static_cast<int>(m_points.size()); }
    int verticalLineCount() const { return m_lineCount; }
    QStringList curveNames() const;
    /// The points curve `index` shows (every segment in order; values a log axis cannot show are left out).
    std::vector<std::pair<double, double>> curvePoints(int index) const;
    /// The marked points and their labels, in the order added.
    const std::vector<std::pair<double, double>>& points() const { return m_points; }
    const QStringList& pointLabels() const { return m_pointLabels; }
    /// Fits both axes to all curves and points (with equal scales: one unit is as long on both axes, the axis with
    /// room to spare widened, so a circle draws round).
    void rescale();
    /// Equal scales on x and y (an XY plot of two positions); applied at the next rescale().
    void setEqualScales(bool on) { m_equalScales = on; }
    bool equalScales() const { return m_equalScales; }
    void setXRange(double lower, double upper);
    void setYRange(double lower, double upper);

    /// PNG, SVG or PDF by suffix; false on failure (see lastError()).
    bool exportImage(const QString& path, int width = 0, int height = 0);
    QString lastError() const { return m_lastError; }
    void replotNow();

private:
    struct Curve {
        QString name;
        std::vector<QCPCurve*> segments; // one per NaN-separated piece; the first is in the legend
    };
    QCustomPlot* m_plot = nullptr;
    std::vector<Curve> m_curves;
    std::vector<std::pair<double, double>> m_points;
    QStringList m_pointLabels;
    int m_lineCount = 0;
    bool m_logX = false;
    bool m_logY = false;
    bool m_equalScales = false;
    QString m_lastError;
};

} // namespace widgets
} // namespace axistune

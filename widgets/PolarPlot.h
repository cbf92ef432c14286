// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Polar plot of ball-bar traces: the nominal circle, the radial deviation magnified (automatically
// so that the largest deviation spans a third of the radius, or as set) with rings every division,
// the scale in µm per division as text, reversal markers at given angles, several traces with a
// legend. Equal aspect ratio. Angle 0 along +x (first axis of the plane), counter-clockwise.

#include "core/model/BallBarTrace.h"

#include <QColor>
#include <QString>
#include <QWidget>

#include <vector>

class QCustomPlot;
class QCPCurve;

namespace axistune {
namespace widgets {

class PolarPlot : public QWidget {
    Q_OBJECT
public:
    explicit PolarPlot(QWidget* parent = nullptr);
    ~PolarPlot() override;

    /// Nominal radius [m] (shown in the scale text). Default 0.1 m; addTrace(BallBarTrace) sets it.
    void setNominalRadius(double radiusM);
    double nominalRadius() const { return m_radiusM; }
    /// Adds a trace (angles [rad], deviations [m] from the nominal radius); returns its index.
    int addTrace(const QString& name, const std::vector<double>& angleRad, const std::vector<double>& deviationM,
                 const QColor& color = QColor(), Qt::PenStyle style = Qt::SolidLine);
    /// Adds a ball-bar trace and takes its nominal radius.
    int addTrace(const model::BallBarTrace& trace, const QString& name, const QColor& color = QColor(),
                 Qt::PenStyle style = Qt::SolidLine);
    /// A reversal marker (radial tick with a label) at an angle [rad].
    void addMarker(double angleRad, const QString& label);
    void clear();
    int traceCount() const { return static_cast<int>(m_traces.size()); }
    int markerCount() const { return static_cast<int>(m_markers.size()); }

    /// Magnification of the deviation (display radial deviation / true deviation); 0 = automatic.
    void setMagnification(double factor);
    /// The magnification in use (automatic or set).
    double magnification() const;
    /// Scale of the rings [µm per division].
    double micrometresPerDivision() const;
    /// The scale text shown on the plot.
    QString scaleText() const;

    /// PNG, SVG or PDF by suffix; false on failure (see lastError()).
    bool exportImage(const QString& path, int width = 0, int height = 0);
    QString lastError() const { return m_lastError; }
    void replotNow();

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    struct Trace {
        QString name;
        std::vector<double> angleRad;
        std::vector<double> deviationM;
        QColor color;
        Qt::PenStyle style;
    };
    struct Marker {
        double angleRad;
        QString label;
    };
    void rebuild();
    void keepEqualAspect();
    double maxAbsDeviation() const;

    QCustomPlot* m_plot = nullptr;
    std::vector<Trace> m_traces;
    std::vector<Marker> m_markers;
    double m_radiusM = 0.1;
    double m_setMagnification = 0.0;
    int m_colorIndex = 0;
    QString m_lastError;
};

}  // namespace widgets
}  // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Time traces of a capture (and overlays such as predictions), smooth with 1,000,000 points per
// channel: QCustomPlot's adaptive sampling over data copied once. Channels are grouped by unit, one
// strip per unit (y label with the unit taken from the channel name suffix: _rad_s -> rad/s,
// _Nm -> N·m, ...); all strips share the time axis [s]. Wheel zooms and drag pans in time only
// (setZoomY(true) also in y); a double click fits all. Two vertical cursors (a right click moves the
// nearer one; the left button drags a cursor grabbed within a few pixels) with a readout of Δt and the
// channel values at the cursors below the plot.

#include "core/model/Capture.h"

#include <QColor>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <memory>
#include <utility>
#include <vector>

class QCustomPlot;
class QCPAxisRect;
class QCPGraph;
class QCPMarginGroup;
class QLabel;
class QMouseEvent;

namespace axistune {
namespace widgets {

class TimeTracePlot : public QWidget {
    Q_OBJECT
public:
    explicit TimeTracePlot(QWidget* parent = nullptr);
    ~TimeTracePlot() override;

    /// Shows the named channels of `capture` (empty = every channel except the time channel).
    /// Time axis: a "t_s"/"time_s" channel if present, else sample index / metadata fs_Hz (1 Hz if
    /// absent). Replaces a previous capture; overlay series stay. Unknown channel names are skipped.
    /// A channel's unit: metadata `unit.CHANNEL` when the capture states it (scope captures), else the
    /// name's suffix.
    void setCapture(std::shared_ptr<const model::Capture> capture, const QStringList& channels = {});
    /// Adds an overlay series (t [s] increasing, y in `unit`, a unit token such as "rad_s", "Nm", "m",
    /// or a label such as "rad/s"); it joins the strip of that unit. Returns nothing; see seriesNames().
    void addSeries(const QString& name, const std::vector<double>& t, const std::vector<double>& y, const QString& unit,
                   const QColor& color = QColor(), Qt::PenStyle style = Qt::SolidLine);
    /// Removes the capture and every series.
    void clear();

    /// Names of every plotted channel and series, in drawing order.
    QStringList seriesNames() const;
    /// Number of strips (distinct units).
    int stripCount() const;

    void setVisibleRange(double t0, double t1);
    std::pair<double, double> visibleRange() const;
    /// Fits time and values to all data.
    void rescale();
    /// Wheel/drag also act on the value axes (default false: time only).
    void setZoomY(bool enabled);

    /// Places the two cursors [s] and updates the readout.
    void setCursors(double t1, double t2);
    std::pair<double, double> cursors() const { return {m_cursorT[0], m_cursorT[1]}; }
    void hideCursors();
    /// Value of a channel or series at cursor 0 or 1 (linear interpolation between samples; equal
    /// to the sample at a sample time); NaN when unknown or outside the data.
    double cursorValue(int cursor, const QString& name) const;
    /// The readout text shown below the plot.
    QString cursorReadout() const;

    /// Writes the capture channels shown, only the samples with t0 <= t <= t1 of the visible range,
    /// as CSV with header `time_s,<channel>...`. Without a capture, the overlay series are written
    /// when they share one time base. False on failure (see lastError()).
    bool exportVisibleCsv(const QString& path) const;
    /// PNG, SVG or PDF by suffix; false on failure (see lastError()).
    bool exportImage(const QString& path, int width = 0, int height = 0);
    QString lastError() const { return m_lastError; }

    /// Redraws now (benchmarks and tests; the widget redraws itself otherwise).
    void replotNow();
    /// Whether the trace is drawn from its min/max envelope (a long trace seen whole) rather than its samples.
    bool showsEnvelope(const QString& name) const;

private:
    struct Trace;
    struct Strip;

    void rebuild();
    void rescaleValues(Strip& s);
    static QString quantityOf(const QString& unitLabel);
    Strip& stripFor(const QString& unitLabel);
    void addTraceGraph(Trace& t, Strip& s);
    void updateCursorItems();
    void updateReadout();
    void onPlotMousePress(QMouseEvent* event);
    void onPlotMouseMove(QMouseEvent* event);
    void onPlotMouseRelease(QMouseEvent* event);
    void syncTimeAxes(double lower, double upper);
    void chooseEnvelopes();
    double traceTime(const Trace& t, std::size_t i) const;

    QCustomPlot* m_plot = nullptr;
    QLabel* m_readout = nullptr;
    QCPMarginGroup* m_margins = nullptr;
    std::shared_ptr<const model::Capture> m_capture;
    std::vector<Trace> m_traces;
    std::vector<Strip> m_strips;
    double m_cursorT[2];
    bool m_cursorsShown = false;
    int m_dragCursor = -1; ///< the cursor being dragged with the left button, −1: none
    bool m_zoomY = false;
    bool m_syncing = false;
    mutable QString m_lastError;
};

/// The unit label of a channel name's suffix ("motor_vel_rad_s" -> "rad/s", "torque_Nm" -> "N·m");
/// empty when the name carries no known unit.
QString channelUnitLabel(const QString& channelName);

} // namespace widgets
} // namespace axistune

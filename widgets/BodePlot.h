// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Bode plot of any number of frequency responses: magnitude [dB] on top, phase [deg] below and a
// coherence strip (0..1) at the bottom that appears when a response has a finite coherence. The
// three share one logarithmic frequency axis [Hz]; wheel zooms and drag pans in frequency only.
// Points with valid == false are drawn as gaps in the response and faintly behind it.

#include "core/dsp/FrequencyResponse.h"

#include <QColor>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <vector>

class QCustomPlot;
class QCPAxisRect;
class QCPGraph;
class QCPMarginGroup;

namespace axistune {
namespace widgets {

class BodePlot : public QWidget {
    Q_OBJECT
public:
    enum class BandKind {
        MultiSweepOnly, ///< above the observation Nyquist: valid only by the multi-sweep method
        NotMeasurable   ///< no method can measure here
    };
    enum class MarkerKind { Resonance, Notch, AntiResonance, Other };

    explicit BodePlot(QWidget* parent = nullptr);
    ~BodePlot() override;

    /// Adds a response; an invalid colour picks the next one of the palette. Returns its id (>= 0).
    int addResponse(const dsp::FrequencyResponse& frf, const QString& name, const QColor& color = QColor(),
                    Qt::PenStyle style = Qt::SolidLine);
    void removeResponse(int id);
    void clearResponses();
    int responseCount() const;
    /// Removes responses, bands and markers.
    void clear();
    QStringList responseNames() const;

    /// Shades [fromHz, toHz] in all three strips; each kind gets one legend entry.
    void addBand(double fromHz, double toHz, BandKind kind);
    void clearBands();
    int bandCount() const;

    /// A vertical line at fHz across magnitude and phase with a label at the top.
    void addMarker(double fHz, MarkerKind kind, const QString& label);
    void clearMarkers();
    int markerCount() const;

    /// The magnitude axis's title (e.g. with the response's units); empty: "Magnitude [dB]".
    void setMagnitudeTitle(const QString& title);
    QString magnitudeTitle() const;

    /// Phase drawn unwrapped (continuous) instead of in (-180, 180]. Default: wrapped.
    void setPhaseUnwrapped(bool unwrapped);
    bool phaseUnwrapped() const { return m_unwrapped; }

    /// Shows [fminHz, fmaxHz]; responses added later keep this range (until rescale()).
    void setFrequencyRange(double fminHz, double fmaxHz);
    /// Frequency range currently shown [Hz].
    std::pair<double, double> frequencyRange() const;
    /// Fits all axes to the data (also done when a response is added).
    void rescale();
    /// True when the coherence strip is shown (some response has a finite coherence).
    bool coherenceVisible() const;

    /// Plotted magnitude [dB] of response `id` at fHz (linear interpolation in log f between the
    /// plotted points); NaN outside the data, at gaps or for an unknown id.
    double magnitudeDbAt(int id, double fHz) const;
    /// Plotted phase [deg] of response `id` at fHz, as magnitudeDbAt.
    double phaseDegAt(int id, double fHz) const;

    /// PNG, SVG or PDF by suffix; false on failure (see lastError()).
    bool exportImage(const QString& path, int width = 0, int height = 0);
    QString lastError() const { return m_lastError; }

    /// Redraws now (benchmarks and tests; the widget redraws itself otherwise).
    void replotNow();

private:
    struct Response;
    struct Band;
    struct Marker;

    void setupAxes();
    void rebuildResponse(Response& r);
    void rebuildBands();
    void rebuildMarkers();
    void alignMarkerLabels();
    void updateCoherenceStrip();
    void updateBandLegend();
    const Response* findResponse(int id) const;

    QCustomPlot* m_plot = nullptr;
    QCPAxisRect* m_magRect = nullptr;
    QCPAxisRect* m_phaseRect = nullptr;
    QCPAxisRect* m_cohRect = nullptr;
    QCPMarginGroup* m_margins = nullptr;
    std::vector<Response> m_responses;
    std::vector<Band> m_bands;
    std::vector<Marker> m_markers;
    std::vector<QCPGraph*> m_bandLegendGraphs;
    int m_nextId = 0;
    int m_colorIndex = 0;
    bool m_unwrapped = false;
    bool m_userRange = false;
    QString m_lastError;
};

}  // namespace widgets
}  // namespace axistune

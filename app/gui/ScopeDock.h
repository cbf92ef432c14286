// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The scope dock of the main window (docs/scope.md "The GUI scope", docs/gui.md "Scope"): the drive's
// scope on one axis, usable while a wizard's test or a jog runs. Channel picker with the drive's units,
// Run (normal: re-arms after every capture) / Single / Stop, trigger channel, level in the channel's
// unit, edge, pre-trigger %, length, divider; roll mode into a bounded history (device::ScopeHistory);
// a time-trace plot with two cursors (Δt, 1/Δt, Δy with units); CSV export (the scope CSV, reloadable),
// PNG/SVG/PDF; save into the session store and reopen from it or from a scope CSV; a small jog panel.
// Every drive request goes through the DriveController (its scope requests also run between the polls
// of a running test).

#include "core/device/Drive.h"
#include "core/device/Scope.h"
#include "core/device/ScopeHistory.h"

#include <QPointer>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QListWidget;
class QPushButton;
class QSpinBox;
class QStackedWidget;
class QTimer;

namespace axistune {
namespace widgets {
class CurvePlot;
class TimeTracePlot;
} // namespace widgets
namespace gui {

class AppContext;
class DriveRequest;
struct DriveReply;

/// A scope capture as the dock plots it: time_s relative to the trigger (triggered) or the drive's machine
/// time n / rate (roll), then every channel but t_s with the drive's unit (metadata unit.CHANNEL).
std::shared_ptr<model::Capture> scopePlotTable(const device::ScopeCapture& capture);

class ScopeDock : public QWidget {
    Q_OBJECT
public:
    explicit ScopeDock(AppContext& ctx, QWidget* parent = nullptr);
    ~ScopeDock() override;

    /// Default roll history per channel [rows] (≥ 10⁶, docs/scope.md).
    static constexpr int kDefaultHistoryRows = 1000000;

    // For tests and scripting: the same as the controls do.
    /// Selects the axis (asks the drive for its scope channels). False when the axis is not offered.
    bool setAxis(const QString& axis);
    QString axis() const;
    /// The drive's channel list is known for the current axis.
    bool channelsKnown() const { return m_caps != nullptr; }
    /// Checks exactly these channels (false when one is not offered).
    bool selectChannels(const QStringList& names);
    QStringList selectedChannels() const;
    void setTrigger(const QString& channel, double level, device::ScopeEdge edge, double prePct, double lengthS);
    void setDivider(int divider);
    void setRollMode(bool roll);
    void setHistoryRows(int rows);
    void setJog(double distance, double speed, double acceleration, bool backAndForth);

    /// The request the controls describe (checked as the drive will check it; errors name the control).
    Result<device::ScopeRequest> request(bool single) const;

    /// The capture shown (live, from the store or from a CSV); null when none.
    std::shared_ptr<const device::ScopeCapture> capture() const { return m_capture; }
    /// True while the scope is armed or rolling.
    bool running() const { return m_running; }
    bool jogRunning() const { return !m_jog.isNull(); }
    const device::ScopeHistory& history() const { return m_history; }
    QString stateText() const;
    QString messageText() const;
    widgets::TimeTracePlot* plot() const { return m_plot; }

    /// Math channel added to the plot: none, A − B, d/dt A (ScopeMath.h).
    enum class Math { None, Difference, Derivative };
    void setMath(Math op, const QString& a, const QString& b = QString());
    /// Name of the math channel shown (empty: none) and the error that kept it from being shown.
    QString mathChannel() const { return m_mathName; }
    /// XY: Y against X of the capture shown, instead of the time traces.
    void setXy(bool on, const QString& x = QString(), const QString& y = QString());
    /// Display scaling of one channel: shown as gain·value + offset (offset in the channel's unit), named
    /// "NAME ×gain +offset"; the capture, its exports and the store keep the drive's values. gain 1, offset 0: none.
    void setScale(const QString& channel, double gain, double offset);
    /// The plotted name of the scaled channel; empty when none is scaled.
    QString scaledChannel() const { return m_scaledName; }
    widgets::CurvePlot* xyPlot() const { return m_xyPlot; }
    /// Keeps the capture shown as a dashed reference in the time plot (overlays of earlier captures).
    void keepReference();
    void clearReferences();
    int referenceCount() const { return m_references; }
    /// Amplitude spectrum of channel A over the visible time window, opened as a document; the plot or null.
    widgets::CurvePlot* showSpectrum(QString* error = nullptr);

    bool exportCsv(const QString& path, QString* error = nullptr) const;
    bool exportImage(const QString& path, QString* error = nullptr) const;
    /// Queues the capture shown into the store (a session of kind "scope"); `saved` follows.
    bool saveToStore(QString* error = nullptr);
    bool openFromStore(qint64 sessionId, QString* error = nullptr);
    bool openCsv(const QString& path, QString* error = nullptr);

public slots:
    void runNormal();
    void runSingle();
    void stop();
    void startJog();
    void stopJog();

signals:
    /// A new capture is shown (live, from the store or a file).
    void captureShown();
    /// The scope stopped (Stop, a single capture done, an error, the link gone).
    void stopped();
    void saved(qint64 sessionId);
    void jogFinished(bool ok, const QString& message);

protected:
    void changeEvent(QEvent* event) override;

private:
    void buildUi();
    void retranslateUi();
    void onConnectionChanged(bool connected);
    void refillAxes();
    void requestChannels();
    void onChannels(const DriveReply& reply);
    void updateTriggerChannels();
    void updateUnits();
    void updateRate();
    void start(bool single);
    void onArmed(const DriveReply& reply);
    void poll();
    void onPolled(const DriveReply& reply);
    void show(std::shared_ptr<const device::ScopeCapture> capture);
    void refreshRoll();
    void setMessage(const QString& text, bool error);
    void setRunning(bool running);
    void updateButtons();
    void exportCsvInteractive();
    void exportImageInteractive();
    void openFromStoreInteractive();
    void openCsvInteractive();
    void onJogDone(const DriveReply& reply);
    static QString stateLabel(const QString& key);
    void updateAnalysisChannels();
    void updateXyPlot();
    void redraw();
    QString channelUnit(const QString& channel) const;
    bool linearAxis() const;
    model::Metadata captureMetadata() const;

    AppContext& m_ctx;
    std::shared_ptr<const device::ScopeCapabilities> m_caps;
    QString m_capsAxis;
    int m_capsRequest = 0;

    // Controls
    QLabel* m_axisLabel = nullptr;
    QComboBox* m_axis = nullptr;
    QListWidget* m_channels = nullptr;
    QGroupBox* m_triggerBox = nullptr;
    QLabel* m_trigChannelLabel = nullptr;
    QComboBox* m_trigChannel = nullptr;
    QLabel* m_levelLabel = nullptr;
    QDoubleSpinBox* m_level = nullptr;
    QLabel* m_edgeLabel = nullptr;
    QComboBox* m_edge = nullptr;
    QLabel* m_preLabel = nullptr;
    QDoubleSpinBox* m_pre = nullptr;
    QLabel* m_lengthLabel = nullptr;
    QDoubleSpinBox* m_length = nullptr;
    QLabel* m_dividerLabel = nullptr;
    QSpinBox* m_divider = nullptr;
    QLabel* m_rate = nullptr;
    QGroupBox* m_rollBox = nullptr;
    QCheckBox* m_roll = nullptr;
    QLabel* m_historyLabel = nullptr;
    QSpinBox* m_historyRows = nullptr;
    QLabel* m_windowLabel = nullptr;
    QDoubleSpinBox* m_window = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_single = nullptr;
    QPushButton* m_stop = nullptr;
    QLabel* m_state = nullptr;
    QLabel* m_message = nullptr;
    widgets::TimeTracePlot* m_plot = nullptr;
    QPushButton* m_exportCsv = nullptr;
    QPushButton* m_exportImage = nullptr;
    QPushButton* m_save = nullptr;
    QPushButton* m_openStore = nullptr;
    QPushButton* m_openCsv = nullptr;
    QGroupBox* m_mathBox = nullptr;
    QLabel* m_mathLabel = nullptr;
    QComboBox* m_mathOp = nullptr;
    QLabel* m_mathALabel = nullptr;
    QComboBox* m_mathA = nullptr;
    QLabel* m_mathBLabel = nullptr;
    QComboBox* m_mathB = nullptr;
    QPushButton* m_spectrum = nullptr;
    QCheckBox* m_xy = nullptr;
    QLabel* m_xLabel = nullptr;
    QComboBox* m_xChannel = nullptr;
    QLabel* m_yLabel = nullptr;
    QComboBox* m_yChannel = nullptr;
    QLabel* m_scaleLabel = nullptr;
    QComboBox* m_scaleChannel = nullptr;
    QDoubleSpinBox* m_scaleGain = nullptr;
    QDoubleSpinBox* m_scaleOffset = nullptr;
    QString m_scaledName;
    QPushButton* m_keepRef = nullptr;
    QPushButton* m_clearRefs = nullptr;
    QStackedWidget* m_plots = nullptr;
    widgets::CurvePlot* m_xyPlot = nullptr;
    QString m_mathName;
    int m_references = 0;
    QGroupBox* m_jogBox = nullptr;
    QLabel* m_jogDistanceLabel = nullptr;
    QDoubleSpinBox* m_jogDistance = nullptr;
    QLabel* m_jogSpeedLabel = nullptr;
    QDoubleSpinBox* m_jogSpeed = nullptr;
    QLabel* m_jogAccelLabel = nullptr;
    QDoubleSpinBox* m_jogAccel = nullptr;
    QCheckBox* m_jogReturn = nullptr;
    QPushButton* m_jogButton = nullptr;
    QPushButton* m_jogStop = nullptr;

    // State
    QTimer* m_timer = nullptr;
    bool m_running = false;
    bool m_rollRunning = false;
    bool m_pollInFlight = false;
    int m_armRequest = 0;
    std::optional<device::ScopeRequest> m_armed;
    std::uint64_t m_knownCaptures = 0;
    std::uint64_t m_nextSample = 0;
    std::uint64_t m_lostAtStart = 0;
    qint64 m_lastRollDraw = 0;
    device::ScopeHistory m_history;
    std::shared_ptr<const device::ScopeCapture> m_capture;
    QString m_captureAxis;
    QString m_captureSource; ///< connection URI, "store session N" or the CSV path
    QString m_stateKey;      ///< untranslated state for retranslation
    QString m_messageText;
    bool m_messageError = false;
    QPointer<DriveRequest> m_jog;
};

} // namespace gui
} // namespace axistune

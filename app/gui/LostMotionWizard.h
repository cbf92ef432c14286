// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Lost-motion wizard (issue 9 item 3; spec/lost-motion-and-two-inertia.md chapter 4 and W-LM §4.6;
// docs/wizards/lost-motion.md): ball-bar traces imported from files or measured by circle tests on
// the machine at two or more table positions → polar plot and diagnostics (core/tuning
// BallBarDiagnostics) → A/B fit of Δx = (A + B·x)·ΔT (core/tuning LostMotion) → compensated trace
// predicted over the measured one, with the conventional step's cut-in → apply (lostmotion.*) →
// verify with a new circle → save (session kind "lost-motion", model kind "lost_motion").
//
// Circle tests: each circle is one TestType::Circle request through the DriveController on whatever
// drive is connected (the embedded simulated drive, or a Modbus drive such as axistune-simdrive): the
// drive moves both plane axes with its own parameters, and the trace of both axes becomes a ball-bar
// trace on this side (sim::ballBarFromCircleTrace). Abort stops the running circle at once.

#include "app/gui/TuningWizard.h"
#include "app/gui/DriveController.h"
#include "core/device/Drive.h"
#include "core/io/BallBarCsv.h"
#include "core/sim/CircleTest.h"
#include "core/tuning/BallBarDiagnostics.h"
#include "core/tuning/LostMotion.h"

#include <QFutureWatcher>
#include <QWizardPage>

#include <atomic>
#include <map>
#include <memory>
#include <optional>
#include <vector>

class QButtonGroup;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QRadioButton;
class QTableWidget;

namespace axistune {
namespace widgets {
class CurvePlot;
class PolarPlot;
}  // namespace widgets
namespace gui {

class AppContext;
class ApplyPage;
class SafetyPage;

/// Everything the pages share; owned by the wizard.
struct LostMotionData {
    bool fromMachine = false;
    QString plane = "XY";
    int axisRole = 1;  ///< 0 = first plane axis, 1 = second
    QString axisName() const { return plane.mid(axisRole, 1); }
    double screwOffsetM = 0.2;
    double screwSign = 1.0;
    tuning::BallBarOptions options;
    // Circle settings (machine source).
    double radiusM = 0.05;
    double feedMPerS = 1000.0 / 60000.0;
    std::vector<double> centresM;  ///< circle centres along the identified axis
    QStringList files;
    std::vector<io::BallBarTrace> traces;
    // Analysis.
    std::optional<tuning::BallBarReport> report;
    std::vector<tuning::LostMotionPoint> points;
    std::optional<tuning::LostMotionFit> fit;
    double conventionalBacklashM = 0.0;
    std::vector<tuning::CompensationPrediction> predictions;
    QString analysisError;
    // Verification.
    std::optional<io::BallBarTrace> verification;
    std::optional<double> stepBeforeM, stepAfterM, predictedStepAfterM;
    std::optional<double> circularityBeforeM, circularityAfterM, predictedCircularityM;
};

/// Runs circle tests through the drive link (see the header comment): one Circle request after another,
/// progress from the drive, Abort through DriveController::abort.
class CircleRunner : public QObject {
    Q_OBJECT
public:
    CircleRunner(AppContext& ctx, QObject* parent = nullptr);
    /// Empty when circle tests can run on the current connection, else why not (translated).
    QString unavailableReason() const;
    void start(const QString& plane, std::vector<sim::CircleTestOptions> circles);
    /// Stops the running circle at once (the drive restores both axes' parameters) and runs no further one.
    void abort();
    bool isRunning() const { return m_running; }
    const std::vector<io::BallBarTrace>& traces() const { return m_traces; }

signals:
    /// Progress in units of 1/1000 circle.
    void progress(int done, int total, const QString& text);
    void finished(bool ok, const QString& error, bool aborted);

private:
    void runNext();
    void onCircle(const DriveReply& reply);
    void finish(bool ok, const QString& error, bool aborted);
    AppContext& m_ctx;
    QString m_plane;
    std::vector<sim::CircleTestOptions> m_circles;
    std::vector<io::BallBarTrace> m_traces;
    int m_currentId = 0;  ///< request id of the running circle, 0 when none
    std::shared_ptr<std::atomic<bool>> m_abort;
    bool m_running = false;
};

class LostMotionSourcePage : public QWizardPage {
    Q_OBJECT
public:
    LostMotionSourcePage(AppContext& ctx, LostMotionData& data, QWidget* parent = nullptr);
    /// Reads ball-bar files (errors listed with file, line and field); false when any failed.
    bool addFiles(const QStringList& paths);
    void initializePage() override;
    bool isComplete() const override;
    bool validatePage() override;
    int nextId() const override;

private:
    void updateMode();
    AppContext& m_ctx;
    LostMotionData& m_d;
    QRadioButton* m_importRadio = nullptr;
    QRadioButton* m_machineRadio = nullptr;
    QListWidget* m_fileList = nullptr;
    QLabel* m_fileErrors = nullptr;
    QComboBox* m_axisRole = nullptr;
    QDoubleSpinBox* m_offset = nullptr;
    QComboBox* m_sign = nullptr;
    QDoubleSpinBox* m_exclude = nullptr;
    QDoubleSpinBox* m_radius = nullptr;
    QDoubleSpinBox* m_feed = nullptr;
    QLineEdit* m_centres = nullptr;
    QLabel* m_machineNote = nullptr;
    QWidget* m_importBox = nullptr;
    QWidget* m_machineBox = nullptr;
};

/// Runs the circle tests of the source page (progress, Abort).
class LostMotionCirclePage : public QWizardPage {
    Q_OBJECT
public:
    LostMotionCirclePage(AppContext& ctx, LostMotionData& data, QWidget* parent = nullptr);
    void initializePage() override;
    void cleanupPage() override;
    bool isComplete() const override;
    QPushButton* abortButton() const { return m_abort; }
    bool succeeded() const { return m_ok; }

signals:
    /// A failed or aborted run, with the traces measured so far already in the data.
    void runFailed(const QString& why);

private:
    void start();
    AppContext& m_ctx;
    LostMotionData& m_d;
    CircleRunner* m_runner = nullptr;
    QLabel* m_label = nullptr;
    QProgressBar* m_bar = nullptr;
    QPushButton* m_abort = nullptr;
    QPushButton* m_retry = nullptr;
    bool m_ok = false;
};

/// Polar plot and diagnostics table; the analysis (diagnostics, fit, prediction) runs here off the GUI thread.
class LostMotionDiagnosticsPage : public QWizardPage {
    Q_OBJECT
public:
    LostMotionDiagnosticsPage(LostMotionData& data, QWidget* parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    QTableWidget* table() const { return m_table; }
    widgets::PolarPlot* plot() const { return m_plot; }
    bool analysed() const { return m_done; }

private:
    void showResults();
    LostMotionData& m_d;
    widgets::PolarPlot* m_plot = nullptr;
    QTableWidget* m_table = nullptr;
    QLabel* m_status = nullptr;
    QFutureWatcher<LostMotionData>* m_watcher = nullptr;
    bool m_done = false;
};

/// The A/B fit with its points and line, and the predicted compensated trace with the conventional one.
class LostMotionFitPage : public QWizardPage {
    Q_OBJECT
public:
    LostMotionFitPage(AppContext& ctx, LostMotionData& data, ApplyPage* apply, QWidget* parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    int nextId() const override;

private:
    AppContext& m_ctx;
    LostMotionData& m_d;
    ApplyPage* m_apply;
    widgets::CurvePlot* m_fitPlot = nullptr;
    widgets::PolarPlot* m_predPlot = nullptr;
    QLabel* m_result = nullptr;
    QTableWidget* m_predTable = nullptr;
};

/// A new circle at the last table position with the applied compensation: measured against predicted.
class LostMotionVerifyPage : public QWizardPage {
    Q_OBJECT
public:
    LostMotionVerifyPage(AppContext& ctx, LostMotionData& data, ApplyPage* apply, QWidget* parent = nullptr);
    void initializePage() override;
    void cleanupPage() override;
    bool isComplete() const override;

signals:
    /// The verification circle failed or was aborted (the compensation is then unverified).
    void runFailed(const QString& why);

private:
    void evaluate();
    AppContext& m_ctx;
    LostMotionData& m_d;
    ApplyPage* m_apply;
    CircleRunner* m_runner = nullptr;
    QLabel* m_label = nullptr;
    QProgressBar* m_bar = nullptr;
    QPushButton* m_abort = nullptr;
    widgets::PolarPlot* m_plot = nullptr;
    QTableWidget* m_table = nullptr;
    bool m_done = false;
};

/// Summary and save (the session is saved when this page is entered).
class LostMotionSavePage : public QWizardPage {
    Q_OBJECT
public:
    LostMotionSavePage(AppContext& ctx, LostMotionData& data, ApplyPage* apply, QWidget* parent = nullptr);
    void initializePage() override;

private:
    AppContext& m_ctx;
    LostMotionData& m_d;
    ApplyPage* m_apply;
    QLabel* m_text = nullptr;
};

class LostMotionWizard : public TuningWizard {
    Q_OBJECT
public:
    enum PageId { Source, Safety, Circles, Diagnostics, Fit, Apply, Verify, Save };

    explicit LostMotionWizard(AppContext& ctx, QWidget* parent = nullptr);

    LostMotionData& data() { return m_data; }
    LostMotionSourcePage* sourcePage() const { return m_source; }
    SafetyPage* safetyPage() const { return m_safety; }
    LostMotionCirclePage* circlePage() const { return m_circles; }
    LostMotionDiagnosticsPage* diagnosticsPage() const { return m_diag; }
    ApplyPage* applyPage() const { return m_apply; }

    /// Saves the session (Completed, or Aborted with the reason); called by the last page, or on failure.
    void saveSession(bool aborted, const QString& reason) override;

private:
    AppContext& m_ctx;
    LostMotionData m_data;
    LostMotionSourcePage* m_source = nullptr;
    SafetyPage* m_safety = nullptr;
    LostMotionCirclePage* m_circles = nullptr;
    LostMotionDiagnosticsPage* m_diag = nullptr;
    ApplyPage* m_apply = nullptr;
};

}  // namespace gui
}  // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The machining wizard (issue 10 item 5, docs/wizards/machining.md). Works offline (no drive):
//   1. tool     — modal parameters per direction (mass, damping, stiffness; x = feed), or a tool.json;
//   2. cut      — teeth, K_t, K_r, radial immersion, down/up milling, the current spindle speed and depth,
//                 the speed range and the steps per tooth period of the lobe computation;
//   3. lobes    — stability lobes by semi-discretization (core/machining/StabilityLobes) off the GUI
//                 thread with progress and Cancel, the current point marked stable/unstable;
//   4. advice   — from a chatter frequency (entered, or estimated from a capture by the Kalman AR
//                 estimator) the lobe number and the stable-pocket speed (core/machining/SpindleSpeed);
//   5. analysis — a captured cut (capture CSV) or a cut simulated on the vmc X axis with this tool and cut:
//                 the cutting-force observer estimate and the chatter intervals (seed 004 detector);
//   5b. avoidance — the cut with a chatter-avoidance method in the loop (MachiningAvoidancePage.h);
//   6. save     — the session (kind "machining"): inputs, lobes, advice, intervals, the analysed cut.

#include "core/machining/SpindleSpeed.h"
#include "core/machining/StabilityLobes.h"
#include "core/machining/ToolModel.h"
#include "core/machining/VibrationModeChatter.h"
#include "core/model/Capture.h"

#include <QFutureWatcher>
#include <QWizard>
#include <QWizardPage>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace axistune {
namespace widgets {
class CurvePlot;
class TimeTracePlot;
} // namespace widgets
namespace gui {

class AppContext;

/// Step 1: the tool's modes (table rows: direction, mass kg, damping N·s/m, stiffness N/m).
class MachiningToolPage : public QWizardPage {
    Q_OBJECT
public:
    explicit MachiningToolPage(QWidget* parent = nullptr);
    QTableWidget* table() const { return m_table; }
    QLabel* errorLabel() const { return m_error; }
    /// Fills the table from a tool.json; false (and the message shown) on error.
    bool loadToolFile(const QString& path);
    /// Fills the table with modes fitted to measured tool-tip receptance FRFs (FRF CSV, h in m/N) in x
    /// and y (machining::fitToolModes with the page's band and mode count; modesPerDirection ≥ 0 overrides
    /// the count, 0 = automatic). On error or a fit refused by the quality gate: false, the table emptied
    /// (no lobes) and the reason, naming the file, shown.
    bool fitToolFrfs(const QString& xPath, const QString& yPath, int modesPerDirection = -1);
    QLineEdit* fitMinHz() const { return m_fitMin; }
    QLineEdit* fitMaxHz() const { return m_fitMax; }
    QSpinBox* fitModes() const { return m_fitModes; }
    QLabel* fitStatus() const { return m_fitStatus; }
    void setTool(const machining::ToolModes& tool);
    /// The tool in the table, validated (machining::validateTool); the error names the row and column.
    Result<machining::ToolModes> tool() const;
    QString source() const { return m_source; }
    bool isComplete() const override;

private:
    void addRow(const QString& dir, const machining::ModalParameters& m);
    void revalidate();
    QTableWidget* m_table = nullptr;
    QLabel* m_error = nullptr;
    QLabel* m_derived = nullptr;
    QLineEdit* m_fitMin = nullptr;
    QLineEdit* m_fitMax = nullptr;
    QSpinBox* m_fitModes = nullptr;
    QLabel* m_fitStatus = nullptr;
    QString m_fitError; ///< why the last FRF fit was refused (shown until the table is edited)
    QString m_source;
};

/// Everything of step 2 in SI.
struct MachiningCutInputs {
    machining::CuttingConditions cut;
    double rpm = 0.0;
    double depthM = 0.0;
    double rpmMin = 0.0, rpmMax = 0.0, rpmStep = 0.0;
    int stepsPerPeriod = 80;
};

/// Step 2: cutting data, the current operating point and the lobe range.
class MachiningCutPage : public QWizardPage {
    Q_OBJECT
public:
    explicit MachiningCutPage(QWidget* parent = nullptr);
    QSpinBox* teeth() const { return m_teeth; }
    QLineEdit* ktGPa() const { return m_kt; }
    QLineEdit* krGPa() const { return m_kr; }
    QLineEdit* immersion() const { return m_immersion; }
    QComboBox* milling() const { return m_milling; }
    QLineEdit* rpm() const { return m_rpm; }
    QLineEdit* depthMm() const { return m_depth; }
    QLineEdit* rpmMin() const { return m_rpmMin; }
    QLineEdit* rpmMax() const { return m_rpmMax; }
    QLineEdit* rpmStep() const { return m_rpmStep; }
    QSpinBox* stepsPerPeriod() const { return m_steps; }
    QLabel* errorLabel() const { return m_error; }
    bool loadCutFile(const QString& path);
    Result<MachiningCutInputs> inputs() const;
    bool isComplete() const override;

private:
    void revalidate();
    QSpinBox* m_teeth = nullptr;
    QLineEdit *m_kt = nullptr, *m_kr = nullptr, *m_immersion = nullptr, *m_rpm = nullptr, *m_depth = nullptr;
    QLineEdit *m_rpmMin = nullptr, *m_rpmMax = nullptr, *m_rpmStep = nullptr;
    QComboBox* m_milling = nullptr;
    QSpinBox* m_steps = nullptr;
    QLabel* m_error = nullptr;
};

/// The lobe computation's result.
struct LobeResult {
    std::vector<machining::LobePoint> lobes;
    double limitAtCurrentM = 0.0;
    QString error;
};

/// Step 3: the lobe diagram with the current point.
class MachiningLobesPage : public QWizardPage {
    Q_OBJECT
public:
    MachiningLobesPage(const class MachiningToolPage& tool, const MachiningCutPage& cut, QWidget* parent = nullptr);
    ~MachiningLobesPage() override;
    widgets::CurvePlot* plot() const { return m_plot; }
    QLabel* status() const { return m_status; }
    QPushButton* cancelButton() const { return m_cancel; }
    QProgressBar* progress() const { return m_progress; }
    bool done() const { return m_done; }
    const LobeResult& result() const { return m_result; }
    /// The limit depth [m] at `rpm` interpolated on the computed lobes (NaN outside or before done).
    double limitAt(double rpm) const;
    void initializePage() override;
    void cleanupPage() override;
    bool isComplete() const override;
    void start();

private:
    void finished();
    const MachiningToolPage& m_toolPage;
    const MachiningCutPage& m_cutPage;
    widgets::CurvePlot* m_plot = nullptr;
    QLabel* m_status = nullptr;
    QProgressBar* m_progress = nullptr;
    QPushButton* m_cancel = nullptr;
    QPushButton* m_again = nullptr;
    QFutureWatcher<LobeResult>* m_watcher = nullptr;
    LobeResult m_result;
    bool m_done = false;
    bool m_restart = false;
};

/// Step 4: the stable-pocket advice from a chatter frequency.
class MachiningAdvicePage : public QWizardPage {
    Q_OBJECT
public:
    MachiningAdvicePage(const MachiningCutPage& cut, const MachiningLobesPage& lobes, QWidget* parent = nullptr);
    QLineEdit* chatterHz() const { return m_chatter; }
    QLabel* adviceText() const { return m_text; }
    widgets::CurvePlot* plot() const { return m_plot; }
    const std::optional<machining::PocketAdvice>& advice() const { return m_advice; }
    /// Estimates the chatter frequency from a capture CSV (channel tool_x_m, else cutting_force_N, else the
    /// first channel that is not time) with machining::estimateChatterFrequencies; false on error (shown).
    bool estimateFromCapture(const QString& path);
    QString estimateSource() const { return m_estimateSource; }
    void initializePage() override;

private:
    void update();
    const MachiningCutPage& m_cutPage;
    const MachiningLobesPage& m_lobesPage;
    QLineEdit* m_chatter = nullptr;
    QLabel* m_text = nullptr;
    QLabel* m_estimate = nullptr;
    widgets::CurvePlot* m_plot = nullptr;
    std::optional<machining::PocketAdvice> m_advice;
    QString m_estimateSource;
};

/// What the analysis computes off the GUI thread.
struct CutAnalysis {
    std::shared_ptr<const model::Capture> capture;
    QString source;
    std::vector<double> timeS, forceEstimateN;
    std::optional<machining::ChatterAnalysis> chatter;
    QString stageSource;
    QString error;
};

/// Step 5: cutting force estimate and chatter intervals of a captured or simulated cut.
class MachiningAnalysisPage : public QWizardPage {
    Q_OBJECT
public:
    MachiningAnalysisPage(const MachiningToolPage& tool, const MachiningCutPage& cut, QWidget* parent = nullptr);
    ~MachiningAnalysisPage() override;
    widgets::TimeTracePlot* plot() const { return m_plot; }
    QTableWidget* intervalTable() const { return m_table; }
    QLabel* summary() const { return m_summary; }
    QLineEdit* stagePath() const { return m_stage; }
    QLineEdit* durationS() const { return m_duration; }
    /// Analyses a capture CSV (off the GUI thread).
    void loadCapture(const QString& path);
    /// Simulates the cut of steps 1–2 on the vmc X axis, then analyses it (off the GUI thread).
    void simulateCut();
    bool busy() const;
    bool analysed() const { return m_analysis.capture != nullptr && m_analysis.error.isEmpty(); }
    const CutAnalysis& analysis() const { return m_analysis; }
    bool isComplete() const override;

private:
    void run(std::function<CutAnalysis()> job);
    void show();
    const MachiningToolPage& m_toolPage;
    const MachiningCutPage& m_cutPage;
    QLineEdit* m_stage = nullptr;
    QLineEdit* m_duration = nullptr;
    QPushButton* m_load = nullptr;
    QPushButton* m_simulate = nullptr;
    QProgressBar* m_busy = nullptr;
    widgets::TimeTracePlot* m_plot = nullptr;
    QTableWidget* m_table = nullptr;
    QLabel* m_summary = nullptr;
    QFutureWatcher<CutAnalysis>* m_watcher = nullptr;
    CutAnalysis m_analysis;
    bool m_running = false;
};

/// Step 6: the session is saved on entering; shows its id.
class MachiningSavePage : public QWizardPage {
    Q_OBJECT
public:
    explicit MachiningSavePage(QWidget* parent = nullptr);
    QLabel* status() const { return m_status; }
    void showSaved(const QString& text);

private:
    QLabel* m_status = nullptr;
};

class MachiningWizard : public QWizard {
    Q_OBJECT
public:
    /// TapId is reached only from the tool page's "Tap test…" button (nextId()).
    enum PageId { ToolId, CutId, LobesId, AdviceId, AnalysisId, SaveId, TapId, AvoidId };

    explicit MachiningWizard(AppContext& ctx, QWidget* parent = nullptr);

    MachiningToolPage* toolPage() const { return m_tool; }
    MachiningCutPage* cutPage() const { return m_cut; }
    MachiningLobesPage* lobesPage() const { return m_lobes; }
    MachiningAdvicePage* advicePage() const { return m_advice; }
    MachiningAnalysisPage* analysisPage() const { return m_analysis; }
    MachiningSavePage* savePage() const { return m_save; }
    class MachiningAvoidancePage* avoidancePage() const { return m_avoid; }
    class MachiningTapPage* tapPage() const { return m_tap; }
    /// From the tool page: opens the tap-test page.
    void openTapTest();
    int nextId() const override;
    std::int64_t savedSessionId() const { return m_sessionId; }

signals:
    void sessionSaved(qint64 id);

private:
    void onPageChanged(int id);
    void save();

    AppContext& m_ctx;
    MachiningToolPage* m_tool = nullptr;
    MachiningCutPage* m_cut = nullptr;
    MachiningLobesPage* m_lobes = nullptr;
    MachiningAdvicePage* m_advice = nullptr;
    MachiningAnalysisPage* m_analysis = nullptr;
    MachiningSavePage* m_save = nullptr;
    class MachiningAvoidancePage* m_avoid = nullptr;
    class MachiningTapPage* m_tap = nullptr;
    bool m_tapRequested = false;
    std::int64_t m_sessionId = 0;
};

/// Unit helpers shared by the pages: a number typed in the user's locale or with a '.'.
std::optional<double> machiningNumber(const QString& text);

} // namespace gui
} // namespace axistune

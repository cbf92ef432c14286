// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The notch wizard (issue 8 item 5; docs/wizards/notch.md): source FRF (a new multi-sweep
// measurement or a saved session's FRF) → resonances and proposed notches with their rules, the
// predicted FRF and the margins before/after (editable) → apply (diff, confirm, read back, journal)
// → verify by a new measurement overlaid on the prediction → save as a session of kind "notch".
// The analysis is core/tuning (Resonance.h, Notch.h, FrfComparison.h); the pages only show it.

#include "app/gui/AbortGuard.h"
#include "app/gui/WizardPages.h"

#include "core/dsp/FrequencyResponse.h"
#include "core/tuning/FrfComparison.h"
#include "core/tuning/Notch.h"
#include "core/tuning/Resonance.h"

#include <QFutureWatcher>
#include <QWizard>
#include <QWizardPage>

#include <map>
#include <optional>
#include <vector>

class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QPushButton;
class QRadioButton;
class QSpinBox;
class QTableWidget;
class QTextBrowser;

namespace axistune {
namespace widgets {
class BodePlot;
}
namespace gui {

class AppContext;
class NotchWizard;
class NcPidPage;

/// One notch of the table: drive slot (1-based) and the drive's filter parameters.
struct NotchRow {
    int slot = 0;
    dsp::NotchSpec spec;
    double resonanceHz = 0.0;  ///< 0: added or edited by the user
    QString rule;              ///< why (translated)
};

/// Everything the analysis of one FRF produced (computed off the GUI thread).
struct NotchAnalysis {
    QString error;  ///< empty: ok
    std::vector<tuning::Resonance> resonances;
    tuning::NotchProposal proposal;
    std::vector<NotchRow> rows;  ///< the proposal with drive slots and rules
    tuning::NotchPrediction prediction;
};

/// Resonances, proposal (drive slots: the existing filters keep theirs, new notches take the free
/// ones in increasing order), rules and prediction of one measured FRF. Pure; runs off the GUI thread.
NotchAnalysis analyseNotchFrf(const dsp::FrequencyResponse& measured, const tuning::LoopForm& form,
                              const tuning::ResonanceOptions& resonanceOptions, const tuning::NotchOptions& notchOptions,
                              const std::map<int, dsp::NotchSpec>& existing);

class NotchSourcePage : public QWizardPage {
    Q_OBJECT
public:
    explicit NotchSourcePage(NotchWizard& wizard, AppContext& ctx);
    void initializePage() override;
    bool isComplete() const override;
    bool validatePage() override;
    int nextId() const override;
    bool fromSession() const;
    QListWidget* sessionList() const { return m_sessions; }
    QRadioButton* measureButton() const { return m_measure; }
    QRadioButton* sessionButton() const { return m_session; }
    double fminHz() const;
    double fmaxHz() const;  ///< 0: just below the trace rate
    int points() const;
    double amplitudePct() const;

private:
    void fillSessions();
    NotchWizard& m_wizard;
    AppContext& m_ctx;
    QRadioButton* m_measure = nullptr;
    QRadioButton* m_session = nullptr;
    QListWidget* m_sessions = nullptr;
    QDoubleSpinBox* m_fmin = nullptr;
    QDoubleSpinBox* m_fmax = nullptr;
    QSpinBox* m_points = nullptr;
    QDoubleSpinBox* m_amplitude = nullptr;
    QLabel* m_note = nullptr;
};

class NotchProposePage : public QWizardPage {
    Q_OBJECT
public:
    explicit NotchProposePage(NotchWizard& wizard, AppContext& ctx);
    void initializePage() override;
    bool isComplete() const override;
    bool validatePage() override;
    int nextId() const override;
    bool analysing() const { return m_busy; }
    QTableWidget* notchTable() const { return m_table; }
    QTableWidget* marginsTable() const { return m_margins; }
    widgets::BodePlot* plot() const { return m_plot; }
    QDoubleSpinBox* minHeight() const { return m_minHeight; }
    int measuredId() const { return m_measuredId; }
    int predictedId() const { return m_predictedId; }

private:
    void onParameters(const axistune::gui::DriveReply& r);
    void readDrive();
    void startOffline();
    void showRefusal(const QString& why);
    void startAnalysis();
    void showAnalysis();
    void fillTable();
    void onEdited();
    void updatePrediction();
    void showRules();
    NotchWizard& m_wizard;
    AppContext& m_ctx;
    int m_readRequest = 0;
    bool m_busy = false;
    bool m_filling = false;
    QFutureWatcher<NotchAnalysis> m_watcher;
    QLabel* m_status = nullptr;
    QDoubleSpinBox* m_minHeight = nullptr;
    QTableWidget* m_resonances = nullptr;
    QTableWidget* m_table = nullptr;
    QTableWidget* m_margins = nullptr;
    QTextBrowser* m_rules = nullptr;
    QPushButton* m_remove = nullptr;
    QPushButton* m_reset = nullptr;
    widgets::BodePlot* m_plot = nullptr;
    int m_measuredId = -1;
    int m_predictedId = -1;
};

class NotchVerifyPage : public QWizardPage {
    Q_OBJECT
public:
    explicit NotchVerifyPage(NotchWizard& wizard);
    void initializePage() override;
    widgets::BodePlot* plot() const { return m_plot; }
    QLabel* deviationLabel() const { return m_deviation; }
    int measuredId() const { return m_ids[0]; }
    int predictedId() const { return m_ids[1]; }
    int verificationId() const { return m_ids[2]; }

private:
    NotchWizard& m_wizard;
    widgets::BodePlot* m_plot = nullptr;
    QLabel* m_deviation = nullptr;
    QTableWidget* m_peaks = nullptr;
    QTableWidget* m_margins = nullptr;
    int m_ids[3] = {-1, -1, -1};
};

class NotchSavePage : public QWizardPage {
    Q_OBJECT
public:
    explicit NotchSavePage(NotchWizard& wizard);
    void initializePage() override;
    QLabel* summary() const { return m_summary; }

private:
    NotchWizard& m_wizard;
    QLabel* m_summary = nullptr;
};

class NotchWizard : public QWizard {
    Q_OBJECT
public:
    enum PageId { kSource = 0, kSafety, kMeasure, kPropose, kApply, kVerifyRun, kVerify, kSave, kNcPid };

    explicit NotchWizard(AppContext& ctx, QWidget* parent = nullptr);
    ~NotchWizard() override;

    /// Starts from this FRF (e.g. handed over by the FRF wizard) on `axis`: the wizard opens at the
    /// proposal. `origin` is stored in the session's inputs (e.g. "frf wizard").
    void setSourceFrf(const dsp::FrequencyResponse& frf, const QString& axis, const QString& origin = QString());

    // State, for the pages and for tests.
    QString axis() const { return m_axis; }
    void setAxis(const QString& axis) { m_axis = axis; }
    bool hasMeasured() const { return !m_measured.empty(); }
    const dsp::FrequencyResponse& measured() const { return m_measured; }
    void setMeasured(const dsp::FrequencyResponse& frf, const QString& origin, std::int64_t sessionId = 0);
    const dsp::FrequencyResponse& predicted() const { return m_predicted; }
    const dsp::FrequencyResponse& verification() const { return m_verification; }
    const std::vector<tuning::Resonance>& resonances() const { return m_analysis.resonances; }
    const NotchAnalysis& analysis() const { return m_analysis; }
    const std::vector<NotchRow>& proposedRows() const { return m_analysis.rows; }
    /// The notches as they stand in the table (edited or not).
    const std::vector<NotchRow>& rows() const { return m_rows; }
    const std::optional<dsp::LoopMargins>& marginsBefore() const { return m_before; }
    const std::optional<dsp::LoopMargins>& marginsPredicted() const { return m_after; }
    const std::optional<dsp::LoopMargins>& marginsVerified() const { return m_verified; }
    const tuning::FrfDeviation& deviation() const { return m_deviation; }
    double execRateHz() const { return m_execRateHz; }
    double traceRateHz() const { return m_traceRateHz; }
    bool safetyConfirmed() const { return m_safetyConfirmed; }
    /// Why this wizard's drive-slot proposal does not apply on the connected axis (a position PID the NC closes, hal:,
    /// linuxcnc:: a new measurement goes to ncPidPage(), which proposes LinuxCNC's biquad); empty: it does.
    QString ncPidRefusal() const { return m_ncPidRefusal; }
    void setNcPidRefusal(const QString& why) { m_ncPidRefusal = why; }
    NcPidPage* ncPidPage() const { return m_ncPid; }
    bool saved() const { return m_savedId > 0; }
    qint64 savedSessionId() const { return m_savedId; }
    bool savedAborted() const { return m_savedAborted; }
    QString abortReason() const { return m_abortReason; }

    SafetyPage* safetyPage() const { return m_safety; }
    TestRunPage* measurePage() const { return m_measureRun; }
    NotchProposePage* proposePage() const { return m_propose; }
    ApplyPage* applyPage() const { return m_apply; }
    TestRunPage* verifyRunPage() const { return m_verifyRun; }
    NotchVerifyPage* verifyPage() const { return m_verifyPage; }
    NotchSavePage* savePage() const { return m_save; }
    NotchSourcePage* sourcePage() const { return m_source; }

    int nextId() const override;
    void reject() override;

    // Used by the pages.
    void setDriveContext(double execRateHz, int slotCount, const std::map<int, dsp::NotchSpec>& existing);
    int slotCount() const { return m_slotCount; }
    const std::map<int, dsp::NotchSpec>& existingNotches() const { return m_existing; }
    void setAnalysis(const NotchAnalysis& a);
    /// Replaces the table's notches and recomputes the prediction; false (with why) when a notch
    /// cannot run at the execution rate.
    bool setRows(const std::vector<NotchRow>& rows, QString* why);
    model::ParameterValues proposedValues() const;
    void setVerification(const dsp::FrequencyResponse& frf);
    tuning::LoopForm loopForm() const;
    tuning::ResonanceOptions resonanceOptions() const { return m_resOptions; }
    void setMinHeightDb(double db) { m_resOptions.minHeightDb = db; }
    tuning::NotchOptions notchOptions() const { return m_notchOptions; }
    /// Saves the completed session (the save page calls it once).
    void saveCompleted();

private:
    device::TestRequest frfRequest() const;
    void onRunFailed(TestRunPage* page, bool verification);
    void saveSession(store::SessionStatus status, const QString& note);
    void readTraceRate(const QString& axis);

    AppContext& m_ctx;
    NotchSourcePage* m_source = nullptr;
    SafetyPage* m_safety = nullptr;
    TestRunPage* m_measureRun = nullptr;
    NotchProposePage* m_propose = nullptr;
    ApplyPage* m_apply = nullptr;
    TestRunPage* m_verifyRun = nullptr;
    NotchVerifyPage* m_verifyPage = nullptr;
    NotchSavePage* m_save = nullptr;

    QString m_axis;
    QString m_machine;  ///< kept: a lost connection empties AppContext::machine()
    QString m_origin;  ///< "measurement", "session", or what setSourceFrf was told
    std::int64_t m_sourceSession = 0;
    dsp::FrequencyResponse m_measured, m_predicted, m_verification;
    NotchAnalysis m_analysis;
    std::vector<NotchRow> m_rows;
    std::optional<dsp::LoopMargins> m_before, m_after, m_verified;
    tuning::FrfDeviation m_deviation;
    tuning::ResonanceOptions m_resOptions;
    tuning::NotchOptions m_notchOptions;
    double m_execRateHz = 16000.0;
    double m_traceRateHz = 0.0;
    int m_slotCount = 4;
    std::map<int, dsp::NotchSpec> m_existing;
    bool m_safetyConfirmed = false;
    AbortGuard* m_guard = nullptr;
    int m_traceRequest = 0;
    qint64 m_savedId = 0;
    bool m_savedAborted = false;
    QString m_abortReason;
    QString m_ncPidRefusal;
    NcPidPage* m_ncPid = nullptr;
};

}  // namespace gui
}  // namespace axistune

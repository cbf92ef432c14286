// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one-button tuning wizard (issue 18 item 5; docs/tuning.md "The wizard"): the GUI of core/autotune, the
// same sequence as `axistune-cli autotune`. Three pages:
//   choices (axis, style, time budget, dry run, the confirmation that the axis may move) →
//   run (the nine steps with their state, the progress of the whole sequence, Abort, and what each finished step
//        measured, chose and by which rule) →
//   result (the final figures and the parameters old → new, or the refusal in red with "nothing was changed"; after an
//           applied run, Undo: AutoTuneUndo.cpp).
// The sequence runs on the drive thread as one DriveController request (DriveControllerAutoTune.cpp), so the drive
// is used by that thread only; Abort sets the request's token and the sequence restores every parameter it wrote.
// Each run is saved as a session of kind "autotune" with the result JSON the CLI writes.

#include "app/gui/DriveController.h"
#include "core/autotune/AutoTune.h"

#include <QPointer>
#include <QWizard>
#include <QWizardPage>

#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QDialog;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QRadioButton;
class QSpinBox;
class QTabWidget;
class QTableWidget;

namespace axistune {
namespace widgets {
class CurvePlot;
}
namespace gui {

class AppContext;

struct AutoTuneData {
    autotune::Options options;
    std::shared_ptr<const autotune::AutoTuneResult> result; ///< the sequence's answer (also refused/aborted)
    QString error; ///< the run could not start (bad options, not connected): nothing moved
    bool running = false;
    bool abortPressed = false;
    qint64 sessionId = 0; ///< the saved session (0: not saved)
    /// An earlier applied run chosen on the first page for Undo (its session's result JSON; AutoTuneEarlier.cpp):
    /// the run page is skipped and the result page offers its Undo. Null for a run of this wizard.
    std::shared_ptr<const nlohmann::json> stored;
};

/// The translated name of a step of the sequence ("frf" → "Adaptive frequency response").
QString autoTuneStepTitle(const QString& name);

class AutoTuneChoicePage : public QWizardPage {
    Q_OBJECT
public:
    AutoTuneChoicePage(AppContext& ctx, AutoTuneData& data, QWidget* parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    bool validatePage() override;

    QComboBox* axis() const { return m_axis; }
    QDoubleSpinBox* timeBudget() const { return m_budget; }
    QCheckBox* dryRun() const { return m_dryRun; }
    QCheckBox* confirmation() const { return m_confirm; }
    QRadioButton* styleButton(autotune::Style s) const;
    /// Over the travel: 1 ("off") or N >= 2 positions; disabled (with the reason in travelNote()) where the drive
    /// cannot move the axis between measurements (autotune::travelChoice).
    QSpinBox* positions() const { return m_positions; }
    QLabel* travelNote() const { return m_travelNote; }
    /// Amplitude map: "5, 10, 20" [% of rated torque], empty for none.
    QLineEdit* amplitudes() const { return m_amplitudes; }
    /// Required velocity crossover [Hz]; 0 ("the style's").
    QDoubleSpinBox* minBandwidth() const { return m_minBandwidth; }
    /// Why the choices cannot run together (autotune::checkChoices), empty when they can.
    QLabel* choiceError() const { return m_choiceError; }
    /// The answer of the travel query arrived for the current axis.
    bool travelKnown() const { return m_travelKnown; }
    /// "Undo an earlier run…": lists the applied runs of the store's sessions on this machine's axes.
    QPushButton* undoEarlierButton() const { return m_undoEarlier; }
    /// Goes to the result page with the applied run of session `sessionId` (its Undo offered); false with the reason
    /// when the session holds no applied run of an axis of this connection.
    bool openEarlierRun(qint64 sessionId, QString* why);
    int nextId() const override;

private:
    /// The choices as the sequence's options; the reason when they cannot run (the core's checks).
    autotune::Options collect(QString* why) const;
    void queryTravel();
    void updateChoices();
    void chooseEarlierRun();
    AppContext& m_ctx;
    AutoTuneData& m_d;
    QPushButton* m_undoEarlier = nullptr;
    QComboBox* m_axis = nullptr;
    QSpinBox* m_positions = nullptr;
    QLabel* m_travelNote = nullptr;
    QLineEdit* m_amplitudes = nullptr;
    QDoubleSpinBox* m_minBandwidth = nullptr;
    QLabel* m_choiceError = nullptr;
    bool m_travelKnown = false;
    bool m_travelPossible = false;
    bool m_budgetEdited = false; ///< the user set the budget: it no longer follows the positions
    int m_travelQuery = 0;
    QRadioButton* m_gentle = nullptr;
    QRadioButton* m_standard = nullptr;
    QRadioButton* m_stiff = nullptr;
    QDoubleSpinBox* m_budget = nullptr;
    QCheckBox* m_dryRun = nullptr;
    QCheckBox* m_confirm = nullptr;
};

class AutoTuneRunPage : public QWizardPage {
    Q_OBJECT
public:
    AutoTuneRunPage(AppContext& ctx, AutoTuneData& data, QWidget* parent = nullptr);
    void initializePage() override;
    void cleanupPage() override;
    bool isComplete() const override;

    QTableWidget* steps() const { return m_steps; }
    QProgressBar* progress() const { return m_progress; }
    QPushButton* abortButton() const { return m_abort; }
    QPlainTextEdit* log() const { return m_log; }
    QLabel* state() const { return m_state; }
    /// Stops the sequence (the worker restores every parameter it wrote); the page waits for its answer.
    void abort();

signals:
    /// The sequence answered (result or error) and the session was queued for saving.
    void runFinished();

private:
    void start();
    void onStepStarted(const QString& name);
    void onStepFinished(const QString& name, const QString& json);
    void onReply(const DriveReply& reply);
    void setRowState(int row, const QString& state, int icon);
    void saveSession();
    AppContext& m_ctx;
    AutoTuneData& m_d;
    QTableWidget* m_steps = nullptr;
    QProgressBar* m_progress = nullptr;
    QPushButton* m_abort = nullptr;
    QPlainTextEdit* m_log = nullptr;
    QLabel* m_state = nullptr;
    QPointer<DriveRequest> m_request;
    int m_runningRow = -1;
};

class AutoTuneResultPage : public QWizardPage {
    Q_OBJECT
public:
    AutoTuneResultPage(AppContext& ctx, AutoTuneData& data, QWidget* parent = nullptr);
    void initializePage() override;
    void cleanupPage() override; ///< back to the first page: an earlier run chosen is forgotten

    QLabel* outcome() const { return m_outcome; }
    QTableWidget* figures() const { return m_figures; }
    QTableWidget* parameters() const { return m_parameters; }
    QTabWidget* tabs() const { return m_tabs; }
    /// Over the travel: first resonance [Hz] against position [m or rad], labelled with its height [dB].
    widgets::CurvePlot* resonanceMap() const { return m_resonancePlot; }
    /// Over the travel: per position, the re-measured margins and bandwidths (final.positions[]).
    QTableWidget* positionsTable() const { return m_positionsTable; }
    /// Amplitude map: lines over frequency × amplitude (curves "linear", "non-linear", "not compared").
    widgets::CurvePlot* amplitudeMap() const { return m_ampMap; }
    /// Amplitude map: |T| [dB] per amplitude, non-linear lines marked.
    widgets::CurvePlot* amplitudeMagnitude() const { return m_ampMagnitude; }
    QLabel* amplitudeSummary() const { return m_ampSummary; }
    enum Tab { FiguresTab, ResonanceTab, AmplitudeTab };

    // Undo of an applied run (docs/tuning.md "Undo in the wizard"; AutoTuneUndo.cpp): autotune::undoTune on the drive
    // thread, the CLI's `autotune --undo` rules.
    /// Shown after an applied run; opens the confirmation with the diff. Disabled while a test runs, while the undo
    /// runs, and once undone.
    QPushButton* undoButton() const { return m_undo; }
    /// Shown after Undo was refused because the drive no longer holds what the run applied; opens a second
    /// confirmation (a box to tick: overwrite the later change), then undoes with force.
    QPushButton* undoAnywayButton() const { return m_undoAnyway; }
    /// The outcome of the undo (refusal in red, naming the key).
    QLabel* undoState() const { return m_undoState; }
    /// The open confirmation ("atUndoConfirm": the diff table "atUndoDiff", for Undo anyway the box
    /// "atUndoOverwrite"; the button box "atUndoButtons"), null when none is open.
    QDialog* undoDialog() const { return m_undoDialog; }
    bool isUndoing() const { return m_undoing; }
    bool isUndone() const { return m_undone; }

signals:
    /// The undo answered (undone, refused or failed).
    void undoFinished();

private:
    void showResonanceMap(const nlohmann::json& result, bool linear);
    void showAmplitudeMap(const nlohmann::json& map);
    void fillParameters();
    /// The page for an earlier applied run (m_d.stored): its parameters before → applied and its Undo.
    void initializeStored();
    /// A value in the parameter's display unit (the other wizards' apply pages), the SI value without metadata.
    QString valueText(const std::string& key, double si) const;
    QString unitText(const std::string& key) const;
    void onMetadata(const DriveReply& reply);
    /// Shows Undo for m_tune and reads the axis's parameter metadata (the units of the diff).
    void offerUndo();
    void updateUndoButtons();
    /// Shows the confirmation; `force`: the second one, after a refusal.
    void confirmUndo(bool force);
    void onUndoReply(const DriveReply& reply);
    void saveUndoSession(const DriveReply& reply);
    AppContext& m_ctx;
    AutoTuneData& m_d;
    QLabel* m_outcome = nullptr;
    QTabWidget* m_tabs = nullptr;
    widgets::CurvePlot* m_resonancePlot = nullptr;
    QTableWidget* m_positionsTable = nullptr;
    widgets::CurvePlot* m_ampMap = nullptr;
    widgets::CurvePlot* m_ampMagnitude = nullptr;
    QLabel* m_ampSummary = nullptr;
    QTableWidget* m_figures = nullptr;
    QLabel* m_parametersTitle = nullptr;
    QTableWidget* m_parameters = nullptr;
    QLabel* m_session = nullptr;
    QPushButton* m_undo = nullptr;
    QPushButton* m_undoAnyway = nullptr;
    QLabel* m_undoState = nullptr;
    QPointer<QDialog> m_undoDialog;
    std::optional<autotune::AppliedTune> m_tune; ///< the applied run as core reads it back (appliedTuneFromJson)
    std::vector<model::ParameterMeta> m_metas;
    bool m_metasKnown = false; ///< the metadata answered (also with an error: then SI values, no unit)
    int m_metaRequest = 0;
    int m_undoRequest = 0;
    bool m_undoing = false;
    bool m_undoForced = false;
    bool m_undone = false;
    std::vector<autotune::ChangedParameter> m_changed; ///< the refusal's changed parameters
    model::ParameterValues m_driveNow;                 ///< the applied keys as the drive held them at the refusal
};

class AutoTuneWizard : public QWizard {
    Q_OBJECT
public:
    enum PageId { Choice, Run, Result };
    explicit AutoTuneWizard(AppContext& ctx, QWidget* parent = nullptr);

    AutoTuneData& data() { return m_data; }
    AutoTuneChoicePage* choicePage() const { return m_choice; }
    AutoTuneRunPage* runPage() const { return m_run; }
    AutoTuneResultPage* resultPage() const { return m_result; }
    /// Cancel while the sequence runs: aborts it and closes when it has answered (every parameter restored). While an
    /// undo runs: closes when it has answered.
    void reject() override;

private:
    AutoTuneData m_data;
    AutoTuneChoicePage* m_choice = nullptr;
    AutoTuneRunPage* m_run = nullptr;
    AutoTuneResultPage* m_result = nullptr;
    bool m_closeWhenDone = false;
};

} // namespace gui
} // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Pages every wizard shares (DESIGN.md "The GUI": safety check → configure → run with progress and
// Abort → analyse → propose → predict → apply (diff, confirm, read back) → verify → save):
//   SafetyPage   — the axis, what will move, the relevant limits, and a confirmation before motion;
//   TestRunPage  — runs one or more drive tests with progress and Abort; faults end it as aborted;
//   ApplyPage    — the diff of proposed against device values, confirm, write, read back, journal.
// The wizard-specific pages (configure, analyse, propose, verify) live with each wizard.

#include "app/gui/DriveController.h"

#include "core/device/Drive.h"
#include "core/model/Parameter.h"
#include "core/store/Database.h"

#include <QWizardPage>

#include <functional>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace axistune {
namespace gui {

class AppContext;

/// SI value in the parameter's display unit, as text with 6 significant digits.
QString displayParameterValue(const model::ParameterMeta& meta, double si);

/// Asks the connected drive (Drive::capabilities) whether `axis` is a position loop the NC closes with a PID
/// (device::isNcPositionPid: hal:, linuxcnc:), which has no drive velocity loop and no notch slots: the notch and
/// velocity/position wizards then go on with their NcPidPage. `done` gets true and the net the PID output drives,
/// or false when the axis is not such a loop or the drive cannot describe it (the wizard goes on as before); not
/// called when `receiver` is gone.
void checkNcPositionPid(AppContext& ctx, const QString& axis, QObject* receiver,
                        std::function<void(bool ncPid, const QString& outputSignal)> done);

/// The measured frequency response of a saved session, for wizards that start from one.
struct SessionFrf {
    dsp::FrequencyResponse frf;
    QString axis;         ///< the session's axis
    QString captureName;  ///< the capture it came from
};
/// Loads a session and takes its FRF capture named "measured", else its first FRF capture. The error
/// text (translated) names the session and, for an unreadable capture, the capture.
Result<SessionFrf> loadSessionFrf(AppContext& ctx, qint64 sessionId);

class SafetyPage : public QWizardPage {
    Q_OBJECT
public:
    /// Registers the wizard field "axis" (the chosen axis name).
    explicit SafetyPage(AppContext& ctx, QWidget* parent = nullptr);

    /// What will move and how, shown above the confirmation (translated text).
    void setMotionDescription(const QString& text);
    /// Parameters whose values and limits are shown (e.g. velocity limit, torque limit).
    void setLimitKeys(const QStringList& keys);
    /// Restricts the axes offered (empty: every axis of the connected machine).
    void setAxes(const QStringList& axes);

    QString axis() const;
    QCheckBox* confirmation() const { return m_confirm; }
    /// The page after this one (default: the next page id), for wizards that confirm a later motion here.
    void setNextIdFunction(std::function<int()> fn) { m_nextIdFn = std::move(fn); }

    void initializePage() override;
    bool isComplete() const override;
    int nextId() const override { return m_nextIdFn ? m_nextIdFn() : QWizardPage::nextId(); }

private:
    void onReply(const DriveReply& r);
    void showLimits();
    AppContext& m_ctx;
    QStringList m_limitKeys;
    QStringList m_axes;
    QComboBox* m_axis = nullptr;
    QLabel* m_motion = nullptr;
    QLabel* m_state = nullptr;
    QTableWidget* m_limits = nullptr;
    QCheckBox* m_confirm = nullptr;
    int m_metaRequest = 0;
    int m_readRequest = 0;
    std::vector<model::ParameterMeta> m_metas;
    std::function<int()> m_nextIdFn;
};

class TestRunPage : public QWizardPage {
    Q_OBJECT
public:
    explicit TestRunPage(AppContext& ctx, QWidget* parent = nullptr);

    /// Called when the page is entered: the tests to run, in order. Entering the page starts them.
    void setRequestFactory(std::function<std::vector<device::TestRequest>()> factory);
    /// Why the factory yields no request (shown as the failure instead of "Nothing to run.").
    void setEmptyReason(std::function<QString()> reason) { m_emptyReason = std::move(reason); }
    /// How a request is run (default: DriveController::runTest); e.g. the FRF wizard's adaptive multisine.
    void setRunner(std::function<DriveRequest*(const device::TestRequest&)> runner) { m_runner = std::move(runner); }

    bool isRunning() const { return m_running; }
    bool succeeded() const { return m_succeeded; }
    /// Why the run failed (empty when it succeeded); ErrorCode::Aborted for a user abort.
    QString failure() const { return m_failure; }
    ErrorCode failureCode() const { return m_failureCode; }
    /// One reply per completed test, in order.
    const std::vector<DriveReply>& replies() const { return m_replies; }
    QPushButton* abortButton() const { return m_abort; }
    QPushButton* retryButton() const { return m_retry; }

    void initializePage() override;
    void cleanupPage() override;  ///< going back aborts a running test
    bool isComplete() const override;

public slots:
    void start();
    void abortRun();

signals:
    /// Emitted once per run: ok, or not with failure()/failureCode() set.
    void runFinished(bool ok);

private:
    void next();
    void finish(bool ok, const QString& why, ErrorCode code);
    void onReply(const axistune::gui::DriveReply& r);

    AppContext& m_ctx;
    std::function<std::vector<device::TestRequest>()> m_factory;
    std::function<QString()> m_emptyReason;
    std::function<DriveRequest*(const device::TestRequest&)> m_runner;
    std::vector<device::TestRequest> m_requests;
    std::vector<DriveReply> m_replies;
    std::size_t m_index = 0;
    int m_request = 0;
    bool m_running = false;
    bool m_succeeded = false;
    QString m_failure;
    ErrorCode m_failureCode = ErrorCode::Internal;
    QLabel* m_label = nullptr;
    QProgressBar* m_bar = nullptr;
    QPushButton* m_abort = nullptr;
    QPushButton* m_retry = nullptr;
    QPlainTextEdit* m_log = nullptr;
};

class ApplyPage : public QWizardPage {
    Q_OBJECT
public:
    explicit ApplyPage(AppContext& ctx, QWidget* parent = nullptr);

    /// The proposal, set by the wizard before the page is shown (values in SI).
    void setProposal(const QString& axis, const model::ParameterValues& proposed);

    bool applied() const { return m_applied; }
    /// The device values before the write (for a restore and the journal).
    const model::ParameterValues& previousValues() const { return m_previous; }
    /// The values read back after the write.
    const model::ParameterValues& readBack() const { return m_readBack; }
    /// One entry per written key and write (old → read-back), restores included, for the session record.
    std::vector<store::JournalEntry> journal() const;

    QCheckBox* confirmation() const { return m_confirm; }
    QCheckBox* skipCheck() const { return m_skip; }
    QPushButton* applyButton() const { return m_apply; }
    QPushButton* restoreButton() const { return m_restore; }
    QTableWidget* diffTable() const { return m_table; }

    void initializePage() override;
    bool isComplete() const override;

public slots:
    void apply();
    /// Writes the previous values back (after a bad verification, for example).
    void restore();

signals:
    void appliedChanged(bool applied);
    /// restore() was refused or the link failed; the applied values may still be active.
    void restoreFailed(const QString& error);

private:
    void fillTable();
    void onReply(const axistune::gui::DriveReply& r);
    void addJournal(const model::ParameterValues& before, const model::ParameterValues& after);

    AppContext& m_ctx;
    QString m_axis;
    std::vector<store::JournalEntry> m_journal;
    model::ParameterValues m_proposed;
    model::ParameterValues m_previous;
    model::ParameterValues m_readBack;
    std::vector<model::ParameterMeta> m_metas;
    bool m_applied = false;
    int m_metaRequest = 0;
    int m_readRequest = 0;
    int m_writeRequest = 0;
    int m_restoreRequest = 0;
    QLabel* m_status = nullptr;
    QTableWidget* m_table = nullptr;
    QCheckBox* m_confirm = nullptr;
    QCheckBox* m_skip = nullptr;
    QPushButton* m_apply = nullptr;
    QPushButton* m_restore = nullptr;
};

}  // namespace gui
}  // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The page the velocity/position and notch wizards show for a position loop the NC closes with a PID (hal:,
// linuxcnc:; docs/linuxcnc.md "The wizards on hal:"): it measures the open loop with the gains that run, proposes
// (core/autotune/PidTune.h: P, I, D, FF1, FF2 and LinuxCNC's biquad notch, or a notch alone for the running gains)
// with the rule behind each number and the predicted margins, applies and verifies by measuring again (a loop that
// misses the margins gets back what ran before), offers Undo, and saves the session.

#include "app/gui/DriveController.h"
#include "core/autotune/PidTune.h"
#include "core/store/Database.h"

#include <QPointer>
#include <QWizardPage>

#include <memory>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace axistune::widgets {
class BodePlot;
}

namespace axistune {
namespace gui {

class AppContext;

class NcPidPage : public QWizardPage {
    Q_OBJECT
public:
    NcPidPage(AppContext& ctx, autotune::PidTuneScope scope, QWidget* parent = nullptr);
    ~NcPidPage() override;

    /// The axis chosen when the page opens (a pid instance on hal:, an axis name on linuxcnc:); the page's own list
    /// offers the connection's axes.
    void setAxis(const QString& axis) { m_axis = axis; }
    QString axis() const { return m_axis; }

    void initializePage() override;
    void cleanupPage() override; ///< going back aborts a running measurement
    bool isComplete() const override;
    int nextId() const override { return -1; }

    // For tests.
    QPushButton* measureButton() const { return m_measure; }
    QPushButton* applyButton() const { return m_apply; }
    QPushButton* undoButton() const { return m_undo; }
    QPushButton* undoAnywayButton() const { return m_undoAnyway; }
    QCheckBox* overwriteBox() const { return m_overwrite; }
    QPushButton* abortButton() const { return m_abort; }
    QCheckBox* confirmation() const { return m_confirm; }
    QDoubleSpinBox* amplitudeBox() const { return m_amplitude; }
    QTableWidget* table() const { return m_table; }
    QLabel* status() const { return m_status; }
    widgets::BodePlot* plot() const { return m_plot; }
    bool busy() const { return static_cast<bool>(m_request); }
    const autotune::PidLoopMeasurement* measurement() const { return m_measured.get(); }
    const autotune::PidTuneProposal* proposal() const { return m_proposal.get(); }
    const autotune::PidTuneApplied* applied() const { return m_applied.get(); }
    bool undone() const { return m_undone; }
    /// The session of the last save (one after each measurement, apply and undo), once the store has answered.
    qint64 savedSessionId() const { return m_sessionId; }
    int pendingSaves() const { return m_pendingSaves; }

public slots:
    void measure();
    void applyProposal();
    void undo();
    void undoAnyway(); ///< after a refused Undo: overwrites what changed since the apply (the box ticked first)
    void abortRun();

private:
    autotune::PidTuneRequest request() const;
    void onMeasured(const DriveReply& r);
    void onApplied(const DriveReply& r);
    void onUndone(const DriveReply& r);
    void startUndo(bool force);
    void track(DriveRequest* r);
    void showTable();
    void showPlot();
    void setStatus(const QString& text, bool error = false);
    void updateButtons();
    void saveSession(const QString& note, store::SessionStatus status);
    void showIntro();
    void clearResult(); ///< forgets the measurement, proposal and apply shown

    AppContext& m_ctx;
    autotune::PidTuneScope m_scope;
    QString m_axis;
    QLabel* m_intro = nullptr;
    QComboBox* m_axisBox = nullptr;
    QDoubleSpinBox* m_amplitude = nullptr;
    QComboBox* m_input = nullptr;
    QDoubleSpinBox* m_pm = nullptr;
    QDoubleSpinBox* m_gm = nullptr;
    QCheckBox* m_notch = nullptr;
    QCheckBox* m_confirm = nullptr;
    QPushButton* m_measure = nullptr;
    QPushButton* m_apply = nullptr;
    QPushButton* m_undo = nullptr;
    QPushButton* m_undoAnyway = nullptr;
    QCheckBox* m_overwrite = nullptr;
    QPushButton* m_abort = nullptr;
    QProgressBar* m_bar = nullptr;
    QLabel* m_status = nullptr;
    QTableWidget* m_table = nullptr;
    widgets::BodePlot* m_plot = nullptr;
    QPointer<DriveRequest> m_request;
    autotune::PidTuneRequest m_asked; ///< the request of the measurement shown
    std::shared_ptr<const autotune::PidLoopMeasurement> m_measured;
    std::shared_ptr<const autotune::PidTuneProposal> m_proposal;
    std::shared_ptr<const autotune::PidTuneApplied> m_applied;
    bool m_undone = false;
    bool m_undoRefused = false; ///< the last Undo was refused because HAL no longer holds what was applied
    bool m_undoForced = false;
    /// The undo's writes (autotune::pidTuneUndoWrites): from what HAL held just before it to what it put back.
    std::vector<autotune::PidTuneWrite> m_undoWrites;
    qint64 m_sessionId = 0;
    int m_pendingSaves = 0;
};

} // namespace gui
} // namespace axistune

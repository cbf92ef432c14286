// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Velocity/position-loop wizard (issue 9 item 2; spec/lost-motion-and-two-inertia.md §2.8, TI-5,
// §4.11–4.12; docs/wizards/velocity-loop.md): the velocity PI from the fitted inertia (chapter 5 rule,
// K_P = k√2·ω_l·J_m, K_I = k·ω_l²·J_m) or from margins on a measured response (crossover and phase
// margin), the predicted open and closed loop with their margins, the position gain with its stability
// limit, and a velocity step on the drive before and after applying, overlaid with the prediction
// (core/tuning VelocityLoop, VelocityStep) → apply velocity.kp / velocity.ki / position.kp → save
// (session kind "velocity-loop").

#include "app/gui/TuningWizard.h"
#include "core/dsp/FrequencyResponse.h"
#include "core/model/Capture.h"
#include "core/tuning/TwoInertia.h"
#include "core/tuning/VelocityLoop.h"
#include "core/tuning/VelocityLoopDesign.h"
#include "core/tuning/VelocityStep.h"

#include <QWizardPage>

#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QRadioButton;
class QTableWidget;

namespace axistune {
namespace widgets {
class BodePlot;
class CurvePlot;
} // namespace widgets
namespace gui {

class AppContext;
class ApplyPage;
class NcPidPage;
class SafetyPage;
class TestRunPage;

struct VelocityLoopData {
    enum class Method { Inertia, Frf };
    enum class FrfSource { Measure, Session };
    Method method = Method::Inertia;
    FrfSource frfSource = FrfSource::Measure;
    /// The verification step tests the velocity loop only: the position gain is applied only on request.
    bool applyPositionGain = false;
    QString axis;
    // Inertia rule.
    double jmKgm2 = 1e-3;
    double omegaLHz = 24.0; ///< ω_l/2π
    double k = 10.0;
    qint64 modelSession = 0;                       ///< two-inertia session the model came from (0: entered)
    std::optional<tuning::TwoInertiaParams> model; ///< the fitted model of that session
    // Margins.
    double crossoverHz = 40.0;
    double phaseMarginDeg = 50.0;
    double fminHz = 5.0, fmaxHz = 500.0, amplitudePct = 5.0;
    int points = 50;
    qint64 frfSession = 0;
    std::optional<dsp::FrequencyResponse> measured; ///< as measured (closed loop when "complementary")
    std::optional<dsp::FrequencyResponse> plant;    ///< torque → motor velocity
    // Loop as found on the drive.
    tuning::VelocityPi before{1.0, 50.0};
    double positionKpBefore = 0.0;
    double velocityPeriodS = 250e-6, currentPeriodS = 62.5e-6;
    // Step test.
    double stepRadS = 10.0, stepDurationS = 0.2;
    std::shared_ptr<const model::Capture> stepBefore, stepAfter;
    // Proposal and prediction (core's design; the fields below are its copies for the pages and the session).
    std::optional<tuning::VelocityLoopDesign> design;
    tuning::VelocityPi proposed;
    QString rule;
    QString error;
    tuning::LoopMargins marginsBefore, marginsAfter;
    tuning::PositionGainDesign position;
    std::vector<double> fHz;
    std::vector<std::complex<double>> openLoop, closedLoop;
    std::optional<tuning::VelocityStepPrediction> predictedBefore, predictedAfter;
};

class VelocityLoopSourcePage : public QWizardPage {
    Q_OBJECT
public:
    VelocityLoopSourcePage(AppContext& ctx, VelocityLoopData& data, QWidget* parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    bool validatePage() override;
    int nextId() const override;
    QComboBox* modelSessions() const { return m_modelSessions; }
    QComboBox* frfSessions() const { return m_frfSessions; }
    QDoubleSpinBox* inertia() const { return m_jm; }
    QDoubleSpinBox* bandwidth() const { return m_wl; }
    QDoubleSpinBox* gainFactor() const { return m_k; }
    /// The chosen axis is a position loop the NC closes with a PID (hal:, linuxcnc:): Next goes to the wizard's
    /// NcPidPage, which tunes its P, I, D, FF1, FF2 and notch instead of a drive velocity loop.
    bool ncPid() const { return m_ncPid; }
    /// What the page says about such an axis (empty otherwise).
    QString ncPidNote() const;
    void setNcPidPage(NcPidPage* page) { m_ncPidPage = page; }

private:
    void modelSessionChosen();
    void checkAxis();
    AppContext& m_ctx;
    VelocityLoopData& m_d;
    QComboBox* m_axis = nullptr;
    QLabel* m_ncPidLabel = nullptr; ///< what happens to a position PID the NC closes (hal:, linuxcnc:)
    QList<QWidget*> m_choices;      ///< the rule and data groups (disabled for a PID the NC closes)
    bool m_checking = false;        ///< asking the drive what the axis is
    bool m_ncPid = false;
    NcPidPage* m_ncPidPage = nullptr;
    QRadioButton* m_inertiaMethod = nullptr;
    QRadioButton* m_frfMethod = nullptr;
    QComboBox* m_modelSessions = nullptr;
    QDoubleSpinBox* m_jm = nullptr;
    QDoubleSpinBox* m_wl = nullptr;
    QDoubleSpinBox* m_k = nullptr;
    QRadioButton* m_measure = nullptr;
    QRadioButton* m_session = nullptr;
    QComboBox* m_frfSessions = nullptr;
    QDoubleSpinBox* m_crossover = nullptr;
    QDoubleSpinBox* m_pm = nullptr;
    QDoubleSpinBox* m_step = nullptr;
    QLabel* m_note = nullptr;
};

/// The proposal with its rule, Bode of the open and closed loop, margins, position gain, step prediction.
class VelocityLoopDesignPage : public QWizardPage {
    Q_OBJECT
public:
    VelocityLoopDesignPage(AppContext& ctx, VelocityLoopData& data, TestRunPage* run, ApplyPage* apply,
                           QWidget* parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    int nextId() const override;
    QTableWidget* table() const { return m_table; }
    bool isBusy() const { return m_readRequest != 0; }

private:
    void analyse();
    /// The proposal handed to the apply page: the PI, and the position gain when its box is ticked.
    void updateProposal();
    AppContext& m_ctx;
    VelocityLoopData& m_d;
    TestRunPage* m_run;
    ApplyPage* m_apply;
    QCheckBox* m_applyPositionGain = nullptr;
    widgets::BodePlot* m_bode = nullptr;
    widgets::CurvePlot* m_step = nullptr;
    QTableWidget* m_table = nullptr;
    QLabel* m_status = nullptr;
    int m_readRequest = 0;
    bool m_done = false;
};

class VelocityLoopVerifyPage : public QWizardPage {
    Q_OBJECT
public:
    VelocityLoopVerifyPage(VelocityLoopData& data, TestRunPage* run, QWidget* parent = nullptr);
    void initializePage() override;
    widgets::CurvePlot* plot() const { return m_plot; }

private:
    VelocityLoopData& m_d;
    TestRunPage* m_run;
    widgets::CurvePlot* m_plot = nullptr;
    QLabel* m_text = nullptr;
};

class VelocityLoopSavePage : public QWizardPage {
    Q_OBJECT
public:
    VelocityLoopSavePage(AppContext& ctx, VelocityLoopData& data, ApplyPage* apply, QWidget* parent = nullptr);
    void initializePage() override;

private:
    AppContext& m_ctx;
    VelocityLoopData& m_d;
    ApplyPage* m_apply;
    QLabel* m_text = nullptr;
};

class VelocityLoopWizard : public TuningWizard {
    Q_OBJECT
public:
    enum PageId { Source, Safety, Run, Design, Apply, VerifyRun, Verify, Save, NcPid };

    explicit VelocityLoopWizard(AppContext& ctx, QWidget* parent = nullptr);

    VelocityLoopData& data() { return m_data; }
    VelocityLoopSourcePage* sourcePage() const { return m_source; }
    SafetyPage* safetyPage() const { return m_safety; }
    TestRunPage* runPage() const { return m_run; }
    VelocityLoopDesignPage* designPage() const { return m_design; }
    ApplyPage* applyPage() const { return m_apply; }
    TestRunPage* verifyRunPage() const { return m_verifyRun; }
    NcPidPage* ncPidPage() const { return m_ncPid; }

    /// Saves the session (Completed, or Aborted with the reason and whatever was measured).
    void saveSession(bool aborted, const QString& reason) override;

private:
    AppContext& m_ctx;
    VelocityLoopData m_data;
    VelocityLoopSourcePage* m_source = nullptr;
    SafetyPage* m_safety = nullptr;
    TestRunPage* m_run = nullptr;
    VelocityLoopDesignPage* m_design = nullptr;
    ApplyPage* m_apply = nullptr;
    TestRunPage* m_verifyRun = nullptr;
    NcPidPage* m_ncPid = nullptr;
};

} // namespace gui
} // namespace axistune

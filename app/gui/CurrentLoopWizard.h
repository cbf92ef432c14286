// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Current-loop wizard (issue 9 item 1; spec/current-loop-and-multisweep-frf.md chapter 2;
// docs/wizards/current-loop.md): motor data entered or read from the drive's read-only motor
// parameters, with the back-EMF check at the contouring speed → the design of core/tuning CurrentLoop
// (α sweep; per α the optimum under dead-time stability, voltage envelope and overshoot limit) shown
// in the k_p–k_i plane, rise time against α, the gain schedule over current → step responses
// (delay-free design, delay-inclusive prediction at the drive's period and dead time) → safety → a
// current step measured on the drive with its present gains (TestType::CurrentStep, progress and Abort)
// → apply current.kp / current.ki / current.alpha → the same step again → verify (read back; measured
// step over the design and the prediction with the read-back gains, rise time and overshoot of each, the
// difference; the step before for comparison) → save (session kind "current-loop", the measured steps as
// captures "current_step" and "current_step_before").

#include "app/gui/DriveController.h"
#include "app/gui/TuningWizard.h"
#include "core/model/Capture.h"
#include "core/tuning/CurrentLoop.h"
#include "core/tuning/CurrentStep.h"
#include "core/tuning/VelocityLoopDesign.h"

#include <QWizardPage>

#include <memory>
#include <numbers>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace axistune {
namespace widgets {
class CurvePlot;
} // namespace widgets
namespace gui {

class AppContext;
class ApplyPage;
class SafetyPage;
class TestRunPage;

/// Line-to-line rms volts per 1000 min⁻¹ from the q-axis peak constant [V·s/rad] (core/tuning/VelocityLoopDesign.h).
using tuning::kKeToVPerKrpm;

struct CurrentLoopData {
    QString axis;
    bool fromDrive = false;
    bool fromProfile = false;  ///< some motor data taken from the machine profile's motor model
    tuning::MotorData motor;
    tuning::CurrentLoopSettings settings;
    double drivePeriodS = 62.5e-6;   ///< current.period of the drive (discrete prediction)
    double driveDeadTimeS = 62.5e-6; ///< current.dead_time of the drive (delay-inclusive prediction)
    QString backEmfText;             ///< the back-EMF check in words with the numbers
    bool backEmfOk = true;
    // Design (computed off the GUI thread).
    std::optional<tuning::CurrentLoopDesign> design;
    QString error;
    tuning::BoundaryCurve stability;
    std::vector<tuning::BoundaryCurve> voltage;   ///< per design.table row
    std::vector<tuning::BoundaryCurve> overshoot; ///< per design.table row
    int chosenRow = -1;                           ///< row of design.table chosen (default: the optimum)
    tuning::StepResponse step;                    ///< for the chosen row, at the drive's period
    std::vector<double> fineTimeS, fineDelayFree; ///< delay-free step on a fine grid (400 points)
    // Verification (read back after apply).
    bool verified = false;
    double readKp = 0.0, readKi = 0.0, readAlpha = 0.0;
    tuning::StepResponse verifyStep;
    double verifyOvershoot = 0.0, verifyRiseS = 0.0;
    // The current step measured on the drive (TestType::CurrentStep).
    bool measure = true;          ///< measure a current step after apply
    double stepAmplitudeA = 0.0;  ///< step of the q-axis current command [A]
    double stepRecordS = 0.0;     ///< recording length [s] (the step comes 10 % in)
    std::shared_ptr<const model::Capture> measuredCapture;
    std::optional<tuning::MeasuredCurrentStep> measured;
    std::shared_ptr<const model::Capture> beforeCapture;  ///< the same step before applying (present gains)
    std::optional<tuning::MeasuredCurrentStep> before;
    tuning::StepFigures beforeFigures;
    QString measureError;         ///< why there is no measured step (empty when there is one)
    tuning::StepResponse measuredPrediction;  ///< prediction with the read-back gains on the measured grid
    tuning::StepFigures measuredFigures, designFigures, predictedFigures;
    tuning::StepDifference difference;        ///< measured − delay-inclusive prediction (normalised)
    QString measuredVerdict;

    const tuning::AlphaOptimum* chosen() const
    {
        return design && chosenRow >= 0 && chosenRow < int(design->table.size()) ? &design->table[chosenRow] : nullptr;
    }
};

/// Motor data and design settings; "Read from drive" fills them from the axis's parameters.
class CurrentLoopMotorPage : public QWizardPage {
    Q_OBJECT
public:
    CurrentLoopMotorPage(AppContext& ctx, CurrentLoopData& data, QWidget* parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    bool validatePage() override;
    QPushButton* readButton() const { return m_read; }
    QPushButton* profileButton() const { return m_fromProfile; }
    QComboBox* axisBox() const { return m_axis; }
    bool isReading() const { return m_readRequest != 0; }
    void setMotor(const tuning::MotorData& m);

public slots:
    void readFromDrive();
    /// Fills the fields the machine profile's "motor" model of the axis holds (docs/formats-profile.md).
    void takeFromProfile();

private:
    void updateCheck();
    tuning::MotorData motorFromFields() const;
    AppContext& m_ctx;
    CurrentLoopData& m_d;
    QComboBox* m_axis = nullptr;
    QPushButton* m_read = nullptr;
    QPushButton* m_fromProfile = nullptr;
    QDoubleSpinBox* m_r = nullptr;
    QDoubleSpinBox* m_l = nullptr;
    QDoubleSpinBox* m_imax = nullptr;
    QDoubleSpinBox* m_vmax = nullptr;
    QDoubleSpinBox* m_delta = nullptr;
    QDoubleSpinBox* m_rated = nullptr;
    QDoubleSpinBox* m_emf = nullptr;
    QDoubleSpinBox* m_speed = nullptr;
    QDoubleSpinBox* m_tau = nullptr;
    QDoubleSpinBox* m_gm = nullptr;
    QDoubleSpinBox* m_os = nullptr;
    QDoubleSpinBox* m_ripple = nullptr;
    QLabel* m_check = nullptr;
    QLabel* m_source = nullptr;
    int m_readRequest = 0;
};

/// The k_p–k_i plane, rise time against α, the α table and the gain schedule.
class CurrentLoopDesignPage : public QWizardPage {
    Q_OBJECT
public:
    CurrentLoopDesignPage(AppContext& ctx, CurrentLoopData& data, QWidget* parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    bool validatePage() override;
    QComboBox* alphaBox() const { return m_alpha; }
    QCheckBox* allAlphas() const { return m_all; }
    widgets::CurvePlot* planePlot() const { return m_plane; }
    QTableWidget* table() const { return m_table; }
    bool isBusy() const { return m_busy; }

private:
    void showDesign();
    void drawPlane();
    AppContext& m_ctx;
    CurrentLoopData& m_d;
    widgets::CurvePlot* m_plane = nullptr;
    widgets::CurvePlot* m_rise = nullptr;
    widgets::CurvePlot* m_schedule = nullptr;
    QTableWidget* m_table = nullptr;
    QTableWidget* m_scheduleTable = nullptr;
    QComboBox* m_alpha = nullptr;
    QCheckBox* m_all = nullptr;
    QLabel* m_status = nullptr;
    bool m_busy = false;
};

/// Step responses: delay-free design against the delay-inclusive prediction.
class CurrentLoopStepPage : public QWizardPage {
    Q_OBJECT
public:
    CurrentLoopStepPage(AppContext& ctx, CurrentLoopData& data, ApplyPage* apply, QWidget* parent = nullptr);
    void initializePage() override;
    int nextId() const override;
    bool validatePage() override;
    widgets::CurvePlot* plot() const { return m_plot; }
    QCheckBox* measureCheck() const { return m_measure; }
    QDoubleSpinBox* amplitudeSpin() const { return m_amp; }
    QDoubleSpinBox* recordSpin() const { return m_record; }

    /// Default step: the largest whose voltage before the current responds, (α k_p + (d + 1) k_i T)·i* with d
    /// dead-time periods, stays within 80 % of V_max, at most 10 % of I_max (linear loop, small inductance drop).
    static double defaultStepAmplitude(const CurrentLoopData& d);

private:
    AppContext& m_ctx;
    CurrentLoopData& m_d;
    ApplyPage* m_apply;
    widgets::CurvePlot* m_plot = nullptr;
    QLabel* m_text = nullptr;
    QWidget* m_measureBox = nullptr;
    QCheckBox* m_measure = nullptr;
    QDoubleSpinBox* m_amp = nullptr;
    QDoubleSpinBox* m_record = nullptr;
    QLabel* m_measureNote = nullptr;
    /// The drive's limits of a current step (DriveController::describeAxis), read when the page opens.
    void showLimits(const DriveReply& reply);
    int m_limitsRequest = -1;
    std::optional<device::DriveLimits> m_limits;
    QString m_noteDefault;
};

/// Read back after apply and the prediction with the read-back gains.
class CurrentLoopVerifyPage : public QWizardPage {
    Q_OBJECT
public:
    CurrentLoopVerifyPage(AppContext& ctx, CurrentLoopData& data, ApplyPage* apply, QWidget* parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    widgets::CurvePlot* plot() const { return m_plot; }

private:
    void showResult();
    /// The measured step against the prediction with the read-back gains; returns the text.
    QString compareMeasured();
    AppContext& m_ctx;
    CurrentLoopData& m_d;
    ApplyPage* m_apply;
    widgets::CurvePlot* m_plot = nullptr;
    QLabel* m_text = nullptr;
    int m_readRequest = 0;
};

class CurrentLoopSavePage : public QWizardPage {
    Q_OBJECT
public:
    CurrentLoopSavePage(AppContext& ctx, CurrentLoopData& data, ApplyPage* apply, QWidget* parent = nullptr);
    void initializePage() override;

private:
    AppContext& m_ctx;
    CurrentLoopData& m_d;
    ApplyPage* m_apply;
    QLabel* m_text = nullptr;
};

class CurrentLoopWizard : public TuningWizard {
    Q_OBJECT
public:
    enum PageId { Motor, Design, Step, Safety, BeforeRun, Apply, MeasureRun, Verify, Save };

    explicit CurrentLoopWizard(AppContext& ctx, QWidget* parent = nullptr);

    CurrentLoopData& data() { return m_data; }
    CurrentLoopMotorPage* motorPage() const { return m_motor; }
    CurrentLoopDesignPage* designPage() const { return m_design; }
    ApplyPage* applyPage() const { return m_apply; }
    SafetyPage* safetyPage() const { return m_safety; }
    TestRunPage* runPage() const { return m_run; }
    TestRunPage* beforeRunPage() const { return m_beforeRun; }

    /// Saves the session (Completed, or Aborted with the reason and whatever was measured).
    void saveSession(bool aborted = false, const QString& reason = {}) override;
    int nextId() const override;

private:
    AppContext& m_ctx;
    CurrentLoopData m_data;
    CurrentLoopMotorPage* m_motor = nullptr;
    CurrentLoopDesignPage* m_design = nullptr;
    ApplyPage* m_apply = nullptr;
    SafetyPage* m_safety = nullptr;
    TestRunPage* m_run = nullptr;
    TestRunPage* m_beforeRun = nullptr;
};

} // namespace gui
} // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Two-inertia wizard (issue 9 item 4; spec/lost-motion-and-two-inertia.md chapter 5 and W-TI §4.14;
// docs/wizards/two-inertia.md): the low-frequency response measured on the drive (closed velocity
// loop, converted to the plant with the loop's PI) or taken from a saved session → two-inertia fit
// (core/tuning TwoInertia) drawn over it with its residual, anti-resonance and resonance → F_m / F_L
// settings and the predicted load error of an acceleration profile with and without the filter → a jog
// with the profile before the change (the measured "without") → apply (the filter suppression.*, mode
// from the axis's position.feedback, with the velocity PI of the thesis rule TI-5 on the fitted J_m and
// the feedforwards TI-3 needs) → verify with the same profile (measured load error y_L − y* against the
// prediction with and without the filter; load − motor against the prediction from the measured motor
// motion) → save (session kind "two-inertia", model kind "two_inertia").

#include "app/gui/TuningWizard.h"
#include "app/gui/DriveController.h"
#include "core/dsp/FrequencyResponse.h"
#include "core/tuning/TwoInertia.h"
#include "core/tuning/TwoInertiaFilter.h"
#include "core/tuning/TwoInertiaPrediction.h"
#include "core/tuning/VelocityLoop.h"

#include <QWizardPage>

#include <memory>
#include <optional>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QRadioButton;
class QSpinBox;
class QTableWidget;

namespace axistune {
namespace widgets {
class BodePlot;
class CurvePlot;
}  // namespace widgets
namespace gui {

class AppContext;
class ApplyPage;
class SafetyPage;
class TestRunPage;

struct TwoInertiaData {
    bool fromSession = false;
    qint64 sourceSession = 0;
    QString axis;
    double fminHz = 5.0, fmaxHz = 300.0;
    int points = 60;
    double amplitudePct = 5.0;
    tuning::TwoInertiaFitOptions fitOptions;
    // The velocity loop the response was measured in (for T → P).
    tuning::VelocityPi loopPi{11.24, 1198.0};
    double velocityPeriodS = 250e-6, currentPeriodS = 62.5e-6;
    std::optional<dsp::FrequencyResponse> measured;  ///< as measured (T, or P when not complementary)
    std::optional<dsp::FrequencyResponse> plant;     ///< torque → motor velocity
    std::optional<tuning::TwoInertiaFit> fit;
    QString error;
    tuning::SuppressionFilter filter;
    double tauS = 0.0;  ///< F_L τ as entered (0: default rule)
    tuning::MotionProfile profile;
    tuning::LoadErrorTraces loadError;
    tuning::VelocityPi proposedPi;
    int feedback = -1;                 ///< the axis's position.feedback (0 semi, 1 full), -1 unknown
    /// The axis has the linear axes' parameters (lostmotion.*): the profile, given in motor revolutions, is
    /// not run there (its units would be read as metres).
    bool linearAxis = false;
    model::ParameterValues proposal;   ///< what the apply page writes (SI)
    // Verification (jog of the profile's speed and acceleration).
    std::shared_ptr<const model::Capture> jog;
    std::vector<double> verifyT, measuredTwist, predictedTwist;
    double measuredMaxTwist = 0.0, predictedMaxTwist = 0.0, idealMaxTwist = 0.0;
    // Load error y_L − y* of the profile: measured before the apply (the drive's settings then) and
    // after it (with the filter), predicted under ideal motor tracking without and with F_m.
    std::shared_ptr<const model::Capture> beforeJog;
    tuning::MeasuredLoadError loadBefore, loadAfter;
    double predictedLoadWithout = 0.0, predictedLoadWith = 0.0;
};

/// The jog of the profile: one S-curve move (v_max, a_max, jerk) with profile.cruiseS at v_max, a dwell
/// of profile.settleS before and after.
device::TestRequest profileJog(const QString& axis, const tuning::MotionProfile& profile);

class TwoInertiaSourcePage : public QWizardPage {
    Q_OBJECT
public:
    TwoInertiaSourcePage(AppContext& ctx, TwoInertiaData& data, QWidget* parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    bool validatePage() override;
    int nextId() const override;
    QComboBox* sessions() const { return m_sessions; }

private:
    AppContext& m_ctx;
    TwoInertiaData& m_d;
    QRadioButton* m_measure = nullptr;
    QRadioButton* m_session = nullptr;
    QComboBox* m_sessions = nullptr;
    QDoubleSpinBox* m_fmin = nullptr;
    QDoubleSpinBox* m_fmax = nullptr;
    QSpinBox* m_points = nullptr;
    QDoubleSpinBox* m_amplitude = nullptr;
    QDoubleSpinBox* m_kp = nullptr;
    QDoubleSpinBox* m_ki = nullptr;
    QLabel* m_note = nullptr;
};

/// Fit, Bode overlay, residual, anti-resonance / resonance table.
class TwoInertiaFitPage : public QWizardPage {
    Q_OBJECT
public:
    TwoInertiaFitPage(AppContext& ctx, TwoInertiaData& data, TestRunPage* run, QWidget* parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    QTableWidget* table() const { return m_table; }

private:
    void analyse();
    void showResults();
    AppContext& m_ctx;
    TwoInertiaData& m_d;
    TestRunPage* m_run;
    widgets::BodePlot* m_bode = nullptr;
    widgets::CurvePlot* m_residual = nullptr;
    QTableWidget* m_table = nullptr;
    QLabel* m_status = nullptr;
    int m_readRequest = 0;
    bool m_busy = false;
};

/// F_m / F_L settings, predicted load error with and without the filter, the velocity-PI proposal.
class TwoInertiaFilterPage : public QWizardPage {
    Q_OBJECT
public:
    TwoInertiaFilterPage(AppContext& ctx, TwoInertiaData& data, ApplyPage* apply, QWidget* parent = nullptr);
    void initializePage() override;
    bool isComplete() const override;
    int nextId() const override;
    QComboBox* mode() const { return m_mode; }

private:
    void update();
    AppContext& m_ctx;
    TwoInertiaData& m_d;
    ApplyPage* m_apply;
    int m_readRequest = 0;
    QComboBox* m_mode = nullptr;
    QDoubleSpinBox* m_tau = nullptr;
    QDoubleSpinBox* m_vmax = nullptr;
    QDoubleSpinBox* m_accel = nullptr;
    QDoubleSpinBox* m_jerk = nullptr;
    QTableWidget* m_table = nullptr;
    widgets::CurvePlot* m_plot = nullptr;
    QLabel* m_result = nullptr;
};

class TwoInertiaVerifyPage : public QWizardPage {
    Q_OBJECT
public:
    TwoInertiaVerifyPage(TwoInertiaData& data, TestRunPage* before, TestRunPage* run, QWidget* parent = nullptr);
    void initializePage() override;

private:
    void loadError();
    TwoInertiaData& m_d;
    TestRunPage* m_before;
    TestRunPage* m_run;
    widgets::CurvePlot* m_plot = nullptr;
    QLabel* m_result = nullptr;
};

class TwoInertiaSavePage : public QWizardPage {
    Q_OBJECT
public:
    TwoInertiaSavePage(AppContext& ctx, TwoInertiaData& data, ApplyPage* apply, QWidget* parent = nullptr);
    void initializePage() override;

private:
    AppContext& m_ctx;
    TwoInertiaData& m_d;
    ApplyPage* m_apply;
    QLabel* m_text = nullptr;
};

class TwoInertiaWizard : public TuningWizard {
    Q_OBJECT
public:
    enum PageId { Source, Safety, Run, Fit, Filter, BeforeRun, Apply, VerifyRun, Verify, Save };

    explicit TwoInertiaWizard(AppContext& ctx, QWidget* parent = nullptr);

    TwoInertiaData& data() { return m_data; }
    TwoInertiaSourcePage* sourcePage() const { return m_source; }
    SafetyPage* safetyPage() const { return m_safety; }
    TestRunPage* runPage() const { return m_run; }
    TwoInertiaFitPage* fitPage() const { return m_fit; }
    TwoInertiaFilterPage* filterPage() const { return m_filter; }
    TestRunPage* beforeRunPage() const { return m_beforeRun; }
    ApplyPage* applyPage() const { return m_apply; }
    TestRunPage* verifyRunPage() const { return m_verifyRun; }

    /// Saves the session (Completed, or Aborted with the reason and whatever was measured).
    void saveSession(bool aborted, const QString& reason) override;

private:
    AppContext& m_ctx;
    TwoInertiaData m_data;
    TwoInertiaSourcePage* m_source = nullptr;
    SafetyPage* m_safety = nullptr;
    TestRunPage* m_run = nullptr;
    TwoInertiaFitPage* m_fit = nullptr;
    TwoInertiaFilterPage* m_filter = nullptr;
    TestRunPage* m_beforeRun = nullptr;
    ApplyPage* m_apply = nullptr;
    TestRunPage* m_verifyRun = nullptr;
};

}  // namespace gui
}  // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The frequency-response wizard (issue 8 item 4, docs/wizards/frf.md):
//   1. safety   — axis, the limits that matter for a torque injection, the excitation amplitude in %
//                 of rated torque (refused above the drive's own limit, Drive::limits), confirmation;
//   2. method   — multi-sweep sine stream (default), conventional sine stream, PRBS with Welch,
//                 multisine, band fmin..fmax and points, estimated motion time
//                 (the drive's own plan, DriveController::planTest → Drive::planTest);
//   3. run      — one device::TestRequest of type Frf on the shared TestRunPage (progress, Abort);
//   4. result   — Bode plot of the measured closed loop with coherence, the validity bands
//                 ("valid only by multi-sweep" fs/2..fs, "not measurable" at invalid points and above
//                 fs) and the resonances of the open loop (tuning::findResonances) as table and markers;
//   5. save     — the session (kind "frf"): inputs, the FRF as capture "measured", the resonances.
// A run that fails (Abort, lost connection, drive fault) is saved at once as Aborted with the reason.

#include "app/gui/WizardPages.h"

#include "core/device/Drive.h"
#include "core/dsp/FrequencyResponse.h"
#include "core/tuning/Resonance.h"

#include <QFutureWatcher>
#include <QWizard>
#include <QWizardPage>

#include <cstdint>
#include <optional>
#include <vector>
#include <nlohmann/json_fwd.hpp>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QCheckBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace axistune {
namespace widgets {
class BodePlot;
}
namespace gui {

class AppContext;

/// The drive values the FRF pages need (SI), read once per axis.
struct FrfDriveInfo {
    QString axis;
    model::ParameterValues values;
    std::optional<device::DriveLimits> limits; ///< the drive's own limits (Drive::limits); unset: unknown
    std::optional<device::DriveCapabilities> capabilities; ///< Drive::capabilities; unset: unknown
    QString limitsError;                       ///< why the limits are unknown
    /// The drive takes the FRF peak in its injection point's own units (hal:: the PID output's), not in % of rated
    /// torque (DriveCapabilities::frfPeakInOutputUnits).
    bool peakInOutputUnits() const { return capabilities && capabilities->frfPeakInOutputUnits; }
    /// The signal whose units the peak is in (DriveCapabilities::frfOutputSignal, e.g. "pid.x.output").
    QString outputSignal() const;
    /// The drive's FRF amplitude limit [% of rated torque] (NaN when unknown).
    double maxAmplitudePct() const;
    /// The drive's FRF peak limit in the output's units (DriveLimits::frfPeakMax; NaN when unknown or not given).
    double maxPeak() const;
    /// Highest FRF frequency the drive measures, exclusive (DriveCapabilities::frfMaxHz; 0: no own limit).
    double frfMaxHz() const { return capabilities ? capabilities->frfMaxHz : 0.0; }
    double ratedTorqueNm() const;  ///< motor.rated_current × motor.torque_constant (NaN when unknown)
    double traceRateHz() const;    ///< 1 / (trace.divider × velocity.period) (NaN when unknown)
};

/// Safety step: SafetyPage plus the excitation amplitude (wizard field "amplitudePct" in % of rated torque, or
/// "amplitudePeak" in the output's units on a drive that takes the peak so, hal:).
class FrfSafetyPage : public SafetyPage {
    Q_OBJECT
public:
    explicit FrfSafetyPage(AppContext& ctx, QWidget* parent = nullptr);
    QDoubleSpinBox* amplitude() const { return m_amplitude; }
    /// The peak in the output's units (shown instead of amplitude() when the drive takes it).
    QDoubleSpinBox* amplitudePeak() const { return m_peak; }
    const FrfDriveInfo& driveInfo() const { return m_info; }
    void initializePage() override;
    /// Also waits for the drive values (the amplitude in N·m is shown before the confirmation counts).
    bool isComplete() const override;

signals:
    /// The drive values of the axis were read (or the read failed).
    void driveInfoChanged();

private:
    void readInfo();
    void showAmplitude();
    AppContext& m_ctx;
    FrfDriveInfo m_info;
    int m_request = 0;
    int m_describeRequest = 0;
    int m_answersPending = 0;
    bool m_infoPending = false;
    void showAmplitudeMode();
    QDoubleSpinBox* m_amplitude = nullptr;
    QDoubleSpinBox* m_peak = nullptr;
    QLabel* m_amplitudeText = nullptr;
    QFormLayout* m_form = nullptr;
};

/// Method and band (fields "method", "fminHz", "fmaxHz", "points") with the estimated motion time.
class FrfConfigPage : public QWizardPage {
    Q_OBJECT
public:
    explicit FrfConfigPage(AppContext& ctx, const FrfSafetyPage& safety, QWidget* parent = nullptr);
    QComboBox* method() const { return m_method; }
    QDoubleSpinBox* fmin() const { return m_fmin; }
    QDoubleSpinBox* fmax() const { return m_fmax; }
    QSpinBox* points() const { return m_points; }
    /// What the FRF reports, when the drive offers a choice (DriveCapabilities::frfQuantities; hidden otherwise).
    QComboBox* quantity() const { return m_quantity; }
    device::FrfQuantity selectedQuantity() const;
    /// Adaptive multisine (device::runAdaptiveFrf; offered with the multisine on a drive that plans it in % of rated
    /// torque): re-excite the lines not yet valid until every line is valid or the time budget is spent.
    QCheckBox* adaptive() const { return m_adaptive; }
    QDoubleSpinBox* timeBudget() const { return m_budget; }
    /// The motion-time budget of an adaptive run [s]; unset: one ordinary test.
    std::optional<double> adaptiveBudgetS() const;
    /// Motion time of the planned test [s] (adaptive: of its first pass); NaN while unknown or when refused.
    double estimatedMotionS() const { return m_motionS; }
    device::FrfMethod selectedMethod() const;
    void initializePage() override;
    bool isComplete() const override;

private:
    void updateEstimate();
    AppContext& m_ctx;
    const FrfSafetyPage& m_safety;
    void offerMethods();
    void offerAdaptive();
    QComboBox* m_method = nullptr;
    QComboBox* m_quantity = nullptr;
    QLabel* m_quantityLabel = nullptr;
    QDoubleSpinBox* m_fmin = nullptr;
    QDoubleSpinBox* m_fmax = nullptr;
    QSpinBox* m_points = nullptr;
    QCheckBox* m_adaptive = nullptr;
    QDoubleSpinBox* m_budget = nullptr;
    QLabel* m_budgetLabel = nullptr;
    QLabel* m_validity = nullptr;
    QLabel* m_estimate = nullptr;
    int m_planRequest = -1; ///< the drive's planTest request under way (DriveController::planTest)
    int m_generation = 0;
    int m_pendingGeneration = -1;
    bool m_planOk = false;
    double m_motionS = 0.0;
};

/// What the result page computes off the GUI thread.
struct FrfAnalysis {
    std::vector<tuning::Resonance> resonances;
    QString error;        ///< why no resonance list (e.g. too few usable points)
    QString analysedForm; ///< which response the resonances come from
};

/// Bode plot with validity bands and resonance markers, and the resonance table.
class FrfResultPage : public QWizardPage {
    Q_OBJECT
public:
    explicit FrfResultPage(QWidget* parent = nullptr);
    /// The measured FRF to show (set by the wizard before the page is entered); `frfMaxHz` the drive's highest
    /// measurable frequency (0: none of its own), `outputSignal` what a peak in output units is in (may be empty).
    void setMeasurement(const dsp::FrequencyResponse& frf, device::FrfMethod method, double frfMaxHz = 0.0,
                        const QString& outputSignal = QString());
    /// What an adaptive run did (its passes, the lines left invalid and why); empty: hidden.
    void setAdaptiveSummary(const QString& text);
    QLabel* adaptiveSummary() const { return m_adaptiveText; }
    /// The measured quantity as its metadata say: "plant", "open-loop", or empty (the closed velocity loop).
    QString quantity() const { return m_quantity; }
    widgets::BodePlot* bodePlot() const { return m_plot; }
    QTableWidget* resonanceTable() const { return m_table; }
    const dsp::FrequencyResponse& measured() const { return m_frf; }
    bool analysed() const { return m_done; }
    const FrfAnalysis& analysis() const { return m_analysis; }
    double traceRateHz() const { return m_fsHz; }
    void initializePage() override;
    bool isComplete() const override;

private:
    void showAnalysis();
    void addBands();
    dsp::FrequencyResponse m_frf;
    device::FrfMethod m_method = device::FrfMethod::MultiSweep;
    double m_fsHz = 0.0;
    double m_frfMaxHz = 0.0;
    QString m_quantity;
    QString m_outputSignal;
    FrfAnalysis m_analysis;
    bool m_done = false;
    widgets::BodePlot* m_plot = nullptr;
    QTableWidget* m_table = nullptr;
    QLabel* m_summary = nullptr;
    QLabel* m_adaptiveText = nullptr;
    QFutureWatcher<FrfAnalysis>* m_watcher = nullptr;
};

/// Saves the session on entering; shows its id and what was stored.
class FrfSavePage : public QWizardPage {
    Q_OBJECT
public:
    explicit FrfSavePage(QWidget* parent = nullptr);
    QLineEdit* note() const { return m_note; }
    QLabel* status() const { return m_status; }
    QPushButton* openNotchButton() const { return m_openNotch; }
    /// Checked (default): Finish also opens the saved session as a document of the main window.
    QCheckBox* openDocumentBox() const { return m_openDocument; }
    void showSaved(const QString& text);

private:
    QLineEdit* m_note = nullptr;
    QPushButton* m_openNotch = nullptr;
    QCheckBox* m_openDocument = nullptr;
    QLabel* m_status = nullptr;
};

class FrfWizard : public QWizard {
    Q_OBJECT
public:
    enum PageId { SafetyId, ConfigId, RunId, ResultId, SaveId };

    explicit FrfWizard(AppContext& ctx, QWidget* parent = nullptr);

    FrfSafetyPage* safetyPage() const { return m_safety; }
    FrfConfigPage* configPage() const { return m_config; }
    TestRunPage* runPage() const { return m_run; }
    FrfResultPage* resultPage() const { return m_result; }
    FrfSavePage* savePage() const { return m_save; }

    /// The test as configured on the pages.
    device::TestRequest request() const;
    /// Id of the last session this wizard saved (completed or aborted); 0: none.
    std::int64_t savedSessionId() const { return m_sessionId; }

    /// Finish on the save page stores the completed session.
    void accept() override;
    void reject() override;

    /// Saves the session (as Finish) and hands the measured FRF to a new notch wizard, which opens at
    /// its proposal; this wizard closes.
    void openInNotchWizard();

signals:
    void sessionSaved(qint64 id);
    /// The notch wizard opened by openInNotchWizard() (deletes itself on close).
    void notchWizardOpened(QWizard* wizard);

private:
    void onRunFinished(bool ok);
    void onPageChanged(int id);
    /// The inputs JSON of the current request.
    nlohmann::json inputsJson() const;
    /// The result page's text of an adaptive run.
    QString adaptiveSummary(const device::AdaptiveFrfResult& a) const;
    void saveCompleted();
    void saveAborted(const QString& reason);

    AppContext& m_ctx;
    FrfSafetyPage* m_safety = nullptr;
    FrfConfigPage* m_config = nullptr;
    TestRunPage* m_run = nullptr;
    FrfResultPage* m_result = nullptr;
    FrfSavePage* m_save = nullptr;
    device::TestRequest m_lastRequest{{}, device::FrfTest{}}; ///< always of kind Frf (request())
    std::shared_ptr<const device::FrfMeasurement> m_measurement;
    std::optional<double> m_lastBudgetS;                         ///< the run is adaptive with this budget [s]
    std::shared_ptr<const device::AdaptiveFrfResult> m_adaptive; ///< its passes and the lines left invalid
    bool m_runSaved = false;  ///< the session of the current run is stored
    std::int64_t m_sessionId = 0;
};

}  // namespace gui
}  // namespace axistune

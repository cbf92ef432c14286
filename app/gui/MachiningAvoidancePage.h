// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Machining wizard, step "chatter avoidance" (docs/chatter-avoidance.md, docs/wizards/machining.md): runs the
// cut of steps 1–2 on the simulated vmc X axis with a chosen avoidance method (core/avoidance/AvoidanceCut)
// on a worker thread with progress and Abort, and plots the tool acceleration, its spectrum before and after
// the avoidance, the spindle speed and its command, the estimated chatter frequency and the cost over time,
// and the operating point moving on the stability lobes of step 3 (a time slider moves it).

#include "core/avoidance/AvoidanceCut.h"

#include <QFutureWatcher>
#include <QWizardPage>

#include <atomic>
#include <memory>

class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSlider;
class QTimer;

namespace axistune {
namespace widgets {
class CurvePlot;
class TimeTracePlot;
} // namespace widgets
namespace gui {

class MachiningToolPage;
class MachiningCutPage;
class MachiningLobesPage;

struct AvoidanceRun {
    std::shared_ptr<const avoidance::AvoidanceCutResult> result;
    double constantRmsLast = 0.0; ///< tool acceleration RMS of the last 0.3 s of the same cut at constant speed
    QString error;
    bool aborted = false;
};

class MachiningAvoidancePage : public QWizardPage {
    Q_OBJECT
public:
    MachiningAvoidancePage(const MachiningToolPage& tool, const MachiningCutPage& cut, const MachiningLobesPage& lobes,
                           QWidget* parent = nullptr);
    ~MachiningAvoidancePage() override;
    QComboBox* method() const { return m_method; }
    QComboBox* sensor() const { return m_sensor; }
    QLineEdit* durationS() const { return m_duration; }
    QLineEdit* escMinRpm() const { return m_escMin; }
    QLineEdit* escMaxRpm() const { return m_escMax; }
    QLineEdit* escStartS() const { return m_escStart; }
    QLineEdit* escCurvature() const { return m_escCurv; }
    QLineEdit* sigmaTh() const { return m_sigmaTh; }
    QPushButton* runButton() const { return m_run; }
    QPushButton* abortButton() const { return m_abort; }
    QProgressBar* progress() const { return m_progress; }
    QSlider* timeSlider() const { return m_slider; }
    widgets::TimeTracePlot* tracePlot() const { return m_trace; }
    widgets::CurvePlot* spectrumPlot() const { return m_spectrum; }
    widgets::CurvePlot* lobesPlot() const { return m_lobes; }
    QLabel* summary() const { return m_summary; }
    const AvoidanceRun& run() const { return m_run_; }
    bool busy() const { return m_running; }
    void initializePage() override;
    /// Starts the cut (off the GUI thread); the summary shows why when the inputs are not valid.
    void start();
    void abort();

private:
    void finished();
    void showLobes();
    void updateMethodFields();
    const MachiningToolPage& m_toolPage;
    const MachiningCutPage& m_cutPage;
    const MachiningLobesPage& m_lobesPage;
    QComboBox* m_method = nullptr;
    QComboBox* m_sensor = nullptr;
    QLineEdit *m_duration = nullptr, *m_escMin = nullptr, *m_escMax = nullptr, *m_escStart = nullptr,
              *m_escCurv = nullptr, *m_sigmaTh = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_abort = nullptr;
    QProgressBar* m_progress = nullptr;
    QSlider* m_slider = nullptr;
    QTimer* m_poll = nullptr;
    widgets::TimeTracePlot* m_trace = nullptr;
    widgets::CurvePlot* m_spectrum = nullptr;
    widgets::CurvePlot* m_lobes = nullptr;
    QLabel* m_summary = nullptr;
    QFutureWatcher<AvoidanceRun>* m_watcher = nullptr;
    AvoidanceRun m_run_;
    std::shared_ptr<std::atomic<double>> m_done = std::make_shared<std::atomic<double>>(0.0);
    std::shared_ptr<std::atomic<bool>> m_stop = std::make_shared<std::atomic<bool>>(false);
    double m_durationRun = 1.0;
    bool m_running = false;
};

} // namespace gui
} // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
// Current-loop wizard: page order, the save page and the session record (CurrentLoopWizard.h,
// docs/wizards/current-loop.md). Method: spec/current-loop-and-multisweep-frf.md chapter 2.
#include "app/gui/CurrentLoopWizard.h"

#include "app/gui/AbortGuard.h"
#include "app/gui/AppContext.h"
#include "app/gui/WizardPages.h"
#include "app/gui/WizardRegistry.h"
#include "core/model/ResultJson.h"
#include "core/store/SessionRecord.h"

#include <QLabel>
#include <QVBoxLayout>

#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

namespace {

const WizardRegistrar kRegistrar{
    "current-loop", QT_TRANSLATE_NOOP("Wizards", "Current loop…"), 30,
    [](AppContext& ctx, QWidget* parent) -> QWizard* { return new CurrentLoopWizard(ctx, parent); }, false};

nlohmann::json gainsJson(const tuning::PiGains& g)
{
    return {{"kp_V_per_A", g.kpVPerA}, {"ki_V_per_As", g.kiVPerAs}};
}

} // namespace

CurrentLoopSavePage::CurrentLoopSavePage(AppContext& ctx, CurrentLoopData& shared, ApplyPage* apply, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared), m_apply(apply)
{
    setTitle(tr("Save"));
    setSubTitle(
        tr("The session holds the motor data and settings, the α table, the chosen α and gains with the rise "
           "time, the gain schedule, the predicted step responses, what was applied with its journal, the read-back, "
           "and the current step measured on the drive with its comparison."));
    auto* lay = new QVBoxLayout(this);
    m_text = new QLabel(this);
    m_text->setObjectName("clSummary");
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    lay->addWidget(m_text);
    lay->addStretch(1);
    setFinalPage(true);
}

void CurrentLoopSavePage::initializePage()
{
    auto* w = qobject_cast<CurrentLoopWizard*>(wizard());
    if (w && w->savedSessionId() == 0)
        w->saveSession();
    QString text;
    if (const auto* c = m_d.chosen())
        text += tr("α = %1, k_p = %2 V/A, k_i = %3 V/(A·s), rise time %4 µs (delay-free design).")
                    .arg(c->alpha, 0, 'f', 2)
                    .arg(c->gains.kpVPerA, 0, 'f', 3)
                    .arg(c->gains.kiVPerAs, 0, 'g', 6)
                    .arg(c->riseTimeS * 1e6, 0, 'f', 1);
    if (!m_ctx.drive().isConnected())
        text += "\n" + tr("Not connected: the gains were not applied.");
    else if (!m_apply->applied())
        text += "\n" + tr("Not applied: the proposal is kept in the session.");
    else
        text += "\n" + tr("Applied to axis %1 and read back.").arg(m_d.axis);
    if (m_d.measured)
        text += "\n" + tr("Measured current step of %1 A: rise time %2 µs (predicted %3 µs), overshoot %4 % (predicted "
                           "%5 %); largest difference %6 % of the step.")
                           .arg(m_d.measured->amplitudeA, 0, 'f', 2)
                           .arg(m_d.measuredFigures.riseTimeS * 1e6, 0, 'f', 1)
                           .arg(m_d.predictedFigures.riseTimeS * 1e6, 0, 'f', 1)
                           .arg(m_d.measuredFigures.overshoot * 100.0, 0, 'f', 1)
                           .arg(m_d.predictedFigures.overshoot * 100.0, 0, 'f', 1)
                           .arg(m_d.difference.maxAbs * 100.0, 0, 'f', 1);
    text += "\n" + (w && w->savedSessionId() > 0 ? tr("Saved as session %1.").arg(w->savedSessionId())
                                                 : tr("The session was not saved (no store open)."));
    m_text->setText(text);
}

CurrentLoopWizard::CurrentLoopWizard(AppContext& ctx, QWidget* parent) : TuningWizard(parent), m_ctx(ctx)
{
    setWindowTitle(tr("Current loop"));
    setObjectName("currentLoopWizard");
    m_motor = new CurrentLoopMotorPage(ctx, m_data, this);
    m_design = new CurrentLoopDesignPage(ctx, m_data, this);
    m_apply = new ApplyPage(ctx, this);
    m_apply->setObjectName("clApply");
    auto* step = new CurrentLoopStepPage(ctx, m_data, m_apply, this);
    m_safety = new SafetyPage(ctx, this);
    m_safety->setObjectName("clSafety");
    m_safety->setLimitKeys({"motor.max_current", "drive.max_voltage", "current.kp", "current.ki", "current.alpha"});
    auto stepRequest = [this] {
        device::TestRequest r;
        r.axis = m_data.axis.toStdString();
        auto& c = r.test.emplace<device::CurrentStepTest>();
        c.currentA = m_data.stepAmplitudeA;
        c.recordS = m_data.stepRecordS;
        return std::vector<device::TestRequest>{r};
    };
    // The same step before applying, with the gains the drive holds: the comparison for the one after.
    m_beforeRun = new TestRunPage(ctx, this);
    m_beforeRun->setObjectName("clBeforeRunPage");
    m_beforeRun->setRequestFactory([this, stepRequest] {
        m_data.beforeCapture.reset();
        return stepRequest();
    });
    connect(m_beforeRun, &TestRunPage::runFinished, this, [this](bool ok) {
        if (ok && !m_beforeRun->replies().empty() && m_beforeRun->replies().front().capture)
            m_data.beforeCapture = m_beforeRun->replies().front().capture;
        else
            guard()->runFailed(tr("The current step before applying failed: %1").arg(m_beforeRun->failure()));
    });
    m_run = new TestRunPage(ctx, this);
    m_run->setObjectName("clRunPage");
    m_run->setRequestFactory([this, stepRequest] {
        m_data.measuredCapture.reset();
        m_data.measured.reset();
        m_data.measureError.clear();
        return stepRequest();
    });
    connect(m_run, &TestRunPage::runFinished, this, [this](bool ok) {
        if (ok && !m_run->replies().empty() && m_run->replies().front().capture) {
            m_data.measuredCapture = m_run->replies().front().capture;
            return;
        }
        m_data.measureError = m_run->failure();
        // Nothing verified the applied gains: they are restored and the session is kept as aborted.
        guard()->runFailed(tr("The current step after applying failed: %1").arg(m_run->failure()));
    });
    guardEarlyStops(ctx, m_apply, {m_beforeRun, m_run}, tr("the current-loop gains"),
                    [this] { return !m_beforeRun->replies().empty() || !m_run->replies().empty(); });
    auto* verify = new CurrentLoopVerifyPage(ctx, m_data, m_apply, this);
    auto* save = new CurrentLoopSavePage(ctx, m_data, m_apply, this);
    setPage(Motor, m_motor);
    setPage(Design, m_design);
    setPage(Step, step);
    setPage(Safety, m_safety);
    setPage(BeforeRun, m_beforeRun);
    setPage(Apply, m_apply);
    setPage(MeasureRun, m_run);
    setPage(Verify, verify);
    setPage(Save, save);
    setStartId(Motor);
    resize(1000, 700);
}

int CurrentLoopWizard::nextId() const
{
    if (currentId() == Apply && !m_data.measure)
        return Verify;  // no measurement wanted: straight to the read-back
    return QWizard::nextId();
}

void CurrentLoopWizard::saveSession(bool aborted, const QString& reason)
{
    const auto& d = m_data;
    store::SessionRecord rec;
    rec.info.kind = "current-loop";
    rec.info.axis = d.axis.toStdString();
    rec.info.status = aborted ? store::SessionStatus::Aborted : store::SessionStatus::Completed;
    rec.info.note = reason.toStdString();
    const auto& m = d.motor;
    rec.inputs = {{"source", d.fromDrive ? (d.fromProfile ? "drive+profile" : "drive")
                                         : (d.fromProfile ? "profile" : "entered")},
                  {"motor",
                   {{"resistance_ohm", m.resistanceOhm},
                    {"inductance_q_H", m.inductanceQH},
                    {"max_current_A", m.maxCurrentA},
                    {"max_voltage_V", m.maxVoltageV},
                    {"inductance_drop_at_max", m.inductanceDropAtMax},
                    {"rated_current_A", m.ratedCurrentA},
                    {"back_emf_V_per_krpm", m.backEmfVPerKrpm},
                    {"contouring_speed_rpm", m.contouringSpeedRpm}}},
                  {"settings",
                   {{"tau_s", d.settings.deadTimeS},
                    {"gain_margin_dB", d.settings.gainMarginDb},
                    {"overshoot", d.settings.overshootMax},
                    {"ripple", d.settings.rippleFraction},
                    {"alpha_step", d.settings.alphaStep}}},
                  {"drive_period_s", d.drivePeriodS},
                  {"drive_dead_time_s", d.driveDeadTimeS},
                  {"back_emf_check", d.backEmfText.toStdString()}};
    // The motor data become the axis's motor model in the profile (docs/formats-profile.md), for the next
    // session's "From profile".
    if (!d.axis.isEmpty() && !m_ctx.machine().isEmpty() && tuning::validateMotor(m, "motor data").ok()) {
        nlohmann::json motor{{"resistance_ohm", m.resistanceOhm},
                             {"inductance_q_H", m.inductanceQH},
                             {"inductance_drop_at_max", m.inductanceDropAtMax},
                             {"max_current_A", m.maxCurrentA},
                             {"max_voltage_V", m.maxVoltageV}};
        if (m.ratedCurrentA > 0.0)
            motor["rated_current_A"] = m.ratedCurrentA;
        if (m.backEmfVPerKrpm > 0.0)  // line-to-line rms per 1000 min⁻¹ → q-axis peak V·s/rad (k_e = k_t/1.5)
            motor["back_emf_constant_V_s_per_rad"] = m.backEmfVPerKrpm / kKeToVPerKrpm;
        rec.models.push_back({0, rec.info.axis, "motor", {}, motor});
    }
    const auto* c = d.chosen();
    if (d.design && c) {
        nlohmann::json table = nlohmann::json::array();
        for (const auto& row : d.design->table) {
            nlohmann::json r{
                {"alpha", row.alpha}, {"feasible", row.feasible}, {"active_constraints", row.activeConstraints}};
            if (row.feasible) {
                r.update(gainsJson(row.gains));
                r["rise_time_s"] = row.riseTimeS;
                r["overshoot"] = row.overshoot;
            }
            table.push_back(r);
        }
        nlohmann::json schedule = nlohmann::json::array();
        for (const auto& p : d.design->schedule) {
            const double f = tuning::scheduleFactor(m, p.currentA);
            schedule.push_back({{"current_A", p.currentA},
                                {"factor", f},
                                {"kp_V_per_A", f * c->gains.kpVPerA},
                                {"ki_V_per_As", f * c->gains.kiVPerAs}});
        }
        nlohmann::json result{{"alpha", c->alpha},
                              {"kp_V_per_A", c->gains.kpVPerA},
                              {"ki_V_per_As", c->gains.kiVPerAs},
                              {"rise_time_s", c->riseTimeS},
                              {"overshoot", c->overshoot},
                              {"optimum_alpha", d.design->alpha},
                              {"optimum", gainsJson(d.design->gains)},
                              {"table", table},
                              {"schedule", schedule}};
        rec.results.push_back({"design", result, {}});
        if (!d.step.timeS.empty())
            rec.results.push_back(
                {"step_prediction",
                 {{"period_s", d.drivePeriodS}, {"dead_time_s", d.driveDeadTimeS}},
                 {{"t_s", d.step.timeS}, {"delay_free", d.step.delayFree}, {"delay_inclusive", d.step.discrete}}});
        if (!d.fineTimeS.empty())
            rec.results.push_back({"step_design",
                                   {{"points", d.fineTimeS.size()}},
                                   {{"t_s", d.fineTimeS}, {"delay_free", d.fineDelayFree}}});
        if (!d.axis.isEmpty() && !m_ctx.machine().isEmpty())
            rec.parameterSets.push_back(
                {0,
                 rec.info.axis,
                 store::ParameterSource::Proposed,
                 {},
                 "current-loop wizard",
                 {{"current.kp", c->gains.kpVPerA}, {"current.ki", c->gains.kiVPerAs}, {"current.alpha", c->alpha}}});
    }
    if (d.measuredCapture)
        rec.captures.push_back({"current_step", *d.measuredCapture});
    if (d.beforeCapture)
        rec.captures.push_back({"current_step_before", *d.beforeCapture});
    if (d.verified) {
        nlohmann::json v{{"kp_V_per_A", d.readKp},
                         {"ki_V_per_As", d.readKi},
                         {"alpha", d.readAlpha},
                         {"predicted_overshoot", d.verifyOvershoot},
                         {"predicted_rise_time_s", d.verifyRiseS}};
        std::vector<model::Channel> arrays{{"t_s", d.verifyStep.timeS}, {"delay_inclusive", d.verifyStep.discrete}};
        if (d.measured) {
            // A figure the step does not reach is left out and named (docs/formats.md "Undefined values").
            const char* notReached = "not reached within the recorded step";
            auto figures = [notReached](nlohmann::json& o, const std::string& prefix, double riseS, double overshoot) {
                model::putNumber(o, prefix + "rise_time_s", riseS, notReached);
                model::putNumber(o, prefix + "overshoot", overshoot, notReached);
            };
            nlohmann::json meas{{"capture", "current_step"},
                                {"step_A", d.measured->amplitudeA},
                                {"max_abs_difference", d.difference.maxAbs},
                                {"rms_difference", d.difference.rms},
                                {"samples_compared", d.difference.samples},
                                {"verdict", d.measuredVerdict.toStdString()}};
            figures(meas, "", d.measuredFigures.riseTimeS, d.measuredFigures.overshoot);
            figures(meas, "design_", d.designFigures.riseTimeS, d.designFigures.overshoot);
            figures(meas, "predicted_", d.predictedFigures.riseTimeS, d.predictedFigures.overshoot);
            v["measured"] = meas;
            if (d.before) {
                nlohmann::json b{{"capture", "current_step_before"}, {"step_A", d.before->amplitudeA}};
                figures(b, "", d.beforeFigures.riseTimeS, d.beforeFigures.overshoot);
                v["measured_before"] = b;
            }
            arrays = {{"t_s", d.measured->tS},
                      {"measured", d.measured->normalised},
                      {"delay_inclusive", d.measuredPrediction.discrete},
                      {"delay_free", d.measuredPrediction.delayFree}};
        } else {
            v["note"] = d.measure ? "no measured current step: " + d.measureError.toStdString()
                                  : std::string("no current step was measured (not chosen)");
            model::putUndefined(v, "measured", v["note"].get<std::string>());
        }
        rec.results.push_back({"verification", v, arrays});
    }
    if (m_apply->applied())
        rec.parameterSets.push_back(
            {0, rec.info.axis, store::ParameterSource::Applied, {}, "current-loop wizard", m_apply->readBack()});
    rec.journal = m_apply->journal();
    auto id = m_ctx.saveSession(rec);
    sessionStored(id ? *id : 0, aborted);
}

} // namespace gui
} // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
// Two-inertia wizard: page order, the summary page and the session record (TwoInertiaWizard.h,
// docs/wizards/two-inertia.md). Method: spec/lost-motion-and-two-inertia.md chapter 5, §4.8–4.14.
#include "app/gui/TwoInertiaWizard.h"

#include "app/gui/AbortGuard.h"
#include "app/gui/AppContext.h"
#include "app/gui/WizardPages.h"
#include "app/gui/WizardRegistry.h"
#include "core/model/Constants.h"
#include "core/model/MetadataKeys.h"
#include "core/store/FrfCapture.h"
#include "core/store/SessionRecord.h"

#include <QLabel>
#include <QVBoxLayout>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

namespace axistune {
namespace gui {

namespace {

using model::kTwoPi;

const WizardRegistrar kRegistrar{"two-inertia", QT_TRANSLATE_NOOP("Wizards", "Two-inertia vibration suppression…"), 60,
                                 [](AppContext& ctx, QWidget* parent) -> QWizard* {
                                     return new TwoInertiaWizard(ctx, parent);
                                 },
                                 false};

}  // namespace

device::TestRequest profileJog(const QString& axis, const tuning::MotionProfile& p)
{
    device::TestRequest r;
    r.axis = axis.toStdString();
    auto& j = r.test.emplace<device::JogTest>();
    j.distance = p.vMax * (tuning::sCurveRampS(p) + p.cruiseS);
    j.velocity = p.vMax;
    j.acceleration = p.aMax;
    j.jerk = p.jerk;
    j.returnToStart = false; // a second move would start while the first still rings
    j.dwellS = p.settleS;
    return r;
}

TwoInertiaSavePage::TwoInertiaSavePage(AppContext& ctx, TwoInertiaData& shared, ApplyPage* apply, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared), m_apply(apply)
{
    setTitle(tr("Save"));
    setSubTitle(tr("The session holds the measured response, the plant, the fitted model, the filter settings, the "
                   "predicted load error, what was applied with its journal, and the verification."));
    auto* lay = new QVBoxLayout(this);
    m_text = new QLabel(this);
    m_text->setObjectName("tiSummary");
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    lay->addWidget(m_text);
    lay->addStretch(1);
    setFinalPage(true);
}

void TwoInertiaSavePage::initializePage()
{
    auto* w = qobject_cast<TwoInertiaWizard*>(wizard());
    if (w && w->savedSessionId() == 0)
        w->saveSession(false, {});
    QString text;
    if (m_d.fit) {
        const auto& p = m_d.fit->params;
        text += tr("Axis %1: anti-resonance f₀ %2 Hz, resonance f_p %3 Hz; filter %4: f₀ %5 Hz, ζ %6%7.")
                    .arg(m_d.axis)
                    .arg(tuning::antiresonanceRadS(p) / kTwoPi, 0, 'f', 3)
                    .arg(tuning::resonanceRadS(p) / kTwoPi, 0, 'f', 3)
                    .arg(m_d.filter.mode == tuning::SuppressionMode::Full ? tr("F_L (full-closed)") : tr("F_m (semi-closed)"))
                    .arg(m_d.filter.f0Hz, 0, 'f', 3)
                    .arg(m_d.filter.zeta, 0, 'f', 4)
                    .arg(m_d.filter.mode == tuning::SuppressionMode::Full
                             ? tr(", τ %1 ms").arg(m_d.filter.tauS * 1e3, 0, 'f', 2)
                             : QString());
    }
    if (m_d.loadAfter.maxAbs > 0.0)
        text += "\n" + tr("Maximum load error of the profile: measured %1° with the filter (%2° before the change); "
                          "predicted %3° without and %4° with the filter.")
                           .arg(m_d.loadAfter.maxAbs * model::kDegPerRad, 0, 'f', 3)
                           .arg(m_d.loadBefore.maxAbs * model::kDegPerRad, 0, 'f', 3)
                           .arg(m_d.predictedLoadWithout * model::kDegPerRad, 0, 'f', 3)
                           .arg(m_d.predictedLoadWith * model::kDegPerRad, 0, 'f', 3);
    if (!m_ctx.drive().isConnected())
        text += "\n" + tr("Not connected: applying the filter and verifying with the profile need a connection.");
    else if (!m_apply->applied())
        text += "\n" + tr("Not applied: the proposal is kept in the session.");
    text += "\n" + (w && w->savedSessionId() > 0 ? tr("Saved as session %1.").arg(w->savedSessionId())
                                                 : tr("The session was not saved (no store open)."));
    m_text->setText(text);
}

TwoInertiaWizard::TwoInertiaWizard(AppContext& ctx, QWidget* parent) : TuningWizard(parent), m_ctx(ctx)
{
    setWindowTitle(tr("Two-inertia vibration suppression"));
    setObjectName("twoInertiaWizard");
    m_source = new TwoInertiaSourcePage(ctx, m_data, this);
    m_safety = new SafetyPage(ctx, this);
    m_safety->setMotionDescription(
        tr("Frequency response: a torque sine stream at the set amplitude is injected into the closed velocity "
           "loop (the axis oscillates about its position). Before and after applying the filter: one move with "
           "the profile's speed, acceleration and jerk (it does not return to the start)."));
    m_safety->setLimitKeys({"velocity.kp", "velocity.ki", "motor.rated_current"});
    // Measured here: safety → FRF run. From a session: filter → safety (the session's axis) → profile.
    m_safety->setNextIdFunction([this] { return m_data.fromSession ? int(BeforeRun) : int(Run); });
    m_run = new TestRunPage(ctx, this);
    m_run->setObjectName("tiRunPage");
    m_run->setRequestFactory([this] {
        const device::FrfTest frf{.method = device::FrfMethod::MultiSweep,
                                  .fminHz = m_data.fminHz,
                                  .fmaxHz = m_data.fmaxHz,
                                  .points = m_data.points,
                                  .amplitudePct = m_data.amplitudePct};
        return std::vector<device::TestRequest>{{.axis = m_safety->axis().toStdString(), .test = frf}};
    });
    m_fit = new TwoInertiaFitPage(ctx, m_data, m_run, this);
    m_apply = new ApplyPage(ctx, this);
    m_apply->setObjectName("tiApply");
    m_filter = new TwoInertiaFilterPage(ctx, m_data, m_apply, this);
    // The same profile before the change (the measured "without") and after it.
    m_beforeRun = new TestRunPage(ctx, this);
    m_beforeRun->setObjectName("tiBeforeRunPage");
    m_beforeRun->setTitle(tr("Profile before the change"));
    // The profile is given in motor revolutions: on a linear axis its numbers would be read as metres.
    auto profileRequests = [this] {
        return m_data.linearAxis ? std::vector<device::TestRequest>{}
                                 : std::vector<device::TestRequest>{profileJog(m_data.axis, m_data.profile)};
    };
    auto linearRefusal = [this] {
        return m_data.linearAxis ? tr("Refused: the profile is given in motor revolutions and runs on rotary axes "
                                      "only; axis %1 is linear (its jog would be read in metres). Measure the load "
                                      "error with the NC's own test.")
                                       .arg(m_data.axis)
                                 : QString();
    };
    m_beforeRun->setRequestFactory(profileRequests);
    m_beforeRun->setEmptyReason(linearRefusal);
    m_verifyRun = new TestRunPage(ctx, this);
    m_verifyRun->setObjectName("tiVerifyRunPage");
    m_verifyRun->setRequestFactory(profileRequests);
    m_verifyRun->setEmptyReason(linearRefusal);
    auto* verify = new TwoInertiaVerifyPage(m_data, m_beforeRun, m_verifyRun, this);
    auto* save = new TwoInertiaSavePage(ctx, m_data, m_apply, this);
    setPage(Source, m_source);
    setPage(Safety, m_safety);
    setPage(Run, m_run);
    setPage(Fit, m_fit);
    setPage(Filter, m_filter);
    setPage(BeforeRun, m_beforeRun);
    setPage(Apply, m_apply);
    setPage(VerifyRun, m_verifyRun);
    setPage(Verify, verify);
    setPage(Save, save);
    setStartId(Source);
    connect(this, &QWizard::currentIdChanged, this, [this](int id) {
        if (id == Filter)
            m_safety->setAxes(m_data.fromSession ? QStringList{m_data.axis} : QStringList{});
    });
    guardEarlyStops(ctx, m_apply, {m_run, m_beforeRun, m_verifyRun}, tr("the suppression filter and gains"),
                    [this] { return !m_run->replies().empty() || !m_beforeRun->replies().empty(); });
    for (TestRunPage* run : {m_run, m_beforeRun, m_verifyRun})
        connect(run, &TestRunPage::runFinished, this, [this, run](bool ok) {
            if (!ok)
                guard()->runFailed(run->failure());
        });
    resize(1000, 700);
}

void TwoInertiaWizard::saveSession(bool aborted, const QString& reason)
{
    const auto& d = m_data;
    store::SessionRecord rec;
    rec.info.kind = "two-inertia";
    rec.info.axis = (d.axis.isEmpty() ? m_safety->axis() : d.axis).toStdString();
    rec.info.status = aborted ? store::SessionStatus::Aborted : store::SessionStatus::Completed;
    rec.info.note = reason.toStdString();
    rec.inputs = {{"source", d.fromSession ? "session" : "measurement"},
                  {"source_session", d.sourceSession},
                  {"fmin_Hz", d.fminHz},
                  {"fmax_Hz", d.fmaxHz},
                  {"points", d.points},
                  {"amplitude_pct", d.amplitudePct},
                  {"fit_fmin_Hz", d.fitOptions.fminHz},
                  {"fit_fmax_Hz", d.fitOptions.fmaxHz},
                  {"loop_kp_Nms_per_rad", d.loopPi.kpNmsPerRad},
                  {"loop_ki_Nm_per_rad", d.loopPi.kiNmPerRad},
                  {"velocity_period_s", d.velocityPeriodS},
                  {"current_period_s", d.currentPeriodS},
                  {"mode", d.filter.mode == tuning::SuppressionMode::Full ? "full" : "semi"},
                  {"position_feedback", d.feedback},
                  {"tau_s", d.tauS},
                  {"profile",
                   {{"vmax_rad_s", d.profile.vMax},
                    {"accel_rad_s2", d.profile.aMax},
                    {"jerk_rad_s3", d.profile.jerk},
                    {"cruise_s", d.profile.cruiseS},
                    {"settle_s", d.profile.settleS}}}};
    if (d.measured)
        rec.captures.push_back({"measured", store::frfAsCapture(*d.measured)});
    if (d.plant)
        rec.captures.push_back({"plant", store::frfAsCapture(*d.plant)});
    if (d.fit && d.plant) {
        const auto& p = d.fit->params;
        dsp::FrequencyResponse model;
        model.metadata.set(model::meta::kContentOf, "two-inertia model");
        for (double f : d.plant->freqHz)
            model.push(f, tuning::motorVelocityResponse(p, f), std::nan(""), true);
        rec.captures.push_back({"model", store::frfAsCapture(model)});
        const double f0 = tuning::antiresonanceRadS(p) / kTwoPi, fp = tuning::resonanceRadS(p) / kTwoPi;
        const nlohmann::json fit = {{"Jm_kgm2", p.jmKgm2},
                                    {"JL_kgm2", p.jlKgm2},
                                    {"K_Nm_per_rad", p.kNmPerRad},
                                    {"C_Nms_per_rad", p.cNmsPerRad},
                                    {"delay_s", p.delayS},
                                    {"antiresonance_Hz", f0},
                                    {"f0_Hz", f0},
                                    {"resonance_Hz", fp},
                                    {"zeta_zero", tuning::zetaZero(p)},
                                    {"zeta_pole", tuning::zetaPole(p)},
                                    {"fit_error", d.fit->fitError},
                                    {"points_used", d.fit->pointsUsed}};
        rec.results.push_back({"fit", fit, {}});
        rec.results.push_back({"filter",
                               {{"mode", d.filter.mode == tuning::SuppressionMode::Full ? "full" : "semi"},
                                {"f0_Hz", d.filter.f0Hz},
                                {"zeta", d.filter.zeta},
                                {"tau_s", d.filter.tauS},
                                {"source", "model"},
                                {"drive_parameters", d.proposal}},
                               {}});
        rec.results.push_back({"load_error",
                               {{"profile", rec.inputs["profile"]}},
                               {{"t_s", d.loadError.tS},
                                {"without_filter_rad", d.loadError.withoutFilter},
                                {"with_filter_rad", d.loadError.withFilter}}});
        if (!m_ctx.machine().isEmpty()) {
            rec.models.push_back({0,
                                  rec.info.axis,
                                  "two_inertia",
                                  {},
                                  {{"motor_inertia_kgm2", p.jmKgm2},
                                   {"load_inertia_kgm2", p.jlKgm2},
                                   {"stiffness_Nm_per_rad", p.kNmPerRad},
                                   {"damping_Nms_per_rad", p.cNmsPerRad},
                                   {"delay_s", p.delayS},
                                   {"antiresonance_Hz", f0},
                                   {"resonance_Hz", fp}}});
            model::ParameterValues proposed = d.proposal;
            proposed.insert({{"velocity.kp", d.proposedPi.kpNmsPerRad}, {"velocity.ki", d.proposedPi.kiNmPerRad}});
            rec.parameterSets.push_back(
                {0, rec.info.axis, store::ParameterSource::Proposed, {}, "two-inertia wizard", proposed});
        }
    }
    if (d.beforeJog)
        rec.captures.push_back({"before", *d.beforeJog});
    if (d.jog) {
        rec.captures.push_back({"verification", *d.jog});
        rec.results.push_back({"verification",
                               {{"measured_max_load_error_rad", d.loadAfter.maxAbs},
                                {"measured_before_max_load_error_rad", d.beforeJog ? nlohmann::json(d.loadBefore.maxAbs)
                                                                                   : nlohmann::json()},
                                {"predicted_max_load_error_without_filter_rad", d.predictedLoadWithout},
                                {"predicted_max_load_error_with_filter_rad", d.predictedLoadWith},
                                {"measured_max_twist_rad", d.measuredMaxTwist},
                                {"predicted_max_twist_rad", d.predictedMaxTwist},
                                {"ideal_tracking_max_twist_rad", d.idealMaxTwist}},
                               {{"t_s", d.verifyT},
                                {"measured_twist_rad", d.measuredTwist},
                                {"predicted_twist_rad", d.predictedTwist},
                                {"load_error_t_s", d.loadAfter.tS},
                                {"load_error_rad", d.loadAfter.error},
                                {"before_load_error_t_s", d.loadBefore.tS},
                                {"before_load_error_rad", d.loadBefore.error}}});
    }
    if (m_apply->applied())
        rec.parameterSets.push_back(
            {0, rec.info.axis, store::ParameterSource::Applied, {}, "two-inertia wizard", m_apply->readBack()});
    rec.journal = m_apply->journal();
    auto id = m_ctx.saveSession(rec);
    sessionStored(id ? *id : 0, aborted);
}

}  // namespace gui
}  // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
// Velocity/position-loop wizard: page order, the save page and the session record
// (VelocityLoopWizard.h, docs/wizards/velocity-loop.md). Method: spec/lost-motion-and-two-inertia.md
// §2.8, §4.11–4.12.
#include "app/gui/VelocityLoopWizard.h"

#include "app/gui/AbortGuard.h"
#include "app/gui/AppContext.h"
#include "app/gui/NcPidPage.h"
#include "app/gui/WizardPages.h"
#include "app/gui/WizardRegistry.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/dsp/LoopMarginsJson.h"
#include "core/model/MetadataKeys.h"
#include "core/model/ResultJson.h"
#include "core/store/FrfCapture.h"
#include "core/store/SessionRecord.h"
#include "core/tuning/VelocityLoopDesignJson.h"

#include <QLabel>
#include <QVBoxLayout>

#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

namespace {

const WizardRegistrar kRegistrar{
    "velocity-loop", QT_TRANSLATE_NOOP("Wizards", "Velocity and position loop…"), 40,
    [](AppContext& ctx, QWidget* parent) -> QWizard* { return new VelocityLoopWizard(ctx, parent); }, false};

} // namespace

VelocityLoopSavePage::VelocityLoopSavePage(AppContext& ctx, VelocityLoopData& shared, ApplyPage* apply, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared), m_apply(apply)
{
    setTitle(tr("Save"));
    setSubTitle(tr("The session holds the rule and its inputs, the proposed PI and position gain, the predicted "
                   "loops with their margins, the steps before and after with the prediction, what was applied with "
                   "its journal."));
    auto* lay = new QVBoxLayout(this);
    m_text = new QLabel(this);
    m_text->setObjectName("vlSummary");
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    lay->addWidget(m_text);
    lay->addStretch(1);
    setFinalPage(true);
}

void VelocityLoopSavePage::initializePage()
{
    auto* w = qobject_cast<VelocityLoopWizard*>(wizard());
    if (w && w->savedSessionId() == 0)
        w->saveSession(false, {});
    QString text = tr("K_P = %1 N·m·s/rad, K_I = %2 N·m/rad; position gain %3 1/s.")
                       .arg(m_d.proposed.kpNmsPerRad, 0, 'g', 6)
                       .arg(m_d.proposed.kiNmPerRad, 0, 'g', 6)
                       .arg(m_d.position.recommendedPerS, 0, 'g', 4);
    if (!m_ctx.drive().isConnected())
        text += "\n" + tr("Not connected: nothing was applied.");
    else if (!m_apply->applied())
        text += "\n" + tr("Not applied: the proposal is kept in the session.");
    text += "\n" + (w && w->savedSessionId() > 0 ? tr("Saved as session %1.").arg(w->savedSessionId())
                                                 : tr("The session was not saved (no store open)."));
    m_text->setText(text);
}

VelocityLoopWizard::VelocityLoopWizard(AppContext& ctx, QWidget* parent) : TuningWizard(parent), m_ctx(ctx)
{
    setWindowTitle(tr("Velocity and position loop"));
    setObjectName("velocityLoopWizard");
    m_source = new VelocityLoopSourcePage(ctx, m_data, this);
    m_safety = new SafetyPage(ctx, this);
    m_safety->setMotionDescription(
        tr("A velocity step of the set size (motor side) in the velocity loop, before and after applying; with a "
           "measured response first a torque sine stream in the closed velocity loop."));
    m_safety->setLimitKeys({"velocity.kp", "velocity.ki", "position.kp", "motor.rated_current"});
    m_run = new TestRunPage(ctx, this);
    m_run->setObjectName("vlRunPage");
    m_run->setRequestFactory([this] {
        std::vector<device::TestRequest> reqs;
        m_data.axis = m_safety->axis();
        const std::string axis = m_data.axis.toStdString();
        if (m_data.method == VelocityLoopData::Method::Frf &&
            m_data.frfSource == VelocityLoopData::FrfSource::Measure) {
            const device::FrfTest frf{.method = device::FrfMethod::MultiSweep,
                                      .fminHz = m_data.fminHz,
                                      .fmaxHz = m_data.fmaxHz,
                                      .points = m_data.points,
                                      .amplitudePct = m_data.amplitudePct};
            reqs.push_back({.axis = axis, .test = frf});
        }
        device::TestRequest s;
        s.axis = axis;
        auto& step = s.test.emplace<device::StepTest>();
        step.velocityRadS = m_data.stepRadS;
        step.recordS = m_data.stepDurationS;
        reqs.push_back(s);
        return reqs;
    });
    m_apply = new ApplyPage(ctx, this);
    m_apply->setObjectName("vlApply");
    m_design = new VelocityLoopDesignPage(ctx, m_data, m_run, m_apply, this);
    m_verifyRun = new TestRunPage(ctx, this);
    m_verifyRun->setObjectName("vlVerifyRunPage");
    m_verifyRun->setRequestFactory([this] {
        device::TestRequest s;
        s.axis = m_data.axis.toStdString();
        auto& step = s.test.emplace<device::StepTest>();
        step.velocityRadS = m_data.stepRadS;
        step.recordS = m_data.stepDurationS;
        return std::vector<device::TestRequest>{s};
    });
    auto* verify = new VelocityLoopVerifyPage(m_data, m_verifyRun, this);
    auto* save = new VelocityLoopSavePage(ctx, m_data, m_apply, this);
    setPage(Source, m_source);
    setPage(Safety, m_safety);
    setPage(Run, m_run);
    setPage(Design, m_design);
    setPage(Apply, m_apply);
    setPage(VerifyRun, m_verifyRun);
    setPage(Verify, verify);
    setPage(Save, save);
    m_ncPid = new NcPidPage(ctx, autotune::PidTuneScope::GainsAndNotch, this);
    m_source->setNcPidPage(m_ncPid);
    setPage(NcPid, m_ncPid);
    setStartId(Source);
    guardEarlyStops(ctx, m_apply, {m_run, m_verifyRun}, tr("the velocity-loop gains"),
                    [this] { return !m_run->replies().empty() || m_run->isRunning(); });
    connect(m_run, &TestRunPage::runFinished, this, [this](bool ok) {
        if (!ok)
            guard()->runFailed(m_run->failure());
    });
    // A failed step after applying restores the gains from before (nothing verified them).
    connect(m_verifyRun, &TestRunPage::runFinished, this, [this](bool ok) {
        if (!ok)
            guard()->runFailed(tr("The step after applying failed: %1").arg(m_verifyRun->failure()));
    });
    resize(1000, 700);
}

void VelocityLoopWizard::saveSession(bool aborted, const QString& reason)
{
    const auto& d = m_data;
    store::SessionRecord rec;
    rec.info.kind = "velocity-loop";
    rec.info.axis = (d.axis.isEmpty() ? m_safety->axis() : d.axis).toStdString();
    rec.info.status = aborted ? store::SessionStatus::Aborted : store::SessionStatus::Completed;
    rec.info.note = reason.toStdString();
    const bool inertia = d.method == VelocityLoopData::Method::Inertia;
    rec.inputs = {{"method", inertia ? "inertia" : "margins"},
                  {"Jm_kgm2", d.jmKgm2},
                  {"omega_l_Hz", d.omegaLHz},
                  {"k", d.k},
                  {"model_session", d.modelSession},
                  {"crossover_Hz", d.crossoverHz},
                  {"phase_margin_deg", d.phaseMarginDeg},
                  {"frf_source", d.frfSource == VelocityLoopData::FrfSource::Session ? "session" : "measurement"},
                  {"frf_session", d.frfSession},
                  {"step_rad_s", d.stepRadS},
                  {"step_duration_s", d.stepDurationS},
                  {"before",
                   {{"velocity_kp", d.before.kpNmsPerRad},
                    {"velocity_ki", d.before.kiNmPerRad},
                    {"position_kp", d.positionKpBefore}}},
                  {"velocity_period_s", d.velocityPeriodS},
                  {"current_period_s", d.currentPeriodS}};
    if (d.model)
        rec.inputs["model"] = {{"Jm_kgm2", d.model->jmKgm2},
                               {"JL_kgm2", d.model->jlKgm2},
                               {"K_Nm_per_rad", d.model->kNmPerRad},
                               {"C_Nms_per_rad", d.model->cNmsPerRad}};
    if (d.measured)
        rec.captures.push_back({"measured", store::frfAsCapture(*d.measured)});
    if (d.plant)
        rec.captures.push_back({"plant", store::frfAsCapture(*d.plant)});
    if (d.stepBefore)
        rec.captures.push_back({"step_before", *d.stepBefore});
    if (d.stepAfter)
        rec.captures.push_back({"step_after", *d.stepAfter});
    if (!d.fHz.empty() && d.error.isEmpty()) {
        dsp::FrequencyResponse l, t;
        l.metadata.set(model::meta::kContentOf, "predicted open loop");
        t.metadata.set(model::meta::kContentOf, "predicted closed loop");
        for (std::size_t i = 0; i < d.fHz.size(); ++i) {
            l.push(d.fHz[i], d.openLoop[i], std::nan(""), true);
            t.push(d.fHz[i], d.closedLoop[i], std::nan(""), true);
        }
        rec.captures.push_back({"predicted_open_loop", store::frfAsCapture(l)});
        rec.captures.push_back({"predicted", store::frfAsCapture(t)});
        nlohmann::json proposal = d.design ? tuning::velocityLoopProposalJson(*d.design) : nlohmann::json::object();
        proposal["rule"] = d.rule.toStdString(); // as the page showed it (translated)
        rec.results.push_back({"proposal", proposal, {}});
        if (d.predictedAfter)
            rec.results.push_back(
                {"step_prediction",
                 {{"step_rad_s", d.stepRadS}},
                 {{"t_s", d.predictedAfter->tS},
                  {"after_rad_s", d.predictedAfter->motorVelRadS},
                  {"before_rad_s", d.predictedBefore ? d.predictedBefore->motorVelRadS : std::vector<double>{}}}});
        if (!m_ctx.machine().isEmpty() && !rec.info.axis.empty()) {
            const model::ParameterValues v =
                d.design ? tuning::velocityLoopParameters(*d.design, true) : model::ParameterValues{};
            rec.parameterSets.push_back(
                {0, rec.info.axis, store::ParameterSource::Proposed, {}, "velocity-loop wizard", v});
        }
    }
    if (m_apply->applied())
        rec.parameterSets.push_back(
            {0, rec.info.axis, store::ParameterSource::Applied, {}, "velocity-loop wizard", m_apply->readBack()});
    rec.journal = m_apply->journal();
    auto id = m_ctx.saveSession(rec);
    sessionStored(id ? *id : 0, aborted);
}

} // namespace gui
} // namespace axistune

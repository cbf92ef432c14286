// SPDX-License-Identifier: GPL-3.0-or-later
// Lost-motion wizard: page order, the summary page and the session record (LostMotionWizard.h,
// docs/wizards/lost-motion.md). Method: spec/lost-motion-and-two-inertia.md §1.7–1.10, §4.2–4.6.
#include "app/gui/LostMotionWizard.h"

#include "app/gui/AbortGuard.h"
#include "app/gui/AppContext.h"
#include "app/gui/BallBarText.h"
#include "app/gui/WizardPages.h"
#include "app/gui/WizardRegistry.h"
#include "core/model/CircleDirectionName.h"
#include "core/model/MetadataKeys.h"
#include "core/model/ResultJson.h"
#include "core/store/SessionRecord.h"

#include <QLabel>
#include <QVBoxLayout>

#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

namespace {

model::Capture traceCapture(const io::BallBarTrace& t)
{
    model::Capture c;
    c.metadata = t.metadata;
    c.metadata.set(model::meta::kContent, "ballbar");
    c.metadata.set(model::meta::kSource, t.source);
    c.metadata.set(model::meta::kRadiusM, t.radiusM);
    c.metadata.set("feed_m_per_s", t.feedMPerS);
    c.metadata.set(model::meta::kDirection, model::circleDirectionName(t.direction));
    c.metadata.set(model::meta::kPlane, t.plane);
    c.metadata.set("center_x_m", t.centerXM);
    c.metadata.set("center_y_m", t.centerYM);
    if (t.dTxNm)
        c.metadata.set("dT_x_Nm", *t.dTxNm);
    if (t.dTyNm)
        c.metadata.set("dT_y_Nm", *t.dTyNm);
    c.channels.push_back({"angle_rad", t.angleRad});
    c.channels.push_back({"deviation_m", t.deviationM});
    return c;
}

const WizardRegistrar kRegistrar{"lost-motion", QT_TRANSLATE_NOOP("Wizards", "Lost motion…"), 50,
                                 [](AppContext& ctx, QWidget* parent) -> QWizard* {
                                     return new LostMotionWizard(ctx, parent);
                                 },
                                 false};

}  // namespace

LostMotionSavePage::LostMotionSavePage(AppContext& ctx, LostMotionData& shared, ApplyPage* apply, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared), m_apply(apply)
{
    setTitle(tr("Save"));
    setSubTitle(tr("The session holds the traces, the diagnostics, A and B with their points, the proposal, what "
                   "was applied with its journal, and the verification."));
    auto* lay = new QVBoxLayout(this);
    m_text = new QLabel(this);
    m_text->setObjectName("lmSummary");
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    lay->addWidget(m_text);
    lay->addStretch(1);
    setFinalPage(true);
}

void LostMotionSavePage::initializePage()
{
    auto* w = qobject_cast<LostMotionWizard*>(wizard());
    if (w && w->savedSessionId() == 0)
        w->saveSession(false, {});
    QString text;
    if (m_d.fit)
        text += tr("Axis %1: A = %2 µm/(N·m), B = %3 µm/(N·m·m), x₀ = %4 mm.")
                    .arg(m_d.axisName())
                    .arg(m_d.fit->aMPerNm * 1e6, 0, 'f', 3)
                    .arg(m_d.fit->bPerNm * 1e6, 0, 'f', 2)
                    .arg(m_d.screwOffsetM * 1e3);
    if (!m_ctx.drive().isConnected())
        text += "\n" + tr("Not connected: applying the compensation and verifying it with a new circle need a "
                          "connection to the machine.");
    else if (!m_apply->applied())
        text += "\n" + tr("Not applied: the proposal is kept in the session.");
    else if (m_d.stepBeforeM && m_d.stepAfterM)
        text += "\n" + tr("Applied; reversal step %1 µm before, %2 µm after.")
                           .arg(*m_d.stepBeforeM * 1e6, 0, 'f', 2)
                           .arg(*m_d.stepAfterM * 1e6, 0, 'f', 2);
    text += "\n" + (w && w->savedSessionId() > 0 ? tr("Saved as session %1.").arg(w->savedSessionId())
                                                 : tr("The session was not saved (no store open)."));
    m_text->setText(text);
}

LostMotionWizard::LostMotionWizard(AppContext& ctx, QWidget* parent) : TuningWizard(parent), m_ctx(ctx)
{
    setWindowTitle(tr("Lost motion"));
    setObjectName("lostMotionWizard");
    m_source = new LostMotionSourcePage(ctx, m_data, this);
    m_safety = new SafetyPage(ctx, this);
    m_safety->setMotionDescription(
        tr("Circle tests: both axes of the plane move together on circles (radius and centres as set on the first "
           "page) at the programmed feed, one circle per table position, and once more for the verification."));
    m_safety->setLimitKeys({"position.kp", "velocity.kp", "lostmotion.mode"});
    m_circles = new LostMotionCirclePage(ctx, m_data, this);
    m_diag = new LostMotionDiagnosticsPage(m_data, this);
    m_apply = new ApplyPage(ctx, this);
    m_apply->setObjectName("lmApply");
    auto* fit = new LostMotionFitPage(ctx, m_data, m_apply, this);
    auto* verify = new LostMotionVerifyPage(ctx, m_data, m_apply, this);
    auto* save = new LostMotionSavePage(ctx, m_data, m_apply, this);
    setPage(Source, m_source);
    setPage(Safety, m_safety);
    setPage(Circles, m_circles);
    setPage(Diagnostics, m_diag);
    setPage(Fit, fit);
    setPage(Apply, m_apply);
    setPage(Verify, verify);
    setPage(Save, save);
    setStartId(Source);
    guardEarlyStops(
        ctx, m_apply, {}, tr("the lost-motion compensation"), [this] { return !m_data.traces.empty(); },
        [this, verify] {
            m_circles->cleanupPage();  // aborts a running circle
            verify->cleanupPage();
        });
    connect(m_circles, &LostMotionCirclePage::runFailed, guard(), &AbortGuard::runFailed);
    connect(verify, &LostMotionVerifyPage::runFailed, guard(), &AbortGuard::runFailed);
    resize(1000, 700);
}

void LostMotionWizard::saveSession(bool aborted, const QString& reason)
{
    const auto& d = m_data;
    store::SessionRecord rec;
    rec.info.kind = "lost-motion";
    rec.info.axis = d.axisName().toStdString();
    rec.info.status = aborted ? store::SessionStatus::Aborted : store::SessionStatus::Completed;
    rec.info.note = reason.toStdString();
    nlohmann::json files = nlohmann::json::array();
    for (const auto& f : d.files)
        files.push_back(f.toStdString());
    rec.inputs = {{"source", d.fromMachine ? "circle-tests" : "files"},
                  {"files", files},
                  {"plane", d.plane.toStdString()},
                  {"axis", d.axisName().toStdString()},
                  {"axis_role", d.axisRole},
                  {"screw_offset_m", d.screwOffsetM},
                  {"screw_sign", d.screwSign},
                  {"exclude_deg", d.options.excludeDeg},
                  {"window_deg", d.options.fitWindowDeg},
                  {"radius_m", d.radiusM},
                  {"feed_m_per_s", d.feedMPerS},
                  {"centres_m", d.centresM}};
    for (std::size_t i = 0; i < d.traces.size(); ++i)
        rec.captures.push_back({"trace-" + std::to_string(i + 1), traceCapture(d.traces[i])});
    if (d.verification)
        rec.captures.push_back({"verification", traceCapture(*d.verification)});
    if (d.report) {
        nlohmann::json f = nlohmann::json::array();
        for (const auto& x : d.report->findings)
            f.push_back(BallBarText::findingJson(x));
        nlohmann::json refused = nlohmann::json::array();
        for (const auto& r : d.report->refused)
            refused.push_back(BallBarText::refusalJson(r));
        rec.results.push_back({"diagnostics", {{"findings", f}, {"refused", refused}}, {}});
    }
    if (d.fit) {
        nlohmann::json pts = nlohmann::json::array();
        for (std::size_t i = 0; i < d.points.size(); ++i)
            pts.push_back({{"x_m", d.points[i].xM},
                           {"dT_Nm", d.points[i].dTNm},
                           {"dx_m", d.points[i].dxM},
                           {"residual_m", i < d.fit->residualsM.size() ? d.fit->residualsM[i] : 0.0},
                           {"source", d.points[i].source}});
        nlohmann::json fit{{"A_m_per_Nm", d.fit->aMPerNm},
                           {"B_per_Nm", d.fit->bPerNm},
                           {"method", tuning::lostMotionMethodName(d.fit->method)},
                           {"residual_rms_m", d.fit->residualRmsM},
                           {"warnings", d.fit->warnings},
                           {"points", pts},
                           {"conventional_backlash_m", d.conventionalBacklashM}};
        const char* noStdErr = "no standard error: the fit has no more points than unknowns";
        model::putOptional(fit, "A_stderr_m_per_Nm", d.fit->aStdErr, 1.0, noStdErr);
        model::putOptional(fit, "B_stderr_per_Nm", d.fit->bStdErr, 1.0, noStdErr);
        rec.results.push_back({"fit", fit, {}});
        if (!d.predictions.empty()) {
            const auto& p = d.predictions.back();
            nlohmann::json pj{{"trace", d.traces.back().source},
                              {"measured_cut_in_m", p.measuredCutInM},
                              {"proposed_cut_in_m", p.proposedCutInM},
                              {"conventional_cut_in_m", p.conventionalCutInM}};
            const char* noCircle = "the trace is not a full circle";
            model::putOptional(pj, "measured_circularity_m", p.measuredCircularityM, 1.0, noCircle);
            model::putOptional(pj, "proposed_circularity_m", p.proposedCircularityM, 1.0, noCircle);
            model::putOptional(pj, "conventional_circularity_m", p.conventionalCircularityM, 1.0, noCircle);
            rec.results.push_back({"prediction",
                                   pj,
                                   {{"angle_rad", p.angleRad},
                                    {"measured_m", p.measuredM},
                                    {"proposed_m", p.proposedM},
                                    {"conventional_m", p.conventionalM}}});
        }
        const model::ParameterValues proposal{{"lostmotion.mode", 2.0},
                                              {"lostmotion.A", d.fit->aMPerNm},
                                              {"lostmotion.B", d.fit->bPerNm},
                                              {"lostmotion.screw_offset", d.screwOffsetM}};
        const bool known = !m_ctx.machine().isEmpty();
        if (known) {
            rec.parameterSets.push_back({0, rec.info.axis, store::ParameterSource::Proposed, {}, "lost-motion wizard", proposal});
            rec.models.push_back({0,
                                  rec.info.axis,
                                  "lost_motion",
                                  {},
                                  {{"A_m_per_Nm", d.fit->aMPerNm},
                                   {"B_per_Nm", d.fit->bPerNm},
                                   {"screw_offset_m", d.screwOffsetM},
                                   {"screw_sign", d.screwSign}}});
        }
    }
    if (d.verification) {
        nlohmann::json v = nlohmann::json::object();
        const char* noStep = "no reversal step measured";
        const char* noCircle = "no full-circle trace measured";
        model::putOptional(v, "step_before_m", d.stepBeforeM, 1.0, noStep);
        model::putOptional(v, "step_after_m", d.stepAfterM, 1.0, noStep);
        model::putOptional(v, "predicted_step_after_m", d.predictedStepAfterM, 1.0, noStep);
        model::putOptional(v, "circularity_before_m", d.circularityBeforeM, 1.0, noCircle);
        model::putOptional(v, "circularity_after_m", d.circularityAfterM, 1.0, noCircle);
        model::putOptional(v, "predicted_circularity_m", d.predictedCircularityM, 1.0, noCircle);
        rec.results.push_back({"verification", v, {}});
    }
    if (m_apply->applied()) {
        rec.parameterSets.push_back(
            {0, rec.info.axis, store::ParameterSource::Applied, {}, "lost-motion wizard", m_apply->readBack()});
    }
    rec.journal = m_apply->journal();
    auto id = m_ctx.saveSession(rec);
    sessionStored(id ? *id : 0, aborted);
}

}  // namespace gui
}  // namespace axistune

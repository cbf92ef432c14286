// SPDX-License-Identifier: GPL-3.0-or-later
// The notch wizard: flow, failure handling (restore of applied notches) and the session record.
// Analysis: resonances (tuning::findResonances), notch proposal (tuning::proposeNotches, spec
// current-loop-and-multisweep-frf.md §3.8 and §4.4 "Wizard D"), prediction (tuning::predictWithNotches);
// rules in docs/notch.md, the wizard in docs/wizards/notch.md.
#include "app/gui/NotchWizard.h"

#include "app/gui/AppContext.h"
#include "app/gui/NcPidPage.h"
#include "app/gui/WizardRegistry.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/dsp/LoopMarginsJson.h"
#include "core/model/ResultJson.h"
#include "core/store/FrfCapture.h"
#include "core/store/SessionRecord.h"
#include "core/tuning/VelocityLoopDesign.h"

#include <QBoxLayout>
#include <QCheckBox>
#include <QCoreApplication>
#include <QLabel>
#include <QPushButton>

#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

namespace {

const WizardRegistrar kRegistrar{"notch", QT_TRANSLATE_NOOP("Wizards", "Notch filters…"), 20,
                                 [](AppContext& ctx, QWidget* parent) -> QWizard* { return new NotchWizard(ctx, parent); }};

/// Margins before/predicted/verified; one not measured is left out and named (docs/formats.md
/// "Undefined values", never null).
void putMargins(nlohmann::json& j, const char* key, const std::optional<dsp::LoopMargins>& m)
{
    if (m)
        j[key] = dsp::loopMarginsJson(*m);
    else
        model::putUndefined(j, key, "not measured");
}

QLabel* addNote(TestRunPage* page, const QString& name)
{
    auto* label = new QLabel(page);
    label->setObjectName(name);
    label->setWordWrap(true);
    label->setStyleSheet("QLabel { color: #b00000; }");
    if (auto* box = qobject_cast<QBoxLayout*>(page->layout()))
        box->addWidget(label);
    return label;
}

}  // namespace

NotchWizard::NotchWizard(AppContext& ctx, QWidget* parent) : QWizard(parent), m_ctx(ctx)
{
    setObjectName("notchWizard");
    setWindowTitle(tr("Notch filters"));
    setWizardStyle(QWizard::ClassicStyle);
    setOption(QWizard::NoBackButtonOnLastPage, true);
    setOption(QWizard::NoCancelButtonOnLastPage, true);
    resize(1000, 700);
    m_notchOptions.maxNotches = m_notchOptions.slotCount;

    m_source = new NotchSourcePage(*this, ctx);
    m_safety = new SafetyPage(ctx, this);
    m_safety->setObjectName("notchSafetyPage");
    m_safety->setMotionDescription(
        tr("A multi-sweep frequency-response test: a sinusoidal torque of the chosen amplitude (in % of the rated "
           "torque) is added to the velocity controller's output at each frequency of the band, three times with "
           "phase offsets of 0°, +120° and −120°, while the velocity loop holds the axis. The axis vibrates a little "
           "around its position; it does not travel."));
    m_safety->setLimitKeys({"motor.rated_current", "motor.max_current", "velocity.kp", "velocity.ki",
                            "filter.notch1.center", "filter.notch2.center", "filter.notch3.center", "filter.notch4.center"});
    m_measureRun = new TestRunPage(ctx, this);
    m_measureRun->setObjectName("notchMeasurePage");
    m_measureRun->setTitle(tr("Measure the frequency response"));
    m_measureRun->setRequestFactory([this] { return std::vector<device::TestRequest>{frfRequest()}; });
    m_propose = new NotchProposePage(*this, ctx);
    m_apply = new ApplyPage(ctx, this);
    m_apply->setObjectName("notchApplyPage");
    m_apply->setTitle(tr("Apply the notch filters"));
    m_verifyRun = new TestRunPage(ctx, this);
    m_verifyRun->setObjectName("notchVerifyRunPage");
    m_verifyRun->setTitle(tr("Verify: measure again with the notches"));
    m_verifyRun->setRequestFactory([this] { return std::vector<device::TestRequest>{frfRequest()}; });
    m_verifyPage = new NotchVerifyPage(*this);
    m_save = new NotchSavePage(*this);

    setPage(kSource, m_source);
    setPage(kSafety, m_safety);
    setPage(kMeasure, m_measureRun);
    setPage(kPropose, m_propose);
    setPage(kApply, m_apply);
    setPage(kVerifyRun, m_verifyRun);
    setPage(kVerify, m_verifyPage);
    setPage(kSave, m_save);
    m_ncPid = new NcPidPage(ctx, autotune::PidTuneScope::NotchOnly, this);
    setPage(kNcPid, m_ncPid);
    setStartId(kSource);

    addNote(m_measureRun, "measureAbortNote");
    addNote(m_verifyRun, "verifyAbortNote");

    connect(m_measureRun, &TestRunPage::runFinished, this, [this](bool ok) {
        if (!ok) {
            onRunFailed(m_measureRun, false);
            return;
        }
        const auto& r = m_measureRun->replies();
        if (!r.empty() && r.back().frf)
            setMeasured(r.back().frf->frf, QStringLiteral("measurement"));
    });
    connect(m_verifyRun, &TestRunPage::runFinished, this, [this](bool ok) {
        if (!ok) {
            onRunFailed(m_verifyRun, true);
            return;
        }
        const auto& r = m_verifyRun->replies();
        if (!r.empty() && r.back().frf)
            setVerification(r.back().frf->frf);
    });
    AbortGuard::Hooks hooks;
    hooks.saved = [this] { return saved(); };
    hooks.hasData = [this] { return hasMeasured(); };
    hooks.saveAborted = [this](const QString& why) { saveSession(store::SessionStatus::Aborted, why); };
    hooks.close = [this] { QWizard::reject(); };
    m_guard = new AbortGuard(ctx, m_apply, {m_measureRun, m_verifyRun}, tr("the notch filters"), hooks, this);
    connect(this, &QWizard::currentIdChanged, this, [this](int id) {
        if (id == kSafety && m_ctx.drive().isConnected())
            readTraceRate(m_axis.isEmpty() ? (m_ctx.axes().isEmpty() ? QString() : m_ctx.axes().front()) : m_axis);
    });
    connect(m_safety->confirmation(), &QCheckBox::toggled, this, [this] {
        const QString a = field("axis").toString();
        if (!a.isEmpty()) {
            m_axis = a;
            readTraceRate(a);
        }
    });
}

NotchWizard::~NotchWizard() = default;

void NotchWizard::setSourceFrf(const dsp::FrequencyResponse& frf, const QString& axis, const QString& origin)
{
    m_axis = axis;
    setMeasured(frf, origin.isEmpty() ? QStringLiteral("given") : origin);
    setStartId(kPropose);
    if (isVisible())
        restart();
}

void NotchWizard::setMeasured(const dsp::FrequencyResponse& frf, const QString& origin, std::int64_t sessionId)
{
    m_measured = frf;
    m_origin = origin;
    m_sourceSession = sessionId;
    if (m_machine.isEmpty())
        m_machine = m_ctx.machine();
}

void NotchWizard::readTraceRate(const QString& axis)
{
    if (axis.isEmpty() || !m_ctx.drive().isConnected())
        return;
    auto* req = m_ctx.drive().readParameters(axis, {"velocity.period", "trace.divider"});
    m_traceRequest = req->id();
    connect(req, &DriveRequest::finished, this, [this](const DriveReply& r) {
        if (r.id == m_traceRequest && r.ok) {
            const auto vp = r.values.find("velocity.period");
            const auto div = r.values.find("trace.divider");
            if (vp != r.values.end() && div != r.values.end() && vp->second > 0.0)
                m_traceRateHz = 1.0 / (vp->second * std::max(1.0, div->second));
        }
    });
}

tuning::LoopForm NotchWizard::loopForm() const
{
    // One parser of loop measurements (core/tuning/VelocityLoopDesign.h); no key: the drives' complementary FRF.
    // A value that is not a loop form (plant, unknown) is analysed as complementary, as before.
    const auto kind = tuning::loopMeasurementOf(m_measured, tuning::LoopMeasurementKind::Complementary);
    if (!kind)
        return {};
    auto f = tuning::loopFormOf(*kind);
    return f ? *f : tuning::LoopForm{};
}

device::TestRequest NotchWizard::frfRequest() const
{
    device::TestRequest r;
    r.axis = (m_axis.isEmpty() ? field("axis").toString() : m_axis).toStdString();
    auto& f = r.test.emplace<device::FrfTest>();
    f.method = device::FrfMethod::MultiSweep;
    f.amplitudePct = m_source->amplitudePct();
    if (!m_measured.empty()) {  // verification: the band and points of the source FRF
        f.fminHz = m_measured.freqHz.front();
        f.fmaxHz = m_measured.freqHz.back();
        f.points = static_cast<int>(std::min<std::size_t>(m_measured.size(), 400));
        return r;
    }
    f.fminHz = m_source->fminHz();
    const double fs = m_traceRateHz > 0.0 ? m_traceRateHz : 4000.0;
    f.fmaxHz = m_source->fmaxHz() > 0.0 ? m_source->fmaxHz() : 0.975 * fs;
    f.points = m_source->points();
    return r;
}

int NotchWizard::nextId() const
{
    switch (currentId()) {
    case kSource:
        return m_source->nextId();
    case kSafety:
        return hasMeasured() ? kVerifyRun : kMeasure;
    case kMeasure:
        return kPropose;
    case kPropose:
        return m_propose->nextId(); // kApply, or kNcPid for a position PID the NC closes
    case kApply:
        return m_apply->applied() ? (visitedIds().contains(kSafety) ? kVerifyRun : kSafety) : kSave;
    case kVerifyRun:
        return kVerify;
    case kVerify:
        return kSave;
    default:
        return -1;
    }
}

void NotchWizard::setDriveContext(double execRateHz, int slotCount, const std::map<int, dsp::NotchSpec>& existing)
{
    m_execRateHz = execRateHz;
    m_slotCount = slotCount;
    m_existing = existing;
    m_notchOptions.execRateHz = execRateHz;
    m_notchOptions.slotCount = slotCount;
    m_notchOptions.maxNotches = slotCount;
}

void NotchWizard::setAnalysis(const NotchAnalysis& a)
{
    m_analysis = a;
    m_rows = a.rows;
    if (a.error.isEmpty()) {
        m_before = a.prediction.before;
        m_after = a.prediction.after;
        m_predicted = a.prediction.measuredAfter;
    }
}

bool NotchWizard::setRows(const std::vector<NotchRow>& rows, QString* why)
{
    std::vector<dsp::NotchSpec> specs;
    for (const auto& r : rows) {
        const auto st = tuning::checkExistingNotch(r.spec, m_execRateHz, "slot " + std::to_string(r.slot));
        if (!st) {
            if (why)
                *why = QString::fromStdString(st.error().detail);
            return false;
        }
        specs.push_back(r.spec);
    }
    auto pred = tuning::predictWithNotches(m_measured, loopForm(), specs, m_execRateHz);
    if (!pred) {
        if (why)
            *why = QString::fromStdString(pred.error().detail);
        return false;
    }
    m_rows = rows;
    m_before = pred->before;
    m_after = pred->after;
    m_predicted = pred->measuredAfter;
    return true;
}

model::ParameterValues NotchWizard::proposedValues() const
{
    model::ParameterValues v;
    for (const auto& r : m_rows) {
        const std::string k = "filter.notch" + std::to_string(r.slot);
        v[k + ".center"] = r.spec.centerHz;
        v[k + ".width"] = r.spec.widthHz;
        v[k + ".depth"] = r.spec.depth;
    }
    return v;
}

void NotchWizard::setVerification(const dsp::FrequencyResponse& frf)
{
    m_verification = frf;
    m_deviation = tuning::compareMagnitudes(m_predicted, m_verification, -50.0);
    auto v = tuning::predictWithNotches(m_verification, loopForm(), {}, m_execRateHz);
    if (v)
        m_verified = v->before;
}

void NotchWizard::onRunFailed(TestRunPage* page, bool verification)
{
    if (verification)
        page->retryButton()->setEnabled(false);  // the notches may be restored now: a re-run verifies nothing
    m_guard->runFailed(page->failure());
}

void NotchWizard::reject()
{
    if (!m_guard->reject())
        QWizard::reject();
}

void NotchWizard::saveCompleted()
{
    if (!saved())
        saveSession(store::SessionStatus::Completed, {});
}

void NotchWizard::saveSession(store::SessionStatus status, const QString& note)
{
    store::SessionRecord rec;
    rec.info.kind = "notch";
    rec.info.machine = (m_machine.isEmpty() ? m_ctx.machine() : m_machine).toStdString();
    rec.info.axis = m_axis.toStdString();
    rec.info.status = status;
    rec.info.note = note.toStdString();
    if (m_ctx.drive().identity())
        rec.machineAxes = m_ctx.drive().identity()->axes;
    const auto request = frfRequest();
    const auto& req = request.frf();
    rec.inputs = {{"source", m_origin.toStdString()},
                  {"axis", m_axis.toStdString()},
                  {"method", "multisweep"},
                  {"fmin_Hz", req.fminHz},
                  {"fmax_Hz", req.fmaxHz},
                  {"points", req.points},
                  {"amplitude_pct", req.amplitudePct},
                  {"exec_rate_Hz", m_execRateHz},
                  {"slots", m_slotCount},
                  {"min_height_dB", m_resOptions.minHeightDb},
                  {"target_open_loop_dB", m_notchOptions.targetOpenLoopDb},
                  {"loop", loopForm().open ? "open" : "closed"}};
    if (m_sourceSession > 0)
        rec.inputs["source_session"] = m_sourceSession;
    rec.inputs["existing"] = nlohmann::json::array();
    for (const auto& [slot, n] : m_existing)
        rec.inputs["existing"].push_back({{"slot", slot}, {"center_Hz", n.centerHz}, {"width_Hz", n.widthHz}, {"depth", n.depth}});
    if (!m_measured.empty())
        rec.captures.push_back({"measured", store::frfAsCapture(m_measured)});
    if (!m_predicted.empty() && !m_rows.empty())
        rec.captures.push_back({"predicted", store::frfAsCapture(m_predicted)});
    if (!m_verification.empty())
        rec.captures.push_back({"verification", store::frfAsCapture(m_verification)});

    nlohmann::json res = nlohmann::json::array();
    for (const auto& r : m_analysis.resonances)
        res.push_back({{"f_Hz", r.freqHz}, {"peak_dB", r.peakDb}, {"width_Hz", r.widthHz}, {"open_loop_dB", r.levelDb}});
    nlohmann::json notches = nlohmann::json::array();
    for (const auto& r : m_rows)
        notches.push_back({{"slot", r.slot},
                           {"center_Hz", r.spec.centerHz},
                           {"width_Hz", r.spec.widthHz},
                           {"depth", r.spec.depth},
                           {"resonance_Hz", r.resonanceHz},
                           {"rule", r.rule.toStdString()}});
    nlohmann::json skipped = nlohmann::json::array();
    for (const auto& s : m_analysis.proposal.skipped)
        skipped.push_back({{"f_Hz", s.freqHz}, {"reason", s.reason}});
    if (!m_analysis.resonances.empty() || !m_rows.empty()) {
        rec.results.push_back({"resonances", res, {}});
        rec.results.push_back({"notches", {{"notches", notches}, {"skipped", skipped}}, {}});
    }
    if (m_before) {
        nlohmann::json margins = nlohmann::json::object();
        putMargins(margins, "before", m_before);
        putMargins(margins, "predicted", m_after);
        putMargins(margins, "verified", m_verified);
        rec.results.push_back({"margins", margins, {}});
    }
    if (!m_verification.empty()) {
        nlohmann::json peaks = nlohmann::json::array();
        for (const auto& r : m_rows) {
            const char* noPoint = "no valid point within 5 % of the centre";
            nlohmann::json p{{"center_Hz", r.spec.centerHz}};
            model::putNumber(p, "measured_dB", tuning::peakMagnitudeDb(m_measured, r.spec.centerHz, 0.05), noPoint);
            model::putNumber(p, "predicted_dB", tuning::peakMagnitudeDb(m_predicted, r.spec.centerHz, 0.05), noPoint);
            model::putNumber(p, "verified_dB", tuning::peakMagnitudeDb(m_verification, r.spec.centerHz, 0.05), noPoint);
            peaks.push_back(p);
        }
        nlohmann::json v{{"compared_points", m_deviation.points}, {"floor_dB", -50.0}, {"peaks", peaks}};
        const char* noCompared = "no point above the floor to compare";
        model::putNumber(v, "max_abs_deviation_dB", m_deviation.maxAbsDb, noCompared);
        model::putNumber(v, "max_deviation_at_Hz", m_deviation.maxAtHz, noCompared);
        model::putNumber(v, "rms_deviation_dB", m_deviation.rmsDb, noCompared);
        rec.results.push_back({"verification", v, {}});
    }
    if (!m_rows.empty()) {
        store::ParameterSet ps;
        ps.axis = m_axis.toStdString();
        ps.source = store::ParameterSource::Proposed;
        ps.note = "notch wizard";
        ps.values = proposedValues();
        rec.parameterSets.push_back(ps);
    }
    if (m_apply->applied()) {
        store::ParameterSet ps;
        ps.axis = m_axis.toStdString();
        ps.source = store::ParameterSource::Applied;
        ps.note = "notch wizard, read back";
        ps.values = m_apply->readBack();
        rec.parameterSets.push_back(ps);
    }
    rec.journal = m_apply->journal();
    auto id = m_ctx.saveSession(rec);
    m_savedId = id ? *id : -1;
    m_savedAborted = status != store::SessionStatus::Completed;
    m_abortReason = m_savedAborted ? note : QString();
    const QString text = !id ? tr("The session could not be saved: %1").arg(QString::fromStdString(id.error().detail))
                         : m_savedAborted ? tr("Stopped: %1 Session %2 saved as aborted.").arg(note).arg(*id)
                                          : tr("Session %1 saved.").arg(*id);
    if (m_savedAborted) {
        for (auto* name : {"measureAbortNote", "verifyAbortNote"})
            if (auto* l = findChild<QLabel*>(name))
                l->setText(currentPage() && currentPage()->isAncestorOf(l) ? text : QString());
    }
    m_ctx.log(text);
}

}  // namespace gui
}  // namespace axistune

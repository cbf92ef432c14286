// SPDX-License-Identifier: GPL-3.0-or-later
// The frequency-response wizard (issue 8 item 4; docs/wizards/frf.md): safety → method and band →
// run → Bode with validity bands and resonances → session. The test itself is the drive's FRF test
// (docs/frequency-response-sim.md); the session stores the FRF only through store::frfAsCapture.
#include "app/gui/FrfWizard.h"

#include "app/gui/AppContext.h"
#include "app/gui/NotchWizard.h"
#include "app/gui/SessionReviewView.h"
#include "app/gui/WizardRegistry.h"
#include "core/device/AdaptiveFrf.h"
#include "core/device/AdaptiveFrfJson.h"
#include "core/device/FrfQuantityName.h"
#include "core/device/FrfTest.h"
#include "core/model/Constants.h"
#include "core/store/Database.h"
#include "core/store/FrfCapture.h"
#include "core/store/SessionRecord.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

namespace {
const WizardRegistrar kRegistrar{"frf", QT_TRANSLATE_NOOP("Wizards", "Frequency response…"), 10,
                                 [](AppContext& ctx, QWidget* parent) -> QWizard* { return new FrfWizard(ctx, parent); }};
}  // namespace

FrfWizard::FrfWizard(AppContext& ctx, QWidget* parent) : QWizard(parent), m_ctx(ctx)
{
    setObjectName("frfWizard");
    setWindowTitle(tr("Frequency response"));
    setWizardStyle(QWizard::ClassicStyle);
    setOption(QWizard::NoBackButtonOnLastPage, false);
    resize(1000, 700);
    m_safety = new FrfSafetyPage(ctx, this);
    m_config = new FrfConfigPage(ctx, *m_safety, this);
    m_run = new TestRunPage(ctx, this);
    m_run->setObjectName("frfRunPage");
    m_result = new FrfResultPage(this);
    m_save = new FrfSavePage(this);
    setPage(SafetyId, m_safety);
    setPage(ConfigId, m_config);
    setPage(RunId, m_run);
    setPage(ResultId, m_result);
    setPage(SaveId, m_save);
    m_run->setRequestFactory([this] {
        m_lastRequest = request();
        m_lastBudgetS = m_config->adaptiveBudgetS();
        m_adaptive.reset();
        m_measurement.reset();
        m_runSaved = false;
        return std::vector<device::TestRequest>{m_lastRequest};
    });
    m_run->setRunner([this](const device::TestRequest& r) {
        if (!m_lastBudgetS)
            return m_ctx.drive().runTest(r);
        device::AdaptiveFrfOptions o;
        o.timeBudgetS = *m_lastBudgetS;
        return m_ctx.drive().runAdaptiveFrf(r, o);
    });
    connect(m_run, &TestRunPage::runFinished, this, &FrfWizard::onRunFinished);
    connect(this, &QWizard::currentIdChanged, this, &FrfWizard::onPageChanged);
    connect(m_save->openNotchButton(), &QPushButton::clicked, this, &FrfWizard::openInNotchWizard);
}

device::TestRequest FrfWizard::request() const
{
    device::TestRequest r;
    r.axis = field("axis").toString().toStdString();
    auto& f = r.test.emplace<device::FrfTest>();
    f.method = m_config->selectedMethod();
    f.fminHz = field("fminHz").toDouble();
    f.fmaxHz = field("fmaxHz").toDouble();
    f.points = field("points").toInt();
    f.amplitudePct = field("amplitudePct").toDouble();
    if (m_safety->driveInfo().peakInOutputUnits())
        f.amplitudePeak = field("amplitudePeak").toDouble(); // the drive's output units (hal:: the PID output's)
    f.quantity = m_config->selectedQuantity();
    if (f.method == device::FrfMethod::Multisine && f.points > 0)
        // Lines on a linear grid: at least `points` of them in the band, never coarser than the
        // drive's default fmin/2 (docs/wizards/frf.md).
        f.multisineSpacingHz = std::min(f.fminHz / 2.0, (f.fmaxHz - f.fminHz) / f.points);
    return r;
}

void FrfWizard::onRunFinished(bool ok)
{
    if (!ok) {
        if (!m_runSaved)
            saveAborted(m_run->failure());
        return;
    }
    const auto& replies = m_run->replies();
    if (replies.empty() || !replies.back().frf) {
        saveAborted(tr("The drive returned no frequency response."));
        return;
    }
    m_measurement = replies.back().frf;
    m_adaptive = replies.back().adaptive;
    m_result->setAdaptiveSummary(m_adaptive ? adaptiveSummary(*m_adaptive) : QString());
    m_result->setMeasurement(m_measurement->frf, m_lastRequest.frf().method, m_safety->driveInfo().frfMaxHz(),
                             m_safety->driveInfo().outputSignal());
}

QString FrfWizard::adaptiveSummary(const device::AdaptiveFrfResult& a) const
{
    const std::size_t lines = a.measurement.frf.size();
    QString text =
        tr("Adaptive multisine: %n pass(es), %1 s of motion (budget %2 s); %3 of %4 lines valid (%5 %).", nullptr,
           static_cast<int>(a.passes.size()))
            .arg(a.motionTimeS, 0, 'f', 2)
            .arg(m_lastBudgetS.value_or(0.0), 0, 'f', 1)
            .arg(a.validLines)
            .arg(lines)
            .arg(lines > 0 ? 100.0 * static_cast<double>(a.validLines) / static_cast<double>(lines) : 0.0, 0, 'f', 1);
    if (a.invalid.empty())
        return text;
    const auto n = device::invalidByReason(a);
    using R = device::InvalidReason;
    return text + QLatin1Char(' ') +
           tr("Left invalid: %1 by noise (the budget was spent), %2 held by the voltage limit, %3 by the torque "
              "limit, %4 non-linear (the passes disagree).")
               .arg(n[static_cast<std::size_t>(R::Noise)])
               .arg(n[static_cast<std::size_t>(R::VoltageLimit)])
               .arg(n[static_cast<std::size_t>(R::TorqueLimit)])
               .arg(n[static_cast<std::size_t>(R::Nonlinear)]);
}

void FrfWizard::onPageChanged(int id)
{
    if (id != SaveId)
        return;
    const auto& r = m_lastRequest.frf();
    const int n = static_cast<int>(m_result->analysis().resonances.size());
    // A drive that takes the peak in its output's units (hal:) gets it stored and shown so; the others in % of rated
    // torque with the number of points.
    const bool peak = r.amplitudePeak > 0.0;
    const QString text =
        peak ? tr("Finish stores: the settings (axis %1, %2, %3–%4 Hz, peak %5 in the units of %6), the measured "
                  "frequency response (%7 points) and the %n resonance(s) found.",
                  nullptr, n)
             : tr("Finish stores: the settings (axis %1, %2, %3–%4 Hz, %5 points, %6 % of rated torque), the measured "
                  "frequency response (%7 points) and the %n resonance(s) found.",
                  nullptr, n);
    const QString axis = QString::fromStdString(m_lastRequest.axis);
    m_save->showSaved(text.arg(axis, QString::fromLatin1(device::frfMethodName(r.method)))
                          .arg(r.fminHz)
                          .arg(r.fmaxHz)
                          .arg(peak ? QStringLiteral("%1").arg(r.amplitudePeak) : QString::number(r.points),
                               peak ? m_safety->driveInfo().outputSignal() : QStringLiteral("%1").arg(r.amplitudePct))
                          .arg(m_result->measured().size()));
}

nlohmann::json FrfWizard::inputsJson() const
{
    const auto& r = m_lastRequest.frf();
    nlohmann::json j;
    j["axis"] = m_lastRequest.axis;
    j["method"] = device::frfMethodName(r.method);
    j["fmin_Hz"] = r.fminHz;
    j["fmax_Hz"] = r.fmaxHz;
    j["points"] = r.points;
    if (r.amplitudePeak > 0.0) {
        // The peak in the drive's output units (hal:: the PID output's), and which signal that is.
        j["amplitude_peak"] = r.amplitudePeak;
        j["amplitude_signal"] = m_safety->driveInfo().outputSignal().toStdString();
    } else {
        j["amplitude_pct"] = r.amplitudePct;
        const double rated = m_safety->driveInfo().ratedTorqueNm();
        if (std::isfinite(rated))
            j["amplitude_Nm"] = model::torqueNmFromRatedPct(r.amplitudePct, rated);
    }
    if (r.quantity != device::FrfQuantity::Default)
        j["quantity"] = device::frfQuantityMetadataName(r.quantity);
    j["connection"] = m_ctx.drive().uri().toStdString();
    if (std::isfinite(m_config->estimatedMotionS()))
        j["estimated_motion_s"] = m_config->estimatedMotionS();
    if (m_lastBudgetS) {
        j["adaptive"] = true;
        j["time_budget_s"] = *m_lastBudgetS;
    }
    return j;
}

void FrfWizard::saveCompleted()
{
    if (m_runSaved || !m_measurement)
        return;
    store::SessionRecord rec;
    rec.info.kind = "frf";
    rec.info.axis = m_lastRequest.axis;
    rec.info.status = store::SessionStatus::Completed;
    rec.info.note = m_save->note()->text().toStdString();
    rec.inputs = inputsJson();
    rec.captures.push_back({"measured", store::frfAsCapture(m_result->measured())});
    nlohmann::json res;
    res["analysed"] = m_result->analysis().analysedForm.toStdString();
    res["error"] = m_result->analysis().error.toStdString();
    res["resonances"] = nlohmann::json::array();
    for (const auto& x : m_result->analysis().resonances)
        res["resonances"].push_back({{"frequency_Hz", x.freqHz},
                                     {"peak_dB", x.peakDb},
                                     {"width_Hz", x.widthHz},
                                     {"width_one_sided", x.widthOneSided},
                                     {"open_loop_dB", x.levelDb}});
    rec.results.push_back({"resonances", res, {}});
    nlohmann::json meas;
    meas["motion_time_s"] = m_measurement->motionTimeS;
    meas["fs_Hz"] = m_result->traceRateHz();
    std::size_t valid = 0;
    for (bool v : m_result->measured().valid)
        valid += v ? 1 : 0;
    meas["points"] = m_result->measured().size();
    meas["valid_points"] = valid;
    rec.results.push_back({"measurement", meas, {}});
    if (m_adaptive)
        rec.results.push_back({"adaptive", device::adaptiveFrfJson(*m_adaptive, m_lastBudgetS.value_or(0.0)), {}});
    auto id = m_ctx.saveSession(rec);
    m_runSaved = true;
    if (id) {
        m_sessionId = *id;
        emit sessionSaved(*id);
    }
}

void FrfWizard::saveAborted(const QString& reason)
{
    store::SessionRecord rec;
    rec.info.kind = "frf";
    rec.info.axis = m_lastRequest.axis;
    rec.info.status = store::SessionStatus::Aborted;
    rec.info.note = reason.toStdString();
    rec.inputs = inputsJson();
    m_runSaved = true;
    auto id = m_ctx.saveSession(rec);
    if (id) {
        m_sessionId = *id;
        emit sessionSaved(*id);
    }
}

void FrfWizard::accept()
{
    if (currentId() == SaveId) {
        saveCompleted();
        if (m_save->openDocumentBox()->isChecked() && m_sessionId > 0 && m_ctx.database()) {
            if (auto rec = m_ctx.database()->loadSession(m_sessionId))
                m_ctx.showDocument(new SessionView(std::move(rec).value()),
                                   tr("Session %1 (%2)").arg(m_sessionId).arg(QStringLiteral("frf")));
        }
    }
    QWizard::accept();
}

void FrfWizard::openInNotchWizard()
{
    if (!m_measurement || m_result->measured().empty())
        return;
    saveCompleted();
    auto* notch = new NotchWizard(m_ctx, parentWidget());
    notch->setAttribute(Qt::WA_DeleteOnClose);
    // The origin is data of the notch session, not a user-visible text.
    const QString origin = m_sessionId > 0 ? QStringLiteral("frf wizard, session %1").arg(m_sessionId)
                                           : QStringLiteral("frf wizard");
    notch->setSourceFrf(m_result->measured(), QString::fromStdString(m_lastRequest.axis), origin);
    emit notchWizardOpened(notch);
    notch->show();
    QWizard::accept();
}

void FrfWizard::reject()
{
    if (m_run->isRunning()) {
        m_run->abortRun();
        if (!m_runSaved)
            saveAborted(tr("The wizard was closed during the run."));
    }
    QWizard::reject();
}

}  // namespace gui
}  // namespace axistune

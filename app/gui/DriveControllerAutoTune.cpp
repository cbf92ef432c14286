// SPDX-License-Identifier: GPL-3.0-or-later
// The one-button tuner through the controller (issue 18 item 5; docs/tuning.md "The wizard"): the whole sequence
// of core/autotune runs as one request on the drive thread, like a test: the Drive is never touched from another
// thread, the request's cancel token is the sequence's abort token, and the progress and the step records are
// sent back to the GUI thread as signals of the request.
#include "app/gui/DriveController.h"

#include <QCoreApplication>

#include <algorithm>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

DriveReply DriveWorker::doAutoTune(int id, autotune::Options options, std::shared_ptr<std::atomic<bool>> cancel)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::AutoTune;
    r.axis = QString::fromStdString(options.axis);
    if (auto refused = refuseBeforeStart(r, *cancel))
        return *refused;
    // The bar counts the nine steps equally; within a step it follows the running test. It never falls (a second
    // design attempt runs steps 5 to 8 again while the bar waits).
    const auto& names = autotune::stepNames();
    const double nSteps = static_cast<double>(names.size());
    double stepIndex = 0.0, shown = 0.0, lastReported = -1.0;
    auto report = [&](double f, const QString& detail) {
        shown = std::max(shown, std::clamp(f, 0.0, 1.0));
        if (shown - lastReported >= 0.005 || shown >= 1.0) {
            lastReported = shown;
            emit progress(id, shown, detail);
        }
    };
    options.run.abort = cancel.get();
    options.run.progress = [&](double f, const std::string& detail) {
        drainSide(); // scope requests between the test's polls
        report((stepIndex + std::clamp(f, 0.0, 1.0)) / nSteps, QString::fromStdString(detail));
    };
    options.stepStarted = [&](const std::string& name) {
        const auto it = std::find(names.begin(), names.end(), name);
        stepIndex = static_cast<double>(it - names.begin());
        report(stepIndex / nSteps, {});
        emit autoTuneStep(id, QString::fromStdString(name), false, {});
    };
    options.stepFinished = [&](const autotune::Step& s) {
        const nlohmann::json j{{"name", s.name},
                               {"measured", s.measured},
                               {"chosen", s.chosen},
                               {"rule", s.rule},
                               {"motion_time_s", s.motionTimeS}};
        emit autoTuneStep(id, QString::fromStdString(s.name), true, QString::fromStdString(j.dump()));
    };
    auto result = autotune::runAutoTune(*m_drive, options);
    if (!result)
        return fail(r, result.error());
    if (result->outcome != autotune::Outcome::Refused)
        report(1.0, {});
    r.autotune = std::make_shared<const autotune::AutoTuneResult>(std::move(result).value());
    r.ok = true;
    return r;
}

DriveReply DriveWorker::doAutoTuneTravel(int id, const QString& axis)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::Describe;
    r.axis = axis;
    if (!m_drive)
        return fail(r, notConnected());
    auto t = autotune::travelChoice(*m_drive, axis.toStdString());
    if (!t)
        return fail(r, t.error());
    r.travel = *t;
    r.ok = true;
    return r;
}

DriveReply DriveWorker::doAutoTuneUndo(int id, const autotune::AppliedTune& tune, bool force)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::AutoTuneUndo;
    r.axis = QString::fromStdString(tune.axis);
    if (!m_drive)
        return fail(r, notConnected());
    if (!force) {
        // The check undoTune makes, kept per parameter for the window (which key changed, to what); undoTune checks
        // again before it writes.
        std::vector<std::string> keys;
        for (const auto& [k, v] : tune.applied)
            keys.push_back(k);
        auto now = m_drive->readParameters(tune.axis, keys);
        if (!now)
            return fail(r, now.error());
        if (auto changed = autotune::changedSinceApplied(*now, tune); !changed.empty()) {
            r.values = *now;
            const Error e = autotune::changedRefusal(tune, changed);
            r.undoChanged = std::move(changed);
            r.code = e.code;
            r.error = QString::fromStdString(e.detail);
            return r;
        }
    }
    auto undone = autotune::undoTune(*m_drive, tune, force);
    if (!undone)
        return fail(r, undone.error());
    r.undone = std::move(undone).value();
    for (const auto& u : r.undone)
        r.values[u.key] = u.restored;
    r.ok = true;
    return r;
}

DriveRequest* DriveController::undoAutoTune(const autotune::AppliedTune& tune, bool force)
{
    return post(DriveReply::Kind::AutoTuneUndo,
                [tune, force](DriveWorker& w, int id) { return w.doAutoTuneUndo(id, tune, force); });
}

DriveRequest* DriveController::autoTuneTravel(const QString& axis)
{
    return post(DriveReply::Kind::Describe, [axis](DriveWorker& w, int id) { return w.doAutoTuneTravel(id, axis); });
}

DriveRequest* DriveController::runAutoTune(const autotune::Options& options)
{
    // The token exists before the job is queued: an abort() from now on reaches the sequence.
    auto token = std::make_shared<std::atomic<bool>>(false);
    DriveRequest* req = post(DriveReply::Kind::AutoTune,
                             [options, token](DriveWorker& w, int id) { return w.doAutoTune(id, options, token); });
    req->m_cancel = token;
    m_open[req->id()].cancel = token;
    return req;
}

} // namespace gui
} // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
// A position PID the NC closes, through the controller (docs/linuxcnc.md "The wizards on hal:"): core/autotune's
// PidTune steps run on the drive thread as one request each, like a test: the request's cancel token aborts the
// measurement (the drive stops the excitation and removes what it inserted), progress goes to the GUI thread.
#include "app/gui/DriveController.h"
#include "core/autotune/PidTune.h"
#include "core/device/hal/AxisNotch.h"

#include <QCoreApplication>

namespace axistune {
namespace gui {

DriveReply DriveWorker::doPidTune(int id, std::shared_ptr<const autotune::PidTuneRequest> request,
                                  std::shared_ptr<const autotune::PidLoopMeasurement> measured,
                                  std::shared_ptr<const autotune::PidTuneProposal> proposal,
                                  std::shared_ptr<std::atomic<bool>> cancel)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::PidTune;
    r.axis = QString::fromStdString(request->axis);
    if (auto refused = refuseBeforeStart(r, *cancel))
        return *refused;
    device::RunOptions run;
    run.abort = cancel.get();
    double shown = 0.0;
    run.progress = [&](double f, const std::string& detail) {
        drainSide(); // scope requests between the test's polls
        shown = std::max(shown, std::clamp(f, 0.0, 1.0));
        emit progress(id, shown, QString::fromStdString(detail));
    };
    if (!measured) {
        auto m = autotune::measurePidLoop(*m_drive, *request, run);
        if (!m)
            return fail(r, m.error());
        r.pidLoop = std::make_shared<const autotune::PidLoopMeasurement>(std::move(m).value());
        auto p = autotune::proposePidTune(*r.pidLoop, *request);
        if (!p)
            return fail(r, p.error()); // the measurement stays in the reply
        r.pidProposal = std::make_shared<const autotune::PidTuneProposal>(std::move(p).value());
        r.ok = true;
        return r;
    }
    auto a = autotune::applyPidTune(*m_drive, *request, *measured, *proposal, run);
    if (!a)
        return fail(r, a.error());
    r.pidApplied = std::make_shared<const autotune::PidTuneApplied>(std::move(a).value());
    r.ok = true;
    return r;
}

DriveReply DriveWorker::doPidTuneUndo(int id, const autotune::AppliedTune& tune,
                                      const autotune::PidTuneNotchUndo& notch, bool force)
{
    DriveReply r;
    r.id = id;
    r.kind = DriveReply::Kind::AutoTuneUndo;
    r.axis = QString::fromStdString(tune.axis);
    if (!m_drive)
        return fail(r, notConnected());
    // The notch is checked first: a refusal there leaves the gains as they are, too.
    if (auto st = autotune::checkPidTuneNotchUndo(*m_drive, notch, force); !st)
        return fail(r, st.error());
    if (!tune.applied.empty()) {
        r = doAutoTuneUndo(id, tune, force);
        r.kind = DriveReply::Kind::AutoTuneUndo;
        r.axis = QString::fromStdString(tune.axis);
        if (!r.ok)
            return r;
    }
    auto n = autotune::undoPidTuneNotch(*m_drive, notch);
    if (!n)
        return fail(r, n.error());
    r.pidNotchUndone = std::make_shared<const autotune::PidTuneNotchUndone>(std::move(n).value());
    r.ok = true;
    return r;
}

DriveRequest* DriveController::measurePidTune(const autotune::PidTuneRequest& request)
{
    return applyPidTune(request, nullptr, nullptr);
}

DriveRequest* DriveController::applyPidTune(const autotune::PidTuneRequest& request,
                                            std::shared_ptr<const autotune::PidLoopMeasurement> measured,
                                            std::shared_ptr<const autotune::PidTuneProposal> proposal)
{
    // The token exists before the job is queued: an abort() from now on reaches the measurement.
    auto token = std::make_shared<std::atomic<bool>>(false);
    auto req = std::make_shared<const autotune::PidTuneRequest>(request);
    DriveRequest* r = post(DriveReply::Kind::PidTune, [req, measured, proposal, token](DriveWorker& w, int id) {
        return w.doPidTune(id, req, measured, proposal, token);
    });
    r->m_cancel = token;
    m_open[r->id()].cancel = token;
    return r;
}

DriveRequest* DriveController::undoPidTune(const autotune::AppliedTune& tune, const autotune::PidTuneNotchUndo& notch,
                                           bool force)
{
    return post(DriveReply::Kind::AutoTuneUndo,
                [tune, notch, force](DriveWorker& w, int id) { return w.doPidTuneUndo(id, tune, notch, force); });
}

} // namespace gui
} // namespace axistune

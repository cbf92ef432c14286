// SPDX-License-Identifier: GPL-3.0-or-later
// Early stop of a tuning wizard: restore, read back, aborted session (AbortGuard.h).
#include "app/gui/AbortGuard.h"

#include "app/gui/AppContext.h"
#include "app/gui/DriveController.h"
#include "app/gui/WizardPages.h"

namespace axistune {
namespace gui {

AbortGuard::AbortGuard(AppContext& ctx, ApplyPage* apply, std::vector<TestRunPage*> runs, QString what, Hooks hooks,
                       QObject* parent)
    : QObject(parent), m_ctx(ctx), m_apply(apply), m_runs(std::move(runs)), m_what(std::move(what)),
      m_hooks(std::move(hooks))
{
    connect(m_apply, &ApplyPage::appliedChanged, this, [this](bool applied) {
        if (applied || !m_restoring)
            return;
        m_restoring = false;
        m_ctx.log(tr("Restored %1 from before the write.").arg(m_what));
        done(tr("The previous values of %1 were restored on the drive and read back.").arg(m_what));
    });
    connect(m_apply, &ApplyPage::restoreFailed, this, [this](const QString& error) {
        if (!m_restoring)
            return;
        m_restoring = false;
        done(tr("Restoring %1 failed (%2): the applied values may still be active on the drive.").arg(m_what, error));
    });
    // A connection lost while nothing runs: nothing can be restored; the session records it.
    connect(&m_ctx.drive(), &DriveController::connectionLost, this, [this](const QString& why) {
        bool running = false;
        for (auto* r : m_runs)
            running = running || r->isRunning();
        if (!running && m_apply->applied() && !m_hooks.saved() && !m_restoring)
            finish(tr("Connection lost: %1").arg(why), false);
    });
}

bool AbortGuard::reject()
{
    for (auto* r : m_runs)
        if (r->isRunning())
            m_ctx.drive().abort();
    if (m_hooks.abortRuns)
        m_hooks.abortRuns();
    if (m_restoring)
        return true;  // closes when the restore is done
    if (m_hooks.saved() || (!m_hooks.hasData() && !m_apply->applied()))
        return false;
    finish(tr("Cancelled by the operator."), true);
    return true;
}

void AbortGuard::runFailed(const QString& why) { finish(why, false); }

void AbortGuard::finish(const QString& why, bool closeAfter)
{
    if (m_restoring)
        return;
    // A sentence ends with "." (or "。" in Japanese); the note that follows starts a new one.
    m_reason = why.endsWith(QLatin1Char('.')) || why.endsWith(QChar(0x3002)) ? why : why + QLatin1Char('.');
    m_closeAfter = closeAfter;
    if (m_apply->applied() && m_ctx.drive().isConnected()) {
        m_restoring = true;
        m_ctx.log(tr("Restoring %1 from before the write…").arg(m_what));
        m_apply->restore();
        return;
    }
    done(m_apply->applied() ? tr("Could not restore %1: the connection to the drive is lost. Check them on the drive "
                                 "before the axis runs again.")
                                  .arg(m_what)
                            : QString());
}

void AbortGuard::done(const QString& note)
{
    if (!m_hooks.saved())
        m_hooks.saveAborted(note.isEmpty() ? m_reason : m_reason + QLatin1Char(' ') + note);
    if (m_closeAfter)
        m_hooks.close();
}

} // namespace gui
} // namespace axistune

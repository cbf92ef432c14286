// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The shell the tuning wizards share (current loop, velocity loop, lost motion, two-inertia): classic
// style, the id of the saved session, and the early stop through one AbortGuard (cancel, a failed run,
// a lost connection after applying: restore, read back, session kept as aborted).

#include <QString>
#include <QWizard>

#include <functional>
#include <vector>

namespace axistune {
namespace gui {

class AbortGuard;
class AppContext;
class ApplyPage;
class TestRunPage;

class TuningWizard : public QWizard {
    Q_OBJECT
public:
    /// Id of the saved completed session (0 before the save).
    qint64 savedSessionId() const { return m_sessionId; }
    /// Saves the session (Completed, or Aborted with the reason and whatever was measured).
    virtual void saveSession(bool aborted, const QString& reason) = 0;
    /// Cancel: aborts a running test, restores applied values and records the session as aborted.
    void reject() override;

protected:
    explicit TuningWizard(QWidget* parent);
    /// Hands the early stops to an AbortGuard; call once, when the pages exist. `what` names the written
    /// parameters in words; `hasData`: something measured worth keeping; `abortRuns` stops runs that are
    /// not TestRunPages.
    void guardEarlyStops(AppContext& ctx, ApplyPage* apply, std::vector<TestRunPage*> runs, const QString& what,
                         std::function<bool()> hasData, std::function<void()> abortRuns = {});
    /// Records what the store answered to saveSession() (id 0: not saved).
    void sessionStored(qint64 id, bool aborted);
    AbortGuard* guard() const { return m_guard; }

private:
    AbortGuard* m_guard = nullptr;
    qint64 m_sessionId = 0;
    bool m_savedAborted = false;
};

} // namespace gui
} // namespace axistune

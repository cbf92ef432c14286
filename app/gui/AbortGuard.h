// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What every tuning wizard does when it stops early (DESIGN.md "Safety in the tool"): a wizard that is
// cancelled, whose test fails (drive fault, Abort, lost connection) or that loses the connection after
// applying restores the values from before the write (ApplyPage::restore), reads them back, and records
// the session as aborted with its partial data and the reason. One object per wizard; the wizard
// forwards its reject() and its failed runs here.

#include <QObject>
#include <QString>

#include <functional>
#include <vector>

class QWizard;

namespace axistune {
namespace gui {

class AppContext;
class ApplyPage;
class TestRunPage;

class AbortGuard : public QObject {
    Q_OBJECT
public:
    struct Hooks {
        std::function<bool()> saved;                          ///< the session is already stored
        std::function<bool()> hasData;                        ///< something measured or proposed worth keeping
        std::function<void(const QString& reason)> saveAborted; ///< store the session as aborted
        std::function<void()> close;                          ///< QWizard::reject() of the wizard
        std::function<void()> abortRuns;                      ///< optional: stops runs that are not TestRunPages
    };

    /// `runs`: the wizard's test pages (aborted on cancel); `what`: the written parameters in words, for
    /// the messages ("the current-loop gains").
    AbortGuard(AppContext& ctx, ApplyPage* apply, std::vector<TestRunPage*> runs, QString what, Hooks hooks,
               QObject* parent);

    /// From the wizard's reject(). True when the guard took over: it restores (if anything was applied),
    /// saves the aborted session and then closes the wizard itself. False: close as usual.
    bool reject();
    /// A test failed (fault, Abort, lost connection): restore if applied, save as aborted; the wizard stays open.
    void runFailed(const QString& why);
    bool restoring() const { return m_restoring; }

private:
    void finish(const QString& why, bool closeAfter);
    void done(const QString& note);

    AppContext& m_ctx;
    ApplyPage* m_apply;
    std::vector<TestRunPage*> m_runs;
    QString m_what;
    Hooks m_hooks;
    bool m_restoring = false;
    bool m_closeAfter = false;
    QString m_reason;
};

} // namespace gui
} // namespace axistune

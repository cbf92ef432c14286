// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/TuningWizard.h"

#include "app/gui/AbortGuard.h"

namespace axistune {
namespace gui {

TuningWizard::TuningWizard(QWidget* parent) : QWizard(parent)
{
    setWizardStyle(QWizard::ClassicStyle);
    setOption(QWizard::NoBackButtonOnLastPage, true);
}

void TuningWizard::guardEarlyStops(AppContext& ctx, ApplyPage* apply, std::vector<TestRunPage*> runs,
                                   const QString& what, std::function<bool()> hasData,
                                   std::function<void()> abortRuns)
{
    AbortGuard::Hooks hooks;
    hooks.saved = [this] { return m_sessionId > 0 || m_savedAborted; };
    hooks.hasData = std::move(hasData);
    hooks.saveAborted = [this](const QString& why) { saveSession(true, why); };
    hooks.close = [this] { QWizard::reject(); };
    hooks.abortRuns = std::move(abortRuns);
    m_guard = new AbortGuard(ctx, apply, std::move(runs), what, std::move(hooks), this);
}

void TuningWizard::sessionStored(qint64 id, bool aborted)
{
    if (id <= 0)
        return;
    if (aborted)
        m_savedAborted = true;
    else
        m_sessionId = id;
}

void TuningWizard::reject()
{
    if (!m_guard || !m_guard->reject())
        QWizard::reject();
}

} // namespace gui
} // namespace axistune

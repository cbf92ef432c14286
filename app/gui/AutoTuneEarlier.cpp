// SPDX-License-Identifier: GPL-3.0-or-later
// Undo of an earlier applied run from the one-button wizard (docs/tuning.md "Undo in the wizard"): the first page
// lists the applied runs saved in the store for this machine's axes; the chosen one opens the result page with its
// parameters (before → applied) and the same Undo as right after a run (AutoTuneUndo.cpp: autotune::undoTune on the
// drive thread, refused when the drive no longer holds what the run applied, Undo anyway after a second
// confirmation). Nothing moves.
#include "app/gui/AppContext.h"
#include "app/gui/AutoTuneWizard.h"
#include "app/gui/AutoTuneWizardText.h"
#include "core/autotune/Undo.h"
#include "core/store/Database.h"
#include "core/store/SessionRecord.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QWizard>

#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

using autotunetext::qs;

int AutoTuneChoicePage::nextId() const
{
    return m_d.stored ? AutoTuneWizard::Result : AutoTuneWizard::Run;
}

bool AutoTuneChoicePage::openEarlierRun(qint64 sessionId, QString* why)
{
    auto* db = m_ctx.database();
    if (!db) {
        *why = tr("No store is open.");
        return false;
    }
    auto rec = db->loadSession(sessionId);
    if (!rec) {
        *why = tr("Reading session %1 failed: %2").arg(sessionId).arg(qs(rec.error().detail));
        return false;
    }
    const nlohmann::json* j = rec->result("autotune");
    if (rec->info.kind != "autotune" || !j) {
        *why = tr("Session %1 is not a run of the automatic tuning.").arg(sessionId);
        return false;
    }
    auto tune = autotune::appliedTuneFromJson(*j);
    if (!tune) {
        *why = tr("Session %1: %2").arg(sessionId).arg(qs(tune.error().detail));
        return false;
    }
    if (!m_ctx.axes().contains(qs(tune->axis))) {
        *why = tr("Session %1 tuned axis %2, which this connection does not have.").arg(sessionId).arg(qs(tune->axis));
        return false;
    }
    m_d.result.reset();
    m_d.error.clear();
    m_d.sessionId = sessionId;
    m_d.stored = std::make_shared<const nlohmann::json>(*j);
    wizard()->next();
    return true;
}

void AutoTuneChoicePage::chooseEarlierRun()
{
    auto* db = m_ctx.database();
    if (!db)
        return;
    auto* dlg = new QDialog(this);
    dlg->setObjectName("atEarlierRuns");
    dlg->setAttribute(Qt::WA_DeleteOnClose);
    dlg->setWindowTitle(tr("Undo an earlier run"));
    auto* lay = new QVBoxLayout(dlg);
    auto* text = new QLabel(tr("Applied runs of the automatic tuning saved for %1, newest first. The next page shows "
                               "what the chosen run changed; nothing is written before you confirm Undo there.")
                                .arg(m_ctx.machine()),
                            dlg);
    text->setWordWrap(true);
    lay->addWidget(text);
    auto* list = new QListWidget(dlg);
    list->setObjectName("atEarlierList");
    if (auto sessions = db->listSessions(m_ctx.machine().toStdString())) {
        for (auto it = sessions->rbegin(); it != sessions->rend(); ++it) {
            if (it->kind != "autotune" || it->status != store::SessionStatus::Completed ||
                !m_ctx.axes().contains(qs(it->axis)))
                continue;
            auto rec = db->loadSession(it->id);
            const nlohmann::json* j = rec ? rec->result("autotune") : nullptr;
            if (!j || j->value("outcome", std::string()) != "applied")
                continue;
            auto tune = autotune::appliedTuneFromJson(*j);
            if (!tune)
                continue;
            auto* item = new QListWidgetItem(
                tr("Session %1 (%2), axis %3: %n parameter(s) applied", nullptr, int(tune->applied.size()))
                    .arg(it->id)
                    .arg(qs(it->started), qs(it->axis)),
                list);
            item->setData(Qt::UserRole, QVariant::fromValue<qint64>(it->id));
        }
    }
    if (list->count() == 0)
        text->setText(tr("No applied run of the automatic tuning is saved for the axes of %1.").arg(m_ctx.machine()));
    list->setCurrentRow(0);
    lay->addWidget(list, 1);
    auto* error = new QLabel(dlg);
    error->setWordWrap(true);
    error->setStyleSheet(QStringLiteral("color: #b00020;"));
    lay->addWidget(error);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Open | QDialogButtonBox::Cancel, dlg);
    buttons->button(QDialogButtonBox::Open)->setEnabled(list->count() > 0);
    lay->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, dlg, &QDialog::reject);
    connect(buttons, &QDialogButtonBox::accepted, dlg, [this, dlg, list, error] {
        if (!list->currentItem())
            return;
        QString why;
        if (openEarlierRun(list->currentItem()->data(Qt::UserRole).value<qint64>(), &why))
            dlg->accept();
        else
            error->setText(why);
    });
    dlg->resize(640, 360);
    dlg->open();
}

void AutoTuneResultPage::cleanupPage()
{
    m_d.stored.reset();
}

void AutoTuneResultPage::initializeStored()
{
    auto tune = autotune::appliedTuneFromJson(*m_d.stored);
    m_figures->setVisible(false);
    m_tabs->setTabVisible(ResonanceTab, false);
    m_tabs->setTabVisible(AmplitudeTab, false);
    m_tabs->setTabVisible(FiguresTab, true);
    m_tabs->setCurrentIndex(FiguresTab);
    m_tabs->setVisible(true);
    m_session->setText(tr("An earlier run: session %1.").arg(m_d.sessionId));
    if (!tune) { // openEarlierRun checked it; a store changed meanwhile
        m_outcome->setText(tr("Session %1: %2").arg(m_d.sessionId).arg(qs(tune.error().detail)));
        return;
    }
    if (!m_undoing && !m_undone)
        m_tune = std::move(tune).value();
    m_outcome->setStyleSheet(QString());
    m_outcome->setText(tr("Session %1 applied these parameters to axis %2. Undo writes back the values they had "
                          "before it, in one write, read back, when the drive still holds what the run applied.")
                           .arg(m_d.sessionId)
                           .arg(qs(m_tune->axis)));
    m_parameters->setVisible(true);
    m_parametersTitle->setVisible(true);
    m_parametersTitle->setText(tr("Parameters the run applied (before → applied):"));
    fillParameters();
    offerUndo();
}

} // namespace gui
} // namespace axistune

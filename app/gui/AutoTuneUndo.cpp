// SPDX-License-Identifier: GPL-3.0-or-later
// Undo of an applied one-button tune from the wizard's result page (AutoTuneWizard.h; docs/tuning.md "Undo in the
// wizard"): the diff to confirm (each parameter: applied → before, in its display unit), then autotune::undoTune on
// the drive thread (DriveController::undoAutoTune), the CLI's `autotune --undo` rules: refused with nothing written
// when the drive no longer holds what the run applied (the key named), "Undo anyway" after a second confirmation; one
// write, read back; the undo saved as a session "autotune-undo" with its journal.
#include "app/gui/AppContext.h"
#include "app/gui/AutoTuneWizard.h"
#include "app/gui/AutoTuneWizardText.h"
#include "app/gui/ParameterText.h"
#include "app/gui/WizardPages.h"
#include "core/model/Units.h"
#include "core/store/SessionRecord.h"

#include <QCheckBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

using autotunetext::item;
using autotunetext::qs;

QString AutoTuneResultPage::valueText(const std::string& key, double si) const
{
    const auto* m = model::findParameter(m_metas, key);
    return m ? displayParameterValue(*m, si) : QString::number(si, 'g', 6);
}

QString AutoTuneResultPage::unitText(const std::string& key) const
{
    const auto* m = model::findParameter(m_metas, key);
    return m ? qs(model::unitLabel(m->displayUnit)) : QString();
}

void AutoTuneResultPage::fillParameters()
{
    m_parameters->setRowCount(0);
    auto addRow = [this](const std::string& k, const std::optional<double>& before, double applied) {
        const int row = m_parameters->rowCount();
        m_parameters->insertRow(row);
        const auto* m = model::findParameter(m_metas, k);
        m_parameters->setItem(row, 0, item(m ? tr("%1 (%2)").arg(parameterLabel(m->label), qs(k)) : qs(k)));
        m_parameters->setItem(row, 1, item(before ? valueText(k, *before) : QStringLiteral("–")));
        m_parameters->setItem(row, 2, item(valueText(k, applied)));
        m_parameters->setItem(row, 3, item(unitText(k)));
    };
    if (m_d.stored && m_tune) { // an earlier run (AutoTuneEarlier.cpp): before → applied from its session
        for (const auto& [k, v] : m_tune->applied)
            addRow(k, m_tune->before.at(k), v);
        return;
    }
    const auto* r = m_d.result.get();
    if (!r || !r->final)
        return;
    for (const auto& [k, v] : r->final->parameters) {
        const auto it = r->before.find(k);
        addRow(k, it == r->before.end() ? std::nullopt : std::optional<double>(it->second), v);
    }
}

void AutoTuneResultPage::onMetadata(const DriveReply& reply)
{
    if (reply.id != m_metaRequest)
        return;
    m_metasKnown = true;
    if (reply.ok) {
        m_metas = reply.metadata;
        fillParameters();
    } else if (!m_undone && m_undoState->text().isEmpty()) {
        m_undoState->setText(
            tr("Reading the parameters' units failed (%1): values are shown in SI units.").arg(reply.error));
    }
    updateUndoButtons();
}

void AutoTuneResultPage::offerUndo()
{
    m_undo->setVisible(true);
    if (m_ctx.drive().isConnected())
        m_metaRequest =
            connectReply(m_ctx.drive().readMetadata(qs(m_tune->axis)), this, &AutoTuneResultPage::onMetadata);
    else
        m_metasKnown = true;
    updateUndoButtons();
}

void AutoTuneResultPage::updateUndoButtons()
{
    const bool offered = m_tune.has_value();
    const bool free = offered && !m_undone && !m_undoing && m_metasKnown && !m_d.running &&
                      m_ctx.drive().isConnected() && !m_ctx.drive().isTestRunning() && !m_undoDialog;
    m_undo->setVisible(offered);
    m_undo->setEnabled(free);
    m_undoAnyway->setVisible(offered && !m_undone && !m_changed.empty());
    m_undoAnyway->setEnabled(free && !m_changed.empty());
}

void AutoTuneResultPage::confirmUndo(bool force)
{
    if (!m_tune || m_undone || m_undoing || m_undoDialog)
        return;
    if (force && m_changed.empty())
        return;
    const auto& t = *m_tune;
    auto* dlg = new QDialog(this);
    dlg->setObjectName("atUndoConfirm");
    dlg->setAttribute(Qt::WA_DeleteOnClose);
    dlg->setWindowTitle(force ? tr("Undo the automatic tuning anyway") : tr("Undo the automatic tuning"));
    auto* lay = new QVBoxLayout(dlg);
    auto* text = new QLabel(dlg);
    text->setWordWrap(true);
    text->setText(tr("Undo writes back the values the parameters of axis %1 had before the run, all in one write, and "
                     "reads them back. Nothing moves. These parameters change:")
                      .arg(qs(t.axis)));
    lay->addWidget(text);
    // Undo: applied → before. Undo anyway: also what the drive holds now (the changed rows marked).
    const int cols = force ? 5 : 4;
    auto* table = new QTableWidget(0, cols, dlg);
    table->setObjectName("atUndoDiff");
    QStringList headers{tr("Parameter"), tr("Applied by the run")};
    if (force)
        headers << tr("On the drive now");
    headers << tr("→ Before the run (written)") << tr("Unit");
    table->setHorizontalHeaderLabels(headers);
    table->verticalHeader()->hide();
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->horizontalHeader()->setStretchLastSection(true);
    table->setSelectionMode(QAbstractItemView::NoSelection);
    table->setFocusPolicy(Qt::NoFocus);
    QStringList changedKeys;
    for (const auto& [k, applied] : t.applied) {
        const int row = table->rowCount();
        table->insertRow(row);
        const auto* m = model::findParameter(m_metas, k);
        table->setItem(row, 0, item(m ? tr("%1 (%2)").arg(parameterLabel(m->label), qs(k)) : qs(k)));
        table->setItem(row, 1, item(valueText(k, applied)));
        int col = 2;
        if (force) {
            const auto c = std::find_if(m_changed.begin(), m_changed.end(), [&](const auto& x) { return x.key == k; });
            const auto now = m_driveNow.find(k);
            auto* cell = item(now == m_driveNow.end() ? QStringLiteral("–") : valueText(k, now->second));
            if (c != m_changed.end()) {
                changedKeys << qs(k);
                cell->setBackground(QColor(255, 205, 205));
                table->item(row, 0)->setBackground(QColor(255, 205, 205));
                cell->setToolTip(tr("Changed after the run applied it: Undo anyway overwrites this value"));
            }
            table->setItem(row, col++, cell);
        }
        table->setItem(row, col++, item(valueText(k, t.before.at(k))));
        table->setItem(row, col, item(unitText(k)));
    }
    lay->addWidget(table, 1);
    QCheckBox* overwrite = nullptr;
    if (force) {
        auto* warn = new QLabel(dlg);
        warn->setWordWrap(true);
        warn->setStyleSheet(QStringLiteral("color: #b00020;"));
        warn->setText(tr("The drive no longer holds what the run applied for %1 (marked red): someone or something "
                         "changed it after the run. Undo anyway overwrites that later change with the value before "
                         "the run.")
                          .arg(changedKeys.join(QStringLiteral(", "))));
        lay->addWidget(warn);
        overwrite =
            new QCheckBox(tr("Overwrite the later change of %1").arg(changedKeys.join(QStringLiteral(", "))), dlg);
        overwrite->setObjectName("atUndoOverwrite");
        lay->addWidget(overwrite);
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, dlg);
    buttons->setObjectName("atUndoButtons");
    auto* ok = buttons->button(QDialogButtonBox::Ok);
    ok->setText(force ? tr("Undo anyway") : tr("Undo"));
    buttons->button(QDialogButtonBox::Cancel)->setDefault(true);
    if (overwrite) {
        ok->setEnabled(false);
        connect(overwrite, &QCheckBox::toggled, ok, &QPushButton::setEnabled);
    }
    lay->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, dlg, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, dlg, &QDialog::reject);
    connect(dlg, &QDialog::accepted, this, [this, force, overwrite] {
        if (force && !(overwrite && overwrite->isChecked()))
            return; // the second confirmation is the ticked box
        m_undoing = true;
        m_undoForced = force;
        m_undoState->setStyleSheet(QString());
        m_undoState->setText(tr("Undoing: writing the values before the run and reading them back…"));
        m_undoRequest =
            connectReply(m_ctx.drive().undoAutoTune(*m_tune, force), this, &AutoTuneResultPage::onUndoReply);
        m_ctx.log(tr("Automatic tuning of axis %1: undo%2").arg(qs(m_tune->axis), force ? tr(" (anyway)") : QString()));
        updateUndoButtons();
    });
    // finished comes before accepted (QDialog::done): the buttons follow again once the dialog is gone.
    connect(dlg, &QDialog::finished, this, [this] {
        m_undoDialog = nullptr;
        updateUndoButtons();
    });
    m_undoDialog = dlg;
    updateUndoButtons();
    dlg->resize(force ? 940 : 760, force ? 380 : 330);
    dlg->open();
}

void AutoTuneResultPage::onUndoReply(const DriveReply& r)
{
    if (r.id != m_undoRequest)
        return;
    m_undoing = false;
    if (r.ok) {
        m_undone = true;
        m_changed.clear();
        m_undoState->setStyleSheet(QString());
        QStringList lines;
        for (const auto& u : r.undone)
            lines << tr("%1: %2 → %3 %4")
                         .arg(qs(u.key), valueText(u.key, u.applied), valueText(u.key, u.restored), unitText(u.key));
        m_undoState->setText(tr("Undone: %n parameter(s) written back to the values before the run and read back "
                                "equal.",
                                nullptr, int(r.undone.size())) +
                             QStringLiteral("\n") + lines.join(QStringLiteral("; ")));
        emit m_ctx.parametersApplied(r.axis);
    } else if (!r.undoChanged.empty() && r.code == ErrorCode::Safety) {
        m_changed = r.undoChanged;
        m_driveNow = r.values;
        const auto& c = m_changed.front();
        QStringList others;
        for (std::size_t i = 1; i < m_changed.size(); ++i)
            others << qs(m_changed[i].key);
        m_undoState->setStyleSheet(QStringLiteral("color: #b00020;"));
        m_undoState->setText(
            tr("Undo refused, nothing written: %1 is %2 %3 on the drive, not the %4 %3 the run applied. It was "
               "changed after the run, and undoing would overwrite that change.")
                .arg(qs(c.key), valueText(c.key, c.now.value_or(0.0)), unitText(c.key), valueText(c.key, c.applied)) +
            (others.isEmpty() ? QString() : QStringLiteral(" ") + tr("Also changed: %1.").arg(others.join(", "))) +
            QStringLiteral("\n") + tr("Undo anyway… overwrites it after a second confirmation."));
    } else {
        m_undoState->setStyleSheet(QStringLiteral("color: #b00020;"));
        m_undoState->setText(
            r.code == ErrorCode::NotFound || r.code == ErrorCode::Safety
                ? tr("Undo refused, nothing written: %1").arg(r.error)
                : tr("Undo failed: %1\nRead the axis's parameters to see what the drive holds.").arg(r.error));
    }
    m_ctx.log(m_undoState->text());
    saveUndoSession(r);
    updateUndoButtons();
    emit undoFinished();
}

void AutoTuneResultPage::saveUndoSession(const DriveReply& r)
{
    store::SessionRecord rec;
    rec.info.kind = "autotune-undo";
    rec.info.axis = m_tune->axis;
    rec.info.status = r.ok ? store::SessionStatus::Completed : store::SessionStatus::Failed;
    rec.info.note = r.ok ? (m_undoForced ? "undo anyway (forced)" : "undo") : r.error.toStdString();
    rec.inputs = {{"connection", m_ctx.drive().uri().toStdString()},
                  {"axis", m_tune->axis},
                  {"force", m_undoForced},
                  {"undoes_session", m_d.sessionId > 0 ? nlohmann::json(m_d.sessionId) : nlohmann::json()}};
    nlohmann::json out = nlohmann::json::object();
    if (r.ok) {
        nlohmann::json list = nlohmann::json::array();
        model::ParameterValues restored;
        for (const auto& u : r.undone) {
            list.push_back({{"key", u.key}, {"was", u.applied}, {"now", u.restored}});
            restored[u.key] = u.restored;
            store::JournalEntry e;
            e.axis = m_tune->axis;
            e.key = u.key;
            e.oldValue = u.applied;
            e.newValue = u.restored;
            rec.journal.push_back(e);
        }
        out["undone"] = list;
        rec.parameterSets.push_back(
            {0, m_tune->axis, store::ParameterSource::Applied, {}, "autotune wizard: undo", restored});
    } else {
        out["error"] = r.error.toStdString();
        nlohmann::json changed = nlohmann::json::array();
        for (const auto& c : r.undoChanged)
            changed.push_back(
                {{"key", c.key}, {"applied", c.applied}, {"now", c.now ? nlohmann::json(*c.now) : nlohmann::json()}});
        out["changed"] = changed;
    }
    rec.results.push_back({"undo", out, {}});
    if (m_ctx.database())
        m_ctx.saveSessionAsync(std::move(rec), this);
}

} // namespace gui
} // namespace axistune

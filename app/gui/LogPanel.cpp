// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/LogPanel.h"

#include "app/gui/AppContext.h"

#include <QEvent>
#include <QHeaderView>
#include <QPlainTextEdit>
#include <QTableWidget>

namespace axistune {
namespace gui {

LogPanel::LogPanel(AppContext& ctx, QWidget* parent) : QTabWidget(parent), m_ctx(ctx)
{
    setObjectName("logPanel");
    m_log = new QPlainTextEdit(this);
    m_log->setObjectName("logView");
    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(5000);
    m_journal = new QTableWidget(0, 6, this);
    m_journal->setObjectName("journalTable");
    m_journal->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_journal->verticalHeader()->hide();
    m_journal->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_journal->horizontalHeader()->setStretchLastSection(true);
    addTab(m_log, QString());
    addTab(m_journal, QString());
    retranslateUi();
    connect(&m_ctx, &AppContext::logged, m_log, &QPlainTextEdit::appendPlainText);
    connect(&m_ctx, &AppContext::sessionSaved, this, &LogPanel::refreshJournal);
    connect(&m_ctx, &AppContext::parametersApplied, this, &LogPanel::refreshJournal);
}

void LogPanel::retranslateUi()
{
    setTabText(0, tr("Log"));
    setTabText(1, tr("Parameter journal"));
    m_journal->setHorizontalHeaderLabels({tr("Time"), tr("Axis"), tr("Parameter"), tr("Old (SI)"), tr("New (SI)"), tr("Session")});
}

void LogPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QTabWidget::changeEvent(event);
}

void LogPanel::setMachine(const QString& machine)
{
    m_machine = machine;
    refreshJournal();
}

void LogPanel::refreshJournal()
{
    m_journal->setRowCount(0);
    auto* db = m_ctx.database();
    if (!db || m_machine.isEmpty())
        return;
    auto j = db->journal(m_machine.toStdString());
    if (!j) {
        m_ctx.log(tr("Reading the journal of %1 failed: %2").arg(m_machine, QString::fromStdString(j.error().detail)));
        return;
    }
    // Newest first: what was changed last is what one looks for.
    m_journal->setRowCount(static_cast<int>(j->size()));
    int row = 0;
    for (auto it = j->rbegin(); it != j->rend(); ++it, ++row) {
        const auto& e = *it;
        m_journal->setItem(row, 0, new QTableWidgetItem(QString::fromStdString(e.time)));
        m_journal->setItem(row, 1, new QTableWidgetItem(QString::fromStdString(e.axis)));
        m_journal->setItem(row, 2, new QTableWidgetItem(QString::fromStdString(e.key)));
        m_journal->setItem(
            row, 3, new QTableWidgetItem(e.oldValue ? QString::number(*e.oldValue, 'g', 8) : tr("not recorded")));
        m_journal->setItem(row, 4, new QTableWidgetItem(QString::number(e.newValue, 'g', 8)));
        m_journal->setItem(row, 5, new QTableWidgetItem(e.sessionId ? QString::number(*e.sessionId) : QString()));
    }
}

}  // namespace gui
}  // namespace axistune

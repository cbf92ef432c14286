// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/SessionReview.h"

#include "app/gui/AppContext.h"
#include "app/gui/SessionReviewView.h"

#include "app/gui/ReportDialog.h"
#include "core/store/SessionRecord.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace axistune {
namespace gui {

namespace {
constexpr int kIdRole = Qt::UserRole;
constexpr int kAbortedRole = Qt::UserRole + 1;
}  // namespace

SessionReview::SessionReview(AppContext& ctx, QWidget* parent) : QWidget(parent), m_ctx(ctx)
{
    setObjectName("sessionReview");
    auto* lay = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    m_machineLabel = new QLabel(this);
    m_machine = new QComboBox(this);
    m_machine->setObjectName("reviewMachineCombo");
    m_machine->setMinimumContentsLength(16);
    top->addWidget(m_machineLabel);
    top->addWidget(m_machine);
    top->addStretch(1);
    m_reload = new QPushButton(this);
    top->addWidget(m_reload);
    lay->addLayout(top);

    m_list = new QTreeWidget(this);
    m_list->setObjectName("sessionList");
    m_list->setColumnCount(ColumnCount);
    m_list->setRootIsDecorated(false);
    m_list->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_list->setAlternatingRowColors(true);
    m_list->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_list->header()->setStretchLastSection(false);
    m_list->header()->setSectionResizeMode(ColNote, QHeaderView::Stretch);
    lay->addWidget(m_list, 1);

    auto* buttons = new QHBoxLayout;
    m_open = new QPushButton(this);
    m_open->setObjectName("openSessionButton");
    m_overlay = new QPushButton(this);
    m_overlay->setObjectName("overlayButton");
    buttons->addWidget(m_open);
    buttons->addWidget(m_overlay);
    m_report = new QPushButton(this);
    m_report->setObjectName("reportButton");
    buttons->addWidget(m_report);
    connect(m_report, &QPushButton::clicked, this, [this] {
        const auto ids = selectedIds();
        if (!ids.isEmpty())
            showSessionReport(m_ctx, ids.front(), this);
    });
    buttons->addStretch(1);
    lay->addLayout(buttons);

    connect(m_open, &QPushButton::clicked, this, &SessionReview::openSelected);
    connect(m_overlay, &QPushButton::clicked, this, &SessionReview::overlaySelected);
    connect(m_reload, &QPushButton::clicked, this, [this] {
        reloadMachines();
        reload();
    });
    connect(m_list, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item) {
        openSession(item->data(ColId, kIdRole).toLongLong());
    });
    connect(m_machine, &QComboBox::currentIndexChanged, this, [this] { reload(); });
    connect(&m_ctx, &AppContext::sessionSaved, this, [this] {
        reloadMachines();
        reload();
    });
    connect(&m_ctx, &AppContext::databaseChanged, this, [this] {
        reloadMachines();
        reload();
    });
    retranslateUi();
    reloadMachines();
    reload();
}

void SessionReview::retranslateUi()
{
    m_machineLabel->setText(tr("Machine:"));
    if (m_machine->count() > 0)
        m_machine->setItemText(0, tr("(all machines)"));
    m_reload->setText(tr("Reload"));
    m_open->setText(tr("Open"));
    m_open->setToolTip(tr("Shows the selected session read-only with all its plots"));
    m_overlay->setText(tr("Overlay responses"));
    m_overlay->setToolTip(tr("One Bode plot with the frequency responses of every selected session"));
    if (m_report)
        m_report->setText(tr("Report…"));
    m_list->setHeaderLabels({tr("Id"), tr("Kind"), tr("Status"), tr("Started (UTC)"), tr("Operator"), tr("Note"),
                             tr("Captures"), tr("Results")});
    reload();
}

void SessionReview::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void SessionReview::reloadMachines()
{
    const QString keep = m_machine->currentIndex() > 0 ? m_machine->currentText() : m_wantedMachine;
    const QSignalBlocker block(m_machine);
    m_machine->clear();
    m_machine->addItem(tr("(all machines)"), QString());
    if (auto* db = m_ctx.database())
        if (auto names = db->listMachines())
            for (const auto& n : *names)
                m_machine->addItem(QString::fromStdString(n), QString::fromStdString(n));
    const int i = keep.isEmpty() ? 0 : m_machine->findData(keep);
    m_machine->setCurrentIndex(std::max(0, i));
}

void SessionReview::setMachine(const QString& machine)
{
    m_wantedMachine = machine;
    const int i = machine.isEmpty() ? 0 : m_machine->findData(machine);
    if (i >= 0 && i != m_machine->currentIndex())
        m_machine->setCurrentIndex(i);  // reloads
}

QString SessionReview::machine() const { return m_machine->currentData().toString(); }

void SessionReview::reload()
{
    m_list->clear();
    auto* db = m_ctx.database();
    if (!db)
        return;
    auto sessions = db->listSessions(machine().toStdString());
    if (!sessions) {
        m_ctx.log(tr("Listing the sessions failed: %1").arg(QString::fromStdString(sessions.error().detail)));
        return;
    }
    // Newest first.
    for (auto it = sessions->rbegin(); it != sessions->rend(); ++it) {
        const auto& s = *it;
        const bool aborted = s.status != store::SessionStatus::Completed;
        QString status = s.status == store::SessionStatus::Completed ? tr("completed")
                         : s.status == store::SessionStatus::Aborted ? tr("ABORTED")
                                                                     : tr("FAILED");
        auto* item = new QTreeWidgetItem(m_list);
        item->setText(ColId, QString::number(s.id));
        item->setData(ColId, kIdRole, static_cast<qlonglong>(s.id));
        item->setData(ColId, kAbortedRole, aborted);
        item->setText(ColKind, QString::fromStdString(s.kind) +
                                   (machine().isEmpty() && !s.machine.empty() ? " (" + QString::fromStdString(s.machine) + ")"
                                                                             : QString()));
        item->setText(ColStatus, status);
        item->setText(ColStarted, QString::fromStdString(s.started).replace('T', ' ').remove('Z'));
        item->setText(ColOperator, QString::fromStdString(s.operatorName));
        item->setText(ColNote, QString::fromStdString(s.note));
        item->setToolTip(ColNote, QString::fromStdString(s.note));
        item->setText(ColCaptures, QString::number(s.captureCount));
        item->setText(ColResults, QString::number(s.resultCount));
        item->setTextAlignment(ColCaptures, Qt::AlignRight | Qt::AlignVCenter);
        item->setTextAlignment(ColResults, Qt::AlignRight | Qt::AlignVCenter);
        if (aborted) {
            item->setForeground(ColStatus, QColor(0xb0, 0x00, 0x20));
            QFont f = item->font(ColStatus);
            f.setBold(true);
            item->setFont(ColStatus, f);
            item->setIcon(ColStatus, style()->standardIcon(QStyle::SP_MessageBoxWarning));
        }
    }
}

QList<qint64> SessionReview::sessionIds() const
{
    QList<qint64> ids;
    for (int i = 0; i < m_list->topLevelItemCount(); ++i)
        ids << m_list->topLevelItem(i)->data(ColId, kIdRole).toLongLong();
    return ids;
}

bool SessionReview::isMarkedAborted(qint64 id) const
{
    for (int i = 0; i < m_list->topLevelItemCount(); ++i) {
        auto* item = m_list->topLevelItem(i);
        if (item->data(ColId, kIdRole).toLongLong() == id)
            return item->data(ColId, kAbortedRole).toBool();
    }
    return false;
}

void SessionReview::selectSessions(const QList<qint64>& ids)
{
    for (int i = 0; i < m_list->topLevelItemCount(); ++i) {
        auto* item = m_list->topLevelItem(i);
        item->setSelected(ids.contains(item->data(ColId, kIdRole).toLongLong()));
    }
}

QList<qint64> SessionReview::selectedIds() const
{
    QList<qint64> ids;
    for (auto* item : m_list->selectedItems())
        ids << item->data(ColId, kIdRole).toLongLong();
    std::sort(ids.begin(), ids.end());
    return ids;
}

void SessionReview::openSelected()
{
    for (qint64 id : selectedIds())
        openSession(id);
}

void SessionReview::overlaySelected() { overlaySessions(selectedIds()); }

SessionView* SessionReview::openSession(qint64 id)
{
    auto* db = m_ctx.database();
    if (!db)
        return nullptr;
    auto rec = db->loadSession(id);
    if (!rec) {
        m_ctx.log(tr("Session %1 could not be loaded: %2").arg(id).arg(QString::fromStdString(rec.error().detail)));
        return nullptr;
    }
    const QString kind = QString::fromStdString(rec->info.kind);
    auto* view = new SessionView(std::move(rec).value());
    m_ctx.showDocument(view, tr("Session %1 (%2)").arg(id).arg(kind));
    return view;
}

SessionOverlay* SessionReview::overlaySessions(const QList<qint64>& ids)
{
    auto* db = m_ctx.database();
    if (!db || ids.isEmpty())
        return nullptr;
    std::vector<store::SessionRecord> records;
    QStringList names;
    for (qint64 id : ids) {
        auto rec = db->loadSession(id);
        if (!rec) {
            m_ctx.log(tr("Session %1 could not be loaded: %2").arg(id).arg(QString::fromStdString(rec.error().detail)));
            continue;
        }
        records.push_back(std::move(rec).value());
        names << QString::number(id);
    }
    if (records.empty())
        return nullptr;
    auto* view = new SessionOverlay(records);
    m_ctx.showDocument(view, tr("Sessions %1").arg(names.join(", ")));
    return view;
}

}  // namespace gui
}  // namespace axistune

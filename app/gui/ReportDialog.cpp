// SPDX-License-Identifier: GPL-3.0-or-later
// Report dialog: the session report in a read-only browser, saved as HTML or PDF.
#include "app/gui/ReportDialog.h"

#include "app/gui/AppContext.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTextBrowser>
#include <QTextDocument>
#include <QVBoxLayout>

namespace axistune {
namespace gui {

ReportDialog::ReportDialog(SessionReport report, QWidget* parent) : QDialog(parent), m_report(std::move(report))
{
    setObjectName(QStringLiteral("reportDialog"));
    setWindowTitle(tr("Report of session %1").arg(m_report.record().info.id));
    m_browser = new QTextBrowser(this);
    m_browser->setObjectName(QStringLiteral("reportBrowser"));
    m_browser->setReadOnly(true);
    m_browser->setOpenExternalLinks(false);
    m_browser->setDocument(m_report.createDocument(m_browser));
    m_saveHtml = new QPushButton(tr("Save as HTML…"), this);
    m_saveHtml->setObjectName(QStringLiteral("reportSaveHtml"));
    m_savePdf = new QPushButton(tr("Save as PDF…"), this);
    m_savePdf->setObjectName(QStringLiteral("reportSavePdf"));
    auto* close = new QPushButton(tr("Close"), this);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("reportStatus"));
    connect(m_saveHtml, &QPushButton::clicked, this, [this] { saveInteractive(false); });
    connect(m_savePdf, &QPushButton::clicked, this, [this] { saveInteractive(true); });
    connect(close, &QPushButton::clicked, this, &QDialog::close);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_status, 1);
    buttons->addWidget(m_saveHtml);
    buttons->addWidget(m_savePdf);
    buttons->addWidget(close);
    auto* lay = new QVBoxLayout(this);
    lay->addWidget(m_browser, 1);
    lay->addLayout(buttons);
    resize(900, 700);
}

void ReportDialog::saveInteractive(bool pdf)
{
    const QString suggested = QDir::home().filePath(
        QStringLiteral("session%1-report.%2").arg(m_report.record().info.id).arg(pdf ? "pdf" : "html"));
    const QString path = QFileDialog::getSaveFileName(this, pdf ? tr("Save report as PDF") : tr("Save report as HTML"),
                                                      suggested, pdf ? tr("PDF (*.pdf)") : tr("HTML (*.html *.htm)"));
    if (path.isEmpty())
        return;
    QString error;
    const bool ok = pdf ? savePdf(path, &error) : saveHtml(path, &error);
    if (!ok) {
        m_status->setText(error);
        QMessageBox::warning(this, tr("Report not saved"), error);
        return;
    }
    m_status->setText(tr("Saved %1").arg(QDir::toNativeSeparators(path)));
}

ReportDialog* showSessionReport(AppContext& ctx, qint64 sessionId, QWidget* parent)
{
    auto* db = ctx.database();
    QString error;
    if (!db) {
        error = ReportDialog::tr("No store is open.");
    } else if (auto rec = db->loadSession(sessionId); !rec) {
        error = ReportDialog::tr("Session %1 cannot be loaded: %2")
                    .arg(sessionId)
                    .arg(QString::fromStdString(rec.error().detail));
    } else {
        auto* dlg = new ReportDialog(SessionReport::build(*rec), parent);
        dlg->setAttribute(Qt::WA_DeleteOnClose);
        dlg->show();
        return dlg;
    }
    ctx.log(error);
    QMessageBox::warning(parent, ReportDialog::tr("No report"), error);
    return nullptr;
}

} // namespace gui
} // namespace axistune

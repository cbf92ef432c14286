// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The report of one session, read-only (QTextBrowser), with Save as HTML / Save as PDF
// (docs/reports.md). showSessionReport() is the entry point the session review calls.

#include "app/gui/Report.h"

#include <QDialog>

class QTextBrowser;
class QPushButton;
class QLabel;

namespace axistune {
namespace gui {

class AppContext;

class ReportDialog : public QDialog {
    Q_OBJECT
public:
    explicit ReportDialog(SessionReport report, QWidget* parent = nullptr);

    const SessionReport& report() const { return m_report; }
    QTextBrowser* browser() const { return m_browser; }
    bool saveHtml(const QString& path, QString* error) const { return m_report.saveHtml(path, error); }
    bool savePdf(const QString& path, QString* error) const { return m_report.savePdf(path, error); }

private:
    void saveInteractive(bool pdf);

    SessionReport m_report;
    QTextBrowser* m_browser = nullptr;
    QPushButton* m_saveHtml = nullptr;
    QPushButton* m_savePdf = nullptr;
    QLabel* m_status = nullptr;
};

/// Loads the session from the context's store and shows its report (non-modal, deleted on close).
/// Returns the dialog, or nullptr when there is no store or the session cannot be loaded (a message
/// box says why and the error is logged).
ReportDialog* showSessionReport(AppContext& ctx, qint64 sessionId, QWidget* parent);

} // namespace gui
} // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The bottom dock of the main window: the application log (AppContext::logged) and the parameter
// journal of a machine (every parameter write the store recorded: time, axis, key, old → new, session).

#include <QString>
#include <QTabWidget>

class QPlainTextEdit;
class QTableWidget;

namespace axistune {
namespace gui {

class AppContext;

class LogPanel : public QTabWidget {
    Q_OBJECT
public:
    explicit LogPanel(AppContext& ctx, QWidget* parent = nullptr);

    /// Shows the journal of this machine (empty: none).
    void setMachine(const QString& machine);
    void refreshJournal();

    QPlainTextEdit* logView() const { return m_log; }
    QTableWidget* journalTable() const { return m_journal; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();

    AppContext& m_ctx;
    QString m_machine;
    QPlainTextEdit* m_log = nullptr;
    QTableWidget* m_journal = nullptr;
};

}  // namespace gui
}  // namespace axistune

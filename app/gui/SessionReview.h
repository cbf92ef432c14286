// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Session review: the sessions of a machine (id, kind, status with aborted/failed marked, started,
// operator, note, capture and result counts) from Database::listSessions. Open shows one session
// read-only in a document tab (SessionView); Overlay puts the FRFs of every selected session into one
// Bode plot (SessionOverlay). Documents go to the main window through AppContext::showDocument.

#include <QList>
#include <QString>
#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QTreeWidget;

namespace axistune {
namespace gui {

class AppContext;
class SessionOverlay;
class SessionView;

class SessionReview : public QWidget {
    Q_OBJECT
public:
    enum Column { ColId = 0, ColKind, ColStatus, ColStarted, ColOperator, ColNote, ColCaptures, ColResults, ColumnCount };

    explicit SessionReview(AppContext& ctx, QWidget* parent = nullptr);

    /// Lists the sessions of this machine (empty: of every machine).
    void setMachine(const QString& machine);
    QString machine() const;
    void reload();

    QTreeWidget* sessionList() const { return m_list; }
    QList<qint64> sessionIds() const;
    /// True when the row of this session is marked as aborted or failed.
    bool isMarkedAborted(qint64 id) const;
    void selectSessions(const QList<qint64>& ids);

    /// Loads the session and shows it as a document; the view (owned by the document area, or by
    /// nobody when no main window listens), or nullptr when it cannot be loaded (logged).
    SessionView* openSession(qint64 id);
    /// Overlays the FRFs of these sessions; nullptr when none can be loaded.
    SessionOverlay* overlaySessions(const QList<qint64>& ids);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void openSelected();
    void overlaySelected();
    void reloadMachines();
    QList<qint64> selectedIds() const;

    AppContext& m_ctx;
    QLabel* m_machineLabel = nullptr;
    QComboBox* m_machine = nullptr;
    QTreeWidget* m_list = nullptr;
    QPushButton* m_open = nullptr;
    QPushButton* m_overlay = nullptr;
    QPushButton* m_reload = nullptr;
    QPushButton* m_report = nullptr;  ///< only when ReportDialog.h is part of the build
    QString m_wantedMachine;
};

}  // namespace gui
}  // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The main window (DESIGN.md "The GUI"): machine/axis tree from the store plus the connected machine
// on the left; documents (session views, plots from wizards) in the centre; the parameter inspector
// (device / profile / proposed) on the right; log and journal at the bottom; connection, axis state
// and test progress with Abort in the status bar. Owns the one AppContext of the app.

#include "app/gui/DriveController.h"

#include <QMainWindow>
#include <QPointer>

#include <vector>

class QAction;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QTabWidget;
class QTableWidget;
class QTreeWidget;
class QTreeWidgetItem;
class QDockWidget;
class QWizard;

namespace axistune {
namespace gui {

class AppContext;
class LogPanel;
class ParameterInspector;
class ScopeDock;
class SessionReview;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    /// Opens the store at `storePath` (empty: QSettings "store/path" or the user's data directory).
    explicit MainWindow(const QString& storePath = QString(), QWidget* parent = nullptr);
    ~MainWindow() override;

    AppContext& context() { return *m_ctx; }

    /// Connects (asynchronously) to the built-in simulated machine with this preset; returns the
    /// request id. The tree and inspector update when the reply arrives.
    int connectSimulated(const QString& preset, quint64 seed = 1);
    /// Connects to any URI ("sim:PRESET", "modbus://HOST:PORT").
    int connectTo(const QString& uri, quint64 seed = 1);

    QTreeWidget* machineTree() const { return m_tree; }
    /// The table of the parameter inspector.
    QTableWidget* parameterTable() const;
    ParameterInspector* inspector() const { return m_inspector; }
    LogPanel* logPanel() const { return m_logPanel; }
    ScopeDock* scope() const { return m_scope; }
    QDockWidget* scopeDock() const { return m_scopeDock; }
    /// Shows and raises the scope dock (Tools → Scope).
    void showScope();
    QTabWidget* documents() const { return m_documents; }
    QMenu* wizardsMenu() const { return m_wizardsMenu; }
    /// The top-level menus in order (Machine, Wizards, Sessions, Settings, Help).
    std::vector<QMenu*> menus() const;
    /// The status-bar text of the connection.
    QString connectionText() const;
    /// The wizard actions (data: the wizard id).
    const std::vector<QAction*>& wizardActions() const { return m_wizardActions; }

    /// Adds a document tab (takes ownership) and shows it.
    void addDocument(QWidget* widget, const QString& title);
    /// Opens the wizard with this id modeless (nullptr when unknown or not allowed now).
    QWizard* openWizard(const QString& id);
    /// Opens the session list as a document tab.
    SessionReview* showSessionReview();

public slots:
    void showConnectDialog();
    void showSettings();
    void disconnectDrive();
    /// Selects an axis of the connected machine (or of the first machine with that axis).
    void showAxis(const QString& axis);
    /// Rebuilds the machine tree from the store and the connection.
    void populateTree();

protected:
    void changeEvent(QEvent* event) override;
    /// Waits for the session saves still queued (nothing is lost when the window closes).
    void closeEvent(QCloseEvent* event) override;

private:
    void buildUi();
    void buildMenus();
    void retranslateUi();
    void rebuildWizardMenu();
    void updateDriveActions();
    void onConnectionChanged(bool connected, const QString& description);
    void onConnectionLost(const QString& reason);
    void onReply(const DriveReply& reply);
    void onProgress(int id, double fraction, const QString& detail);
    void onTreeSelection(QTreeWidgetItem* item);
    void setConnectionText(const QString& text, bool error);
    void showAbout();

    AppContext* m_ctx = nullptr;
    QTreeWidget* m_tree = nullptr;
    QTabWidget* m_documents = nullptr;
    ParameterInspector* m_inspector = nullptr;
    LogPanel* m_logPanel = nullptr;
    QDockWidget* m_treeDock = nullptr;
    QDockWidget* m_inspectorDock = nullptr;
    QDockWidget* m_logDock = nullptr;
    ScopeDock* m_scope = nullptr;
    QDockWidget* m_scopeDock = nullptr;
    QPointer<SessionReview> m_review;

    QMenu* m_machineMenu = nullptr;
    QMenu* m_wizardsMenu = nullptr;
    QMenu* m_sessionsMenu = nullptr;
    QMenu* m_toolsMenu = nullptr;
    QMenu* m_settingsMenu = nullptr;
    QMenu* m_helpMenu = nullptr;
    QAction* m_connectAction = nullptr;
    QAction* m_disconnectAction = nullptr;
    QAction* m_quitAction = nullptr;
    QAction* m_reviewAction = nullptr;
    QAction* m_historyAction = nullptr;
    QAction* m_ncExportAction = nullptr;
    QAction* m_identifyAction = nullptr;
    QAction* m_scopeAction = nullptr;
    QAction* m_prefsAction = nullptr;
    QAction* m_aboutAction = nullptr;
    std::vector<QAction*> m_wizardActions;

    QLabel* m_connection = nullptr;
    QLabel* m_axisState = nullptr;
    QProgressBar* m_progress = nullptr;
    QProgressBar* m_saveProgress = nullptr; ///< session save on the store thread
    QPushButton* m_abort = nullptr;
    QString m_connectionRaw;   ///< untranslated state for retranslation: "", "connected", "lost", "failed"
    QString m_connectionDetail;
    QString m_testAxis;
    int m_connectRequest = -1;
};

}  // namespace gui
}  // namespace axistune

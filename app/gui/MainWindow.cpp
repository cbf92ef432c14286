// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/MainWindow.h"

#include "app/gui/AppContext.h"
#include "app/gui/ConnectDialog.h"
#include "app/gui/HistoryView.h"
#include "app/gui/IdentifyDialog.h"
#include "app/gui/LogPanel.h"
#include "app/gui/NcExportDialog.h"
#include "app/gui/ParameterInspector.h"
#include "app/gui/ScopeDock.h"
#include "app/gui/SessionReview.h"
#include "app/gui/SettingsDialog.h"
#include "app/gui/WizardRegistry.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QEvent>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTreeWidget>
#include <QWizard>

#include <algorithm>
#include <cmath>

namespace axistune {
namespace gui {

namespace {
constexpr int kMachineRole = Qt::UserRole;
constexpr int kAxisRole = Qt::UserRole + 1;
constexpr int kConnectedRole = Qt::UserRole + 2;
}  // namespace

MainWindow::MainWindow(const QString& storePath, QWidget* parent) : QMainWindow(parent), m_ctx(new AppContext(this))
{
    setObjectName("mainWindow");
    m_ctx->setOperatorName(QSettings().value("ui/operator").toString());
    buildUi();
    buildMenus();
    retranslateUi();

    connect(&m_ctx->drive(), &DriveController::connectionChanged, this, &MainWindow::onConnectionChanged);
    connect(&m_ctx->drive(), &DriveController::connectionLost, this, &MainWindow::onConnectionLost);
    connect(&m_ctx->drive(), &DriveController::replied, this, &MainWindow::onReply);
    connect(&m_ctx->drive(), &DriveController::progress, this, &MainWindow::onProgress);
    connect(m_ctx, &AppContext::sessionSaved, this, &MainWindow::populateTree);
    connect(m_ctx, &AppContext::savingChanged, this, [this](bool saving) {
        m_saveProgress->setValue(0);
        m_saveProgress->setVisible(saving);
    });
    connect(m_ctx, &AppContext::sessionSaveProgress, this, [this](double f) {
        m_saveProgress->setValue(static_cast<int>(std::lround(std::clamp(f, 0.0, 1.0) * 1000.0)));
    });
    connect(m_ctx, &AppContext::databaseChanged, this, &MainWindow::populateTree);
    connect(m_ctx, &AppContext::documentRequested, this, &MainWindow::addDocument);

    const QString path = storePath.isEmpty() ? defaultStorePath() : storePath;
    QDir().mkpath(QFileInfo(path).absolutePath());
    m_ctx->openDatabase(path);  // logs a failure; the app works without a store
    populateTree();
    updateDriveActions();
    showSessionReview();  // the centre starts with the session list of the store
}

MainWindow::~MainWindow()
{
    // Wizards and documents refer to the context: delete them before it goes.
    for (QWizard* w : findChildren<QWizard*>())
        delete w;
    delete m_documents;
    m_documents = nullptr;
}

void MainWindow::buildUi()
{
    m_documents = new QTabWidget(this);
    m_documents->setObjectName("documents");
    m_documents->setTabsClosable(true);
    m_documents->setDocumentMode(true);
    connect(m_documents, &QTabWidget::tabCloseRequested, this, [this](int i) {
        QWidget* w = m_documents->widget(i);
        m_documents->removeTab(i);
        w->deleteLater();
    });
    setCentralWidget(m_documents);

    m_tree = new QTreeWidget(this);
    m_tree->setObjectName("machineTree");
    m_tree->setColumnCount(2);
    m_tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_treeDock = new QDockWidget(this);
    m_treeDock->setObjectName("treeDock");
    m_treeDock->setWidget(m_tree);
    m_treeDock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    addDockWidget(Qt::LeftDockWidgetArea, m_treeDock);
    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) { onTreeSelection(item); });

    m_inspector = new ParameterInspector(*m_ctx, this);
    m_inspectorDock = new QDockWidget(this);
    m_inspectorDock->setObjectName("inspectorDock");
    m_inspectorDock->setWidget(m_inspector);
    m_inspectorDock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    addDockWidget(Qt::RightDockWidgetArea, m_inspectorDock);

    m_logPanel = new LogPanel(*m_ctx, this);
    m_logDock = new QDockWidget(this);
    m_logDock->setObjectName("logDock");
    m_logDock->setWidget(m_logPanel);
    m_logDock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    addDockWidget(Qt::BottomDockWidgetArea, m_logDock);

    // The scope (docs/scope.md "The GUI scope"): a tab beside the log, raised from Tools → Scope.
    m_scope = new ScopeDock(*m_ctx, this);
    m_scopeDock = new QDockWidget(this);
    m_scopeDock->setObjectName("scopeDockWidget");
    m_scopeDock->setWidget(m_scope);
    m_scopeDock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable |
                             QDockWidget::DockWidgetClosable);
    addDockWidget(Qt::BottomDockWidgetArea, m_scopeDock);
    tabifyDockWidget(m_logDock, m_scopeDock);
    m_logDock->raise();
    resizeDocks({m_treeDock, m_inspectorDock}, {190, 600}, Qt::Horizontal);
    resizeDocks({m_logDock}, {150}, Qt::Vertical);

    m_connection = new QLabel(this);
    m_connection->setObjectName("connectionLabel");
    m_axisState = new QLabel(this);
    m_axisState->setObjectName("axisStateLabel");
    m_progress = new QProgressBar(this);
    m_progress->setObjectName("testProgress");
    m_progress->setRange(0, 1000);
    m_progress->setMaximumWidth(180);
    m_progress->setVisible(false);
    m_abort = new QPushButton(this);
    m_abort->setObjectName("abortButton");
    m_abort->setVisible(false);
    connect(m_abort, &QPushButton::clicked, this, [this] {
        m_ctx->drive().abort();
        m_ctx->log(tr("Abort requested"));
    });
    statusBar()->addWidget(m_connection, 1);
    statusBar()->addPermanentWidget(m_axisState);
    m_saveProgress = new QProgressBar(this);
    m_saveProgress->setObjectName("saveProgress");
    m_saveProgress->setRange(0, 1000);
    m_saveProgress->setMaximumWidth(180);
    m_saveProgress->setVisible(false);
    statusBar()->addPermanentWidget(m_saveProgress);
    statusBar()->addPermanentWidget(m_progress);
    statusBar()->addPermanentWidget(m_abort);
    resize(1240, 760);
}

void MainWindow::buildMenus()
{
    m_machineMenu = menuBar()->addMenu(QString());
    m_connectAction = m_machineMenu->addAction(QString(), this, &MainWindow::showConnectDialog);
    m_disconnectAction = m_machineMenu->addAction(QString(), this, &MainWindow::disconnectDrive);
    m_machineMenu->addSeparator();
    m_quitAction = m_machineMenu->addAction(QString(), this, &QWidget::close);
    m_quitAction->setShortcut(QKeySequence::Quit);

    m_wizardsMenu = menuBar()->addMenu(QString());
    m_wizardsMenu->setObjectName("wizardsMenu");
    m_sessionsMenu = menuBar()->addMenu(QString());
    m_reviewAction = m_sessionsMenu->addAction(QString(), this, [this] { showSessionReview(); });
    m_historyAction = m_sessionsMenu->addAction(QString(), this, [this] { showHistory(*m_ctx, this); });
    m_ncExportAction = m_sessionsMenu->addAction(QString(), this, [this] { showNcExportDialog(*m_ctx, this); });
    m_toolsMenu = menuBar()->addMenu(QString());
    m_identifyAction = m_toolsMenu->addAction(QString(), this, [this] { showIdentifyDialog(this); });
    m_scopeAction = m_toolsMenu->addAction(QString(), this, [this] { showScope(); });
    m_settingsMenu = menuBar()->addMenu(QString());
    m_prefsAction = m_settingsMenu->addAction(QString(), this, &MainWindow::showSettings);
    m_helpMenu = menuBar()->addMenu(QString());
    m_aboutAction = m_helpMenu->addAction(QString(), this, &MainWindow::showAbout);
}

void MainWindow::rebuildWizardMenu()
{
    m_wizardsMenu->clear();
    m_wizardActions.clear();
    for (const auto& e : registeredWizards()) {
        QAction* a = m_wizardsMenu->addAction(wizardTitle(e));
        a->setData(e.id);
        a->setProperty("needsDrive", e.needsDrive);
        const QString id = e.id;
        connect(a, &QAction::triggered, this, [this, id] { openWizard(id); });
        m_wizardActions.push_back(a);
    }
    if (m_wizardActions.empty())
        m_wizardsMenu->addAction(tr("(no wizards)"))->setEnabled(false);
    updateDriveActions();
}

void MainWindow::showScope()
{
    m_scopeDock->show();
    m_scopeDock->raise();
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    m_ctx->waitForSaves();
    QMainWindow::closeEvent(event);
}

void MainWindow::retranslateUi()
{
    m_saveProgress->setFormat(tr("Saving session %p%"));
    setWindowTitle(tr("AxisTune"));
    m_machineMenu->setTitle(tr("&Machine"));
    m_connectAction->setText(tr("&Connect…"));
    m_disconnectAction->setText(tr("&Disconnect"));
    m_quitAction->setText(tr("&Quit"));
    m_wizardsMenu->setTitle(tr("&Wizards"));
    m_sessionsMenu->setTitle(tr("&Sessions"));
    m_reviewAction->setText(tr("&Review…"));
    m_historyAction->setText(tr("&History…"));
    m_ncExportAction->setText(tr("Export NC &parameters…"));
    m_toolsMenu->setTitle(tr("T&ools"));
    m_identifyAction->setText(tr("Identify from &motion…"));
    m_settingsMenu->setTitle(tr("Se&ttings"));
    m_prefsAction->setText(tr("&Preferences…"));
    m_helpMenu->setTitle(tr("&Help"));
    m_aboutAction->setText(tr("&About AxisTune"));
    m_tree->setHeaderLabels({tr("Machine / axis"), tr("State")});
    m_treeDock->setWindowTitle(tr("Machines"));
    m_inspectorDock->setWindowTitle(tr("Parameters"));
    m_logDock->setWindowTitle(tr("Log and journal"));
    m_scopeDock->setWindowTitle(tr("Scope"));
    m_scopeAction->setText(tr("&Scope"));
    m_abort->setText(tr("Abort"));
    m_abort->setToolTip(tr("Stops the running test at once; the drive restores the parameters from before the test"));
    rebuildWizardMenu();
    setConnectionText(QString(), false);
    m_axisState->setText(m_progress->isVisible() ? tr("Test running") : tr("Idle"));
    populateTree();
}

void MainWindow::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange && m_machineMenu)
        retranslateUi();
    QMainWindow::changeEvent(event);
}

std::vector<QMenu*> MainWindow::menus() const
{
    return {m_machineMenu, m_wizardsMenu, m_sessionsMenu, m_settingsMenu, m_helpMenu};
}

QTableWidget* MainWindow::parameterTable() const { return m_inspector->table(); }

QString MainWindow::connectionText() const { return m_connection->text(); }

void MainWindow::setConnectionText(const QString&, bool)
{
    // Built from the state so that a language switch rewrites it.
    QString text;
    bool error = false;
    if (m_connectionRaw == "connected")
        text = tr("Connected: %1 (machine %2)").arg(m_ctx->drive().uri(), m_ctx->machine());
    else if (m_connectionRaw == "connecting")
        text = tr("Connecting to %1 …").arg(m_ctx->drive().uri());
    else if (m_connectionRaw == "lost") {
        text = tr("CONNECTION LOST: %1").arg(m_connectionDetail);
        error = true;
    } else if (m_connectionRaw == "failed") {
        text = tr("Connection failed: %1").arg(m_connectionDetail);
        error = true;
    } else
        text = tr("Not connected");
    m_connection->setText(text);
    m_connection->setToolTip(text);
    m_connection->setStyleSheet(error ? "QLabel { color: white; background: #c62828; font-weight: bold; padding: 1px 4px; }"
                                      : QString());
}

int MainWindow::connectSimulated(const QString& preset, quint64 seed) { return connectTo("sim:" + preset, seed); }

int MainWindow::connectTo(const QString& uri, quint64 seed)
{
    m_connectionRaw = "connecting";
    m_connectRequest = m_ctx->drive().connectTo(uri, seed)->id();
    setConnectionText(QString(), false);
    m_ctx->log(tr("Connecting to %1").arg(uri));
    return m_connectRequest;
}

void MainWindow::disconnectDrive()
{
    m_ctx->drive().abort();
    m_ctx->drive().disconnectFrom();
}

void MainWindow::onConnectionChanged(bool connected, const QString&)
{
    // The state text follows the Connect/Disconnect replies (onReply) and connectionLost.
    if (connected)
        m_ctx->log(tr("Connected to %1: machine %2, axes %3")
                       .arg(m_ctx->drive().uri(), m_ctx->machine(), m_ctx->axes().join(", ")));
    populateTree();
    updateDriveActions();
    if (connected && !m_ctx->axes().isEmpty())
        showAxis(m_ctx->axes().front());
}

void MainWindow::onConnectionLost(const QString& reason)
{
    m_connectionRaw = "lost";
    m_connectionDetail = reason;
    m_ctx->log(tr("Connection lost: %1").arg(reason));
    setConnectionText(QString(), true);
    m_progress->setVisible(false);
    m_abort->setVisible(false);
    m_axisState->setText(tr("Idle"));
    populateTree();
    updateDriveActions();
}

void MainWindow::onReply(const DriveReply& reply)
{
    if (reply.kind == DriveReply::Kind::Connect) {
        m_connectionRaw = reply.ok ? "connected" : "failed";
        m_connectionDetail = reply.error;
        if (!reply.ok)
            m_ctx->log(tr("Connection to %1 failed: %2").arg(m_ctx->drive().uri(), reply.error));
        setConnectionText(QString(), !reply.ok);
        return;
    }
    if (reply.kind == DriveReply::Kind::Disconnect) {
        m_connectionRaw.clear();
        m_ctx->log(tr("Disconnected"));
        setConnectionText(QString(), false);
        return;
    }
    if (reply.kind == DriveReply::Kind::Test) {
        m_progress->setVisible(false);
        m_abort->setVisible(false);
        m_axisState->setText(tr("Idle"));
        m_ctx->log(reply.ok ? tr("Test on axis %1 completed").arg(reply.axis)
                            : tr("Test on axis %1 ended: %2").arg(reply.axis, reply.error));
    }
}

void MainWindow::onProgress(int, double fraction, const QString& detail)
{
    m_progress->setVisible(true);
    m_abort->setVisible(true);
    m_progress->setValue(static_cast<int>(std::clamp(fraction, 0.0, 1.0) * 1000.0));
    m_progress->setToolTip(detail);
    m_axisState->setText(tr("Test running"));
}

void MainWindow::updateDriveActions()
{
    const bool connected = m_ctx->drive().isConnected();
    m_disconnectAction->setEnabled(connected);
    for (QAction* a : m_wizardActions)
        a->setEnabled(connected || !a->property("needsDrive").toBool());
}

void MainWindow::populateTree()
{
    if (!m_tree)
        return;
    QString selMachine, selAxis;
    if (auto* cur = m_tree->currentItem()) {
        selMachine = cur->data(0, kMachineRole).toString();
        selAxis = cur->data(0, kAxisRole).toString();
    }
    const QSignalBlocker block(m_tree);
    m_tree->clear();
    const QString connected = m_ctx->machine();
    std::vector<std::pair<QString, QStringList>> machines;  // name, axes
    std::map<QString, int> sessions;
    if (auto* db = m_ctx->database()) {
        if (auto names = db->listMachines()) {
            for (const auto& n : *names) {
                QStringList axes;
                if (auto p = db->loadProfile(n))
                    for (const auto& a : p->axes)
                        axes << QString::fromStdString(a.name);
                machines.emplace_back(QString::fromStdString(n), axes);
                if (auto s = db->listSessions(n))
                    sessions[QString::fromStdString(n)] = static_cast<int>(s->size());
            }
        }
    }
    if (!connected.isEmpty()) {
        auto it = std::find_if(machines.begin(), machines.end(), [&](const auto& m) { return m.first == connected; });
        if (it == machines.end())
            machines.emplace_back(connected, m_ctx->axes());
        else
            for (const auto& a : m_ctx->axes())
                if (!it->second.contains(a))
                    it->second << a;
    }
    QTreeWidgetItem* toSelect = nullptr;
    for (const auto& [name, axes] : machines) {
        const bool isConnected = name == connected;
        auto* root = new QTreeWidgetItem(m_tree, {name});
        root->setData(0, kMachineRole, name);
        root->setData(0, kConnectedRole, isConnected);
        const int n = sessions.count(name) ? sessions[name] : 0;
        QString state = tr("%n session(s)", "", n);
        if (isConnected) {
            state = tr("connected, %1").arg(state);
            QFont f = root->font(0);
            f.setBold(true);
            root->setFont(0, f);
            root->setForeground(1, QColor(0, 128, 0));
        }
        root->setText(1, state);
        for (const auto& a : axes) {
            auto* item = new QTreeWidgetItem(root, {a});
            item->setData(0, kMachineRole, name);
            item->setData(0, kAxisRole, a);
            item->setData(0, kConnectedRole, isConnected);
            if (name == selMachine && a == selAxis)
                toSelect = item;
        }
    }
    m_tree->expandAll();
    if (toSelect)
        m_tree->setCurrentItem(toSelect);
    m_logPanel->setMachine(!selMachine.isEmpty() ? selMachine : connected);
}

void MainWindow::onTreeSelection(QTreeWidgetItem* item)
{
    if (!item)
        return;
    const QString machine = item->data(0, kMachineRole).toString();
    const QString axis = item->data(0, kAxisRole).toString();
    m_logPanel->setMachine(machine);
    if (!axis.isEmpty())
        m_inspector->setAxis(machine, axis);
    if (m_review)
        m_review->setMachine(machine);
}

void MainWindow::showAxis(const QString& axis)
{
    const QString connected = m_ctx->machine();
    QTreeWidgetItem* fallback = nullptr;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i) {
        auto* root = m_tree->topLevelItem(i);
        for (int j = 0; j < root->childCount(); ++j) {
            auto* c = root->child(j);
            if (c->data(0, kAxisRole).toString() != axis)
                continue;
            if (root->data(0, kMachineRole).toString() == connected) {
                m_tree->setCurrentItem(c);
                return;
            }
            if (!fallback)
                fallback = c;
        }
    }
    if (fallback)
        m_tree->setCurrentItem(fallback);
}

void MainWindow::addDocument(QWidget* widget, const QString& title)
{
    if (!widget)
        return;
    const int i = m_documents->addTab(widget, title);
    m_documents->setCurrentIndex(i);
}

QWizard* MainWindow::openWizard(const QString& id)
{
    const WizardEntry* e = findWizard(id);
    if (!e || (e->needsDrive && !m_ctx->drive().isConnected()))
        return nullptr;
    QWizard* w = e->create(*m_ctx, this);
    if (!w)
        return nullptr;
    w->setAttribute(Qt::WA_DeleteOnClose);
    w->setWindowFlag(Qt::Window);
    w->setModal(false);
    w->show();
    return w;
}

SessionReview* MainWindow::showSessionReview()
{
    if (m_review) {
        m_documents->setCurrentWidget(m_review);
        return m_review;
    }
    m_review = new SessionReview(*m_ctx);
    auto* cur = m_tree->currentItem();
    m_review->setMachine(cur ? cur->data(0, kMachineRole).toString() : m_ctx->machine());
    addDocument(m_review, tr("Sessions"));
    return m_review;
}

void MainWindow::showConnectDialog()
{
    auto* d = new ConnectDialog(*m_ctx, this);
    d->setAttribute(Qt::WA_DeleteOnClose);
    d->open();
}

void MainWindow::showSettings()
{
    auto* d = new SettingsDialog(*m_ctx, this);
    d->setAttribute(Qt::WA_DeleteOnClose);
    d->open();
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About AxisTune"),
                       tr("<b>AxisTune</b> %1<br>Commissioning and tuning of NC feed axes.<br>"
                          "GPL-3.0-or-later.")
                           .arg(QApplication::applicationVersion()));
}

}  // namespace gui
}  // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/MainWindow.h"

#include "app/gui/ParameterText.h"

#include "core/model/Parameter.h"
#include "core/model/Units.h"
#include "core/sim/MachineDefinition.h"

#include <QApplication>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSplitter>
#include <QStatusBar>
#include <QTableWidget>
#include <QTreeWidget>

namespace axistune {
namespace gui {

namespace {
QString displayValue(const model::ParameterMeta& meta, double si)
{
    auto v = model::convertUnit(si, meta.siUnit, meta.displayUnit);
    return QString::number(v ? *v : si, 'g', 6);
}
QString unitText(const std::string& token) { return QString::fromStdString(model::unitLabel(token)); }
}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) { buildUi(); }

MainWindow::~MainWindow() = default;

void MainWindow::buildUi()
{
    setWindowTitle(tr("AxisTune"));
    auto* fileMenu = menuBar()->addMenu(tr("&Machine"));
    fileMenu->addAction(tr("&Connect…"), this, &MainWindow::showConnectDialog);
    fileMenu->addSeparator();
    fileMenu->addAction(tr("&Quit"), qApp, &QApplication::quit);

    auto* split = new QSplitter(this);
    m_tree = new QTreeWidget(split);
    m_tree->setHeaderLabel(tr("Machine / axis"));
    m_tree->setMinimumWidth(180);
    m_params = new QTableWidget(split);
    m_params->setColumnCount(5);
    m_params->setHorizontalHeaderLabels({tr("Parameter"), tr("Key"), tr("Value"), tr("Unit"), tr("Limits")});
    // Values, units and limits take what they need; the parameter name takes the rest.
    m_params->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_params->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_params->setWordWrap(false);
    m_params->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_params->verticalHeader()->hide();
    split->setStretchFactor(1, 1);
    setCentralWidget(split);

    m_connection = new QLabel(tr("Not connected"), this);
    statusBar()->addPermanentWidget(m_connection);

    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
        if (item && item->parent())
            showAxis(item->text(0));
    });
    resize(1000, 640);
}

bool MainWindow::connectSimulated(const QString& preset)
{
    auto d = device::connect({"sim:" + preset.toStdString(), 1});
    if (!d) {
        QMessageBox::warning(this, tr("Connection failed"),
                             tr("Could not start the simulated machine: %1").arg(QString::fromStdString(d.error().detail)));
        return false;
    }
    m_drive = std::move(d).value();
    m_machine = preset;
    m_connection->setText(tr("Connected: simulated machine %1").arg(preset));
    populateTree();
    return true;
}

void MainWindow::populateTree()
{
    m_tree->clear();
    auto id = m_drive->identify();
    if (!id)
        return;
    auto* root = new QTreeWidgetItem(m_tree, {m_machine});
    for (const auto& a : id->axes)
        new QTreeWidgetItem(root, {QString::fromStdString(a)});
    m_tree->expandAll();
    if (root->childCount() > 0)
        m_tree->setCurrentItem(root->child(0));
}

void MainWindow::showAxis(const QString& axis)
{
    if (!m_drive)
        return;
    const std::string a = axis.toStdString();
    auto metas = m_drive->parameterMetadata(a);
    auto values = m_drive->readParameters(a, {});
    if (!metas || !values) {
        statusBar()->showMessage(tr("Reading the parameters of axis %1 failed").arg(axis), 5000);
        return;
    }
    m_params->setRowCount(static_cast<int>(metas->size()));
    int row = 0;
    for (const auto& m : *metas) {
        const double v = values->count(m.key) ? values->at(m.key) : 0.0;
        auto* name = new QTableWidgetItem(parameterLabel(m.label));
        m_params->setItem(row, 0, name);
        m_params->setItem(row, 1, new QTableWidgetItem(QString::fromStdString(m.key)));
        auto* val = new QTableWidgetItem(displayValue(m, v));
        val->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_params->setItem(row, 2, val);
        m_params->setItem(row, 3, new QTableWidgetItem(unitText(m.displayUnit)));
        m_params->setItem(row, 4, new QTableWidgetItem(tr("%1 … %2%3")
                                                           .arg(displayValue(m, m.minSi), displayValue(m, m.maxSi),
                                                                m.writable ? QString() : tr(" (read-only)"))));
        ++row;
    }
    statusBar()->showMessage(tr("Axis %1: %2 parameters read from the drive").arg(axis).arg(row), 5000);
}

void MainWindow::showConnectDialog()
{
    QStringList presets;
    for (const auto& p : sim::presetNames())
        presets << QString::fromStdString(p);
    bool ok = false;
    const int current = std::max(0, static_cast<int>(presets.indexOf(m_machine.isEmpty() ? "vmc" : m_machine)));
    const QString p = QInputDialog::getItem(this, tr("Connect"), tr("Built-in simulated machine:"), presets, current,
                                            false, &ok);
    if (ok && !p.isEmpty())
        connectSimulated(p);
}

}  // namespace gui
}  // namespace axistune

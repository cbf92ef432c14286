// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The main window: machine/axis tree on the left, the selected axis's parameters (read through the
// Drive, with units) on the right, connection state in the status bar.

#include "core/device/Drive.h"

#include <QMainWindow>

#include <memory>

class QTreeWidget;
class QTableWidget;
class QLabel;

namespace axistune {
namespace gui {

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Connects to the built-in simulated machine with this preset; false (and a message) on error.
    bool connectSimulated(const QString& preset);

    QTreeWidget* machineTree() const { return m_tree; }
    QTableWidget* parameterTable() const { return m_params; }

public slots:
    void showConnectDialog();
    void showAxis(const QString& axis);

private:
    void buildUi();
    void populateTree();

    std::unique_ptr<device::Drive> m_drive;
    QString m_machine;
    QTreeWidget* m_tree = nullptr;
    QTableWidget* m_params = nullptr;
    QLabel* m_connection = nullptr;
};

}  // namespace gui
}  // namespace axistune

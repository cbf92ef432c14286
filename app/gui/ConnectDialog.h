// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The connection dialog: the built-in simulated machine (default; preset and noise seed) or a drive
// over Modbus TCP (host, port, response timeout, register map; the unit ids come from the register
// map: axis i answers on unit_id_base + i, docs/modbus.md). Connect goes through
// DriveController::connectTo; the dialog stays open and responsive while connecting and shows the
// drive's message when the connection fails.

#include "app/gui/DriveController.h"

#include <QDialog>

class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QRadioButton;
class QSpinBox;
class QStackedWidget;

namespace axistune {
namespace gui {

class AppContext;

class ConnectDialog : public QDialog {
    Q_OBJECT
public:
    explicit ConnectDialog(AppContext& ctx, QWidget* parent = nullptr);

    /// The URI the current settings describe ("sim:vmc", "modbus://HOST:PORT?timeout_ms=N").
    QString uri() const;
    quint64 seed() const;
    /// Selects the simulated machine with this preset, or Modbus TCP with host and port.
    void setSimulated(const QString& preset, quint64 seed = 1);
    void setModbus(const QString& host, int port);
    /// Starts connecting (what the Connect button does).
    void startConnect();
    /// The message shown after a failed attempt (empty otherwise).
    QString errorText() const;
    bool isConnecting() const { return m_request >= 0; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void onReply(const DriveReply& reply);
    void retranslateUi();
    void updateMode();

    AppContext& m_ctx;
    QRadioButton* m_simRadio = nullptr;
    QRadioButton* m_modbusRadio = nullptr;
    QStackedWidget* m_stack = nullptr;
    QLabel* m_presetLabel = nullptr;
    QComboBox* m_preset = nullptr;
    QLabel* m_seedLabel = nullptr;
    QSpinBox* m_seed = nullptr;
    QLabel* m_modelLabel = nullptr;
    QLineEdit* m_model = nullptr;
    QLabel* m_modelAxisLabel = nullptr;
    QLineEdit* m_modelAxis = nullptr;
    QLabel* m_hostLabel = nullptr;
    QLineEdit* m_host = nullptr;
    QLabel* m_portLabel = nullptr;
    QSpinBox* m_port = nullptr;
    QLabel* m_timeoutLabel = nullptr;
    QSpinBox* m_timeout = nullptr;
    QLabel* m_mapLabel = nullptr;
    QLineEdit* m_map = nullptr;
    QLabel* m_unitNote = nullptr;
    QLabel* m_status = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
    QPushButton* m_connectButton = nullptr;
    int m_request = -1;
    bool m_failed = false;
};

}  // namespace gui
}  // namespace axistune

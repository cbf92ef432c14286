// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The connection dialog: one choice per registered drive backend (core/device/DriveRegistry.h,
// docs/drive-seam.md): the built-in simulated machine (default), a drive over Modbus TCP, a replayed
// capture, and whatever registers later. Each backend's settings form is built from its setting
// descriptions (label, type, default, unit); the labels are translated in the context
// "DriveRegistry". Connect goes through DriveController::connectTo; the dialog stays open and
// responsive while connecting and shows the drive's message when the connection fails.

#include "app/gui/DriveController.h"

#include <QDialog>

#include <map>
#include <vector>

class QButtonGroup;
class QComboBox;
class QDialogButtonBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QSpinBox;
class QStackedWidget;
class QWidget;

namespace axistune {
namespace device {
struct DriveBackend;
}
namespace gui {

class AppContext;

class ConnectDialog : public QDialog {
    Q_OBJECT
public:
    explicit ConnectDialog(AppContext& ctx, QWidget* parent = nullptr);

    /// The URI the current settings describe ("sim:vmc", "modbus://HOST:PORT?timeout_ms=N", "replay:FILE");
    /// empty when a setting is refused (settingsError() says why).
    QString uri() const;
    /// Why the current settings make no URI (empty when they do).
    QString settingsError() const;
    quint64 seed() const;
    /// Selects the backend with this scheme ("sim:", "modbus://", "replay:"); false when none is registered.
    bool selectBackend(const QString& scheme);
    /// Sets one setting of the selected backend by its name (DriveRegistry.h); false when there is none.
    bool setSetting(const QString& name, const QString& value);
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
    struct Field {
        QLabel* label = nullptr;
        QWidget* editor = nullptr;
    };
    struct Page {
        const device::DriveBackend* backend = nullptr;
        QRadioButton* radio = nullptr;
        QLabel* form = nullptr; ///< the URI form and description
        std::vector<Field> fields;
        QLabel* seedLabel = nullptr;
        QSpinBox* seed = nullptr;
    };
    void onReply(const DriveReply& reply);
    void retranslateUi();
    void updateMode();
    int current() const;
    QString value(const Page& page, std::size_t field) const;
    void setValue(Page& page, std::size_t field, const QString& value);

    AppContext& m_ctx;
    std::vector<Page> m_pages;
    QButtonGroup* m_group = nullptr;
    QStackedWidget* m_stack = nullptr;
    QLabel* m_status = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
    QPushButton* m_connectButton = nullptr;
    int m_request = -1;
    bool m_failed = false;
};

/// A backend's key for object names and settings: its scheme without ':' and '/' ("sim", "modbus").
QString backendKey(const device::DriveBackend& backend);

} // namespace gui
} // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The parameter inspector (right dock of the main window): for one axis, every parameter with the
// value on the device (read through the DriveController, asynchronously), in the profile (the store's
// current parameters) and proposed by a wizard (AppContext::proposed), with unit and limits.
// Differences are highlighted: a profile value that differs from the device, a proposed value that
// differs from the device. Refreshed on parametersApplied, proposedChanged and sessionSaved.

#include "app/gui/DriveController.h"

#include "core/model/Parameter.h"

#include <QString>
#include <QWidget>

#include <map>
#include <optional>
#include <vector>

class QLabel;
class QTableWidget;

namespace axistune {
namespace gui {

class AppContext;

class ParameterInspector : public QWidget {
    Q_OBJECT
public:
    enum Column { ColParameter = 0, ColDevice, ColProfile, ColProposed, ColUnit, ColLimits, ColumnCount };

    explicit ParameterInspector(AppContext& ctx, QWidget* parent = nullptr);

    /// Shows `axis` of `machine`; the device column is filled only when `machine` is the connected one.
    void setAxis(const QString& machine, const QString& axis);
    QString machine() const { return m_machine; }
    QString axis() const { return m_axis; }
    /// Reads profile and proposed values again and, when connected, the device values.
    void refresh();

    QTableWidget* table() const { return m_table; }
    /// Row of a parameter key, -1 when not shown.
    int rowOf(const QString& key) const;
    /// Text of a cell of a parameter (empty when the key or value is missing).
    QString cellText(const QString& key, Column column) const;
    /// True when the cell is highlighted as different from the device value.
    bool isHighlighted(const QString& key, Column column) const;
    /// True once the device values of the current axis have arrived (or when none are expected).
    bool deviceValuesShown() const { return m_deviceShown; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void onReply(const DriveReply& reply);
    void requestDevice();
    void loadStoreValues();
    void rebuild();
    void retranslateUi();
    bool isConnectedMachine() const;

    AppContext& m_ctx;
    QLabel* m_title = nullptr;
    QTableWidget* m_table = nullptr;
    QString m_machine;
    QString m_axis;
    int m_metaRequest = -1;
    int m_readRequest = -1;
    bool m_deviceShown = true;
    std::map<QString, std::vector<model::ParameterMeta>> m_metaCache;  ///< per axis of the connection
    model::ParameterValues m_device;
    model::ParameterValues m_profile;
    model::ParameterValues m_proposed;
};

}  // namespace gui
}  // namespace axistune

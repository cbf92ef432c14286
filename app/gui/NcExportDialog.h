// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// NC export dialog (docs/reports.md): choose the NC family, see the NC parameter numbers and values of
// the machine's current parameters (store profile) per axis, the keys without a mapping, the file as
// it will be written, and save it. The file is exactly io::exportNc's text.

#include "core/io/NcExport.h"
#include "core/io/Profile.h"

#include <QDialog>
#include <QStringList>

#include <optional>

class QComboBox;
class QLabel;
class QListWidget;
class QPlainTextEdit;
class QPushButton;
class QTableWidget;

namespace axistune {
namespace gui {

class AppContext;

class NcExportDialog : public QDialog {
    Q_OBJECT
public:
    enum Column { ColAxis = 0, ColKey, ColNumber, ColNcValue, ColValue, ColDescription, ColumnCount };

    explicit NcExportDialog(AppContext& ctx, QWidget* parent = nullptr);

    /// The NC families found in the map directory (resources/nc/*.json).
    static QStringList families();

    QComboBox* machineBox() const { return m_machine; }
    QComboBox* familyBox() const { return m_family; }
    QComboBox* axisBox() const { return m_axis; }
    QTableWidget* table() const { return m_table; }
    QListWidget* unmappedList() const { return m_unmapped; }
    /// The text the dialog would write (empty when the export failed; see errorText()).
    QString exportText() const;
    QString errorText() const { return m_error; }

    void setMachine(const QString& machine);
    void setFamily(const QString& family);
    /// Writes the export to `path`; false with `error` when there is none or it cannot be written.
    bool saveTo(const QString& path, QString* error) const;

private:
    void reloadMachines();
    void loadProfile();
    void refresh();
    void fillTable();
    void saveInteractive();

    AppContext& m_ctx;
    QComboBox* m_machine = nullptr;
    QComboBox* m_family = nullptr;
    QComboBox* m_axis = nullptr;
    QTableWidget* m_table = nullptr;
    QListWidget* m_unmapped = nullptr;
    QPlainTextEdit* m_preview = nullptr;
    QLabel* m_status = nullptr;
    QPushButton* m_save = nullptr;
    std::optional<io::MachineProfile> m_profile;
    std::optional<io::NcMap> m_map;
    std::optional<io::NcExport> m_export;
    QString m_error;
};

/// Opens the NC export dialog for the context's machine (non-modal, deleted on close).
NcExportDialog* showNcExportDialog(AppContext& ctx, QWidget* parent);

} // namespace gui
} // namespace axistune

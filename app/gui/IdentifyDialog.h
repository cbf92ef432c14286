// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// "Identify from motion" (docs/identification.md "The dialog"): load a capture, pick the position and
// force columns, identify inertia, viscous and Coulomb friction and the offset with their standard
// deviations (core/ident), optionally validate on a second record under its controller with a plot of
// measured against simulated position, and save the result JSON `axistune-cli identify` writes.

#include "core/ident/MotionIdentification.h"
#include "core/model/Capture.h"

#include <QDialog>

#include <nlohmann/json.hpp>
#include <optional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace axistune {
namespace widgets {
class TimeTracePlot;
}
namespace gui {

class IdentifyDialog : public QDialog {
    Q_OBJECT
public:
    explicit IdentifyDialog(QWidget* parent = nullptr);

    /// Loads a capture CSV and fills the column choices; false with the reason shown otherwise.
    bool loadEstimation(const QString& path);
    bool loadValidation(const QString& path);
    /// Picks a column by name in one of the boxes (position, force, reference, extra).
    void selectColumns(const QString& position, const QString& force, const QString& reference = {},
                       const QString& extra = {});
    /// Reads kp_per_s, kv, saturation, delay_samples, force_scale into the controller fields.
    bool loadController(const QString& path);
    /// Runs the identification (and the validation when a record is loaded); false when refused.
    bool identify();
    bool saveTo(const QString& path, QString* error) const;

    QTableWidget* resultTable() const { return m_table; }
    QString statusText() const;
    QString validationText() const;
    QDoubleSpinBox* forceScaleBox() const { return m_forceScale; }
    QComboBox* unitBox() const { return m_unit; }
    QCheckBox* asymmetricBox() const { return m_asymmetric; }
    widgets::TimeTracePlot* plot() const { return m_plot; }
    const std::optional<nlohmann::json>& result() const { return m_result; }

private:
    QWidget* buildInputs();
    QWidget* buildController();
    void showResult(const ident::IdentificationResult& r, ident::AxisMotion motion);
    void showValidation(const ident::ValidationRecord& rec, const ident::ValidationResult& v, ident::AxisMotion motion);
    void setStatus(const QString& text, bool error);
    std::optional<model::Capture> readCapture(const QString& path);

    QLineEdit* m_estFile = nullptr;
    QLineEdit* m_valFile = nullptr;
    QComboBox* m_position = nullptr;
    QComboBox* m_force = nullptr;
    QComboBox* m_reference = nullptr;
    QComboBox* m_extra = nullptr;
    QComboBox* m_unit = nullptr;
    QDoubleSpinBox* m_forceScale = nullptr;
    QDoubleSpinBox* m_cutoff = nullptr;
    QCheckBox* m_asymmetric = nullptr;
    QDoubleSpinBox* m_kp = nullptr;
    QDoubleSpinBox* m_kv = nullptr;
    QDoubleSpinBox* m_saturation = nullptr;
    QSpinBox* m_delay = nullptr;
    QDoubleSpinBox* m_ctrlScale = nullptr;
    QTableWidget* m_table = nullptr;
    QLabel* m_status = nullptr;
    QLabel* m_validation = nullptr;
    QPushButton* m_save = nullptr;
    widgets::TimeTracePlot* m_plot = nullptr;
    std::optional<model::Capture> m_estCapture, m_valCapture;
    std::optional<nlohmann::json> m_result;
};

/// Opens the dialog (non-modal, deleted on close).
IdentifyDialog* showIdentifyDialog(QWidget* parent);

} // namespace gui
} // namespace axistune

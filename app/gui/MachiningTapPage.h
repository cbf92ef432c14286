// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The machining wizard's tap-test page (docs/machining.md "Tap test", docs/wizards/machining.md): impact
// records (any import format) → receptance by core/dsp/ImpactTest → used as the tool's x and/or y FRF
// (the tool page fits the modes; the exponential window's damping is removed from them).
// Reached from the tool page's "Tap test…" button; Next continues to the cut page.

#include "core/dsp/ImpactTest.h"

#include <QStringList>
#include <QTemporaryDir>
#include <QWizardPage>

#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace axistune {
namespace widgets {
class BodePlot;
}
namespace gui {

class MachiningToolPage;

class MachiningTapPage : public QWizardPage {
    Q_OBJECT
public:
    MachiningTapPage(MachiningToolPage& tool, QWidget* parent = nullptr);
    QListWidget* records() const { return m_records; }
    QComboBox* forceColumn() const { return m_force; }
    QComboBox* responseColumn() const { return m_response; }
    QComboBox* responseType() const { return m_responseType; }
    QLineEdit* triggerN() const { return m_trigger; }
    QLineEdit* expTauMs() const { return m_expTau; }
    QComboBox* doubleHit() const { return m_doubleHit; }
    QSpinBox* modes() const { return m_modes; }
    QLabel* summary() const { return m_summary; }
    QLabel* errorLabel() const { return m_error; }
    widgets::BodePlot* plot() const { return m_plot; }
    const std::optional<dsp::ImpactResult>& result() const { return m_result; }

    /// Adds a record file; the column choices come from the first one. False (message shown) on error.
    bool addRecord(const QString& path);
    /// Computes the receptance from the records; false (message shown) on error.
    bool compute();
    /// Saves the receptance as an FRF CSV (units=m/N and the tap-test keys).
    bool saveFrf(const QString& path);
    /// Uses the receptance as the tool FRF in x, y or both ("x", "y", "xy"); when both directions have one,
    /// the tool page fits the modes and the window's damping is removed. False (message shown) on error.
    bool useAsToolFrf(const QString& direction);
    int nextId() const override;

private:
    void fillColumns(const QStringList& names);
    void setError(const QString& text);
    MachiningToolPage& m_tool;
    QListWidget* m_records = nullptr;
    QComboBox *m_force = nullptr, *m_response = nullptr, *m_responseType = nullptr, *m_doubleHit = nullptr;
    QLineEdit *m_trigger = nullptr, *m_expTau = nullptr;
    QSpinBox* m_modes = nullptr;
    QLabel *m_summary = nullptr, *m_error = nullptr;
    widgets::BodePlot* m_plot = nullptr;
    std::optional<dsp::ImpactResult> m_result;
    QTemporaryDir m_dir;
    QString m_xPath, m_yPath;
    int m_saved = 0;
};

} // namespace gui
} // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small widget helpers the wizard pages share: read-only tables, spin boxes with unit suffixes.

#include <QString>
#include <QStringList>

#include <string>

class QDoubleSpinBox;
class QTableWidget;
class QWidget;

namespace axistune {
namespace gui {

inline QString qs(const std::string& s) { return QString::fromStdString(s); }

/// A read-only table with these column headers, no row numbers, the last column stretched.
QTableWidget* makeTable(QWidget* parent, const QStringList& headers, const char* objectName = nullptr);
/// Appends a row of text cells.
void addRow(QTableWidget* table, const QStringList& cells);
/// A spin box over [lo, hi] with `decimals` and a unit suffix (" Hz", " ms").
QDoubleSpinBox* spin(QWidget* parent, double lo, double hi, double value, int decimals, const QString& suffix,
                     const char* objectName = nullptr);

} // namespace gui
} // namespace axistune

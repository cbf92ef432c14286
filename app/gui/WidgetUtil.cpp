// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/WidgetUtil.h"

#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QTableWidget>

namespace axistune {
namespace gui {

QTableWidget* makeTable(QWidget* parent, const QStringList& headers, const char* objectName)
{
    auto* t = new QTableWidget(0, static_cast<int>(headers.size()), parent);
    if (objectName)
        t->setObjectName(objectName);
    t->setHorizontalHeaderLabels(headers);
    t->verticalHeader()->setVisible(false);
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->horizontalHeader()->setStretchLastSection(true);
    t->setWordWrap(true);
    return t;
}

void addRow(QTableWidget* t, const QStringList& cells)
{
    const int r = t->rowCount();
    t->insertRow(r);
    for (int c = 0; c < cells.size(); ++c)
        t->setItem(r, c, new QTableWidgetItem(cells[c]));
}

QDoubleSpinBox* spin(QWidget* parent, double lo, double hi, double value, int decimals, const QString& suffix,
                     const char* objectName)
{
    auto* s = new QDoubleSpinBox(parent);
    s->setRange(lo, hi);
    s->setDecimals(decimals);
    s->setValue(value);
    s->setSuffix(suffix);
    if (objectName)
        s->setObjectName(objectName);
    return s;
}

} // namespace gui
} // namespace axistune

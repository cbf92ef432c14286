// SPDX-License-Identifier: GPL-3.0-or-later
// NC export dialog over core/io/NcExport (map files resources/nc/<family>.json, docs/formats-profile.md).
#include "app/gui/NcExportDialog.h"

#include "app/gui/AppContext.h"
#include "core/model/Parameter.h"
#include "core/model/Units.h"
#include "core/sim/AxisParameters.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

namespace {

QString siValueText(const std::string& key, double v)
{
    for (auto kind : {sim::AxisKind::Linear, sim::AxisKind::Rotary})
        if (const auto* m = model::findParameter(sim::axisParameterMetas(kind), key))
            return QString::fromStdString(model::formatDisplay(*m, v));
    return QString::number(v, 'g', 8);
}

} // namespace

NcExportDialog::NcExportDialog(AppContext& ctx, QWidget* parent) : QDialog(parent), m_ctx(ctx)
{
    setObjectName(QStringLiteral("ncExportDialog"));
    setWindowTitle(tr("Export NC parameters"));
    m_machine = new QComboBox(this);
    m_machine->setObjectName(QStringLiteral("ncMachine"));
    m_family = new QComboBox(this);
    m_family->setObjectName(QStringLiteral("ncFamily"));
    for (const auto& f : families())
        m_family->addItem(f, f);
    m_axis = new QComboBox(this);
    m_axis->setObjectName(QStringLiteral("ncAxis"));
    m_table = new QTableWidget(0, ColumnCount, this);
    m_table->setObjectName(QStringLiteral("ncTable"));
    m_table->setHorizontalHeaderLabels(
        {tr("Axis"), tr("Parameter"), tr("NC number"), tr("NC value"), tr("AxisTune value"), tr("Description")});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_unmapped = new QListWidget(this);
    m_unmapped->setObjectName(QStringLiteral("ncUnmapped"));
    m_preview = new QPlainTextEdit(this);
    m_preview->setObjectName(QStringLiteral("ncPreview"));
    m_preview->setReadOnly(true);
    m_preview->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("ncStatus"));
    m_status->setWordWrap(true);
    m_save = new QPushButton(tr("Save file…"), this);
    m_save->setObjectName(QStringLiteral("ncSave"));
    auto* close = new QPushButton(tr("Close"), this);

    auto* form = new QFormLayout;
    form->addRow(tr("Machine:"), m_machine);
    form->addRow(tr("NC family:"), m_family);
    form->addRow(tr("Show axis:"), m_axis);

    auto* unmappedBox = new QGroupBox(tr("Parameters without a mapping (written as comments)"), this);
    (new QVBoxLayout(unmappedBox))->addWidget(m_unmapped);
    auto* previewBox = new QGroupBox(tr("File"), this);
    (new QVBoxLayout(previewBox))->addWidget(m_preview);
    auto* lower = new QSplitter(Qt::Horizontal, this);
    lower->addWidget(unmappedBox);
    lower->addWidget(previewBox);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_table);
    split->addWidget(lower);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_status, 1);
    buttons->addWidget(m_save);
    buttons->addWidget(close);
    auto* lay = new QVBoxLayout(this);
    lay->addLayout(form);
    lay->addWidget(split, 1);
    lay->addLayout(buttons);
    resize(1000, 700);

    connect(m_machine, &QComboBox::currentIndexChanged, this, [this] { loadProfile(); });
    connect(m_family, &QComboBox::currentIndexChanged, this, [this] { refresh(); });
    connect(m_axis, &QComboBox::currentIndexChanged, this, [this] { fillTable(); });
    connect(m_save, &QPushButton::clicked, this, &NcExportDialog::saveInteractive);
    connect(close, &QPushButton::clicked, this, &QDialog::close);
    reloadMachines();
}

QStringList NcExportDialog::families()
{
    const QFileInfo any(QString::fromStdString(io::defaultNcMapPath("fanuc")));
    QStringList out;
    for (const auto& fi : any.dir().entryInfoList({QStringLiteral("*.json")}, QDir::Files, QDir::Name))
        out << fi.completeBaseName();
    return out;
}

void NcExportDialog::reloadMachines()
{
    const QSignalBlocker block(m_machine);
    m_machine->clear();
    if (auto* db = m_ctx.database()) {
        if (auto ms = db->listMachines())
            for (const auto& m : *ms)
                m_machine->addItem(QString::fromStdString(m));
    }
    const int i = m_machine->findText(m_ctx.machine());
    if (i >= 0)
        m_machine->setCurrentIndex(i);
    loadProfile();
}

void NcExportDialog::setMachine(const QString& machine)
{
    if (m_machine->findText(machine) < 0)
        reloadMachines();
    m_machine->setCurrentIndex(m_machine->findText(machine));
    loadProfile();
}

void NcExportDialog::setFamily(const QString& family)
{
    m_family->setCurrentIndex(m_family->findData(family));
    refresh();
}

void NcExportDialog::loadProfile()
{
    m_profile.reset();
    m_error.clear();
    auto* db = m_ctx.database();
    const QString machine = m_machine->currentText();
    if (!db)
        m_error = tr("No store is open.");
    else if (machine.isEmpty())
        m_error = tr("The store holds no machine.");
    else if (auto p = db->loadProfile(machine.toStdString()); !p)
        m_error = tr("The profile of %1 cannot be loaded: %2").arg(machine, QString::fromStdString(p.error().detail));
    else
        m_profile = *p;
    {
        const QSignalBlocker block(m_axis);
        const QString was = m_axis->currentData().toString();
        m_axis->clear();
        m_axis->addItem(tr("All axes"), QString());
        if (m_profile)
            for (const auto& a : m_profile->axes)
                m_axis->addItem(QString::fromStdString(a.name), QString::fromStdString(a.name));
        m_axis->setCurrentIndex(std::max(0, m_axis->findData(was)));
    }
    refresh();
}

void NcExportDialog::refresh()
{
    m_map.reset();
    m_export.reset();
    if (m_profile) {
        m_error.clear();
        const QString family = m_family->currentData().toString();
        auto map = io::readNcMapFile(io::defaultNcMapPath(family.toStdString()));
        if (!map) {
            m_error = tr("NC map %1: %2").arg(family, QString::fromStdString(map.error().detail));
        } else {
            m_map = *map;
            auto out = io::exportNc(*m_profile, *m_map);
            if (!out)
                m_error = tr("Export to %1 failed: %2").arg(family, QString::fromStdString(out.error().detail));
            else
                m_export = *out;
        }
    }
    m_preview->setPlainText(m_export ? QString::fromStdString(m_export->text) : QString());
    m_save->setEnabled(m_export.has_value());
    m_status->setText(m_error.isEmpty() && m_map ? QString::fromStdString(m_map->title) : m_error);
    m_status->setStyleSheet(m_error.isEmpty() ? QString() : QStringLiteral("color:#b00000"));
    fillTable();
}

void NcExportDialog::fillTable()
{
    m_table->setRowCount(0);
    m_unmapped->clear();
    if (!m_profile || !m_map)
        return;
    const QString only = m_axis->currentData().toString();
    for (const auto& axis : m_profile->axes) {
        const QString axisName = QString::fromStdString(axis.name);
        if (!only.isEmpty() && axisName != only)
            continue;
        // Mapped: one row per map entry (a key may go to several NC numbers), in the file's order.
        for (const auto& entry : m_map->entries) {
            const auto it = axis.parameters.find(entry.key);
            if (it == axis.parameters.end())
                continue;
            const std::string& key = it->first;
            const double value = it->second;
            const int row = m_table->rowCount();
            m_table->insertRow(row);
            auto nc = io::formatNcValue(entry, value);
            // The NC number as written, and what one count of it means: "3000 × 0.01 s⁻¹".
            const QString unit = QString::fromStdString(model::unitLabel(entry.unit));
            QString ncText = tr("error: %1").arg(nc ? QString() : QString::fromStdString(nc.error().detail));
            if (nc)
                ncText = entry.scale == 1.0 ? QStringLiteral("%1 %2").arg(QString::fromStdString(*nc), unit)
                                            : QStringLiteral("%1 × %2 %3")
                                                  .arg(QString::fromStdString(*nc))
                                                  .arg(1.0 / entry.scale, 0, 'g', 6)
                                                  .arg(unit);
            const QStringList cells{axisName, QString::fromStdString(key), QString::fromStdString(entry.number),
                                    ncText,   siValueText(key, value),     QString::fromStdString(entry.description)};
            for (int c = 0; c < ColumnCount; ++c)
                m_table->setItem(row, c, new QTableWidgetItem(cells[c]));
        }
        for (const auto& [key, value] : axis.parameters) {
            const bool mapped = std::any_of(m_map->entries.begin(), m_map->entries.end(),
                                            [&key](const io::NcMapEntry& e) { return e.key == key; });
            if (!mapped)
                m_unmapped->addItem(
                    tr("%1  %2 = %3").arg(axisName, QString::fromStdString(key), siValueText(key, value)));
        }
    }
    m_table->resizeColumnsToContents();
    m_table->resizeRowsToContents();
}

QString NcExportDialog::exportText() const
{
    return m_export ? QString::fromStdString(m_export->text) : QString();
}

bool NcExportDialog::saveTo(const QString& path, QString* error) const
{
    if (!m_export) {
        if (error)
            *error = m_error.isEmpty() ? tr("Nothing to export.") : m_error;
        return false;
    }
    auto st = io::writeTextFileAtomic(path.toStdString(), m_export->text);
    if (!st) {
        if (error)
            *error = QString::fromStdString(st.error().detail);
        return false;
    }
    return true;
}

void NcExportDialog::saveInteractive()
{
    const QString family = m_family->currentData().toString();
    const QString suggested = QDir::home().filePath(QStringLiteral("%1-%2.txt").arg(m_machine->currentText(), family));
    const QString path = QFileDialog::getSaveFileName(this, tr("Save NC parameter file"), suggested,
                                                      tr("Text files (*.txt *.nc *.mpf *.mp);;All files (*)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!saveTo(path, &error)) {
        m_status->setText(error);
        m_status->setStyleSheet(QStringLiteral("color:#b00000"));
        QMessageBox::warning(this, tr("NC file not saved"), error);
        return;
    }
    m_status->setStyleSheet(QString());
    m_status->setText(tr("Saved %1. Verify every number against the NC's parameter manual before loading it.")
                          .arg(QDir::toNativeSeparators(path)));
    m_ctx.log(tr("NC parameters of %1 exported for %2 to %3").arg(m_machine->currentText(), family, path));
}

NcExportDialog* showNcExportDialog(AppContext& ctx, QWidget* parent)
{
    auto* dlg = new NcExportDialog(ctx, parent);
    dlg->setAttribute(Qt::WA_DeleteOnClose);
    dlg->show();
    return dlg;
}

} // namespace gui
} // namespace axistune

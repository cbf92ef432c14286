// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/ParameterInspector.h"

#include "app/gui/AppContext.h"
#include "app/gui/ParameterText.h"

#include "core/model/Units.h"

#include <QBrush>
#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>
#include <set>

namespace axistune {
namespace gui {

namespace {
constexpr int kKeyRole = Qt::UserRole;
constexpr int kDiffersRole = Qt::UserRole + 1;
/// Values equal within float32 resolution (the Modbus link carries float32).
constexpr double kRelTol = 1e-6;

bool sameValue(double a, double b) { return std::abs(a - b) <= kRelTol * std::max({1e-12, std::abs(a), std::abs(b)}); }

QString displayValue(const model::ParameterMeta* meta, double si)
{
    if (!meta)
        return QString::number(si, 'g', 6);
    auto v = model::convertUnit(si, meta->siUnit, meta->displayUnit);
    return QString::number(v ? *v : si, 'g', 6);
}

std::optional<double> valueOf(const model::ParameterValues& values, const std::string& key)
{
    const auto it = values.find(key);
    return it == values.end() ? std::nullopt : std::optional<double>(it->second);
}
}  // namespace

ParameterInspector::ParameterInspector(AppContext& ctx, QWidget* parent) : QWidget(parent), m_ctx(ctx)
{
    setObjectName("parameterInspector");
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(2, 2, 2, 2);
    m_title = new QLabel(this);
    m_title->setObjectName("inspectorTitle");
    lay->addWidget(m_title);
    m_table = new QTableWidget(0, ColumnCount, this);
    m_table->setObjectName("parameterTable");
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // Names get a fixed, adjustable width (full text in the tooltip); the limits take the rest.
    m_table->horizontalHeader()->setSectionResizeMode(ColParameter, QHeaderView::Interactive);
    m_table->horizontalHeader()->resizeSection(ColParameter, 200);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setWordWrap(false);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->hide();
    lay->addWidget(m_table);
    retranslateUi();

    connect(&m_ctx, &AppContext::proposedChanged, this, [this](const QString& axis) {
        if (axis == m_axis) {
            m_proposed = m_ctx.proposed(m_axis);
            rebuild();
        }
    });
    connect(&m_ctx, &AppContext::parametersApplied, this, [this](const QString& axis) {
        if (axis == m_axis)
            refresh();
    });
    connect(&m_ctx, &AppContext::sessionSaved, this, [this] { refresh(); });
    connect(&m_ctx.drive(), &DriveController::connectionChanged, this, [this](bool connected) {
        if (!connected) {
            m_metaCache.clear();
            m_device.clear();
            m_deviceShown = true;
            rebuild();
        }
    });
}

void ParameterInspector::retranslateUi()
{
    m_table->setHorizontalHeaderLabels(
        {tr("Parameter"), tr("Device"), tr("Profile"), tr("Proposed"), tr("Unit"), tr("Limits")});
    m_title->setText(m_axis.isEmpty() ? tr("No axis selected")
                                      : tr("Machine %1, axis %2").arg(m_machine.isEmpty() ? tr("(none)") : m_machine, m_axis));
    m_table->horizontalHeaderItem(ColProfile)->setToolTip(tr("Current parameters of the profile in the store"));
    m_table->horizontalHeaderItem(ColProposed)->setToolTip(tr("Values proposed by a wizard, not yet applied"));
    rebuild();
}

void ParameterInspector::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

bool ParameterInspector::isConnectedMachine() const
{
    return m_ctx.drive().isConnected() && !m_machine.isEmpty() && m_machine == m_ctx.machine() &&
           m_ctx.axes().contains(m_axis);
}

void ParameterInspector::setAxis(const QString& machine, const QString& axis)
{
    if (machine != m_machine || axis != m_axis)
        m_device.clear();
    m_machine = machine;
    m_axis = axis;
    retranslateUi();
    refresh();
}

void ParameterInspector::refresh()
{
    loadStoreValues();
    // Proposals belong to the connected machine (or to offline work when nothing is connected).
    m_proposed = isConnectedMachine() || !m_ctx.drive().isConnected() ? m_ctx.proposed(m_axis) : model::ParameterValues{};
    rebuild();
    requestDevice();
}

void ParameterInspector::loadStoreValues()
{
    m_profile.clear();
    if (auto* db = m_ctx.database(); db && !m_machine.isEmpty() && !m_axis.isEmpty()) {
        if (auto v = db->currentParameters(m_machine.toStdString(), m_axis.toStdString()))
            m_profile = std::move(v).value();
    }
}

void ParameterInspector::requestDevice()
{
    if (!isConnectedMachine()) {
        m_deviceShown = true;
        return;
    }
    m_deviceShown = false;
    if (!m_metaCache.count(m_axis))
        m_metaRequest = connectReply(m_ctx.drive().readMetadata(m_axis), this, &ParameterInspector::onReply);
    m_readRequest = connectReply(m_ctx.drive().readParameters(m_axis), this, &ParameterInspector::onReply);
}

void ParameterInspector::onReply(const DriveReply& reply)
{
    if (reply.id == m_metaRequest) {
        m_metaRequest = -1;
        if (reply.ok)
            m_metaCache[reply.axis] = reply.metadata;
        else
            m_ctx.log(tr("Reading the parameter list of axis %1 failed: %2").arg(reply.axis, reply.error));
        rebuild();
    } else if (reply.id == m_readRequest) {
        m_readRequest = -1;
        if (reply.ok && reply.axis == m_axis)
            m_device = reply.values;
        else if (!reply.ok)
            m_ctx.log(tr("Reading the parameters of axis %1 failed: %2").arg(reply.axis, reply.error));
        m_deviceShown = true;
        rebuild();
    }
}

void ParameterInspector::rebuild()
{
    // Rows: the drive's parameters in catalogue order, then keys known only to the profile or a proposal.
    std::vector<std::string> keys;
    std::set<std::string> seen;
    const std::vector<model::ParameterMeta>* metas = nullptr;
    if (const auto it = m_metaCache.find(m_axis); it != m_metaCache.end() && isConnectedMachine())
        metas = &it->second;
    std::map<std::string, const model::ParameterMeta*> metaOf;
    if (metas)
        for (const auto& m : *metas) {
            keys.push_back(m.key);
            seen.insert(m.key);
            metaOf[m.key] = &m;
        }
    for (const auto* src : {&m_device, &m_profile, &m_proposed})
        for (const auto& [k, v] : *src)
            if (seen.insert(k).second)
                keys.push_back(k);

    const QBrush profileDiff(QColor(255, 236, 160));   // device ≠ profile
    const QBrush proposedDiff(QColor(190, 225, 255));  // proposed ≠ device
    m_table->setRowCount(static_cast<int>(keys.size()));
    int row = 0;
    for (const auto& key : keys) {
        const auto* meta = metaOf.count(key) ? metaOf[key] : nullptr;
        const QString qkey = QString::fromStdString(key);
        auto* name = new QTableWidgetItem(meta ? parameterLabel(meta->label) : qkey);
        name->setData(kKeyRole, qkey);
        name->setToolTip((meta ? parameterLabel(meta->label) + "\n" : QString()) + qkey +
                         (meta && !meta->description.empty() ? "\n" + QString::fromStdString(meta->description) : QString()));
        m_table->setItem(row, ColParameter, name);
        const auto dev = valueOf(m_device, key);
        const auto prof = valueOf(m_profile, key);
        const auto prop = valueOf(m_proposed, key);
        auto valueItem = [&](const std::optional<double>& v, bool differs, const QBrush& brush) {
            auto* it = new QTableWidgetItem(v ? displayValue(meta, *v) : QString());
            it->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            it->setData(kDiffersRole, differs);
            if (differs) {
                it->setBackground(brush);
                QFont f = it->font();
                f.setBold(true);
                it->setFont(f);
                it->setToolTip(tr("Differs from the device value"));
            }
            return it;
        };
        m_table->setItem(row, ColDevice, valueItem(dev, false, {}));
        m_table->setItem(row, ColProfile, valueItem(prof, dev && prof && !sameValue(*dev, *prof), profileDiff));
        m_table->setItem(row, ColProposed, valueItem(prop, prop && (!dev || !sameValue(*dev, *prop)), proposedDiff));
        const QString unit = meta ? QString::fromStdString(model::unitLabel(meta->displayUnit)) : QString();
        m_table->setItem(row, ColUnit, new QTableWidgetItem(unit));
        QString limits;
        if (meta)
            limits = tr("%1 … %2%3").arg(displayValue(meta, meta->minSi), displayValue(meta, meta->maxSi),
                                         meta->writable ? QString() : tr(" (read-only)"));
        m_table->setItem(row, ColLimits, new QTableWidgetItem(limits));
        ++row;
    }
}

int ParameterInspector::rowOf(const QString& key) const
{
    for (int r = 0; r < m_table->rowCount(); ++r)
        if (m_table->item(r, ColParameter) && m_table->item(r, ColParameter)->data(kKeyRole).toString() == key)
            return r;
    return -1;
}

QString ParameterInspector::cellText(const QString& key, Column column) const
{
    const int r = rowOf(key);
    return r < 0 || !m_table->item(r, column) ? QString() : m_table->item(r, column)->text();
}

bool ParameterInspector::isHighlighted(const QString& key, Column column) const
{
    const int r = rowOf(key);
    return r >= 0 && m_table->item(r, column) && m_table->item(r, column)->data(kDiffersRole).toBool();
}

}  // namespace gui
}  // namespace axistune

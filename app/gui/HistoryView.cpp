// SPDX-License-Identifier: GPL-3.0-or-later
// History of a machine axis across sessions: fields found in the stored results, parameter sets and
// models (field names: app/gui/*Wizard.cpp, app/cli/CmdBallBar.cpp, docs/storage.md).
#include "app/gui/HistoryView.h"

#include "app/gui/AppContext.h"
#include "core/model/Units.h"
#include "core/store/SessionRecord.h"
#include "widgets/CurvePlot.h"
#include "core/io/Profile.h"

#include <QComboBox>
#include <QDateTime>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <optional>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

namespace {

using Series = std::map<QString, std::vector<HistoryPoint>>;

/// The resonance list of a result: an array of objects, or {"resonances": [...]}, or a CLI file
/// result {"data": ...}.
const nlohmann::json* resonanceList(const nlohmann::json& j, int depth = 0)
{
    if (depth > 3)
        return nullptr;
    if (j.is_array())
        return &j;
    if (!j.is_object())
        return nullptr;
    if (auto it = j.find("resonances"); it != j.end())
        return resonanceList(*it, depth + 1);
    if (auto it = j.find("data"); it != j.end())
        return resonanceList(*it, depth + 1);
    return nullptr;
}

std::optional<double> number(const nlohmann::json& j, const char* key)
{
    if (!j.is_object())
        return std::nullopt;
    auto it = j.find(key);
    if (it == j.end() || !it->is_number())
        return std::nullopt;
    const double v = it->get<double>();
    return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

/// Breadth-first search of a key holding a finite number (results nest their fields).
std::optional<double> findNumber(const nlohmann::json& root, const char* key)
{
    std::deque<const nlohmann::json*> queue{&root};
    while (!queue.empty()) {
        const auto* j = queue.front();
        queue.pop_front();
        if (auto v = number(*j, key))
            return v;
        if (j->is_object() || j->is_array())
            for (const auto& child : *j)
                if (child.is_object() || child.is_array())
                    queue.push_back(&child);
    }
    return std::nullopt;
}

double toDisplay(double si, const char* siUnit, const char* unit)
{
    auto v = model::convertUnit(si, siUnit, unit);
    return v ? *v : si;
}

void resonances(const store::SessionRecord& rec, HistoryPoint p, Series& out)
{
    for (const auto& r : rec.results) {
        if (r.name != "resonances" && !(r.data.is_object() && r.data.contains("resonances")))
            continue;
        const auto* list = resonanceList(r.data);
        if (!list)
            continue;
        std::vector<double> f;
        for (const auto& e : *list) {
            auto v = number(e, "frequency_Hz");
            if (!v)
                v = number(e, "f_Hz");
            if (v && *v > 0)
                f.push_back(*v);
        }
        std::sort(f.begin(), f.end());
        for (std::size_t i = 0; i < f.size(); ++i) {
            p.value = f[i];
            out[QCoreApplication::translate("HistoryView", "Resonance %1").arg(i + 1)].push_back(p);
        }
        return; // one resonance list per session
    }
}

void appliedSets(const store::SessionRecord& rec, const std::string& axis, HistoryPoint p, Series& notch, Series& a,
                 Series& b)
{
    for (const auto& s : rec.parameterSets) {
        if (s.source != store::ParameterSource::Applied || (!s.axis.empty() && s.axis != axis))
            continue;
        for (const auto& [key, v] : s.values) {
            if (key.rfind("filter.notch", 0) == 0 && key.size() > 7 && key.substr(key.size() - 7) == ".center") {
                if (v <= 0 || !std::isfinite(v))
                    continue; // centre 0: notch off
                p.value = v;
                const auto n = QString::fromStdString(key.substr(12, key.size() - 12 - 7));
                notch[QCoreApplication::translate("HistoryView", "Notch %1 centre").arg(n)].push_back(p);
            } else if (key == "lostmotion.A" && std::isfinite(v)) {
                p.value = toDisplay(v, "m/Nm", "um/Nm");
                a[QCoreApplication::translate("HistoryView", "A applied")].push_back(p);
            } else if (key == "lostmotion.B" && std::isfinite(v)) {
                p.value = toDisplay(v, "1/Nm", "um/(Nm*m)");
                b[QCoreApplication::translate("HistoryView", "B applied")].push_back(p);
            }
        }
    }
}

void identifiedLostMotion(const store::SessionRecord& rec, const std::string& axis, HistoryPoint p, Series& a,
                          Series& b)
{
    std::optional<double> av, bv;
    for (const auto& m : rec.models)
        if (m.kind == "lost_motion" && (m.axis.empty() || m.axis == axis)) {
            av = number(m.data, "A_m_per_Nm");
            bv = number(m.data, "B_per_Nm");
        }
    if (!av && !bv)
        for (const auto& r : rec.results)
            if (r.name == "fit" || r.name == "lost_motion") {
                av = findNumber(r.data, "A_m_per_Nm");
                bv = findNumber(r.data, "B_per_Nm");
            }
    if (av) {
        p.value = toDisplay(*av, "m/Nm", "um/Nm");
        a[QCoreApplication::translate("HistoryView", "A identified")].push_back(p);
    }
    if (bv) {
        p.value = toDisplay(*bv, "1/Nm", "um/(Nm*m)");
        b[QCoreApplication::translate("HistoryView", "B identified")].push_back(p);
    }
}

void circularity(const store::SessionRecord& rec, HistoryPoint p, Series& out)
{
    std::optional<double> measuredM, afterM;
    for (const auto& r : rec.results) {
        if (!afterM)
            afterM = findNumber(r.data, "circularity_after_m");
        if (!measuredM)
            for (const char* k : {"measured_circularity_m", "circularity_before_m", "circularity_m"})
                if ((measuredM = findNumber(r.data, k)))
                    break;
        if (!measuredM)
            for (const char* k : {"measured_circularity_um", "circularity_um"})
                if (auto um = findNumber(r.data, k)) {
                    measuredM = *um * 1e-6;
                    break;
                }
    }
    if (measuredM) {
        p.value = *measuredM * 1e6;
        out[QCoreApplication::translate("HistoryView", "Circularity measured")].push_back(p);
    }
    if (afterM) {
        p.value = *afterM * 1e6;
        out[QCoreApplication::translate("HistoryView", "Circularity after compensation")].push_back(p);
    }
}

std::vector<HistorySeries> toSeries(const Series& s)
{
    std::vector<HistorySeries> out;
    for (const auto& [name, pts] : s)
        out.push_back({name, pts});
    return out;
}

} // namespace

HistoryData collectHistory(const std::vector<store::SessionRecord>& sessions, const std::string& axis)
{
    HistoryData d;
    Series res, notch, a, b, circ;
    std::optional<QDateTime> first;
    for (const auto& rec : sessions) {
        if (rec.info.axis != axis)
            continue;
        ++d.sessions;
        const QDateTime t = QDateTime::fromString(QString::fromStdString(rec.info.started), Qt::ISODateWithMs);
        if (t.isValid() && (!first || t < *first))
            first = t;
    }
    for (const auto& rec : sessions) {
        if (rec.info.axis != axis)
            continue;
        HistoryPoint p;
        p.sessionId = rec.info.id;
        const QDateTime t = QDateTime::fromString(QString::fromStdString(rec.info.started), Qt::ISODateWithMs);
        p.days = (t.isValid() && first) ? first->msecsTo(t) / 86400e3 : 0.0;
        resonances(rec, p, res);
        appliedSets(rec, axis, p, notch, a, b);
        identifiedLostMotion(rec, axis, p, a, b);
        circularity(rec, p, circ);
    }
    d.series[static_cast<int>(HistoryQuantity::Resonance)] = toSeries(res);
    d.series[static_cast<int>(HistoryQuantity::Notch)] = toSeries(notch);
    d.series[static_cast<int>(HistoryQuantity::LostMotionA)] = toSeries(a);
    d.series[static_cast<int>(HistoryQuantity::LostMotionB)] = toSeries(b);
    d.series[static_cast<int>(HistoryQuantity::Circularity)] = toSeries(circ);
    return d;
}

HistoryData collectHistory(const store::Database& db, const std::string& machine, const std::string& axis,
                           QString* error)
{
    std::vector<store::SessionRecord> recs;
    auto list = db.listSessions(machine);
    if (!list) {
        if (error)
            *error = QString::fromStdString(list.error().detail);
        return {};
    }
    auto infos = *list;
    std::sort(infos.begin(), infos.end(), [](const auto& x, const auto& y) { return x.id < y.id; });
    for (const auto& info : infos) {
        if (info.axis != axis)
            continue;
        auto rec = db.loadSession(info.id);
        if (!rec) {
            if (error && error->isEmpty())
                *error = QString::fromStdString(rec.error().detail);
            continue;
        }
        recs.push_back(std::move(rec).value());
    }
    return collectHistory(recs, axis);
}

QString historyQuantityLabel(HistoryQuantity q)
{
    switch (q) {
    case HistoryQuantity::Resonance:
        return QCoreApplication::translate("HistoryView", "Resonance frequency");
    case HistoryQuantity::Notch:
        return QCoreApplication::translate("HistoryView", "Notch centre (applied)");
    case HistoryQuantity::LostMotionA:
        return QCoreApplication::translate("HistoryView", "Lost motion A");
    case HistoryQuantity::LostMotionB:
        return QCoreApplication::translate("HistoryView", "Lost motion B");
    case HistoryQuantity::Circularity:
        return QCoreApplication::translate("HistoryView", "Circularity");
    case HistoryQuantity::Count:
        break;
    }
    return {};
}

QString historyQuantityUnit(HistoryQuantity q)
{
    switch (q) {
    case HistoryQuantity::Resonance:
    case HistoryQuantity::Notch:
        return QStringLiteral("Hz");
    case HistoryQuantity::LostMotionA:
        return QString::fromStdString(model::unitLabel("um/Nm"));
    case HistoryQuantity::LostMotionB:
        return QString::fromStdString(model::unitLabel("um/(Nm*m)"));
    case HistoryQuantity::Circularity:
        return QStringLiteral("µm");
    case HistoryQuantity::Count:
        break;
    }
    return {};
}

HistoryView::HistoryView(AppContext& ctx, QWidget* parent) : QWidget(parent), m_ctx(ctx)
{
    setObjectName(QStringLiteral("historyView"));
    setWindowTitle(tr("History"));
    m_machine = new QComboBox(this);
    m_machine->setObjectName(QStringLiteral("historyMachine"));
    m_axis = new QComboBox(this);
    m_axis->setObjectName(QStringLiteral("historyAxis"));
    m_xMode = new QComboBox(this);
    m_xMode->setObjectName(QStringLiteral("historyXMode"));
    m_xMode->addItem(tr("Session number"));
    m_xMode->addItem(tr("Days since the first session"));
    auto* reloadButton = new QPushButton(tr("Reload"), this);
    auto* bar = new QHBoxLayout;
    bar->addWidget(new QLabel(tr("Machine:"), this));
    bar->addWidget(m_machine);
    bar->addWidget(new QLabel(tr("Axis:"), this));
    bar->addWidget(m_axis);
    bar->addWidget(new QLabel(tr("x axis:"), this));
    bar->addWidget(m_xMode);
    bar->addStretch(1);
    bar->addWidget(reloadButton);

    auto* grid = new QGridLayout;
    for (int q = 0; q < static_cast<int>(HistoryQuantity::Count); ++q) {
        m_plots[q] = new widgets::CurvePlot(this);
        m_plots[q]->setObjectName(QStringLiteral("historyPlot%1").arg(q));
        m_plots[q]->setMinimumSize(300, 200);
        grid->addWidget(m_plots[q], q / 3, q % 3);
    }
    m_points = new QTreeWidget(this);
    m_points->setObjectName(QStringLiteral("historyPoints"));
    m_points->setHeaderLabels({tr("Quantity"), tr("Session"), tr("Value")});
    m_points->setRootIsDecorated(false);
    grid->addWidget(m_points, 1, 2);

    auto* lay = new QVBoxLayout(this);
    lay->addLayout(bar);
    lay->addLayout(grid, 1);
    resize(1000, 700);

    connect(m_machine, &QComboBox::currentIndexChanged, this, [this] { reloadAxes(); });
    connect(m_axis, &QComboBox::currentIndexChanged, this, [this] { reload(); });
    connect(m_xMode, &QComboBox::currentIndexChanged, this, [this] { redraw(); });
    connect(reloadButton, &QPushButton::clicked, this, [this] { reloadMachines(); });
    connect(&m_ctx, &AppContext::sessionSaved, this, [this] { reload(); });
    connect(&m_ctx, &AppContext::databaseChanged, this, [this] { reloadMachines(); });
    reloadMachines();
}

void HistoryView::reloadMachines()
{
    const QString was = m_machine->currentText().isEmpty() ? m_ctx.machine() : m_machine->currentText();
    {
        const QSignalBlocker block(m_machine);
        m_machine->clear();
        if (auto* db = m_ctx.database())
            if (auto ms = db->listMachines())
                for (const auto& m : *ms)
                    m_machine->addItem(QString::fromStdString(m));
        m_machine->setCurrentIndex(std::max(0, m_machine->findText(was)));
    }
    reloadAxes();
}

void HistoryView::reloadAxes()
{
    const QVariant was = m_axis->currentData();
    {
        const QSignalBlocker block(m_axis);
        m_axis->clear();
        if (auto* db = m_ctx.database(); db && !m_machine->currentText().isEmpty())
            if (auto p = db->loadProfile(m_machine->currentText().toStdString()))
                for (const auto& a : p->axes)
                    m_axis->addItem(QString::fromStdString(a.name), QString::fromStdString(a.name));
        // Sessions without an axis (ball-bar runs of a plane, CLI analyses): a pseudo-axis of their own.
        if (!m_machine->currentText().isEmpty())
            m_axis->addItem(tr("(no axis)"), QString(""));
        m_axis->setCurrentIndex(was.isValid() ? std::max(0, m_axis->findData(was)) : 0);
    }
    reload();
}

void HistoryView::setMachine(const QString& machine)
{
    if (m_machine->findText(machine) < 0)
        reloadMachines();
    m_machine->setCurrentIndex(m_machine->findText(machine));
}

void HistoryView::setAxis(const QString& axis)
{
    m_axis->setCurrentIndex(m_axis->findData(axis));
}

void HistoryView::setTimeAxis(bool days)
{
    m_xMode->setCurrentIndex(days ? 1 : 0);
}

void HistoryView::reload()
{
    m_data = {};
    auto* db = m_ctx.database();
    if (db && !m_machine->currentText().isEmpty() && m_axis->currentIndex() >= 0) {
        QString error;
        m_data = collectHistory(*db, m_machine->currentText().toStdString(),
                                m_axis->currentData().toString().toStdString(), &error);
        if (!error.isEmpty())
            m_ctx.log(tr("History: %1").arg(error));
    }
    redraw();
}

void HistoryView::redraw()
{
    const bool days = m_xMode->currentIndex() == 1;
    m_points->clear();
    for (int q = 0; q < static_cast<int>(HistoryQuantity::Count); ++q) {
        auto* plot = m_plots[q];
        plot->clear();
        const auto quantity = static_cast<HistoryQuantity>(q);
        plot->setAxes(days ? tr("Time since the first session") : tr("Session"), days ? tr("d") : QString(),
                      historyQuantityLabel(quantity), historyQuantityUnit(quantity));
        for (const auto& s : m_data.of(quantity)) {
            std::vector<double> x, y;
            for (const auto& p : s.points) {
                x.push_back(days ? p.days : static_cast<double>(p.sessionId));
                y.push_back(p.value);
                m_points->addTopLevelItem(new QTreeWidgetItem(
                    {s.name, QString::number(p.sessionId),
                     QStringLiteral("%1 %2").arg(p.value, 0, 'g', 5).arg(historyQuantityUnit(quantity))}));
            }
            plot->addCurve(s.name, x, y, QColor(), Qt::SolidLine, true);
        }
        plot->rescale();
        plot->replotNow();
    }
    m_points->resizeColumnToContents(0);
}

HistoryView* showHistory(AppContext& ctx, QWidget* parent)
{
    auto* view = new HistoryView(ctx, parent);
    view->setWindowFlag(Qt::Window, true);
    view->setAttribute(Qt::WA_DeleteOnClose);
    view->show();
    return view;
}

} // namespace gui
} // namespace axistune

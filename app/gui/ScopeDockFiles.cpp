// SPDX-License-Identifier: GPL-3.0-or-later
// The scope dock's files and store: CSV and image export, save to and open from the session store, open a CSV
// (ScopeDock.h).
#include "app/gui/AppContext.h"
#include "app/gui/DriveController.h"
#include "app/gui/ScopeDock.h"
#include "app/gui/WidgetUtil.h"
#include "core/device/ScopeMath.h"
#include "core/io/CaptureCsv.h"
#include "core/io/ScopeCsv.h"
#include "core/model/MetadataJson.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/store/SessionRecord.h"
#include "widgets/CurvePlot.h"
#include "widgets/TimeTracePlot.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QSplitter>
#include <QStackedWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

namespace axistune {
namespace gui {

namespace {
constexpr const char* kStoreCapture = "scope";
} // namespace

model::Metadata ScopeDock::captureMetadata() const
{
    model::Metadata m;
    m.set(model::meta::kConnection, m_captureSource.toStdString());
    if (m_armed && m_capture && m_capture->triggered) {
        m.set("divider", static_cast<double>(m_armed->divider));
        m.set("trigger", m_armed->triggerChannel + ":" + model::formatNumber(m_armed->triggerLevel, 17) + ":" +
                             device::scopeEdgeName(m_armed->edge));
        m.set("pre_trigger_pct", m_armed->preTriggerPct);
        m.set("capture_number", static_cast<double>(m_capture->number));
    }
    return m;
}

bool ScopeDock::exportCsv(const QString& path, QString* error) const
{
    if (!m_capture) {
        if (error)
            *error = tr("No capture to export");
        return false;
    }
    const auto table = device::scopeCaptureToTable(*m_capture, m_captureAxis.toStdString(), captureMetadata());
    if (auto st = io::writeCaptureCsvFile(path.toStdString(), table); !st) {
        if (error)
            *error = qs(st.error().detail);
        return false;
    }
    return true;
}

bool ScopeDock::exportImage(const QString& path, QString* error) const
{
    if (!m_plot->exportImage(path)) {
        if (error)
            *error = m_plot->lastError();
        return false;
    }
    return true;
}

void ScopeDock::exportCsvInteractive()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the capture as CSV"),
                                                      QStringLiteral("scope.csv"), tr("Scope CSV (*.csv)"));
    if (path.isEmpty())
        return;
    QString e;
    if (exportCsv(path, &e))
        setMessage(tr("Written: %1").arg(path), false);
    else
        setMessage(e, true);
}

void ScopeDock::exportImageInteractive()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the plot"), QStringLiteral("scope.png"),
                                                      tr("Images (*.png *.svg *.pdf)"));
    if (path.isEmpty())
        return;
    QString e;
    if (exportImage(path, &e))
        setMessage(tr("Written: %1").arg(path), false);
    else
        setMessage(e, true);
}

bool ScopeDock::saveToStore(QString* error)
{
    if (!m_capture) {
        if (error)
            *error = tr("No capture to save");
        return false;
    }
    if (!m_ctx.database()) {
        if (error)
            *error = tr("No store is open (Settings → Preferences)");
        return false;
    }
    store::SessionRecord rec;
    rec.info.kind = "scope";
    rec.info.axis = m_captureAxis.toStdString();
    rec.info.note = m_capture->triggered ? "scope: triggered capture" : "scope: roll record";
    nlohmann::json in = nlohmann::json::object();
    for (const auto& [k, v] : captureMetadata())
        in[k] = v;
    in["mode"] = m_capture->triggered ? "triggered" : "roll";
    rec.inputs = in;
    rec.captures.push_back({kStoreCapture, device::scopeCaptureToTable(*m_capture, rec.info.axis, captureMetadata())});
    m_ctx.saveSessionAsync(std::move(rec), this, [this](Result<std::int64_t> id) {
        if (id) {
            setMessage(tr("Capture saved in the store as session %1").arg(*id), false);
            emit saved(*id);
        } else {
            setMessage(tr("The capture was not saved: %1").arg(qs(id.error().detail)), true);
        }
    });
    return true;
}

bool ScopeDock::openFromStore(qint64 sessionId, QString* error)
{
    auto fail = [&](const QString& e) {
        if (error)
            *error = e;
        return false;
    };
    if (!m_ctx.database())
        return fail(tr("No store is open (Settings → Preferences)"));
    auto s = m_ctx.database()->loadSession(sessionId);
    if (!s)
        return fail(qs(s.error().detail));
    for (const auto& c : s->captures) {
        if (c.name != kStoreCapture)
            continue;
        auto cap = device::scopeCaptureFromTable(c.capture);
        if (!cap)
            return fail(tr("Session %1: %2").arg(sessionId).arg(qs(cap.error().detail)));
        if (m_running)
            stop();
        m_armed.reset();
        m_captureAxis = qs(s->info.axis);
        m_captureSource = tr("store session %1").arg(sessionId);
        m_stateKey = "offline";
        show(std::make_shared<const device::ScopeCapture>(std::move(cap).value()));
        setMessage(tr("Session %1 (%2, axis %3) from the store").arg(sessionId).arg(qs(s->info.started), m_captureAxis),
                   false);
        m_state->setText(stateText());
        return true;
    }
    return fail(tr("Session %1 holds no scope capture").arg(sessionId));
}

void ScopeDock::openFromStoreInteractive()
{
    if (!m_ctx.database())
        return;
    auto list = m_ctx.database()->listSessions();
    if (!list) {
        setMessage(qs(list.error().detail), true);
        return;
    }
    QStringList items;
    std::vector<qint64> ids;
    for (const auto& s : *list) {
        if (s.kind != "scope")
            continue;
        items << tr("Session %1: %2, axis %3, %4").arg(s.id).arg(qs(s.machine), qs(s.axis), qs(s.started));
        ids.push_back(s.id);
    }
    if (items.isEmpty()) {
        setMessage(tr("The store holds no scope capture"), false);
        return;
    }
    bool ok = false;
    const QString choice =
        QInputDialog::getItem(this, tr("Open a saved capture"), tr("Capture:"), items, 0, false, &ok);
    if (!ok)
        return;
    QString e;
    if (!openFromStore(ids[static_cast<std::size_t>(items.indexOf(choice))], &e))
        setMessage(e, true);
}

bool ScopeDock::openCsv(const QString& path, QString* error)
{
    auto t = io::readScopeCsvFile(path.toStdString());
    if (!t) {
        if (error)
            *error = qs(t.error().detail);
        return false;
    }
    auto cap = device::scopeCaptureFromTable(t->capture);
    if (!cap) {
        if (error)
            *error = path + QStringLiteral(": ") + qs(cap.error().detail);
        return false;
    }
    if (m_running)
        stop();
    m_armed.reset();
    const auto a = t->capture.metadata.text(model::meta::kAxis);
    m_captureAxis = a ? qs(*a) : QString();
    m_captureSource = path;
    m_stateKey = "offline";
    show(std::make_shared<const device::ScopeCapture>(std::move(cap).value()));
    setMessage(tr("Opened %1").arg(path), false);
    m_state->setText(stateText());
    return true;
}

void ScopeDock::openCsvInteractive()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open a scope CSV"), QString(), tr("Scope CSV (*.csv)"));
    if (path.isEmpty())
        return;
    QString e;
    if (!openCsv(path, &e))
        setMessage(e, true);
}

// ------------------------------------------------------------------------------------------------
// Jog

} // namespace gui
} // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// History of one machine axis across its stored sessions (docs/reports.md): resonance frequencies
// (results "resonances" of frf/notch sessions), notch centres (applied sets filter.notchN.center),
// lost-motion A and B (applied sets lostmotion.A/B; identified: lost_motion models or "fit" results)
// and ball-bar circularity (results of lost-motion / ball-bar sessions) as trend plots over the
// session number or the time since the first session. Sessions lacking a field are skipped.

#include "core/store/Database.h"

#include <QCoreApplication>
#include <QString>
#include <QWidget>

#include <array>
#include <vector>

class QComboBox;
class QTreeWidget;

namespace axistune {
namespace widgets {
class CurvePlot;
}

namespace gui {

class AppContext;

struct HistoryPoint {
    qint64 sessionId = 0;
    double days = 0.0;  ///< time since the first session of the axis (days)
    double value = 0.0; ///< in the series' display unit
};

struct HistorySeries {
    QString name; ///< "Resonance 1", "Notch 2 centre", "A applied", ...
    std::vector<HistoryPoint> points;
};

enum class HistoryQuantity { Resonance = 0, Notch, LostMotionA, LostMotionB, Circularity, Count };

struct HistoryData {
    std::array<std::vector<HistorySeries>, static_cast<int>(HistoryQuantity::Count)> series;
    int sessions = 0; ///< sessions of the axis looked at
    const std::vector<HistorySeries>& of(HistoryQuantity q) const { return series[static_cast<int>(q)]; }
};

/// Collects the history of `axis` of `machine` from the store (sessions in id order). Sessions
/// that cannot be loaded or lack a field are skipped; `error` gets the first problem.
HistoryData collectHistory(const store::Database& db, const std::string& machine, const std::string& axis,
                           QString* error = nullptr);
/// The same from records already loaded (for tests and callers holding them).
HistoryData collectHistory(const std::vector<store::SessionRecord>& sessions, const std::string& axis);

/// Label and unit of a quantity's plot (translated).
QString historyQuantityLabel(HistoryQuantity q);
QString historyQuantityUnit(HistoryQuantity q);

class HistoryView : public QWidget {
    Q_OBJECT
public:
    explicit HistoryView(AppContext& ctx, QWidget* parent = nullptr);

    void setMachine(const QString& machine);
    /// An axis of the machine, or "" for the sessions without an axis (ball-bar, CLI analyses).
    void setAxis(const QString& axis);
    /// x = session number (false) or days since the first session (true).
    void setTimeAxis(bool days);
    void reload();

    const HistoryData& data() const { return m_data; }
    widgets::CurvePlot* plot(HistoryQuantity q) const { return m_plots[static_cast<int>(q)]; }
    QTreeWidget* pointList() const { return m_points; }

private:
    void reloadMachines();
    void reloadAxes();
    void redraw();

    AppContext& m_ctx;
    QComboBox* m_machine = nullptr;
    QComboBox* m_axis = nullptr;
    QComboBox* m_xMode = nullptr;
    std::array<widgets::CurvePlot*, static_cast<int>(HistoryQuantity::Count)> m_plots{};
    QTreeWidget* m_points = nullptr;
    HistoryData m_data;
};

/// Opens the history of the context's machine in a window (deleted on close).
HistoryView* showHistory(AppContext& ctx, QWidget* parent);

} // namespace gui
} // namespace axistune

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One stored session, read-only: its FRF captures overlaid in one Bode plot (legend = capture name,
// bands where points are not valid), every time capture in a time-trace plot, the inputs and results
// JSON as a tree, the parameter sets and the journal as tables. Export: every capture as CSV (FRFs in
// the FRF CSV format, traces in the capture CSV format) and the plots as PNG, SVG or PDF.
// SessionOverlay: the FRFs of several sessions in one Bode plot ("session N: name").

#include "core/dsp/FrequencyResponse.h"
#include "core/store/Database.h"
#include "core/store/SessionRecord.h"

#include <QString>
#include <QStringList>
#include <QWidget>

#include <vector>

class QTabWidget;

namespace axistune {
namespace widgets {
class BodePlot;
class TimeTracePlot;
}  // namespace widgets

namespace gui {

/// Adds an FRF to a Bode plot with bands for its invalid points and, when its metadata gives the trace
/// rate fs_Hz of a multi-sweep/multisine measurement, the band fs/2..fs valid only by that method.
int addFrfWithBands(widgets::BodePlot& plot, const dsp::FrequencyResponse& frf, const QString& name);

class SessionView : public QWidget {
    Q_OBJECT
public:
    explicit SessionView(store::SessionRecord record, QWidget* parent = nullptr);

    const store::SessionRecord& record() const { return m_record; }
    /// The Bode plot of the session's FRFs (nullptr when it has none).
    widgets::BodePlot* bodePlot() const { return m_bode; }
    /// Response id in bodePlot() of the FRF capture with this name, -1 when none.
    int responseId(const QString& captureName) const;
    const std::vector<widgets::TimeTracePlot*>& tracePlots() const { return m_traces; }
    QTabWidget* tabs() const { return m_tabs; }

    /// Writes every capture to DIR/session<ID>-<name>.csv; the files written, or false with `error`.
    bool exportCsv(const QString& dir, QStringList* files, QString* error) const;
    /// Writes every plot to DIR/session<ID>-<plot>.<suffix> (png, svg, pdf).
    bool exportImages(const QString& dir, const QString& suffix, QStringList* files, QString* error);

private:
    void buildPlots();
    void buildTables();
    void exportCsvInteractive();
    void exportImagesInteractive();

    store::SessionRecord m_record;
    QTabWidget* m_tabs = nullptr;
    widgets::BodePlot* m_bode = nullptr;
    std::vector<std::pair<QString, int>> m_responseIds;
    std::vector<widgets::TimeTracePlot*> m_traces;
};

class SessionOverlay : public QWidget {
    Q_OBJECT
public:
    /// The FRF captures of every session, legend "session N: name".
    explicit SessionOverlay(const std::vector<store::SessionRecord>& sessions, QWidget* parent = nullptr);
    widgets::BodePlot* bodePlot() const { return m_bode; }
    QStringList responseNames() const;

private:
    widgets::BodePlot* m_bode = nullptr;
};

}  // namespace gui
}  // namespace axistune

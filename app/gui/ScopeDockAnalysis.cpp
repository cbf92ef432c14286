// SPDX-License-Identifier: GPL-3.0-or-later
// The scope dock's plot: traces, math channel, scaling, XY, references and the spectrum (ScopeDock.h).
#include "app/gui/AppContext.h"
#include "app/gui/DriveController.h"
#include "app/gui/ScopeDock.h"
#include "app/gui/WidgetUtil.h"
#include "core/device/ScopeMath.h"
#include "core/io/CaptureCsv.h"
#include "core/io/ScopeCsv.h"
#include "core/model/Number.h"
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

void ScopeDock::redraw()
{
    m_mathName.clear();
    if (!m_capture) {
        m_plot->setCapture(nullptr);
        updateXyPlot();
        return;
    }
    auto table = scopePlotTable(*m_capture);
    const auto op = static_cast<Math>(std::clamp(m_mathOp->currentIndex(), 0, 2));
    const std::string a = m_mathA->currentText().toStdString(), b = m_mathB->currentText().toStdString();
    if (op != Math::None && !a.empty()) {
        auto m =
            op == Math::Difference ? device::scopeDifference(*m_capture, a, b) : device::scopeDerivative(*m_capture, a);
        if (m) {
            m_mathName = qs(m->info.name);
            table->metadata.set("unit." + m->info.name, m->info.unit);
            table->channels.push_back({m->info.name, std::move(m->values)});
        } else {
            setMessage(qs(m.error().detail), true);
        }
    }
    m_scaledName.clear();
    const double gain = m_scaleGain->value(), offset = m_scaleOffset->value();
    if (m_scaleChannel->currentIndex() > 0 && (gain != 1.0 || offset != 0.0)) {
        const std::string name = m_scaleChannel->currentText().toStdString();
        for (auto& ch : table->channels) {
            if (ch.name != name)
                continue;
            for (double& v : ch.data)
                v = gain * v + offset;
            const std::string shown = name + " ×" + model::formatShortest(gain) +
                                      (offset != 0.0 ? " +" + model::formatShortest(offset) : std::string());
            if (const auto* u = table->metadata.find("unit." + name)) {
                table->metadata.set("unit." + shown, *u);
                table->metadata.erase("unit." + name);
            }
            ch.name = shown;
            m_scaledName = qs(shown);
        }
    }
    const bool keepCursors = !m_plot->cursorReadout().isEmpty();
    m_plot->setCapture(table);
    if (!keepCursors && m_capture->rows() >= 2) {
        const auto [lo, hi] = m_plot->visibleRange();
        m_plot->setCursors(lo + 0.25 * (hi - lo), lo + 0.75 * (hi - lo));
    }
    updateXyPlot();
}

void ScopeDock::updateAnalysisChannels()
{
    QStringList names;
    if (m_capture)
        for (const auto& ch : m_capture->channels)
            names << qs(ch.name);
    {
        // Scale: "none" first, then the channels; the choice kept while it exists.
        QStringList have;
        for (int i = 1; i < m_scaleChannel->count(); ++i)
            have << m_scaleChannel->itemText(i);
        if (have != names) {
            const QString current = m_scaleChannel->currentIndex() > 0 ? m_scaleChannel->currentText() : QString();
            const QSignalBlocker block(m_scaleChannel);
            while (m_scaleChannel->count() > 1)
                m_scaleChannel->removeItem(1);
            m_scaleChannel->addItems(names);
            const int i = current.isEmpty() ? -1 : m_scaleChannel->findText(current);
            m_scaleChannel->setCurrentIndex(i > 0 ? i : 0);
        }
    }
    for (auto* c : {m_mathA, m_mathB, m_xChannel, m_yChannel}) {
        QStringList have;
        for (int i = 0; i < c->count(); ++i)
            have << c->itemText(i);
        if (have == names)
            continue;
        const QString current = c->currentText();
        const QSignalBlocker block(c);
        c->clear();
        c->addItems(names);
        // Keep the choice; else the first channel that is not the machine time (B and Y: the next one).
        const int skip = names.isEmpty() || names.front() != QLatin1String("t_s") ? 0 : 1;
        if (const int i = c->findText(current); i >= 0)
            c->setCurrentIndex(i);
        else
            c->setCurrentIndex(std::min(skip + ((c == m_mathB || c == m_yChannel) ? 1 : 0), c->count() - 1));
    }
}

void ScopeDock::updateXyPlot()
{
    if (!m_xy->isChecked())
        return;
    m_xyPlot->clear();
    if (!m_capture)
        return;
    int kx = -1, ky = -1;
    for (std::size_t k = 0; k < m_capture->channels.size(); ++k) {
        if (qs(m_capture->channels[k].name) == m_xChannel->currentText())
            kx = static_cast<int>(k);
        if (qs(m_capture->channels[k].name) == m_yChannel->currentText())
            ky = static_cast<int>(k);
    }
    if (kx < 0 || ky < 0)
        return;
    m_xyPlot->setAxes(m_xChannel->currentText(), qs(m_capture->channels[kx].unit), m_yChannel->currentText(),
                      qs(m_capture->channels[ky].unit));
    // Two quantities of one unit (X against Y of a circle) get one scale, so the plot shows their true shape.
    m_xyPlot->setEqualScales(m_capture->channels[kx].unit == m_capture->channels[ky].unit);
    m_xyPlot->addCurve(tr("capture"), m_capture->columns[kx], m_capture->columns[ky]);
    m_xyPlot->rescale();
}

void ScopeDock::setScale(const QString& channel, double gain, double offset)
{
    const QSignalBlocker b1(m_scaleChannel), b2(m_scaleGain), b3(m_scaleOffset);
    const int i = channel.isEmpty() ? 0 : m_scaleChannel->findText(channel);
    m_scaleChannel->setCurrentIndex(i > 0 ? i : 0);
    m_scaleGain->setValue(gain);
    m_scaleOffset->setValue(offset);
    redraw();
}

void ScopeDock::setMath(Math op, const QString& a, const QString& b)
{
    m_mathA->setCurrentIndex(m_mathA->findText(a));
    m_mathB->setCurrentIndex(m_mathB->findText(b));
    m_mathOp->setCurrentIndex(static_cast<int>(op));
    redraw();
}

void ScopeDock::setXy(bool on, const QString& x, const QString& y)
{
    if (!x.isEmpty())
        m_xChannel->setCurrentIndex(m_xChannel->findText(x));
    if (!y.isEmpty())
        m_yChannel->setCurrentIndex(m_yChannel->findText(y));
    m_xy->setChecked(on);
    updateXyPlot();
}

void ScopeDock::keepReference()
{
    if (!m_capture)
        return;
    ++m_references;
    const auto table = scopePlotTable(*m_capture);
    const auto& time = table->channels.front().data;
    for (std::size_t k = 1; k < table->channels.size(); ++k) {
        const auto& ch = table->channels[k];
        const auto u = table->metadata.text("unit." + ch.name);
        m_plot->addSeries(tr("ref %1: %2").arg(m_references).arg(qs(ch.name)), time, ch.data, u ? qs(*u) : QString(),
                          QColor(150, 150, 150), Qt::DashLine);
    }
}

void ScopeDock::clearReferences()
{
    m_references = 0;
    m_plot->clear();
    redraw();
}

widgets::CurvePlot* ScopeDock::showSpectrum(QString* error)
{
    auto fail = [&](const QString& e) -> widgets::CurvePlot* {
        if (error)
            *error = e;
        return nullptr;
    };
    if (!m_capture)
        return fail(tr("No capture shown"));
    const QString channel = m_mathA->currentText();
    // The rows inside the visible time window (time as the plot shows it).
    const auto table = scopePlotTable(*m_capture);
    const auto& t = table->channels.front().data;
    const auto [lo, hi] = m_plot->visibleRange();
    const auto first = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), lo) - t.begin());
    const auto last = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), hi) - t.begin());
    auto s = device::scopeSpectrum(*m_capture, channel.toStdString(), first, last > first ? last - first : 0);
    if (!s)
        return fail(qs(s.error().detail));
    QString unit;
    for (const auto& ch : m_capture->channels)
        if (qs(ch.name) == channel)
            unit = qs(ch.unit);
    auto* plot = new widgets::CurvePlot;
    plot->setAxes(tr("Frequency"), QStringLiteral("Hz"), tr("Amplitude"), unit);
    plot->addCurve(channel, s->freqHz, s->amplitude);
    plot->rescale();
    plot->setProperty("resolutionHz", s->resolutionHz);
    m_ctx.showDocument(plot, tr("Spectrum of %1 (%2 samples, %3 Hz resolution)")
                                 .arg(channel)
                                 .arg(last - first)
                                 .arg(qs(model::formatNumber(s->resolutionHz, 4))));
    return plot;
}

} // namespace gui
} // namespace axistune

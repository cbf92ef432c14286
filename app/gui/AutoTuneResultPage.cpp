// SPDX-License-Identifier: GPL-3.0-or-later
// The one-button tuning wizard's result page (AutoTuneWizard.h; docs/tuning.md "The wizard"): the figures and the
// parameters applied, the resonance map over the travel and the amplitude map.
#include "app/gui/AppContext.h"
#include "app/gui/AutoTuneWizard.h"
#include "app/gui/AutoTuneWizardText.h"
#include "widgets/CurvePlot.h"

#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

namespace axistune {
namespace gui {

using autotunetext::item;
using autotunetext::qs;
using autotunetext::wasAborted;

// ---------------------------------------------------------------------------------------------------------------
// Result

AutoTuneResultPage::AutoTuneResultPage(AppContext& ctx, AutoTuneData& shared, QWidget* parent)
    : QWizardPage(parent), m_ctx(ctx), m_d(shared)
{
    setTitle(tr("Result"));
    auto* lay = new QVBoxLayout(this);
    m_outcome = new QLabel(this);
    m_outcome->setObjectName("atOutcome");
    m_outcome->setWordWrap(true);
    m_outcome->setTextInteractionFlags(Qt::TextSelectableByMouse);
    lay->addWidget(m_outcome);
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName("atResultTabs");

    auto* figuresTab = new QWidget(m_tabs);
    auto* fl = new QVBoxLayout(figuresTab);
    m_figures = new QTableWidget(0, 2, figuresTab);
    m_figures->setObjectName("atFigures");
    m_figures->setHorizontalHeaderLabels({tr("Figure"), tr("Value")});
    m_figures->verticalHeader()->hide();
    m_figures->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_figures->horizontalHeader()->setStretchLastSection(true);
    fl->addWidget(m_figures, 1);
    m_parametersTitle = new QLabel(figuresTab);
    fl->addWidget(m_parametersTitle);
    m_parameters = new QTableWidget(0, 4, figuresTab);
    m_parameters->setObjectName("atParameters");
    m_parameters->setHorizontalHeaderLabels({tr("Parameter"), tr("Before"), tr("After"), tr("Unit")});
    m_parameters->verticalHeader()->hide();
    m_parameters->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_parameters->horizontalHeader()->setStretchLastSection(true);
    fl->addWidget(m_parameters, 1);
    m_tabs->addTab(figuresTab, tr("Figures and parameters"));

    auto* resTab = new QWidget(m_tabs);
    auto* rl = new QVBoxLayout(resTab);
    m_resonancePlot = new widgets::CurvePlot(resTab);
    m_resonancePlot->setObjectName("atResonanceMap");
    m_resonancePlot->setMinimumHeight(260);
    rl->addWidget(m_resonancePlot, 3);
    m_positionsTable = new QTableWidget(0, 9, resTab);
    m_positionsTable->setObjectName("atPositionsTable");
    m_positionsTable->verticalHeader()->hide();
    m_positionsTable->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_positionsTable->horizontalHeader()->setStretchLastSection(true);
    rl->addWidget(m_positionsTable, 2);
    m_tabs->addTab(resTab, tr("Resonance map over the travel"));

    auto* ampTab = new QWidget(m_tabs);
    auto* al = new QVBoxLayout(ampTab);
    m_ampSummary = new QLabel(ampTab);
    m_ampSummary->setObjectName("atAmplitudeSummary");
    m_ampSummary->setWordWrap(true);
    al->addWidget(m_ampSummary);
    auto* plots = new QHBoxLayout;
    m_ampMap = new widgets::CurvePlot(ampTab);
    m_ampMap->setObjectName("atAmplitudeMap");
    plots->addWidget(m_ampMap, 1);
    m_ampMagnitude = new widgets::CurvePlot(ampTab);
    m_ampMagnitude->setObjectName("atAmplitudeMagnitude");
    plots->addWidget(m_ampMagnitude, 1);
    al->addLayout(plots, 1);
    m_tabs->addTab(ampTab, tr("Amplitude map"));
    lay->addWidget(m_tabs, 1);

    m_session = new QLabel(this);
    m_session->setObjectName("atSession");
    lay->addWidget(m_session);
    auto* undoRow = new QHBoxLayout;
    m_undoState = new QLabel(this);
    m_undoState->setObjectName("atUndoState");
    m_undoState->setWordWrap(true);
    m_undoState->setTextInteractionFlags(Qt::TextSelectableByMouse);
    undoRow->addWidget(m_undoState, 1);
    m_undoAnyway = new QPushButton(tr("Undo anyway…"), this);
    m_undoAnyway->setObjectName("atUndoAnyway");
    undoRow->addWidget(m_undoAnyway);
    m_undo = new QPushButton(tr("Undo…"), this);
    m_undo->setObjectName("atUndo");
    m_undo->setToolTip(tr("Write back the values the parameters had before the run"));
    undoRow->addWidget(m_undo);
    lay->addLayout(undoRow);
    connect(m_undo, &QPushButton::clicked, this, [this] { confirmUndo(false); });
    connect(m_undoAnyway, &QPushButton::clicked, this, [this] { confirmUndo(true); });
    connect(&m_ctx.drive(), &DriveController::testRunningChanged, this, &AutoTuneResultPage::updateUndoButtons);
    connect(&m_ctx.drive(), &DriveController::connectionChanged, this, &AutoTuneResultPage::updateUndoButtons);
    lay->addStretch(0); // takes the room of the hidden tables after a refusal
    setFinalPage(true);
}

void AutoTuneResultPage::showResonanceMap(const nlohmann::json& j, bool linear)
{
    // From the result JSON (resultJson: resonance_map[] and final.positions[]), as the CLI writes it.
    const QString unit = linear ? QStringLiteral("m") : QStringLiteral("rad");
    m_resonancePlot->clear();
    m_resonancePlot->setAxes(tr("Position"), unit, tr("First resonance"), tr("Hz"));
    std::vector<double> x, f;
    for (const auto& m : j["resonance_map"]) {
        const double pos = m.value("position", std::numeric_limits<double>::quiet_NaN());
        if (!m.contains("frequency_Hz") || !m["frequency_Hz"].is_number())
            continue;
        x.push_back(pos);
        f.push_back(m["frequency_Hz"].get<double>());
    }
    m_resonancePlot->addCurve(tr("first resonance (labels: frequency, height above the baseline)"), x, f,
                              QColor(0, 90, 181));
    std::size_t k = 0;
    for (const auto& m : j["resonance_map"]) {
        if (!m.contains("frequency_Hz") || !m["frequency_Hz"].is_number())
            continue;
        const double h =
            m.contains("height_dB") && m["height_dB"].is_number() ? m["height_dB"].get<double>() : std::nan("");
        m_resonancePlot->addPoint(x[k], f[k], tr("%1 Hz, %2 dB").arg(f[k], 0, 'f', 1).arg(h, 0, 'f', 1));
        ++k;
    }
    m_resonancePlot->rescale();
    // Room for the labels right of and above the points.
    if (!x.empty()) {
        const auto [x0, x1] = std::minmax_element(x.begin(), x.end());
        const auto [f0, f1] = std::minmax_element(f.begin(), f.end());
        const double dx = std::max(*x1 - *x0, 1e-3 * std::max(1.0, std::abs(*x0)));
        const double df = std::max(*f1 - *f0, 0.05 * *f1);
        m_resonancePlot->setXRange(*x0 - 0.08 * dx, *x1 + 0.25 * dx);
        m_resonancePlot->setYRange(*f0 - 0.15 * df, *f1 + 0.2 * df);
    }

    m_positionsTable->setRowCount(0);
    m_positionsTable->setHorizontalHeaderLabels({tr("Position\n[%1]").arg(unit), tr("First resonance\n[Hz]"),
                                                 tr("Height\n[dB]"), tr("Phase margin\n[°]"), tr("Gain margin\n[dB]"),
                                                 tr("Velocity bandwidth\n[Hz]"), tr("Position bandwidth\n[Hz]"),
                                                 tr("Predicted phase\nmargin [°]"), tr("Predicted gain\nmargin [dB]")});
    const auto& map = j["resonance_map"];
    const nlohmann::json none = nlohmann::json::array();
    const auto& per = j.contains("final") && j["final"].contains("positions") ? j["final"]["positions"] : none;
    auto num = [](const nlohmann::json& o, const char* key, int decimals) {
        return o.contains(key) && o[key].is_number() ? QString::number(o[key].get<double>(), 'f', decimals)
                                                     : QStringLiteral("–");
    };
    for (std::size_t i = 0; i < map.size(); ++i) {
        const auto& m = map[i];
        const int row = m_positionsTable->rowCount();
        m_positionsTable->insertRow(row);
        m_positionsTable->setItem(row, 0, item(num(m, "position", 4)));
        const bool has = m.contains("frequency_Hz") && m["frequency_Hz"].is_number();
        m_positionsTable->setItem(row, 1, item(has ? num(m, "frequency_Hz", 1) : tr("none in the band")));
        m_positionsTable->setItem(row, 2, item(has ? num(m, "height_dB", 1) : QStringLiteral("–")));
        const nlohmann::json p = i < per.size() ? per[i] : nlohmann::json::object();
        m_positionsTable->setItem(row, 3, item(num(p, "phase_margin_deg", 1)));
        m_positionsTable->setItem(row, 4, item(num(p, "gain_margin_dB", 1)));
        m_positionsTable->setItem(row, 5, item(num(p, "velocity_bandwidth_Hz", 1)));
        m_positionsTable->setItem(row, 6, item(num(p, "position_bandwidth_Hz", 1)));
        m_positionsTable->setItem(row, 7, item(num(p, "predicted_phase_margin_deg", 1)));
        m_positionsTable->setItem(row, 8, item(num(p, "predicted_gain_margin_dB", 1)));
    }
}

void AutoTuneResultPage::showAmplitudeMap(const nlohmann::json& map)
{
    // From the frf step's measured.amplitude_map (autotune::inUseJson): every line at every amplitude it was
    // measured at, coloured by the core's verdict.
    m_ampMap->clear();
    m_ampMagnitude->clear();
    m_ampMap->setAxes(tr("Frequency"), tr("Hz"), tr("Multisine peak"), tr("% of rated torque"), true, true);
    m_ampMagnitude->setAxes(tr("Frequency"), tr("Hz"), tr("Closed velocity loop |T|"), tr("dB"), true, false);
    std::vector<double> fl, al, fn, an, fo, ao, fnMag, nMag;
    std::map<double, std::pair<std::vector<double>, std::vector<double>>> perAmplitude;
    double fmin = std::numeric_limits<double>::infinity(), fmax = 0.0;
    for (const auto& line : map.value("lines", nlohmann::json::array())) {
        const double f = line.value("f_Hz", std::nan(""));
        const bool nonlinear = line.value("nonlinear", false);
        const bool compared = line.value("compared", false);
        double top = -std::numeric_limits<double>::infinity();
        for (const auto& at : line.value("at", nlohmann::json::array())) {
            const double a = at.value("amplitude_pct", std::nan(""));
            const double db = at.value("magnitude_dB", std::nan(""));
            (nonlinear ? fn : compared ? fl : fo).push_back(f);
            (nonlinear ? an : compared ? al : ao).push_back(a);
            perAmplitude[a].first.push_back(f);
            perAmplitude[a].second.push_back(db);
            top = std::max(top, db);
        }
        if (nonlinear && std::isfinite(top)) {
            fnMag.push_back(f);
            nMag.push_back(top);
        }
        if (std::isfinite(f)) {
            fmin = std::min(fmin, f);
            fmax = std::max(fmax, f);
        }
    }
    if (map.contains("design_amplitude_pct") && map["design_amplitude_pct"].is_number() && fmax > fmin) {
        const double a = map["design_amplitude_pct"].get<double>();
        m_ampMap->addCurve(tr("designed from %1 %").arg(a, 0, 'g', 4), {fmin, fmax}, {a, a}, QColor(40, 140, 40),
                           Qt::DashLine);
    }
    // The few linear lines over the many non-linear ones (vmc X: 14 of 388), so that they show.
    m_ampMap->addCurve(tr("non-linear"), fn, an, QColor(200, 0, 30), Qt::SolidLine, true);
    m_ampMap->addCurve(tr("linear"), fl, al, QColor(0, 90, 181), Qt::SolidLine, true);
    m_ampMap->addCurve(tr("not compared"), fo, ao, QColor(170, 170, 170), Qt::SolidLine, true);
    m_ampMap->rescale();
    if (!perAmplitude.empty()) // the amplitudes' rows with room above and below (log axis)
        m_ampMap->setYRange(perAmplitude.begin()->first / 1.4, perAmplitude.rbegin()->first * 1.4);
    for (const auto& [a, fx] : perAmplitude)
        m_ampMagnitude->addCurve(tr("%1 % of rated torque").arg(a, 0, 'g', 4), fx.first, fx.second);
    m_ampMagnitude->addCurve(tr("non-linear lines"), fnMag, nMag, QColor(200, 0, 30), Qt::SolidLine, true);
    m_ampMagnitude->rescale();
    const auto count = [&](const char* key) {
        return map.contains(key) && map[key].is_number() ? QString::number(map[key].get<double>(), 'g', 6)
                                                         : QStringLiteral("–");
    };
    m_ampSummary->setText(
        tr("%1 of %2 compared lines non-linear (a line is non-linear when two amplitudes differ by more than %3 "
           "combined standard errors). Peak torque of the move with the running gains: %4 % of rated torque; "
           "designed from the amplitude %5 % of rated torque.")
            .arg(count("nonlinear_lines"), count("lines_compared"), count("threshold_sigmas"),
                 map.contains("use_torque_pct") && map["use_torque_pct"].is_number()
                     ? QString::number(map["use_torque_pct"].get<double>(), 'f', 1)
                     : QStringLiteral("–"),
                 count("design_amplitude_pct")));
}

void AutoTuneResultPage::initializePage()
{
    m_figures->setRowCount(0);
    m_parameters->setRowCount(0);
    if (!m_undoing && !m_undone) { // a second call (the session id arrived) keeps an undo's outcome
        m_tune.reset();
        m_changed.clear();
        m_driveNow.clear();
        m_undoState->clear();
        m_undoState->setStyleSheet(QString());
    }
    m_undo->setVisible(false);
    m_undoAnyway->setVisible(false);
    if (m_d.stored) {
        initializeStored();
        return;
    }
    const auto* r = m_d.result.get();
    const bool refused = !r || r->outcome == autotune::Outcome::Refused || !r->final;
    m_figures->setVisible(!refused);
    m_parameters->setVisible(!refused);
    m_parametersTitle->setVisible(!refused);
    // The maps, also after a refusal when the run measured them (what the frf step found).
    static const std::vector<autotune::Step> kNoSteps;
    const auto& steps = r ? r->steps : kNoSteps;
    bool linear = true;
    for (const auto& st : steps)
        if (st.name == "safety-envelope") {
            const auto& from = st.chosen.contains("axis_units") ? st.chosen : st.measured;
            linear = from.value("axis_units", std::string("m")) == "m";
        }
    nlohmann::json j = r ? autotune::resultJson(*r, m_d.options) : nlohmann::json::object();
    const bool hasMap = j.contains("resonance_map") && !j["resonance_map"].empty();
    const nlohmann::json* amp = nullptr;
    for (const auto& st : steps)
        if (st.name == "frf" && st.measured.contains("amplitude_map"))
            amp = &st.measured["amplitude_map"];
    if (hasMap)
        showResonanceMap(j, linear);
    if (amp)
        showAmplitudeMap(*amp);
    m_tabs->setTabVisible(FiguresTab, !refused);
    m_tabs->setTabVisible(ResonanceTab, hasMap);
    m_tabs->setTabVisible(AmplitudeTab, amp != nullptr);
    m_tabs->setVisible(!refused || hasMap || amp);
    m_tabs->setCurrentIndex(!refused ? FiguresTab : hasMap ? ResonanceTab : AmplitudeTab);
    if (auto* box = qobject_cast<QBoxLayout*>(layout()))
        box->setStretch(box->count() - 1, m_tabs->isVisibleTo(this) ? 0 : 1);
    m_session->setText(m_d.sessionId > 0 ? tr("Saved as session %1.").arg(m_d.sessionId)
                                         : tr("The session is saved to the store when one is open."));
    if (refused) {
        m_outcome->setStyleSheet(QStringLiteral("color: #b00020;"));
        if (!r)
            m_outcome->setText(tr("The run could not start: %1.\nNothing was changed.").arg(m_d.error));
        else if (!r->restored)
            m_outcome->setText(tr("%1: %2\nRESTORING THE PARAMETERS FAILED: check the drive's parameters.")
                                   .arg(wasAborted(*r) ? tr("Aborted") : tr("Refused"), qs(r->reason)));
        else
            m_outcome->setText(tr("%1: %2\nNothing was changed: every parameter was restored and read back equal.")
                                   .arg(wasAborted(*r) ? tr("Aborted") : tr("Refused"), qs(r->reason)));
        return;
    }
    m_outcome->setStyleSheet(QString());
    const auto& f = *r->final;
    m_outcome->setText((r->outcome == autotune::Outcome::DryRun
                            ? tr("Dry run finished: every parameter was restored; the values below were not applied.")
                            : tr("Applied: the parameters below are written and read back equal.")) +
                       (f.positions.empty()
                            ? QString()
                            : QStringLiteral("\n") + tr("Over %1 positions: the figures are the worst position's; "
                                                        "every position is in the resonance map's table.")
                                                         .arg(f.positions.size())));
    auto add = [&](const QString& name, const QString& value, const char* objectName) {
        const int row = m_figures->rowCount();
        m_figures->insertRow(row);
        m_figures->setItem(row, 0, item(name));
        auto* v = item(value);
        v->setData(Qt::UserRole, QString::fromLatin1(objectName));
        m_figures->setItem(row, 1, v);
    };
    add(tr("Phase margin (re-measured)"), tr("%1°").arg(f.phaseMarginDeg, 0, 'f', 1), "phase_margin_deg");
    add(tr("Gain margin (re-measured)"), tr("%1 dB").arg(f.gainMarginDb, 0, 'f', 1), "gain_margin_dB");
    add(tr("Velocity bandwidth (−3 dB)"), tr("%1 Hz").arg(f.velocityBandwidthHz, 0, 'f', 1), "velocity_bandwidth_Hz");
    add(tr("Position bandwidth (−3 dB)"), tr("%1 Hz").arg(f.positionBandwidthHz, 0, 'f', 1), "position_bandwidth_Hz");
    add(tr("Settling time of the move"),
        f.settlingTimeS ? tr("%1 ms").arg(1e3 * *f.settlingTimeS, 0, 'f', 1) : tr("not settled within the record"),
        "settling_time_s");
    add(tr("Peak following error"),
        linear ? tr("%1 µm").arg(1e6 * f.peakFollowingError, 0, 'f', 2)
               : tr("%1 mrad").arg(1e3 * f.peakFollowingError, 0, 'f', 3),
        "peak_following_error");
    add(tr("Motion time of the sequence"), tr("%1 s").arg(f.motionTimeS, 0, 'f', 2), "motion_time_s");
    m_parametersTitle->setText(r->outcome == autotune::Outcome::DryRun ? tr("Parameters it would apply (not applied):")
                                                                       : tr("Parameters applied (old → new):"));
    fillParameters();
    if (r->outcome != autotune::Outcome::Applied)
        return;
    // Undo: the applied run as core reads it from the result JSON (the CLI's `--undo` reads the same), and the
    // parameters' metadata for the units of the diff.
    auto tune = autotune::appliedTuneFromJson(j);
    if (!tune) {
        m_undoState->setText(tr("Undo is not offered: %1").arg(qs(tune.error().detail)));
        return;
    }
    m_tune = std::move(tune).value();
    offerUndo();
}

} // namespace gui
} // namespace axistune

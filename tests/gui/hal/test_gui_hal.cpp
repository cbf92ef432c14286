// SPDX-License-Identifier: GPL-3.0-or-later
// The GUI's wizards on LinuxCNC's HAL (issue 17 item 6, docs/linuxcnc.md "The wizards on hal:"): each test starts the
// repository's test machine through the fixture (tests/linuxcnc/HalTestbed.h: scripts/hal-testbed under the
// machine-wide lock), connects an AppContext to hal: and drives the wizards as a user would, offscreen.
//
// Expected numbers come from outside the code under test: the plant's exact discrete-time response computed from the
// component's own update equations and its pins (HalTestbed.h exactResponse, read with halcmd getp), the output limit
// read with halcmd getp, and the drive's documented plan (one settling period and three averaged periods of the
// multisine, docs/linuxcnc.md "The hal: connection").
// clang-format off
// First: HAL's headers use the name "signals", which Qt defines as a macro.
#include "core/store/SessionRecord.h"
#include "tests/linuxcnc/HalTestbed.h"
// clang-format on

#include "app/gui/AppContext.h"
#include "app/gui/FrfWizard.h"
#include "app/gui/NcPidPage.h"
#include "app/gui/NotchWizard.h"
#include "app/gui/VelocityLoopWizard.h"
#include "core/device/Drive.h"
#include "core/dsp/FrequencyResponse.h"
#include "core/store/Database.h"
#include "widgets/BodePlot.h"

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QListWidget>
#include <QPointer>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>

#include <cmath>
#include <complex>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tests/gui/GuiTestUtil.h"

using namespace axistune;
using axistune::gui::FrfWizard;
using axistune::testing::halText;
using axistune::testing::maybeScreenshot;
using axistune::testing::netsOf;
using axistune::testing::waitUntil;

namespace {

class GuiOnHal : public axistune::testing::HalTestbed {
protected:
    /// Starts the test machine (1 kHz servo thread) and connects `ctx` to hal: as the app does (AXISTUNE_HALCMD).
    /// Starts the test machine and connects to it through `uri` (hal:, or linuxcnc: with the machine's own INI, whose
    /// axis is X); `axis` is the name the connection gives pid.x.
    void connectBed(gui::AppContext& ctx, const QString& uri = QStringLiteral("hal:"),
                    const QString& axis = QStringLiteral("pid.x"))
    {
        startBed(1000000);
        if (HasFatalFailure())
            return;
        qputenv("AXISTUNE_HALCMD", QByteArray::fromStdString(axistune::testing::kScript + " halcmd"));
        m_sig = halText({"-s", "show", "sig"});
        m_funct = halText({"-s", "show", "funct"});
        ASSERT_TRUE(m_tmp.isValid());
        ASSERT_TRUE(ctx.openDatabase(m_tmp.filePath("hal.db")));
        ctx.drive().connectTo(uri);
        ASSERT_TRUE(waitUntil([&] { return ctx.drive().isConnected(); }, 30000)) << uri.toStdString()
                                                                                  << " did not connect";
        ASSERT_TRUE(ctx.axes().contains(axis)) << ctx.axes().join(' ').toStdString();
    }
    /// HAL's nets (names, types, writers, readers) and functions are as they were before the test.
    void expectHalUnchanged()
    {
        EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), netsOf(m_sig));
        EXPECT_EQ(halText({"-s", "show", "funct"}), m_funct);
    }
    std::string m_sig, m_funct;
    QTemporaryDir m_tmp;
};

QLabel* amplitudeText(FrfWizard& w)
{
    return w.safetyPage()->findChild<QLabel*>("frfAmplitudeText");
}

// Issue 17 item 6: the FRF wizard on hal: pid.x. The amplitude is a peak in the PID output's units, bounded by the
// drive's limit (half of maxoutput, read here with halcmd); the method offered is the one the drive advertises
// (multisine); the quantity is the plant; the motion time is the drive's plan; the plotted plant equals the exact
// discrete response within 0.1 dB and 0.5° (issue 17's tolerance, the one HalTestbed.MultisinePlantFrfEqualsThe-
// ExactDiscreteResponse holds through the CLI path, measured there at 0.0006 dB); HAL's nets are unchanged afterwards.
TEST_F(GuiOnHal, FrfWizardMeasuresThePlantInThePidOutputsUnits)
{
    gui::AppContext ctx;
    connectBed(ctx);
    if (HasFatalFailure())
        return;
    const double maxOutput = axistune::testing::getp("pid.x.maxoutput");
    ASSERT_GT(maxOutput, 0.0);
    const double maxPeak = 0.5 * maxOutput; // docs/linuxcnc.md: above half of maxoutput the test is refused

    auto* wizard = new FrfWizard(ctx);
    QPointer<FrfWizard> guard(wizard);
    FrfWizard& w = *wizard;
    w.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
    auto* safety = w.safetyPage();
    ASSERT_TRUE(waitUntil([&] { return safety->driveInfo().capabilities.has_value(); }, 30000))
        << amplitudeText(w)->text().toStdString();
    EXPECT_EQ(safety->axis(), QStringLiteral("pid.x"));
    // The pid's limits and gains are listed (the servo drive's keys the page also asks for are not there): maxoutput,
    // maxerror, Pgain, Igain, Dgain.
    auto* limits = safety->findChild<QTableWidget*>();
    ASSERT_TRUE(limits);
    EXPECT_TRUE(waitUntil([&] { return limits->rowCount() == 5; }, 30000)) << limits->rowCount();
    // The peak in the PID output's units is asked, not % of rated torque.
    EXPECT_TRUE(safety->driveInfo().peakInOutputUnits());
    EXPECT_FALSE(safety->amplitude()->isVisibleTo(&w));
    EXPECT_TRUE(safety->amplitudePeak()->isVisibleTo(&w));
    EXPECT_TRUE(safety->amplitudePeak()->suffix().contains("pid.x.output"))
        << safety->amplitudePeak()->suffix().toStdString();
    EXPECT_NEAR(safety->driveInfo().maxPeak(), maxPeak, 1e-9 * maxPeak);
    // Above the drive's limit: refused with the limit named, Next stays off even with the confirmation.
    safety->amplitudePeak()->setValue(1.02 * maxPeak);
    safety->confirmation()->setChecked(true);
    EXPECT_FALSE(w.button(QWizard::NextButton)->isEnabled());
    // The refusal names the limit (half of maxoutput as read above) and the signal, in the user's language.
    EXPECT_EQ(amplitudeText(w)->text(),
              QCoreApplication::translate("axistune::gui::FrfSafetyPage",
                                          "<span style='color:#b00000'>Refused: the drive allows a peak of at most %1 "
                                          "in the units of %2.</span>")
                  .arg(maxPeak, 0, 'g', 4)
                  .arg("pid.x.output"));
    // A tenth of maxoutput (the CLI's documented 0.2 N·m on this machine).
    const double peak = 0.1 * maxOutput;
    safety->amplitudePeak()->setValue(peak);
    EXPECT_FALSE(w.button(QWizard::NextButton)->isEnabled()); // a new amplitude needs a new confirmation
    safety->confirmation()->setChecked(true);
    ASSERT_TRUE(w.button(QWizard::NextButton)->isEnabled()) << amplitudeText(w)->text().toStdString();
    maybeScreenshot(&w, "frf-hal-01-safety");
    w.next();
    ASSERT_EQ(w.currentId(), int(FrfWizard::ConfigId));

    auto* cfg = w.configPage();
    // The methods and quantities the drive advertises (hal:: multisine, multi-sweep, PRBS; not the conventional sine
    // stream; plant and open loop).
    const auto& advertised = safety->driveInfo().capabilities->frfMethods;
    ASSERT_EQ(cfg->method()->count(), int(advertised.size()));
    for (auto m : advertised)
        EXPECT_GE(cfg->method()->findData(int(m)), 0) << device::frfMethodName(m);
    EXPECT_LT(cfg->method()->findData(int(device::FrfMethod::Conventional)), 0);
    cfg->method()->setCurrentIndex(cfg->method()->findData(int(device::FrfMethod::Multisine)));
    EXPECT_EQ(cfg->selectedMethod(), device::FrfMethod::Multisine);
    EXPECT_TRUE(cfg->quantity()->isVisibleTo(&w));
    ASSERT_EQ(cfg->quantity()->count(), 2);
    EXPECT_EQ(cfg->selectedQuantity(), device::FrfQuantity::Plant);
    // The default band ends below half the servo rate (lines above it would fold): 90 % of 500 Hz.
    EXPECT_DOUBLE_EQ(cfg->fmax()->value(), 450.0);
    // 2–450 Hz with 224 points: the wizard's line spacing min(fmin/2, (fmax − fmin)/points) = 1 Hz, a window of 1 s
    // (1000 servo periods); a period of the three-phase multisine is three windows (docs/multisine.md), and the drive
    // plans one settling period and three averaged ones (docs/linuxcnc.md): (1 + 3) × 3 × 1 s = 12 s of motion.
    cfg->fmin()->setValue(2.0);
    cfg->points()->setValue(224);
    ASSERT_TRUE(waitUntil([&] { return cfg->isComplete(); }, 30000))
        << cfg->findChild<QLabel*>("frfEstimate")->text().toStdString();
    EXPECT_NEAR(cfg->estimatedMotionS(), 12.0, 1e-9);
    // Above the drive's band limit the drive's refusal is shown and Next stays off.
    cfg->fmax()->setValue(500.0);
    ASSERT_TRUE(waitUntil(
        [&] { return cfg->findChild<QLabel*>("frfEstimate")->text().contains("half the servo rate"); }, 30000))
        << cfg->findChild<QLabel*>("frfEstimate")->text().toStdString();
    EXPECT_FALSE(cfg->isComplete());
    cfg->fmax()->setValue(450.0);
    ASSERT_TRUE(waitUntil([&] { return cfg->isComplete(); }, 30000));
    maybeScreenshot(&w, "frf-hal-02-method");
    const device::TestRequest req = w.request();
    ASSERT_TRUE(req.is<device::FrfTest>());
    EXPECT_DOUBLE_EQ(req.frf().amplitudePeak, peak);
    EXPECT_EQ(req.frf().quantity, device::FrfQuantity::Plant);
    EXPECT_DOUBLE_EQ(req.frf().multisineSpacingHz, 1.0);
    w.next();
    ASSERT_EQ(w.currentId(), int(FrfWizard::RunId));
    ASSERT_TRUE(waitUntil([&] { return !w.runPage()->isRunning(); }, 120000));
    ASSERT_TRUE(w.runPage()->succeeded()) << w.runPage()->failure().toStdString();
    maybeScreenshot(&w, "frf-hal-03-run");
    w.next();
    ASSERT_EQ(w.currentId(), int(FrfWizard::ResultId));
    auto* res = w.resultPage();
    ASSERT_TRUE(waitUntil([&] { return res->analysed(); }, 30000));
    maybeScreenshot(&w, "frf-hal-04-result");

    // The plant, feedback / drive input, every line against the exact discrete response of the running plant.
    EXPECT_EQ(res->quantity(), QStringLiteral("plant"));
    EXPECT_EQ(res->bodePlot()->magnitudeTitle(),
              QCoreApplication::translate("axistune::gui::FrfResultPage", "Plant [dB]"));
    const auto& frf = res->measured();
    // Lines every 1 Hz inside 2–450 Hz, none missing.
    ASSERT_GE(frf.size(), 440u);
    EXPECT_GE(frf.freqHz.front(), 2.0 - 1e-9);
    EXPECT_LE(frf.freqHz.back(), 450.0 + 1e-9);
    for (std::size_t i = 1; i < frf.size(); ++i)
        ASSERT_NEAR(frf.freqHz[i] - frf.freqHz[i - 1], 1.0, 1e-9) << "at " << frf.freqHz[i] << " Hz";
    RecordProperty("lines", std::to_string(frf.size()) + " from " + model::formatShortest(frf.freqHz.front()) + " to " +
                                model::formatShortest(frf.freqHz.back()) + " Hz");
    const axistune::testing::Plant plant = axistune::testing::readPlant();
    double worstDb = 0.0, worstDeg = 0.0, worstPlotDb = 0.0;
    for (std::size_t i = 0; i < frf.size(); ++i) {
        const std::complex<double> exact = axistune::testing::exactResponse(plant, 1e-3, frf.freqHz[i]);
        const std::complex<double> ratio = frf.h[i] / exact;
        ASSERT_TRUE(std::isfinite(std::abs(ratio)) && std::abs(exact) > 0.0) << frf.freqHz[i] << " Hz";
        worstDb = std::max(worstDb, std::abs(20.0 * std::log10(std::abs(ratio))));
        worstDeg = std::max(worstDeg, std::abs(std::arg(ratio)) * 180.0 / M_PI);
        // What the plot draws is that response, point by point.
        worstPlotDb = std::max(worstPlotDb,
                               std::abs(res->bodePlot()->magnitudeDbAt(0, frf.freqHz[i]) - dsp::magnitudeDb(frf.h[i])));
    }
    EXPECT_LE(worstDb, 0.1);
    EXPECT_LE(worstDeg, 0.5);
    EXPECT_LE(worstPlotDb, 1e-6);
    RecordProperty("worst_dB", model::formatShortest(worstDb));
    RecordProperty("worst_deg", model::formatShortest(worstDeg));
    // The two-mass resonance in the table: the peak of the exact response's |H|·(2πf)² (flat for the rigid body of this
    // torque-driven plant; docs/linuxcnc.md reads it at 106.92 Hz) within 2 % (issue 17's tolerance for the modes).
    double exactPeakHz = 0.0, exactPeak = 0.0;
    for (double f = 80.0; f <= 150.0; f += 0.01) {
        const double m = std::abs(axistune::testing::exactResponse(plant, 1e-3, f)) * std::pow(2.0 * M_PI * f, 2);
        if (m > exactPeak) {
            exactPeak = m;
            exactPeakHz = f;
        }
    }
    ASSERT_EQ(res->analysis().resonances.size(), 1u)
        << res->analysis().error.toStdString() << " " << res->analysis().analysedForm.toStdString();
    EXPECT_NEAR(res->analysis().resonances.front().freqHz, exactPeakHz, 0.02 * exactPeakHz);
    EXPECT_EQ(res->resonanceTable()->rowCount(), int(res->analysis().resonances.size()));
    EXPECT_EQ(res->bodePlot()->markerCount(), int(res->analysis().resonances.size()));
    for (const auto& r : res->analysis().resonances)
        RecordProperty("resonance_Hz", model::formatShortest(r.freqHz));

    w.next();
    ASSERT_EQ(w.currentId(), int(FrfWizard::SaveId));
    w.savePage()->openDocumentBox()->setChecked(false);
    maybeScreenshot(&w, "frf-hal-05-save");
    // Save and hand over to the notch wizard: on hal: its drive-slot proposal does not apply, and Next goes to the page
    // that proposes LinuxCNC's biquad for the axis.
    QPointer<QWizard> opened;
    QObject::connect(&w, &FrfWizard::notchWizardOpened, [&](QWizard* n) { opened = n; });
    w.savePage()->openNotchButton()->click();
    ASSERT_GT(w.savedSessionId(), 0);
    auto saved = ctx.database()->loadSession(w.savedSessionId());
    ASSERT_TRUE(saved.ok());
    EXPECT_DOUBLE_EQ(saved->inputs.at("amplitude_peak").get<double>(), peak);
    EXPECT_EQ(saved->inputs.at("amplitude_signal").get<std::string>(), "pid.x.output");
    EXPECT_EQ(saved->inputs.at("quantity").get<std::string>(), "plant");
    EXPECT_FALSE(saved->inputs.contains("amplitude_pct"));
    auto* notch = qobject_cast<gui::NotchWizard*>(opened.data());
    ASSERT_TRUE(notch);
    ASSERT_TRUE(QTest::qWaitForWindowExposed(notch));
    ASSERT_EQ(notch->currentId(), int(gui::NotchWizard::kPropose));
    ASSERT_TRUE(waitUntil([&] { return !notch->ncPidRefusal().isEmpty(); }, 30000));
    EXPECT_TRUE(notch->ncPidRefusal().contains("biquad")) << notch->ncPidRefusal().toStdString();
    EXPECT_TRUE(notch->ncPidRefusal().contains("pid.x.output"));
    QTest::qWait(200);
    EXPECT_TRUE(notch->rows().empty()); // no drive slots proposed
    ASSERT_TRUE(notch->proposePage()->isComplete());
    ASSERT_TRUE(notch->button(QWizard::NextButton)->isEnabled());
    maybeScreenshot(notch, "notch-hal-handover");
    notch->next();
    ASSERT_EQ(notch->currentId(), int(gui::NotchWizard::kNcPid));
    EXPECT_EQ(notch->ncPidPage()->axis(), QStringLiteral("pid.x"));
    EXPECT_FALSE(notch->ncPidPage()->measureButton()->isEnabled()); // not before the safety confirmation
    notch->close();
    ASSERT_TRUE(waitUntil([&] { return opened.isNull(); }, 5000));
    if (guard)
        delete guard.data();

    // Nothing AxisTune inserted is left in HAL, and the pid's gains are as the configuration set them.
    expectHalUnchanged();
}

/// Measures on the NC PID page (10 % of maxoutput, as the CLI's 0.2 on this machine) and waits for the proposal.
void measureOn(gui::NcPidPage& page)
{
    page.amplitudeBox()->setValue(10.0);
    EXPECT_FALSE(page.measureButton()->isEnabled()); // not before the safety confirmation
    page.confirmation()->setChecked(true);
    ASSERT_TRUE(page.measureButton()->isEnabled());
    page.measureButton()->click();
    ASSERT_TRUE(page.busy());
    EXPECT_TRUE(page.abortButton()->isEnabled());
    ASSERT_TRUE(waitUntil([&] { return !page.busy(); }, 180000));
    ASSERT_TRUE(page.measurement()) << page.status()->text().toStdString();
    ASSERT_TRUE(page.proposal()) << page.status()->text().toStdString();
}

/// Applies the page's proposal and waits for the verification.
void applyOn(gui::NcPidPage& page)
{
    ASSERT_TRUE(page.applyButton()->isEnabled()) << page.status()->text().toStdString();
    page.applyButton()->click();
    ASSERT_TRUE(waitUntil([&] { return !page.busy(); }, 180000));
    ASSERT_TRUE(page.applied()) << page.status()->text().toStdString();
}

/// The plant's resonance: the peak of the exact response's |H|·ω² on a 0.01 Hz grid (as the CLI test reads it).
double exactResonanceHz()
{
    return axistune::testing::exactResonanceHz(axistune::testing::readPlant(), 1e-3);
}

const std::vector<std::string> kGainKeys{"Pgain", "Igain", "Dgain", "FF1", "FF2"};

/// The gains of pid.x as HAL holds them (halcmd getp).
std::map<std::string, double> halGains()
{
    std::map<std::string, double> g;
    for (const auto& k : kGainKeys)
        g[k] = axistune::testing::getp("pid.x." + k);
    return g;
}

/// The journal entry of `key` in a saved session (each key at most once in a session of the NC PID page).
const store::JournalEntry* journalEntry(const store::SessionRecord& s, const std::string& key)
{
    for (const auto& e : s.journal)
        if (e.key == key)
            return &e;
    return nullptr;
}

/// The journal holds each gain from `from` to `to` (halcmd's values: 7 digits).
void expectGainsJournaled(const store::SessionRecord& s, const std::map<std::string, double>& from,
                          const std::map<std::string, double>& to)
{
    for (const auto& k : kGainKeys) {
        const auto* e = journalEntry(s, k);
        ASSERT_TRUE(e) << k;
        ASSERT_TRUE(e->oldValue) << k;
        EXPECT_NEAR(*e->oldValue, from.at(k), 1e-6 * std::abs(from.at(k)) + 1e-12) << k;
        EXPECT_NEAR(e->newValue, to.at(k), 1e-6 * std::abs(to.at(k)) + 1e-12) << k;
    }
}

/// The notch inserted where none ran, as the journal says it (docs/storage.md "Journal"): it runs (0 → 1), f0 and Q
/// with nothing before and the values HAL holds now (halcmd getp).
void expectNotchInsertedIn(const store::SessionRecord& s)
{
    const auto* runs = journalEntry(s, "axistune-notch");
    ASSERT_TRUE(runs);
    EXPECT_EQ(runs->oldValue, std::optional<double>(0.0));
    EXPECT_EQ(runs->newValue, 1.0);
    const auto* f0 = journalEntry(s, "axistune-notch.f0");
    const auto* q = journalEntry(s, "axistune-notch.Q");
    ASSERT_TRUE(f0 && q);
    EXPECT_FALSE(f0->oldValue);
    EXPECT_FALSE(q->oldValue);
    EXPECT_NEAR(f0->newValue, axistune::testing::getp("axistune-notch.f0"), 1e-4);
    EXPECT_NEAR(q->newValue, axistune::testing::getp("axistune-notch.Q"), 1e-6);
}

/// The notch removed: it runs no more (1 → 0); f0 and Q have no value after it, so they have no entry.
void expectNotchRemovedIn(const store::SessionRecord& s)
{
    const auto* runs = journalEntry(s, "axistune-notch");
    ASSERT_TRUE(runs);
    EXPECT_EQ(runs->oldValue, std::optional<double>(1.0));
    EXPECT_EQ(runs->newValue, 0.0);
    EXPECT_FALSE(journalEntry(s, "axistune-notch.f0"));
    EXPECT_FALSE(journalEntry(s, "axistune-notch.Q"));
}

// Issue 17 item 6: the velocity/position wizard on hal: goes from its first page to the NC PID page, which measures
// the open loop, proposes P, I, D, FF1, FF2 and a biquad notch with a rule for each, applies them live and verifies
// them: the measured margins meet the (PM ≥ 45°, GM ≥ 6 dB) within 3° / 1 dB of the prediction
// (expectVerifiedMargins, as pid-tune's CLI test), HAL holds the proposed gains (halcmd getp) and the notch within 2 %
// of the exact plant's resonance; the session holds the three loops and the result. After a later change of Pgain in
// HAL, Undo is refused with nothing written and Undo anyway (after its box is ticked) puts back the configuration's
// gains and removes the notch, leaving HAL's nets and functions as they were.
TEST_F(GuiOnHal, VelocityWizardTunesThePositionPidAndUndoes)
{
    gui::AppContext ctx;
    connectBed(ctx);
    if (HasFatalFailure())
        return;
    const double pBefore = axistune::testing::getp("pid.x.Pgain");
    const auto gainsBefore = halGains();
    gui::VelocityLoopWizard v(ctx);
    v.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&v));
    auto* source = v.sourcePage();
    ASSERT_TRUE(waitUntil([&] { return source->ncPid(); }, 30000));
    EXPECT_TRUE(source->ncPidNote().contains("pid.x")) << source->ncPidNote().toStdString();
    ASSERT_TRUE(source->isComplete());
    maybeScreenshot(&v, "velocity-hal-01-source");
    v.next();
    ASSERT_EQ(v.currentId(), int(gui::VelocityLoopWizard::NcPid));
    gui::NcPidPage& page = *v.ncPidPage();
    EXPECT_EQ(page.axis(), QStringLiteral("pid.x"));
    measureOn(page);
    if (HasFatalFailure())
        return;
    EXPECT_TRUE(page.proposal()->notch.has_value()) << page.proposal()->notchRule;
    EXPECT_EQ(page.proposal()->input, tuning::DriveInput::Torque);
    // Nothing was written by the measurement.
    EXPECT_DOUBLE_EQ(axistune::testing::getp("pid.x.Pgain"), pBefore);
    // The table shows every gain with its rule.
    for (int row = 0; row < 5; ++row)
        EXPECT_FALSE(page.table()->item(row, 4)->text().isEmpty()) << page.table()->item(row, 0)->text().toStdString();
    maybeScreenshot(&v, "velocity-hal-02-proposal");
    applyOn(page);
    if (HasFatalFailure())
        return;
    ASSERT_TRUE(page.applied()->applied) << page.applied()->refusal;
    autotune::PidTuneRequest asked; // the page's defaults: PM 50°, GM 8 dB
    asked.axis = "pid.x";
    const auto result = autotune::pidTuneJson(asked, *page.measurement(), *page.proposal(), page.applied());
    axistune::testing::expectVerifiedMargins(result);
    const auto& g = page.proposal()->gains;
    for (const auto& [k, x] :
         std::map<std::string, double>{{"Pgain", g.p}, {"Igain", g.i}, {"Dgain", g.d}, {"FF1", g.ff1}, {"FF2", g.ff2}})
        EXPECT_NEAR(axistune::testing::getp("pid.x." + k), x, 1e-6 * std::abs(x)) << k; // halcmd: 7 digits
    ASSERT_TRUE(page.proposal()->notch);
    EXPECT_NEAR(page.proposal()->notch->f0Hz / exactResonanceHz(), 1.0, 0.02);
    EXPECT_NEAR(axistune::testing::getp("axistune-notch.f0"), page.proposal()->notch->f0Hz, 1e-4);
    RecordProperty("verified_phase_margin_deg", model::formatShortest(page.applied()->measured.phaseMarginDeg));
    RecordProperty("verified_gain_margin_dB", model::formatShortest(page.applied()->measured.gainMarginDb));
    EXPECT_EQ(page.plot()->responseCount(), 3); // running, predicted, verified
    maybeScreenshot(&v, "velocity-hal-03-verified");
    // The session: the three loops and the result, the journal of the gains written.
    ASSERT_TRUE(waitUntil([&] { return page.savedSessionId() > 0 && page.pendingSaves() == 0; }, 30000));
    auto saved = ctx.database()->loadSession(page.savedSessionId());
    ASSERT_TRUE(saved.ok());
    EXPECT_EQ(saved->info.kind, "pid-tune");
    EXPECT_EQ(saved->captures.size(), 3u);
    // Measured and predicted loops name their quantity alike (the backends' "open-loop"; the page wrote "open_loop").
    for (const auto& c : saved->captures)
        EXPECT_EQ(c.capture.metadata.textOr("quantity", ""), "open-loop") << c.name;
    ASSERT_TRUE(saved->result("pid-tune"));
    EXPECT_TRUE(saved->result("pid-tune")->at("applied").get<bool>());
    // Its journal: each gain from the value before the tune to the one HAL holds now, then the notch inserted.
    EXPECT_EQ(saved->journal.size(), 8u);
    expectGainsJournaled(*saved, gainsBefore, halGains());
    expectNotchInsertedIn(*saved);
    const qint64 applySession = page.savedSessionId();

    // Someone changes Pgain in HAL after the apply: Undo is refused with nothing written (the later change named);
    // Undo anyway appears and stays disabled until its box is ticked (the second confirmation); then it puts back
    // the gains and removes the notch.
    axistune::testing::halText({"setp", "pid.x.Pgain", "0.3"});
    EXPECT_FALSE(page.undoAnywayButton()->isVisible());
    ASSERT_TRUE(page.undoButton()->isEnabled());
    page.undoButton()->click();
    ASSERT_TRUE(waitUntil([&] { return !page.busy(); }, 60000));
    EXPECT_FALSE(page.undone());
    EXPECT_TRUE(page.status()->text().contains(QStringLiteral("Pgain"))) << page.status()->text().toStdString();
    EXPECT_DOUBLE_EQ(axistune::testing::getp("pid.x.Pgain"), 0.3);
    EXPECT_NEAR(axistune::testing::getp("pid.x.Igain"), g.i, 1e-6 * std::abs(g.i)); // nothing written
    EXPECT_NEAR(axistune::testing::getp("axistune-notch.f0"), page.proposal()->notch->f0Hz, 1e-4);
    ASSERT_TRUE(page.undoAnywayButton()->isVisible());
    EXPECT_FALSE(page.undoAnywayButton()->isEnabled());
    maybeScreenshot(&v, "velocity-hal-04-undo-refused");
    page.overwriteBox()->setChecked(true);
    ASSERT_TRUE(page.undoAnywayButton()->isEnabled());
    const auto gainsHeld = halGains(); // Pgain 0.3, the later change
    page.undoAnywayButton()->click();
    ASSERT_TRUE(waitUntil([&] { return !page.busy(); }, 60000));
    ASSERT_TRUE(page.undone()) << page.status()->text().toStdString();
    EXPECT_DOUBLE_EQ(axistune::testing::getp("pid.x.Pgain"), pBefore);
    EXPECT_FALSE(page.undoAnywayButton()->isVisible());
    maybeScreenshot(&v, "velocity-hal-05-undone");
    // The undo's session: its journal starts from what HAL held just before it wrote (Pgain 0.3, not the value the
    // tune applied) and ends at what runs now (the gains before the tune), and the notch removed.
    ASSERT_TRUE(waitUntil([&] { return page.savedSessionId() > applySession && page.pendingSaves() == 0; }, 30000));
    auto undoneSession = ctx.database()->loadSession(page.savedSessionId());
    ASSERT_TRUE(undoneSession.ok());
    EXPECT_EQ(undoneSession->journal.size(), 6u);
    ASSERT_TRUE(journalEntry(*undoneSession, "Pgain"));
    EXPECT_NEAR(journalEntry(*undoneSession, "Pgain")->oldValue.value_or(NAN), 0.3, 1e-9);
    expectGainsJournaled(*undoneSession, gainsHeld, gainsBefore);
    expectNotchRemovedIn(*undoneSession);
    expectHalUnchanged();
}

// The NC PID page through linuxcnc: (the test machine's own INI; its axis X is pid.x): the velocity/position wizard
// names the axis by its letter, measures, proposes and applies gains and a notch through the INI's axis (HAL's
// pid.x holds the proposed gains, the notch runs after pid.x), the measured margins lie within 3° / 1 dB of the
// prediction, and Undo puts back the gains and removes the notch, leaving HAL as it was.
TEST_F(GuiOnHal, NcPidPageThroughLinuxCncTunesAxisXByItsLetter)
{
    gui::AppContext ctx;
    const QString ini =
        QString::fromStdString(std::string(AXISTUNE_SOURCE_DIR) + "/linuxcnc/testbed/axistune-testbed.ini");
    connectBed(ctx, QStringLiteral("linuxcnc:") + ini, QStringLiteral("X"));
    if (HasFatalFailure())
        return;
    const double pBefore = axistune::testing::getp("pid.x.Pgain");
    gui::VelocityLoopWizard v(ctx);
    v.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&v));
    ASSERT_TRUE(waitUntil([&] { return v.sourcePage()->ncPid(); }, 30000));
    v.next();
    ASSERT_EQ(v.currentId(), int(gui::VelocityLoopWizard::NcPid));
    gui::NcPidPage& page = *v.ncPidPage();
    EXPECT_EQ(page.axis(), QStringLiteral("X"));
    measureOn(page);
    if (HasFatalFailure())
        return;
    ASSERT_TRUE(page.proposal()->notch) << page.proposal()->notchRule;
    applyOn(page);
    if (HasFatalFailure())
        return;
    ASSERT_TRUE(page.applied()->applied) << page.applied()->refusal;
    const auto& p = *page.proposal();
    EXPECT_NEAR(page.applied()->measured.phaseMarginDeg, p.predicted.phaseMarginDeg, 3.0);
    EXPECT_NEAR(page.applied()->measured.gainMarginDb, p.predicted.gainMarginDb, 1.0);
    EXPECT_NEAR(axistune::testing::getp("pid.x.Pgain"), p.gains.p, 1e-6 * p.gains.p); // halcmd: 7 digits
    EXPECT_NEAR(axistune::testing::getp("pid.x.Dgain"), p.gains.d, 1e-6 * p.gains.d);
    EXPECT_NEAR(axistune::testing::getp("axistune-notch.f0"), p.notch->f0Hz, 1e-4);
    ASSERT_TRUE(page.undoButton()->isEnabled());
    page.undoButton()->click();
    ASSERT_TRUE(waitUntil([&] { return !page.busy(); }, 60000));
    ASSERT_TRUE(page.undone()) << page.status()->text().toStdString();
    EXPECT_DOUBLE_EQ(axistune::testing::getp("pid.x.Pgain"), pBefore);
    expectHalUnchanged();
}

// Issue 17 item 6: the notch wizard on hal: a new measurement goes to the NC PID page in its notch-only form: the
// running gains stay, a biquad at the plant's resonance (within 2 % of the exact one) raises the running loop's gain
// margin by at least the 1 dB its rule asks with the phase margin kept at the 50° asked, the measured margins after
// inserting it lie within 3° / 1 dB of the prediction, and removing it (Undo) leaves HAL's nets and functions as they
// were. First an Abort mid-measurement: nothing proposed, HAL as before, the session kept as aborted. In between, the
// wizard opened a second time over the inserted notch proposes nothing (no notch on top of the notch).
TEST_F(GuiOnHal, NotchWizardInsertsABiquadForTheRunningGains)
{
    gui::AppContext ctx;
    connectBed(ctx);
    if (HasFatalFailure())
        return;
    gui::NotchWizard n(ctx);
    n.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&n));
    ASSERT_EQ(n.currentId(), int(gui::NotchWizard::kSource));
    ASSERT_TRUE(waitUntil([&] { return !n.ncPidRefusal().isEmpty(); }, 30000));
    EXPECT_TRUE(n.sourcePage()->measureButton()->isChecked());
    maybeScreenshot(&n, "notch-hal-01-source");
    n.next();
    ASSERT_EQ(n.currentId(), int(gui::NotchWizard::kNcPid));
    gui::NcPidPage& page = *n.ncPidPage();
    // Abort during the measurement (12 s of motion): the excitation stops, what AxisTune inserted leaves HAL, nothing
    // is proposed, and the session is kept as aborted.
    page.confirmation()->setChecked(true);
    page.measureButton()->click();
    ASSERT_TRUE(page.busy());
    QTest::qWait(1500);
    ASSERT_TRUE(page.busy());
    page.abortButton()->click();
    ASSERT_TRUE(waitUntil([&] { return !page.busy(); }, 30000));
    EXPECT_FALSE(page.measurement());
    EXPECT_FALSE(page.proposal());
    EXPECT_FALSE(page.applyButton()->isEnabled());
    ASSERT_TRUE(waitUntil([&] { return page.savedSessionId() > 0 && page.pendingSaves() == 0; }, 30000));
    auto aborted = ctx.database()->loadSession(page.savedSessionId());
    ASSERT_TRUE(aborted.ok());
    EXPECT_EQ(aborted->info.status, store::SessionStatus::Aborted) << aborted->info.note;
    expectHalUnchanged();
    page.confirmation()->setChecked(false);
    measureOn(page);
    if (HasFatalFailure())
        return;
    const auto& p = *page.proposal();
    ASSERT_TRUE(p.notch) << p.notchRule;
    EXPECT_NEAR(p.notch->f0Hz / exactResonanceHz(), 1.0, 0.02);
    EXPECT_GE(p.predicted.gainMarginDb, p.runningMargins.gainMarginDb + 1.0);
    EXPECT_GE(p.predicted.phaseMarginDeg, std::min(50.0, p.runningMargins.phaseMarginDeg - 3.0)); // 50°: asked
    EXPECT_DOUBLE_EQ(p.gains.p, page.measurement()->running.p);
    maybeScreenshot(&n, "notch-hal-02-proposal");
    applyOn(page);
    if (HasFatalFailure())
        return;
    ASSERT_TRUE(page.applied()->applied) << page.applied()->refusal;
    EXPECT_TRUE(page.applied()->written.empty()); // no gain written
    EXPECT_DOUBLE_EQ(axistune::testing::getp("pid.x.Pgain"), page.measurement()->running.p);
    EXPECT_NEAR(axistune::testing::getp("axistune-notch.f0"), p.notch->f0Hz, 1e-4);
    EXPECT_NEAR(page.applied()->measured.phaseMarginDeg, p.predicted.phaseMarginDeg, 3.0);
    EXPECT_NEAR(page.applied()->measured.gainMarginDb, p.predicted.gainMarginDb, 1.0);
    RecordProperty("running_gain_margin_dB", model::formatShortest(p.runningMargins.gainMarginDb));
    RecordProperty("verified_gain_margin_dB", model::formatShortest(page.applied()->measured.gainMarginDb));
    maybeScreenshot(&n, "notch-hal-03-verified");
    // The apply's session: no gain written, the notch inserted.
    ASSERT_TRUE(waitUntil([&] { return page.pendingSaves() == 0; }, 30000));
    const qint64 applySession = page.savedSessionId();
    auto applied = ctx.database()->loadSession(applySession);
    ASSERT_TRUE(applied.ok());
    EXPECT_EQ(applied->journal.size(), 3u);
    expectNotchInsertedIn(*applied);
    {
        // The notch wizard opened again on the notched axis: the loop it measures runs through the notch, which the
        // page divides out of the plant; the running notch is then the best candidate, nothing beats it by the 1 dB
        // the rule asks, and nothing is proposed (no second notch on top of the first). HAL keeps the first notch.
        gui::NotchWizard again(ctx);
        again.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&again));
        ASSERT_TRUE(waitUntil([&] { return !again.ncPidRefusal().isEmpty(); }, 30000));
        again.next();
        ASSERT_EQ(again.currentId(), int(gui::NotchWizard::kNcPid));
        gui::NcPidPage& second = *again.ncPidPage();
        measureOn(second);
        if (HasFatalFailure())
            return;
        const auto& q = *second.proposal();
        ASSERT_TRUE(q.runningNotch);
        EXPECT_NEAR(q.runningNotch->f0Hz, p.notch->f0Hz, 1e-4 * p.notch->f0Hz); // as halcmd reads it back
        EXPECT_DOUBLE_EQ(q.runningNotch->q, p.notch->q);
        EXPECT_FALSE(q.changesSomething()) << q.notchRule;
        EXPECT_NE(q.notchRule.find("the running notch"), std::string::npos) << q.notchRule;
        EXPECT_FALSE(second.applyButton()->isEnabled());
        // The running column of the table shows the notch that runs.
        QTableWidget* t = second.table();
        int row = -1;
        for (int r = 0; r < t->rowCount(); ++r)
            if (t->item(r, 0) && t->item(r, 0)->text() == gui::NcPidPage::tr("Notch f0 [Hz]"))
                row = r;
        ASSERT_GE(row, 0);
        EXPECT_NEAR(t->item(row, 1)->text().toDouble(), p.notch->f0Hz, 0.01 * p.notch->f0Hz);
        EXPECT_NEAR(axistune::testing::getp("axistune-notch.f0"), p.notch->f0Hz, 1e-4);
        maybeScreenshot(&again, "notch-hal-04-again");
    }
    page.undoButton()->click();
    ASSERT_TRUE(waitUntil([&] { return !page.busy(); }, 60000));
    ASSERT_TRUE(page.undone()) << page.status()->text().toStdString();
    expectHalUnchanged();
    // The undo's session: the notch removed, nothing else.
    ASSERT_TRUE(waitUntil([&] { return page.savedSessionId() > applySession && page.pendingSaves() == 0; }, 30000));
    auto undone = ctx.database()->loadSession(page.savedSessionId());
    ASSERT_TRUE(undone.ok());
    EXPECT_EQ(undone->journal.size(), 1u);
    expectNotchRemovedIn(*undone);
}

} // namespace

int main(int argc, char** argv)
{
    // Offscreen unless a display is chosen (xvfb-run for screenshots).
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    axistune::testing::installLanguageFromEnv();
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}

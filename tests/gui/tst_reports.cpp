// SPDX-License-Identifier: GPL-3.0-or-later
// Reports, NC export dialog and history on a store built by the test (docs/reports.md):
// - a report of a session of every kind (frf with an analytic FRF stored through store::frfAsCapture,
//   lost-motion with a trace, results and arrays, an aborted session, the other wizard kinds and a CLI
//   session): the PDF starts with %PDF and holds one image XObject ("/Subtype /Image") per plot, the
//   HTML one <img> per plot, the rendered plots are not blank, an aborted report says so with its reason;
// - the NC export dialog writes byte for byte what core/io exportNc writes for the store's profile
//   (and, for the vmc sample, the committed tests/data/nc/vmc.<family>.expected files);
// - a real CLI session (axistune-cli ballbar --db) has a report and its circularity in the history;
// - the history shows one point per session for a resonance stored in three sessions, with the values.
#include "app/gui/AppContext.h"
#include "app/gui/HistoryView.h"
#include "app/gui/NcExportDialog.h"
#include "app/gui/Report.h"
#include "app/gui/ReportDialog.h"
#include "core/io/NcExport.h"
#include "core/io/Profile.h"
#include "core/store/FrfCapture.h"
#include "core/store/SessionRecord.h"
#include "widgets/CurvePlot.h"

#include <QFile>
#include <QFileInfo>
#include <QListWidget>
#include <QProcess>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QTextDocument>
#include <QtTest>

#include <cmath>
#include <complex>
#include <memory>
#include <numbers>
#include <nlohmann/json.hpp>

#include "tests/gui/GuiTestUtil.h"

using namespace axistune;

namespace {

/// Second-order resonance H(f) = wn² / (wn² − w² + j·2ζ·wn·w).
dsp::FrequencyResponse analyticFrf(double fnHz, double zeta)
{
    dsp::FrequencyResponse frf;
    for (int i = 0; i < 200; ++i) {
        const double f = 10.0 * std::pow(10.0, 2.5 * i / 199.0);
        const double w = 2.0 * std::numbers::pi * f, wn = 2.0 * std::numbers::pi * fnHz;
        frf.push(f, wn * wn / std::complex<double>(wn * wn - w * w, 2.0 * zeta * wn * w), std::nan(""), true);
    }
    frf.metadata.set("method", "analytic");
    return frf;
}

model::Capture circleTrace()
{
    model::Capture c;
    c.metadata.set("fs_Hz", 1000.0);
    model::Channel t{"t_s", {}}, x{"x_m", {}}, y{"y_m", {}};
    for (int i = 0; i < 1000; ++i) {
        t.data.push_back(i / 1000.0);
        x.data.push_back(0.05 * std::cos(2 * std::numbers::pi * i / 1000.0));
        y.data.push_back(0.05 * std::sin(2 * std::numbers::pi * i / 1000.0));
    }
    c.channels = {t, x, y};
    return c;
}

store::SessionRecord session(const std::string& machine, const std::string& axis, const std::string& kind)
{
    store::SessionRecord r;
    r.info.machine = machine;
    r.info.axis = axis;
    r.info.kind = kind;
    r.info.operatorName = "tester";
    r.machineAxes = {"X", "Y", "Z"};
    r.inputs = {{"axis", axis}, {"amplitude_Nm", 0.5}};
    return r;
}

int countOf(const QByteArray& hay, const QByteArray& needle)
{
    int n = 0;
    for (int p = hay.indexOf(needle); p >= 0; p = hay.indexOf(needle, p + 1))
        ++n;
    return n;
}

/// Fraction of pixels that are not (near) white: a rendered plot has axes, labels and curves (a blank
/// render has none; the thinnest report plot, one line, measured about 0.9 %).
double inkFraction(const QImage& im)
{
    int ink = 0;
    for (int y = 0; y < im.height(); y += 2)
        for (int x = 0; x < im.width(); x += 2)
            ink += qGray(im.pixel(x, y)) < 200 ? 1 : 0;
    return ink / double((im.width() / 2) * (im.height() / 2));
}

} // namespace

class TestReports : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    std::unique_ptr<gui::AppContext> m_ctx;
    std::int64_t m_frf = 0, m_lost = 0, m_aborted = 0, m_empty = 0;
    std::vector<std::int64_t> m_others;
    std::vector<std::int64_t> m_history;
    std::string m_vmc;
    QString m_lang;

    /// The report's text in the installed language.
    static QString rtr(const char* s) { return QCoreApplication::translate("SessionReport", s); }

    store::Database& db() { return *m_ctx->database(); }

private slots:
    void initTestCase()
    {
        m_lang = testing::installLanguageFromEnv();
        QVERIFY(m_dir.isValid());
        m_ctx = std::make_unique<gui::AppContext>();
        QVERIFY(m_ctx->openDatabase(m_dir.filePath("store.sqlite")));

        auto frf = session("mill", "X", "frf");
        frf.info.note = "table clamped, spindle at rest";
        frf.captures.push_back({"measured", store::frfAsCapture(analyticFrf(412.0, 0.05))});
        frf.captures.push_back({"predicted", store::frfAsCapture(analyticFrf(430.0, 0.08))});
        frf.results.push_back({"resonances", {{"resonances", {{{"frequency_Hz", 412.0}, {"peak_dB", 20.0}}}}}, {}});
        frf.results.push_back({"verification", {{"max_abs_deviation_dB", 0.8}}, {}});
        frf.parameterSets.push_back({0,
                                     "X",
                                     store::ParameterSource::Proposed,
                                     {},
                                     "notch wizard",
                                     {{"filter.notch1.center", 412.0}, {"filter.notch1.width", 80.0}}});
        frf.parameterSets.push_back({0,
                                     "X",
                                     store::ParameterSource::Applied,
                                     {},
                                     "notch wizard",
                                     {{"filter.notch1.center", 412.0}, {"filter.notch1.width", 80.0}}});
        frf.journal.push_back({0, {}, "X", "filter.notch1.center", 0.0, 412.0, {}, {}});
        m_frf = *db().recordSession(frf);

        auto lost = session("mill", "X", "lost-motion");
        lost.captures.push_back({"circle", circleTrace()});
        for (const char* name : {"trace-1", "verification"}) {
            model::Capture bb; // the lost-motion wizard's ball-bar layout
            bb.metadata = {{"content", "ballbar"}, {"radius_m", 0.05}};
            model::Channel a{"angle_rad", {}}, d{"deviation_m", {}};
            for (int i = 0; i < 720; ++i) {
                a.data.push_back(2 * std::numbers::pi * i / 720.0);
                d.data.push_back(3e-6 * std::cos(2 * a.data.back()) + (i % 180 == 0 ? 4e-6 : 0.0));
            }
            bb.channels = {a, d};
            lost.captures.push_back({name, bb});
        }
        lost.results.push_back({"fit", {{"A_m_per_Nm", 2.0e-6}, {"B_per_Nm", 3.0e-6}, {"method", "ols"}}, {}});
        lost.results.push_back({"prediction",
                                {{"measured_circularity_m", 6.0e-6}},
                                {{"angle_rad", {0.0, 1.0, 2.0, 3.0}}, {"measured_m", {1e-6, 2e-6, 1e-6, 0.0}}}});
        lost.results.push_back({"verification", {{"circularity_after_m", 2.5e-6}}, {}});
        lost.models.push_back({0, "X", "lost_motion", {}, {{"A_m_per_Nm", 2.0e-6}, {"B_per_Nm", 3.0e-6}}});
        m_lost = *db().recordSession(lost);

        auto aborted = session("mill", "X", "current-loop");
        aborted.info.status = store::SessionStatus::Aborted;
        aborted.info.note = "connection lost at 40 % of the step tests";
        m_aborted = *db().recordSession(aborted);

        for (const char* kind : {"notch", "velocity-loop", "two-inertia", "machining", "capture"}) {
            auto s = session("mill", "Y", kind);
            s.results.push_back({"design", {{"kp", 1.5}, {"list", {1, 2, 3}}}, {}});
            m_others.push_back(*db().recordSession(s));
        }
        m_empty = m_others.back();
    }

    void reportOfEachKindHasItsPlotsInThePdf()
    {
        struct Case {
            std::int64_t id;
            int plots; // Bode of both FRFs; ball-bar polar, time trace, prediction arrays; none
        };
        std::vector<Case> cases{{m_frf, 1}, {m_lost, 3}, {m_aborted, 0}};
        for (auto id : m_others)
            cases.push_back({id, 0});
        qint64 emptySize = 0, frfSize = 0;
        for (const auto& c : cases) {
            auto rec = db().loadSession(c.id);
            QVERIFY(rec.ok());
            const auto report = gui::SessionReport::build(*rec);
            QCOMPARE(report.images().size(), c.plots);
            for (const auto& im : report.images()) {
                QVERIFY(!im.image.isNull());
                if (qEnvironmentVariableIsSet("TST_REPORTS_KEEP"))
                    im.image.save(QStringLiteral("/tmp/tst_reports-%1-%2").arg(c.id).arg(im.name));
                QVERIFY2(inkFraction(im.image) > 0.003, qPrintable(im.title));
            }
            QCOMPARE(countOf(report.standaloneHtml().toUtf8(), "<img src=\"data:image/png;base64,"), c.plots);
            QVERIFY(report.html().contains(QString::fromStdString(rec->info.kind)));
            QVERIFY(report.html().contains("tester"));

            const QString pdf = m_dir.filePath(QStringLiteral("report%1.pdf").arg(c.id));
            QString error;
            QVERIFY2(report.savePdf(pdf, &error), qPrintable(error));
            QFile f(pdf);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QByteArray bytes = f.readAll();
            QVERIFY(bytes.startsWith("%PDF"));
            QCOMPARE(countOf(bytes, "/Subtype /Image"), c.plots);
            if (c.id == m_empty)
                emptySize = bytes.size();
            if (c.id == m_frf)
                frfSize = bytes.size();

            const QString html = m_dir.filePath(QStringLiteral("report%1.html").arg(c.id));
            QVERIFY2(report.saveHtml(html, &error), qPrintable(error));
            QVERIFY(QFileInfo(html).size() > 0);
        }
        QVERIFY(frfSize > emptySize + 10000); // the Bode image is in the file
    }

    void frfReportShowsParametersWithUnitsAndVerification()
    {
        auto rec = db().loadSession(m_frf);
        QVERIFY(rec.ok());
        std::unique_ptr<QTextDocument> doc(gui::SessionReport::build(*rec).createDocument());
        const QString text = doc->toPlainText();
        QVERIFY(text.contains("table clamped, spindle at rest")); // operator's note
        QVERIFY(text.contains("filter.notch1.center"));
        QVERIFY(text.contains("412 Hz")); // value with its unit from the metadata
        QVERIFY(text.contains(rtr("Proposed")) && text.contains(rtr("Applied")));
        QVERIFY(text.contains("max_abs_deviation_dB")); // verification section
        QVERIFY(!text.contains(rtr("ABORTED")));
    }

    void abortedReportSaysAbortedWithItsReason()
    {
        auto rec = db().loadSession(m_aborted);
        QVERIFY(rec.ok());
        const auto report = gui::SessionReport::build(*rec);
        std::unique_ptr<QTextDocument> doc(report.createDocument());
        const QString text = doc->toPlainText();
        const QString reason = "connection lost at 40 % of the step tests";
        if (m_lang == "en")
            QVERIFY(text.contains("This session was ABORTED. Reason: " + reason));
        QVERIFY(text.contains(rtr("This session was %1. Reason: %2").arg(rtr("ABORTED"), reason)));

        auto* dlg = gui::showSessionReport(*m_ctx, m_frf, nullptr);
        QVERIFY(dlg);
        QVERIFY(dlg->browser()->toPlainText().contains(rtr("Session %1: %2").arg(m_frf).arg("frf")));
        testing::maybeScreenshot(dlg, "report");
        dlg->close();
    }

    void ncExportDialogWritesWhatCoreWrites()
    {
        const QDir nc = QFileInfo(QString::fromStdString(io::defaultNcMapPath("fanuc"))).dir();
        auto sample = io::readProfileFile(nc.filePath("../samples/vmc-profile.json").toStdString());
        QVERIFY(sample.ok());
        QVERIFY(db().importProfile(*sample, "vmc-profile.json").ok());
        m_vmc = sample->name;
        auto profile = db().loadProfile(m_vmc);
        QVERIFY(profile.ok());

        gui::NcExportDialog dlg(*m_ctx);
        dlg.setMachine(QString::fromStdString(m_vmc));
        QVERIFY(gui::NcExportDialog::families().contains("fanuc"));
        for (const QString family : {"fanuc", "siemens", "heidenhain"}) {
            dlg.setFamily(family);
            const QString path = m_dir.filePath("vmc." + family);
            QString error;
            QVERIFY2(dlg.saveTo(path, &error), qPrintable(error));
            QFile f(path);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QByteArray written = f.readAll();

            auto map = io::readNcMapFile(io::defaultNcMapPath(family.toStdString()));
            QVERIFY(map.ok());
            auto direct = io::exportNc(*profile, *map);
            QVERIFY(direct.ok());
            QCOMPARE(written, QByteArray::fromStdString(direct->text));
            auto expected =
                io::readTextFile(std::string(AXISTUNE_TEST_DATA_DIR) + "/nc/vmc." + family.toStdString() + ".expected");
            QVERIFY(expected.ok());
            QCOMPARE(written, QByteArray::fromStdString(*expected));

            // The table lists each mapped parameter of every axis, the list the unmapped ones.
            int mapped = 0, unmapped = 0; // rows: one per map entry and axis; unmapped: per key and axis
            for (const auto& a : profile->axes)
                for (const auto& [key, v] : a.parameters) {
                    int n = 0;
                    for (const auto& e : map->entries)
                        n += e.key == key ? 1 : 0;
                    mapped += n;
                    unmapped += n == 0 ? 1 : 0;
                }
            QCOMPARE(dlg.table()->rowCount(), mapped);
            QCOMPARE(dlg.unmappedList()->count(), unmapped);
            for (const auto& key : direct->unmapped)
                QVERIFY(!dlg.unmappedList()->findItems(QString::fromStdString(key), Qt::MatchContains).isEmpty());
        }
        // FANUC: position.kp 30 1/s is written as 3000 (unit 0.01/s), tests/core/io/test_ncexport.cpp.
        dlg.setFamily("fanuc");
        bool found = false;
        for (int r = 0; r < dlg.table()->rowCount(); ++r)
            if (dlg.table()->item(r, gui::NcExportDialog::ColKey)->text() == "position.kp") {
                QCOMPARE(dlg.table()->item(r, gui::NcExportDialog::ColNumber)->text(), QString("01825"));
                QVERIFY(dlg.table()->item(r, gui::NcExportDialog::ColNcValue)->text().startsWith("3000 × 0.01 "));
                found = true;
            }
        QVERIFY(found);
        QString error;
        QVERIFY(!dlg.saveTo(m_dir.filePath("no-such-dir/file.txt"), &error));
        QVERIFY(!error.isEmpty());
        dlg.resize(1000, 700);
        testing::maybeScreenshot(&dlg, "nc-export");
    }

    void cliSessionReportAndHistory()
    {
        // A real CLI session: axistune-cli ballbar --db on the sample trace (machine vmc, no axis).
        QVERIFY(!m_vmc.empty());
        const QDir nc = QFileInfo(QString::fromStdString(io::defaultNcMapPath("fanuc"))).dir();
        QProcess cli;
        cli.start(AXISTUNE_CLI, {"ballbar", "--in", nc.filePath("../samples/ballbar-cw.csv"), "--db",
                                 QString::fromStdString(db().path()), "--machine", QString::fromStdString(m_vmc),
                                 "--operator", "cli-op"});
        QVERIFY(cli.waitForFinished(60000));
        QCOMPARE(cli.exitCode(), 0);
        const auto out = nlohmann::json::parse(cli.readAllStandardOutput().toStdString(), nullptr, false);
        QVERIFY(out.is_object() && out["circularity_um"].is_number());
        const double circUm = out["circularity_um"].get<double>();

        auto list = db().listSessions(m_vmc);
        QVERIFY(list.ok());
        std::int64_t id = 0;
        for (const auto& s : *list)
            if (s.kind == "ballbar")
                id = s.id;
        QVERIFY(id > 0);
        auto rec = db().loadSession(id);
        QVERIFY(rec.ok());
        const auto report = gui::SessionReport::build(*rec);
        QVERIFY(report.html().contains("cli-op"));
        QVERIFY(report.html().contains("circularity_um"));
        QString error;
        const QString pdf = m_dir.filePath("cli.pdf");
        QVERIFY2(report.savePdf(pdf, &error), qPrintable(error));
        QFile f(pdf);
        QVERIFY(f.open(QIODevice::ReadOnly) && f.read(4) == "%PDF");

        gui::HistoryView view(*m_ctx);
        view.setMachine(QString::fromStdString(m_vmc));
        view.setAxis(""); // sessions without an axis
        const auto& circ = view.data().of(gui::HistoryQuantity::Circularity);
        QCOMPARE(circ.size(), std::size_t(1));
        QCOMPARE(circ[0].points.size(), std::size_t(1));
        QCOMPARE(circ[0].points[0].sessionId, id);
        QVERIFY(std::abs(circ[0].points[0].value - circUm) <= 1e-9 * std::abs(circUm));
    }

    void historyShowsOnePointPerSession()
    {
        const double f[3] = {402.5, 398.0, 405.25};
        const double notch[3] = {400.0, 0.0, 404.0}; // second session: no applied notch
        for (int i = 0; i < 3; ++i) {
            auto s = session("lathe", "Z", i == 1 ? "notch" : "frf");
            s.info.started = QStringLiteral("2026-11-%1T08:00:00.000Z").arg(10 + 3 * i).toStdString();
            if (i == 1) // the notch wizard's layout: a bare array with f_Hz
                s.results.push_back({"resonances", {{{"f_Hz", f[i]}, {"peak_dB", 12.0}}}, {}});
            else
                s.results.push_back({"resonances", {{"resonances", {{{"frequency_Hz", f[i]}}}}}, {}});
            if (notch[i] > 0)
                s.parameterSets.push_back(
                    {0, "Z", store::ParameterSource::Applied, {}, "", {{"filter.notch1.center", notch[i]}}});
            m_history.push_back(*db().recordSession(s));
        }
        // Sessions lacking the fields, broken JSON shapes, another axis: skipped.
        auto odd = session("lathe", "Z", "frf");
        odd.results.push_back({"resonances", {{"resonances", "none"}}, {}});
        odd.results.push_back({"fit", {{"A_m_per_Nm", "x"}}, {}});
        QVERIFY(db().recordSession(odd).ok());
        auto other = session("lathe", "X", "frf");
        other.results.push_back({"resonances", {{"resonances", {{{"frequency_Hz", 900.0}}}}}, {}});
        QVERIFY(db().recordSession(other).ok());
        auto lm = session("lathe", "Z", "lost-motion");
        lm.results.push_back({"fit", {{"A_m_per_Nm", 2.0e-6}, {"B_per_Nm", 3.0e-6}}, {}});
        lm.results.push_back({"verification", {{"circularity_before_m", 6.0e-6}, {"circularity_after_m", 2.5e-6}}, {}});
        const auto lmId = *db().recordSession(lm);

        gui::HistoryView view(*m_ctx);
        view.setMachine("lathe");
        view.setAxis("Z");
        const auto& res = view.data().of(gui::HistoryQuantity::Resonance);
        QCOMPARE(res.size(), std::size_t(1));
        QCOMPARE(res[0].points.size(), std::size_t(3));
        for (int i = 0; i < 3; ++i) {
            QCOMPARE(res[0].points[i].sessionId, m_history[i]);
            QCOMPARE(res[0].points[i].value, f[i]);
            QVERIFY(std::abs(res[0].points[i].days - 3.0 * i) < 1e-9);
        }
        QCOMPARE(view.plot(gui::HistoryQuantity::Resonance)->curveCount(), 1);
        const auto& notches = view.data().of(gui::HistoryQuantity::Notch);
        QCOMPARE(notches.size(), std::size_t(1));
        QCOMPARE(notches[0].points.size(), std::size_t(2));
        QCOMPARE(notches[0].points[1].value, 404.0);
        const auto& a = view.data().of(gui::HistoryQuantity::LostMotionA);
        QCOMPARE(a.size(), std::size_t(1));
        QCOMPARE(a[0].points.size(), std::size_t(1));
        QCOMPARE(a[0].points[0].sessionId, lmId);
        QVERIFY(std::abs(a[0].points[0].value - 2.0) < 1e-12); // µm/(N·m)
        const auto& circ = view.data().of(gui::HistoryQuantity::Circularity);
        QCOMPARE(circ.size(), std::size_t(2));
        for (const auto& s : circ) {
            QCOMPARE(s.points.size(), std::size_t(1));
            QVERIFY(std::abs(s.points[0].value - 6.0) < 1e-9 || std::abs(s.points[0].value - 2.5) < 1e-9); // µm
        }
        view.setTimeAxis(true);
        view.resize(1000, 700);
        testing::maybeScreenshot(&view, "history");
    }
};

QTEST_MAIN(TestReports)
#include "tst_reports.moc"

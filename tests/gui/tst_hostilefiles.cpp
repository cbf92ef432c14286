// SPDX-License-Identifier: GPL-3.0-or-later
// The GUI survives the hostile files of issue 21 (docs/robustness.md): every file-loading path of the
// app — the identification dialog (capture CSV, controller JSON), the lost-motion wizard (ball-bar CSV),
// the machining wizard (tool JSON, tool-tip FRF CSV fit, cut JSON, stage JSON with a captured cut, the
// chatter capture of the advice page) and the tap test (impact records) — is fed the committed fuzz
// regression inputs of its format (tests/data/fuzz/<target>/), a FIFO without a writer, /dev/zero, a
// directory, a missing file and a file whose name is not UTF-8. Each is refused with the reason shown in
// the page's error text naming the file (no message box: nothing blocks), or, where the format's reader
// accepts the file, loaded; nothing crashes or hangs (a FIFO opened for reading would block for ever and
// the test would time out). Afterwards the same pages load the valid samples: the app stays usable.
#include "app/gui/AppContext.h"
#include "app/gui/IdentifyDialog.h"
#include "app/gui/LostMotionWizard.h"
#include "app/gui/MachiningTapPage.h"
#include "app/gui/MachiningWizard.h"

#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <sys/stat.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "tests/app/cli/CliRunner.h"
#include "tests/gui/GuiTestUtil.h"

using namespace axistune;
using axistune::gui::AppContext;

namespace {

const QString kData = QStringLiteral(AXISTUNE_TEST_DATA_DIR);
const QString kSamples = QStringLiteral(AXISTUNE_TEST_DATA_DIR) + "/../../resources/samples/";

/// The committed regression inputs of a fuzz target (never empty: the test fails if the folder is).
QStringList fuzzInputs(const QString& target)
{
    QStringList out;
    for (const auto& f : QDir(kData + "/fuzz/" + target).entryInfoList(QDir::Files))
        out << f.absoluteFilePath();
    return out;
}

/// Files no reader may open as data: a FIFO without a writer, /dev/zero, a directory, a missing file,
/// a file named with a byte that is not UTF-8 (content valid for nothing: one line).
struct SpecialFiles {
    QTemporaryDir dir;
    QStringList paths;
    QByteArray raw; ///< the name that is not UTF-8, as bytes
    SpecialFiles(const QString& ext)
    {
        const QString fifo = dir.filePath("fifo" + ext);
        if (mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0)
            paths << fifo;
        paths << "/dev/zero";
        QDir(dir.path()).mkdir("folder" + ext);
        paths << dir.filePath("folder" + ext);
        paths << dir.filePath("missing" + ext);
        raw = QFile::encodeName(dir.path()) + "/name-\xff\xfe" + ext.toUtf8();
        if (FILE* f = std::fopen(raw.constData(), "w")) {
            std::fputs("x\n", f);
            std::fclose(f);
        }
        paths << QFile::decodeName(raw);
    }
    // QTemporaryDir removes by decoded names and cannot name this file: it goes first, so the folder goes too.
    ~SpecialFiles() { ::unlink(raw.constData()); }
};

/// The shown text names the file (its name; for a directory or /dev/zero the path).
bool namesFile(const QString& text, const QString& path)
{
    return text.contains(QFileInfo(path).fileName()) || text.contains(path);
}

} // namespace

class TstHostileFiles : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        testing::installLanguageFromEnv();
        for (const char* t : {"capture_csv", "ballbar_csv", "frf_csv", "tool_json", "cut_json", "stage_json"})
            QVERIFY2(!fuzzInputs(t).isEmpty(), t);
    }

    void identifyDialog()
    {
        gui::IdentifyDialog d;
        d.show();
        SpecialFiles special(".csv");
        for (const auto& p : special.paths) {
            QVERIFY2(!d.loadEstimation(p), qPrintable(p));
            QVERIFY2(namesFile(d.statusText(), p), qPrintable(p + " → " + d.statusText()));
            QVERIFY2(!d.loadController(p), qPrintable(p));
            QVERIFY2(namesFile(d.statusText(), p), qPrintable(p + " → " + d.statusText()));
        }
        for (const auto& p : fuzzInputs("capture_csv")) {
            if (!d.loadEstimation(p))
                QVERIFY2(namesFile(d.statusText(), p), qPrintable(p + " → " + d.statusText()));
        }
        for (const auto& p : fuzzInputs("profile_json") + fuzzInputs("tool_json")) {
            QVERIFY2(!d.loadController(p), qPrintable(p));
            QVERIFY2(namesFile(d.statusText(), p), qPrintable(p + " → " + d.statusText()));
        }
        // Still usable: the sample record and controller load.
        QVERIFY2(d.loadEstimation(kSamples + "capture-step-vmc-x.csv"), qPrintable(d.statusText()));
        QVERIFY2(d.loadController(kSamples + "identify-controller-emps.json"), qPrintable(d.statusText()));
    }

    void lostMotionBallBar()
    {
        AppContext ctx;
        gui::LostMotionWizard w(ctx);
        w.show();
        const auto* label = w.findChild<QLabel*>("lmFileErrors");
        QVERIFY(label);
        SpecialFiles special(".csv");
        for (const auto& p : special.paths + fuzzInputs("ballbar_csv")) {
            QVERIFY2(!w.sourcePage()->addFiles({p}), qPrintable(p));
            QVERIFY2(namesFile(label->text(), p), qPrintable(p + " → " + label->text()));
        }
        QVERIFY(!w.sourcePage()->isComplete());
        QVERIFY2(w.sourcePage()->addFiles({kSamples + "ballbar-ccw.csv"}), qPrintable(label->text()));
    }

    void machiningToolCutStageAndCaptures()
    {
        AppContext ctx;
        gui::MachiningWizard w(ctx);
        w.resize(1000, 700);
        w.show();
        auto* tool = w.toolPage();
        auto* cut = w.cutPage();
        SpecialFiles json(".json"), csv(".csv");

        for (const auto& p : json.paths + fuzzInputs("tool_json")) {
            QVERIFY2(!tool->loadToolFile(p), qPrintable(p));
            QVERIFY2(namesFile(tool->errorLabel()->text(), p), qPrintable(p + " → " + tool->errorLabel()->text()));
        }
        for (const auto& p : csv.paths + fuzzInputs("frf_csv")) {
            QVERIFY2(!tool->fitToolFrfs(p, kSamples + "frf-two-inertia.csv"), qPrintable(p));
            QVERIFY2(namesFile(tool->errorLabel()->text(), p), qPrintable(p + " → " + tool->errorLabel()->text()));
        }
        testing::maybeScreenshot(tool, "hostile-tool-error");
        QVERIFY2(tool->loadToolFile(kSamples + "tool-table1.json"), qPrintable(tool->errorLabel()->text()));

        for (const auto& p : json.paths + fuzzInputs("cut_json")) {
            QVERIFY2(!cut->loadCutFile(p), qPrintable(p));
            QVERIFY2(namesFile(cut->errorLabel()->text(), p), qPrintable(p + " → " + cut->errorLabel()->text()));
        }
        QVERIFY2(cut->loadCutFile(kSamples + "cut-table1.json"), qPrintable(cut->errorLabel()->text()));

        auto* advice = w.advicePage();
        auto* estimate = advice->findChild<QLabel*>("machEstimateText");
        QVERIFY(estimate);
        for (const auto& p : csv.paths + fuzzInputs("capture_csv")) {
            if (!advice->estimateFromCapture(p))
                QVERIFY2(namesFile(estimate->text(), p), qPrintable(p + " → " + estimate->text()));
        }

        auto* analysis = w.analysisPage();
        auto finished = [analysis] { return testing::waitUntil([analysis] { return !analysis->busy(); }, 60000); };
        for (const auto& p : csv.paths + fuzzInputs("capture_csv")) {
            analysis->stagePath()->clear();
            analysis->loadCapture(p);
            QVERIFY(finished());
            if (!analysis->analysed())
                QVERIFY2(namesFile(analysis->summary()->text(), p),
                         qPrintable(p + " → " + analysis->summary()->text()));
        }
        for (const auto& p : json.paths + fuzzInputs("stage_json")) {
            analysis->stagePath()->setText(p);
            analysis->loadCapture(kSamples + "capture-step-vmc-x.csv");
            QVERIFY(finished());
            QVERIFY2(!analysis->analysed(), qPrintable(p));
            QVERIFY2(namesFile(analysis->summary()->text(), p), qPrintable(p + " → " + analysis->summary()->text()));
        }
        // Still usable: a cut simulated by the CLI (as tst_machiningwizard does) is analysed with the sample stage.
        const QString cutCsv = csv.dir.filePath("stable.csv");
        const auto r = testing::runCli("simulate-cut --machine vmc --axis X --tool " + kSamples.toStdString() +
                                       "tool-table1.json --cut " + kSamples.toStdString() +
                                       "cut-table1.json --rpm 1500 --depth-m 0.5e-3 --duration-s 1.2 --seed 3 --out " +
                                       cutCsv.toStdString());
        QVERIFY2(r.exitCode == 0, r.err.c_str());
        analysis->stagePath()->setText(kSamples + "stage.json");
        analysis->loadCapture(cutCsv);
        QVERIFY(finished());
        QVERIFY2(analysis->analysed(), qPrintable(analysis->summary()->text()));

        auto* tap = w.tapPage();
        for (const auto& p : csv.paths + fuzzInputs("capture_csv")) {
            if (!tap->addRecord(p))
                QVERIFY2(namesFile(tap->errorLabel()->text(), p), qPrintable(p + " → " + tap->errorLabel()->text()));
            tap->records()->clear();
        }
        QVERIFY2(tap->addRecord(QStringLiteral(AXISTUNE_REAL_DATA_DIR) + "/impact_test_raw_time.csv"),
                 qPrintable(tap->errorLabel()->text()));
    }
};

QTEST_MAIN(TstHostileFiles)
#include "tst_hostilefiles.moc"

// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli profile / import / export / session end to end against a temporary store.
#include "core/io/CaptureCsv.h"
#include "core/store/Database.h"
#include "core/store/SessionRecord.h"
#include "tests/app/cli/CliRunner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace axistune;
using axistune::testing::makeTempDir;
using axistune::testing::readFileText;
using axistune::testing::runCli;

namespace {

const std::string kSample = std::string(AXISTUNE_SOURCE_RESOURCE_DIR) + "/samples/vmc-profile.json";
const std::string kData = std::string(AXISTUNE_TEST_DATA_DIR) + "/nc/";

}  // namespace

TEST(CliStore, ProfileImportExportImportExportIsIdentical)
{
    const auto dir = makeTempDir("store-profile");
    const auto db1 = (dir / "a.db").string();
    const auto db2 = (dir / "b.db").string();
    auto r = runCli("profile import --db " + db1 + " --in " + kSample);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["machine"], "vmc");
    r = runCli("profile export --db " + db1 + " --machine vmc --out " + (dir / "1.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runCli("profile import --db " + db2 + " --in " + (dir / "1.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runCli("profile export --db " + db2 + " --machine vmc");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, readFileText(dir / "1.json"));
    EXPECT_EQ(r.out, readFileText(kSample));
}

TEST(CliStore, ExportEveryFormatMatchesCommittedFiles)
{
    const auto dir = makeTempDir("store-export");
    const auto db = (dir / "s.db").string();
    ASSERT_EQ(runCli("profile import --db " + db + " --in " + kSample).exitCode, 0);
    for (const std::string f : {"fanuc", "siemens", "heidenhain", "json", "csv"}) {
        const auto out = (dir / ("vmc." + f)).string();
        auto r = runCli("export --db " + db + " --machine vmc --format " + f + " --out " + out);
        ASSERT_EQ(r.exitCode, 0) << f << ": " << r.err;
        EXPECT_EQ(readFileText(out), readFileText(kData + "vmc." + f + ".expected")) << f;
        if (f == "fanuc" || f == "siemens" || f == "heidenhain") {
            EXPECT_NE(r.err.find("have no " + f + " mapping and are NOT in the file"), std::string::npos) << r.err;
            EXPECT_NE(r.err.find("current.dead_time"), std::string::npos) << r.err;
            EXPECT_FALSE(nlohmann::json::parse(r.out)["unmapped"].empty());
        }
    }
}

TEST(CliStore, JsonAndCsvRoundTripThroughImport)
{
    const auto dir = makeTempDir("store-roundtrip");
    const auto db = (dir / "s.db").string();
    ASSERT_EQ(runCli("profile import --db " + db + " --in " + kSample).exitCode, 0);
    for (const std::string f : {"json", "csv"}) {
        const auto first = (dir / ("first." + f)).string();
        ASSERT_EQ(runCli("export --db " + db + " --machine vmc --format " + f + " --out " + first).exitCode, 0);
        const auto db2 = (dir / (f + ".db")).string();
        auto r = runCli("import --db " + db2 + " --in " + first);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(nlohmann::json::parse(r.out)["parameters"], 3 * 32) << f;  // the sample has 32 keys per axis
        r = runCli("export --db " + db2 + " --machine vmc --format " + f);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.out, readFileText(first)) << f;
    }
}

TEST(CliStore, SessionListShowExport)
{
    const auto dir = makeTempDir("store-session");
    const auto db = (dir / "s.db").string();
    {
        auto d = store::Database::open(db);
        ASSERT_TRUE(d.ok()) << d.error().detail;
        store::SessionRecord r;
        r.info.machine = "vmc";
        r.info.axis = "X";
        r.info.kind = "frf";
        r.info.status = store::SessionStatus::Aborted;
        r.inputs = {{"amplitude_Nm", 2.0}};
        model::Capture c;
        c.metadata.set("fs_Hz", 4000.0);
        c.channels = {{"t_s", {0.0, 0.00025, 0.0005}}, {"torque_cmd_Nm", {0.5, -0.25, 1e-9}}};
        r.captures.push_back({"sweep 1", c});
        r.results.push_back({"frf", {{"resonance_Hz", 812.5}}, {{"f_Hz", {10.0, 20.0}}, {"mag_dB", {-3.0, -6.0}}}});
        r.results.push_back({"uneven", {}, {{"a", {1.0}}, {"b", {1.0, 2.0}}}});
        ASSERT_TRUE(d.value().recordSession(r).ok());
    }
    auto r = runCli("session list --db " + db);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto list = nlohmann::json::parse(r.out);
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(list[0]["kind"], "frf");
    EXPECT_EQ(list[0]["status"], "aborted");
    EXPECT_EQ(list[0]["captures"], 1);
    const std::string id = std::to_string(list[0]["id"].get<int>());

    r = runCli("session show --db " + db + " --id " + id);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto show = nlohmann::json::parse(r.out);
    EXPECT_EQ(show["captures"][0]["samples"], 3);
    EXPECT_EQ(show["results"][0]["data"]["resonance_Hz"], 812.5);

    const auto folder = dir / "export";
    r = runCli("session export --db " + db + " --id " + id + " --out " + folder.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto manifest = nlohmann::json::parse(readFileText(folder / "manifest.json"));
    EXPECT_EQ(manifest["format"], "axistune-session-export-1");
    EXPECT_EQ(manifest["inputs"]["amplitude_Nm"], 2.0);
    const std::string capFile = manifest["captures"][0]["file"];
    EXPECT_EQ(capFile, "capture_1_sweep_1.csv");
    auto cap = io::readCaptureCsvFile((folder / capFile).string());
    ASSERT_TRUE(cap.ok()) << cap.error().detail;
    EXPECT_EQ(cap->metadata.number("fs_Hz").value(), 4000.0);
    EXPECT_EQ(cap->channel("torque_cmd_Nm")->data, (std::vector<double>{0.5, -0.25, 1e-9}));
    EXPECT_EQ(manifest["results"][0]["files"][0], "result_1_frf.csv");
    auto res = io::readCaptureCsvFile((folder / "result_1_frf.csv").string());
    ASSERT_TRUE(res.ok()) << res.error().detail;
    EXPECT_EQ(res->channel("mag_dB")->data, (std::vector<double>{-3.0, -6.0}));
    EXPECT_EQ(manifest["results"][1]["files"].size(), 2u);  // arrays of different lengths: one file each
}

TEST(CliStore, BadFilesGiveClearErrors)
{
    const auto dir = makeTempDir("store-bad");
    const auto text = (dir / "notes.txt").string();
    std::ofstream(text) << "this is not a database\n";
    auto r = runCli("session list --db " + text);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find(text + ": not an AxisTune store"), std::string::npos) << r.err;

    r = runCli("session list --db " + (dir / "missing.db").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("no such store"), std::string::npos) << r.err;

    const auto db = (dir / "s.db").string();
    ASSERT_EQ(runCli("profile import --db " + db + " --in " + kSample).exitCode, 0);
    r = runCli("export --db " + db + " --machine lathe --format fanuc");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("no machine 'lathe'"), std::string::npos) << r.err;
    r = runCli("export --db " + db + " --machine vmc --format mazak");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("nc/mazak.json: cannot open (no such file)"), std::string::npos) << r.err;

    const auto badCsv = (dir / "p.csv").string();
    std::ofstream(badCsv) << "# format=axistune-parameters\nmachine,axis,key,value\nvmc,X,velocity.kp,fast\n";
    r = runCli("import --db " + db + " --in " + badCsv);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find(badCsv + " line 3, column 'value'"), std::string::npos) << r.err;
}

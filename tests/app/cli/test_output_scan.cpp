// SPDX-License-Identifier: GPL-3.0-or-later
// No result file or JSON holds NaN, Inf or null where a number belongs (docs/formats.md "Undefined
// values", docs/robustness.md). CliOutputScan.AllCommandsOnSampleInputs runs every command of
// axistune-cli on the sample inputs (resources/samples, tests/data), including cases with values that
// are not defined (a partial ball-bar arc, a sweep without coherence, margins without a phase crossover,
// a recorded session with a first parameter write), and scans its stdout and every JSON/CSV file it wrote
// (OutputScan.h). The other tests check that the scan finds what it must.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/app/cli/CliRunner.h"
#include "tests/app/cli/OutputScan.h"

using namespace axistune::testing;

namespace {

const std::string kSamples = std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/samples/";
const std::string kData = std::string(AXISTUNE_TEST_DATA_DIR) + "/";
const std::string kReal = AXISTUNE_REAL_DATA_DIR;

} // namespace

TEST(CliOutputScan, FindsNullNanAndInf)
{
    EXPECT_TRUE(scanOutputText(R"({"a": 1.5, "b": [1, 2], "undefined": {"c": "null reason"}})", "o").empty());
    const auto n = scanOutputText(R"({"a": {"b": [1, null]}})", "o");
    ASSERT_EQ(n.size(), 1u);
    EXPECT_EQ(n[0], "o: null at /a/b/1");
    EXPECT_EQ(scanOutputText(R"({"a": NaN})", "o").size(), 1u);
    EXPECT_EQ(scanOutputText("[1, -Infinity]", "o").size(), 1u);
    EXPECT_TRUE(scanOutputText("# note=inf nan null\nf_Hz,re\n1,2.5e-3\n2,\"nan text\"\n", "o").empty());
    const auto c = scanOutputText("f_Hz,re,im\n1,2,3\n2,nan,-inf\n3,4,INF\n", "c.csv");
    ASSERT_EQ(c.size(), 3u);
    EXPECT_EQ(c[0], "c.csv line 3: 'nan'");
    EXPECT_EQ(c[1], "c.csv line 3: '-inf'");
    EXPECT_EQ(c[2], "c.csv line 4: 'INF'");
    EXPECT_TRUE(scanOutputText("value 12.5 Hz, information: infinite loop avoided\n", "t").empty());
}

TEST(CliOutputScan, ScansTheOutputFilesAndFolders)
{
    const auto dir = makeTempDir("scan");
    std::ofstream(dir / "r.json") << R"({"x": null})";
    std::filesystem::create_directories(dir / "folder" / "sub");
    std::ofstream(dir / "folder" / "sub" / "t.csv") << "a,b\n1,nan\n";
    std::ofstream(dir / "folder" / "notes.txt") << "nan\n"; // neither JSON nor CSV: not scanned
    const auto bad = scanCliOutputs("frf --in x.csv --out " + (dir / "r.json").string() +
                                        " --measured-out=" + (dir / "folder").string() + " --fs 1000",
                                    "{\"ok\": 1}\n");
    ASSERT_EQ(bad.size(), 2u);
    EXPECT_EQ(bad[0], (dir / "r.json").string() + ": null at /x");
    EXPECT_EQ(bad[1], (dir / "folder" / "sub" / "t.csv").string() + " line 2: 'nan'");
    std::filesystem::remove_all(dir);
}

TEST(CliOutputScan, AllCommandsOnSampleInputs)
{
    const auto dir = makeTempDir("allcmds");
    const auto d = [&dir](const std::string& name) { return (dir / name).string(); };
    const std::string db = d("s.db");
    const std::vector<std::string> commands{
        "profile import --db " + db + " --in " + kSamples + "vmc-profile.json",
        "profile export --db " + db + " --machine vmc --out " + d("profile.json"),
        "import --db " + db + " --in " + kSamples + "vmc-profile.json",
        "export --db " + db + " --machine vmc --format json --out " + d("export.json"),
        "export --db " + db + " --machine vmc --format csv --out " + d("export.csv"),
        "params --connect sim:vmc --axis X --get velocity.kp",
        "capture --connect sim:vmc --axis X --test step --amplitude 5 --duration 0.1 --out " + d("cap.csv") + " --db " +
            db + " --machine vmc",
        "frf --in " + kData + "welch/input.csv --input x --output y --nperseg 500 --noverlap 100",
        "frf --sweep " + kSamples + "sweep-dd-table.csv --out " + d("frf.csv"),
        "frf --sweep " + kSamples + "sweep-dd-table.csv", // JSON arrays: no coherence from a sweep
        "frf --sweep " + kSamples + "sweep-dd-table.csv --margins complementary --out " + d("frf2.csv"),
        "import-frf --in " + kSamples + "uff58-frf.unv --record 1 --out " + d("uff.csv"),
        "notch --frf " + kSamples + "frf-two-inertia.csv --out-frf " + d("pred.csv") + " --db " + db + " --machine vmc",
        // The sample is the drive's closed velocity loop of sim:two-inertia (docs/tuning.md "Measured").
        "two-inertia --frf " + kSamples +
            "frf-two-inertia.csv --fmin 5 --fmax 300 --loop-pi 11.24,1198 --loop-period-s 250e-6 --out " + d("ti.json"),
        "current-loop --motor " + kSamples + "motor-rotary.json --plots --out " + d("cl.json") + " --db " + db +
            " --machine vmc",
        "circle --connect sim:vmc --radius-mm 50 --feed-mm-min 1000 --direction ccw --out " + d("circle.csv"),
        "ballbar --in " + kSamples + "ballbar-ccw.csv --in " + kSamples + "ballbar-cw.csv --out " + d("bb.json"),
        "ballbar --in " + kData + "ballbar/partial.csv", // refused diagnostics: named in "undefined"
        "lost-motion --ballbar " + kData + "ballbar/lm_y_c200.csv " + kData + "ballbar/lm_y_c400.csv " + kData +
            "ballbar/lm_y_c600.csv --axis y --screw-offset-m 0.05 --out " + d("lm.json"),
        "lost-motion --ballbar " + kData + "ballbar/lm_y_c400.csv --axis x --b-free --compensated-out " + d("comp.csv"),
        "reversal-comp --connect sim:vmc --radius-mm 50 --feed-mm-min 1000 --dry-run --out " + d("rc.json"),
        "identify --in " + kReal +
            "/emps_DATA_EMPS.csv --position q_motor --position-unit m --force u_voltage "
            "--force-scale 35.15065188 --out " +
            d("id.json"),
        "lobes --tool " + kSamples + "tool-table1.json --cut " + kSamples +
            "cut-table1.json --rpm-min 2800 --rpm-max 2955 --rpm-step 155 --steps-per-period 80 --out " +
            d("lobes.csv"),
        "spindle-speed --chatter-hz 1390 --rpm 2800 --teeth 4",
        "simulate-cut --machine vmc --axis X --tool " + kSamples + "tool-table1.json --cut " + kSamples +
            "cut-table1.json --rpm 1500 --depth-m 1e-3 --out " + d("cut.csv"),
        "cutting-force --in " + d("cut.csv") + " --stage " + kSamples + "stage.json --out " + d("force.csv"),
        "chatter-detect --in " + d("cut.csv") + " --stage " + kSamples + "stage.json --out " + d("chatter.csv"),
        "session list --db " + db,
        "session show --db " + db + " --id 1",
        "session export --db " + db + " --id 1 --out " + d("session1"),
    };
    int scanned = 0;
    for (const auto& c : commands) {
        const auto r = runCli(c);
        EXPECT_EQ(r.exitCode, 0) << "axistune-cli " << c << "\n" << r.err;
        if (r.exitCode != 0)
            continue;
        for (const auto& bad : scanCliOutputs(c, r.out))
            ADD_FAILURE() << "axistune-cli " << c << "\n  NaN, Inf or null in the output: " << bad;
        ++scanned;
    }
    EXPECT_EQ(scanned, static_cast<int>(commands.size()));
    std::filesystem::remove_all(dir);
}

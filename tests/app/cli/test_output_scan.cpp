// SPDX-License-Identifier: GPL-3.0-or-later
// The scan that runCli applies to every successful CLI run (OutputScan.h) finds what it must: null in
// JSON, NaN/Inf text in JSON-looking and CSV output, output files named after --out-like options and
// files inside an output folder; and it leaves numbers, metadata lines and quoted text alone.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

#include "tests/app/cli/CliRunner.h"
#include "tests/app/cli/OutputScan.h"

using namespace axistune::testing;

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

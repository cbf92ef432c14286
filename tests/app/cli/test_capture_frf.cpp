// SPDX-License-Identifier: GPL-3.0-or-later
// End to end: axistune-cli capture --test frf writes an FRF CSV (and the sine-stream CSV that
// `frf --sweep` turns into the same FRF); bad options give exit code 2 with a message.
#include "core/io/FrfCsv.h"
#include "core/io/SweepCsv.h"
#include "tests/app/cli/CliRunner.h"

#include <gtest/gtest.h>

#include <fstream>

using axistune::testing::makeTempDir;
using axistune::testing::runCli;

TEST(CliCaptureFrf, MultiSweepOnTwoInertiaWritesFrfAndSweep)
{
    const auto dir = makeTempDir("capture_frf");
    const auto out = (dir / "frf.csv").string(), sweep = (dir / "sweep.csv").string(), again = (dir / "again.csv").string();
    auto r = runCli("capture --connect sim:two-inertia --axis A --test frf --method multisweep --fmin 5 --fmax 300 --points 8 "
                    "--amplitude-pct 5 --out " + out + " --sweep-out " + sweep);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\"motion_time_s\""), std::string::npos);
    std::ifstream in(out);
    std::string line;
    while (std::getline(in, line) && line.rfind("#", 0) == 0) {}
    EXPECT_EQ(line, "f_Hz,re,im,mag_dB,phase_deg,coherence,valid");
    auto frf = axistune::io::readFrfCsvFile(out);
    ASSERT_TRUE(frf.ok()) << frf.error().detail;
    ASSERT_EQ(frf->size(), 8u);
    EXPECT_EQ(frf->metadata.text("method"), "multisweep");
    EXPECT_EQ(frf->metadata.text("measurement"), "complementary");
    for (std::size_t i = 0; i < frf->size(); ++i)
        EXPECT_TRUE(frf->valid[i]);
    // Low frequency: the integral action gives T ≈ 1 (0 dB within 1 dB at 5 Hz).
    EXPECT_NEAR(std::abs(frf->h.front()), 1.0, 0.13);
    auto rec = axistune::io::readSweepCsvFile(sweep);
    ASSERT_TRUE(rec.ok()) << rec.error().detail;
    EXPECT_EQ(rec->blocks.size(), 24u);  // three phase offsets per frequency
    // The sweep CSV re-analysed by `frf --sweep` gives the same FRF.
    r = runCli("frf --sweep " + sweep + " --out " + again);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto frf2 = axistune::io::readFrfCsvFile(again);
    ASSERT_TRUE(frf2.ok());
    ASSERT_EQ(frf2->size(), frf->size());
    for (std::size_t i = 0; i < frf->size(); ++i)
        EXPECT_NEAR(std::abs(frf2->h[i] - frf->h[i]), 0.0, 1e-9 * std::abs(frf->h[i]));
    std::filesystem::remove_all(dir);
}

TEST(CliCaptureFrf, PrbsGivesCoherence)
{
    const auto dir = makeTempDir("capture_frf_prbs");
    const auto out = (dir / "frf.csv").string();
    auto r = runCli("capture --connect sim:two-inertia --axis A --test frf --method prbs --fmin 20 --fmax 1000 --points 20 "
                    "--amplitude-pct 5 --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto frf = axistune::io::readFrfCsvFile(out);
    ASSERT_TRUE(frf.ok());
    ASSERT_GE(frf->size(), 10u);
    for (std::size_t i = 0; i < frf->size(); ++i) {
        EXPECT_GE(frf->coherence[i], 0.0);
        EXPECT_LE(frf->coherence[i], 1.0 + 1e-12);
    }
    std::filesystem::remove_all(dir);
}

TEST(CliCaptureFrf, BadOptionsGiveExitCode2)
{
    const auto dir = makeTempDir("capture-frf-bad"); // nothing is written there, unless a refusal fails
    const std::string out = (dir / "axistune_simfrf_bad.csv").string();
    const std::string base = "capture --connect sim:dd-table --axis C --test frf --out " + out + " ";
    auto r = runCli(base + "--method swoop");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--method"), std::string::npos);
    r = runCli(base + "--amplitude-pct 80");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("refused"), std::string::npos);
    r = runCli(base + "--fmax 4000");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("fmax"), std::string::npos);
    r = runCli(base + "--points 0");
    EXPECT_EQ(r.exitCode, 2);
    r = runCli(base + "--method prbs --fmax 1000 --sweep-out " + (dir / "axistune_simfrf_bad_sweep.csv").string());
    EXPECT_EQ(r.exitCode, 2);
    r = runCli("capture --connect sim:vmc --axis X --test step --amplitude 1 --sweep-out " + (dir / "s.csv").string() +
               " --out " + out);
    EXPECT_EQ(r.exitCode, 2);
    // A peak in output units is hal:'s (docs/linuxcnc.md); the simulated drive takes % of rated torque and says so.
    for (const char* method : {"multisweep", "multisine"}) {
        r = runCli(base + "--method " + method + " --amplitude 0.5");
        EXPECT_EQ(r.exitCode, 2) << method;
        EXPECT_NE(r.err.find("--amplitude-pct"), std::string::npos) << r.err;
        // The plant and the open position loop are quantities of a PID the NC closes (hal:), not of this drive.
        r = runCli(base + "--method " + method + " --quantity open-loop");
        EXPECT_EQ(r.exitCode, 2) << method;
        EXPECT_NE(r.err.find("--quantity"), std::string::npos) << r.err;
    }
    r = runCli(base + "--quantity closed");
    EXPECT_EQ(r.exitCode, 2);
}

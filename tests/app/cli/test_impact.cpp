// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli frf --impact and import-frf end to end, on the real records of shared/data/real.
#include "core/io/FrfCsv.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>

#include "CliRunner.h"

using namespace axistune;
using namespace axistune::testing;

namespace {

std::string realData(const std::string& name)
{
    return std::string(AXISTUNE_REAL_DATA_DIR) + "/" + name;
}

} // namespace

TEST(CliImpact, RealRecordGivesReceptanceWithUnits)
{
    const auto dir = makeTempDir("impact");
    const auto out = (dir / "h.csv").string();
    auto r = runCli("frf --impact --in " + realData("impact_test_raw_time.csv") +
                    " --force force_N --response accel_m_s2 --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto frf = io::readFrfCsvFile(out);
    ASSERT_TRUE(frf) << frf.error().detail;
    EXPECT_EQ(frf->metadata.text("units"), "m/N");
    // the author's published H11 at 1056 Hz is 6.776e-7 m/N (tooltip_frf_H11_H15.csv)
    double best = 0.0, bestHz = 0.0;
    for (std::size_t i = 0; i < frf->size(); ++i) {
        if (frf->valid[i] && std::abs(frf->h[i]) > best) {
            best = std::abs(frf->h[i]);
            bestHz = frf->freqHz[i];
        }
    }
    EXPECT_NEAR(best, 6.77628525945477e-07, 0.05 * 6.77628525945477e-07);
    EXPECT_NEAR(bestHz, 1056.0, 2.0);
}

TEST(CliImpact, WelchOnAHammerRecordSaysUseImpact)
{
    const auto dir = makeTempDir("welchimpact");
    auto r = runCli("frf --in " + realData("impact_test_raw_time.csv") + " --input force_N --output accel_m_s2 --out " +
                    (dir / "w.csv").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("use --impact"), std::string::npos) << r.err;
    // a noise-like excitation gets no such note (EMPS control voltage)
    auto e = runCli("frf --in " + realData("emps_DATA_EMPS.csv") + " --input u_voltage --output q_motor --out " +
                    (dir / "e.csv").string());
    ASSERT_EQ(e.exitCode, 0) << e.err;
    EXPECT_EQ(e.err.find("use --impact"), std::string::npos) << e.err;
}

TEST(CliImpact, JitteredTimeColumnsAcceptedAndFsOverrides)
{
    const auto dir = makeTempDir("emps");
    auto r = runCli("frf --in " + realData("emps_DATA_EMPS.csv") + " --input u_voltage --output q_motor --out " +
                    (dir / "e.csv").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // EMPS is sampled at 1 kHz (its jitter is below the tolerance): fs from the time column, a JSON integer
    EXPECT_NE(r.out.find("\"fs_Hz\":1000,"), std::string::npos) << r.out;
    auto f = runCli("frf --in " + realData("emps_DATA_EMPS.csv") +
                    " --input u_voltage --output q_motor --fs 500 --out " + (dir / "e2.csv").string());
    ASSERT_EQ(f.exitCode, 0) << f.err;
    EXPECT_NE(f.out.find("\"fs_Hz\":500,"), std::string::npos) << f.out;
}

TEST(CliImpact, DoubleHitExitsTwoWithTheTime)
{
    const auto dir = makeTempDir("dbl");
    const auto in = (dir / "dbl.csv").string();
    {
        std::ofstream f(in);
        f << "t_s;force_N;accel_m_s2\n";
        for (int i = 0; i < 2000; ++i) {
            double force = 0.0;
            if (i >= 20 && i <= 24)
                force = 100.0;
            if (i >= 60 && i <= 63)
                force = 30.0; // the rebound 4 ms later
            const double t = i * 1e-4;
            std::string ts = std::to_string(t), fs = std::to_string(force),
                        as = std::to_string(std::sin(0.3 * i) * std::exp(-0.01 * i));
            for (auto* s : {&ts, &fs, &as})
                for (char& c : *s)
                    c = c == '.' ? ',' : c; // decimal comma, semicolon separator
            f << ts << ';' << fs << ';' << as << '\n';
        }
    }
    auto r =
        runCli("frf --impact --in " + in + " --force force_N --response accel_m_s2 --out " + (dir / "h.csv").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("double hit at 0.002 s"), std::string::npos) << r.err;
}

TEST(CliImportFrf, ColumnAndUnitsOfTheToolHolderFile)
{
    const auto dir = makeTempDir("impfrf");
    const auto out = (dir / "h12.csv").string();
    auto r =
        runCli("import-frf --in " + realData("tooltip_frf_H11_H15.csv") + " --column H12 --units um/N --out " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto frf = io::readFrfCsvFile(out);
    ASSERT_TRUE(frf);
    EXPECT_DOUBLE_EQ(frf->h[1].real(), 0.004482785e-6); // line "1.0,...,0.004482785,..." of the file, in µm/N
    auto bad = runCli("import-frf --in " + realData("tooltip_frf_H11_H15.csv") +
                      " --column H12 --units parsec/N --out " + out);
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("parsec/N"), std::string::npos);
}

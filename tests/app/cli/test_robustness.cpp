// SPDX-License-Identifier: GPL-3.0-or-later
// Hostile input through the real axistune-cli (issue 21, docs/robustness.md): every case must end in
// exit 2 with the file (and line and field where there is one) named, or in a correct result; never a
// crash, a hang, or NaN/Inf/null in a result. A hang fails the
// test by its ctest timeout instead of blocking for ever.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <regex>
#include <sys/stat.h>
#include <nlohmann/json.hpp>

#include "tests/app/cli/CliRunner.h"

using namespace axistune::testing;
namespace fs = std::filesystem;

namespace {

const std::string kResources = std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources";
const std::string kSamples = kResources + "/samples";
const std::string kData = AXISTUNE_TEST_DATA_DIR;

class Robustness : public ::testing::Test {
protected:
    std::string write(const std::string& name, const std::string& text)
    {
        const auto p = m_dir / name;
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }
    std::string quoted(const std::string& p) const { return "'" + p + "'"; }
    ScopedTempDir m_dir{"robust"}; // one per test, removed after it
};

/// Exit 2 and the stderr names every fragment.
void expectRefused(const CliResult& r, std::initializer_list<std::string> fragments)
{
    EXPECT_EQ(r.exitCode, 2) << r.err << r.out;
    EXPECT_TRUE(r.out.empty()) << r.out;
    for (const auto& f : fragments)
        EXPECT_NE(r.err.find(f), std::string::npos) << "missing '" << f << "' in: " << r.err;
}

std::string readSample(const std::string& name)
{
    return readFileText(kSamples + "/" + name);
}

} // namespace

TEST_F(Robustness, FifoWithoutWriterIsRefusedNotWaitedOn)
{
    const auto fifo = (m_dir / "motor.json").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    expectRefused(runCli("current-loop --motor " + fifo), {fifo + ": is not a regular file"});
    expectRefused(runCli("ballbar --in " + fifo), {fifo + ": is not a regular file"});
    expectRefused(runCli("notch --frf " + fifo), {fifo + ": is not a regular file"});
    // The format sniffing of `frf --in` (halscope or CSV) used to read the first line of any file.
    expectRefused(runCli("frf --in " + fifo + " --input x --output y"), {fifo + ": is not a regular file"});
    // identify: the record and the controller file.
    expectRefused(runCli("identify --in " + fifo + " --position x_m --force f_N"), {fifo + ": is not a regular file"});
    const auto rec = std::string(AXISTUNE_TEST_DATA_DIR) + "/ident/fuzz-seed-motion.csv";
    expectRefused(runCli("identify --in " + rec + " --position x_m --force f_N --validate " + rec +
                         " --reference x_m --controller " + fifo),
                  {fifo + ": is not a regular file"});
}

TEST_F(Robustness, DevZeroAsJsonIsRefused)
{
    expectRefused(runCli("current-loop --motor /dev/zero"), {"/dev/zero: is not a regular file"});
}

TEST_F(Robustness, MotorNumbersOutsideTheDoubleRangeNameFileLineAndKey)
{
    const std::string m = readSample("motor-rotary.json");
    const std::regex r("(\"resistance_ohm\"\\s*:\\s*)[-0-9.eE+]+");
    const auto big = write("big.json", std::regex_replace(m, r, "$011e309"));
    expectRefused(runCli("current-loop --motor " + big),
                  {big + " line ", "key 'resistance_ohm'", "does not fit a double"});
    const auto neg = write("neg.json", std::regex_replace(m, r, "$01-1e309"));
    expectRefused(runCli("current-loop --motor " + neg), {"key 'resistance_ohm'", "-1e309 does not fit a double"});
    // Used to loop for ever in the phase-crossover search.
    const auto den = write("den.json", std::regex_replace(m, r, "$015e-324"));
    expectRefused(runCli("current-loop --motor " + den), {"key 'resistance_ohm'", "5e-324 is denormal"});
}

TEST_F(Robustness, DeeplyNestedJsonIsRefused)
{
    const auto deep = write("deep.json", std::string(100000, '[') + std::string(100000, ']'));
    expectRefused(runCli("current-loop --motor " + deep), {deep + " line 1: nested deeper than 32 levels"});
    expectRefused(runCli("lobes --tool " + kSamples + "/tool-table1.json --rpm-min 2800 --rpm-max 2955 --rpm-step 155 --cut "
                         + deep),
                  {deep + " line 1: nested deeper than 32 levels"});
}

TEST_F(Robustness, ProfileWithAMisspeltTopLevelKeyIsRefused)
{
    std::string p = readSample("vmc-profile.json");
    const auto pos = p.find("\"axes\"");
    ASSERT_NE(pos, std::string::npos);
    p.replace(pos, 6, "\"axes\": [], \"axess\"");
    const auto f = write("typo.json", p);
    expectRefused(runCli("import --db " + (m_dir / "s.db").string() + " --in " + f), {f + ": unknown field 'axess'"});
}

TEST_F(Robustness, NcMapThatWouldLoopOrDropTheNoticeOrTheValuesIsRefused)
{
    // A store holding the sample profile, then the export through edited FANUC maps.
    const std::string db = (m_dir / "s.db").string();
    ASSERT_EQ(runCli("import --db " + db + " --in " + kSamples + "/vmc-profile.json").exitCode, 0);
    const std::string fanuc = readFileText(kResources + "/nc/fanuc.json");
    auto edited = [&](const std::string& name, const std::string& from, const std::string& to) {
        std::string t = fanuc;
        const auto pos = t.find(from);
        EXPECT_NE(pos, std::string::npos) << from;
        t.replace(pos, from.size(), to);
        return write(name, t);
    };
    const std::string machine = "vmc";
    const std::string base = "export --db " + db + " --machine " + machine + " --format fanuc --map ";
    auto space = edited("space.json", "\"comment_forbidden\": [\"(\", \")\", \"%\"]", "\"comment_forbidden\": [\" \"]");
    expectRefused(runCli(base + space), {space + ": field 'comment_forbidden'"});
    auto noText = edited("notext.json", "\"comment\": \"({text})\"", "\"comment\": \"(see manual)\"");
    expectRefused(runCli(base + noText), {noText + ": field 'comment' must contain {text}"});
    auto noValue =
        edited("novalue.json", "\"axis_item\": \"A{axis_index}P{value}\"", "\"axis_item\": \"A{axis_index}\"");
    expectRefused(runCli(base + noValue), {noValue + ": field 'axis_item' must contain {value}"});
}

TEST_F(Robustness, NonUtf8FileNamesDoNotAbort)
{
    const std::string bad = "run-\xff\xfe";
    const auto bb = write(bad + "-ccw.csv", readSample("ballbar-ccw.csv"));
    const auto bb2 = write(bad + "-cw.csv", readSample("ballbar-cw.csv"));
    auto r = runCli("ballbar --in " + quoted(bb) + " --in " + quoted(bb2));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("run-\xEF\xBF\xBD\xEF\xBF\xBD-ccw.csv"), std::string::npos); // U+FFFD for each bad byte
    const auto frf = write(bad + ".csv", readSample("frf-two-inertia.csv"));
    r = runCli("notch --frf " + quoted(frf) + " --out-frf " + quoted((m_dir / (bad + "-out.csv")).string()));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\"frf\": \"" + (m_dir / "run-\xEF\xBF\xBD\xEF\xBF\xBD.csv").string() + "\""), std::string::npos)
        << r.out;
}

TEST_F(Robustness, HugeFiniteSampleIsRefusedNotWrittenAsValidNanRows)
{
    // Issue 21: one 1.79e308 sample made `frf --in` write NaN/Inf rows marked valid=1.
    std::string cap = readSample("capture-step-vmc-x.csv");
    const auto hdr = cap.find("t_s,");
    const auto row = cap.find('\n', cap.find('\n', cap.find('\n', hdr) + 1) + 1) + 1; // the third data row
    const auto comma = cap.find(',', row);
    cap.replace(comma + 1, cap.find(',', comma + 1) - comma - 1, "1.79e308");
    const auto in = write("huge.csv", cap);
    const auto out = (m_dir / "frf.csv").string();
    auto r =
        runCli("frf --in " + in + " --input velocity_cmd_rad_s --output motor_vel_rad_s --nperseg 64 --out " + out);
    expectRefused(r, {in, "too large"});
    EXPECT_FALSE(fs::exists(out) && readFileText(out).find("nan") != std::string::npos);
}

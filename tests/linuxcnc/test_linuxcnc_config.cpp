// SPDX-License-Identifier: GPL-3.0-or-later
// Reading LinuxCNC configurations (the stock servo_sim sample of Debian's linuxcnc-uspace, the repository's test
// machine, hand-made cases) and Persist: only the INI keys that feed the changed gains change.
#include "core/device/hal/LinuxCncConfig.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace axistune;
using namespace axistune::device::hal;
namespace fs = std::filesystem;

namespace {

const fs::path kStockServoSim = "/usr/share/doc/linuxcnc/examples/sample-configs/sim/tklinuxcnc/servo_sim.ini";

std::string slurp(const fs::path& p)
{
    std::ifstream f(p, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

void spit(const fs::path& p, const std::string& text)
{
    std::ofstream f(p, std::ios::binary);
    f << text;
}

std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> out;
    std::stringstream s(text);
    std::string l;
    while (std::getline(s, l))
        out.push_back(l);
    return out;
}

class TempDir : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_dir = fs::temp_directory_path() / ("axistune-lcnc-" + std::to_string(::getpid()) + "-" +
                                             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }
    fs::path m_dir;
};

} // namespace

TEST_F(TempDir, StockServoSimJointsPidsAndGainKeysAreFound)
{
    ASSERT_TRUE(fs::exists(kStockServoSim))
        << "Debian's linuxcnc-uspace sample configurations are missing (scripts/deps)";
    const fs::path ini = m_dir / "servo_sim.ini";
    fs::copy_file(kStockServoSim, ini); // the HAL file comes from LinuxCNC's library (hallib)
    auto cfg = readLinuxCncConfig(ini.string());
    ASSERT_TRUE(cfg) << cfg.error().detail;
    ASSERT_EQ(cfg->halFiles.size(), 1u);
    EXPECT_EQ(cfg->halFiles[0], "/usr/share/linuxcnc/hallib/servo_sim.hal");
    ASSERT_EQ(cfg->pids.size(), 3u);
    const char* names[] = {"pid_x", "pid_y", "pid_z"};
    const char* letters[] = {"X", "Y", "Z"};
    for (int j = 0; j < 3; ++j) {
        const PidInstance* p = cfg->findPid(names[j]);
        ASSERT_NE(p, nullptr) << names[j];
        EXPECT_EQ(p->joint, j);
        EXPECT_EQ(p->axisLetter, letters[j]);
        const std::string section = "JOINT_" + std::to_string(j);
        for (auto [gain, key] : {std::pair{"Pgain", "PGAIN"},
                                 {"Igain", "IGAIN"},
                                 {"Dgain", "DGAIN"},
                                 {"FF0", "FF0"},
                                 {"FF1", "FF1"},
                                 {"FF2", "FF2"},
                                 {"bias", "BIAS"},
                                 {"deadband", "DEADBAND"},
                                 {"maxoutput", "MAX_VELOCITY"}}) {
            ASSERT_EQ(p->gains.count(gain), 1u) << names[j] << "." << gain;
            EXPECT_EQ(p->gains.at(gain).section, section);
            EXPECT_EQ(p->gains.at(gain).key, key);
            EXPECT_TRUE(p->gains.at(gain).literal.empty());
        }
    }
    const IniEntry* pg = cfg->ini.find("JOINT_0", "PGAIN");
    ASSERT_NE(pg, nullptr);
    EXPECT_EQ(pg->value, "1500.0");
}

TEST_F(TempDir, PersistChangesOnlyTheFeedingKeysAndKeepsABackup)
{
    const fs::path ini = m_dir / "servo_sim.ini";
    fs::copy_file(kStockServoSim, ini);
    const std::string original = slurp(ini);
    auto cfg = readLinuxCncConfig(ini.string());
    ASSERT_TRUE(cfg) << cfg.error().detail;
    auto edits = persistGains(*cfg, {{"pid_x", "Pgain", 1234.5}, {"pid_y", "FF1", 0.25}, {"pid_z", "Dgain", 4.0}});
    ASSERT_TRUE(edits) << edits.error().detail;
    // pid_z Dgain is 4.0 already: the same number, so its line keeps its text.
    ASSERT_EQ(edits->size(), 2u);
    EXPECT_EQ((*edits)[0].key, "PGAIN");
    EXPECT_EQ((*edits)[0].oldValue, "1500.0");
    EXPECT_EQ((*edits)[0].newValue, "1234.5");
    EXPECT_EQ((*edits)[1].section, "JOINT_1");
    EXPECT_EQ((*edits)[1].newValue, "0.25");
    EXPECT_EQ(slurp(m_dir / "servo_sim.ini.axistune-backup"), original);

    const auto before = lines(original), after = lines(slurp(ini));
    ASSERT_EQ(before.size(), after.size());
    std::vector<std::size_t> changed;
    for (std::size_t i = 0; i < before.size(); ++i)
        if (before[i] != after[i])
            changed.push_back(i + 1);
    ASSERT_EQ(changed.size(), 2u);
    EXPECT_EQ(changed[0], (*edits)[0].line);
    EXPECT_EQ(changed[1], (*edits)[1].line);
    EXPECT_EQ(after[changed[0] - 1], "PGAIN = 1234.5");
    EXPECT_EQ(after[changed[1] - 1], "FF1 = 0.25");
    EXPECT_EQ(original.back() == '\n', slurp(ini).back() == '\n');

    auto again = readLinuxCncConfig(ini.string());
    ASSERT_TRUE(again);
    EXPECT_EQ(again->ini.find("JOINT_0", "PGAIN")->value, "1234.5");
}

TEST_F(TempDir, TheTestMachineConfigurationIsALinuxCncConfiguration)
{
    const fs::path src = fs::path(AXISTUNE_SOURCE_DIR) / "linuxcnc/testbed";
    auto cfg = readLinuxCncConfig((src / "axistune-testbed.ini").string());
    ASSERT_TRUE(cfg) << cfg.error().detail;
    const PidInstance* p = cfg->findPid("pid.x");
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->joint, 0);
    EXPECT_EQ(p->axisLetter, "X"); // [TRAJ]COORDINATES with trivkins
    EXPECT_EQ(p->gains.at("Pgain").key, "P");
    EXPECT_EQ(p->gains.at("maxerror").key, "FERROR");
}

TEST_F(TempDir, AGainWrittenAsALiteralInAHalFileIsReportedNotEdited)
{
    spit(m_dir / "m.hal", "loadrt pid count=2\n"
                          "setp pid.0.Pgain [JOINT_0]P   # fed by the INI\n"
                          "setp pid.1.Pgain 2.5\n");
    const std::string iniText = "[HAL]\nHALFILE = m.hal\n\n[JOINT_0]\nP = 1.0\n";
    spit(m_dir / "m.ini", iniText);
    auto cfg = readLinuxCncConfig((m_dir / "m.ini").string());
    ASSERT_TRUE(cfg) << cfg.error().detail;
    ASSERT_EQ(cfg->pids.size(), 2u);
    EXPECT_EQ(cfg->pids[1].name, "pid.1");
    auto r = persistGains(*cfg, {{"pid.0", "Pgain", 3.0}, {"pid.1", "Pgain", 3.0}});
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().detail.find("m.hal:3"), std::string::npos) << r.error().detail;
    EXPECT_NE(r.error().detail.find("literal 2.5"), std::string::npos) << r.error().detail;
    EXPECT_EQ(slurp(m_dir / "m.ini"), iniText); // nothing written, not even the other gain
    EXPECT_FALSE(fs::exists(m_dir / "m.ini.axistune-backup"));

    auto unknown = persistGains(*cfg, {{"pid.0", "FF2", 1.0}});
    ASSERT_FALSE(unknown);
    EXPECT_NE(unknown.error().detail.find("no setp line"), std::string::npos) << unknown.error().detail;
    auto nan = persistGains(*cfg, {{"pid.0", "Pgain", std::nan("")}});
    ASSERT_FALSE(nan);
}

TEST_F(TempDir, MalformedIniAndMissingHalFilesNameFileAndLine)
{
    spit(m_dir / "bad.ini", "[HAL]\nHALFILE = m.hal\nthis line has no equals sign\n");
    auto bad = readLinuxCncConfig((m_dir / "bad.ini").string());
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().detail.find("bad.ini:3"), std::string::npos) << bad.error().detail;

    spit(m_dir / "nohal.ini", "[HAL]\nHALFILE = missing.hal\n");
    auto missing = readLinuxCncConfig((m_dir / "nohal.ini").string(), m_dir.string());
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().detail.find("nohal.ini:2"), std::string::npos) << missing.error().detail;
    EXPECT_NE(missing.error().detail.find("missing.hal"), std::string::npos) << missing.error().detail;

    spit(m_dir / "none.ini", "[EMC]\nMACHINE = x\n");
    auto none = readLinuxCncConfig((m_dir / "none.ini").string());
    ASSERT_FALSE(none);
    EXPECT_NE(none.error().detail.find("HALFILE"), std::string::npos);
}

TEST(HalFileText, MalformedPidLinesAreRefusedWithLineAndOddSetpLinesIgnored)
{
    LinuxCncConfig cfg;
    auto emptyName = addHalText(cfg, "m.hal", "# x\nloadrt pid names=pid_x,,pid_z\n", "XYZ");
    ASSERT_FALSE(emptyName.ok());
    EXPECT_NE(emptyName.error().detail.find("m.hal:2"), std::string::npos) << emptyName.error().detail;

    auto zero = addHalText(cfg, "m.hal", "loadrt pid count=0\n", "XYZ");
    ASSERT_FALSE(zero.ok());
    EXPECT_NE(zero.error().detail.find("m.hal:1"), std::string::npos) << zero.error().detail;

    // A pin ending in a dot names no gain; a setp of an unknown component is not a pid gain.
    LinuxCncConfig ok;
    ASSERT_TRUE(addHalText(ok, "n.hal",
                           "loadrt pid names=pid_y\nsetp pid_y. 5\nsetp other.Pgain 3\nsetp pid_y.Pgain [JOINT_1]P\n",
                           "XYZ")
                    .ok());
    ASSERT_EQ(ok.pids.size(), 1u);
    ASSERT_EQ(ok.pids[0].gains.size(), 1u);
    const auto& p = ok.pids[0].gains.at("Pgain");
    EXPECT_EQ(p.section, "JOINT_1");
    EXPECT_EQ(p.key, "P");
    EXPECT_EQ(p.halLine, 4u);
    EXPECT_EQ(ok.pids[0].joint, 1);
    EXPECT_EQ(ok.pids[0].axisLetter, "Y");
}

// SPDX-License-Identifier: GPL-3.0-or-later
// A full LinuxCNC, headless (scripts/hal-testbed linuxcnc: DISPLAY = dummy, machine switched on through LinuxCNC's
// Python module), from a copy of Debian's stock sim/tklinuxcnc/servo_sim configuration: a gain changed live through
// `linuxcnc:` and written by `axistune-cli persist` into the INI is what the next full LinuxCNC started from that INI
// runs with (issue 17, Persist).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "tests/linuxcnc/HalTestbed.h"

using namespace axistune;
using namespace axistune::testing;
namespace fs = std::filesystem;

namespace {

const fs::path kServoSim = "/usr/share/doc/linuxcnc/examples/sample-configs/sim/tklinuxcnc";

/// A full LinuxCNC under the machine-wide lock; stopped at the end.
class FullLinuxCnc : public ::testing::Test {
protected:
    void start(const fs::path& ini)
    {
        if (!m_lock)
            m_lock = std::make_unique<HalMachineLock>();
        ASSERT_TRUE(m_lock->held()) << "cannot open /tmp/axistune-hal-machine.lock";
        auto st = runScript({"linuxcnc", ini.string()});
        ASSERT_TRUE(st) << st.error().detail;
        m_started = true;
    }
    void stop()
    {
        ASSERT_TRUE(runScript({"stop"}));
        m_started = false;
    }
    void TearDown() override
    {
        if (m_started)
            (void)runScript({"stop"});
        m_lock.reset();
    }
    bool m_started = false;
    std::unique_ptr<HalMachineLock> m_lock;
};

std::string slurp(const fs::path& p)
{
    std::ifstream f(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
}

} // namespace

TEST_F(FullLinuxCnc, PersistedGainIsReadByTheNextFullLinuxCnc)
{
    ASSERT_TRUE(fs::exists(kServoSim / "servo_sim.ini")) << "linuxcnc-uspace's sample configurations are missing";
    const fs::path dir = fs::path(::testing::TempDir()) / "full-linuxcnc-persist";
    fs::remove_all(dir);
    fs::copy(kServoSim, dir, fs::copy_options::recursive); // symlinks followed: copies of the files
    const fs::path ini = dir / "servo_sim.ini";
    const std::string original = slurp(ini);
    ::setenv("AXISTUNE_HALCMD", (kScript + " halcmd").c_str(), 1);
    const std::string cli = std::string(AXISTUNE_CLI);

    start(ini);
    // The stock gain, and the machine on (motion enables the joint's pid).
    EXPECT_DOUBLE_EQ(getp("pid_x.Pgain"), 1500.0);
    EXPECT_NE(halText({"-s", "show", "pin", "pid_x.enable"}).find("TRUE"), std::string::npos);
    ASSERT_EQ(
        std::system(
            (cli + " params --connect linuxcnc:" + ini.string() + " --axis X --set Pgain=1234.5 >/dev/null").c_str()),
        0);
    EXPECT_DOUBLE_EQ(getp("pid_x.Pgain"), 1234.5);
    ASSERT_EQ(std::system((cli + " persist --ini " + ini.string() + " --axis X --from-hal >/dev/null").c_str()), 0);
    // Line by line: only [JOINT_0]PGAIN differs.
    const auto changed = changedLines(original, slurp(ini));
    ASSERT_EQ(changed.size(), 1u);
    EXPECT_EQ(changed[0].first, "PGAIN = 1500.0");
    EXPECT_EQ(changed[0].second, "PGAIN = 1234.5");
    stop();

    // The next full LinuxCNC from the persisted INI runs pid_x with the new gain; the other joints keep theirs.
    start(ini);
    EXPECT_DOUBLE_EQ(getp("pid_x.Pgain"), 1234.5);
    EXPECT_DOUBLE_EQ(getp("pid_y.Pgain"), 1500.0);
    EXPECT_NE(halText({"-s", "show", "pin", "pid_x.enable"}).find("TRUE"), std::string::npos);
    stop();
    fs::remove_all(dir);
}

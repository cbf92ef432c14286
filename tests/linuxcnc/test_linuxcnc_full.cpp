// SPDX-License-Identifier: GPL-3.0-or-later
// A full LinuxCNC, headless (scripts/hal-testbed linuxcnc: DISPLAY = dummy, machine switched on through LinuxCNC's
// Python module), from a copy of Debian's stock sim/tklinuxcnc/servo_sim configuration: a gain changed live through
// `linuxcnc:` and written by `axistune-cli persist` into the INI is what the next full LinuxCNC started from that INI
// runs with (issue 17, Persist).
#include "core/io/CaptureCsv.h"
#include "core/io/FrfCsv.h"
#include "core/model/Number.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "tests/ScopedTempDir.h"
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
    const ScopedTempDir tmp("full-linuxcnc-persist");
    const fs::path dir = tmp.path();
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

namespace {

/// The open position loop of servo_sim's joint 0 as its HAL file builds it (/usr/share/linuxcnc/hallib/servo_sim.hal,
/// the INI's [JOINT_0]), written out here from the components' update equations, one servo period T:
///   pid (LinuxCNC's discrete PID):  C(z) = P + I*T/(1 - 1/z) + D*(1 - 1/z)/T
///   scale (gain DRIVE_RATIO 15), lowpass (gain a = 0.1): y[n] = y[n-1] + a*(15*u[n] - y[n-1])  [motor rev/s]
///   sim_encoder (MOTOR_PPR 100, 4 counts per pulse) counts during the next period, encoder (INPUT_SCALE 6000
///   counts/in) is captured at the next period's start: x[n+1] = x[n] + T*y[n]*400/6000
///   P(z) = a*15*T*(400/6000) / z / ((1 - 1/z)(1 - (1 - a)/z)).
/// The open loop as AxisTune measures it, -PID output / drive input, is L = C*P.
std::complex<double> servoSimOpenLoop(double fHz)
{
    const double T = 1e-3, P = 1500.0, I = 8000.0, D = 4.0, a = 0.1;
    const std::complex<double> zi = std::exp(std::complex<double>(0.0, -2.0 * M_PI * fHz * T));
    const auto c = P + I * T / (1.0 - zi) + D * (1.0 - zi) / T;
    const auto p = a * 15.0 * T * (400.0 / 6000.0) * zi / ((1.0 - zi) * (1.0 - (1.0 - a) * zi));
    return c * p;
}

} // namespace

TEST_F(FullLinuxCnc, ServoSimOpenLoopMeasuredThroughLinuxCncEqualsItsHalFileAndGivesTheCrossover)
{
    // Issue 17: "the stock servo_sim configuration: an FRF measured through a full headless linuxcnc, the crossover
    // reported". The stock pid has DEADBAND 0.0001 in (0.6 encoder counts): a dead zone on the following error that
    // lowers the small-signal gain by 1.5-2.5 dB and the coherence to < 0.9 at the injection's amplitudes. It is set
    // to 0 live for the measurement (every other gain as the INI has it), so the loop is the linear one above plus
    // the encoder's quantization.
    ASSERT_TRUE(fs::exists(kServoSim / "servo_sim.ini")) << "linuxcnc-uspace's sample configurations are missing";
    const ScopedTempDir tmp("full-linuxcnc-frf");
    const fs::path dir = tmp.path();
    fs::remove_all(dir);
    fs::copy(kServoSim, dir, fs::copy_options::recursive);
    const fs::path ini = dir / "servo_sim.ini";
    ::setenv("AXISTUNE_HALCMD", (kScript + " halcmd").c_str(), 1);
    const std::string cli = std::string(AXISTUNE_CLI);
    const std::string conn = " --connect linuxcnc:" + ini.string() + " --axis X";
    start(ini);
    EXPECT_DOUBLE_EQ(getp("pid_x.Pgain"), 1500.0);
    EXPECT_DOUBLE_EQ(getp("pid_x.Igain"), 8000.0);
    EXPECT_DOUBLE_EQ(getp("pid_x.Dgain"), 4.0);
    ASSERT_EQ(std::system((cli + " params" + conn + " --set deadband=0 >/dev/null").c_str()), 0);
    // 10 ... 190 Hz (19 lines), peak 0.8 in/s (maxoutput is MAX_VELOCITY 1.67: at most half), 120 periods: 36.3 s.
    // The encoder's pulses come from the base thread, whose timing is the machine's (uspace without an RT kernel):
    // under load the lines are noisier. With 60 periods a run at load 6 left no line valid, 120 periods left 17.
    const std::string csv = (dir / "open-loop.csv").string();
    const int rc = std::system((cli + " capture" + conn +
                                " --test frf --method multisine --band 10:200:10 --amplitude 0.8 --periods 120 "
                                "--quantity open-loop --out " +
                                csv + " >/dev/null")
                                   .c_str());
    ASSERT_EQ(rc, 0);
    const std::string notchJson = (dir / "margins.json").string();
    ASSERT_EQ(std::system((cli + " notch --frf " + csv + " --loop open > " + notchJson).c_str()), 0);
    stop();

    auto frf = io::readFrfCsvFile(csv);
    ASSERT_TRUE(frf.ok()) << frf.error().detail;
    EXPECT_EQ(frf->metadata.text("quantity"), "open-loop");
    EXPECT_EQ(frf->metadata.number("fs_Hz").value(), 1000.0);
    // Every valid line against the model: a valid line has sigma_H/|H| <= 0.03 (max_relative_noise), so 3.5 sigma is
    // 0.105 of |H|: 0.9 dB and 6.0 deg; the base thread's pulses (50 us) shift the encoder by up to one base period,
    // 2.2 deg at 123 Hz. Hence 1 dB and 8 deg, over the crossover's region up to 150 Hz (1.7x the crossover); above
    // it the model leaves out the pulses' timing and the measured |L| runs up to 1.3 dB above it (seen at 193 Hz).
    // Seen up to 150 Hz: within 0.64 dB and 4.5 deg.
    std::size_t valid = 0;
    for (std::size_t i = 0; i < frf->size(); ++i) {
        if (!frf->valid[i] || frf->freqHz[i] > 150.0)
            continue;
        ++valid;
        const auto model = servoSimOpenLoop(frf->freqHz[i]);
        const auto ratio = frf->h[i] / model;
        EXPECT_LT(std::abs(20.0 * std::log10(std::abs(ratio))), 1.0) << frf->freqHz[i] << " Hz";
        EXPECT_LT(std::abs(std::arg(ratio)) * 180.0 / M_PI, 8.0) << frf->freqHz[i] << " Hz";
    }
    EXPECT_GE(valid, 5u) << "too few valid lines to read a crossover";
    // The crossover AxisTune reports (notch --loop open: margins of the measured L on its valid lines) against the
    // model's |L| = 1 (bisection). |L| falls about 24 dB/decade there (63 -> 123 Hz: 3.9 -> -3.0 dB in the model), so
    // the lines' 1 dB moves the crossover by up to 10 %; the phase margin within the lines' 8 deg.
    double lo = 20.0, hi = 400.0;
    for (int k = 0; k < 60; ++k) {
        const double mid = std::sqrt(lo * hi);
        (std::abs(servoSimOpenLoop(mid)) > 1.0 ? lo : hi) = mid;
    }
    const double fcModel = lo;
    const double pmModel = 180.0 + std::arg(servoSimOpenLoop(fcModel)) * 180.0 / M_PI;
    const auto m = nlohmann::json::parse(slurp(notchJson))["margins_before"];
    ASSERT_TRUE(m.contains("phase_margin_Hz")) << m.dump();
    EXPECT_NEAR(m["phase_margin_Hz"].get<double>(), fcModel, 0.10 * fcModel);
    EXPECT_NEAR(m["phase_margin_deg"].get<double>(), pmModel, 8.0);
    std::cout << "servo_sim open loop: " << valid << " valid lines; crossover " << m["phase_margin_Hz"] << " Hz, PM "
              << m["phase_margin_deg"] << " deg; the HAL file's model " << fcModel << " Hz, " << pmModel << " deg\n";
    fs::remove_all(dir);
}

// Issue 17 item 2: a jog through LinuxCNC's own motion. On a full headless LinuxCNC (servo_sim, inch), `capture
// --test jog --back` on linuxcnc: sends a joint jog out and back through LinuxCNC's NML channels while hal: records:
// the command the pid follows (feedback + following error) rises by the distance and comes back (to 1e-6 in), its
// speed reaches the asked velocity and its acceleration the joint's MAX_ACCELERATION (finite differences of the 1 kHz
// record; motion plans a trapezoid), AxisTune's own offset stays 0, the nets are as before; a gentler acceleration
// than the joint's, or a speed above MAX_VELOCITY, is refused with exit 2 naming the key.
TEST_F(FullLinuxCnc, JogThroughLinuxCncsMotionIsRecordedOutAndBack)
{
    ASSERT_TRUE(fs::exists(kServoSim / "servo_sim.ini")) << "linuxcnc-uspace's sample configurations are missing";
    const ScopedTempDir tmp("full-linuxcnc-jog");
    const fs::path dir = tmp.path();
    fs::remove_all(dir);
    fs::copy(kServoSim, dir, fs::copy_options::recursive);
    const fs::path ini = dir / "servo_sim.ini";
    // servo_sim compensates its X screw (COMP_FILE screwcompX.dat): motion then adds up to 3 thousandths of an inch,
    // switched with the direction, to the command the pid follows. Without it that command is the jog's own path.
    {
        std::istringstream in(slurp(ini));
        std::string text, line;
        while (std::getline(in, line))
            if (line.rfind("COMP_FILE", 0) != 0)
                text += line + "\n";
        std::ofstream(ini, std::ios::binary) << text;
    }
    ::setenv("AXISTUNE_HALCMD", (kScript + " halcmd").c_str(), 1);
    const std::string cli = std::string(AXISTUNE_CLI) + " capture --connect linuxcnc:" + ini.string() + " --axis X";
    start(ini);
    const std::string sigBefore = netsOf(halText({"-s", "show", "sig"}));
    const std::string csv = (dir / "jog.csv").string();
    const std::string log = (dir / "jog.log").string();
    // 0.5 in at 0.25 in/s: servo_sim's joint 0 has MAX_VELOCITY 1.67 in/s and MAX_ACCELERATION 20 in/s², FERROR
    // 0.05 in. Slowly: without an RT kernel a loaded machine can stall the servo thread for a tenth of a second, and
    // at 1 in/s that is more than FERROR (once, at load 7, LinuxCNC switched the machine off during this test).
    const std::string jog = cli + " --test jog --distance 0.5 --velocity 0.25 --back --duration 0.2 ";
    const std::string out = (dir / "jog.json").string();
    const int rc = std::system((jog + "--acceleration 20 --out " + csv + " >" + out + " 2>" + log).c_str());
    ASSERT_EQ(rc, 0) << slurp(log);
    // stdout is the CLI's JSON alone (LinuxCNC's status library prints on stdout when it first reads the status), and
    // the record is as long as planned.
    const auto summary = nlohmann::json::parse(slurp(out));
    EXPECT_EQ(summary.at("samples"), summary.at("planned_samples"));
    EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), sigBefore);
    const int gentle = std::system((jog + "--acceleration 5 --out " + (dir / "never.csv").string() + " 2>" + log).c_str());
    EXPECT_EQ(WEXITSTATUS(gentle), 2);
    EXPECT_NE(slurp(log).find("MAX_ACCELERATION = 20"), std::string::npos) << slurp(log);
    const int fast = std::system(
        (cli + " --test jog --distance 0.5 --velocity 2 --back --acceleration 20 --out " + (dir / "never.csv").string() +
         " 2>" + log)
            .c_str());
    EXPECT_EQ(WEXITSTATUS(fast), 2);
    EXPECT_NE(slurp(log).find("MAX_VELOCITY = 1.67"), std::string::npos) << slurp(log);
    // With the machine switched off (through LinuxCNC's Python module, as an operator's GUI would): refused, exit 4.
    ASSERT_EQ(std::system("cd / && /usr/bin/python3 -c 'import linuxcnc; c = linuxcnc.command(); "
                          "c.state(linuxcnc.STATE_OFF); c.wait_complete(5)' >/dev/null 2>&1"),
              0);
    const int off = std::system((jog + "--acceleration 20 --out " + (dir / "never.csv").string() + " 2>" + log).c_str());
    EXPECT_EQ(WEXITSTATUS(off), 4);
    EXPECT_NE(slurp(log).find("machine is not on"), std::string::npos) << slurp(log);
    EXPECT_FALSE(fs::exists(dir / "never.csv"));
    stop();

    auto trace = io::readCaptureCsvFile(csv);
    ASSERT_TRUE(trace) << trace.error().detail;
    EXPECT_NE(trace->metadata.text("moved_by").value().find("LinuxCNC's motion"), std::string::npos);
    const auto* fb = trace->channel("feedback");
    const auto* fe = trace->channel("following_error");
    const auto* offset = trace->channel("position_offset");
    ASSERT_TRUE(fb && fe && offset);
    const std::size_t n = fb->data.size();
    ASSERT_GT(n, 1000u);
    std::vector<double> cmd(n);
    for (std::size_t i = 0; i < n; ++i) {
        cmd[i] = fb->data[i] + fe->data[i];
        ASSERT_EQ(offset->data[i], 0.0) << "row " << i;
    }
    const double c0 = cmd.front();
    const double top = *std::max_element(cmd.begin(), cmd.end());
    EXPECT_NEAR(top - c0, 0.5, 1e-6);
    EXPECT_NEAR(cmd.back(), c0, 1e-6);
    const double T = 1e-3;
    double vmax = 0.0, amax = 0.0;
    for (std::size_t i = 1; i + 1 < n; ++i) {
        vmax = std::max(vmax, std::abs(cmd[i + 1] - cmd[i]) / T);
        amax = std::max(amax, std::abs(cmd[i + 1] - 2.0 * cmd[i] + cmd[i - 1]) / (T * T));
    }
    // The planner's speed plateau is the asked 0.25 in/s (to its rounding, 1 %); its acceleration the joint's 20 in/s².
    // A second difference over a corner of the trapezoid reads at most the full acceleration, so the largest one is
    // 20 in/s² within 5 % (the planner's segment boundaries fall between samples).
    EXPECT_NEAR(vmax, 0.25, 0.0025);
    EXPECT_NEAR(amax, 20.0, 1.0);
    RecordProperty("peak_velocity", model::formatShortest(vmax));
    RecordProperty("peak_acceleration", model::formatShortest(amax));
}

// SPDX-License-Identifier: GPL-3.0-or-later
// The command line and moves on AxisTune's LinuxCNC test machine: a move tripping FERROR, persist, pid-tune and
// the NC export (scripts/hal-testbed: LinuxCNC's pid around linuxcnc/axistune_plant.comp, a real HAL session
// started by each test; ctest runs these one at a time).
#include "core/device/Drive.h"
#include "core/device/hal/HalAxis.h"
#include "core/device/hal/LinuxCncConfig.h"
#include "core/dsp/Multisine.h"
#include "core/io/FrfCsv.h"
#include "core/model/Number.h"
#include "core/tuning/PositionPid.h"

#include <Eigen/Dense>
#include <chrono>
#include <cmath>
#include <complex>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "tests/ScopedTempDir.h"
#include "tests/linuxcnc/HalTestbed.h"

using namespace axistune;
using namespace axistune::device::hal;
using namespace axistune::testing;

// Issue 17 items 2 and 5, a move through the pid's command: with the running gains (P 2, I 10, D 0.047) the move
// 5 mm out and back at 50 mm/s and 1000 mm/s² lags by about 0.19 mm (the move test above). Through linuxcnc: with an
// INI whose [JOINT_0]FERROR is 0.02 mm (the pid's own maxerror stays 5 mm), the injection trips on the joint's
// FERROR: the test fails naming the following error, the offset returns to zero at the move's speed instead of
// jumping, the axis is back where it started, and the nets and functions are as before.
TEST_F(HalTestbed, AMoveTripsOnTheJointsFerrorAndGoesBack)
{
    startBed(1000000);
    ::setenv("AXISTUNE_HALCMD", (kScript + " halcmd").c_str(), 1);
    const ScopedTempDir tmp("ferror-testbed");
    const std::filesystem::path dir = tmp.path();
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::filesystem::path src = std::filesystem::path(AXISTUNE_SOURCE_DIR) / "linuxcnc/testbed";
    std::filesystem::copy_file(src / "axistune-testbed.hal", dir / "axistune-testbed.hal");
    std::ifstream in(src / "axistune-testbed.ini");
    std::ofstream out(dir / "axistune-testbed.ini");
    for (std::string line; std::getline(in, line);)
        out << (line.rfind("FERROR", 0) == 0 ? std::string("FERROR = 0.02") : line) << "\n";
    out.close();
    const std::string ini = (dir / "axistune-testbed.ini").string();
    EXPECT_DOUBLE_EQ(getp("pid.x.maxerror"), 5.0);
    const std::string sigBefore = netsOf(halText({"-s", "show", "sig"}));
    const std::string funBefore = halText({"-s", "show", "funct"});
    const double start = getp("plant.x.position");

    const std::string log = (dir / "move.log").string();
    const std::string cmd = std::string(AXISTUNE_CLI) + " capture --connect linuxcnc:" + ini +
                            " --axis X --test jog --distance 5 --velocity 50 --acceleration 1000 --back --duration "
                            "0.05 --out " +
                            (dir / "move.csv").string() + " 2>" + log;
    const int rc = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(rc));
    EXPECT_NE(WEXITSTATUS(rc), 0);
    std::ifstream l(log);
    const std::string err((std::istreambuf_iterator<char>(l)), {});
    EXPECT_NE(err.find("following error exceeded"), std::string::npos) << err;
    // The command is the NC's again and the axis stands where it started (the offset came back at 50 mm/s; after it
    // the loop settles within a few µm).
    EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), sigBefore);
    EXPECT_EQ(halText({"-s", "show", "funct"}), funBefore);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    EXPECT_NEAR(getp("plant.x.position"), start, 0.005);
    EXPECT_EQ(getp("pid.x.command"), 0.0);
}

// Issue 17 item 3, Persist: a gain changed live (setp through the hal: connection) is written by `axistune-cli
// persist --from-hal` into exactly the INI key that feeds it (one line differs, the backup is the original), and a
// HAL session started from the persisted INI reads the new gain; a dry run writes nothing; an unknown axis is exit 2.
TEST_F(HalTestbed, PersistedGainsAreReadByTheNextStart)
{
    startBed(1000000);
    ::setenv("AXISTUNE_HALCMD", (kScript + " halcmd").c_str(), 1);
    const ScopedTempDir tmp("persist-testbed");
    const std::filesystem::path dir = tmp.path();
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::filesystem::path src = std::filesystem::path(AXISTUNE_SOURCE_DIR) / "linuxcnc/testbed";
    for (const char* f : {"axistune-testbed.ini", "axistune-testbed.hal"})
        std::filesystem::copy_file(src / f, dir / f);
    const std::string ini = (dir / "axistune-testbed.ini").string();
    auto slurp = [](const std::string& p) {
        std::ifstream f(p, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(f), {});
    };
    const std::string original = slurp(ini);
    const std::string cli = std::string(AXISTUNE_CLI);
    ASSERT_EQ(
        std::system((cli + " params --connect linuxcnc:" + ini + " --axis X --set Pgain=3.25 >/dev/null").c_str()), 0);
    EXPECT_DOUBLE_EQ(getp("pid.x.Pgain"), 3.25);

    ASSERT_EQ(std::system((cli + " persist --ini " + ini + " --axis X --from-hal --dry-run >/dev/null").c_str()), 0);
    EXPECT_EQ(slurp(ini), original);
    ASSERT_EQ(std::system((cli + " persist --ini " + ini + " --axis X --from-hal >/dev/null").c_str()), 0);
    const std::string persisted = slurp(ini);
    EXPECT_EQ(slurp(ini + ".axistune-backup"), original);
    // Line by line: only [JOINT_0]P differs, and it reads 3.25.
    const auto changed = changedLines(original, persisted);
    ASSERT_EQ(changed.size(), 1u);
    EXPECT_EQ(changed[0].first, "P = 2.0");
    EXPECT_EQ(changed[0].second, "P = 3.25");
    EXPECT_EQ(WEXITSTATUS(std::system((cli + " persist --ini " + ini + " --axis Y --set Pgain=1 2>/dev/null").c_str())),
              2);

    // The next start from the persisted INI: the pid gets 3.25 from [JOINT_0]P.
    ASSERT_TRUE(runScript({"stop"}));
    ASSERT_TRUE(runScript({"start", "--ini", ini}));
    EXPECT_DOUBLE_EQ(getp("pid.x.Pgain"), 3.25);
}

// Issue 17 item 4 from the command line: `axistune-cli pid-tune --connect hal: --apply` measures the open loop,
// proposes gains with a rule for each and a biquad notch at the plant's resonance, applies them and verifies: the
// measured margins meet the issue's (PM ≥ 45°, GM ≥ 6 dB) and lie within 3° / 1 dB of the prediction; the gains in
// HAL are the proposed ones; the notch sits within 2 % of the exact plant's resonance and raises the crossover by at
// least the 10 % its rule asks against the proposal without it; `--remove-notch` leaves the nets and functions as
// they were.
TEST_F(HalTestbed, CliPidTuneAppliesAndVerifiesItsProposal)
{
    startBed(1000000);
    ::setenv("AXISTUNE_HALCMD", (kScript + " halcmd").c_str(), 1);
    const std::string sigBefore = netsOf(halText({"-s", "show", "sig"}));
    const std::string funBefore = halText({"-s", "show", "funct"});
    const double fr = exactResonanceHz(readPlant(), 1e-3);
    const std::string cli = std::string(AXISTUNE_CLI) + " pid-tune --connect hal: --axis pid.x --amplitude 0.2 --pm 50 "
                                                        "--gm 8 ";
    auto readJson = [](const std::string& path) {
        std::ifstream f(path);
        return nlohmann::json::parse(f);
    };
    const ScopedTempDir tmp("pid-tune");
    const std::string plain = tmp.string() + "/pid-tune-plain.json";
    const std::string plainLog = tmp.string() + "/pid-tune-plain.log";
    auto slurpLog = [](const std::string& p) {
        std::ifstream l(p);
        return std::string(std::istreambuf_iterator<char>(l), {});
    };
    int plainRc = std::system((cli + "--notch none --out " + plain + " 2>" + plainLog).c_str());
    // The injection's heartbeat watchdog (30 ms) trips when the machine starves AxisTune's heartbeat thread or
    // LinuxCNC's non-realtime servo thread (seen twice in CI's de-locale pass, started beside the GUI tests at
    // ctest -j2): the run is then refused and nothing is applied, as it must be. Once more, saying so.
    if (plainRc != 0 && slurpLog(plainLog).find("the heartbeat was lost") != std::string::npos) {
        std::printf("[ note ] pid-tune refused: the injection's heartbeat was lost under load; run again\n");
        plainRc = std::system((cli + "--notch none --out " + plain + " 2>" + plainLog).c_str());
    }
    ASSERT_EQ(plainRc, 0) << "pid-tune --notch none exit " << WEXITSTATUS(plainRc) << ": " << slurpLog(plainLog);
    const double plainCrossover = readJson(plain).at("proposed").at("predicted").at("crossover_Hz").get<double>();

    const std::string out = tmp.string() + "/pid-tune.json";
    // With a move out and back (5 mm at 50 mm/s, 1000 mm/s²) run after the verification: issue 17 asks the measured
    // following error of a given move within 10 % of the prediction.
    const std::string log = tmp.string() + "/pid-tune.log";
    int rc = std::system((cli + "--apply --move 5:50:1000 --out " + out + " 2>" + log).c_str());
    if (rc != 0 && slurpLog(log).find("the heartbeat was lost") != std::string::npos) { // as above
        std::printf("[ note ] pid-tune --apply refused: the injection's heartbeat was lost under load; run again\n");
        rc = std::system((cli + "--apply --move 5:50:1000 --out " + out + " 2>" + log).c_str());
    }
    if (rc != 0) { // say why (a refusal names its reason in the log and the JSON)
        std::ifstream l(log);
        ADD_FAILURE() << "pid-tune --apply exit " << WEXITSTATUS(rc) << ": "
                      << std::string(std::istreambuf_iterator<char>(l), {});
        return;
    }
    const auto j = readJson(out);
    {
        const auto& mv = j.at("move").at("proposed");
        ASSERT_TRUE(mv.contains("measured_peak_following_error")) << j.at("move").dump(2);
        const double predictedFe = mv.at("predicted_peak_following_error").get<double>();
        const double measuredFe = mv.at("measured_peak_following_error").get<double>();
        EXPECT_GT(measuredFe, 0.0);
        EXPECT_NEAR(measuredFe / predictedFe, 1.0, 0.10) << "predicted " << predictedFe << ", measured " << measuredFe;
        EXPECT_TRUE(j.at("move").at("error_previous_target").get<bool>()); // LinuxCNC 2.9's default
        RecordProperty("move_following_error_predicted", model::formatShortest(predictedFe));
        RecordProperty("move_following_error_measured", model::formatShortest(measuredFe));
    }
    EXPECT_TRUE(j.at("applied").get<bool>());
    EXPECT_EQ(j.at("drive_input"), "torque");
    expectVerifiedMargins(j);
    const auto& predicted = j.at("proposed").at("predicted");
    const auto& measured = j.at("verified").at("measured");
    EXPECT_EQ(j.at("proposed").at("rules").size(), 6u); // crossover, P, I, D, FF2, FF1
    ASSERT_TRUE(j.at("proposed").contains("notch")) << j.dump(2);
    EXPECT_NEAR(j.at("proposed").at("notch").at("f0_Hz").get<double>() / fr, 1.0, 0.02);
    EXPECT_GE(predicted.at("crossover_Hz").get<double>(), 1.1 * plainCrossover);
    EXPECT_GE(measured.at("crossover_Hz").get<double>(), 1.1 * plainCrossover);
    RecordProperty("crossover_without_notch_Hz", model::formatShortest(plainCrossover));
    RecordProperty("crossover_with_notch_Hz", model::formatShortest(measured.at("crossover_Hz").get<double>()));
    for (const char* k : {"Pgain", "Igain", "Dgain", "FF1", "FF2"}) {
        const double proposed = j.at("proposed").at("gains").at(k).get<double>();
        // halcmd shows 7 significant digits; a gain of 0 reads back 0.
        EXPECT_NEAR(getp(std::string("pid.x.") + k), proposed, 1e-6 * std::abs(proposed)) << k;
    }
    EXPECT_NEAR(getp("axistune-notch.f0"), j.at("proposed").at("notch").at("f0_Hz").get<double>(), 1e-4);

    ASSERT_EQ(std::system((std::string(AXISTUNE_CLI) + " pid-tune --connect hal: --axis pid.x --remove-notch "
                                                       ">/dev/null")
                              .c_str()),
              0);
    EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), sigBefore);
    EXPECT_EQ(halText({"-s", "show", "funct"}), funBefore);
}

// Issue 17 item 7: the NC export for LinuxCNC, checked by loading it. From the sample profile of the test machine,
// `export --format linuxcnc-hal` gives setp lines that halcmd loads into the running session, and `export --format
// linuxcnc` gives [JOINT_0] keys that a session started from an INI beginning with them reads (LinuxCNC takes the
// first value of a key); in both, every pid gain in HAL equals the profile's within halcmd's seven digits.
TEST_F(HalTestbed, NcExportForLinuxCncLoadsIntoHal)
{
    const ScopedTempDir tmp("lcnc-export");
    const std::filesystem::path dir = tmp.path();
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::filesystem::permissions(dir, std::filesystem::perms::all); // the HAL user reads the files
    const std::string profilePath = std::string(AXISTUNE_SOURCE_DIR) + "/resources/samples/linuxcnc-profile.json";
    const std::string db = (dir / "s.db").string();
    const std::string cli = std::string(AXISTUNE_CLI);
    ASSERT_EQ(std::system((cli + " profile import --db " + db + " --in " + profilePath + " >/dev/null").c_str()), 0);
    for (const char* f : {"linuxcnc", "linuxcnc-hal"})
        ASSERT_EQ(std::system((cli + " export --db " + db + " --machine lcnc-testbed --format " + f + " --out " +
                               (dir / f).string() + " >/dev/null 2>&1")
                                  .c_str()),
                  0)
            << f;
    std::ifstream pf(profilePath);
    const auto profile = nlohmann::json::parse(pf);
    const auto& params = profile.at("axes").at(0).at("parameters");
    auto expectGains = [&](const char* what) {
        for (const auto& [k, v] : params.items())
            EXPECT_NEAR(getp("pid.x." + k), v.get<double>(), 5e-7 * std::abs(v.get<double>())) << what << " " << k;
    };

    startBed(1000000);
    halText({"-f", (dir / "linuxcnc-hal").string()});
    expectGains("setp lines");

    std::ifstream fi(dir / "linuxcnc"), ti(std::string(AXISTUNE_SOURCE_DIR) + "/linuxcnc/testbed/axistune-testbed.ini");
    const std::string fragment((std::istreambuf_iterator<char>(fi)), {});
    const std::string testbed((std::istreambuf_iterator<char>(ti)), {});
    // Merged as a user merges it: each exported [JOINT_0] key replaces that key's line in the machine's [JOINT_0]
    // section (LinuxCNC reads only the first section of a name), keys the section lacks are added at its start.
    auto exported = device::hal::parseIni("export", fragment);
    ASSERT_TRUE(exported) << exported.error().detail;
    std::istringstream lines(testbed);
    std::string merged, line, section;
    std::set<std::string> written;
    while (std::getline(lines, line)) {
        if (!line.empty() && line.front() == '[') {
            section = line.substr(1, line.find(']') - 1);
            merged += line + "\n";
            if (section == "JOINT_0")
                for (const auto& e : exported->entries)
                    if (e.section == "JOINT_0" && !std::regex_search(testbed, std::regex("\\n" + e.key + " = ")))
                        merged += e.key + " = " + e.value + "\n", written.insert(e.key);
            continue;
        }
        const auto eq = line.find(" = ");
        const std::string key = eq == std::string::npos ? std::string() : line.substr(0, eq);
        const auto* e = section == "JOINT_0" && !key.empty() ? exported->find("JOINT_0", key) : nullptr;
        merged += (e ? key + " = " + e->value : line) + "\n";
        if (e)
            written.insert(key);
    }
    EXPECT_EQ(written.size(), exported->entries.size());
    const std::string ini = (dir / "exported.ini").string();
    {
        std::ofstream o(ini);
        o << merged;
    }
    ASSERT_TRUE(runScript({"stop"}));
    ASSERT_TRUE(runScript({"start", "--ini", ini}));
    expectGains("INI keys");
}

// `autotune` is the drive velocity loop's one-button tuner; a LinuxCNC joint is a position PID the NC closes, and
// its tuner is pid-tune: autotune says so (exit 2) before anything is inserted into HAL.
TEST_F(HalTestbed, AutotuneOnAPositionPidNamesPidTuneAndChangesNothing)
{
    startBed(1000000);
    const auto sigBefore = halText({"-s", "show", "sig"});
    const auto functBefore = halText({"-s", "show", "funct"});
    const ScopedTempDir tmp("autotune-hal");
    const std::string out = tmp.string() + "/autotune-hal.err";
    const int rc =
        std::system((std::string(AXISTUNE_CLI) + " autotune --connect hal: --axis pid.x >/dev/null 2>" + out).c_str());
    EXPECT_EQ(WEXITSTATUS(rc), 2);
    std::ifstream f(out);
    const std::string err((std::istreambuf_iterator<char>(f)), {});
    EXPECT_NE(err.find("is a position PID the NC closes"), std::string::npos) << err;
    EXPECT_NE(err.find("pid-tune"), std::string::npos) << err;
    EXPECT_EQ(halText({"-s", "show", "sig"}), sigBefore);
    EXPECT_EQ(halText({"-s", "show", "funct"}), functBefore);
}

// Issue 17 item 3's undo: `pid-tune --undo RESULT.json` puts back the gains that ran before an applied pid-tune (its
// `running.gains`) and removes the notch it inserted: every gain reads back as before (halcmd's 7 digits), the nets and
// functions are as before the tune; a second undo is refused with exit 4 and changes nothing (HAL no longer holds what
// the run applied); the result of a run that applied nothing is refused with exit 2 naming the field.
TEST_F(HalTestbed, CliPidTuneUndoPutsBackTheGainsThatRanBefore)
{
    startBed(1000000);
    ::setenv("AXISTUNE_HALCMD", (kScript + " halcmd").c_str(), 1);
    const std::string sigBefore = netsOf(halText({"-s", "show", "sig"}));
    const std::string funBefore = halText({"-s", "show", "funct"});
    const std::vector<std::string> keys{"Pgain", "Igain", "Dgain", "FF1", "FF2"};
    std::map<std::string, double> before;
    for (const auto& k : keys)
        before[k] = getp("pid.x." + k);
    const ScopedTempDir tmp("pid-tune-undo");
    const std::string dir = tmp.string();
    const std::string result = dir + "/pid-tune-undo.json";
    const std::string log = dir + "/pid-tune-undo.log";
    auto slurpLog = [&] {
        std::ifstream l(log);
        return std::string(std::istreambuf_iterator<char>(l), {});
    };
    const std::string base = std::string(AXISTUNE_CLI) + " pid-tune --connect hal: --axis pid.x ";
    const std::string tune = base + "--amplitude 0.2 --pm 50 --gm 8 --apply --out " + result + " >/dev/null 2>" + log;
    int rc = std::system(tune.c_str());
    if (rc != 0 && slurpLog().find("the heartbeat was lost") != std::string::npos) { // as in the test above
        std::printf("[ note ] pid-tune --apply refused: the injection's heartbeat was lost under load; run again\n");
        rc = std::system(tune.c_str());
    }
    ASSERT_EQ(rc, 0) << slurpLog();
    EXPECT_NE(getp("pid.x.Pgain"), before["Pgain"]);
    ASSERT_NE(halText({"-s", "show", "funct"}), funBefore) << "the run inserted no notch: the undo's removal is untested";

    ASSERT_EQ(std::system((base + "--undo " + result + " >" + dir + "/undo.json 2>" + log).c_str()), 0) << slurpLog();
    for (const auto& k : keys)
        EXPECT_NEAR(getp("pid.x." + k), before[k], 1e-6 * std::abs(before[k])) << k;
    EXPECT_EQ(netsOf(halText({"-s", "show", "sig"})), sigBefore);
    EXPECT_EQ(halText({"-s", "show", "funct"}), funBefore);
    std::ifstream undoOut(dir + "/undo.json");
    const auto undone = nlohmann::json::parse(undoOut);
    EXPECT_EQ(undone.at("undone").size(), keys.size());
    EXPECT_TRUE(undone.at("notch_removed").get<bool>());
    // Its journal: the five gains, then the notch removed (it runs no more: 1 → 0).
    ASSERT_EQ(undone.at("journal").size(), keys.size() + 1) << undone.dump(2);
    EXPECT_EQ(undone.at("journal").back(),
              nlohmann::json::parse(R"({"key": "axistune-notch", "old": 1.0, "new": 0.0})"));

    EXPECT_EQ(WEXITSTATUS(std::system((base + "--undo " + result + " >/dev/null 2>" + log).c_str())), 4);
    for (const auto& k : keys)
        EXPECT_NEAR(getp("pid.x." + k), before[k], 1e-6 * std::abs(before[k])) << k;

    const std::string dry = dir + "/pid-tune-dry.json";
    std::ofstream(dry) << R"({"axis": "pid.x", "applied": false})";
    EXPECT_EQ(WEXITSTATUS(std::system((base + "--undo " + dry + " >/dev/null 2>" + log).c_str())), 2);
    EXPECT_NE(slurpLog().find("'applied'"), std::string::npos) << slurpLog();
}

// SPDX-License-Identifier: GPL-3.0-or-later
// End to end, issue 18 items 5 and 6: `axistune-cli autotune` on sim:vmc X, sim:dd-table C and sim:two-inertia A,
// then an ordinary `capture --test frf` with the parameters it applied (the embedded drive starts from its preset in
// every process, so the capture writes them with --set): the margins of the re-measured open velocity loop
// L = T/(1-T) (dsp::loopMargins on the valid lines, smallest over every crossover) are at least the standard style's
// 45 deg / 6 dB (issue 18) and within 3 deg / 1 dB of what `final` reports (issue 18); the closed-loop -3 dB bandwidth
// is at least that of the wizards' hand sequence on the same machine, measured the same way. The hand sequence: the
// notch wizard's rule (`notch` = tuning::analyseNotches with its defaults) on a multisine FRF of the running loop,
// then the velocity wizard's default rule (`velocity-loop --method inertia`: chapter 5, omega_l = 24 Hz, k = 10, on
// the drive's J_m = velocity.inertia, with the recommended position gain) = tuning::designVelocityLoop.
#include "core/autotune/AutoTune.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/io/FrfCsv.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/app/cli/CliRunner.h"
#include "tests/app/cli/SimDriveProcess.h"

using axistune::testing::makeTempDir;
using axistune::testing::readFileText;
using axistune::testing::runCli;

namespace {

struct Measured {
    double pmDeg = 0.0, gmDb = 0.0, bwHz = 0.0;
    bool ok = false;
};

/// Margins and -3 dB bandwidth of a drive FRF file (the closed velocity loop T).
Measured measure(const std::string& path)
{
    Measured m;
    auto frf = axistune::io::readFrfCsvFile(path);
    EXPECT_TRUE(frf.ok()) << path;
    if (!frf.ok())
        return m;
    EXPECT_EQ(frf->metadata.text("measurement"), "complementary");
    const auto open = axistune::dsp::openLoopFromClosedLoop(*frf, axistune::dsp::LoopMeasurement::Complementary);
    axistune::dsp::FrequencyResponse l;
    std::vector<double> f;
    std::vector<std::complex<double>> t;
    for (std::size_t i = 0; i < open.size(); ++i)
        if (open.valid[i] && frf->valid[i]) {
            l.push(open.freqHz[i], open.h[i], open.coherence[i], true);
            f.push_back(frf->freqHz[i]);
            t.push_back(frf->h[i]);
        }
    const auto margins = axistune::dsp::loopMargins(l);
    const auto bw = axistune::autotune::closedLoopBandwidthHz(f, t);
    m.pmDeg = margins.phaseMarginDeg;
    m.gmDb = margins.gainMarginDb;
    m.bwHz = bw.value_or(0.0);
    m.ok = std::isfinite(m.pmDeg) && std::isfinite(m.gmDb) && bw.has_value();
    return m;
}

std::string sets(const nlohmann::json& params)
{
    std::string s;
    for (const auto& [k, v] : params.items())
        s += "--set " + k + "=" + nlohmann::json(v.get<double>()).dump() + " ";
    return s;
}

std::string frfCapture(const std::string& machine, const std::string& axis, double amplitudePct)
{
    return "capture --connect sim:" + machine + " --axis " + axis +
           " --test frf --method multisine --fmin 20 --fmax 3900 --spacing-hz 10 --adaptive --time-budget 5 "
           "--amplitude-pct " +
           nlohmann::json(amplitudePct).dump() + " ";
}

void tuneAndCheck(const std::string& machine, const std::string& axis)
{
    const auto dir = makeTempDir("autotune-" + machine);
    const auto result = (dir / "result.json").string();
    const auto r = runCli("autotune --connect sim:" + machine + " --axis " + axis + " --out " + result);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(readFileText(result));
    EXPECT_EQ(j["outcome"], "applied");
    const std::vector<std::string> names{"safety-envelope", "current-loop", "frf",    "notches", "velocity-pi",
                                         "position",        "move",         "verify", "apply"};
    // In this order; velocity-pi ... verify appear again when the verification sent the design back.
    std::size_t next = 0;
    for (const auto& step : j["steps"]) {
        const auto name = step["name"].get<std::string>();
        if (next < names.size() && name == names[next])
            ++next;
        else
            EXPECT_TRUE(name == "velocity-pi" || name == "position" || name == "move" || name == "verify") << name;
        EXPECT_TRUE(step["measured"].is_object());
        EXPECT_TRUE(step["chosen"].is_object());
        EXPECT_FALSE(step["rule"].get<std::string>().empty());
    }
    EXPECT_EQ(next, names.size()) << j.dump(1);
    const auto& fin = j["final"];
    for (const char* k : {"phase_margin_deg", "gain_margin_dB", "velocity_bandwidth_Hz", "position_bandwidth_Hz",
                          "settling_time_s", "peak_following_error", "motion_time_s"})
        EXPECT_TRUE(fin.contains(k) && fin[k].is_number()) << k << ": " << fin.dump(1);
    ASSERT_TRUE(fin["parameters"].contains("velocity.kp"));
    // issue 18 "Measured": at most 30 s of motion for one position.
    EXPECT_LE(fin["motion_time_s"].get<double>(), 30.0);
    const double pct = j["steps"][2]["chosen"]["amplitude_pct"].get<double>();

    // An ordinary capture afterwards, with what autotune applied.
    const auto after = (dir / "after.csv").string();
    const auto c = runCli(frfCapture(machine, axis, pct) + sets(fin["parameters"]) + "--out " + after);
    ASSERT_EQ(c.exitCode, 0) << c.err;
    const auto m = measure(after);
    ASSERT_TRUE(m.ok);
    EXPECT_GE(m.pmDeg, 45.0);
    EXPECT_GE(m.gmDb, 6.0);
    EXPECT_NEAR(m.pmDeg, fin["phase_margin_deg"].get<double>(), 3.0);
    EXPECT_NEAR(m.gmDb, fin["gain_margin_dB"].get<double>(), 1.0);

    // The wizards' hand sequence on the same machine, measured the same way: the notch wizard's notches, then the
    // velocity wizard with either of its rules at their defaults. A hand result that misses the 45 deg / 6 dB is no
    // tuning to beat (printed, not compared); the running loop as found is compared too. At least one is compared.
    const auto handFrf = (dir / "hand-frf.csv").string();
    const auto h1 = runCli(frfCapture(machine, axis, pct) + "--out " + handFrf);
    ASSERT_EQ(h1.exitCode, 0) << h1.err;
    const auto n = runCli("notch --frf " + handFrf);
    ASSERT_EQ(n.exitCode, 0) << n.err;
    nlohmann::json notchParams = nlohmann::json::object();
    const auto notches = nlohmann::json::parse(n.out);
    for (const auto& notch : notches["notches"])
        for (const auto& [k, v] : notch["parameters"].items())
            notchParams[k] = v;
    int compared = 0;
    const auto compare = [&](const std::string& what, const nlohmann::json& params) {
        const auto out = (dir / "hand-after.csv").string();
        const auto h2 = runCli(frfCapture(machine, axis, pct) + sets(params) + "--out " + out);
        ASSERT_EQ(h2.exitCode, 0) << h2.err;
        const auto hm = measure(out);
        // An unbounded gain margin is no measurement of a loop with a delay (its phase always crosses -180 deg
        // below the trace rate): such a hand result is not compared; no gain crossover (PM inf) is.
        const bool meets = hm.bwHz > 0.0 && hm.pmDeg >= 45.0 && std::isfinite(hm.gmDb) && hm.gmDb >= 6.0;
        std::cout << machine << " " << axis << ": autotune PM " << m.pmDeg << " deg, GM " << m.gmDb << " dB, BW "
                  << m.bwHz << " Hz; " << what << ": PM " << hm.pmDeg << " deg, GM " << hm.gmDb << " dB, BW " << hm.bwHz
                  << " Hz" << (meets ? "" : " (misses 45 deg / 6 dB: not compared)") << "\n";
        if (!meets)
            return;
        ++compared;
        EXPECT_GE(m.bwHz, hm.bwHz) << what << ": " << params.dump();
    };
    compare("running loop as found", nlohmann::json::object());
    for (const std::string& rule : std::vector<std::string>{"--method inertia", "--method margins --frf " + handFrf}) {
        const auto v =
            runCli("velocity-loop --connect sim:" + machine + " --axis " + axis + " " + rule + " --with-position-gain");
        if (v.exitCode != 0) {
            std::cout << machine << " " << axis << ": velocity-loop " << rule << " refused: " << v.err;
            continue;
        }
        nlohmann::json hand = notchParams;
        const auto velocity = nlohmann::json::parse(v.out);
        for (const auto& [k, x] : velocity["parameters"].items())
            hand[k] = x;
        compare("hand sequence, velocity-loop " + rule.substr(0, rule.find(" --frf")), hand);
    }
    EXPECT_GE(compared, 1);
    std::filesystem::remove_all(dir);
}

} // namespace

TEST(Autotune, VmcXMeetsTheMarginsMeasuredAfterwardsAndBeatsTheHandSequence)
{
    tuneAndCheck("vmc", "X");
}
TEST(Autotune, DdTableCMeetsTheMarginsMeasuredAfterwardsAndBeatsTheHandSequence)
{
    tuneAndCheck("dd-table", "C");
}
TEST(Autotune, TwoInertiaAMeetsTheMarginsMeasuredAfterwardsAndBeatsTheHandSequence)
{
    tuneAndCheck("two-inertia", "A");
}

// The refusals over Modbus: axistune-simdrive keeps its parameters between connections, so `params` reads every
// parameter of the axis before and after the refused run (issue 18 item 6: nothing applied, parameters unchanged).
void refusedWithParametersUnchanged(const std::string& simdriveArgs, const std::string& axis,
                                    const std::string& options, const std::string& reason)
{
    axistune::testing::SimDrive srv(simdriveArgs);
    ASSERT_GT(srv.port(), 0);
    const std::string uri = "modbus://127.0.0.1:" + std::to_string(srv.port());
    const auto before = runCli("params --connect " + uri + " --axis " + axis);
    ASSERT_EQ(before.exitCode, 0) << before.err;
    const auto dir = makeTempDir("autotune-refuse");
    const auto result = (dir / "result.json").string();
    const auto r = runCli("autotune --connect " + uri + " --axis " + axis + " " + options + " --out " + result);
    EXPECT_EQ(r.exitCode, 4) << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
    const auto j = nlohmann::json::parse(readFileText(result));
    EXPECT_EQ(j["outcome"], "refused");
    EXPECT_NE(j["reason"].get<std::string>().find(reason), std::string::npos);
    EXPECT_FALSE(j.contains("final"));
    const auto after = runCli("params --connect " + uri + " --axis " + axis);
    ASSERT_EQ(after.exitCode, 0) << after.err;
    const auto pb = nlohmann::json::parse(before.out)["parameters"];
    const auto pa = nlohmann::json::parse(after.out)["parameters"];
    EXPECT_GT(pb.size(), 30u);
    EXPECT_EQ(pa, pb);
    std::filesystem::remove_all(dir);
}

/// A variant of vmc written into `dir`: axis X with one parameter changed (docs/simulator.md), for
/// axistune-simdrive --machine. Returns the file's path.
std::string vmcVariant(const std::filesystem::path& dir, const std::string& key, double value, const std::string& unit)
{
    auto preset = nlohmann::json::parse(readFileText(AXISTUNE_SOURCE_RESOURCE_DIR "/machines/vmc.json"));
    for (auto& a : preset["axes"])
        if (a["name"] == "X")
            a["parameters"][key] = {{"value", value}, {"unit", unit}, {"source", "test variant"}};
    const auto machine = (dir / ("vmc-" + key + ".json")).string();
    std::ofstream f(machine);
    f << preset.dump(1);
    return machine;
}

TEST(Autotune, ResonanceAtTheRequiredBandwidthIsRefusedAndTheParametersAreUnchanged)
{
    // dd-table C has a resonance at 600 Hz (resources/machines/dd-table.json): a required 600 Hz velocity crossover
    // puts it at the required bandwidth.
    refusedWithParametersUnchanged("--preset dd-table", "C", "--min-bandwidth-hz 600",
                                   "resonance too close to the required bandwidth");
}

TEST(Autotune, DriveFaultIsRefusedAndTheParametersAreUnchanged)
{
    // The drive faults 0.5 s (machine time) into a test: the first FRF pass (docs/modbus.md fault injection).
    refusedWithParametersUnchanged("--preset vmc --fault drive-fault:0.5", "X", "", "drive fault");
}

TEST(Autotune, BadOptionsExit2)
{
    EXPECT_EQ(runCli("autotune --connect sim:vmc --axis X --style soft").exitCode, 2);
    EXPECT_EQ(runCli("autotune --connect sim:vmc --axis X --time-budget 0").exitCode, 2);
    EXPECT_EQ(runCli("autotune --connect sim:vmc --axis X --min-bandwidth-hz -1").exitCode, 2);
    EXPECT_EQ(runCli("autotune --connect sim:vmc --axis Q").exitCode, 2);
}

TEST(Autotune, BacklashLargerThanTheSettlingWindowIsRefusedAndTheParametersAreUnchanged)
{
    // A variant of vmc written by the test: X with 20 um of play between nut and table (plant.backlash,
    // docs/simulator.md), served by axistune-simdrive --machine. The move step's reversal measures about 17 um of lost
    // motion at zero torque (the play less the motor-side friction's wind-up, tests/core/autotune "Backlash"), far
    // above the 2 um width of the +-1 um settling window.
    const auto dir = makeTempDir("autotune-backlash");
    const auto machine = vmcVariant(dir, "plant.backlash", 20.0, "um");
    refusedWithParametersUnchanged("--machine " + machine, "X", "", "backlash larger than the settling window");
    std::filesystem::remove_all(dir);
}

TEST(Autotune, FrictionThatHoldsTheAxisDuringTheFrfIsRefusedForThatReason)
{
    // vmc X with 0.5 N m of Coulomb friction (the preset has 0.305 N m): the FRF's excitation does not make the axis
    // slide, and the friction's sign smoothing (0.02 rad/s) acts as a damper of up to 0.5/0.02 = 25 N m s/rad
    // (the FRF reads 3.9 N m s/rad at its amplitudes, where the axis slides part of the time). Designed on that plant
    // alone, the PI crossed over at 440 Hz with kp = 2.9 N m s/rad; the move then commanded -8553 N m and the drive
    // faulted (the run was refused as a drive fault, not for its reason). Now the PI must keep its margins on the plant
    // in motion too (SlidingPlant.h), none does at 40 Hz, and the run is refused before the gains are written, naming
    // the friction.
    const auto dir = makeTempDir("autotune-friction");
    const auto machine = vmcVariant(dir, "plant.coulomb_motor", 0.5, "Nm");
    refusedWithParametersUnchanged("--machine " + machine, "X", "", "friction holds the axis during the FRF");
    std::filesystem::remove_all(dir);
}

TEST(Autotune, AmplitudesNeedThreeIncreasingValues)
{
    EXPECT_EQ(runCli("autotune --connect sim:vmc --axis X --amplitudes 5,10").exitCode, 2);
    EXPECT_EQ(runCli("autotune --connect sim:vmc --axis X --amplitudes 10,5,20").exitCode, 2);
}

TEST(Autotune, UndoPutsBackTheValuesBeforeTheRunAndRefusesWhenTheyChangedSince)
{
    // Over Modbus (the drive keeps its parameters between processes): every parameter read before a tune, after it
    // (some differ: the run applied them), and after --undo (all equal to before, as the JSON of `params`).
    axistune::testing::SimDrive srv("--preset vmc");
    ASSERT_GT(srv.port(), 0);
    const std::string uri = "modbus://127.0.0.1:" + std::to_string(srv.port());
    auto params = [&] {
        const auto p = runCli("params --connect " + uri + " --axis X");
        EXPECT_EQ(p.exitCode, 0) << p.err;
        return nlohmann::json::parse(p.out)["parameters"];
    };
    const auto before = params();
    const auto dir = makeTempDir("autotune-undo");
    const auto result = (dir / "result.json").string();
    const auto r = runCli("autotune --connect " + uri + " --axis X --out " + result);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto applied = params();
    EXPECT_NE(applied, before);
    const auto fin = nlohmann::json::parse(readFileText(result))["final"]["parameters"];
    ASSERT_FALSE(fin.empty());

    const auto u = runCli("autotune --undo " + result + " --connect " + uri);
    ASSERT_EQ(u.exitCode, 0) << u.err;
    EXPECT_EQ(params(), before);
    const auto out = nlohmann::json::parse(u.out);
    EXPECT_EQ(out["undone"].size(), fin.size());
    // `params` prints 8 significant digits of the drive's float32 values: equal within 1e-7 relative.
    for (const auto& e : out["undone"]) {
        const std::string k = e["key"];
        EXPECT_NEAR(e["was"].get<double>(), applied[k].get<double>(), 1e-7 * std::abs(applied[k].get<double>())) << k;
        EXPECT_NEAR(e["now"].get<double>(), before[k].get<double>(), 1e-7 * std::abs(before[k].get<double>())) << k;
    }

    // Again: the drive no longer holds what the run applied; refused (exit 4) and nothing written.
    const auto again = runCli("autotune --undo " + result + " --connect " + uri);
    EXPECT_EQ(again.exitCode, 4) << again.err;
    EXPECT_NE(again.err.find("changed since"), std::string::npos) << again.err;
    EXPECT_EQ(params(), before);

    // A refused run has nothing to undo; another axis and tuning options are refused before connecting.
    auto j = nlohmann::json::parse(readFileText(result));
    j["outcome"] = "refused";
    const auto refused = (dir / "refused.json").string();
    {
        std::ofstream f(refused);
        f << j.dump();
    }
    const auto nr = runCli("autotune --undo " + refused + " --connect " + uri);
    EXPECT_EQ(nr.exitCode, 2);
    EXPECT_NE(nr.err.find("only an applied run can be undone"), std::string::npos) << nr.err;
    EXPECT_EQ(runCli("autotune --undo " + result + " --connect " + uri + " --axis Y").exitCode, 2);
    EXPECT_EQ(runCli("autotune --undo " + result + " --connect " + uri + " --style stiff").exitCode, 2);
    EXPECT_EQ(runCli("autotune --connect " + uri + " --axis X --force").exitCode, 2);
    EXPECT_EQ(runCli("autotune --connect " + uri).exitCode, 2); // no --axis for a tune
    std::filesystem::remove_all(dir);
}

TEST(Autotune, UndoOfAResultWithoutTheValuesBeforeNamesTheField)
{
    const auto dir = makeTempDir("autotune-undo-bad");
    const auto path = (dir / "r.json").string();
    {
        std::ofstream f(path);
        f << R"({"outcome":"applied","axis":"X","final":{"parameters":{"velocity.kp":1.5}},)"
             R"("steps":[{"name":"apply","measured":{}}]})";
    }
    const auto r = runCli("autotune --undo " + path + " --connect sim:vmc");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("steps[apply].measured.before.velocity.kp"), std::string::npos) << r.err;
    std::filesystem::remove_all(dir);
}

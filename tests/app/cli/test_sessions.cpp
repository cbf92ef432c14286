// SPDX-License-Identifier: GPL-3.0-or-later
// Sessions from the CLI (--db FILE --machine NAME on capture/analysis commands, app/cli/SessionRecorder.h)
// end to end: recorded kinds and statuses, inputs/results in `session show`, the capture CSV in
// `session export`, failed runs, unknown machines.
#include "core/io/CaptureCsv.h"
#include "core/io/FrfCsv.h"
#include "tests/app/cli/CliRunner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace axistune;
using axistune::testing::makeTempDir;
using axistune::testing::readFileText;
using axistune::testing::runCli;

namespace {

const std::string kResources = std::string(AXISTUNE_SOURCE_RESOURCE_DIR);
const std::string kProfile = kResources + "/samples/vmc-profile.json";
const std::string kMotor = kResources + "/samples/motor-rotary.json";

std::string makeStore(const std::filesystem::path& dir)
{
    const auto db = (dir / "s.db").string();
    const auto r = runCli("profile import --db " + db + " --in " + kProfile);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return db;
}

nlohmann::json sessionList(const std::string& db)
{
    const auto r = runCli("session list --db " + db);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return nlohmann::json::parse(r.out);
}

nlohmann::json sessionShow(const std::string& db, int id)
{
    const auto r = runCli("session show --db " + db + " --id " + std::to_string(id));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return nlohmann::json::parse(r.out);
}

const nlohmann::json* resultNamed(const nlohmann::json& show, const std::string& name)
{
    for (const auto& r : show["results"]) {
        if (r["name"] == name)
            return &r;
    }
    return nullptr;
}

}  // namespace

TEST(CliSessions, CaptureAndCurrentLoopAreRecordedWithInputsCapturesAndResults)
{
    const auto dir = makeTempDir("sessions");
    const auto db = makeStore(dir);
    const auto trace = (dir / "step.csv").string();
    auto r = runCli("capture --connect sim:vmc --axis X --test step --amplitude 5 --duration 0.1 --out " + trace
                    + " --db " + db + " --machine vmc --operator ana --note 'first step'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("recorded session 2 (completed)"), std::string::npos) << r.err;
    r = runCli("current-loop --motor " + kMotor + " --db " + db + " --machine vmc");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto printed = nlohmann::json::parse(r.out);

    const auto list = sessionList(db);
    ASSERT_EQ(list.size(), 3u);  // profile-import, capture, current-loop
    EXPECT_EQ(list[0]["kind"], "profile-import");
    EXPECT_EQ(list[1]["kind"], "capture");
    EXPECT_EQ(list[1]["status"], "completed");
    EXPECT_EQ(list[1]["machine"], "vmc");
    EXPECT_EQ(list[1]["axis"], "X");
    EXPECT_EQ(list[1]["operator"], "ana");
    EXPECT_EQ(list[1]["note"], "first step");
    EXPECT_EQ(list[1]["captures"], 1);
    EXPECT_EQ(list[2]["kind"], "current-loop");
    EXPECT_EQ(list[2]["status"], "completed");
    EXPECT_EQ(list[2]["axis"], "");
    EXPECT_EQ(list[2]["captures"], 0);

    const auto cap = sessionShow(db, 2);
    EXPECT_EQ(cap["inputs"]["command"], "capture");
    EXPECT_EQ(cap["inputs"]["options"]["--test"], "step");
    EXPECT_EQ(cap["inputs"]["options"]["--amplitude"], "5");
    EXPECT_EQ(cap["inputs"]["options"]["--out"], trace);
    EXPECT_FALSE(cap["inputs"]["options"].contains("--db"));
    EXPECT_EQ(cap["inputs"]["defaults"]["--seed"], "1");
    ASSERT_EQ(cap["captures"].size(), 1u);
    EXPECT_EQ(cap["captures"][0]["name"], "out");
    const auto stdoutResult = resultNamed(cap, "stdout");
    ASSERT_NE(stdoutResult, nullptr);
    EXPECT_EQ((*stdoutResult)["data"]["out"], trace);

    const auto cl = sessionShow(db, 3);
    ASSERT_EQ(cl["inputs"]["files"].size(), 1u);
    const auto& motorFile = cl["inputs"]["files"][0];
    EXPECT_EQ(motorFile["option"], "--motor");
    EXPECT_EQ(motorFile["path"], kMotor);
    EXPECT_EQ(motorFile["bytes"], readFileText(kMotor).size());
    EXPECT_EQ(motorFile["content"], nlohmann::json::parse(readFileText(kMotor)));
    EXPECT_EQ(motorFile["sha256"].get<std::string>().size(), 64u);
    const auto clResult = resultNamed(cl, "stdout");
    ASSERT_NE(clResult, nullptr);
    EXPECT_EQ((*clResult)["data"], printed);

    // session export writes the recorded trace as a capture CSV equal to the one the command wrote.
    const auto folder = dir / "export2";
    r = runCli("session export --db " + db + " --id 2 --out " + folder.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::filesystem::path exported;
    for (const auto& e : std::filesystem::directory_iterator(folder)) {
        const auto name = e.path().filename().string();
        if (name.rfind("capture_", 0) == 0 && name.size() > 8 && name.substr(name.size() - 8) == "_out.csv")
            exported = e.path();
    }
    ASSERT_FALSE(exported.empty());
    const auto original = io::readCaptureCsvFile(trace);
    const auto copy = io::readCaptureCsvFile(exported.string());
    ASSERT_TRUE(original) << original.error().detail;
    ASSERT_TRUE(copy) << copy.error().detail;
    ASSERT_EQ(copy->channels.size(), original->channels.size());
    for (std::size_t k = 0; k < original->channels.size(); ++k) {
        EXPECT_EQ(copy->channels[k].name, original->channels[k].name);
        EXPECT_EQ(copy->channels[k].data, original->channels[k].data) << original->channels[k].name;  // bit-exact
    }
    EXPECT_EQ(copy->metadata.number("fs_Hz").value(), original->metadata.number("fs_Hz").value());
}

TEST(CliSessions, FrfAnalysisStoresTheFrfAsACapture)
{
    const auto dir = makeTempDir("sessions-frf");
    const auto db = makeStore(dir);
    const auto trace = (dir / "step.csv").string();
    ASSERT_EQ(runCli("capture --connect sim:vmc --axis X --test step --amplitude 5 --duration 0.25 --out " + trace).exitCode, 0);
    const auto frf = (dir / "frf.csv").string();
    const auto r = runCli("frf --in " + trace + " --input torque_cmd_Nm --output motor_vel_rad_s --nperseg 256 --out " + frf
                          + " --db " + db + " --machine vmc");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto show = sessionShow(db, 2);
    EXPECT_EQ(show["session"]["kind"], "frf");
    ASSERT_EQ(show["captures"].size(), 1u);
    EXPECT_EQ(show["captures"][0]["metadata"]["content"], "frf");
    EXPECT_EQ(show["captures"][0]["channels"][0]["name"], "f_Hz");
    const auto written = io::readFrfCsvFile(frf);
    ASSERT_TRUE(written) << written.error().detail;
    EXPECT_EQ(show["captures"][0]["samples"], written->size());  // one row per frequency of the FRF CSV
    // The input capture is named with its digest, not copied.
    ASSERT_EQ(show["inputs"]["files"].size(), 1u);
    EXPECT_EQ(show["inputs"]["files"][0]["bytes"], readFileText(trace).size());
    EXPECT_FALSE(show["inputs"]["files"][0].contains("content"));
}

TEST(CliSessions, FailingCommandRecordsAFailedSessionWithItsInputDigest)
{
    const auto dir = makeTempDir("sessions-fail");
    const auto db = makeStore(dir);
    const auto bad = dir / "abc.json";
    std::ofstream(bad) << "abc";
    const auto r = runCli("current-loop --motor " + bad.string() + " --db " + db + " --machine vmc");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("recorded session 2 (failed)"), std::string::npos) << r.err;
    const auto list = sessionList(db);
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[1]["kind"], "current-loop");
    EXPECT_EQ(list[1]["status"], "failed");
    const auto show = sessionShow(db, 2);
    // SHA-256("abc"), FIPS 180-2 appendix B.1.
    EXPECT_EQ(show["inputs"]["files"][0]["sha256"], "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    EXPECT_EQ(show["inputs"]["files"][0]["bytes"], 3);
    const auto err = resultNamed(show, "error");
    ASSERT_NE(err, nullptr);
    EXPECT_EQ((*err)["data"]["exit_code"], 2);
    EXPECT_NE((*err)["data"]["message"].get<std::string>().find(bad.string()), std::string::npos);

    // 56 bytes: the padding needs a second block. SHA-256 from FIPS 180-2 appendix B.2.
    std::ofstream(bad) << "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
    ASSERT_EQ(runCli("current-loop --motor " + bad.string() + " --db " + db + " --machine vmc").exitCode, 2);
    EXPECT_EQ(sessionShow(db, 3)["inputs"]["files"][0]["sha256"],
              "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(CliSessions, UnknownMachineOrStoreIsExit2AndRunsNothing)
{
    const auto dir = makeTempDir("sessions-unknown");
    const auto db = makeStore(dir);
    const auto trace = (dir / "never.csv").string();
    auto r = runCli("capture --connect sim:vmc --axis X --test step --amplitude 5 --duration 0.1 --out " + trace
                    + " --db " + db + " --machine mill");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("machine 'mill' is not in store " + db), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("machines: vmc"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("axistune-cli profile import --db " + db), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(trace));  // the test did not run
    EXPECT_EQ(sessionList(db).size(), 1u);

    const auto missing = (dir / "none.db").string();
    r = runCli("current-loop --motor " + kMotor + " --db " + missing + " --machine vmc");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("store " + missing + " does not exist"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("profile import"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(missing));

    r = runCli("current-loop --motor " + kMotor + " --db " + db);  // --db needs --machine
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--machine"), std::string::npos) << r.err;
}

TEST(CliSessions, WithoutDbNothingChanges)
{
    const auto r = runCli("current-loop --motor " + kMotor);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err.find("recorded session"), std::string::npos);
    EXPECT_TRUE(nlohmann::json::accept(r.out)) << r.out;
}

// SPDX-License-Identifier: GPL-3.0-or-later
// Files do not depend on the C library's locale (issue 16): the NC exports of every format, the
// machine profile and parameter CSV, a capture CSV and an FRF CSV of the simulated drive, and a
// session export are made once under "C" and once under de_DE.UTF-8 (where printf writes "0,5")
// in this process, and must be equal byte for byte. The simulated measurements run under each
// locale too, so metadata the drive writes (fs_Hz, step_start_s, settle_s, ...) are covered.
#include "core/device/SimulatedDrive.h"
#include "core/device/TestRunner.h"
#include "core/io/CaptureCsv.h"
#include "core/io/FrfCsv.h"
#include "core/io/NcExport.h"
#include "core/io/Profile.h"
#include "core/sim/MachineDefinition.h"
#include "core/store/FrfCapture.h"
#include "core/store/SessionExport.h"

#include <clocale>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <sstream>
#include <string>
#include <nlohmann/json.hpp>

#include "core/store/SessionRecord.h"
#include "tests/core/store/StoreTestUtil.h"

namespace axistune {
namespace {

namespace fs = std::filesystem;
using Files = std::map<std::string, std::string>; ///< name → bytes

const std::string kResources = AXISTUNE_SOURCE_RESOURCE_DIR;

std::string slurp(const fs::path& p)
{
    std::ifstream f(p, std::ios::binary);
    std::ostringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

device::TestStatus runToEnd(device::Drive& d, const device::TestRequest& r)
{
    auto run = device::runTest(d, r, {});
    EXPECT_TRUE(run.ok()) << (run.ok() ? "" : run.error().detail);
    return {run.ok() ? device::TestState::Completed : device::TestState::Faulted, 1.0, {}};
}

/// Everything written under the locale `name` (the C library's LC_ALL, set for this call only).
Files writeEverything(const char* name, const fs::path& dir)
{
    Files out;
    const std::string previous = std::setlocale(LC_ALL, nullptr);
    if (!std::setlocale(LC_ALL, name)) {
        ADD_FAILURE() << "locale " << name << " is not installed (scripts/deps generates de_DE.UTF-8)";
        return out;
    }

    // NC parameter tapes in every format shipped in resources/nc, and the profile's own files.
    auto profile = io::readProfileFile(kResources + "/samples/vmc-profile.json");
    EXPECT_TRUE(profile.ok()) << (profile.ok() ? "" : profile.error().detail);
    for (const auto& e : fs::directory_iterator(kResources + "/nc")) {
        auto map = io::readNcMapFile(e.path().string());
        EXPECT_TRUE(map.ok()) << e.path();
        auto nc = map.ok() && profile.ok() ? io::exportNc(*profile, *map) : Result<io::NcExport>(Error{});
        EXPECT_TRUE(nc.ok()) << e.path() << (nc.ok() ? "" : nc.error().detail);
        if (nc.ok())
            out["nc/" + e.path().stem().string()] = nc->text;
    }
    if (profile.ok()) {
        out["parameters.csv"] = io::parametersToCsv(*profile);
        out["profile.json"] = io::profileToText(*profile);
    }

    // A current step (its metadata holds fractional numbers: step_start_s, current_period_s) and a
    // multi-sweep FRF of the simulated drive, measured under this locale.
    auto def = sim::loadPreset("vmc");
    EXPECT_TRUE(def.ok());
    auto drive = device::SimulatedDrive::create(*def, 3);
    EXPECT_TRUE(drive.ok());
    store::SessionRecord rec;
    rec.info.machine = "vmc";
    rec.info.axis = "X";
    rec.info.kind = "frf";
    rec.info.started = "2026-01-01T00:00:00.000Z";
    rec.info.finished = "2026-01-01T00:01:00.000Z";
    rec.info.appVersion = "test";
    if (drive.ok()) {
        device::TestRequest step;
        step.axis = "X";
        auto& current = step.test.emplace<device::CurrentStepTest>();
        current.currentA = 2.5;
        current.recordS = 0.004;
        EXPECT_EQ(runToEnd(**drive, step).state, device::TestState::Completed);
        auto trace = (*drive)->readTrace();
        EXPECT_TRUE(trace.ok());
        if (trace.ok()) {
            std::ostringstream csv;
            EXPECT_TRUE(io::writeCaptureCsv(csv, *trace).ok());
            out["current-step.csv"] = csv.str();
            rec.captures.push_back({"current-step", *trace});
        }
        device::TestRequest frf;
        frf.axis = "X";
        auto& frfTest = frf.test.emplace<device::FrfTest>();
        frfTest.fminHz = 20.0;
        frfTest.fmaxHz = 400.0;
        frfTest.points = 6;
        frfTest.amplitudePct = 2.5;
        EXPECT_EQ(runToEnd(**drive, frf).state, device::TestState::Completed);
        auto m = (*drive)->readFrequencyResponse();
        EXPECT_TRUE(m.ok());
        if (m.ok()) {
            std::ostringstream csv;
            EXPECT_TRUE(io::writeFrfCsv(csv, m->frf).ok());
            out["frf.csv"] = csv.str();
            rec.captures.push_back({"frf", store::frfAsCapture(m->frf)});
            rec.results.push_back({"frf", {{"points", m->frf.size()}, {"motion_time_s", m->motionTimeS}}, {}});
        }
    }
    rec.captures.push_back({"synthetic", store::testutil::makeCapture(2, 50)});
    auto manifest = store::exportSessionFolder(rec, dir.string());
    EXPECT_TRUE(manifest.ok()) << (manifest.ok() ? "" : manifest.error().detail);
    for (const auto& e : fs::directory_iterator(dir))
        out["session/" + e.path().filename().string()] = slurp(e.path());

    std::setlocale(LC_ALL, previous.c_str());
    return out;
}

TEST(LocaleIndependence, FilesAreByteIdenticalUnderCAndGerman)
{
    const fs::path root = store::testutil::tempDir("locale");
    const Files c = writeEverything("C", root / "c");
    const Files de = writeEverything("de_DE.UTF-8", root / "de");

    // The German locale was really in effect for the C library (else this test proves nothing).
    ASSERT_NE(std::setlocale(LC_ALL, "de_DE.UTF-8"), nullptr);
    char buf[16];
    std::snprintf(buf, sizeof buf, "%g", 0.5);
    std::setlocale(LC_ALL, "C");
    ASSERT_STREQ(buf, "0,5");

    // Every kind of file is there: 3 NC formats, 2 profile files, 2 CSVs, the session's manifest and
    // its 3 capture CSVs.
    ASSERT_EQ(c.size(), de.size());
    for (const char* name : {"nc/fanuc", "nc/siemens", "nc/heidenhain", "parameters.csv", "profile.json",
                             "current-step.csv", "frf.csv", "session/manifest.json"})
        EXPECT_EQ(c.count(name), 1u) << name;
    EXPECT_GE(c.size(), 11u);
    for (const auto& [name, bytes] : c) {
        ASSERT_EQ(de.count(name), 1u) << name;
        EXPECT_FALSE(bytes.empty()) << name;
        EXPECT_TRUE(bytes == de.at(name)) << name << " differs between C and de_DE.UTF-8";
    }
    // The files do hold decimal fractions, written with '.' (a Siemens gain, the current step's start).
    EXPECT_NE(c.at("nc/siemens").find("=1.8000\n"), std::string::npos);
    EXPECT_NE(c.at("current-step.csv").find("# current_period_s=6."), std::string::npos);
    fs::remove_all(root);
}

} // namespace
} // namespace axistune

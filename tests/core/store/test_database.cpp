// SPDX-License-Identifier: GPL-3.0-or-later
// Store: sessions, parameters, models, journal and profiles written and read back.
#include "core/io/Profile.h"
#include "core/store/Database.h"
#include "core/store/SessionRecord.h"
#include "tests/core/store/StoreTestUtil.h"

#include <SQLiteCpp/SQLiteCpp.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

using namespace axistune;
using namespace axistune::store;

namespace {

std::string dbPath(const std::string& tag)
{
    return (testutil::tempDir(tag) / "store.db").string();
}

}  // namespace

TEST(StoreDatabase, NewFileHasCurrentSchemaWalAndForeignKeys)
{
    auto db = Database::open(dbPath("new"));
    ASSERT_TRUE(db.ok()) << db.error().detail;
    Database& d = db.value();
    EXPECT_EQ(d.schemaVersion(), Database::kSchemaVersion);
    EXPECT_EQ(d.connection().execAndGet("PRAGMA journal_mode").getString(), "wal");
    EXPECT_EQ(d.connection().execAndGet("PRAGMA foreign_keys").getInt(), 1);
    EXPECT_EQ(d.connection().execAndGet("PRAGMA application_id").getInt(), Database::kApplicationId);
}

TEST(StoreDatabase, MustExistRefusesMissingFile)
{
    const auto path = dbPath("missing");
    auto db = Database::open(path, OpenMode::MustExist);
    ASSERT_FALSE(db.ok());
    EXPECT_EQ(db.error().code, ErrorCode::NotFound);
    EXPECT_NE(db.error().detail.find(path), std::string::npos);
}

TEST(StoreDatabase, SessionRoundTripKeepsEveryBitAndField)
{
    auto db = Database::open(dbPath("session"));
    ASSERT_TRUE(db.ok()) << db.error().detail;
    Database& d = db.value();
    SessionRecord r;
    r.info.machine = "vmc";
    r.info.axis = "X";
    r.info.kind = "frf";
    r.info.started = "2026-01-02T03:04:05.000Z";
    r.info.finished = "2026-01-02T03:05:00.000Z";
    r.info.status = SessionStatus::Aborted;
    r.info.operatorName = "tester";
    r.info.note = "partial data";
    r.inputs = {{"amplitude_Nm", 1.5}, {"freqs_Hz", {10, 20}}};
    auto cap = testutil::makeCapture(3, 1000);
    // Values a text format would lose or mangle.
    cap.channels[0].data[0] = -0.0;
    cap.channels[0].data[1] = std::numeric_limits<double>::denorm_min();
    cap.channels[0].data[2] = std::nextafter(1.0, 2.0);
    r.captures.push_back({"sweep", cap});
    r.results.push_back({"frf", {{"valid", true}}, {{"f_Hz", {1.0, 2.0, 3.0}}, {"mag_dB", {-1.0, -2.0, -3.5}}}});
    r.parameterSets.push_back({0, "X", ParameterSource::Proposed, "", "notch proposal", {{"filter.notch1.center", 812.5}}});
    r.models.push_back({0, "X", "two_inertia", "", {{"motor_inertia_kgm2", 1.2e-3}}});
    r.journal.push_back({0, "", "X", "velocity.kp", 2.0, 2.5, "", std::nullopt});
    r.journal.push_back({0, "", "X", "velocity.ki", std::nullopt, 400.0, "", std::nullopt});
    auto id = d.recordSession(r);
    ASSERT_TRUE(id.ok()) << id.error().detail;

    auto back = d.loadSession(*id);
    ASSERT_TRUE(back.ok()) << back.error().detail;
    EXPECT_EQ(back->info.machine, "vmc");
    EXPECT_EQ(back->info.axis, "X");
    EXPECT_EQ(back->info.kind, "frf");
    EXPECT_EQ(back->info.started, "2026-01-02T03:04:05.000Z");
    EXPECT_EQ(back->info.finished, "2026-01-02T03:05:00.000Z");
    EXPECT_EQ(back->info.status, SessionStatus::Aborted);
    EXPECT_EQ(back->info.operatorName, "tester");
    EXPECT_EQ(back->info.note, "partial data");
    EXPECT_EQ(back->info.appVersion, AXISTUNE_VERSION);
    EXPECT_EQ(back->inputs, r.inputs);
    ASSERT_EQ(back->captures.size(), 1u);
    EXPECT_EQ(back->captures[0].name, "sweep");
    EXPECT_EQ(back->captures[0].capture.metadata, cap.metadata);
    ASSERT_EQ(back->captures[0].capture.channels.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(back->captures[0].capture.channels[k].name, cap.channels[k].name);
        ASSERT_EQ(back->captures[0].capture.channels[k].data.size(), 1000u);
        for (std::size_t i = 0; i < 1000; ++i) {
            ASSERT_EQ(std::bit_cast<std::uint64_t>(back->captures[0].capture.channels[k].data[i]),
                      std::bit_cast<std::uint64_t>(cap.channels[k].data[i]))
                << "channel " << k << " sample " << i;
        }
    }
    ASSERT_EQ(back->results.size(), 1u);
    EXPECT_EQ(back->results[0].data, r.results[0].data);
    ASSERT_EQ(back->results[0].arrays.size(), 2u);
    EXPECT_EQ(back->results[0].arrays[1].name, "mag_dB");
    EXPECT_EQ(back->results[0].arrays[1].data, (std::vector<double>{-1.0, -2.0, -3.5}));
    ASSERT_EQ(back->parameterSets.size(), 1u);
    EXPECT_EQ(back->parameterSets[0].source, ParameterSource::Proposed);
    EXPECT_EQ(back->parameterSets[0].values.at("filter.notch1.center"), 812.5);
    ASSERT_EQ(back->models.size(), 1u);
    EXPECT_EQ(back->models[0].data["motor_inertia_kgm2"], 1.2e-3);
    ASSERT_EQ(back->journal.size(), 2u);
    EXPECT_EQ(*back->journal[0].oldValue, 2.0);
    EXPECT_EQ(back->journal[0].newValue, 2.5);
    EXPECT_FALSE(back->journal[1].oldValue.has_value());

    auto list = d.listSessions();
    ASSERT_TRUE(list.ok());
    ASSERT_EQ(list->size(), 1u);
    EXPECT_EQ((*list)[0].captureCount, 1);
    EXPECT_EQ((*list)[0].resultCount, 1);
}

TEST(StoreDatabase, CaptureMetadataIsStoredAsJsonNumbersAndTextsAndCheckedOnLoad)
{
    const auto path = dbPath("metadata");
    auto db = Database::open(path);
    ASSERT_TRUE(db.ok()) << db.error().detail;
    Database& d = db.value();
    SessionRecord r;
    r.info.machine = "vmc";
    r.info.kind = "frf";
    auto cap = testutil::makeCapture(1, 10, 0.1);
    cap.metadata.set("test", "step");
    r.captures.push_back({"sweep", cap});
    auto id = d.recordSession(r);
    ASSERT_TRUE(id.ok()) << id.error().detail;
    const auto stored = nlohmann::json::parse(d.connection().execAndGet("SELECT metadata FROM captures").getString());
    EXPECT_EQ(stored, (nlohmann::json{{"fs_Hz", 4000.0}, {"seed", 0.1}, {"test", "step"}}));

    // Metadata stored as text by older versions reads as the same numbers.
    d.connection().exec(R"(UPDATE captures SET metadata = '{"fs_Hz":"4000","seed":"0.1","test":"step"}')");
    auto back = d.loadSession(*id);
    ASSERT_TRUE(back.ok()) << back.error().detail;
    EXPECT_EQ(back->captures[0].capture.metadata, cap.metadata);

    d.connection().exec(R"(UPDATE captures SET metadata = '{"fs_Hz":[4000]}')");
    auto bad = d.loadSession(*id);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().code, ErrorCode::BadInput);
    EXPECT_NE(
        bad.error().detail.find(path + ": session " + std::to_string(*id) + ", capture 'sweep': metadata 'fs_Hz'"),
        std::string::npos)
        << bad.error().detail;
}

TEST(StoreDatabase, CurrentParametersIgnoreProposalsAndTakeNewestValue)
{
    auto db = Database::open(dbPath("params"));
    ASSERT_TRUE(db.ok());
    Database& d = db.value();
    ASSERT_TRUE(d.saveParameterSet("m", {0, "X", ParameterSource::Read, "", "", {{"a", 1.0}, {"b", 2.0}}}).ok());
    ASSERT_TRUE(d.saveParameterSet("m", {0, "X", ParameterSource::Proposed, "", "", {{"a", 9.0}}}).ok());
    ASSERT_TRUE(d.saveParameterSet("m", {0, "X", ParameterSource::Applied, "", "", {{"b", 3.0}}}).ok());
    auto cur = d.currentParameters("m", "X");
    ASSERT_TRUE(cur.ok());
    EXPECT_EQ(*cur, (model::ParameterValues{{"a", 1.0}, {"b", 3.0}}));
    auto sets = d.parameterSets("m", "X");
    ASSERT_TRUE(sets.ok());
    ASSERT_EQ(sets->size(), 3u);
    EXPECT_EQ((*sets)[1].source, ParameterSource::Proposed);
}

TEST(StoreDatabase, FailedSaveLeavesNothingBehind)
{
    auto db = Database::open(dbPath("atomic"));
    ASSERT_TRUE(db.ok());
    Database& d = db.value();
    SessionRecord r;
    r.info.machine = "m";
    r.info.kind = "frf";
    r.captures.push_back({"c", testutil::makeCapture(2, 100)});
    r.models.push_back({0, "X", "two_inertia", "", {{"k", 1}}});
    // A NaN parameter violates NOT NULL (SQLite stores NaN as NULL): the whole save must roll back.
    r.parameterSets.push_back({0, "X", ParameterSource::Applied, "", "", {{"a", std::nan("")}}});
    auto id = d.recordSession(r);
    ASSERT_FALSE(id.ok());
    EXPECT_NE(id.error().detail.find("saving a 'frf' session"), std::string::npos) << id.error().detail;
    EXPECT_EQ(d.connection().execAndGet("SELECT count(*) FROM sessions").getInt(), 0);
    EXPECT_EQ(d.connection().execAndGet("SELECT count(*) FROM captures").getInt(), 0);
    EXPECT_EQ(d.connection().execAndGet("SELECT count(*) FROM models").getInt(), 0);
    EXPECT_EQ(d.connection().execAndGet("SELECT count(*) FROM machines").getInt(), 0);
}

TEST(StoreDatabase, ProfileImportRecordsSessionAndLoadsBack)
{
    auto db = Database::open(dbPath("profile"));
    ASSERT_TRUE(db.ok());
    Database& d = db.value();
    io::MachineProfile p;
    p.name = "lathe";
    p.description = "two axes";
    p.axes.push_back({"Z", {{"position.kp", 30.0}}, {{"motor", {{"resistance_ohm", 0.32}}}}});
    p.axes.push_back({"X", {{"position.kp", 25.0}}, {}});
    auto sid = d.importProfile(p, "lathe.json");
    ASSERT_TRUE(sid.ok()) << sid.error().detail;
    auto s = d.loadSession(*sid);
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->info.kind, "profile-import");
    EXPECT_EQ(s->inputs["source"], "lathe.json");
    auto back = d.loadProfile("lathe");
    ASSERT_TRUE(back.ok()) << back.error().detail;
    EXPECT_EQ(io::profileToText(*back), io::profileToText(p));
    auto missing = d.loadProfile("nope");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::NotFound);
}

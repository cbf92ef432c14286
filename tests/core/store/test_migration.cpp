// SPDX-License-Identifier: GPL-3.0-or-later
// Store migrations: a file written with the version 1 schema (the DDL below is a frozen copy of it,
// written by this test, not taken from the code) opens, migrates to the current version and keeps
// its data.
#include "core/store/Database.h"
#include "core/store/Schema.h"
#include "core/store/SessionRecord.h"
#include "tests/core/store/StoreTestUtil.h"

#include <SQLiteCpp/SQLiteCpp.h>
#include <gtest/gtest.h>

using namespace axistune;
using namespace axistune::store;

namespace {

const char* kVersion1Schema = R"sql(
CREATE TABLE machines (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, description TEXT NOT NULL DEFAULT '', created TEXT NOT NULL);
CREATE TABLE axes (id INTEGER PRIMARY KEY, machine_id INTEGER NOT NULL REFERENCES machines(id) ON DELETE CASCADE,
  name TEXT NOT NULL, position INTEGER NOT NULL, UNIQUE (machine_id, name));
CREATE TABLE sessions (id INTEGER PRIMARY KEY, machine_id INTEGER REFERENCES machines(id) ON DELETE SET NULL,
  axis TEXT NOT NULL DEFAULT '', kind TEXT NOT NULL, started TEXT NOT NULL, finished TEXT NOT NULL,
  status TEXT NOT NULL CHECK (status IN ('completed', 'aborted', 'failed')), app_version TEXT NOT NULL,
  inputs TEXT NOT NULL DEFAULT '{}');
CREATE TABLE parameter_sets (id INTEGER PRIMARY KEY, axis_id INTEGER NOT NULL REFERENCES axes(id) ON DELETE CASCADE,
  source TEXT NOT NULL CHECK (source IN ('read', 'proposed', 'applied', 'imported')), time TEXT NOT NULL,
  note TEXT NOT NULL DEFAULT '', session_id INTEGER REFERENCES sessions(id) ON DELETE SET NULL);
CREATE TABLE parameter_values (set_id INTEGER NOT NULL REFERENCES parameter_sets(id) ON DELETE CASCADE,
  key TEXT NOT NULL, value REAL NOT NULL, PRIMARY KEY (set_id, key)) WITHOUT ROWID;
CREATE TABLE models (id INTEGER PRIMARY KEY, axis_id INTEGER NOT NULL REFERENCES axes(id) ON DELETE CASCADE,
  kind TEXT NOT NULL CHECK (kind IN ('motor', 'two_inertia', 'lost_motion', 'modal')), time TEXT NOT NULL,
  data TEXT NOT NULL, session_id INTEGER REFERENCES sessions(id) ON DELETE SET NULL);
CREATE TABLE captures (id INTEGER PRIMARY KEY, session_id INTEGER NOT NULL REFERENCES sessions(id) ON DELETE CASCADE,
  position INTEGER NOT NULL, name TEXT NOT NULL, metadata TEXT NOT NULL, samples INTEGER NOT NULL);
CREATE TABLE capture_channels (id INTEGER PRIMARY KEY, capture_id INTEGER NOT NULL REFERENCES captures(id) ON DELETE CASCADE,
  position INTEGER NOT NULL, name TEXT NOT NULL, data BLOB NOT NULL);
CREATE TABLE results (id INTEGER PRIMARY KEY, session_id INTEGER NOT NULL REFERENCES sessions(id) ON DELETE CASCADE,
  position INTEGER NOT NULL, name TEXT NOT NULL, data TEXT NOT NULL);
CREATE TABLE result_arrays (id INTEGER PRIMARY KEY, result_id INTEGER NOT NULL REFERENCES results(id) ON DELETE CASCADE,
  position INTEGER NOT NULL, name TEXT NOT NULL, data BLOB NOT NULL);
CREATE TABLE journal (id INTEGER PRIMARY KEY, axis_id INTEGER NOT NULL REFERENCES axes(id) ON DELETE CASCADE,
  key TEXT NOT NULL, old_value REAL, new_value REAL NOT NULL, time TEXT NOT NULL,
  session_id INTEGER REFERENCES sessions(id) ON DELETE SET NULL);
PRAGMA user_version = 1;
PRAGMA application_id = 1096307797;
)sql";

}  // namespace

TEST(StoreMigration, MigrationsAreOrderedAndEndAtTheSchemaVersion)
{
    const auto& m = migrations();
    ASSERT_FALSE(m.empty());
    for (std::size_t i = 0; i < m.size(); ++i)
        EXPECT_EQ(m[i].version, static_cast<int>(i) + 1);
    EXPECT_EQ(m.back().version, Database::kSchemaVersion);
    EXPECT_EQ(Database::kApplicationId, 1096307797);  // "AXTU" as written by the frozen v1 file above
}

TEST(StoreMigration, Version1FileMigratesAndKeepsItsData)
{
    const auto path = (testutil::tempDir("migrate") / "old.db").string();
    const double values[4] = {0.5, -1.25, 3.0e-7, 42.0};
    {
        SQLite::Database old(path, SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE);
        old.exec(kVersion1Schema);
        old.exec("INSERT INTO machines VALUES (1, 'vmc', 'old machine', '2025-01-01T00:00:00.000Z')");
        old.exec("INSERT INTO axes VALUES (1, 1, 'X', 0)");
        old.exec("INSERT INTO sessions VALUES (1, 1, 'X', 'frf', '2025-01-01T00:00:00.000Z', "
                 "'2025-01-01T00:01:00.000Z', 'completed', '0.0.9', '{\"amplitude_Nm\":2}')");
        old.exec("INSERT INTO captures VALUES (1, 1, 0, 'sweep', '{\"fs_Hz\":\"4000\"}', 4)");
        SQLite::Statement ch(old, "INSERT INTO capture_channels VALUES (1, 1, 0, 'torque_cmd_Nm', ?)");
        ch.bind(1, values, static_cast<int>(sizeof values));  // little-endian host: raw doubles are the format
        ch.exec();
        old.exec("INSERT INTO parameter_sets VALUES (1, 1, 'read', '2025-01-01T00:00:00.000Z', 'backup', 1)");
        old.exec("INSERT INTO parameter_values VALUES (1, 'velocity.kp', 2.07)");
        old.exec("INSERT INTO journal VALUES (1, 1, 'velocity.kp', 1.5, 2.07, '2025-01-01T00:00:30.000Z', 1)");
    }
    auto db = Database::open(path);
    ASSERT_TRUE(db.ok()) << db.error().detail;
    Database& d = db.value();
    EXPECT_EQ(d.schemaVersion(), 3);
    auto s = d.loadSession(1);
    ASSERT_TRUE(s.ok()) << s.error().detail;
    EXPECT_EQ(s->info.kind, "frf");
    EXPECT_EQ(s->info.appVersion, "0.0.9");
    EXPECT_EQ(s->info.operatorName, "");  // new column, default
    EXPECT_EQ(s->inputs["amplitude_Nm"], 2);
    ASSERT_EQ(s->captures.size(), 1u);
    EXPECT_EQ(s->captures[0].capture.channels[0].data, std::vector<double>(values, values + 4));
    // Version 1 and 2 stored every metadata value as a string: a number's text reads as the number.
    EXPECT_TRUE(s->captures[0].capture.metadata.find("fs_Hz")->isNumber());
    EXPECT_EQ(s->captures[0].capture.metadata.number("fs_Hz").value(), 4000.0);
    ASSERT_EQ(s->journal.size(), 1u);
    EXPECT_EQ(*s->journal[0].oldValue, 1.5);
    auto p = d.currentParameters("vmc", "X");
    ASSERT_TRUE(p.ok());
    EXPECT_EQ(p->at("velocity.kp"), 2.07);
    // The version 2 index exists, and new sessions can carry an operator.
    EXPECT_EQ(d.connection().execAndGet("SELECT count(*) FROM sqlite_master WHERE name = 'captures_session'").getInt(), 1);
    SessionRecord r;
    r.info.kind = "notch";
    r.info.operatorName = "anna";
    auto id = d.recordSession(r);
    ASSERT_TRUE(id.ok());
    EXPECT_EQ(d.loadSession(*id)->info.operatorName, "anna");
    EXPECT_EQ(*d.integrityCheck(), "ok");
}

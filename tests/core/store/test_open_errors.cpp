// SPDX-License-Identifier: GPL-3.0-or-later
// Store: files that are not a usable AxisTune store are refused with a message naming the file.
#include "core/store/Database.h"
#include "core/store/SessionRecord.h"
#include "tests/core/store/StoreTestUtil.h"

#include <SQLiteCpp/SQLiteCpp.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace axistune;
using namespace axistune::store;
namespace fs = std::filesystem;

namespace {

/// A closed store with two sessions of real data (several pages).
std::string makeStore(const std::string& tag)
{
    const auto path = (testutil::tempDir(tag) / "store.db").string();
    auto db = Database::open(path);
    EXPECT_TRUE(db.ok());
    Database& d = db.value();
    for (int i = 0; i < 2; ++i) {
        SessionRecord r;
        r.info.kind = "frf";
        r.captures.push_back({"c", testutil::makeCapture(2, 20000, i)});
        EXPECT_TRUE(d.recordSession(r).ok());
    }
    return path;
}

void expectRefused(const std::string& path, const std::string& phrase)
{
    auto db = Database::open(path, OpenMode::MustExist);
    ASSERT_FALSE(db.ok()) << path << " was accepted";
    EXPECT_EQ(db.error().code, ErrorCode::BadInput);
    EXPECT_NE(db.error().detail.find(path), std::string::npos) << db.error().detail;
    EXPECT_NE(db.error().detail.find(phrase), std::string::npos) << db.error().detail;
}

}  // namespace

TEST(StoreOpen, ClosedStoreLeavesNoWalAndReopens)
{
    const auto path = makeStore("reopen");
    EXPECT_FALSE(fs::exists(path + "-wal") && fs::file_size(path + "-wal") > 0);
    auto db = Database::open(path, OpenMode::MustExist);
    ASSERT_TRUE(db.ok()) << db.error().detail;
    EXPECT_EQ(db->listSessions()->size(), 2u);
}

TEST(StoreOpen, NewerSchemaIsRefused)
{
    const auto path = makeStore("newer");
    {
        SQLite::Database raw(path, SQLite::OPEN_READWRITE);
        raw.exec("PRAGMA user_version = 99");
    }
    expectRefused(path, "newer AxisTune (store schema version 99, this version reads up to 3)");
}

TEST(StoreOpen, TruncatedFileIsRefused)
{
    const auto path = makeStore("truncated");
    const auto size = fs::file_size(path);
    ASSERT_GT(size, 3u * 65536u);
    fs::resize_file(path, size / 2);
    expectRefused(path, "truncated store");
    fs::resize_file(path, 50);
    expectRefused(path, "truncated store");
}

TEST(StoreOpen, NonSqliteFileIsRefused)
{
    const auto path = (testutil::tempDir("text") / "capture.csv").string();
    std::ofstream(path) << "t_s,torque_cmd_Nm\n0,1\n";
    expectRefused(path, "not an SQLite database file");
}

TEST(StoreOpen, ForeignSqliteDatabaseIsRefused)
{
    const auto path = (testutil::tempDir("foreign") / "other.db").string();
    {
        SQLite::Database raw(path, SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE);
        raw.exec("CREATE TABLE contacts(name TEXT)");
    }
    expectRefused(path, "another program");
}

TEST(StoreOpen, DamagedSchemaPageIsRefused)
{
    const auto path = makeStore("damaged");
    {
        std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(100);
        const std::string junk(4000, '\x5a');
        f.write(junk.data(), static_cast<std::streamsize>(junk.size()));
    }
    expectRefused(path, "damaged");
}

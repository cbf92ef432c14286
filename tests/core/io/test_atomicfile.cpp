// SPDX-License-Identifier: GPL-3.0-or-later
// io::writeFileAtomic / writeFileAtomicVia (core/io/AtomicFile.h): the target is either the old file
// or the whole new one; a failed write removes its temporary file and names the target.
#include "core/io/AtomicFile.h"
#include "tests/ScopedTempDir.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <sys/stat.h>
#include <nlohmann/json.hpp>

using namespace axistune;
namespace fs = std::filesystem;

namespace {

axistune::testing::ScopedTempDir tempDir()
{
    return axistune::testing::ScopedTempDir("atomic");
}

std::string slurp(const fs::path& p)
{
    std::ifstream f(p, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

std::vector<std::string> names(const fs::path& dir)
{
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir))
        out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

TEST(AtomicFile, ReplacesAndKeepsThePermissions)
{
    const auto dir = tempDir();
    const auto p = dir / "a.csv";
    ASSERT_TRUE(io::writeFileAtomic(p.string(), "first\n").ok());
    EXPECT_EQ(slurp(p), "first\n");
    ASSERT_EQ(chmod(p.c_str(), 0640), 0);
    ASSERT_TRUE(io::writeFileAtomic(p.string(), std::string(100000, 'x')).ok());
    EXPECT_EQ(slurp(p), std::string(100000, 'x'));
    struct stat st {};
    ASSERT_EQ(stat(p.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0640u);
    ASSERT_TRUE(io::writeFileAtomic(p.string(), "").ok()); // an empty file when the content is empty
    EXPECT_EQ(fs::file_size(p), 0u);
    EXPECT_EQ(names(dir), std::vector<std::string>{"a.csv"});
}

TEST(AtomicFile, AFailingWriterLeavesTheOldFileAndNoTemporary)
{
    const auto dir = tempDir();
    const auto p = dir / "plot.png";
    ASSERT_TRUE(io::writeFileAtomic(p.string(), "old").ok());
    const auto st = io::writeFileAtomicVia(p.string(), [](const std::string& tmp) -> Status {
        std::ofstream(tmp) << "half";
        return makeError(ErrorCode::Io, "writer failed");
    });
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().detail, p.string() + ": not written (writer failed); the previous file is unchanged");
    EXPECT_EQ(slurp(p), "old");
    EXPECT_EQ(names(dir), std::vector<std::string>{"plot.png"});
    const auto q = dir / "new.png";
    const auto st2 = io::writeFileAtomicVia(
        q.string(), [](const std::string&) -> Status { return makeError(ErrorCode::Io, "writer failed"); });
    ASSERT_FALSE(st2.ok());
    EXPECT_NE(st2.error().detail.find("no file was written"), std::string::npos);
    EXPECT_FALSE(fs::exists(q));
}

TEST(AtomicFile, SymlinkIsFollowedAndFoldersAndMissingFoldersAreNamed)
{
    const auto dir = tempDir();
    fs::create_directory(dir / "real");
    const auto target = dir / "real" / "t.json";
    ASSERT_TRUE(io::writeFileAtomic(target.string(), "1").ok());
    fs::create_symlink(target, dir / "link.json");
    ASSERT_TRUE(io::writeFileAtomic((dir / "link.json").string(), "2").ok());
    EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
    EXPECT_EQ(slurp(target), "2");
    const auto folder = io::writeFileAtomic((dir / "real").string(), "x");
    ASSERT_FALSE(folder.ok());
    EXPECT_EQ(folder.error().detail, (dir / "real").string() + ": is a folder, not a file");
    const auto missing = io::writeFileAtomic((dir / "nope" / "x.csv").string(), "x");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().detail.find((dir / "nope" / "x.csv").string() + ": cannot create a file in"),
              std::string::npos);
    EXPECT_NE(missing.error().detail.find(std::strerror(ENOENT)), std::string::npos);
}

TEST(AtomicFile, DeviceTargetsAreWrittenInPlace)
{
    const auto full = io::writeFileAtomic("/dev/full", "data");
    ASSERT_FALSE(full.ok());
    // The C library words errno in the locale (German under de_DE.UTF-8), as the message does.
    EXPECT_EQ(full.error().detail, std::string("/dev/full: not written (") + std::strerror(ENOSPC) + ")");
    EXPECT_TRUE(io::writeFileAtomic("/dev/null", "data").ok());
}

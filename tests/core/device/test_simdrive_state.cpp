// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-simdrive's state file (--state) is read through the input limits like every other reader
// (docs/robustness.md): a FIFO, a directory or a device is refused at once with the file named (a FIFO
// without a writer would otherwise block the start for ever), malformed content is refused with the
// file and the key named, a missing file is the first run, and a valid file restores the parameters.
#include "core/device/ModbusDrive.h"
#include "core/device/SimDriveServer.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <nlohmann/json.hpp>

#include "tests/core/device/ServerThread.h"
#include "tests/ScopedTempDir.h"

namespace {

using namespace axistune;
namespace fs = std::filesystem;

struct StateDir {
    axistune::testing::ScopedTempDir dir{"state"};
    std::string write(const std::string& name, const std::string& text) const
    {
        std::ofstream(dir / name) << text;
        return (dir / name).string();
    }
};

Result<std::unique_ptr<device::SimDriveServer>> start(const std::string& state)
{
    device::SimDriveServerOptions o;
    o.stateFile = state;
    return device::SimDriveServer::create(o);
}

std::string refusal(const std::string& state)
{
    auto s = start(state);
    EXPECT_FALSE(s.ok()) << state;
    if (s.ok())
        return {};
    EXPECT_EQ(s.error().code, ErrorCode::BadInput) << s.error().detail;
    EXPECT_NE(s.error().detail.find(state), std::string::npos) << "the file is not named: " << s.error().detail;
    return s.error().detail;
}

TEST(SimDriveState, MissingFileIsTheFirstRun)
{
    StateDir d;
    EXPECT_TRUE(start((d.dir / "none.json").string()).ok());
}

TEST(SimDriveState, FifoDirectoryAndDeviceAreRefusedWithoutBlocking)
{
    StateDir d;
    const std::string fifo = (d.dir / "fifo.json").string();
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_NE(refusal(fifo).find("is not a regular file"), std::string::npos);
    EXPECT_NE(refusal(d.dir.string()).find("is a directory, not a file"), std::string::npos);
    EXPECT_NE(refusal("/dev/zero").find("is not a regular file"), std::string::npos);
}

TEST(SimDriveState, MalformedContentIsRefusedNamingTheKey)
{
    StateDir d;
    EXPECT_NE(refusal(d.write("a.json", "[1, 2]")).find("expected an object"), std::string::npos);
    EXPECT_NE(refusal(d.write("b.json", R"({"X": 3})")).find("axis 'X'"), std::string::npos);
    EXPECT_NE(refusal(d.write("c.json", R"({"X": {"velocity.kp": "fast"}})")).find("key 'velocity.kp': not a number"),
              std::string::npos);
    EXPECT_NE(refusal(d.write("d.json", R"({"X": {"velocity.kp": 1e309}})")).find("does not fit a double"),
              std::string::npos);
    EXPECT_NE(refusal(d.write("e.json", "{\"X\": {")).find("not valid JSON"), std::string::npos);
}

TEST(SimDriveState, ValidFileRestoresTheParameters)
{
    StateDir d;
    // 1234.5 lies inside velocity.kp's limits (register map: 0..1e5) and differs from the preset's value.
    // 1234.5 is exact in the register's f32, so the read-back is compared exactly.
    const std::string state = d.write("s.json", R"({"X": {"velocity.kp": 1234.5}})");
    device::SimDriveServerOptions o;
    o.stateFile = state;
    devtest::ServerThread srv(o);
    ASSERT_NE(srv.port(), 0);
    EXPECT_NE(srv.log().find("parameters restored from " + state), std::string::npos) << srv.log();
    auto drive = device::connectAny({srv.uri(), 7});
    ASSERT_TRUE(drive.ok()) << drive.error().detail;
    auto v = (*drive)->readParameters("X", std::vector<std::string>{"velocity.kp"});
    ASSERT_TRUE(v.ok()) << v.error().detail;
    EXPECT_EQ(v->at("velocity.kp"), 1234.5);
}

} // namespace

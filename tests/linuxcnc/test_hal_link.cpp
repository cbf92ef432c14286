// SPDX-License-Identifier: GPL-3.0-or-later
// AxisTune's HAL clients in one long-lived process (core/device/hal/HalLink.cpp): LinuxCNC 2.9's user-space
// rtapi_init() remembers where it first mapped its UUID shared memory (the counter that numbers HAL components); the
// memory must stay there while clients open and close and the process maps large blocks, and after a restart of the
// HAL session the counter must be the new session's.
#include "core/device/hal/HalLink.h"

#include <charconv>
#include <cstdint>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "tests/linuxcnc/HalTestbed.h"

namespace axistune::testing {
namespace {

using device::hal::HalClient;

/// Where this process maps LinuxCNC's UUID segment (key 0x48484c34), from /proc/self/maps; 0 when it does not.
std::uintptr_t uuidMapping()
{
    std::ifstream maps("/proc/self/maps");
    std::string line;
    while (std::getline(maps, line)) {
        if (line.find("/SYSV48484c34") == std::string::npos)
            continue;
        std::uintptr_t start = 0;
        std::from_chars(line.data(), line.data() + line.find('-'), start, 16);
        return start;
    }
    return 0;
}

// A second client opened while the first is open, after a halcmd (another process) has joined and left HAL: its
// component id must exceed the first's by more than one, because the halcmd drew numbers from the same counter. A
// process that counts on a segment of its own (a stale one) gives consecutive ids.
void expectTheCounterIsSharedWithTheSession(const char* when)
{
    SCOPED_TRACE(when);
    auto first = HalClient::open("axistune-first");
    ASSERT_TRUE(first) << first.error().detail;
    (void)halText({"-s", "show", "comp"});
    auto second = HalClient::open("axistune-second");
    ASSERT_TRUE(second) << second.error().detail;
    EXPECT_GT((*second)->componentId(), (*first)->componentId() + 1);
    // Both are listed by the session, each under its own id.
    const std::string comps = halText({"-s", "show", "comp"});
    EXPECT_NE(comps.find("axistune-first"), std::string::npos) << comps;
    EXPECT_NE(comps.find("axistune-second"), std::string::npos) << comps;
}

} // namespace

// Before the fix the second of these cycles crashed in rtapi_init (or wrote into one of the blocks) in about two of
// three runs: the memory was unmapped when the client closed, and the blocks took its address.
TEST_F(HalTestbed, ClientsOpenAndCloseWhileTheProcessMapsLargeBlocks)
{
    startBed(1000000);
    std::vector<std::vector<double>> blocks; // 1 MiB each: glibc maps every one on its own, filling freed ranges
    std::uintptr_t uuidAt = 0;
    for (int cycle = 0; cycle < 12; ++cycle) {
        SCOPED_TRACE(cycle);
        {
            auto client = HalClient::open("axistune-cycle");
            ASSERT_TRUE(client) << client.error().detail;
            auto beat = (*client)->readPin("axistune-cycle.heartbeat");
            ASSERT_TRUE(beat) << beat.error().detail;
            if (cycle == 0)
                uuidAt = uuidMapping();
            ASSERT_NE(uuidAt, 0u);
            EXPECT_EQ(uuidMapping(), uuidAt);
        }
        EXPECT_EQ(uuidMapping(), uuidAt) << "the UUID memory was unmapped when the process's last client closed";
        for (int k = 0; k < 8; ++k)
            blocks.emplace_back(std::size_t{1} << 17, static_cast<double>(cycle));
    }
    for (std::size_t b = 0; b < blocks.size(); ++b)
        for (const double v : blocks[b])
            ASSERT_EQ(v, static_cast<double>(b / 8)) << "block " << b << " was written into";
    expectTheCounterIsSharedWithTheSession("one session");
}

// `realtime stop` removes the UUID segment and the next session creates another: the clients this process opens
// afterwards must be numbered by the new session's counter (a stale counter gives ids the session's own components
// may carry, and hal_exit removes the component it finds by id), at the address rtapi_init remembers.
TEST_F(HalTestbed, AfterTheHalSessionRestartsClientsAreNumberedByTheNewSession)
{
    startBed(1000000);
    {
        auto client = HalClient::open("axistune-before");
        ASSERT_TRUE(client) << client.error().detail;
    }
    const std::uintptr_t before = uuidMapping();
    ASSERT_NE(before, 0u);
    auto stopped = runScript({"stop"});
    ASSERT_TRUE(stopped) << stopped.error().detail;
    m_started = false;
    startBed(1000000);
    expectTheCounterIsSharedWithTheSession("after the restart");
    EXPECT_EQ(uuidMapping(), before);
    const std::string comps = halText({"-s", "show", "comp"});
    EXPECT_EQ(comps.find("axistune-before"), std::string::npos) << comps;
}

} // namespace axistune::testing

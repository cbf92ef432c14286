// SPDX-License-Identifier: GPL-3.0-or-later
// Store: a child process saving a large session is killed with SIGKILL at random moments. After
// every kill the file must pass PRAGMA integrity_check, open normally, and every session saved before
// must read back bit-exact; the interrupted session is either absent or complete.
#include "core/store/Database.h"
#include "core/store/SessionRecord.h"
#include "tests/core/store/StoreTestUtil.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <random>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace axistune;
using namespace axistune::store;

namespace {

constexpr std::size_t kChannels = 8;
constexpr std::size_t kSamples = 100000;  // 6.4 MB per session

SessionRecord bigSession(int seed)
{
    SessionRecord r;
    r.info.machine = "vmc";
    r.info.axis = "X";
    r.info.kind = "frf";
    r.inputs = {{"seed", seed}};
    r.captures.push_back({"trace", testutil::makeCapture(kChannels, kSamples, seed)});
    r.results.push_back({"summary", {{"seed", seed}}, {{"f_Hz", {1.0, 2.0, double(seed)}}}});
    r.journal.push_back({0, "", "X", "velocity.kp", double(seed), double(seed) + 1.0, "", std::nullopt});
    return r;
}

/// Checks one stored session against the data its seed regenerates.
void expectIntact(const Database& db, std::int64_t id)
{
    auto s = db.loadSession(id);
    ASSERT_TRUE(s.ok()) << s.error().detail;
    const int seed = s->inputs.at("seed").get<int>();
    const auto expected = testutil::makeCapture(kChannels, kSamples, seed);
    ASSERT_EQ(s->captures.size(), 1u) << "session " << id;
    const auto& got = s->captures[0].capture;
    ASSERT_EQ(got.channels.size(), kChannels) << "session " << id;
    for (std::size_t k = 0; k < kChannels; ++k)
        ASSERT_TRUE(got.channels[k].data == expected.channels[k].data) << "session " << id << " channel " << k;
    ASSERT_EQ(s->results.size(), 1u);
    EXPECT_EQ(s->results[0].arrays[0].data[2], double(seed));
    ASSERT_EQ(s->journal.size(), 1u);
    EXPECT_EQ(s->journal[0].newValue, double(seed) + 1.0);
}

}  // namespace

TEST(StoreKill, SigkillDuringSaveLeavesPreviousStateIntact)
{
    const auto path = (testutil::tempDir("kill") / "store.db").string();
    double saveSeconds = 0.0;
    {
        auto db = Database::open(path);
        ASSERT_TRUE(db.ok()) << db.error().detail;
        Database& d = db.value();
        for (int seed = 0; seed < 2; ++seed) {
            const auto rec = bigSession(seed);
            const auto t0 = std::chrono::steady_clock::now();
            ASSERT_TRUE(d.recordSession(rec).ok());
            saveSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        }
    }
    std::mt19937 rng(20261122);
    std::uniform_real_distribution<double> moment(0.0, 1.0);
    int nextSeed = 100;
    int killedWhileRunning = 0;
    for (int round = 0; round < 20; ++round) {
        const int seed = nextSeed++;
        int ready[2];
        ASSERT_EQ(pipe(ready), 0);
        const pid_t pid = fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) {
            close(ready[0]);
            auto rec = bigSession(seed);  // built before the signal so the kill lands in the save
            auto db = Database::open(path);
            if (!db.ok())
                _exit(10);
            const char c = 'r';
            if (write(ready[1], &c, 1) != 1)
                _exit(11);
            auto id = db.value().recordSession(rec);
            _exit(id.ok() ? 0 : 12);
        }
        close(ready[1]);
        char c = 0;
        ASSERT_EQ(read(ready[0], &c, 1), 1) << "child did not open the store";
        close(ready[0]);
        // Somewhere inside the save: from its first instruction to the typical duration.
        const double waitS = moment(rng) * saveSeconds;
        std::this_thread::sleep_for(std::chrono::duration<double>(waitS));
        const bool stillRunning = waitpid(pid, nullptr, WNOHANG) == 0;
        killedWhileRunning += stillRunning ? 1 : 0;
        kill(pid, SIGKILL);
        int status = 0;
        waitpid(pid, &status, 0);

        auto db = Database::open(path, OpenMode::MustExist);
        ASSERT_TRUE(db.ok()) << "round " << round << ": " << db.error().detail;
        auto check = db->integrityCheck();
        ASSERT_TRUE(check.ok()) << check.error().detail;
        EXPECT_EQ(*check, "ok") << "round " << round;
        auto list = db->listSessions();
        ASSERT_TRUE(list.ok()) << list.error().detail;
        ASSERT_GE(list->size(), 2u) << "round " << round << ": earlier sessions lost";
        for (const auto& s : *list)
            expectIntact(db.value(), s.id);
    }
    // The test means nothing if the child always finished first.
    EXPECT_GE(killedWhileRunning, 8) << "save took " << saveSeconds << " s";
    std::cout << "killed mid-save in " << killedWhileRunning << " of 20 rounds (save " << saveSeconds << " s)\n";
}

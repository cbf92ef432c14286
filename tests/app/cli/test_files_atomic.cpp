// SPDX-License-Identifier: GPL-3.0-or-later
// Files the tool writes and the store under a full disk, a read-only file system and a file that is
// not SQLite (issue 21 item 6, docs/storage.md "Files the tool writes"), end to end through the real
// axistune-cli. A full disk and a read-only file system are real ones: a small tmpfs mounted in a
// private mount namespace (`unshare --user --map-root-user --mount`, util-linux), which needs no root,
// no LD_PRELOAD, and vanishes with the shell even if the test dies. Each case asserts the message
// (file named), the exit code, and that nothing was lost: previous files byte for byte, the store's
// sessions, no temporary files, no -wal/-shm left behind.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include "tests/app/cli/CliRunner.h"

using namespace axistune::testing;
namespace fs = std::filesystem;

namespace {

const std::string kSamples = std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/samples/";
const std::string kProfile = kSamples + "vmc-profile.json";

std::string lobesArgs(const std::string& out)
{
    return "lobes --tool " + kSamples + "tool-table1.json --cut " + kSamples +
           "cut-table1.json --rpm-min 2800 --rpm-max 2955 --rpm-step 155 --steps-per-period 40 --out " + out;
}

/// Runs `script` with sh in a private user + mount namespace; returns the shell's exit status. A
/// machine where unprivileged namespaces are switched off fails the test loudly (never skipped).
int inNamespace(const fs::path& dir, const std::string& script)
{
    const auto file = dir / "script.sh";
    std::ofstream(file) << "set -u\nCLI=" << AXISTUNE_CLI << "\nD=" << dir.string() << "\n" << script;
    const std::string cmd =
        "unshare --user --map-root-user --mount sh " + file.string() + " >" + (dir / "script.out").string() + " 2>&1";
    const int st = std::system(cmd.c_str());
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

std::string text(const fs::path& p)
{
    return readFileText(p);
}

int rc(const fs::path& dir, const std::string& name)
{
    return std::stoi("0" + text(dir / (name + ".rc")));
}

} // namespace

TEST(FilesAtomic, FullDiskLeavesEveryPreviousFileAndTheStoreIntact)
{
    const auto dir = makeTempDir("fulldisk");
    // 4 MiB tmpfs: a store (64 KiB pages) and old outputs, then filled to the last byte.
    const int sh = inNamespace(
        dir, R"(
mkdir -p $D/disk && mount -t tmpfs -o size=4m tmpfs $D/disk || { echo "cannot mount a tmpfs"; exit 90; }
$CLI profile import --db $D/disk/s.db --in )" +
                 kProfile + R"( >/dev/null || exit 91
printf 'old lobes\n' > $D/disk/lobes.csv
printf 'old report\n' > $D/disk/loop.json
printf 'old capture\n' > $D/disk/step.csv
cp $D/disk/s.db $D/s-before.db
dd if=/dev/zero of=$D/disk/fill bs=4096 >/dev/null 2>&1
$CLI )" + lobesArgs("$D/disk/lobes.csv") +
                 R"( >$D/lobes.out 2>$D/lobes.err; echo $? >$D/lobes.rc
$CLI )" + lobesArgs("$D/disk/new.csv") +
                 R"( >$D/new.out 2>$D/new.err; echo $? >$D/new.rc
$CLI current-loop --motor )" +
                 kSamples + R"(motor-rotary.json --out $D/disk/loop.json >$D/loop.out 2>$D/loop.err; echo $? >$D/loop.rc
$CLI capture --connect sim:vmc --axis X --test step --amplitude 5 --duration 0.1 --out $D/disk/step.csv >$D/step.out 2>$D/step.err; echo $? >$D/step.rc
$CLI profile import --db $D/disk/s.db --in )" +
                 kProfile + R"( --note again >$D/import.out 2>$D/import.err; echo $? >$D/import.rc
$CLI profile import --db $D/disk/fresh.db --in )" +
                 kProfile + R"( >$D/fresh.out 2>$D/fresh.err; echo $? >$D/fresh.rc
ls -a $D/disk >$D/listing.txt
cp $D/disk/lobes.csv $D/lobes.after; cp $D/disk/loop.json $D/loop.after; cp $D/disk/step.csv $D/step.after
cp $D/disk/s.db $D/s-after.db
exit 0
)");
    ASSERT_EQ(sh, 0) << "namespace script failed (unshare/mount unavailable?): " << text(dir / "script.out");
    const std::string disk = (dir / "disk").string();
    // Each write refused with exit 1 (I/O) and the file named; the previous file byte for byte.
    for (const auto& [name, file, old] :
         {std::tuple<std::string, std::string, std::string>{"lobes", "lobes.csv", "old lobes\n"},
          {"loop", "loop.json", "old report\n"},
          {"step", "step.csv", "old capture\n"}}) {
        EXPECT_EQ(rc(dir, name), 1) << name << ": " << text(dir / (name + ".err"));
        EXPECT_NE(text(dir / (name + ".err")).find(disk + "/" + file), std::string::npos)
            << text(dir / (name + ".err"));
        EXPECT_NE(text(dir / (name + ".err")).find("No space left on device"), std::string::npos)
            << text(dir / (name + ".err"));
        EXPECT_NE(text(dir / (name + ".err")).find("previous file is unchanged"), std::string::npos);
        EXPECT_EQ(text(dir / (name + ".after")), old) << name;
    }
    // A new file on the full disk: refused, no empty file left.
    EXPECT_EQ(rc(dir, "new"), 1) << text(dir / "new.err");
    EXPECT_NE(text(dir / "new.err").find("no file was written"), std::string::npos) << text(dir / "new.err");
    // The store: import refused naming the store and the full disk; the store file unchanged byte for
    // byte, and it still holds its one session.
    EXPECT_NE(rc(dir, "import"), 0);
    EXPECT_NE(text(dir / "import.err").find(disk + "/s.db"), std::string::npos) << text(dir / "import.err");
    EXPECT_NE(text(dir / "import.err").find("disk full"), std::string::npos) << text(dir / "import.err");
    EXPECT_EQ(text(dir / "s-after.db"), text(dir / "s-before.db"));
    const auto list = runCli("session list --db " + (dir / "s-after.db").string());
    ASSERT_EQ(list.exitCode, 0) << list.err;
    EXPECT_EQ(nlohmann::json::parse(list.out).size(), 1u);
    // A new store on the full disk: refused, and nothing left of it.
    EXPECT_NE(rc(dir, "fresh"), 0);
    EXPECT_NE(text(dir / "fresh.err").find(disk + "/fresh.db"), std::string::npos) << text(dir / "fresh.err");
    // No temporary file, no -wal/-shm, no half new file.
    const std::string listing = text(dir / "listing.txt");
    EXPECT_EQ(listing, ".\n..\nfill\nlobes.csv\nloop.json\ns.db\nstep.csv\n") << listing;
    fs::remove_all(dir);
}

TEST(FilesAtomic, ReadOnlyStoreIsRefusedBeforeTheTestRuns)
{
    const auto dir = makeTempDir("rostore");
    const int sh = inNamespace(dir, R"(
mkdir -p $D/ro && mount -t tmpfs -o size=4m tmpfs $D/ro || { echo "cannot mount a tmpfs"; exit 90; }
$CLI profile import --db $D/ro/s.db --in )" +
                                        kProfile + R"( >/dev/null || exit 91
cp $D/ro/s.db $D/s-before.db
mount -o remount,ro $D/ro || { echo "cannot remount read-only"; exit 92; }
$CLI capture --connect sim:vmc --axis X --test step --amplitude 5 --duration 0.1 --out $D/step.csv --db $D/ro/s.db --machine vmc >$D/cap.out 2>$D/cap.err; echo $? >$D/cap.rc
$CLI profile import --db $D/ro/s.db --in )" +
                                        kProfile + R"( >$D/import.out 2>$D/import.err; echo $? >$D/import.rc
ls -a $D/ro >$D/listing.txt
cp $D/ro/s.db $D/s-after.db
exit 0
)");
    ASSERT_EQ(sh, 0) << "namespace script failed (unshare/mount unavailable?): " << text(dir / "script.out");
    const std::string store = (dir / "ro" / "s.db").string();
    // capture --db: refused before the test (no capture file written), the store named.
    EXPECT_NE(rc(dir, "cap"), 0);
    EXPECT_NE(text(dir / "cap.err").find(store), std::string::npos) << text(dir / "cap.err");
    EXPECT_NE(text(dir / "cap.err").find("nothing was measured"), std::string::npos) << text(dir / "cap.err");
    EXPECT_FALSE(fs::exists(dir / "step.csv")) << "the test ran although the store could not take its session";
    EXPECT_NE(rc(dir, "import"), 0);
    EXPECT_NE(text(dir / "import.err").find(store), std::string::npos) << text(dir / "import.err");
    EXPECT_EQ(text(dir / "s-after.db"), text(dir / "s-before.db"));
    EXPECT_EQ(text(dir / "listing.txt"), ".\n..\ns.db\n");
    fs::remove_all(dir);
}

TEST(FilesAtomic, StoreThatIsNotSqliteIsRefusedAndKept)
{
    const auto dir = makeTempDir("notsqlite");
    const auto store = (dir / "capture.csv").string();
    const std::string content = "t_s,torque_cmd_Nm\n0,1\n0.001,2\n";
    std::ofstream(store) << content;
    const auto imp = runCli("profile import --db " + store + " --in " + kProfile);
    EXPECT_EQ(imp.exitCode, 2) << imp.err;
    EXPECT_NE(imp.err.find(store + ": not an AxisTune store (not an SQLite database file)"), std::string::npos)
        << imp.err;
    const auto cap = runCli("capture --connect sim:vmc --axis X --test step --amplitude 5 --duration 0.1 --out " +
                            (dir / "step.csv").string() + " --db " + store + " --machine vmc");
    EXPECT_EQ(cap.exitCode, 2) << cap.err;
    EXPECT_NE(cap.err.find(store + ": not an AxisTune store"), std::string::npos) << cap.err;
    EXPECT_FALSE(fs::exists(dir / "step.csv"));
    EXPECT_EQ(readFileText(store), content);
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
        names.push_back(e.path().filename().string());
    EXPECT_EQ(names, std::vector<std::string>{"capture.csv"});
    fs::remove_all(dir);
}

TEST(FilesAtomic, DevFullAndStdoutAreWrittenInPlace)
{
    // Not a regular file: nothing to rename, written in place; /dev/full reports the full disk.
    const auto r = runCli(lobesArgs("/dev/full"));
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("/dev/full: not written (No space left on device)"), std::string::npos) << r.err;
    const auto out = runCli(lobesArgs("/dev/stdout"));
    EXPECT_EQ(out.exitCode, 0) << out.err;
    EXPECT_EQ(out.out.rfind("rpm,limit_depth_m\n", 0), 0u) << out.out;
}

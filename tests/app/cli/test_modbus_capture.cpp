// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli capture over modbus:// against the axistune-simdrive binary: the same FRF as the
// embedded sim: drive with the same seed, and a clean exit 3 naming the lost connection when the
// server is killed in the middle of a multi-sweep.
#include "core/io/CaptureCsv.h"
#include "core/io/FrfCsv.h"
#include "tests/app/cli/CliRunner.h"
#include "tests/app/cli/SimDriveProcess.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

using namespace axistune;
using axistune::testing::makeTempDir;
using axistune::testing::readFileText;
using axistune::testing::runCli;
using axistune::testing::SimDrive;

namespace {

const std::string kFrfArgs = " --axis C --test frf --method multisweep --fmin 100 --fmax 3900 --points 12 --seed 5 --out ";

TEST(ModbusCapture, FrfOverModbusEqualsTheEmbeddedDriveWithTheSameSeed)
{
    SimDrive srv("--preset dd-table --seed 5");
    ASSERT_GT(srv.port(), 0) << srv.log();
    const auto dir = makeTempDir("modbus-capture");
    const auto remote = (dir / "remote.csv").string(), local = (dir / "local.csv").string();
    auto r = runCli("capture --connect " + srv.uri() + kFrfArgs + remote);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runCli("capture --connect sim:dd-table" + kFrfArgs + local);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto a = io::readFrfCsvFile(remote);
    auto b = io::readFrfCsvFile(local);
    ASSERT_TRUE(a.ok() && b.ok());
    ASSERT_EQ(a->freqHz.size(), b->freqHz.size());
    ASSERT_GE(b->freqHz.size(), 10u);
    for (std::size_t i = 0; i < b->freqHz.size(); ++i) {
        EXPECT_EQ(a->freqHz[i], b->freqHz[i]);
        EXPECT_LE(std::abs(a->h[i] - b->h[i]), 1e-9 * std::abs(b->h[i])) << b->freqHz[i] << " Hz";
        EXPECT_EQ(a->valid[i], b->valid[i]);
    }
    std::filesystem::remove_all(dir);
}

TEST(ModbusCapture, ServerKilledMidMultiSweepExitsThreeNamingTheLostConnection)
{
    SimDrive srv("--preset dd-table --pace 1");  // real-time pace: the sweep lasts seconds
    ASSERT_GT(srv.port(), 0) << srv.log();
    const auto dir = makeTempDir("modbus-kill");
    const auto errPath = (dir / "err.txt").string();
    // The default multi-sweep takes about 14 s of machine time, so it is still running at the kill.
    const std::string cmd = std::string(AXISTUNE_CLI) + " capture --connect " + srv.uri("timeout_ms=500")
                            + " --axis C --test frf --method multisweep --out " + (dir / "frf.csv").string() + " 2>"
                            + errPath;
    const pid_t pid = fork();
    if (pid == 0) {
        execl("/bin/sh", "sh", "-c", ("exec " + cmd).c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    // Kill once the server has logged the start of the test (bounded to 15 s), so a slow start on a
    // loaded machine cannot turn this into a refused connection.
    for (int i = 0; i < 150 && srv.log().find("started on axis C") == std::string::npos; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    ASSERT_NE(srv.log().find("started on axis C"), std::string::npos) << srv.log();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    srv.stop(SIGKILL);
    const auto t0 = std::chrono::steady_clock::now();
    int status = 0;
    bool exited = false;
    for (int i = 0; i < 1000 && !exited; ++i) {  // at most 10 s
        exited = waitpid(pid, &status, WNOHANG) == pid;
        if (!exited)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (!exited) {
        kill(pid, SIGKILL);
        waitpid(pid, &status, 0);
    }
    ASSERT_TRUE(exited) << "the CLI hung after the server died";
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 3);
    const auto err = readFileText(errPath);
    EXPECT_NE(err.find("connection lost"), std::string::npos) << err;
    std::filesystem::remove_all(dir);
}

}  // namespace

// capture --test current-step against the axistune-simdrive binary: the current-rate trace (16 kHz)
// equals the embedded drive's with the same seed; a step beyond the drive's limit exits 2 with its message.
TEST(ModbusCapture, CurrentStepOverModbusEqualsTheEmbeddedDrive)
{
    SimDrive srv("--preset vmc --seed 5");
    ASSERT_GT(srv.port(), 0) << srv.log();
    const auto dir = makeTempDir("modbus-current-step");
    const auto remote = (dir / "remote.csv").string(), local = (dir / "local.csv").string();
    const std::string args = " --axis X --test current-step --amplitude 5 --duration 0.003 --seed 5 --out ";
    auto r = runCli("capture --connect " + srv.uri() + args + remote);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = runCli("capture --connect sim:vmc" + args + local);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    auto a = io::readCaptureCsvFile(remote);
    auto b = io::readCaptureCsvFile(local);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(b->metadata.number("fs_Hz").value(), 16000.0);
    EXPECT_EQ(a->metadata.number("fs_Hz").value(), 16000.0);
    ASSERT_EQ(b->size(), 48u); // 3 ms at 62.5 µs
    ASSERT_EQ(a->channels.size(), b->channels.size());
    for (std::size_t c = 0; c < b->channels.size(); ++c) {
        EXPECT_EQ(a->channels[c].name, b->channels[c].name);
        EXPECT_EQ(a->channels[c].data, b->channels[c].data) << b->channels[c].name;
    }
    r = runCli("capture --connect " + srv.uri() + " --axis X --test current-step --amplitude 45 --duration 0.003 --out " +
               remote);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("at most 50 % of motor.max_current (40 A)"), std::string::npos) << r.err;
    std::filesystem::remove_all(dir);
}

// SPDX-License-Identifier: GPL-3.0-or-later
// Scope roll mode over Modbus (docs/scope.md "Measured"): axistune-simdrive's server on its own thread
// (--preset vmc), the Modbus client streaming 8 channels at the drive's fastest scope rate for a given
// wall time. Reports the sustained samples per second (rows × channels) and every lost or repeated sample
// (from the drive's sample numbers). A figure, not a test: nothing is asserted.
//   bench_scope [--seconds S] [--pace F]   (default 60 s; F machine seconds per wall second, default 1: real time)
#include "core/device/Drive.h"
#include "core/device/SimDriveServer.h"
#include "core/model/Number.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>

using namespace axistune;
using namespace axistune::device;

int main(int argc, char** argv)
{
    double seconds = 60.0, pace = 1.0;
    for (int i = 1; i + 1 < argc; ++i) {
        const bool s = std::strcmp(argv[i], "--seconds") == 0, p = std::strcmp(argv[i], "--pace") == 0;
        if (s || p) {
            const auto v = model::parseNumber(argv[i + 1]);
            if (!v || !(*v > 0.0)) {
                std::fprintf(stderr, "bench_scope: %s '%s' must be a positive number\n", argv[i], argv[i + 1]);
                return 2;
            }
            (s ? seconds : pace) = *v;
        }
    }
    SimDriveServerOptions o;
    o.preset = "vmc";
    o.pace = pace; // the scope's axis runs at this many machine seconds per wall second
    auto server = SimDriveServer::create(o);
    if (!server) {
        std::fprintf(stderr, "bench_scope: %s\n", server.error().detail.c_str());
        return 1;
    }
    std::thread thread([&] { (void)(*server)->serve(); });
    int rc = 0;
    {
        auto d = connect({"modbus://127.0.0.1:" + std::to_string((*server)->port()) + "?timeout_ms=2000", 1});
        if (!d) {
            std::fprintf(stderr, "bench_scope: %s\n", d.error().detail.c_str());
            (*server)->requestStop();
            thread.join();
            return 1;
        }
        ScopeRequest r;
        r.axis = "X";
        r.mode = ScopeMode::Roll;
        r.channels = {"t_s",       "velocity_cmd_rad_s", "motor_vel_rad_s", "torque_cmd_Nm",
                      "current_A", "position_cmd_m",     "table_pos_m",     "following_error_m"};
        if (auto st = (*d)->armScope(r); !st) {
            std::fprintf(stderr, "bench_scope: %s\n", st.error().detail.c_str());
            rc = 1;
        } else {
            std::uint64_t next = 0, rows = 0, lost = 0, repeated = 0, reads = 0, behindMax = 0;
            bool started = false;
            double rateHz = 0.0;
            const auto t0 = std::chrono::steady_clock::now();
            while (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < seconds) {
                auto got = (*d)->readScopeRows(next, 4096);
                ++reads;
                if (!got) {
                    std::fprintf(stderr, "bench_scope: %s\n", got.error().detail.c_str());
                    rc = 1;
                    break;
                }
                if (got->rows == 0) {
                    std::this_thread::sleep_for(std::chrono::milliseconds(2));
                    continue;
                }
                if (started && got->firstSample > next)
                    lost += got->firstSample - next;
                if (started && got->firstSample < next)
                    repeated += next - got->firstSample;
                started = true;
                rows += got->rows;
                next = got->firstSample + got->rows;
                if (reads % 64 == 0) {
                    auto s = (*d)->pollScope();
                    if (s) {
                        rateHz = s->rateHz;
                        behindMax = std::max<std::uint64_t>(behindMax, s->nextSample - next);
                    }
                }
            }
            const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            (void)(*d)->stopScope();
            std::printf("scope roll mode over Modbus, %zu channels at %.0f Hz, %.1f s wall time\n", r.channels.size(),
                        rateHz, wall);
            std::printf("  rows %llu (%.0f rows/s), samples %.0f/s sustained, lost %llu, repeated %llu, "
                        "readScopeRows calls %llu, largest backlog %llu rows\n",
                        static_cast<unsigned long long>(rows), rows / wall, rows * r.channels.size() / wall,
                        static_cast<unsigned long long>(lost), static_cast<unsigned long long>(repeated),
                        static_cast<unsigned long long>(reads), static_cast<unsigned long long>(behindMax));
        }
    }
    (*server)->requestStop();
    thread.join();
    return rc;
}

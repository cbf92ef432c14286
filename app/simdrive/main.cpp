// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-simdrive: serves a simulated machine over Modbus TCP on 127.0.0.1 (docs/modbus.md).
#include "app/simdrive/RegisterMapTemplate.h"
#include "core/device/SimDriveServer.h"
#include "core/io/AtomicFile.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <csignal>
#include <ctime>
#include <iostream>
#include <nlohmann/json.hpp>

namespace {

axistune::device::SimDriveServer* g_server = nullptr;

extern "C" void onSignal(int)
{
    if (g_server)
        g_server->requestStop(); // an atomic store: async-signal-safe
}

void logLine(const std::string& line)
{
    const std::time_t t = std::time(nullptr);
    char ts[32];
    std::strftime(ts, sizeof ts, "%H:%M:%S", std::localtime(&t));
    std::cerr << "axistune-simdrive " << ts << " " << line << std::endl;
}

} // namespace

int main(int argc, char** argv)
{
    using namespace axistune;
    CLI::App app{"axistune-simdrive: a simulated machine served over Modbus TCP (127.0.0.1)"};
    device::SimDriveServerOptions o;
    std::vector<std::string> faults;
    std::string writeMap;
    app.add_option("--preset", o.preset, "machine preset (vmc, dd-table, two-inertia, long-axis)")
        ->capture_default_str();
    app.add_option("--machine", o.machineFile,
                   "machine definition JSON (the format of resources/machines/*.json) instead of --preset");
    app.add_option("--port", o.port, "TCP port; 0 picks a free port and prints it")->capture_default_str();
    app.add_option("--bind", o.bind, "address to listen on (127.0.0.1 only)")->capture_default_str();
    app.add_option("--seed", o.seed, "noise seed of the simulated machine")->capture_default_str();
    app.add_option("--map", o.mapFamily, "register map resources/drives/NAME.json")->capture_default_str();
    app.add_option("--fault", faults,
                   "fault injection: drop-after:N, delay:MS, illegal-address, drive-fault:S (repeatable)");
    app.add_option("--watchdog", o.safety.watchdogS, "heartbeat watchdog [s]")->capture_default_str();
    app.add_option("--travel-limit", o.safety.travelLimit, "travel window ± [m] (linear axes)")->capture_default_str();
    app.add_option("--speed-limit", o.safety.speedLimitRadS, "motor speed limit [rad/s]")->capture_default_str();
    app.add_option("--amplitude-limit", o.safety.amplitudeLimitPct, "torque limit in tests [% of rated torque]")
        ->capture_default_str();
    app.add_option("--following-error-limit", o.safety.followingErrorLimit, "following-error limit [m or rad]")
        ->capture_default_str();
    app.add_option("--pace", o.pace, "at most this many machine seconds per wall second (0: as fast as possible)")
        ->capture_default_str();
    app.add_option("--state", o.stateFile, "JSON file keeping the parameters across restarts");
    app.add_option("--write-map", writeMap, "write the register map JSON built from the parameter catalogue and exit");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    if (!writeMap.empty()) {
        if (auto st = io::writeFileAtomic(writeMap, simdrive::simRegisterMapJson()); !st) {
            std::cerr << "axistune-simdrive: " << st.error().detail << "\n";
            return exitCodeFor(st.error().code);
        }
        return 0;
    }
    auto fi = device::parseFaultModes(faults);
    if (!fi) {
        std::cerr << "axistune-simdrive: " << fi.error().detail << "\n";
        return 2;
    }
    o.faults = *fi;
    o.log = logLine;
    auto server = device::SimDriveServer::create(o);
    if (!server) {
        std::cerr << "axistune-simdrive: " << server.error().detail << "\n";
        return exitCodeFor(server.error().code);
    }
    g_server = server.value().get();
    struct sigaction sa {};
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0; // no SA_RESTART: select() returns so the loop sees the stop flag
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
    std::signal(SIGPIPE, SIG_IGN);
    std::cout << "axistune-simdrive listening on 127.0.0.1:" << (*server)->port() << std::endl;
    logLine((o.machineFile.empty() ? "preset " + o.preset : "machine file " + o.machineFile) + ", seed " +
            std::to_string(o.seed) + ", faults " + device::describeFaults(o.faults) + ", watchdog " +
            std::to_string(o.safety.watchdogS) + " s");
    const auto st = (*server)->serve();
    g_server = nullptr;
    logLine(st ? "shut down cleanly" : "stopped: " + st.error().detail);
    return st ? 0 : 3;
}

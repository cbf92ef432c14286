// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The simulated drive served over Modbus TCP (libmodbus) through a register map (docs/modbus.md):
// one SimulatedDrive per server, one unit id per axis, several clients at once, and the safety of a
// real drive around it (amplitude, travel, speed and following-error limits, heartbeat watchdog,
// no parameter write during a test, range checks answered with ILLEGAL DATA VALUE).
// Single-threaded: serve() runs the network loop (poll(), non-blocking sockets, every frame checked
// before anything changes; docs/modbus.md "Under abuse") and the simulation; requestStop() may be
// called from a signal handler or another thread.

#include "core/device/FaultInjection.h"
#include "core/device/RegisterMap.h"
#include "core/device/SimulatedDrive.h"
#include "core/device/TestRegisterCodec.h"

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace axistune::device {

/// Limits enforced by the drive; axis units are m (linear) or rad (rotary).
struct SafetyLimits {
    double amplitudeLimitPct = 300.0; ///< torque excitation, % of rated torque (rated current × k_t)
    double travelLimit = 0.5;         ///< |position| window around 0 [m], linear axes only
    double speedLimitRadS = 2.0 * 3.14159265358979 * 6000.0 / 60.0; ///< motor speed [rad/s]
    double followingErrorLimit = 0.01; ///< |position command − feedback| in position tests [axis units]
    double watchdogS = 1.0;            ///< no heartbeat this long while a test runs → stop
};

struct SimDriveServerOptions {
    std::string preset = "vmc";
    /// A machine definition file (the format of resources/machines/*.json, docs/simulator.md "Presets") instead
    /// of the preset: variants of a preset for tests (e.g. with backlash). Empty: the preset.
    std::string machineFile;
    std::string bind = "127.0.0.1";
    int port = 0; ///< 0: a free port, see SimDriveServer::port()
    std::uint64_t seed = 1;
    std::string mapFamily = "axistune-sim";
    SafetyLimits safety;
    FaultInjection faults;
    double pace = 0.0;     ///< > 0: at most this many machine seconds per wall second
    std::string stateFile; ///< parameters kept across restarts (written after each accepted write)
    std::function<void(const std::string&)> log; ///< one line per connection and per fault
};

class SimDriveServer {
public:
    static Result<std::unique_ptr<SimDriveServer>> create(const SimDriveServerOptions& options);
    ~SimDriveServer();
    SimDriveServer(const SimDriveServer&) = delete;
    SimDriveServer& operator=(const SimDriveServer&) = delete;

    int port() const { return m_port; }
    /// Serves until requestStop(); returns after closing every socket.
    Status serve();
    void requestStop() { m_stop.store(true); }

    /// Answers every complete frame of one client's byte stream in order (answer() and a simulation
    /// step each), as serve() does for one connection, and stops at the first incomplete or invalid
    /// frame (SimDriveServerStream.cpp). For the Modbus fuzz target. Returns the frames answered.
    std::size_t serveBytes(std::span<const std::uint8_t> bytes);

    // The register engine (SimDriveServerRegisters.cpp); returns 0 or a Modbus exception code.
    // A refused write changes nothing (registers, test configuration, heartbeat, trace selection).
    int readRegisters(int unitId, int address, int count, std::uint16_t* out);
    int writeRegisters(int unitId, int address, const std::uint16_t* values, int count);

    /// One complete Modbus TCP frame (as delimited by scanMbapFrame) in, its answer out: decoded and
    /// checked (ModbusTcpFrame.h), executed, encoded. `peer` names the client in the log. Public for
    /// tests and fuzzing; serve() uses it for every frame.
    std::vector<std::uint8_t> answer(std::span<const std::uint8_t> frame, const std::string& peer = "test");

private:
    struct Axis {
        std::string name;
        std::string kind; ///< "linear" or "rotary"
        sim::AxisSimulator* sim = nullptr;
    };
    using Clock = std::chrono::steady_clock;

    SimDriveServer() = default;
    void log(const std::string& line) const;
    int writeRegistersChecked(int ui, int address, const std::uint16_t* values, int count, bool& commandRan);
    /// A refused write that touched test-block fields (test.*, circle.*) of unit index `ui`: they are
    /// marked refused, and start_test is refused until each has been written again successfully.
    void markRefusedConfig(int ui, int address, int count, const std::string& why);
    Status listen(int port); ///< 127.0.0.1:port, non-blocking (SimDriveServerConnections.cpp)
    Status loadState();
    void saveState() const;
    // Simulation and safety (SimDriveServerSafety.cpp).
    void step();
    void checkSafety();
    void trip(const std::string& fault, const std::string& message);
    int startTest(int unitIndex);
    /// The request of the unit's test block with this server's safety checks; 0 or a Modbus exception.
    int buildRequest(int unitIndex, TestRequest& request);
    /// plan_test: the embedded drive's plan of the test block into the plan.* fields.
    int planTest(int unitIndex, std::uint16_t token);
    int refuseError(const Error& e);
    DriveLimits axisLimits(int unitIndex);
    bool encodeDescription(const RegisterField& f, int unitIndex, std::uint16_t* buf);
    int runCommand(int unitIndex, std::uint16_t code, std::uint16_t token);
    void takeTrace();
    void takeFrequencyResponse();
    // The circle test of two axes (SimDriveServerCircle.cpp).
    int startCircle(int unitIndex, TestRequest& request);
    void checkCircleSecondAxis();
    /// Index of the axis named `name`, -1 when the drive has none.
    int axisIndex(const std::string& name) const;
    /// The test type configured on a unit ("step", "frf", ...: the map's name of its test.type code).
    std::string configuredType(int unitIndex) const;
    // The scope (SimDriveServerScope.cpp; docs/modbus.md "Scope").
    struct ScopeConfig {
        std::uint16_t mode = 0, divider = 1, triggerChannel = 0, edge = 0;
        std::uint32_t mask = 0, length = 0;
        double level = 0.0, prePct = 0.0;
    };
    int armScope(int unitIndex);
    /// While the scope is armed and no test moves its axis: runs that axis in wall-clock time (--pace, else 1).
    void stepScope();
    bool scopeArmed() const;
    bool encodeScopeField(const RegisterField& f, int unitIndex, std::uint16_t* buf);
    void encodeScopeWindow(const RegisterField& f, int unitIndex, std::uint16_t* buf);
    int writeScopeField(const RegisterField& f, int unitIndex, const std::uint16_t* words);
    // Register helpers.
    void encodeField(const RegisterField& f, int unitIndex, std::uint16_t* buf);
    bool encodeIdentity(const RegisterField& f, int unitIndex, std::uint16_t* buf);
    void encodeWindow(const RegisterField& f, std::uint16_t* buf);
    int writeField(const RegisterField& f, int unitIndex, const std::uint16_t* words);
    int refuse(int exception, const std::string& message);

    SimDriveServerOptions m_opt;
    RegisterMap m_map;
    std::unique_ptr<SimulatedDrive> m_drive;
    std::string m_machine;
    std::vector<Axis> m_axes;
    std::vector<int> m_owner; ///< register → index into m_slots, -1 unmapped
    struct Slot {
        const RegisterField* field = nullptr;
        const ParameterRegister* parameter = nullptr;
        int address = 0, count = 0;
    };
    std::vector<Slot> m_slots;

    std::vector<TestValues> m_config; ///< per unit: the quantities its carrying fields hold (TestRegisterCodec.h)
    /// Per unit: test-block fields whose last write was refused (name → why); start_test refuses
    /// while this is not empty.
    std::vector<std::map<std::string, std::string>> m_refusedConfig;
    std::string m_state = "idle";
    std::string m_fault = "none";
    std::string m_message;
    double m_progress = 0.0;
    int m_testUnit = -1;
    int m_testSecondUnit = -1; ///< circle: the second plane axis, else -1
    double m_testStartMachineS = 0.0;
    Clock::time_point m_testStartWall;
    Clock::time_point m_lastHeartbeat;
    std::uint16_t m_heartbeat = 0;
    std::uint16_t m_lastCode = 0, m_lastToken = 0;
    int m_lastResult = 0;
    bool m_haveToken = false;
    std::optional<model::Capture> m_trace;
    std::string m_traceNames, m_traceMeta;
    std::vector<double> m_frfBlob; ///< the FRF of the last FRF test, serialised (docs/modbus.md)
    std::string m_frfMeta;
    TestPlan m_plan; ///< the last plan_test answer
    std::uint16_t m_planToken = 0;
    int m_planUnit = -1;
    std::uint32_t m_selOffset = 0;
    std::uint16_t m_selChannel = 0;
    std::vector<ScopeConfig> m_scopeConfig; ///< per unit
    int m_scopeUnit = -1;                   ///< unit the scope was armed on
    Clock::time_point m_scopeWall;          ///< wall time up to which the scope's axis has run
    std::uint16_t m_scopeSource = 0;
    double m_scopeFrom = 0.0;
    std::optional<ScopeCapture> m_scopeCapture; ///< the drive's last capture, for paging

    int m_port = 0;
    int m_listenFd = -1;
    std::atomic<bool> m_stop{false};
};

} // namespace axistune::device

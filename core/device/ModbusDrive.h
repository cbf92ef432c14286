// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Modbus TCP drive (libmodbus client) behind the Drive seam, speaking a register map
// (resources/drives/*.json, docs/modbus.md). Synchronous; one thread per instance (libmodbus
// contexts are not thread-safe). Every request is bounded by the response timeout; requests are
// retried after a reconnect only when repeating them is harmless (reads, absolute writes, commands
// carrying a sequence token); the heartbeat goes out from pollTest() while a test runs.

#include "core/device/Drive.h"
#include "core/device/RegisterMap.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

struct _modbus; // libmodbus's modbus_t

namespace axistune::device {

struct ModbusUri {
    std::string host;
    int port = 502;
    int timeoutMs = 1000;                ///< per request, also the connect timeout
    std::string family = "axistune-sim"; ///< register map resources/drives/<family>.json
    std::string text;                    ///< the URI as given, for messages
};

/// "modbus://HOST:PORT[?timeout_ms=N&map=FAMILY]"; errors name the URI and the part that is wrong.
Result<ModbusUri> parseModbusUri(const std::string& uri);

/// A text for each Modbus exception code (1..11) and libmodbus protocol error.
std::string modbusExceptionText(int exceptionCode);

class ModbusDrive : public Drive {
public:
    static Result<std::unique_ptr<ModbusDrive>> open(const ModbusUri& uri, RegisterMap map);
    ~ModbusDrive() override;

    Result<DriveIdentity> identify() override;
    Result<std::vector<model::ParameterMeta>> parameterMetadata(const std::string& axis) override;
    Result<model::ParameterValues> readParameters(const std::string& axis, std::span<const std::string> keys) override;
    Status writeParameters(const std::string& axis, const model::ParameterValues& values) override;
    Status startTest(const TestRequest& request) override;
    Result<TestStatus> pollTest() override;
    Result<model::Capture> readTrace() override;
    Status abortTest() override;
    /// The FRF the drive evaluated for the last completed Frf test (float64 on the wire: exact).
    Result<FrfMeasurement> readFrequencyResponse() override;
    /// From the describe.* and limits.* registers of the axis (docs/modbus.md "Capabilities, limits and
    /// plans"); a map without them is answered with NotFound naming the missing field.
    Result<DriveCapabilities> capabilities(const std::string& axis) override;
    Result<DriveLimits> limits(const std::string& axis) override;
    /// Writes the test block and sends plan_test; the drive answers in the plan.* registers.
    Result<TestPlan> planTest(const TestRequest& request) override;

    // The scope (docs/modbus.md "Scope"): scope.* configuration, status and window registers.
    Result<ScopeCapabilities> scopeCapabilities(const std::string& axis) override;
    Status armScope(const ScopeRequest& request) override;
    Result<ScopeStatus> pollScope() override;
    /// Pages of scope.window until maxRows rows or the newest row; stops at a gap (overwritten rows), so the
    /// rows returned are consecutive.
    Result<ScopeRows> readScopeRows(std::uint64_t from, std::size_t maxRows) override;
    Result<ScopeCapture> readScopeCapture() override;
    Status stopScope() override;

    /// Writes the heartbeat register now (pollTest() does this every kHeartbeatPeriod while a test runs).
    Status heartbeat();
    const RegisterMap& registerMap() const { return m_map; }
    /// Requests sent so far (for benchmarks).
    std::uint64_t requestCount() const { return m_requests; }

    static constexpr int kMaxAttempts = 3;   ///< per idempotent request
    static constexpr int kMaxReconnects = 5; ///< per session
    static constexpr std::chrono::milliseconds kHeartbeatPeriod{200};
    static constexpr std::chrono::milliseconds kMinPollInterval{10};

private:
    using Clock = std::chrono::steady_clock;
    struct AxisInfo {
        std::string name;
        std::string kind;
        int unit = 0;
    };
    enum class Retry { Idempotent, Never };

    ModbusDrive() = default;
    Status connectOnce();
    void disconnect();
    /// One request with the retry policy; `op` returns libmodbus's result (< 0 with errno on failure).
    Status transact(int unit, const std::string& what, Retry retry, const std::function<int(_modbus*)>& op);
    Status readRegs(int unit, int address, int count, std::uint16_t* out, const std::string& what);
    Status writeRegs(int unit, int address, const std::uint16_t* values, int count, const std::string& what);
    Status command(int unit, const std::string& name);
    /// Every field of the map that carries a test quantity, written from the request to the axis's unit.
    Result<int> writeTestBlock(const TestRequest& request);
    /// Reads a run of named fields of one unit in one request; fails naming a field the map lacks.
    Result<std::vector<std::uint16_t>> readFields(int unit, const std::vector<std::string>& names, int& first,
                                                  const std::string& what);
    Status loadAxes();
    Result<AxisInfo> axisInfo(const std::string& axis);
    Result<std::string> readText(int unit, std::uint16_t channel);
    Result<std::vector<double>> readBlob(int unit, std::uint16_t channel);
    Error exceptionError(int unit, int exceptionCode, const std::string& what);
    /// One scope.window page: source and first sample (or byte offset) written, the window read (function 23).
    Status readScopePage(int unit, const std::string& source, std::uint64_t from, std::vector<std::uint16_t>& page);

    ModbusUri m_uri;
    RegisterMap m_map;
    void* m_ctx = nullptr; ///< modbus_t*
    bool m_connected = false;
    int m_reconnects = 0;
    std::uint64_t m_requests = 0;
    std::vector<AxisInfo> m_axes;
    DriveIdentity m_identity;
    std::uint16_t m_token = 0;
    std::uint16_t m_heartbeat = 0;
    bool m_testRunning = false;
    int m_testUnit = -1;
    Clock::time_point m_lastHeartbeat;
    Clock::time_point m_lastPoll;
    // The armed scope.
    int m_scopeUnit = -1;
    std::vector<ScopeChannelInfo> m_scopeChannels; ///< in the request's order
    std::vector<std::size_t> m_scopeColumn;        ///< request channel k is column m_scopeColumn[k] on the wire
};

/// Opens "modbus://HOST:PORT[?timeout_ms=N&map=FAMILY]" (the map from resources/drives/FAMILY.json).
/// device::connect() can hand modbus:// URIs to this function, so every --connect accepts them.
Result<std::unique_ptr<Drive>> connectModbus(const ConnectionSettings& settings);
/// Same as device::connect(), which opens "sim:PRESET" and "modbus://HOST:PORT" alike.
Result<std::unique_ptr<Drive>> connectAny(const ConnectionSettings& settings);

} // namespace axistune::device

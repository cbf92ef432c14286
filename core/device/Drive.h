// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The drive seam (STYLE.md "A device seam"): synchronous, created and used on one I/O thread.
// Implementations: the embedded simulated drive (SimulatedDrive) and, later, the Modbus TCP client.

#include "core/model/Capture.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"

#include <memory>
#include <span>
#include <string>
#include <vector>

namespace axistune::device {

struct DriveIdentity {
    std::string vendor;
    std::string model;
    std::string firmware;
    std::string machine;            ///< preset or machine name
    std::vector<std::string> axes;  ///< axis names, one drive axis each
};

enum class TestType {
    Step,  ///< velocity step: amplitude [rad/s motor], duration [s]
    Jog,   ///< position move: distance [axis units] at velocity [axis units/s], optional return
    Hold,  ///< position hold for duration [s]
};

struct TestRequest {
    std::string axis;
    TestType type = TestType::Step;
    double amplitude = 0.0;     ///< Step: velocity step [rad/s]
    double distance = 0.0;      ///< Jog: [m] or [rad]
    double velocity = 0.0;      ///< Jog: [m/s] or [rad/s]
    double acceleration = 0.0;  ///< Jog: [m/s²] or [rad/s²]
    bool returnToStart = false; ///< Jog: move back (a reversal)
    double durationS = 0.1;     ///< Step/Hold: recording length; Jog: dwell before and after
    int traceDivider = 0;       ///< 0: the drive's trace.divider parameter
};

enum class TestState { Idle, Running, Completed, Aborted, Faulted };

struct TestStatus {
    TestState state = TestState::Idle;
    double progress = 0.0;  ///< 0..1
    std::string detail;     ///< fault or abort reason
};

const char* testStateName(TestState s);

class Drive {
public:
    virtual ~Drive() = default;
    virtual Result<DriveIdentity> identify() = 0;
    /// Metadata of every parameter of an axis (units, limits, writability).
    virtual Result<std::vector<model::ParameterMeta>> parameterMetadata(const std::string& axis) = 0;
    virtual Result<model::ParameterValues> readParameters(const std::string& axis, std::span<const std::string> keys) = 0;
    /// Range-checked before anything changes; refused while a test runs unless writable during tests.
    virtual Status writeParameters(const std::string& axis, const model::ParameterValues& values) = 0;
    virtual Status startTest(const TestRequest& request) = 0;
    /// Advances and reports the running test.
    virtual Result<TestStatus> pollTest() = 0;
    /// The trace of the last completed test, channels in SI.
    virtual Result<model::Capture> readTrace() = 0;
    /// Stops the motion at once and restores the parameters from before the test.
    virtual Status abortTest() = 0;
};

struct ConnectionSettings {
    std::string uri;  ///< "sim:PRESET" (Modbus TCP "modbus://HOST:PORT" follows in a later issue)
    std::uint64_t seed = 1;
};

/// Opens a connection from a URI; errors name the URI and what is wrong with it.
Result<std::unique_ptr<Drive>> connect(const ConnectionSettings& settings);

}  // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The `linuxcnc:PATH/machine.ini` backend (docs/linuxcnc.md "The linuxcnc: connection"): the HAL session of a
// LinuxCNC started from that INI, seen through the configuration. Its joints' pid instances are found from the
// [HAL]HALFILEs (LinuxCncConfig.h); an axis is named by its joint's letter of [TRAJ]COORDINATES (trivial
// kinematics), else `jointN`, else the pid's name; each parameter says which INI key feeds it. Everything else is
// the `hal:` backend (HalDrive.h) on that axis's pid.

#include "core/device/Drive.h"
#include "core/device/DriveRegistry.h"
#include "core/device/hal/HalDrive.h"
#include "core/device/hal/LinuxCncConfig.h"
#include "core/device/hal/LinuxCncMotion.h"

#include <chrono>
#include <map>
#include <optional>
#include <memory>
#include <string>

namespace axistune::device::hal {

class LinuxCncDrive : public Drive {
public:
    /// Reads the configuration and attaches to HAL; refused when no pid of the configuration runs there.
    static Result<std::unique_ptr<LinuxCncDrive>> open(const std::string& iniPath, const HalSessionOptions& options);

    const LinuxCncConfig& config() const { return m_config; }
    /// The pid instance of an axis name; NotFound naming the axes.
    Result<std::string> pidOf(const std::string& axis) const;

    Result<DriveIdentity> identify() override;
    Result<std::vector<model::ParameterMeta>> parameterMetadata(const std::string& axis) override;
    Result<model::ParameterValues> readParameters(const std::string& axis, std::span<const std::string> keys) override;
    Status writeParameters(const std::string& axis, const model::ParameterValues& values) override;
    Status startTest(const TestRequest& request) override;
    Result<TestStatus> pollTest() override;
    Result<model::Capture> readTrace() override;
    Status abortTest() override;
    Result<FrfMeasurement> readFrequencyResponse() override;
    Result<DriveCapabilities> capabilities(const std::string& axis) override;
    Result<DriveLimits> limits(const std::string& axis) override;
    Result<TestPlan> planTest(const TestRequest& request) override;
    Result<ScopeCapabilities> scopeCapabilities(const std::string& axis) override;
    Status armScope(const ScopeRequest& request) override;
    Result<ScopeStatus> pollScope() override { return m_hal->pollScope(); }
    Result<ScopeRows> readScopeRows(std::uint64_t from, std::size_t maxRows) override
    {
        return m_hal->readScopeRows(from, maxRows);
    }
    Result<ScopeCapture> readScopeCapture() override { return m_hal->readScopeCapture(); }
    Status stopScope() override { return m_hal->stopScope(); }

private:
    LinuxCncDrive() = default;
    Result<TestRequest> onPid(const TestRequest& request) const;
    /// A joint's positive number [JOINT_n]KEY; errors name the file, line and key.
    Result<double> jointNumber(int joint, const char* key) const;
    /// A jog out and back through LinuxCNC's own motion (LinuxCncMotion.h) while hal: records.
    struct MotionJog {
        int joint = -1;
        TestRequest request; ///< on the pid, with the acceleration motion uses
        double recordS = 0.0;
        std::chrono::milliseconds moveTimeout{0}; ///< for each of the two moves
    };
    /// A jog request (on the pid) as a jog through motion, checked against the joint's MAX_VELOCITY and
    /// MAX_ACCELERATION; nullopt when it is AxisTune's offset instead (not a jog, no joint, or no LinuxCNC task answers
    /// on the configuration's NML channels).
    Result<std::optional<MotionJog>> motionJog(const TestRequest& r);

    LinuxCncConfig m_config;
    std::unique_ptr<HalDrive> m_hal;
    std::vector<std::pair<std::string, std::string>> m_axes; ///< (axis name, pid) in joint order
    std::string m_machine;
    std::string m_lastAxis; ///< axis of the last test
    std::unique_ptr<LinuxCncMotion> m_motion; ///< LinuxCNC's task over NML, once a jog has found it running
};

/// The axis name of a pid of a configuration: its letter, `jointN`, or the pid's own name.
std::string linuxCncAxisName(const PidInstance& pid);

} // namespace axistune::device::hal

namespace axistune::device {
/// The registry entry of `linuxcnc:` (Backends.def).
DriveBackend linuxcncBackend();
} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One LinuxCNC servo axis seen through HAL: a `pid` instance, its nets and its servo thread; the run-time
// insertion of AxisTune's guarded injection (linuxcnc/axistune_inject.comp) and a streamer/sampler pair at
// the PID output; and one excitation streamed and recorded row by row (docs/linuxcnc.md).

#include "core/device/hal/HalCmd.h"
#include "core/device/hal/HalLink.h"
#include "core/device/hal/HalSampler.h"
#include "core/device/hal/HalText.h"
#include "core/model/Result.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace axistune::device::hal {

struct HalAxis {
    std::string pid;            ///< instance, e.g. "pid.x" or "pid.0"
    std::string pidFunction;    ///< "<pid>.do-pid-calcs"
    std::string thread;         ///< the thread that runs it
    std::int64_t periodNs = 0;  ///< its period
    std::string outputSignal;   ///< net driven by <pid>.output: the drive input
    std::string feedbackSignal; ///< net into <pid>.feedback
    std::string errorSignal;    ///< net driven by <pid>.error; empty when unlinked
    std::string commandSignal;  ///< net into <pid>.command; empty when unlinked
    double maxOutput = 0.0;     ///< <pid>.maxoutput (0: unlimited)
    double maxError = 0.0;      ///< <pid>.maxerror (0: unlimited)
    /// <pid>.error-previous-target (LinuxCNC 2.9, TRUE by default): the error is the previous period's command
    /// minus the feedback; false when the pin is FALSE or absent.
    bool errorPreviousTarget = false;
};

/// Finds the pid instance, its thread and nets. Errors name what is missing (no such pid, its output or feedback
/// not linked, its function on no thread).
Result<HalAxis> discoverAxis(const HalSessionOptions& options, const std::string& pid);

/// Columns the sampler records each servo period, in this order. At the PID command the injection column is the
/// position offset added to the command, and drive input and PID output are the same net.
enum HalColumn : std::size_t { DriveInput = 0, Feedback, PidOutput, Injection, FollowingError, kHalColumns };
const char* halColumnName(HalColumn c);

/// Where the injection adds its excitation: at the PID output (an FRF: a torque, current or velocity command added
/// to the drive's input) or at the PID command (a move: a position offset added to the command the pid follows).
enum class InjectionPoint { PidOutput, PidCommand };

struct InjectionSettings {
    InjectionPoint point = InjectionPoint::PidOutput;
    int fifoDepth = 16384;           ///< rows of the streamer FIFO (the sampler's: kTestSamplerDepth)
    double limit = 0.0;              ///< largest |excitation| in the PID output's units; the component trips above it
    double maxError = 0.0;           ///< following-error trip during the test; 0: the pid's maxerror
    double heartbeatTimeoutS = 0.03; ///< the injection falls to zero this long after AxisTune stops (issue 17: within
                                     ///< 50 ms; 20 ms left for a late thread)
    /// PidCommand: after a trip, an abort or the end, the position offset returns to zero at this speed [command
    /// units/s] instead of at once (a position step); required (> 0) there, 0 at the PID output.
    double returnRate = 0.0;
};

/// AxisTune's components inserted into one axis; removed (every net restored) by remove() or the destructor.
class HalInjection {
public:
    static Result<std::unique_ptr<HalInjection>> insert(const HalSessionOptions& options, const HalAxis& axis,
                                                        const InjectionSettings& settings, const HalClient& client);
    ~HalInjection();
    HalInjection(const HalInjection&) = delete;
    HalInjection& operator=(const HalInjection&) = delete;

    /// Undoes the insertion in reverse order; the first failure is returned, the remaining steps still run.
    Status remove();
    const HalAxis& axis() const { return m_axis; }
    const HalSessionOptions& options() const { return m_options; }
    const InjectionSettings& settings() const { return m_settings; }

private:
    HalInjection() = default;
    HalSessionOptions m_options;
    HalAxis m_axis;
    InjectionSettings m_settings;
    std::vector<std::vector<std::string>> m_undo; ///< halcmd argument lists, run last first
    std::shared_ptr<HalSamplerModule> m_sampler;  ///< sampler.0 records the test (shared with the scope)
};

/// Restores the nets of an injection left behind by an AxisTune that died (kill -9, power cut of the laptop):
/// relinks the PID output to its net and unloads axistune_inject, streamer and sampler when they are AxisTune's.
/// Succeeds with nothing to do when no injection is loaded.
Status removeLeftoverInjection(const HalSessionOptions& options);

/// AxisTune's notch: LinuxCNC's `biquad` (type 2) loaded as `axistune-notch`, run right after the pid, between
/// <pid>.output and the net it drove (docs/linuxcnc.md "Notches"). It stays until removeNotch() or the HAL session
/// ends: a notch is configuration, not part of a test. One per HAL session (LinuxCNC loads a component once).
inline constexpr const char* kNotchComponent = "axistune-notch";

/// Inserts (or moves and retunes) the notch at `f0Hz` with `q` on the axis. Refused when f0 is not below half the
/// servo rate or q lies outside [0.5, 2] (the component's own limits), when the configuration loads `biquad`
/// itself, or when the component reports its coefficients invalid. Nothing is left changed on a failure.
Status insertNotch(const HalSessionOptions& options, const HalAxis& axis, double f0Hz, double q);

/// Removes AxisTune's notch and relinks <pid>.output to the net the notch drove. Succeeds with nothing to do when
/// there is no notch.
Status removeNotch(const HalSessionOptions& options);

/// AxisTune's notch as it runs in HAL.
struct HalNotch {
    std::string pidOutput; ///< the pin that feeds it (<pid>.output); empty when its input is linked to no writer
    double f0Hz = 0.0;
    double q = 0.0;
};

/// AxisTune's notch when it is loaded (f0, Q as the component holds them, and the pid output that feeds it); none
/// when it is not.
Result<std::optional<HalNotch>> readNotch(const HalSessionOptions& options);

struct HalRecord {
    double sampleRateHz = 0.0;
    std::uint32_t firstSample = 0;            ///< the sampler's number of the first row
    std::vector<std::vector<double>> columns; ///< kHalColumns columns, one value per servo period
};

struct HalRunControl {
    std::function<void(double)> progress;     ///< 0..1, monotone
    const std::atomic<bool>* abort = nullptr; ///< set to stop: the injection is disarmed at once
};

/// Streams `excitation` (one value per servo period, PID output units) through the injection and records every
/// column for each of those periods. Fails (injection disarmed) on a lost or repeated row (sample numbers), a
/// streamer underrun while rows remain, a trip of the component (heartbeat, limit, following error), or abort.
Result<HalRecord> runExcitation(HalClient& client, HalInjection& injection, std::span<const double> excitation,
                                const HalRunControl& control = {});

} // namespace axistune::device::hal

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The `hal:` backend (docs/linuxcnc.md "The hal: connection"): a running HAL session (LinuxCNC, or a bare HAL
// loop such as scripts/hal-testbed) seen as a drive. An axis is a `pid` instance whose do-pid-calcs runs on a
// thread; the drive input is the net driven by <pid>.output, the feedback the net into <pid>.feedback; units
// are the HAL's. Parameters are the pid's gain pins (setp with read-back). Tests: FRF by multisine through
// AxisTune's guarded injection at the PID output (HalAxis.h), evaluated here with core's DSP as the plant
// feedback / (PID output + injection); a move out and back through the same injection at the PID command. Nothing is
// inserted between tests; every test removes what it inserted.

#include "core/device/Drive.h"
#include "core/device/DriveRegistry.h"
#include "core/device/hal/HalAxis.h"
#include "core/device/hal/HalScope.h"
#include "core/dsp/Multisine.h"

#include <atomic>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace axistune::device::hal {

/// halcmd from the environment: AXISTUNE_HALCMD (the command line, words separated by blanks; e.g.
/// "scripts/hal-testbed halcmd" for the repository's test machine run as root), else `halcmd`.
Result<HalSessionOptions> halSessionFromEnvironment();

/// The gain and limit pins of a LinuxCNC `pid` AxisTune offers as parameters (those the instance has).
std::vector<model::ParameterMeta> pidParameterMetadata();

/// An FRF test of a `hal:` axis as planned from the request and the axis: the multisine, how many periods settle
/// and how many are averaged, and the excitation streamed one value per servo period.
struct HalFrfPlan {
    HalAxis axis;
    dsp::MultisineDesign design;
    std::size_t settlePeriods = 1;
    std::size_t periods = 3;
    double fsHz = 0.0;
    FrfQuantity quantity = FrfQuantity::Plant;
    std::size_t totalSamples() const { return (settlePeriods + periods) * design.periodSamples(); }
};

/// Checks a request against the axis (multisine only, band below half the servo rate, peak at most half of
/// maxoutput, at most HalDrive::kMaxTestS of motion) and plans it. Errors name the field and the limit.
Result<HalFrfPlan> planHalFrf(const TestRequest& request, const HalAxis& axis);

/// A move of a `hal:` axis (TestType::Jog with returnToStart): out by `distance` and back, in the pid command's units,
/// added to the command the pid follows as an offset (HalAxis.h, InjectionPoint::PidCommand): dwell, move, move back,
/// dwell. The profile is MotionProfile's (trapezoid, or S-curve with a jerk limit).
struct HalMovePlan {
    HalAxis axis;
    double fsHz = 0.0;
    double distance = 0.0;      ///< command units
    double velocity = 0.0;      ///< command units/s; also the speed at which a tripped move returns
    std::vector<double> offset; ///< one value per servo period, first and last 0
};

/// Checks a jog request against the axis (out and back, finite positive speed and acceleration, at most
/// HalDrive::kMaxTestS, the pid's command linked) and plans it.
Result<HalMovePlan> planHalMove(const TestRequest& request, const HalAxis& axis);

/// The FRF of a completed record of that plan with its metadata: the plant feedback / drive input, or the open
/// loop −(PID output) / drive input.
Result<FrfMeasurement> evaluateHalFrf(const HalFrfPlan& plan, const HalRecord& record);

class HalDrive : public Drive {
public:
    static constexpr double kMaxTestS = 600.0;     ///< longest test [s]
    static constexpr double kMaxAmplitudePct = 50; ///< FRF peak, % of the pid's maxoutput (the injection's limit)

    /// Attaches to the HAL session halcmd reaches; removes an injection a dead AxisTune left behind. Errors say that
    /// no HAL session answers, quoting halcmd.
    static Result<std::unique_ptr<HalDrive>> open(const HalSessionOptions& options);
    ~HalDrive() override;

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

    // The scope (HalScope.h): LinuxCNC's sampler on the pid's pins; not while a test runs (both need the sampler).
    Result<ScopeCapabilities> scopeCapabilities(const std::string& axis) override;
    Status armScope(const ScopeRequest& request) override;
    Result<ScopeStatus> pollScope() override;
    Result<ScopeRows> readScopeRows(std::uint64_t from, std::size_t maxRows) override;
    Result<ScopeCapture> readScopeCapture() override;
    Status stopScope() override;

    /// A following-error limit of the axis besides its pid's maxerror (linuxcnc:: the joint's FERROR): the injection
    /// trips at the smaller of the two. 0 or less: none.
    void setFollowingErrorLimit(const std::string& pid, double limit);

private:
    explicit HalDrive(HalSessionOptions options) : m_options(std::move(options)) {}
    Result<std::vector<std::string>> pidNames() const;
    Status checkAxis(const std::string& axis) const;
    Result<HalFrfPlan> plan(const TestRequest& request) const;
    Result<HalMovePlan> movePlan(const TestRequest& request) const;
    void joinWorker();
    void run(HalAxis axis, InjectionSettings settings, std::vector<double> excitation);

    HalSessionOptions m_options;
    std::thread m_worker;
    mutable std::mutex m_mutex;
    std::condition_variable m_changed;
    TestStatus m_status; ///< guarded by m_mutex
    std::atomic<bool> m_abort{false};
    std::optional<HalFrfPlan> m_plan;       ///< of the last test when an FRF
    std::optional<HalMovePlan> m_move;      ///< of the last test when a move
    std::optional<HalRecord> m_record;      ///< of the last completed test
    bool m_linkLost = false;                ///< the last test failed and HAL no longer answers (guarded by m_mutex)
    std::map<std::string, double> m_ferror; ///< setFollowingErrorLimit, by pid
    std::unique_ptr<HalScope> m_scope;      ///< the armed (or stopped, still readable) scope
    /// The scope was stopped while a test ran: it stopped reading, and its pins and function leave HAL when the test
    /// has ended (a test rewires HAL's nets; the two must not change them at once).
    bool m_scopeStopDeferred = false;
    bool testRunning();
    void finishDeferredScopeStop();
    std::vector<ScopeChannelInfo> m_scopeChannels; ///< of the armed scope, in the request's order
    double m_scopeRateHz = 0.0;
    std::string m_firmware;
};

} // namespace axistune::device::hal

namespace axistune::device {
/// The registry entry of `hal:` (Backends.def).
DriveBackend halBackend();
} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The `hal:` backend (docs/linuxcnc.md "The hal: connection"): a running HAL session (LinuxCNC, or a bare HAL
// loop such as scripts/hal-testbed) seen as a drive. An axis is a `pid` instance whose do-pid-calcs runs on a
// thread; the drive input is the net driven by <pid>.output, the feedback the net into <pid>.feedback; units
// are the HAL's. Parameters are the pid's gain pins (setp with read-back). Tests: FRF by multisine through
// AxisTune's guarded injection at the PID output (HalAxis.h): multisine, multi-sweep or PRBS, evaluated with core's
// DSP as the plant feedback / (PID output + injection) or the open loop; a jog out and back and a position step
// through the same injection at the PID command. Nothing is
// inserted between tests; every test removes what it inserted.

#include "core/device/Drive.h"
#include "core/device/DriveRegistry.h"
#include "core/device/FrfTest.h"
#include "core/device/hal/HalAxis.h"
#include "core/device/hal/HalScope.h"
#include "core/dsp/Multisine.h"

#include <atomic>
#include <condition_variable>
#include <functional>
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

/// The HAL session (halSessionFromEnvironment) and the `pid` of an axis of a hal: or linuxcnc: drive: hal: names the
/// pid, linuxcnc: maps its axis name to the joint's pid (AxisNotch.cpp). BadInput for a drive of another backend.
struct DriveHalAxis {
    HalSessionOptions session;
    HalAxis axis;
};
Result<DriveHalAxis> halAxisOf(Drive& drive, const std::string& axis);

/// The gain and limit pins of a LinuxCNC `pid` AxisTune offers as parameters (those the instance has).
std::vector<model::ParameterMeta> pidParameterMetadata();

/// An FRF test of a `hal:` axis as planned from the request and the axis, one excitation value per servo period: a
/// multisine (its design, how many periods settle and how many are averaged), or sine streams of the multi-sweep
/// method or a PRBS planned by core's planFrfTest at the servo rate (FrfTest.h; `streams`).
struct HalFrfPlan {
    HalAxis axis;
    FrfMethod method = FrfMethod::Multisine;
    dsp::MultisineDesign design;            ///< multisine
    std::shared_ptr<const FrfPlan> streams; ///< multi-sweep, PRBS
    std::size_t settlePeriods = 1;          ///< multisine
    std::size_t periods = 3;                ///< multisine
    double fsHz = 0.0;
    FrfQuantity quantity = FrfQuantity::Plant;
    std::size_t totalSamples() const
    {
        return streams ? streams->totalSamples : (settlePeriods + periods) * design.periodSamples();
    }
    /// The largest |excitation| (the injection's limit): the multisine's peak, the sine or PRBS amplitude.
    double peak() const { return streams ? streams->amplitudeNm : design.peak; }
    /// The excitation, one value per servo period (totalSamples() values).
    std::vector<double> excitation() const;
};

/// Checks a request against the axis (multisine, multi-sweep or PRBS; lines below half the servo rate, peak at most
/// half of maxoutput, at most HalDrive::kMaxTestS of motion) and plans it. Errors name the field and the limit.
Result<HalFrfPlan> planHalFrf(const TestRequest& request, const HalAxis& axis);

/// The multi-sweep or PRBS part of planHalFrf (HalTestMethods.cpp): `plan` holds the axis, rate and quantity, `peak`
/// the checked excitation peak. Settle and measure times from the request, else kHalStreamSettleS and
/// kHalStreamMeasureS (hal: does not know the loop's dynamics).
Result<HalFrfPlan> planHalStreams(const TestRequest& request, HalFrfPlan plan, double peak);
inline constexpr double kHalStreamSettleS = 0.2;  ///< default settle per frequency (and before a PRBS record) [s]
inline constexpr double kHalStreamMeasureS = 0.2; ///< default measured time per frequency (three windows) [s]

/// A move of a `hal:` axis, added to the command the pid follows as an offset (HalAxis.h, InjectionPoint::PidCommand),
/// in the pid command's units. TestType::Jog with JogTest::returnToStart: out by `distance` and back (dwell, move, move
/// back, dwell), MotionProfile's trapezoid or S-curve. TestType::Step: a position step of `distance`
/// (StepTest::position) held for StepTest::recordS, then a step back to zero held as long (docs/linuxcnc.md "Step").
struct HalMovePlan {
    HalAxis axis;
    TestType type = TestType::Jog;
    double fsHz = 0.0;
    double distance = 0.0;      ///< command units
    double velocity = 0.0;      ///< jog: command units/s
    double returnRate = 0.0;    ///< command units/s at which a tripped or aborted move returns to zero
    std::size_t stepAt = 0;     ///< step: the first sample at +distance
    std::size_t backAt = 0;     ///< step: the first sample back at zero
    std::vector<double> offset; ///< one value per servo period, first and last 0
    bool external = false;      ///< the move is made by someone else (startExternalJog); the offset stays 0
};

/// Checks a jog request against the axis (out and back, finite positive speed and acceleration, at most
/// HalDrive::kMaxTestS, the pid's command linked) and plans it.
Result<HalMovePlan> planHalMove(const TestRequest& request, const HalAxis& axis);

/// Checks a step request against the axis and plans it: the step (StepTest::position, command units) at most half
/// of `followingErrorTrip` (the smaller of the pid's maxerror and the joint's FERROR: right after the step the
/// following error equals it; no limit: refused), a positive record length (StepTest::recordS), at most
/// HalDrive::kMaxTestS, the pid's command linked. The step comes after a tenth of the record length (at least one
/// period) at rest.
Result<HalMovePlan> planHalStep(const TestRequest& request, const HalAxis& axis, double followingErrorTrip);
inline constexpr double kHalStepReturnS = 0.1; ///< a tripped or aborted step ramps back to zero in this time [s]

/// The FRF of a completed record of that plan with its metadata: the plant feedback / drive input, or the open
/// loop −(PID output) / drive input.
Result<FrfMeasurement> evaluateHalFrf(const HalFrfPlan& plan, const HalRecord& record);

/// The multi-sweep or PRBS part of evaluateHalFrf: core's evaluateFrfSignals (FrfTest.h) on the record's drive input
/// and feedback (or −PID output).
Result<FrfMeasurement> evaluateHalStreams(const HalFrfPlan& plan, const HalRecord& record);

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

    /// Moves the axis with, while AxisTune records (linuxcnc:'s jog through LinuxCNC's own motion): `run` is called on
    /// the test's worker once the recording has begun and must make the whole move; `stop` turns true when the test
    /// is aborted or the record ends first, and `run` must then stop the motion and return.
    using ExternalMove = std::function<Status(const std::atomic<bool>& stop)>;
    /// A jog out and back (checked as planHalMove checks it) that `move` makes instead of AxisTune's offset to the
    /// command; the record lasts `recordS` (the move, its dwells and the mover's latency) and the offset stays 0.
    Status startExternalJog(const TestRequest& request, double recordS, ExternalMove move);
    /// The plan of such a jog (checked as startExternalJog checks it).
    Result<TestPlan> planExternalJog(const TestRequest& request, double recordS) const;

private:
    explicit HalDrive(HalSessionOptions options) : m_options(std::move(options)) {}
    Result<std::vector<std::string>> pidNames() const;
    Status checkAxis(const std::string& axis) const;
    Result<HalFrfPlan> plan(const TestRequest& request) const;
    Result<HalMovePlan> movePlan(const TestRequest& request) const;
    double followingErrorTrip(const HalAxis& axis) const; ///< the injection's trip: min of maxerror and FERROR
    void joinWorker();
    Status start(const TestRequest& request, ExternalMove external, double recordS);
    void run(HalAxis axis, InjectionSettings settings, std::vector<double> excitation, ExternalMove external);

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

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The embedded simulated drive: the default connection, a simulated machine behind the Drive seam.
// Tests run in slices of machine time inside pollTest(), so a caller on one thread stays responsive
// and can abort between polls.

#include "core/device/Drive.h"
#include "core/device/FaultInjection.h"
#include "core/device/FrfTest.h"
#include "core/device/MultisineTest.h"
#include "core/device/SimulatedDriveLimits.h"
#include "core/sim/AxisSimulator.h"

#include <map>
#include <memory>
#include <optional>

namespace axistune::device {

class SimulatedDrive : public Drive {
public:
    static Result<std::unique_ptr<SimulatedDrive>> create(const sim::MachineDefinition& machine, std::uint64_t seed);

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
    // The scope (docs/scope.md), on the velocity-loop rate of one axis. Machine time runs only in calls:
    // pollScope() runs the scope's axis one slice (setSliceSeconds) unless a running test moves that axis,
    // in which case pollTest() advances it and the scope samples the test. Channels of the other axes of the
    // machine ("Y.table_pos_m", scopeCompanionSignals) are sampled with it in one row: arming brings those axes
    // to the scope axis's machine time, and every poll keeps them there (they hold what they did last while a
    // test moves another axis), so row n holds every axis at the same velocity period.
    Result<ScopeCapabilities> scopeCapabilities(const std::string& axis) override;
    Status armScope(const ScopeRequest& request) override;
    Result<ScopeStatus> pollScope() override;
    Result<ScopeRows> readScopeRows(std::uint64_t from, std::size_t maxRows) override;
    Result<ScopeCapture> readScopeCapture() override;
    Status stopScope() override;
    /// The scope's state without running anything (axistune-simdrive advances the axis in wall-clock time).
    ScopeStatus scopeStatus() const { return m_scope.status(); }
    /// Channels of the armed scope.
    std::size_t scopeChannelCount() const { return m_scopeChannels.size(); }
    /// Whether the armed scope samples axis `axis` (its own axis or a companion's channels).
    bool scopeSamplesAxis(const std::string& axis) const;
    /// Runs every axis of the armed scope `ticks` current periods and keeps them at one machine time
    /// (axistune-simdrive's wall clock while no test moves them).
    void runScopeAxes(std::int64_t ticks);
    /// Brings every axis of the armed scope to the machine time of the one furthest ahead (after a test moved
    /// some of them).
    void syncScopeAxes();

    /// Failure modes of the link for tests (FaultInjection.h): drop-after:N makes the N-th call and every
    /// later one fail with ErrorCode::Device as a lost connection would ("sim:PRESET?fault=drop-after:N").
    void setFaults(const FaultInjection& faults) { m_faults = faults; }

    /// Machine time advanced per pollTest() call [s].
    void setSliceSeconds(double s) { m_slice = s; }
    sim::AxisSimulator* simulator(const std::string& axis);

private:
    SimulatedDrive() = default;
    Result<sim::AxisSimulator*> axisSim(const std::string& axis);
    /// The plan of an FRF test: a sine-stream/PRBS plan or a multisine plan, its length and trace period.
    struct FrfPlans {
        std::shared_ptr<const FrfPlan> sweep;
        std::shared_ptr<const MultisinePlan> multisine;
        double durationS = 0.0;
        double tracePeriodS = 0.0;
    };
    Result<FrfPlans> planFrf(const sim::AxisSimulator& sim, const TestRequest& request) const;
    /// Plans the FRF test, aligns to the trace grid and installs the injection; returns its length [s].
    Result<double> startFrf(sim::AxisSimulator& sim, const TestRequest& request);
    /// Checks of every test but Frf, Circle and CurrentStep; returns the test length [s] (Step, Hold: the record).
    Result<double> checkMotion(const sim::AxisSimulator& sim, const TestRequest& request) const;
    static sim::MotionProfile jogProfile(const sim::AxisSimulator& sim, const TestRequest& request);
    /// Fails when an injected fault has dropped the link (setFaults).
    Status checkLink();
    Result<TestPlan> planCircle(const TestRequest& request);
    /// The two axes of a circle request and its path, after checkCircleRequest (SimulatedDriveCircle.cpp).
    struct CheckedCircle;
    Result<CheckedCircle> checkCircle(const TestRequest& request);
    // The circle test of two axes (SimulatedDriveCircle.cpp).
    struct CircleState;
    Status startCircle(const TestRequest& request);
    Result<TestStatus> pollCircle();
    void abortCircle(const std::string& why);
    /// Whether a running test advances this axis (pollTest runs it).
    bool testMoves(const sim::AxisSimulator* axis) const;
    struct CurrentStepTiming {
        double h = 0.0;         ///< current-loop period [s]
        long long ticks = 0;    ///< record length [current periods]
        long long preTicks = 0; ///< record before the step [current periods]
        double lengthS = 0.0;   ///< record and hold [s]
    };
    Result<CurrentStepTiming> planCurrentStep(const sim::AxisSimulator& sim, const TestRequest& request) const;
    /// Checks and installs a current step (TestType::CurrentStep); returns the test length [s] (record and hold).
    Result<double> startCurrentStep(sim::AxisSimulator& sim, const TestRequest& request);
    /// Current step: at the end of the record, takes the trace and closes the position loop again.
    void endCurrentStepRecord();

    sim::MachineDefinition m_machine;
    std::map<std::string, std::unique_ptr<sim::AxisSimulator>> m_axes;
    double m_slice = 0.05;
    // The running test.
    std::optional<TestRequest> m_request;
    sim::AxisSimulator* m_active = nullptr;
    model::ParameterValues m_backup;
    double m_endTime = 0.0;
    double m_startTime = 0.0;
    TestStatus m_status;
    std::optional<model::Capture> m_trace;
    std::shared_ptr<const FrfPlan> m_frfPlan;
    std::shared_ptr<const MultisinePlan> m_multisinePlan;
    std::uint64_t m_clampsAtStart = 0; ///< voltage clamps of the current loop before a multisine test
    std::optional<FrfMeasurement> m_frf;
    std::shared_ptr<CircleState> m_circle; ///< the running circle test
    double m_recordEnd = -1.0; ///< current step: machine time the record ends and the hold begins (< 0: none)
    double m_stepStart = 0.0;  ///< current step: machine time of the step [s], capture metadata step_start_s
    FaultInjection m_faults;
    int m_requests = 0;
    // The scope.
    ScopeRecorder m_scope;
    sim::AxisSimulator* m_scopeSim = nullptr;
    std::vector<ScopeChannelInfo> m_scopeChannels; ///< of the armed request, in its order
    std::vector<double> m_scopeRow;
    /// One axis the armed scope samples: its simulator, (signal index, column) of its channels, and the offset of
    /// its velocity-period count from the scope axis's (fixed when armed).
    struct ScopeAxis {
        sim::AxisSimulator* sim = nullptr;
        std::vector<std::pair<std::size_t, std::size_t>> picks;
        std::int64_t tickOffset = 0;
    };
    std::vector<ScopeAxis> m_scopeAxes; ///< the scope axis first; more only with companion channels
    /// Rows of several axes waiting for the axes still behind: velocity period → (row, axes written).
    std::map<std::int64_t, std::pair<std::vector<double>, std::size_t>> m_scopePending;
    void disarmScopeTaps();
};

} // namespace axistune::device

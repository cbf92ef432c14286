// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The embedded simulated drive: the default connection, a simulated machine behind the Drive seam.
// Tests run in slices of machine time inside pollTest(), so a caller on one thread stays responsive
// and can abort between polls.

#include "core/device/Drive.h"
#include "core/device/FrfTest.h"
#include "core/device/MultisineTest.h"
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

    /// Machine time advanced per pollTest() call [s].
    void setSliceSeconds(double s) { m_slice = s; }
    sim::AxisSimulator* simulator(const std::string& axis);

private:
    SimulatedDrive() = default;
    Result<sim::AxisSimulator*> axisSim(const std::string& axis);
    /// Plans the FRF test, aligns to the trace grid and installs the injection; returns its length [s].
    Result<double> startFrf(sim::AxisSimulator& sim, const TestRequest& request);
    // The circle test of two axes (SimulatedDriveCircle.cpp).
    struct CircleState;
    Status startCircle(const TestRequest& request);
    Result<TestStatus> pollCircle();
    void abortCircle(const std::string& why);
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
    std::uint64_t m_clampsAtStart = 0;  ///< voltage clamps of the current loop before a multisine test
    std::optional<FrfMeasurement> m_frf;
    std::shared_ptr<CircleState> m_circle;  ///< the running circle test
    double m_recordEnd = -1.0;  ///< current step: machine time the record ends and the hold begins (< 0: none)
    std::string m_stepStart;    ///< current step: machine time of the step, as capture metadata
};

}  // namespace axistune::device

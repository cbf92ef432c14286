// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/SimulatedDrive.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace axistune::device {

const char* testStateName(TestState s)
{
    switch (s) {
    case TestState::Idle: return "idle";
    case TestState::Running: return "running";
    case TestState::Completed: return "completed";
    case TestState::Aborted: return "aborted";
    case TestState::Faulted: return "faulted";
    }
    return "?";
}

Result<std::unique_ptr<Drive>> connect(const ConnectionSettings& settings)
{
    const std::string prefix = "sim:";
    if (settings.uri.rfind(prefix, 0) == 0) {
        auto def = sim::loadPreset(settings.uri.substr(prefix.size()));
        if (!def)
            return makeError(def.error().code, "connection '" + settings.uri + "': " + def.error().detail);
        auto d = SimulatedDrive::create(*def, settings.seed);
        if (!d)
            return d.error();
        return std::unique_ptr<Drive>(std::move(d).value());
    }
    return makeError(ErrorCode::BadInput, "connection '" + settings.uri
                                              + "': expected sim:PRESET (Modbus TCP comes with a later release)");
}

Result<std::unique_ptr<SimulatedDrive>> SimulatedDrive::create(const sim::MachineDefinition& machine, std::uint64_t seed)
{
    std::unique_ptr<SimulatedDrive> d(new SimulatedDrive());
    d->m_machine = machine;
    std::uint64_t axisSeed = seed;
    for (const auto& a : machine.axes) {
        auto s = sim::AxisSimulator::create(a, axisSeed++);
        if (!s)
            return s.error();
        d->m_axes[a.name] = std::move(s).value();
    }
    return d;
}

sim::AxisSimulator* SimulatedDrive::simulator(const std::string& axis)
{
    auto it = m_axes.find(axis);
    return it == m_axes.end() ? nullptr : it->second.get();
}

Result<sim::AxisSimulator*> SimulatedDrive::axisSim(const std::string& axis)
{
    if (auto* s = simulator(axis))
        return s;
    std::string known;
    for (const auto& [n, s] : m_axes)
        known += (known.empty() ? "" : ", ") + n;
    return makeError(ErrorCode::NotFound, "no axis '" + axis + "' on machine " + m_machine.name + " (axes: " + known + ")");
}

Result<DriveIdentity> SimulatedDrive::identify()
{
    DriveIdentity id{"AxisTune", "simulated drive", AXISTUNE_VERSION, m_machine.name, {}};
    for (const auto& a : m_machine.axes)
        id.axes.push_back(a.name);
    return id;
}

Result<std::vector<model::ParameterMeta>> SimulatedDrive::parameterMetadata(const std::string& axis)
{
    auto s = axisSim(axis);
    if (!s)
        return s.error();
    std::vector<model::ParameterMeta> out;
    for (const auto& m : (*s)->parameterMetas()) {
        if (!sim::isPlantParameter(m.key))  // the plant is the machine, not a drive parameter
            out.push_back(m);
    }
    return out;
}

Result<model::ParameterValues> SimulatedDrive::readParameters(const std::string& axis, std::span<const std::string> keys)
{
    auto s = axisSim(axis);
    if (!s)
        return s.error();
    model::ParameterValues out;
    const auto& values = (*s)->parameters();
    if (keys.empty()) {
        for (const auto& [k, v] : values) {
            if (!sim::isPlantParameter(k))
                out[k] = v;
        }
        return out;
    }
    for (const auto& k : keys) {
        auto it = values.find(k);
        if (it == values.end() || sim::isPlantParameter(k))
            return makeError(ErrorCode::NotFound, "axis " + axis + ": unknown parameter '" + k + "'");
        out[k] = it->second;
    }
    return out;
}

Status SimulatedDrive::writeParameters(const std::string& axis, const model::ParameterValues& values)
{
    auto s = axisSim(axis);
    if (!s)
        return s.error();
    const bool testRunning = m_status.state == TestState::Running;
    for (const auto& [k, v] : values) {
        const auto* meta = model::findParameter((*s)->parameterMetas(), k);
        if (!meta || sim::isPlantParameter(k))
            return makeError(ErrorCode::NotFound, "axis " + axis + ": unknown parameter '" + k + "'");
        if (!meta->writable)
            return makeError(ErrorCode::BadInput, "axis " + axis + ": parameter '" + k + "' is read-only");
        if (testRunning && !meta->writableDuringTest)
            return makeError(ErrorCode::Busy, "axis " + axis + ": parameter '" + k + "' cannot be written while a test runs");
        if (auto st = model::checkParameterValue(*meta, v); !st)
            return makeError(st.error().code, "axis " + axis + ": " + st.error().detail);
    }
    return (*s)->setParameters(values);
}

Status SimulatedDrive::startTest(const TestRequest& request)
{
    if (m_status.state == TestState::Running)
        return makeError(ErrorCode::Busy, "a test is already running");
    auto s = axisSim(request.axis);
    if (!s)
        return s.error();
    sim::AxisSimulator& sim = **s;
    if (!(request.durationS > 0.0) || request.durationS > 600.0)
        return makeError(ErrorCode::OutOfRange, "test duration must lie in (0, 600] s");
    m_backup = sim.parameters();
    if (request.traceDivider > 0) {
        if (auto st = sim.setParameters({{"trace.divider", request.traceDivider}}); !st)
            return st;
    }
    const double start = sim.positionCommand();
    double length = request.durationS;
    switch (request.type) {
    case TestType::Step: {
        const double maxSpeed = 2.0 * std::numbers::pi * 6000.0 / 60.0;
        if (!std::isfinite(request.amplitude) || std::abs(request.amplitude) > maxSpeed)
            return makeError(ErrorCode::OutOfRange, "step amplitude must be finite and at most 628 rad/s (6000 min^-1)");
        sim.setControlMode(sim::ControlMode::Velocity);
        const double t0 = sim.time() + 0.01 * request.durationS, amp = request.amplitude;
        sim.setVelocityCommand([t0, amp](double t) { return t >= t0 ? amp : 0.0; });
        break;
    }
    case TestType::Jog: {
        if (!(request.velocity > 0.0) || !(request.acceleration > 0.0) || !std::isfinite(request.distance))
            return makeError(ErrorCode::OutOfRange, "jog needs a positive velocity and acceleration and a finite distance");
        sim::MotionProfile p(start);
        p.dwell(request.durationS);
        p.move(request.distance, request.velocity, request.acceleration);
        if (request.returnToStart)
            p.move(-request.distance, request.velocity, request.acceleration);
        p.dwell(request.durationS);
        sim.setControlMode(sim::ControlMode::Position);
        sim.setPositionProfile(p);
        length = p.duration();
        break;
    }
    case TestType::Hold: {
        sim::MotionProfile p(start);
        p.dwell(request.durationS);
        sim.setControlMode(sim::ControlMode::Position);
        sim.setPositionProfile(p);
        break;
    }
    }
    sim.startTrace();
    m_request = request;
    m_active = &sim;
    m_startTime = sim.time();
    m_endTime = m_startTime + length;
    m_trace.reset();
    m_status = {TestState::Running, 0.0, {}};
    return Status::success();
}

Result<TestStatus> SimulatedDrive::pollTest()
{
    if (m_status.state != TestState::Running || !m_active)
        return m_status;
    const double remaining = m_endTime - m_active->time();
    m_active->run(std::min(m_slice, std::max(0.0, remaining)));
    const double total = m_endTime - m_startTime;
    m_status.progress = std::clamp((m_active->time() - m_startTime) / total, 0.0, 1.0);
    if (m_active->time() >= m_endTime - 0.5 * m_active->currentPeriod()) {
        m_trace = m_active->takeTrace();
        m_trace->metadata["machine"] = m_machine.name;
        m_active->setVelocityCommand({});
        (void)m_active->setParameters(m_backup);
        m_status = {TestState::Completed, 1.0, {}};
        m_active = nullptr;
    }
    return m_status;
}

Result<model::Capture> SimulatedDrive::readTrace()
{
    if (!m_trace)
        return makeError(ErrorCode::NotFound, "no trace: no test has completed");
    return *m_trace;
}

Status SimulatedDrive::abortTest()
{
    if (m_status.state != TestState::Running || !m_active)
        return Status::success();
    // Stop at once: hold the present position, drop the test's commands, restore the parameters.
    m_active->stopTrace();
    m_active->setVelocityCommand({});
    m_active->setTorqueInjection({});
    m_active->setControlMode(sim::ControlMode::Velocity);
    (void)m_active->setParameters(m_backup);
    m_status = {TestState::Aborted, m_status.progress, "aborted by the user"};
    m_active = nullptr;
    return Status::success();
}

}  // namespace axistune::device

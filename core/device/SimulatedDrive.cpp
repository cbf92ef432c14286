// SPDX-License-Identifier: GPL-3.0-or-later
// Current-step test (TestType::CurrentStep): the q-axis current loop of spec/current-loop-and-multisweep-frf.md
// §1.2, §2.3 stepped with the velocity loop open; docs/simulator.md "Current-step test".
#include "core/device/SimulatedDrive.h"

#include "core/device/FrfRequestPlan.h"
#include "core/device/ModbusDrive.h"
#include "core/model/Constants.h"
#include "core/model/Number.h"
#include "core/model/Units.h"
#include "core/sim/IdentifiedPlant.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

namespace {

// "model=PATH[&axis=NAME]": the identified rigid-body model of `axistune-cli identify` as the
// plant of one axis (docs/identification.md "Using the result"). The axis may be left out when the
// machine has one axis of the model's kind.
Status applySimQuery(sim::MachineDefinition& def, const std::string& query)
{
    std::string modelPath, axisName;
    std::size_t start = 0;
    while (start <= query.size()) {
        const auto amp = query.find('&', start);
        const std::string item = query.substr(start, amp == std::string::npos ? std::string::npos : amp - start);
        const auto eq = item.find('=');
        const std::string key = item.substr(0, eq), value = eq == std::string::npos ? "" : item.substr(eq + 1);
        if (key == "model" && !value.empty())
            modelPath = value;
        else if (key == "axis" && !value.empty())
            axisName = value;
        else
            return makeError(ErrorCode::BadInput,
                             "unknown or empty option '" + item + "' (expected model=PATH and axis=NAME)");
        if (amp == std::string::npos)
            break;
        start = amp + 1;
    }
    if (modelPath.empty())
        return makeError(ErrorCode::BadInput, "axis=NAME needs model=PATH");
    auto m = ident::readIdentifiedModelFile(modelPath);
    if (!m)
        return m.error();
    const auto kind = m->motion == ident::AxisMotion::Linear ? sim::AxisKind::Linear : sim::AxisKind::Rotary;
    sim::AxisDefinition* target = nullptr;
    int candidates = 0;
    for (auto& a : def.axes) {
        if (axisName.empty() ? a.kind == kind : a.name == axisName) {
            target = &a;
            ++candidates;
        }
    }
    if (target == nullptr)
        return makeError(ErrorCode::NotFound, axisName.empty() ? "no axis of the model's kind on machine " + def.name
                                                               : "no axis '" + axisName + "' on machine " + def.name);
    if (candidates > 1)
        return makeError(ErrorCode::BadInput, "machine " + def.name + " has several such axes: give axis=NAME");
    return sim::applyIdentifiedModel(*target, *m, modelPath);
}

} // namespace

Result<std::unique_ptr<Drive>> connect(const ConnectionSettings& settings)
{
    const std::string prefix = "sim:";
    if (settings.uri.rfind(prefix, 0) == 0) {
        const std::string rest = settings.uri.substr(prefix.size());
        const auto q = rest.find('?');
        auto def = sim::loadPreset(rest.substr(0, q));
        if (!def)
            return makeError(def.error().code, "connection '" + settings.uri + "': " + def.error().detail);
        if (q != std::string::npos) {
            if (auto st = applySimQuery(def.value(), rest.substr(q + 1)); !st)
                return makeError(st.error().code, "connection '" + settings.uri + "': " + st.error().detail);
        }
        auto d = SimulatedDrive::create(*def, settings.seed);
        if (!d)
            return d.error();
        return std::unique_ptr<Drive>(std::move(d).value());
    }
    if (settings.uri.rfind("modbus://", 0) == 0)
        return connectModbus(settings);
    return makeError(ErrorCode::BadInput, "connection '" + settings.uri + "': expected sim:PRESET or modbus://HOST:PORT");
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
    if (request.type == TestType::Circle)
        return startCircle(request);
    auto s = axisSim(request.axis);
    if (!s)
        return s.error();
    sim::AxisSimulator& sim = **s;
    if (request.type != TestType::Frf && (!(request.durationS > 0.0) || request.durationS > 600.0))
        return makeError(ErrorCode::OutOfRange, "test duration must lie in (0, 600] s");
    m_backup = sim.parameters();
    if (request.traceDivider > 0) {
        if (auto st = sim.setParameters({{"trace.divider", request.traceDivider}}); !st)
            return st;
    }
    const double start = sim.positionCommand();
    double length = request.durationS;
    m_frfPlan.reset();
    m_multisinePlan.reset();
    m_frf.reset();
    m_recordEnd = -1.0;
    switch (request.type) {
    case TestType::Step: {
        if (!std::isfinite(request.amplitude) || std::abs(request.amplitude) > kMaxMotorSpeedRadS)
            return makeError(ErrorCode::OutOfRange, "step amplitude must be finite and at most 628 rad/s (6000 min^-1)");
        sim.setControlMode(sim::ControlMode::Velocity);
        const double t0 = sim.time() + 0.01 * request.durationS, amp = request.amplitude;
        sim.setVelocityCommand([t0, amp](double t) { return t >= t0 ? amp : 0.0; });
        break;
    }
    case TestType::Jog: {
        if (!(request.velocity > 0.0) || !(request.acceleration > 0.0) || !std::isfinite(request.distance))
            return makeError(ErrorCode::OutOfRange, "jog needs a positive velocity and acceleration and a finite distance");
        if (!(request.jerk >= 0.0) || !std::isfinite(request.jerk))
            return makeError(ErrorCode::OutOfRange, "jog jerk must be finite and >= 0 (0: trapezoid)");
        // The velocity is in axis units: m/s on a linear axis (motor speed = v / R), rad/s on a rotary one.
        const bool linear = sim.kind() == sim::AxisKind::Linear;
        const double motorSpeed = linear ? request.velocity / sim.parameter("plant.screw_lead") : request.velocity;
        if (!(motorSpeed <= kMaxMotorSpeedRadS))
            return makeError(ErrorCode::OutOfRange,
                             "jog velocity " + model::formatNumber(request.velocity, 4) + (linear ? " m/s" : " rad/s") +
                                 " means " + model::formatNumber(motorSpeed, 4) +
                                 " rad/s at the motor, above the limit of 628.3 rad/s (6000 min^-1)");
        sim::MotionProfile p(start);
        p.dwell(request.durationS);
        p.move(request.distance, request.velocity, request.acceleration, request.jerk);
        if (request.returnToStart)
            p.move(-request.distance, request.velocity, request.acceleration, request.jerk);
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
    case TestType::Frf: {
        auto len = startFrf(sim, request);
        if (!len) {
            (void)sim.setParameters(m_backup);
            return len.error();
        }
        length = *len;
        break;
    }
    case TestType::Circle:  // started by startCircle above
        break;
    case TestType::CurrentStep: {
        auto len = startCurrentStep(sim, request);
        if (!len) {
            (void)sim.setParameters(m_backup);
            return len.error();
        }
        length = *len;
        break;
    }
    }
    if (request.type != TestType::CurrentStep)
        sim.startTrace();
    m_request = request;
    m_active = &sim;
    m_startTime = sim.time();  // for Frf: aligned to the first trace sample
    m_endTime = m_startTime + length;
    m_trace.reset();
    m_status = {TestState::Running, 0.0, {}};
    return Status::success();
}

Result<TestStatus> SimulatedDrive::pollTest()
{
    if (m_circle && m_status.state == TestState::Running)
        return pollCircle();
    if (m_status.state != TestState::Running || !m_active)
        return m_status;
    const double remaining = (m_recordEnd >= 0.0 ? m_recordEnd : m_endTime) - m_active->time();
    m_active->run(std::min(m_slice, std::max(0.0, remaining)));
    if (m_recordEnd >= 0.0 && m_active->time() >= m_recordEnd - 0.5 * m_active->currentPeriod())
        endCurrentStepRecord();
    const double total = m_endTime - m_startTime;
    m_status.progress = std::clamp((m_active->time() - m_startTime) / total, 0.0, 1.0);
    if (m_active->time() >= m_endTime - 0.5 * m_active->currentPeriod()) {
        if (!m_trace)  // a current step took its trace at the end of its record
            m_trace = m_active->takeTrace();
        m_trace->metadata["machine"] = m_machine.name;
        m_active->setVelocityCommand({});
        m_active->setTorqueInjection({});
        (void)m_active->setParameters(m_backup);
        m_status = {TestState::Completed, 1.0, {}};
        m_active = nullptr;
        if (m_frfPlan || m_multisinePlan) {
            auto frf = m_frfPlan ? evaluateFrfTrace(*m_frfPlan, *m_trace) : evaluateMultisineTrace(*m_multisinePlan, *m_trace);
            if (!frf) {
                m_status = {TestState::Faulted, 1.0, "FRF evaluation: " + frf.error().detail};
                return m_status;
            }
            FrfMeasurement m = std::move(frf).value();
            if (m_multisinePlan) {
                // The traced voltage shows clamps at trace samples only; the simulator counts them at
                // every current tick. A multisine spreads a clamp over every line: none is linear then.
                const std::uint64_t clamps = m_request ? simulator(m_request->axis)->voltageClampCount() - m_clampsAtStart : 0;
                m.frf.metadata["voltage_clamped_ticks"] = std::to_string(clamps);
                if (clamps > 0)
                    std::fill(m.frf.valid.begin(), m.frf.valid.end(), false);
            }
            m.frf.metadata["machine"] = m_machine.name;
            m.frf.metadata["axis"] = m_request->axis;
            m_frf = std::move(m);
        }
    }
    return m_status;
}

Result<model::Capture> SimulatedDrive::readTrace()
{
    if (!m_trace)
        return makeError(ErrorCode::NotFound, "no trace: no test has completed");
    return *m_trace;
}

Result<FrfMeasurement> SimulatedDrive::readFrequencyResponse()
{
    if (!m_frf)
        return makeError(ErrorCode::NotFound, "no frequency response: no FRF test has completed");
    return *m_frf;
}

Result<double> SimulatedDrive::startFrf(sim::AxisSimulator& sim, const TestRequest& r)
{
    const auto& v = sim.parameters();
    const double rated = model::ratedTorqueNm(v.at("motor.rated_current"), v.at("motor.torque_constant"));
    if (!std::isfinite(r.amplitudePct) || !(r.amplitudePct > 0.0) || r.amplitudePct > kMaxFrfAmplitudePct) {
        return makeError(ErrorCode::OutOfRange, "FRF amplitude " + model::formatNumber(r.amplitudePct, 6) +
                                                    " % of rated torque refused: it must lie in (0, " +
                                                    model::formatNumber(kMaxFrfAmplitudePct, 6) + "] % (rated torque " +
                                                    model::formatNumber(rated, 4) + " Nm)");
    }
    AxisClock clock;
    clock.currentPeriodS = sim.currentPeriod();
    clock.ticksPerVelocity = static_cast<int>(std::llround(sim.velocityPeriod() / sim.currentPeriod()));
    clock.traceDivider = static_cast<int>(std::llround(sim.tracePeriod() / sim.velocityPeriod()));
    auto plan = planFrfRequest(r, v, clock);
    if (!plan)
        return plan.error();
    // The axis holds velocity 0 while the disturbance acts (spec §4.3 step 1).
    sim.setControlMode(sim::ControlMode::Velocity);
    sim.setVelocityCommand({});
    // Run to the next current tick that is also a traced velocity tick: trace sample 0 is there.
    const double h = sim.currentPeriod();
    const auto ticksPerSample = std::llround(sim.tracePeriod() / h);
    const auto now = std::llround(sim.time() / h);
    const auto first = (now + ticksPerSample - 1) / ticksPerSample * ticksPerSample;
    sim.runTicks(first - now);
    const double t0 = static_cast<double>(first) * h;
    if (plan->multisine) {
        auto shared = plan->multisine;
        sim.setTorqueInjection(
            [shared, t0, h](double t) { return multisineExcitation(*shared, std::llround((t - t0) / h)); });
        m_multisinePlan = shared;
        m_clampsAtStart = sim.voltageClampCount();
        return shared->durationS();
    }
    auto shared = plan->streams;
    const double sampleS = sim.tracePeriod();
    sim.setTorqueInjection([shared, t0, sampleS, h](double t) {
        // Whole current ticks from the first sample, as a fractional trace-sample position.
        const double ticks = std::round((t - t0) / h);
        return frfExcitation(*shared, ticks * h / sampleS);
    });
    m_frfPlan = shared;
    return shared->durationS();
}

Status SimulatedDrive::abortTest()
{
    if (m_circle && m_status.state == TestState::Running) {
        abortCircle("aborted by the user");
        return Status::success();
    }
    if (m_status.state != TestState::Running || !m_active)
        return Status::success();
    // Stop at once: hold the present position, drop the test's commands, restore the parameters.
    m_active->stopTrace();
    m_active->setVelocityCommand({});
    m_active->setTorqueInjection({});
    m_active->setCurrentCommand({});
    m_active->setControlMode(sim::ControlMode::Velocity);
    (void)m_active->setParameters(m_backup);
    m_recordEnd = -1.0;
    m_frfPlan.reset();
    m_multisinePlan.reset();
    m_status = {TestState::Aborted, m_status.progress, "aborted by the user"};
    m_active = nullptr;
    return Status::success();
}

Result<double> SimulatedDrive::startCurrentStep(sim::AxisSimulator& sim, const TestRequest& r)
{
    const auto& v = sim.parameters();
    const double iMax = v.at("motor.max_current"), kt = v.at("motor.torque_constant"), j = v.at("plant.inertia_motor");
    const double limitA = kMaxCurrentStepFraction * iMax;
    const auto g = [](double x) { return model::formatNumber(x, 6); }; // printf's %g
    if (!std::isfinite(r.amplitude) || r.amplitude == 0.0 || std::abs(r.amplitude) > limitA) {
        return makeError(ErrorCode::OutOfRange,
                         "current step " + g(r.amplitude) + " A refused: it must be finite, non-zero and at most " +
                             g(100.0 * kMaxCurrentStepFraction) + " % of motor.max_current (" + g(limitA) + " A)");
    }
    if (!std::isfinite(r.durationS) || !(r.durationS > 0.0) || r.durationS > kMaxCurrentStepS) {
        return makeError(ErrorCode::OutOfRange, "current-step recording " + g(r.durationS) +
                                                    " s refused: it must lie in (0, " + g(kMaxCurrentStepS) + "] s");
    }
    const double h = sim.currentPeriod();
    const auto ticks = std::llround(r.durationS / h);
    const auto preTicks = std::max<long long>(1, std::llround(0.1 * r.durationS / h));
    if (ticks < preTicks + 2) {
        return makeError(ErrorCode::OutOfRange, "current-step recording " + g(r.durationS) +
                                                    " s refused: shorter than a few current periods (" + g(h) + " s)");
    }
    // With the velocity loop open the motor accelerates freely: k_t·|I|·t / J_m at the end of the record, with
    // the rotor inertia alone (a motor datum; the coupled load can only make it slower).
    const double stepS = static_cast<double>(ticks - preTicks) * h;
    const double speed = j > 0.0 ? kt * std::abs(r.amplitude) * stepS / j : std::numeric_limits<double>::infinity();
    if (!(speed <= kMaxCurrentStepSpeedRadS)) {
        return makeError(ErrorCode::OutOfRange,
                         "current step " + g(r.amplitude) + " A for " + g(stepS) +
                             " s refused: the motor would reach about " + model::formatNumber(speed, 3) +
                             " rad/s (k_t·I·t/J_m with the rotor inertia J_m " + g(j) + " kg·m²), above the " +
                             g(kMaxCurrentStepSpeedRadS) + " rad/s a current step may reach; lower or shorten it");
    }
    // The record starts on a whole current tick; the step comes preTicks later and holds to the end.
    const double t0 = sim.time();
    const double tStep = t0 + static_cast<double>(preTicks) * h;
    const double amp = r.amplitude, half = 0.5 * h;
    sim.setControlMode(sim::ControlMode::Current);
    sim.setCurrentCommand([tStep, amp, half](double t) { return t >= tStep - half ? amp : 0.0; });
    sim.startTrace(sim::TraceRate::Current);
    m_clampsAtStart = sim.voltageClampCount();
    m_recordEnd = t0 + static_cast<double>(ticks) * h;
    m_stepStart = model::formatNumber(tStep, 17);
    return static_cast<double>(ticks) * h + kCurrentStepHoldS;
}

void SimulatedDrive::endCurrentStepRecord()
{
    m_recordEnd = -1.0;
    m_trace = m_active->takeTrace();
    m_trace->metadata["test"] = "current_step";
    m_trace->metadata["step_start_s"] = m_stepStart;
    model::setMetadataNumber(m_trace->metadata, "step_amplitude_A", m_request ? m_request->amplitude : 0.0);
    m_trace->metadata["voltage_clamped_ticks"] = std::to_string(m_active->voltageClampCount() - m_clampsAtStart);
    m_active->setCurrentCommand({});
    m_active->holdPosition();
}

}  // namespace axistune::device

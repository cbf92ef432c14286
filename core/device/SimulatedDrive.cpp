// SPDX-License-Identifier: GPL-3.0-or-later
// Current-step test (TestType::CurrentStep): the q-axis current loop of spec/current-loop-and-multisweep-frf.md
// §1.2, §2.3 stepped with the velocity loop open; docs/simulator.md "Current-step test".
#include "core/device/SimulatedDrive.h"

#include "core/device/FrfRequestPlan.h"
#include "core/model/Constants.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/model/Units.h"

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
    if (auto st = checkLink(); !st)
        return st.error();
    DriveIdentity id{"AxisTune", "simulated drive", AXISTUNE_VERSION, m_machine.name, {}};
    for (const auto& a : m_machine.axes)
        id.axes.push_back(a.name);
    return id;
}

Result<std::vector<model::ParameterMeta>> SimulatedDrive::parameterMetadata(const std::string& axis)
{
    if (auto st = checkLink(); !st)
        return st.error();
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
    if (auto st = checkLink(); !st)
        return st.error();
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
    if (auto st = checkLink(); !st)
        return st;
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

Status SimulatedDrive::checkLink()
{
    if (m_faults.dropAfterRequests > 0 && ++m_requests >= m_faults.dropAfterRequests)
        return makeError(ErrorCode::Device, "connection lost: fault drop-after:" +
                                                std::to_string(m_faults.dropAfterRequests) + " injected");
    return Status::success();
}

Result<double> SimulatedDrive::checkMotion(const sim::AxisSimulator& sim, const TestRequest& request) const
{
    // Record length or dwell: the length of every test but an FRF, whose length follows from its plan.
    const double durationS = recordOrDwellS(request);
    if (request.type() != TestType::Frf && (!(durationS > 0.0) || durationS > kMaxTestDurationS))
        return makeError(ErrorCode::OutOfRange, "test duration " + model::formatNumber(durationS, 6) +
                                                    " s refused: it must lie in (0, " +
                                                    model::formatNumber(kMaxTestDurationS, 6) + "] s");
    switch (request.type()) {
    case TestType::Step: {
        const StepTest& step = request.step();
        if (step.position != 0.0)
            return makeError(ErrorCode::BadInput,
                             "this drive steps the motor velocity (StepTest::velocityRadS, rad/s): a "
                             "position step request is refused");
        if (!std::isfinite(step.velocityRadS) || std::abs(step.velocityRadS) > kMaxMotorSpeedRadS)
            return makeError(ErrorCode::OutOfRange, "step amplitude " + model::formatNumber(step.velocityRadS, 6) +
                                                        " rad/s refused: it must be finite and at most " +
                                                        model::formatNumber(kMaxMotorSpeedRadS, 4) +
                                                        " rad/s (6000 min^-1)");
        return step.recordS;
    }
    case TestType::Jog: {
        const JogTest& jog = request.jog();
        if (!(jog.velocity > 0.0) || !(jog.acceleration > 0.0) || !std::isfinite(jog.distance))
            return makeError(ErrorCode::OutOfRange,
                             "jog needs a positive velocity and acceleration and a finite distance");
        if (!(jog.jerk >= 0.0) || !std::isfinite(jog.jerk))
            return makeError(ErrorCode::OutOfRange, "jog jerk must be finite and >= 0 (0: trapezoid)");
        // The velocity is in axis units: m/s on a linear axis (motor speed = v / R), rad/s on a rotary one.
        const bool linear = sim.kind() == sim::AxisKind::Linear;
        const double motorSpeed = linear ? jog.velocity / sim.parameter("plant.screw_lead") : jog.velocity;
        if (!(motorSpeed <= kMaxMotorSpeedRadS))
            return makeError(ErrorCode::OutOfRange,
                             "jog velocity " + model::formatNumber(jog.velocity, 4) + (linear ? " m/s" : " rad/s") +
                                 " means " + model::formatNumber(motorSpeed, 4) +
                                 " rad/s at the motor, above the limit of " +
                                 model::formatNumber(kMaxMotorSpeedRadS, 4) + " rad/s (6000 min^-1)");
        return jogProfile(sim, request).duration();
    }
    default:
        return durationS;
    }
}

sim::MotionProfile SimulatedDrive::jogProfile(const sim::AxisSimulator& sim, const TestRequest& request)
{
    const JogTest& jog = request.jog();
    sim::MotionProfile p(sim.positionCommand());
    p.dwell(jog.dwellS);
    p.move(jog.distance, jog.velocity, jog.acceleration, jog.jerk);
    if (jog.returnToStart)
        p.move(-jog.distance, jog.velocity, jog.acceleration, jog.jerk);
    p.dwell(jog.dwellS);
    return p;
}

Status SimulatedDrive::startTest(const TestRequest& request)
{
    if (auto st = checkLink(); !st)
        return st;
    if (m_status.state == TestState::Running)
        return makeError(ErrorCode::Busy, "a test is already running");
    if (request.type() == TestType::Circle)
        return startCircle(request);
    auto s = axisSim(request.axis);
    if (!s)
        return s.error();
    sim::AxisSimulator& sim = **s;
    auto checked = checkMotion(sim, request);
    if (!checked)
        return checked.error();
    m_backup = sim.parameters();
    if (request.traceDivider > 0) {
        if (auto st = sim.setParameters({{"trace.divider", request.traceDivider}}); !st)
            return st;
    }
    const double start = sim.positionCommand();
    double length = *checked;
    m_frfPlan.reset();
    m_multisinePlan.reset();
    m_frf.reset();
    m_recordEnd = -1.0;
    switch (request.type()) {
    case TestType::Step: {
        sim.setControlMode(sim::ControlMode::Velocity);
        const double t0 = sim.time() + 0.01 * request.step().recordS, amp = request.step().velocityRadS;
        sim.setVelocityCommand([t0, amp](double t) { return t >= t0 ? amp : 0.0; });
        break;
    }
    case TestType::Jog: {
        sim.setControlMode(sim::ControlMode::Position);
        sim.setPositionProfile(jogProfile(sim, request));
        break;
    }
    case TestType::Hold: {
        sim::MotionProfile p(start);
        p.dwell(request.hold().recordS);
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
    if (request.type() != TestType::CurrentStep)
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
    if (auto st = checkLink(); !st)
        return st.error();
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
        m_trace->metadata.set(model::meta::kMachine, m_machine.name);
        m_trace->metadata.set(model::meta::kMotionTimeS, m_active->time() - m_startTime);
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
                m.frf.metadata.set(model::meta::kVoltageClampedTicks, clamps);
                if (clamps > 0)
                    std::fill(m.frf.valid.begin(), m.frf.valid.end(), false);
            }
            m.frf.metadata.set(model::meta::kMachine, m_machine.name);
            m.frf.metadata.set(model::meta::kAxis, m_request->axis);
            m_frf = std::move(m);
        }
    }
    return m_status;
}

Result<model::Capture> SimulatedDrive::readTrace()
{
    if (auto st = checkLink(); !st)
        return st.error();
    if (!m_trace)
        return makeError(ErrorCode::NotFound, "no trace: no test has completed");
    return *m_trace;
}

Result<FrfMeasurement> SimulatedDrive::readFrequencyResponse()
{
    if (auto st = checkLink(); !st)
        return st.error();
    if (!m_frf)
        return makeError(ErrorCode::NotFound, "no frequency response: no FRF test has completed");
    return *m_frf;
}

Result<SimulatedDrive::FrfPlans> SimulatedDrive::planFrf(const sim::AxisSimulator& sim,
                                                         const TestRequest& request) const
{
    const auto& v = sim.parameters();
    const double rated = model::ratedTorqueNm(v.at("motor.rated_current"), v.at("motor.torque_constant"));
    if (auto st = checkRatedTorqueFrfRequest(request); !st)
        return st.error();
    const FrfTest& r = request.frf();
    if (!std::isfinite(r.amplitudePct) || !(r.amplitudePct > 0.0) || r.amplitudePct > kMaxFrfAmplitudePct) {
        return makeError(ErrorCode::OutOfRange, "FRF amplitude " + model::formatNumber(r.amplitudePct, 6) +
                                                    " % of rated torque refused: it must lie in (0, " +
                                                    model::formatNumber(kMaxFrfAmplitudePct, 6) + "] % (rated torque " +
                                                    model::formatNumber(rated, 4) + " Nm)");
    }
    if (!(r.settleS >= 0.0) || !(r.minMeasureS >= 0.0))
        return makeError(ErrorCode::OutOfRange, "FRF settle and measure times must not be negative");
    // The plan itself is the host's too (FrfRequestPlan.h): a drive that only streams samples is evaluated with it.
    AxisClock clock;
    clock.currentPeriodS = sim.currentPeriod();
    clock.ticksPerVelocity = static_cast<int>(std::llround(sim.velocityPeriod() / sim.currentPeriod()));
    clock.traceDivider =
        static_cast<int>(request.traceDivider > 0 ? request.traceDivider : std::llround(v.at("trace.divider")));
    auto plan = planFrfRequest(request, v, clock);
    if (!plan)
        return plan.error();
    FrfPlans out;
    out.sweep = plan->streams;
    out.multisine = plan->multisine;
    out.durationS = plan->durationS();
    out.tracePeriodS = clock.tracePeriodS();
    return out;
}

Result<double> SimulatedDrive::startFrf(sim::AxisSimulator& sim, const TestRequest& r)
{
    auto plans = planFrf(sim, r);
    if (!plans)
        return plans.error();
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
    if (plans->multisine) {
        auto shared = plans->multisine;
        sim.setTorqueInjection(
            [shared, t0, h](double t) { return multisineExcitation(*shared, std::llround((t - t0) / h)); });
        m_multisinePlan = shared;
        m_clampsAtStart = sim.voltageClampCount();
    } else {
        auto shared = plans->sweep;
        const double sampleS = sim.tracePeriod();
        sim.setTorqueInjection([shared, t0, sampleS, h](double t) {
            // Whole current ticks from the first sample, as a fractional trace-sample position.
            const double ticks = std::round((t - t0) / h);
            return frfExcitation(*shared, ticks * h / sampleS);
        });
        m_frfPlan = shared;
    }
    return plans->durationS;
}

Status SimulatedDrive::abortTest()
{
    if (auto st = checkLink(); !st)
        return st;
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

// ---------------------------------------------------------------------------------------------
// The drive describes itself (docs/drive-seam.md).

Result<DriveCapabilities> SimulatedDrive::capabilities(const std::string& axis)
{
    if (auto st = checkLink(); !st)
        return st.error();
    auto s = axisSim(axis);
    if (!s)
        return s.error();
    DriveCapabilities c;
    c.testTypes = {TestType::Step, TestType::Jog, TestType::Hold, TestType::Frf, TestType::CurrentStep};
    if ((*s)->kind() == sim::AxisKind::Linear && m_axes.size() > 1)
        c.testTypes.insert(c.testTypes.end() - 1, TestType::Circle);  // in the order of TestType
    c.frfMethods = {FrfMethod::MultiSweep, FrfMethod::Conventional, FrfMethod::Prbs, FrfMethod::Multisine};
    c.traceRateHz = 1.0 / (*s)->velocityPeriod();
    c.currentTraceRateHz = 1.0 / (*s)->currentPeriod();
    c.evaluatesFrf = true;
    c.writesParameters = true;
    c.hasLink = false;
    c.scope = true;
    return c;
}

Result<DriveLimits> SimulatedDrive::limits(const std::string& axis)
{
    if (auto st = checkLink(); !st)
        return st.error();
    auto s = axisSim(axis);
    if (!s)
        return s.error();
    DriveLimits l;
    l.frfAmplitudeMaxPct = kMaxFrfAmplitudePct;
    l.currentStepMaxA = kMaxCurrentStepFraction * (*s)->parameter("motor.max_current");
    l.currentStepMaxS = kMaxCurrentStepS;
    l.currentStepMaxSpeedRadS = kMaxCurrentStepSpeedRadS;
    l.motorSpeedMaxRadS = kMaxMotorSpeedRadS;
    l.testDurationMaxS = kMaxTestDurationS;
    // Jogs of the embedded drive have no travel window; circles keep within kTravelWindowM. A machine file may give
    // a linear axis its own ("travel_window", e.g. sim:long-axis).
    const double own = (*s)->definition().travelWindowM;
    l.travelWindow = (*s)->kind() == sim::AxisKind::Linear ? (own > 0.0 ? own : kTravelWindowM)
                                                           : std::numeric_limits<double>::infinity();
    return l;
}

Result<TestPlan> SimulatedDrive::planTest(const TestRequest& request)
{
    if (auto st = checkLink(); !st)
        return st.error();
    if (request.type() == TestType::Circle)
        return planCircle(request);
    auto s = axisSim(request.axis);
    if (!s)
        return s.error();
    const sim::AxisSimulator& sim = **s;
    auto length = checkMotion(sim, request);
    if (!length)
        return length.error();
    const double tracePeriod =
        sim.velocityPeriod() * (request.traceDivider > 0 ? request.traceDivider : sim.parameter("trace.divider"));
    TestPlan p;
    if (request.type() == TestType::Frf) {
        auto plans = planFrf(sim, request);
        if (!plans)
            return plans.error();
        p.motionTimeS = plans->durationS;
        p.traceRateHz = 1.0 / plans->tracePeriodS;
        p.recordSamples = static_cast<std::size_t>(std::llround(plans->durationS / plans->tracePeriodS));
    } else if (request.type() == TestType::CurrentStep) {
        auto c = planCurrentStep(sim, request);
        if (!c)
            return c.error();
        p.motionTimeS = c->lengthS;
        p.traceRateHz = 1.0 / c->h;
        p.recordSamples = static_cast<std::size_t>(c->ticks);
    } else {
        p.motionTimeS = *length;
        p.traceRateHz = 1.0 / tracePeriod;
        p.recordSamples = static_cast<std::size_t>(std::llround(*length / tracePeriod));
    }
    return p;
}

Result<SimulatedDrive::CurrentStepTiming> SimulatedDrive::planCurrentStep(const sim::AxisSimulator& sim,
                                                                          const TestRequest& request) const
{
    const CurrentStepTest& r = request.currentStep();
    const auto& v = sim.parameters();
    const double iMax = v.at("motor.max_current"), kt = v.at("motor.torque_constant"), j = v.at("plant.inertia_motor");
    const double limitA = kMaxCurrentStepFraction * iMax;
    const auto g = [](double x) { return model::formatNumber(x, 6); }; // printf's %g
    if (!std::isfinite(r.currentA) || r.currentA == 0.0 || std::abs(r.currentA) > limitA) {
        return makeError(ErrorCode::OutOfRange,
                         "current step " + g(r.currentA) + " A refused: it must be finite, non-zero and at most " +
                             g(100.0 * kMaxCurrentStepFraction) + " % of motor.max_current (" + g(limitA) + " A)");
    }
    if (!std::isfinite(r.recordS) || !(r.recordS > 0.0) || r.recordS > kMaxCurrentStepS) {
        return makeError(ErrorCode::OutOfRange, "current-step recording " + g(r.recordS) +
                                                    " s refused: it must lie in (0, " + g(kMaxCurrentStepS) + "] s");
    }
    CurrentStepTiming c;
    c.h = sim.currentPeriod();
    c.ticks = std::llround(r.recordS / c.h);
    c.preTicks = std::max<long long>(1, std::llround(0.1 * r.recordS / c.h));
    if (c.ticks < c.preTicks + 2) {
        return makeError(ErrorCode::OutOfRange, "current-step recording " + g(r.recordS) +
                                                    " s refused: shorter than a few current periods (" + g(c.h) +
                                                    " s)");
    }
    // With the velocity loop open the motor accelerates freely: k_t·|I|·t / J_m at the end of the record, with
    // the rotor inertia alone (a motor datum; the coupled load can only make it slower).
    const double stepS = static_cast<double>(c.ticks - c.preTicks) * c.h;
    const double speed = j > 0.0 ? kt * std::abs(r.currentA) * stepS / j : std::numeric_limits<double>::infinity();
    if (!(speed <= kMaxCurrentStepSpeedRadS)) {
        return makeError(ErrorCode::OutOfRange,
                         "current step " + g(r.currentA) + " A for " + g(stepS) +
                             " s refused: the motor would reach about " + model::formatNumber(speed, 3) +
                             " rad/s (k_t·I·t/J_m with the rotor inertia J_m " + g(j) + " kg·m²), above the " +
                             g(kMaxCurrentStepSpeedRadS) + " rad/s a current step may reach; lower or shorten it");
    }
    c.lengthS = static_cast<double>(c.ticks) * c.h + kCurrentStepHoldS;
    return c;
}

Result<double> SimulatedDrive::startCurrentStep(sim::AxisSimulator& sim, const TestRequest& r)
{
    auto c = planCurrentStep(sim, r);
    if (!c)
        return c.error();
    const double h = c->h;
    // The record starts on a whole current tick; the step comes preTicks later and holds to the end.
    const double t0 = sim.time();
    const double tStep = t0 + static_cast<double>(c->preTicks) * h;
    const double amp = r.currentStep().currentA, half = 0.5 * h;
    sim.setControlMode(sim::ControlMode::Current);
    sim.setCurrentCommand([tStep, amp, half](double t) { return t >= tStep - half ? amp : 0.0; });
    sim.startTrace(sim::TraceRate::Current);
    m_clampsAtStart = sim.voltageClampCount();
    m_recordEnd = t0 + static_cast<double>(c->ticks) * h;
    m_stepStart = tStep;
    return c->lengthS;
}

void SimulatedDrive::endCurrentStepRecord()
{
    m_recordEnd = -1.0;
    m_trace = m_active->takeTrace();
    m_trace->metadata.set(model::meta::kTest, "current_step");
    m_trace->metadata.set("step_start_s", m_stepStart);
    m_trace->metadata.set("step_amplitude_A", m_request ? m_request->currentStep().currentA : 0.0);
    m_trace->metadata.set(model::meta::kVoltageClampedTicks, m_active->voltageClampCount() - m_clampsAtStart);
    m_active->setCurrentCommand({});
    m_active->holdPosition();
}

}  // namespace axistune::device

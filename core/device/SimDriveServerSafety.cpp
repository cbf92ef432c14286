// SPDX-License-Identifier: GPL-3.0-or-later
// Safety of the simulated drive (DESIGN.md "Talking to drives"): limits checked before a test
// starts and after every simulation slice while it runs (travel window, motor speed, torque
// excitation in % of rated torque, following error); heartbeat watchdog. A trip stops the motion and
// restores the pre-test parameters (SimulatedDrive::abortTest).
#include "core/device/SimDriveServer.h"
#include "core/model/Constants.h"
#include "core/model/Units.h"

#include <cmath>
#include <cstdio>
#include <modbus/modbus.h>

namespace axistune::device {
namespace {

std::string num(double v) { return model::formatNumber(v, 4); }

} // namespace

std::string SimDriveServer::configuredType(int ui) const
{
    const auto& values = m_config[static_cast<std::size_t>(ui)];
    const auto it = values.find("test.type");
    return it == values.end() ? std::string() : m_map.name("test_type", static_cast<int>(it->second));
}

int SimDriveServer::buildRequest(int ui, TestRequest& req)
{
    const Axis& ax = m_axes[static_cast<std::size_t>(ui)];
    const SafetyLimits& lim = m_opt.safety;
    const std::string type = configuredType(ui);
    // A test never runs on a block the drive refused (it would run on what was there before); the
    // circle block counts for circle tests only.
    std::string refusedFields, refusedWhy;
    for (const auto& [name, why] : m_refusedConfig[static_cast<std::size_t>(ui)]) {
        if (name.rfind("circle.", 0) == 0 && type != "circle")
            continue;
        refusedFields += (refusedFields.empty() ? "" : ", ") + name;
        refusedWhy = why;
    }
    if (!refusedFields.empty())
        return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, "test configuration refused earlier (" + refusedFields +
                                                               ": " + refusedWhy +
                                                               "); write a valid test block before start_test");
    std::vector<std::string> names;
    for (const auto& a : m_axes)
        names.push_back(a.name);
    auto decoded = testRequestOf(m_config[static_cast<std::size_t>(ui)], m_map, ax.name, names);
    if (!decoded)
        return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, decoded.error().detail);
    req = std::move(decoded).value();
    const std::string u = ax.kind == "linear" ? " m" : " rad";
    switch (req.type()) {
    case TestType::Step:
        if (std::abs(req.step().velocityRadS) > lim.speedLimitRadS)
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, "step amplitude " + num(req.step().velocityRadS) +
                                                                   " rad/s exceeds the speed limit " +
                                                                   num(lim.speedLimitRadS) + " rad/s");
        break;
    case TestType::Jog:
    case TestType::Hold: {
        // A hold stays where the axis stands; only a jog moves (and has a velocity).
        const bool jog = req.is<JogTest>();
        const double distance = jog ? req.jog().distance : 0.0, velocity = jog ? req.jog().velocity : 0.0;
        const double target = ax.sim->positionCommand() + distance;
        if (ax.kind == "linear" && std::abs(target) > lim.travelLimit)
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE,
                          "jog target " + num(target) + u + " outside the travel window ±" + num(lim.travelLimit) + u);
        const double motorSpeed = ax.kind == "linear" ? velocity / ax.sim->parameter("plant.screw_lead") : velocity;
        if (jog && std::abs(motorSpeed) > lim.speedLimitRadS)
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, "jog velocity means " + num(motorSpeed) +
                                                                   " rad/s at the motor, above the speed limit " +
                                                                   num(lim.speedLimitRadS) + " rad/s");
        break;
    }
    case TestType::CurrentStep: {
        // The drive's own excitation limit in % of rated torque holds for the current step too; the
        // embedded drive adds its limits (fraction of max current, record length, speed reached).
        const double ratedTorque =
            model::ratedTorqueNm(ax.sim->parameter("motor.rated_current"), ax.sim->parameter("motor.torque_constant"));
        const double currentA = req.currentStep().currentA;
        const double torque = std::abs(currentA) * ax.sim->parameter("motor.torque_constant");
        const double torqueLimit = model::torqueNmFromRatedPct(lim.amplitudeLimitPct, ratedTorque);
        if (!(torque <= torqueLimit))
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE,
                          "current step " + num(currentA) + " A means " + num(torque) +
                              " Nm, above the drive's limit " + num(lim.amplitudeLimitPct) +
                              " % of the rated torque (" + num(torqueLimit) + " Nm)");
        break;
    }
    case TestType::Frf:
        if (!(req.frf().amplitudePct <= lim.amplitudeLimitPct))
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, "excitation amplitude " + num(req.frf().amplitudePct) +
                                                                   " % of the rated torque above the drive's limit " +
                                                                   num(lim.amplitudeLimitPct) + " %");
        break;
    case TestType::Circle:
        return startCircle(ui, req);
    }
    return 0;
}

int SimDriveServer::refuseError(const Error& e)
{
    const auto code = e.code;
    const int ex = code == ErrorCode::Busy       ? MODBUS_EXCEPTION_SLAVE_OR_SERVER_BUSY
                   : code == ErrorCode::NotFound ? MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS
                   : code == ErrorCode::OutOfRange || code == ErrorCode::BadInput
                       ? MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE
                       : MODBUS_EXCEPTION_SLAVE_OR_SERVER_FAILURE;
    return refuse(ex, e.detail);
}

int SimDriveServer::planTest(int ui, std::uint16_t token)
{
    TestRequest req;
    if (const int ex = buildRequest(ui, req); ex != 0)
        return ex;
    auto plan = m_drive->planTest(req);
    if (!plan)
        return refuseError(plan.error());
    m_plan = *plan;
    m_planToken = token;
    m_planUnit = ui;
    return 0;
}

int SimDriveServer::startTest(int ui)
{
    if (m_state == "running")
        return refuse(MODBUS_EXCEPTION_SLAVE_OR_SERVER_BUSY, "a test is already running");
    const Axis& ax = m_axes[static_cast<std::size_t>(ui)];
    TestRequest req;
    if (const int ex = buildRequest(ui, req); ex != 0)
        return ex;
    if (auto st = m_drive->startTest(req); !st)
        return refuseError(st.error());
    m_state = "running";
    m_fault = "none";
    m_message.clear();
    m_progress = 0.0;
    m_testUnit = ui;
    m_testSecondUnit = req.type() == TestType::Circle ? axisIndex(req.circle().secondAxis) : -1;
    m_testStartMachineS = ax.sim->time();
    m_testStartWall = m_lastHeartbeat = Clock::now();
    m_trace.reset();
    m_frfBlob.clear();
    m_frfMeta.clear();
    log(std::string("test ") + testTypeName(req.type()) + " started on axis " + ax.name);
    return 0;
}

DriveLimits SimDriveServer::axisLimits(int ui)
{
    // The embedded drive's limits, narrowed by this server's safety limits (SafetyLimits).
    const Axis& ax = m_axes[static_cast<std::size_t>(ui)];
    const SafetyLimits& lim = m_opt.safety;
    DriveLimits l = m_drive->limits(ax.name).value();
    l.frfAmplitudeMaxPct = std::min(l.frfAmplitudeMaxPct, lim.amplitudeLimitPct);
    // The torque limit in % of rated torque as a current: pct/100 · rated current.
    l.currentStepMaxA =
        std::min(l.currentStepMaxA, lim.amplitudeLimitPct / 100.0 * ax.sim->parameter("motor.rated_current"));
    l.motorSpeedMaxRadS = std::min(l.motorSpeedMaxRadS, lim.speedLimitRadS);
    l.currentStepMaxSpeedRadS = std::min(l.currentStepMaxSpeedRadS, lim.speedLimitRadS);
    if (ax.kind == "linear")
        l.travelWindow = std::min(l.travelWindow, lim.travelLimit);
    return l;
}

void SimDriveServer::trip(const std::string& fault, const std::string& message)
{
    (void)m_drive->abortTest();
    m_state = fault == "heartbeat_lost" ? "aborted" : "faulted";
    m_fault = fault;
    m_message = message;
    log("fault " + fault + ": " + message + "; test stopped, parameters restored");
}

void SimDriveServer::checkSafety()
{
    const Axis& ax = m_axes[static_cast<std::size_t>(m_testUnit)];
    const SafetyLimits& lim = m_opt.safety;
    const sim::AxisSimulator& s = *ax.sim;
    const std::string u = ax.kind == "linear" ? " m" : " rad";
    const double machineS = s.time() - m_testStartMachineS;
    const double ratedTorque =
        model::ratedTorqueNm(s.parameter("motor.rated_current"), s.parameter("motor.torque_constant"));
    const double torqueLimit = model::torqueNmFromRatedPct(lim.amplitudeLimitPct, ratedTorque);
    const bool fullClosed = s.parameter("position.feedback") > 0.5;
    const std::string type = configuredType(m_testUnit);
    const bool positionTest = type == "jog" || type == "hold" || type == "circle"; // the position loop is closed only there
    const double followingError =
        positionTest ? s.loopPositionCommand() - (fullClosed ? s.tablePosition() : s.motorPosition()) : 0.0;
    const bool linear = ax.kind == "linear"; // rotary tables turn endlessly: no travel window
    if (m_opt.faults.driveFaultAfterS >= 0 && machineS >= m_opt.faults.driveFaultAfterS)
        trip("drive_fault", "drive fault injected " + num(machineS) + " s into the test (fault drive-fault)");
    else if (linear && std::abs(s.tablePosition()) > lim.travelLimit)
        trip("travel_limit",
             "position " + num(s.tablePosition()) + u + " left the travel window ±" + num(lim.travelLimit) + u);
    else if (std::abs(s.motorVelocity()) > lim.speedLimitRadS)
        trip("speed_limit",
             "motor speed " + num(s.motorVelocity()) + " rad/s above the limit " + num(lim.speedLimitRadS) + " rad/s");
    else if (std::abs(s.torqueCommand()) > torqueLimit)
        trip("amplitude_limit", "torque command " + num(s.torqueCommand()) + " Nm above " + num(lim.amplitudeLimitPct) +
                                    " % of the rated torque (" + num(torqueLimit) + " Nm)");
    else if (std::abs(followingError) > lim.followingErrorLimit)
        trip("following_error",
             "following error " + num(followingError) + u + " above the limit " + num(lim.followingErrorLimit) + u);
    else if (m_testSecondUnit >= 0)
        checkCircleSecondAxis();
}

void SimDriveServer::takeTrace()
{
    auto t = m_drive->readTrace();
    if (!t) {
        m_trace.reset();
        return;
    }
    model::Capture cap = std::move(t).value();
    const auto& values = m_config[static_cast<std::size_t>(m_testUnit)];
    const auto maskAt = values.find("trace.channel_mask");
    const auto mask = maskAt == values.end() ? 0u : static_cast<std::uint32_t>(maskAt->second);
    if (mask != 0) {
        std::vector<model::Channel> keep;
        for (std::size_t i = 0; i < cap.channels.size() && i < 32; ++i) {
            if (mask & (1u << i))
                keep.push_back(std::move(cap.channels[i]));
        }
        cap.channels = std::move(keep);
    }
    m_traceNames.clear();
    m_traceMeta.clear();
    for (const auto& c : cap.channels)
        m_traceNames += c.name + "\n";
    for (const auto& [k, v] : cap.metadata)
        m_traceMeta += k + "=" + v.text() + "\n";
    m_trace = std::move(cap);
}

void SimDriveServer::takeFrequencyResponse()
{
    if (configuredType(m_testUnit) != "frf")
        return;
    auto r = m_drive->readFrequencyResponse();
    if (!r) {
        m_message = r.error().detail;
        return;
    }
    // Serialised as float64 (docs/modbus.md "FRF readout"): length, motion time, points, then sweep blocks.
    std::vector<double>& b = m_frfBlob;
    b = {0.0, r->motionTimeS, static_cast<double>(r->frf.size())};
    for (std::size_t i = 0; i < r->frf.size(); ++i)
        b.insert(b.end(), {r->frf.freqHz[i], r->frf.h[i].real(), r->frf.h[i].imag(), r->frf.coherence[i],
                           r->frf.valid[i] ? 1.0 : 0.0});
    b.insert(b.end(), {r->sweep.fsHz, r->sweep.amplitude, static_cast<double>(r->sweep.blocks.size())});
    for (const auto& blk : r->sweep.blocks) {
        b.insert(b.end(), {blk.freqHz, blk.phaseOffsetDeg, static_cast<double>(blk.sample.size())});
        for (const auto k : blk.sample)
            b.push_back(static_cast<double>(k));
        b.insert(b.end(), blk.excitation.begin(), blk.excitation.end());
        b.insert(b.end(), blk.response.begin(), blk.response.end());
    }
    b[0] = static_cast<double>(b.size());
    m_frfMeta.clear();
    for (const auto& [k, v] : r->frf.metadata)
        m_frfMeta += "frf." + k + "=" + v.text() + "\n";
    for (const auto& [k, v] : r->sweep.metadata)
        m_frfMeta += "sweep." + k + "=" + v.text() + "\n";
}

void SimDriveServer::step()
{
    stepScope();
    if (m_state != "running")
        return;
    const Axis& ax = m_axes[static_cast<std::size_t>(m_testUnit)];
    const auto now = Clock::now();
    const double sinceHeartbeat = std::chrono::duration<double>(now - m_lastHeartbeat).count();
    if (sinceHeartbeat > m_opt.safety.watchdogS) {
        trip("heartbeat_lost",
             "no heartbeat for " + num(sinceHeartbeat) + " s (watchdog " + num(m_opt.safety.watchdogS) + " s)");
        return;
    }
    if (m_opt.pace > 0) {
        const double wall = std::chrono::duration<double>(now - m_testStartWall).count();
        if (ax.sim->time() - m_testStartMachineS > m_opt.pace * wall)
            return; // ahead of the allowed pace: wait
    }
    auto st = m_drive->pollTest();
    if (!st) {
        trip("drive_fault", st.error().detail);
        return;
    }
    m_progress = st->progress;
    if (st->state == TestState::Completed) {
        takeTrace();
        takeFrequencyResponse();
        m_state = "completed";
        log("test completed on axis " + ax.name + ", " + std::to_string(m_trace ? m_trace->size() : 0) + " samples");
        return;
    }
    if (st->state != TestState::Running) {
        m_state = st->state == TestState::Faulted ? "faulted" : "aborted";
        m_fault = "drive_fault";
        m_message = st->detail;
        return;
    }
    checkSafety();
}

} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
// Multi-rate servo simulation of one feed axis (spec/current-loop-and-multisweep-frf.md §1.2, §1.6;
// current PI with PI ratio α, §2.3; lost motion Δx = (A + B·x)·ΔT and its compensation,
// spec/lost-motion-and-two-inertia.md §1.7–1.9). The discrete-time equations are in docs/simulator.md.
#include "core/sim/AxisSimulator.h"

#include "core/model/Constants.h"
#include "core/model/Metadata.h"
#include "core/model/MetadataKeys.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace axistune::sim {
namespace {

using model::kTwoPi;

Result<int> integerRatio(double num, double den, const std::string& what)
{
    const double r = num / den;
    const long n = std::lround(r);
    if (n < 1 || std::abs(r - static_cast<double>(n)) > 1e-9 * r) {
        return makeError(ErrorCode::OutOfRange, what + " must be a whole multiple (got a ratio of " + std::to_string(r) + ")");
    }
    return static_cast<int>(n);
}

double sgn(double v) { return v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0); }

}  // namespace

AxisSimulator::AxisSimulator(AxisDefinition def, std::uint64_t seed) : m_def(std::move(def)), m_seed(seed), m_rng(seed) {}

Result<std::unique_ptr<AxisSimulator>> AxisSimulator::create(const AxisDefinition& axis, std::uint64_t seed)
{
    std::unique_ptr<AxisSimulator> sim(new AxisSimulator(axis, seed));
    if (auto st = sim->configure(axis.values); !st)
        return makeError(st.error().code, "axis " + axis.name + ": " + st.error().detail);
    sim->reset(0.0);
    return sim;
}

double AxisSimulator::parameter(const std::string& key) const
{
    auto it = m_values.find(key);
    return it == m_values.end() ? std::numeric_limits<double>::quiet_NaN() : it->second;
}

Status AxisSimulator::setParameters(const model::ParameterValues& values)
{
    model::ParameterValues next = m_values;
    for (const auto& [key, value] : values) {
        const auto* meta = model::findParameter(parameterMetas(), key);
        if (!meta)
            return makeError(ErrorCode::NotFound, "axis " + m_def.name + ": unknown parameter '" + key + "'");
        if (auto st = model::checkParameterValue(*meta, value); !st)
            return st;
        next[key] = value;
    }
    return configure(next);
}

Status AxisSimulator::configure(const model::ParameterValues& v)
{
    auto get = [&v](const char* k) { return v.at(k); };
    const double h = get("current.period");
    auto velDiv = integerRatio(get("velocity.period"), h, "velocity.period / current.period");
    if (!velDiv)
        return velDiv.error();
    auto posDiv = integerRatio(get("position.period"), get("velocity.period"), "position.period / velocity.period");
    if (!posDiv)
        return posDiv.error();
    int deadTicks = 0;
    if (get("current.dead_time") > 0.0) {
        auto d = integerRatio(get("current.dead_time"), h, "current.dead_time / current.period");
        if (!d)
            return d.error();
        deadTicks = *d;
    }
    dsp::FilterCascade filters;
    for (int n = 1; n <= kNotchCount; ++n) {
        const std::string k = "filter.notch" + std::to_string(n);
        const double fc = v.at(k + ".center");
        if (fc <= 0.0)
            continue;
        auto b = dsp::designNotch({fc, v.at(k + ".width"), v.at(k + ".depth")}, h);
        if (!b)
            return makeError(b.error().code, k + ": " + b.error().detail);
        filters.add(*b);
    }
    if (const double fc = get("filter.lowpass.cutoff"); fc > 0.0) {
        auto b = dsp::designLowPass(fc, h);
        if (!b)
            return makeError(b.error().code, "filter.lowpass: " + b.error().detail);
        filters.add(*b);
    }

    SuppressionSettings sup;
    sup.mode = static_cast<SuppressionFilterMode>(static_cast<int>(get("suppression.mode")));
    sup.f0Hz = get("suppression.f0");
    sup.zeta = get("suppression.zeta");
    sup.tauS = get("suppression.tau");
    if (auto st = checkSuppressionSettings(sup, get("position.feedback") >= 1.0, get("position.period")); !st)
        return st;
    FmCommandShaper fm;
    dsp::Biquad fl;
    if (sup.mode != SuppressionFilterMode::Off) {  // F_L's feedforward uses F_m's look-ahead too
        if (auto st = fm.configure(sup.f0Hz, sup.zeta, get("position.period")); !st)
            return st;
    }
    if (sup.mode == SuppressionFilterMode::FullClosedFl) {
        auto b = designFlTustin(sup.f0Hz, sup.zeta, sup.tauS, get("position.period"));
        if (!b)
            return b.error();
        fl = *b;
    }

    PlantConfig pc;
    pc.resistanceOhm = get("plant.motor.resistance");
    pc.inductanceH = get("plant.motor.inductance_q");
    pc.inductanceDropAtMax = get("plant.motor.inductance_drop_at_max");
    pc.maxCurrentA = get("motor.max_current");
    pc.torqueConstantNmPerA = get("motor.torque_constant");
    pc.backEmfVsPerRad = get("plant.motor.back_emf_constant");
    pc.inertiaMotorKgm2 = get("plant.inertia_motor");
    pc.inertiaLoadKgm2 = get("plant.inertia_load");
    pc.stiffnessNmPerRad = get("plant.coupling_stiffness");
    pc.dampingNmsPerRad = get("plant.coupling_damping");
    pc.viscousMotorNmsPerRad = get("plant.viscous_motor");
    pc.viscousLoadNmsPerRad = get("plant.viscous_load");
    pc.modes = m_def.modes;
    if (m_def.kind == AxisKind::Linear && m_def.screw.enabled()) {
        pc.screw = m_def.screw;
        pc.screwLeadMPerRad = get("plant.screw_lead");
    }

    const bool rebuildPlant = !m_plant || h != m_hCurrent;
    m_values = v;
    const bool linear = m_def.kind == AxisKind::Linear;
    Loop p;
    p.kt = get("motor.torque_constant");
    p.iMax = get("motor.max_current");
    p.vMax = get("drive.max_voltage");
    p.kp = get("current.kp");
    p.ki = get("current.ki");
    p.alpha = get("current.alpha");
    p.noiseCurrent = get("plant.noise_current");
    p.noisePosition = get("plant.noise_position");
    p.velKp = get("velocity.kp");
    p.velKi = get("velocity.ki");
    p.posKp = get("position.kp");
    p.velFf = get("position.velocity_ff");
    p.torqueFf = get("position.torque_ff");
    p.inertiaFf = get("velocity.inertia");
    p.encoderMotor = get("plant.encoder_motor");
    p.encoderLoad = linear ? 0.0 : get("plant.encoder_load");
    p.scaleResolution = linear ? get("plant.scale_resolution") : 0.0;
    p.coulombMotor = get("plant.coulomb_motor");
    p.coulombLoad = get("plant.coulomb_load");
    p.coulombVelocity = get("plant.coulomb_velocity");
    const bool rigid = get("plant.coupling_stiffness") <= 0.0;
    p.jMotorSide = get("plant.inertia_motor") + (rigid ? get("plant.inertia_load") : 0.0);
    p.jLoadSide = std::max(1e-9, get("plant.inertia_load") + (rigid ? get("plant.inertia_motor") : 0.0));
    p.lead = linear ? get("plant.screw_lead") : 1.0;
    p.lmA = linear ? get("plant.lost_motion_A") : 0.0;
    p.lmB = linear ? get("plant.lost_motion_B") : 0.0;
    p.screwOffset = linear ? get("plant.screw_offset") : 0.0;
    p.compMode = linear ? static_cast<int>(get("lostmotion.mode")) : 0;
    p.compA = linear ? get("lostmotion.A") : 0.0;
    p.compB = linear ? get("lostmotion.B") : 0.0;
    p.compOffset = linear ? get("lostmotion.screw_offset") : 0.0;
    p.backlash = linear ? get("lostmotion.backlash") : 0.0;
    p.play = linear ? get("plant.backlash") : 0.0;
    p.reversalAmp = linear ? get("reversal.amplitude") : 0.0;
    p.reversalTau = linear ? get("reversal.time_constant") : 0.01;
    p.fullClosed = get("position.feedback") >= 1.0;
    m_p = p;
    m_hCurrent = h;
    m_velDiv = *velDiv;
    m_posDiv = *posDiv;
    m_intDiv = static_cast<int>(get("velocity.integral_divider"));
    m_traceDiv = static_cast<int>(get("trace.divider"));
    if (deadTicks != m_deadTicks || m_delayLine.size() != static_cast<std::size_t>(deadTicks)) {
        m_deadTicks = deadTicks;
        m_delayLine.assign(static_cast<std::size_t>(deadTicks), 0.0);
    }
    m_filters = filters;
    // A new design starts from rest (writes are refused while a test moves the axis).
    m_suppression = sup;
    m_fm = fm;
    m_fl = fl;
    if (rebuildPlant) {
        m_plant = std::make_unique<PlantModel>(pc, h);
        if (m_x.size() != m_plant->stateSize())
            m_x = Eigen::VectorXd::Zero(m_plant->stateSize());
    }
    return Status::success();
}

double AxisSimulator::screwLead() const { return m_p.lead; }

void AxisSimulator::reset(double position)
{
    m_x = Eigen::VectorXd::Zero(m_plant->stateSize());
    const double angle = position / screwLead();
    m_x[1] = angle;
    if (!m_plant->rigid())
        m_x[3] = angle;
    m_rng.seed(m_seed);
    m_gauss.reset();
    m_filters.reset();
    m_fm.reset();
    m_fl.reset();
    m_delayLine.assign(static_cast<std::size_t>(m_deadTicks), 0.0);
    m_tick = m_velTick = 0;
    m_currentInt = m_velInt = m_torqueCmd = m_torqueFf = m_velCmd = m_velCmdFromPos = m_velMeas = 0.0;
    m_posCmd = m_posFeedback = m_loopCmd = position;
    m_lmComp = m_lastDirection = m_currentCmd = m_voltage = m_injectionNow = 0.0;
    m_table = tableBeforePlay();
    m_reversalDir = m_reversalVel = 0.0;
    m_reversalStart = -1.0;
    m_prevEncoder = quantize(m_plant->encoderAngle(m_x), m_p.encoderMotor);
    m_clampCount = m_currentLimitCount = 0;
    m_profile = MotionProfile(position);
    m_positionCommand = nullptr;
    m_profileStart = 0.0;
    m_trace.clear();
    m_tracing = false;
    m_traceRate = TraceRate::Velocity;
}

void AxisSimulator::setPositionProfile(MotionProfile profile)
{
    m_profile = std::move(profile);
    m_positionCommand = nullptr;
    m_profileStart = time();
}

void AxisSimulator::setPositionCommand(std::function<MotionState(double)> fn)
{
    m_positionCommand = std::move(fn);
    m_profileStart = time();
}

double AxisSimulator::quantize(double value, double countsPerRev) const
{
    if (!m_nl.quantization || countsPerRev <= 0.0)
        return value;
    const double step = kTwoPi / countsPerRev;
    return std::floor(value / step + 0.5) * step;
}

double AxisSimulator::frictionMotor() const
{
    const double tc = m_p.coulombMotor;
    if (!m_nl.friction || tc <= 0.0)
        return 0.0;
    // The smoothing velocity never goes below what an explicit step can hold stably.
    const double eps = std::max(m_p.coulombVelocity, 2.0 * m_hCurrent * tc / m_p.jMotorSide);
    return tc * std::tanh(PlantModel::motorVelocity(m_x) / eps);
}

double AxisSimulator::frictionLoad() const
{
    const double tc = m_p.coulombLoad;
    if (!m_nl.friction || tc <= 0.0)
        return 0.0;
    const double eps = std::max(m_p.coulombVelocity, 2.0 * m_hCurrent * tc / m_p.jLoadSide);
    return tc * std::tanh(m_plant->loadVelocity(m_x) / eps);
}

double AxisSimulator::lostMotionDeflection() const
{
    if (m_def.kind != AxisKind::Linear || !m_nl.lostMotion)
        return 0.0;
    const double xbs = m_p.screwOffset + m_p.lead * m_plant->loadAngle(m_x);
    return (m_p.lmA + m_p.lmB * xbs) * torque();
}

double AxisSimulator::motorPosition() const { return screwLead() * PlantModel::motorAngle(m_x); }

double AxisSimulator::tableBeforePlay() const
{
    return screwLead() * m_plant->loadAngle(m_x) - lostMotionDeflection();
}

double AxisSimulator::tablePosition() const
{
    return m_table;
}

void AxisSimulator::updatePlay()
{
    // Kinematic play (docs/simulator.md "Backlash"): the table stands still, held by its guideway, while
    // the nut travels through the gap; at either end of the gap the nut takes the table along.
    const double half = m_nl.backlash ? 0.5 * m_p.play : 0.0, nut = tableBeforePlay();
    m_table = std::clamp(m_table, nut - half, nut + half);
}

void AxisSimulator::positionTick(double t, double feedbackPos)
{
    const MotionState nc = m_positionCommand ? m_positionCommand(t - m_profileStart) : m_profile.at(t - m_profileStart);
    // F_m: the semi-closed loop follows the motor command y_m* = F_m·y*; the trace keeps the NC (load)
    // command y*. Full-closed: the loop follows y*, F_m·y* only gives the feedforward velocity.
    const MotionState shaped = m_suppression.mode != SuppressionFilterMode::Off ? m_fm.process(nc) : nc;
    const MotionState s = m_suppression.mode == SuppressionFilterMode::SemiClosedFm ? shaped : nc;
    m_posCmd = nc.position;
    m_loopCmd = s.position;
    m_posFeedback = feedbackPos;
    double comp = 0.0;
    if (m_def.kind == AxisKind::Linear) {
        if (m_p.compMode == 1) {
            if (s.velocity != 0.0)
                m_lastDirection = sgn(s.velocity);  // holds the last direction at standstill
            comp = m_lastDirection * 0.5 * m_p.backlash;
        } else if (m_p.compMode == 2) {
            // (A + B·x_bs)·T_m with the last torque command (no algebraic loop), x_bs = x0 + X_t.
            const double xbs = m_p.compOffset + feedbackPos;
            comp = (m_p.compA + m_p.compB * xbs) * m_torqueCmd;
        }
    }
    m_lmComp = comp;
    if (nc.velocity != 0.0) {
        const double dir = sgn(nc.velocity);
        if (m_reversalDir != 0.0 && dir != m_reversalDir)
            m_reversalStart = t; // a commanded reversal: the compensation pulse starts
        m_reversalDir = dir;
    }
    const double r = screwLead();
    if (m_suppression.mode == SuppressionFilterMode::FullClosedFl) {
        // F_L on the feedback velocity command; on the feedforward F_L·(τs + 1)·s·y* = s·F_m·y*: the
        // command's look-ahead undoes F_L's lag τ, which would otherwise leave v*·τ of following error.
        m_velCmdFromPos = (m_fl.process(m_p.posKp * (s.position + comp - feedbackPos)) + m_p.velFf * shaped.velocity) / r;
    } else {
        m_velCmdFromPos = (m_p.posKp * (s.position + comp - feedbackPos) + m_p.velFf * s.velocity) / r;
    }
    m_torqueFf = m_p.torqueFf * m_p.inertiaFf * s.acceleration / r;
}

void AxisSimulator::velocityTick(double t)
{
    const double tv = velocityPeriod();
    double enc = quantize(m_plant->encoderAngle(m_x), m_p.encoderMotor);
    if (m_nl.noise && m_p.noisePosition > 0.0)
        enc += m_p.noisePosition * m_gauss(m_rng);
    m_velMeas = (enc - m_prevEncoder) / tv;
    m_prevEncoder = enc;
    if (m_mode == ControlMode::Current) {
        // Velocity and position loops open: only the measurement runs; runTicks takes the current command.
        m_velCmd = 0.0;
        ++m_velTick;
        return;
    }

    if (m_mode == ControlMode::Position && m_velTick % m_posDiv == 0) {
        double fb = screwLead() * enc;
        if (m_p.fullClosed) {
            if (m_def.kind == AxisKind::Linear) {
                const double res = m_p.scaleResolution;
                fb = tablePosition();
                if (m_nl.quantization && res > 0.0)
                    fb = std::floor(fb / res + 0.5) * res;
            } else {
                fb = quantize(m_plant->loadAngle(m_x), m_p.encoderLoad);
            }
        }
        positionTick(t, fb);
    }
    if (m_mode == ControlMode::Velocity) {
        m_velCmd = m_velocityCommand ? m_velocityCommand(t) : 0.0;
        m_torqueFf = 0.0;
    } else {
        m_velCmd = m_velCmdFromPos;
        // Reversal compensation pulse a·sgn(v_new)·exp(−(t − t_rev)/τ) on the velocity command.
        m_reversalVel = 0.0;
        if (m_p.reversalAmp > 0.0 && m_reversalStart >= 0.0 && t - m_reversalStart < 30.0 * m_p.reversalTau)
            m_reversalVel =
                m_reversalDir * m_p.reversalAmp / screwLead() * std::exp(-(t - m_reversalStart) / m_p.reversalTau);
        m_velCmd += m_reversalVel;
    }
    const double e = m_velCmd - m_velMeas;
    if (m_velTick % m_intDiv == 0)
        m_velInt += m_p.velKi * tv * m_intDiv * e;
    m_torqueCmd = m_p.velKp * e + m_velInt + m_torqueFf;

    if (m_tracing && m_traceRate == TraceRate::Velocity && m_velTick % m_traceDiv == 0) {
        double row[kSignalCount];
        signalRow(t, row);
        for (std::size_t c = 0; c < m_trace.size(); ++c)
            m_trace[c].push_back(row[c]);
    }
    ++m_velTick;
}

void AxisSimulator::runTicks(std::int64_t ticks)
{
    const double kt = m_p.kt, iMax = m_p.iMax, vMax = m_p.vMax;
    const double kp = m_p.kp, ki = m_p.ki, alpha = m_p.alpha;
    const double noiseI = m_nl.noise ? m_p.noiseCurrent : 0.0;
    for (std::int64_t k = 0; k < ticks; ++k) {
        const double t = time();
        m_injectionNow = m_injection ? m_injection(t) : 0.0;
        if (m_tick % m_velDiv == 0) {
            velocityTick(t);
            if (m_scopeTap)
                scopeTick(t);
        }
        const bool currentMode = m_mode == ControlMode::Current;
        double iCmd = currentMode ? (m_currentCommand ? m_currentCommand(t) : 0.0)
                                  : m_filters.process(m_torqueCmd + m_injectionNow) / kt;
        if (std::abs(iCmd) > iMax) {
            iCmd = sgn(iCmd) * iMax;
            ++m_currentLimitCount;
        }
        m_currentCmd = iCmd;
        if (currentMode)
            m_torqueCmd = kt * iCmd;  // what the current command means as torque (status, safety checks)
        const double iMeas = PlantModel::current(m_x) + (noiseI > 0.0 ? noiseI * m_gauss(m_rng) : 0.0);
        m_currentInt += ki * m_hCurrent * (iCmd - iMeas);
        const double prop = kp * (alpha * iCmd - iMeas);
        double v = m_currentInt + prop;
        if (std::abs(v) > vMax) {
            ++m_clampCount;
            v = sgn(v) * vMax;
            m_currentInt = v - prop;  // anti-windup: the integrator is rewritten to the clamped output
        }
        double applied = v;
        if (m_deadTicks > 0) {
            m_delayLine.push_back(v);
            applied = m_delayLine.front();
            m_delayLine.pop_front();
        }
        m_voltage = applied;
        if (m_tracing && m_traceRate == TraceRate::Current) {
            // State at the start of the period: the command and voltage of this period, the current measured
            // for it (detection noise included), the velocity loop's last measurement.
            const double row[] = {t, iCmd, iMeas, applied, m_velMeas, torque()};
            for (std::size_t c = 0; c < m_trace.size(); ++c)
                m_trace[c].push_back(row[c]);
        }
        const double load = m_loadTorque ? m_loadTorque(t) : 0.0;
        m_plant->step(m_x, applied, -frictionMotor(), load - frictionLoad(), m_nl.inductanceDrop);
        updatePlay();
        ++m_tick;
    }
}

void AxisSimulator::run(double seconds) { runTicks(std::llround(seconds / m_hCurrent)); }

std::vector<std::string> AxisSimulator::traceChannelNames() const
{
    const std::string u = m_def.kind == AxisKind::Linear ? "m" : "rad";
    return {"t_s",          "velocity_cmd_rad_s", "motor_vel_rad_s",    "torque_cmd_Nm",   "injection_Nm",
            "torque_Nm",    "current_cmd_A",      "current_A",          "voltage_V",       "position_cmd_" + u,
            "motor_pos_" + u, "table_pos_" + u,   "lost_motion_comp_" + u, "load_vel_rad_s"};
}

std::vector<std::string> AxisSimulator::currentTraceChannelNames()
{
    return {"t_s", "current_cmd_A", "current_A", "voltage_V", "motor_vel_rad_s", "torque_Nm"};
}

std::vector<ScopeSignal> AxisSimulator::scopeSignals() const
{
    const bool lin = m_def.kind == AxisKind::Linear;
    const std::string u = lin ? "m" : "rad", s = lin ? "_m" : "_rad";
    return {{"t_s", "s", "machine time of the sample"},
            {"velocity_cmd_rad_s", "rad/s", "velocity command at the motor"},
            {"motor_vel_rad_s", "rad/s", "motor velocity measured by the encoder"},
            {"torque_cmd_Nm", "N·m", "torque command of the velocity loop"},
            {"injection_Nm", "N·m", "torque injected by a test"},
            {"torque_Nm", "N·m", "motor torque (k_t × current)"},
            {"current_cmd_A", "A", "q-axis current command"},
            {"current_A", "A", "q-axis current"},
            {"voltage_V", "V", "q-axis voltage applied"},
            {"position_cmd" + s, u, "position command"},
            {"motor_pos" + s, u, "position from the motor encoder"},
            {"table_pos" + s, u, "load (table) position"},
            {"lost_motion_comp" + s, u, "lost-motion compensation"},
            {"load_vel_rad_s", "rad/s", "load velocity"},
            {"following_error" + s, u, "position command followed minus feedback (0 outside position control)"}};
}

void AxisSimulator::signalRow(double t, double* row) const
{
    // In the order of traceChannelNames() and scopeSignals(); m_prevEncoder is this period's encoder reading.
    const double values[kSignalCount] = {t,
                                         m_velCmd,
                                         m_velMeas,
                                         m_torqueCmd,
                                         m_injectionNow,
                                         torque(),
                                         m_currentCmd,
                                         PlantModel::current(m_x),
                                         m_voltage,
                                         m_posCmd,
                                         screwLead() * m_prevEncoder,
                                         tablePosition(),
                                         m_lmComp,
                                         m_plant->loadVelocity(m_x)};
    std::copy(values, values + kSignalCount, row);
}

void AxisSimulator::scopeTick(double t)
{
    double row[kSignalCount + 1];
    signalRow(t, row);
    // The following error as the position loop saw it at its last period (0 outside position control).
    row[kSignalCount] = m_mode == ControlMode::Position ? m_loopCmd - m_posFeedback : 0.0;
    m_scopeTap(m_velTick - 1, row);
}

void AxisSimulator::startTrace(TraceRate rate)
{
    m_traceRate = rate;
    m_trace.assign(rate == TraceRate::Current ? currentTraceChannelNames().size() : traceChannelNames().size(), {});
    m_tracing = true;
}

void AxisSimulator::holdPosition()
{
    const double pos = m_p.fullClosed ? tablePosition() : motorPosition();
    m_mode = ControlMode::Position;
    m_profile = MotionProfile(pos);
    m_positionCommand = nullptr;
    m_profileStart = time();
    m_posCmd = m_posFeedback = pos;
    m_velInt = m_velCmd = m_velCmdFromPos = m_torqueFf = m_torqueCmd = 0.0;
    m_reversalDir = m_reversalVel = 0.0;
    m_reversalStart = -1.0;
    m_filters.reset();
}

model::Capture AxisSimulator::takeTrace()
{
    model::Capture cap;
    const bool currentRate = m_traceRate == TraceRate::Current;
    const auto names = currentRate ? currentTraceChannelNames() : traceChannelNames();
    cap.metadata.set(model::meta::kFsHz, 1.0 / (currentRate ? m_hCurrent : tracePeriod()));
    cap.metadata.set(model::meta::kAxis, m_def.name);
    cap.metadata.set(model::meta::kCurrentPeriodS, m_hCurrent);
    cap.metadata.set(model::meta::kVelocityPeriodS, velocityPeriod());
    // A number while a double holds it exactly; larger seeds stay their exact digits (Metadata::set of an IntegerKey).
    cap.metadata.set(model::meta::kSeed, m_seed);
    for (std::size_t c = 0; c < names.size() && c < m_trace.size(); ++c)
        cap.channels.push_back({names[c], std::move(m_trace[c])});
    m_trace.clear();
    m_tracing = false;
    m_traceRate = TraceRate::Velocity;
    return cap;
}

}  // namespace axistune::sim

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One simulated feed axis with its drive: multi-rate current (default 62.5 µs), velocity (250 µs)
// and position (1 ms) loops, torque-command filters at the current-loop rate, lost-motion
// compensation, semi-/full-closed feedback, a trace recorder at a divider of the velocity period.
// Deterministic for a seed. Not thread-safe: one thread drives one simulator.
// The structure follows spec/current-loop-and-multisweep-frf.md §1.2, §1.6 and §2.3; see
// docs/simulator.md for the exact discrete-time equations.

#include "core/dsp/DigitalFilter.h"
#include "core/model/Capture.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"
#include "core/sim/MachineDefinition.h"
#include "core/sim/MotionProfile.h"
#include "core/sim/PlantModel.h"
#include "core/sim/SuppressionFilter.h"

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <random>
#include <span>

namespace axistune::sim {

enum class ControlMode {
    Velocity, ///< velocity command from setVelocityCommand, position loop open
    Position, ///< position command from setPositionProfile
    Current,  ///< q-axis current command from setCurrentCommand; velocity and position loops open
};

/// Rate of the trace recorder: every trace.divider velocity periods, or every current-loop period.
enum class TraceRate { Velocity, Current };

/// A signal the drive's scope can trace (docs/scope.md): name as in a capture, SI unit, one line of description.
struct ScopeSignal {
    std::string name;
    std::string unit;
    std::string description;
};

/// Switches for the non-ideal parts. All on by default; tests turn them off to see the linear part.
struct Nonlinearities {
    bool friction = true;       ///< Coulomb friction
    bool inductanceDrop = true; ///< L falls with current
    bool quantization = true;   ///< encoder and scale resolution
    bool noise = true;          ///< measurement noise
    bool lostMotion = true;     ///< elastic lost motion of the ball screw
    bool backlash = true;       ///< play between nut and table (plant.backlash)
};

class AxisSimulator {
public:
    /// Builds the simulator of one axis; fails when the periods are not integer multiples.
    static Result<std::unique_ptr<AxisSimulator>> create(const AxisDefinition& axis, std::uint64_t seed);

    const std::string& name() const { return m_def.name; }
    AxisKind kind() const { return m_def.kind; }
    const AxisDefinition& definition() const { return m_def; }
    const std::vector<model::ParameterMeta>& parameterMetas() const { return axisParameterMetas(m_def.kind); }
    const model::ParameterValues& parameters() const { return m_values; }
    double parameter(const std::string& key) const;
    /// Writes several parameters at once: all are range-checked first; nothing changes on an error.
    Status setParameters(const model::ParameterValues& values);

    void setNonlinearities(const Nonlinearities& n) { m_nl = n; }
    const Nonlinearities& nonlinearities() const { return m_nl; }

    /// Zero state at t = 0 with the position held at `position` (axis units); clears the trace and reseeds.
    void reset(double position = 0.0);
    void setControlMode(ControlMode mode) { m_mode = mode; }
    /// Motor velocity command [rad/s] as a function of time, sampled at the velocity-loop rate.
    void setVelocityCommand(std::function<double(double)> fn) { m_velocityCommand = std::move(fn); }
    /// Position command (axis units), sampled at the position-loop rate. Time 0 of the profile is now.
    void setPositionProfile(MotionProfile profile);
    /// Arbitrary position command (axis units) as a function of time since this call, sampled at the
    /// position-loop rate; used instead of the profile while set (an empty function clears it).
    void setPositionCommand(std::function<MotionState(double)> fn);
    /// Current command [A] as a function of time for ControlMode::Current, sampled at the current-loop rate and
    /// limited to motor.max_current; no torque filters and no injection act on it.
    void setCurrentCommand(std::function<double(double)> fn) { m_currentCommand = std::move(fn); }
    /// The drive's normal holding mode: position loop closed at the present feedback position (motor encoder,
    /// or the load in full-closed mode), velocity integrator and torque filters cleared. Used after a
    /// current-command test, when the velocity loop was open and the motor still moves.
    void holdPosition();
    /// Torque added to the torque command [N·m] before the filters, sampled at the current-loop rate.
    void setTorqueInjection(std::function<double(double)> fn) { m_injection = std::move(fn); }
    /// External torque on the load side [N·m] (e.g. a cutting force on the table times the lead R; positive
    /// drives the load in +), sampled at the start of each current-loop period and held over it.
    void setLoadTorque(std::function<double(double)> fn) { m_loadTorque = std::move(fn); }

    /// Runs whole current-loop periods for `seconds` of machine time.
    void run(double seconds);
    void runTicks(std::int64_t ticks);

    double time() const { return static_cast<double>(m_tick) * m_hCurrent; }
    /// Current periods and velocity periods run since the last reset (time() = currentTicks() · currentPeriod()).
    std::int64_t currentTicks() const { return m_tick; }
    std::int64_t velocityTicks() const { return m_velTick; }
    double currentPeriod() const { return m_hCurrent; }
    double velocityPeriod() const { return m_hCurrent * m_velDiv; }
    /// Period of the velocity-rate trace (trace.divider velocity periods); a TraceRate::Current trace is
    /// recorded every currentPeriod().
    double tracePeriod() const { return velocityPeriod() * m_traceDiv; }
    std::uint64_t voltageClampCount() const { return m_clampCount; }
    std::uint64_t currentLimitCount() const { return m_currentLimitCount; }

    // Instantaneous state (SI; positions in axis units).
    double motorVelocity() const { return PlantModel::motorVelocity(m_x); }
    double motorPosition() const; ///< axis units from the rigid motor angle
    double tablePosition() const; ///< load side including elastic lost motion and backlash
    double torque() const { return m_plant->config().torqueConstantNmPerA * PlantModel::current(m_x); }
    double torqueCommand() const { return m_torqueCmd; }
    double positionCommand() const { return m_posCmd; }
    /// The command the position loop follows: y_m* = F_m·y* with suppression.mode 1, else y* (the
    /// following error is taken against it).
    double loopPositionCommand() const { return m_loopCmd; }

    /// Trace recording while enabled: every `trace.divider` velocity periods (TraceRate::Velocity), or every
    /// current-loop period (TraceRate::Current, channels currentTraceChannelNames()).
    void startTrace(TraceRate rate = TraceRate::Velocity);
    void stopTrace() { m_tracing = false; }
    /// The recorded trace as a capture (channels in SI, metadata fs_Hz, axis, preset-free details).
    model::Capture takeTrace();

    /// Names of the trace channels for this axis kind, in capture order.
    std::vector<std::string> traceChannelNames() const;
    /// Names of the channels of a TraceRate::Current trace, in capture order.
    static std::vector<std::string> currentTraceChannelNames();

    /// The signals the scope taps, in the order of the tap's row (docs/scope.md).
    std::vector<ScopeSignal> scopeSignals() const;
    /// Called after every velocity-loop period with that period's number (0, 1, 2 … since the simulator was
    /// made) and the value of every scopeSignals() entry; an empty function removes the tap.
    using ScopeTap = std::function<void(std::int64_t velocityTick, std::span<const double> row)>;
    void setScopeTap(ScopeTap tap) { m_scopeTap = std::move(tap); }

private:
    AxisSimulator(AxisDefinition def, std::uint64_t seed);
    Status configure(const model::ParameterValues& v);
    void velocityTick(double t);
    /// The velocity-rate trace channels' values now (kSignalCount of them, traceChannelNames() order).
    static constexpr std::size_t kSignalCount = 14;
    void signalRow(double t, double* row) const;
    void scopeTick(double t);
    void positionTick(double t, double feedbackPos);
    double frictionMotor() const;
    double frictionLoad() const;
    double lostMotionDeflection() const;
    double tableBeforePlay() const; ///< table position without the backlash
    void updatePlay();
    double quantize(double value, double step) const;
    double screwLead() const; ///< R [m/rad] for linear axes, 1 for rotary

    /// Parameters used in the loops, copied from m_values at configure() (no map look-ups per tick).
    struct Loop {
        double kt = 0, iMax = 0, vMax = 0, kp = 0, ki = 0, alpha = 0, noiseCurrent = 0, noisePosition = 0;
        double velKp = 0, velKi = 0, posKp = 0, velFf = 0, torqueFf = 0, inertiaFf = 0;
        double encoderMotor = 0, encoderLoad = 0, scaleResolution = 0;
        double coulombMotor = 0, coulombLoad = 0, coulombVelocity = 0, jMotorSide = 0, jLoadSide = 0;
        double lead = 1, lmA = 0, lmB = 0, screwOffset = 0;
        double compA = 0, compB = 0, compOffset = 0, backlash = 0;
        double play = 0;                            ///< plant.backlash [m]
        double reversalAmp = 0, reversalTau = 0.01; ///< reversal.amplitude [m/s], reversal.time_constant [s]
        int compMode = 0;
        bool fullClosed = false;
    };

    AxisDefinition m_def;
    model::ParameterValues m_values;
    Loop m_p;
    std::uint64_t m_seed;
    std::mt19937_64 m_rng;
    std::normal_distribution<double> m_gauss{0.0, 1.0};
    Nonlinearities m_nl;

    std::unique_ptr<PlantModel> m_plant;
    Eigen::VectorXd m_x;
    double m_hCurrent = 62.5e-6;
    int m_velDiv = 4;
    int m_posDiv = 4; ///< in velocity periods
    int m_intDiv = 1;
    int m_traceDiv = 1;
    int m_deadTicks = 1;
    dsp::FilterCascade m_filters;
    // Two-inertia suppression filter at the position-loop period (suppression.*; SuppressionFilter.h).
    SuppressionSettings m_suppression;
    FmCommandShaper m_fm;
    dsp::Biquad m_fl;

    ControlMode m_mode = ControlMode::Velocity;
    std::function<double(double)> m_velocityCommand;
    std::function<double(double)> m_injection;
    std::function<double(double)> m_loadTorque;
    std::function<double(double)> m_currentCommand;
    MotionProfile m_profile;
    std::function<MotionState(double)> m_positionCommand;
    double m_profileStart = 0.0;

    // Controller state.
    std::int64_t m_tick = 0;
    std::int64_t m_velTick = 0;
    double m_currentInt = 0.0;
    double m_velInt = 0.0;
    double m_torqueCmd = 0.0;
    double m_torqueFf = 0.0;
    double m_velCmd = 0.0;
    double m_velCmdFromPos = 0.0;
    double m_velMeas = 0.0;
    double m_prevEncoder = 0.0;
    double m_posCmd = 0.0;
    double m_loopCmd = 0.0;
    double m_posFeedback = 0.0;
    double m_lmComp = 0.0;
    double m_table = 0.0;          ///< table position inside the play (plant.backlash)
    double m_reversalDir = 0.0;    ///< direction of the last commanded motion (reversal compensation)
    double m_reversalStart = -1.0; ///< time of the last commanded reversal [s]; < 0: none yet
    double m_reversalVel = 0.0;    ///< reversal pulse on the velocity command now [rad/s motor]
    double m_lastDirection = 0.0;
    double m_currentCmd = 0.0;
    double m_voltage = 0.0;
    double m_injectionNow = 0.0;
    std::deque<double> m_delayLine;
    std::uint64_t m_clampCount = 0;
    std::uint64_t m_currentLimitCount = 0;

    // Trace.
    bool m_tracing = false;
    TraceRate m_traceRate = TraceRate::Velocity;
    std::vector<std::vector<double>> m_trace;
    ScopeTap m_scopeTap;
};

} // namespace axistune::sim

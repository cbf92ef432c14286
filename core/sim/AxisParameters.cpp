// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/AxisParameters.h"

#include <cmath>
#include <numbers>
#include <string>

namespace axistune::sim {
namespace {

using model::ParameterMeta;

struct Def {
    ParameterMeta meta;
    double defaultValue;
};

ParameterMeta P(std::string key, std::string label, std::string si, std::string disp, double lo, double hi,
                std::string group, bool writable = true, bool duringTest = false, bool integer = false)
{
    ParameterMeta m;
    m.key = std::move(key);
    m.label = std::move(label);
    m.siUnit = std::move(si);
    m.displayUnit = std::move(disp);
    m.minSi = lo;
    m.maxSi = hi;
    m.group = std::move(group);
    m.writable = writable;
    m.writableDuringTest = duringTest;
    m.integer = integer;
    return m;
}

std::vector<Def> buildDefs(AxisKind kind)
{
    const bool lin = kind == AxisKind::Linear;
    std::vector<Def> d;
    // Motor and drive ratings (read-only: they come with the hardware).
    d.push_back({P("motor.max_current", "Maximum current (peak)", "A", "A", 0.01, 2000, "motor", false), 80.0});
    d.push_back({P("motor.rated_current", "Rated current (peak)", "A", "A", 0.01, 2000, "motor", false), 15.3});
    d.push_back({P("motor.torque_constant", "Torque constant", "Nm/A", "Nm/A", 1e-4, 1e3, "motor", false), 0.509});
    d.push_back({P("drive.max_voltage", "Maximum voltage", "V", "V", 1, 2000, "motor", false), 282.8});
    // Current loop.
    d.push_back({P("current.period", "Current-loop period", "s", "us", 15.625e-6, 250e-6, "current"), 62.5e-6});
    d.push_back({P("current.kp", "Current proportional gain k_p", "V/A", "V/A", 0, 1e4, "current"), 35.7});
    d.push_back({P("current.ki", "Current integral gain k_i", "V/(A*s)", "V/(A*s)", 0, 1e8, "current"), 1.03e5});
    d.push_back({P("current.alpha", "PI ratio α", "1", "1", 0, 1, "current"), 1.0});
    d.push_back({P("current.dead_time", "Dead time", "s", "us", 0, 500e-6, "current"), 62.5e-6});
    // Velocity loop.
    d.push_back({P("velocity.period", "Velocity-loop period", "s", "us", 62.5e-6, 2e-3, "velocity"), 250e-6});
    d.push_back({P("velocity.kp", "Velocity proportional gain", "Nm*s/rad", "Nm*s/rad", 0, 1e5, "velocity"), 1.0});
    d.push_back({P("velocity.ki", "Velocity integral gain", "Nm/rad", "Nm/rad", 0, 1e8, "velocity"), 50.0});
    d.push_back({P("velocity.integral_divider", "Velocity integral divider", "1", "1", 1, 16, "velocity", true, false, true), 1});
    d.push_back({P("velocity.inertia", "Inertia for torque feedforward", "kgm2", "kgm2", 0, 1e3, "velocity"), 0.0});
    // Position loop.
    d.push_back({P("position.period", "Position-loop period", "s", "ms", 250e-6, 8e-3, "position"), 1e-3});
    d.push_back({P("position.kp", "Position gain", "1/s", "1/s", 0, 1e4, "position"), 50.0});
    d.push_back({P("position.velocity_ff", "Velocity feedforward", "1", "%", 0, 1, "position"), 1.0});
    d.push_back({P("position.torque_ff", "Torque feedforward", "1", "%", 0, 1, "position"), 0.0});
    d.push_back({P("position.feedback", "Feedback (0 semi-closed, 1 full-closed)", "1", "1", 0, 1, "position", true, false, true), 0});
    // Torque-command filters (run at the current-loop rate). Centre 0 = filter off.
    for (int n = 1; n <= kNotchCount; ++n) {
        const std::string k = "filter.notch" + std::to_string(n);
        d.push_back({P(k + ".center", "Notch " + std::to_string(n) + " centre", "Hz", "Hz", 0, 32000, "filter"), 0.0});
        d.push_back({P(k + ".width", "Notch " + std::to_string(n) + " width", "Hz", "Hz", 1, 32000, "filter"), 100.0});
        d.push_back({P(k + ".depth", "Notch " + std::to_string(n) + " depth", "1", "1", 0, 1, "filter"), 0.0});
    }
    d.push_back({P("filter.lowpass.cutoff", "Torque low-pass cutoff (0 = off)", "Hz", "Hz", 0, 32000, "filter"), 0.0});
    // Lost-motion compensation.
    if (lin) {
        d.push_back({P("lostmotion.mode", "Lost-motion compensation (0 off, 1 conventional, 2 proposed)", "1", "1", 0, 2,
                       "lostmotion", true, false, true), 0});
        d.push_back({P("lostmotion.backlash", "Conventional backlash amount", "m", "um", 0, 1e-3, "lostmotion"), 0.0});
        d.push_back({P("lostmotion.A", "Lost-motion coefficient A", "m/Nm", "um/Nm", 0, 1e-3, "lostmotion"), 0.0});
        d.push_back({P("lostmotion.B", "Lost-motion coefficient B", "1/Nm", "um/(Nm*m)", 0, 1e-2, "lostmotion"), 0.0});
        d.push_back({P("lostmotion.screw_offset", "Ball-screw length offset x0", "m", "mm", -10, 10, "lostmotion"), 0.0});
    }
    // Tracing.
    d.push_back({P("trace.divider", "Trace divider (of the velocity period)", "1", "1", 1, 1000, "trace", true, false, true), 1});
    // Two-inertia vibration-suppression filter (spec/lost-motion-and-two-inertia.md §4.1, TI-3/TI-4), off
    // by default: 1 = F_m on the position command (semi-closed feedback only), 2 = F_L on the velocity
    // command of the position loop (full-closed feedback only).
    d.push_back({P("suppression.mode", "Vibration-suppression filter (0 off, 1 semi-closed F_m, 2 full-closed F_L)", "1", "1",
                   0, 2, "suppression", true, false, true), 0});
    d.push_back({P("suppression.f0", "Suppression filter frequency f0", "Hz", "Hz", 1, 500, "suppression"), 20.0});
    d.push_back({P("suppression.zeta", "Suppression filter damping zeta", "1", "1", 0, 1, "suppression"), 0.1});
    d.push_back({P("suppression.tau", "F_L time constant tau", "s", "ms", 0, 0.1, "suppression"), 0.01});
    // Reversal (quadrant-glitch) compensation: at each reversal of the commanded velocity a pulse
    // a·sgn(v_new)·exp(−t/τ) is added to the velocity command (docs/simulator.md). Amplitude 0 = off.
    // Kept after every older drive parameter, so the register addresses of those do not move.
    if (lin) {
        d.push_back({P("reversal.amplitude", "Reversal compensation pulse amplitude (velocity command)", "m/s",
                       "mm/min", 0, 0.05, "reversal"),
                     0.0});
        d.push_back(
            {P("reversal.time_constant", "Reversal compensation pulse time constant", "s", "ms", 1e-4, 0.5, "reversal"),
             0.01});
    }

    // Plant (the machine itself), read-only through the drive.
    d.push_back({P("plant.motor.resistance", "Armature resistance", "ohm", "ohm", 1e-4, 1e3, "plant", false), 0.32});
    d.push_back({P("plant.motor.inductance_q", "q-axis inductance", "H", "mH", 1e-6, 10, "plant", false), 2.19e-3});
    d.push_back({P("plant.motor.inductance_drop_at_max", "Inductance drop at I_max δ", "1", "1", 0, 0.9, "plant", false), 0.0});
    d.push_back({P("plant.motor.back_emf_constant", "Back-EMF constant (q axis)", "V*s/rad", "V*s/rad", 0, 1e3, "plant", false), 0.339});
    d.push_back({P("plant.inertia_motor", "Motor-side inertia J_m", "kgm2", "kgm2", 1e-7, 1e3, "plant", false), 1e-3});
    d.push_back({P("plant.inertia_load", "Load inertia J_L", "kgm2", "kgm2", 0, 1e4, "plant", false), 1e-3});
    d.push_back({P("plant.coupling_stiffness", "Coupling stiffness K (0 = rigid)", "Nm/rad", "Nm/rad", 0, 1e9, "plant", false), 0.0});
    d.push_back({P("plant.coupling_damping", "Coupling damping C", "Nm*s/rad", "Nm*s/rad", 0, 1e6, "plant", false), 0.0});
    d.push_back({P("plant.viscous_motor", "Viscous friction, motor", "Nm*s/rad", "Nm*s/rad", 0, 1e3, "plant", false), 0.0});
    d.push_back({P("plant.viscous_load", "Viscous friction, load", "Nm*s/rad", "Nm*s/rad", 0, 1e3, "plant", false), 0.0});
    d.push_back({P("plant.coulomb_motor", "Coulomb friction, motor side (screw bearings, nut)", "Nm", "Nm", 0, 1e4, "plant", false), 0.0});
    d.push_back({P("plant.coulomb_load", "Coulomb friction, load side (guideways)", "Nm", "Nm", 0, 1e4, "plant", false), 0.0});
    d.push_back({P("plant.coulomb_velocity", "Coulomb friction smoothing velocity", "rad/s", "rad/s", 1e-6, 10, "plant", false), 1e-3});
    d.push_back({P("plant.encoder_motor", "Motor encoder resolution (0 = ideal)", "counts/rev", "counts/rev", 0, 1e12, "plant", false), 0.0});
    d.push_back({P("plant.noise_current", "Current measurement noise (rms)", "A", "A", 0, 100, "plant", false), 0.0});
    d.push_back({P("plant.noise_position", "Encoder position noise (rms)", "rad", "rad", 0, 1, "plant", false), 0.0});
    if (lin) {
        d.push_back({P("plant.screw_lead", "Ball-screw lead R", "m/rad", "mm/rev", 1e-6, 1, "plant", false), 0.012 / (2 * std::numbers::pi)});
        d.push_back({P("plant.lost_motion_A", "Lost-motion compliance A", "m/Nm", "um/Nm", 0, 1e-3, "plant", false), 0.0});
        d.push_back({P("plant.lost_motion_B", "Lost-motion compliance B", "1/Nm", "um/(Nm*m)", 0, 1e-2, "plant", false), 0.0});
        d.push_back({P("plant.screw_offset", "Screw length offset x0", "m", "mm", -10, 10, "plant", false), 0.0});
        d.push_back({P("plant.scale_resolution", "Linear-scale resolution (0 = ideal)", "m", "nm", 0, 1e-3, "plant", false), 0.0});
        d.push_back(
            {P("plant.backlash", "Backlash (play between nut and table)", "m", "um", 0, 1e-3, "plant", false), 0.0});
    } else {
        d.push_back({P("plant.encoder_load", "Load encoder resolution (0 = ideal)", "counts/rev", "counts/rev", 0, 1e12, "plant", false), 0.0});
    }
    return d;
}

const std::vector<Def>& defs(AxisKind kind)
{
    static const std::vector<Def> lin = buildDefs(AxisKind::Linear);
    static const std::vector<Def> rot = buildDefs(AxisKind::Rotary);
    return kind == AxisKind::Linear ? lin : rot;
}

}  // namespace

const std::vector<ParameterMeta>& axisParameterMetas(AxisKind kind)
{
    static const auto build = [](AxisKind k) {
        std::vector<ParameterMeta> v;
        for (const auto& d : defs(k))
            v.push_back(d.meta);
        return v;
    };
    static const std::vector<ParameterMeta> lin = build(AxisKind::Linear);
    static const std::vector<ParameterMeta> rot = build(AxisKind::Rotary);
    return kind == AxisKind::Linear ? lin : rot;
}

model::ParameterValues defaultAxisParameters(AxisKind kind)
{
    model::ParameterValues v;
    for (const auto& d : defs(kind))
        v[d.meta.key] = d.defaultValue;
    return v;
}

bool isPlantParameter(const std::string& key) { return key.rfind("plant.", 0) == 0; }

}  // namespace axistune::sim

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Milling with regeneration for the simulator (issue 10 item 3): a tool with independent modes per
// direction (x = feed direction, y normal), N teeth, tangential/radial specific cutting forces K_t, K_r,
// radial immersion (up or down milling), spindle speed and axial depth. The chip thickness of tooth j is
//   h_j = (f_z + x(t−τ) − x(t)) sin φ_j + (y(t−τ) − y(t)) cos φ_j,   τ = 60 / (n N)   (one tooth period)
// and the force on the tool F = a_p Σ_j g_j h_j [K_t cos φ_j + K_r sin φ_j,  −K_t sin φ_j + K_r cos φ_j],
// g_j = 1 inside the engagement window and while h_j > 0 (the tooth leaves the cut otherwise: this bounds
// chatter to a limit cycle). This is the model of spec/chatter-stability-and-spindle-speed.md §1.3 that
// core/machining/StabilityLobes linearises, so the lobes predict where this simulation chatters.
// The modes are integrated exactly (zero-order hold of the force over one step). The spindle is a
// first-order speed loop (time constant, speed limits) whose command may change during the cut; the spindle
// angle θ integrates the actual speed and the regenerative delay τ(t) is the time since θ was 2π/N smaller
// (spec eq. (1-7)), read from the position history by linear interpolation between steps (at constant speed
// it is exactly k steps, as before). The static chip is the table feed over τ(t): v_f τ(t), v_f = f_z N n₀/60
// (the table keeps its feed rate when the spindle speed changes). The workpiece/table is rigid for the regeneration
// (its vibration is ~10⁴ times smaller than the tool's, docs/machining.md); the reaction −F_x drives the feed axis
// (AxisSimulator setLoadTorque). Plain structs here: core/sim cannot use core/machining (link order).

#include "core/model/Result.h"

#include <cstdint>
#include <vector>

namespace axistune::sim {

struct MillingMode {
    double massKg = 0.0;
    double dampingNsPerM = 0.0;
    double stiffnessNPerM = 0.0;
};

struct MillingSetup {
    std::vector<MillingMode> modesX, modesY; ///< tool modes, displacements add
    int teeth = 0;
    double ktNPerM2 = 0.0;
    double krNPerM2 = 0.0;
    double radialImmersion = 0.0; ///< a_e / D, (0, 1]
    bool upMilling = false;       ///< engagement up [0, acos(1−2r)], down [acos(2r−1), π]
    double spindleRpm = 0.0;
    double axialDepthM = 0.0;    ///< a_p ≥ 0
    double feedPerToothM = 0.0;  ///< f_z ≥ 0
    int stepsPerToothPeriod = 0; ///< 0: the smallest count with a step ≤ 5 µs (at the initial speed)
    /// Spindle speed loop, first order: n' = (clamp(n_cmd) − n)/T. T = 2 ms is the first-order equivalent of
    /// the seed's 80 Hz spindle speed loop (spec §4.3); the limits bound the command (docs/chatter-avoidance.md).
    double spindleTimeConstantS = 0.002;
    double spindleMinRpm = 100.0;
    double spindleMaxRpm = 20000.0;
};

/// Checks every field (modes underdamped with m, k > 0, c ≥ 0; teeth ≥ 1; K_t > 0, K_r ≥ 0; immersion in
/// (0, 1]; rpm > 0; depth, feed ≥ 0; finite). The message names the field.
Status validateMillingSetup(const MillingSetup& setup);

class MillingProcess {
public:
    static Result<MillingProcess> create(const MillingSetup& setup);

    /// Tool at rest, spindle angle 0, clean surface (no regeneration in the first tooth period).
    void reset();
    /// Integrates whole steps up to time t [s] (steps whose start is before t) and returns the mean force on
    /// the tool in x [N] over the steps taken (the last force when none was taken).
    double advanceTo(double tS);

    /// Spindle speed command [rpm] from now on. Outside [spindleMinRpm, spindleMaxRpm] it is limited to the
    /// bound (the drive's limit) and counted in commandLimitCount(); non-finite commands are ignored and counted.
    void setSpindleCommandRpm(double rpm);
    double spindleRpm() const { return m_rpm; }           ///< actual speed
    double spindleCommandRpm() const { return m_rpmCmd; } ///< limited command
    std::uint64_t commandLimitCount() const { return m_cmdLimited; }
    /// The regenerative delay τ(t) [s] used by the last step (one tooth period at constant speed).
    double delayS() const { return m_delay; }
    double time() const { return static_cast<double>(m_step) * m_h; }
    double stepS() const { return m_h; }
    double toothPeriodS() const { return m_tau; }
    double forceX() const { return m_fx; } ///< force on the tool over the last step [N]
    double forceY() const { return m_fy; }
    double toolX() const; ///< tool displacement [m] (sum of the modes)
    double toolY() const;
    double toolAccelX() const; ///< tool acceleration [m/s²] after the last step (sum of the modes)
    double toolAccelY() const;
    const MillingSetup& setup() const { return m_setup; }

private:
    struct Mode {
        double phi[2][2];
        double gamma[2];
        double invMass = 0.0, damping = 0.0, stiffness = 0.0;
        double x = 0.0, v = 0.0;
    };
    MillingProcess() = default;
    void step();

    MillingSetup m_setup;
    double m_h = 0.0, m_tau = 0.0, m_omega = 0.0, m_entry = 0.0, m_exit = 0.0;
    int m_k = 0;
    std::vector<Mode> m_mx, m_my;
    std::vector<double> m_histX, m_histY, m_histTheta; // ring of past tool positions and spindle angles
    std::size_t m_ring = 0;                            // ring length (covers the delay at the minimum speed)
    long long m_step = 0;
    double m_fx = 0.0, m_fy = 0.0;
    double m_rpm = 0.0, m_rpmCmd = 0.0, m_theta = 0.0, m_delay = 0.0, m_feedVel = 0.0, m_spindleDecay = 0.0;
    double m_lag = 0.0; // last delay in steps (search start)
    std::uint64_t m_cmdLimited = 0;
};

} // namespace axistune::sim

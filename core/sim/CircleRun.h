// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The parts of the simulated circle test (docs/ballbar.md "Simulated circle tests", "Circle tests
// through the drive"): the commanded path (CirclePath), the stepping of two existing axis simulators
// along it with a two-axis trace (CircleRun), and the evaluation of such a trace into a ball-bar
// trace with the reversal torque changes (evaluateCircleTrace in CircleTest.h). runCircleTest and the
// drives (SimulatedDrive, over Modbus axistune-simdrive) share them, so a circle measured through a
// drive and one run by runCircleTest follow the same path and are read the same way.
//
// The trace of a circle (one sample per position-loop period, SI):
//   t_s                   time since the circle's command started (the dwell comes first)
//   arc_rad               commanded travelled arc s(t) ≥ 0 along the circle
//   <A>.position_cmd_m    position command of axis A (A = first and second plane axis by name)
//   <A>.table_pos_m       table position of axis A (load side, with the elastic lost motion)
//   <A>.torque_cmd_Nm     torque command of axis A
//   <A>.torque_Nm         motor torque of axis A (k_t·i; ΔT is taken from it)
// with metadata test=circle, axis_x, axis_y, radius_m, feed_m_per_s, direction (ccw|cw), center_x_m,
// center_y_m, data_start_deg, lead_arc_deg, dwell_s, fs_Hz (values printed with 17 digits).

#include "core/model/Capture.h"
#include "core/model/Result.h"
#include "core/sim/CircleTest.h"
#include "core/sim/MotionProfile.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace axistune::sim {

class AxisSimulator;

/// The commanded circle: dwell at the start point, then the travelled arc s(t) (constant angular
/// acceleration over half the lead-in arc, constant feed, deceleration over half the lead-out arc).
class CirclePath {
public:
    /// Checks the options (BadInput naming the option) and plans the path.
    static Result<CirclePath> plan(const CircleTestOptions& options);

    const CircleTestOptions& options() const { return m_o; }
    double duration() const;                 ///< dwell + motion [s]
    double arcAt(double t) const;            ///< travelled arc s(t) [rad]
    MotionState command(double t, bool secondAxis) const;  ///< position command of an axis at t
    double startPosition(bool secondAxis) const { return command(0.0, secondAxis).position; }
    double endPosition(bool secondAxis) const { return command(duration(), secondAxis).position; }
    double phi0() const { return m_phi0; }   ///< geometric angle at s = 0 [rad]
    double sigma() const { return m_sigma; } ///< +1 ccw, −1 cw
    double dataFrom() const { return m_sFrom; } ///< travelled arc at which the 360° data arc begins
    double dataTo() const { return m_sTo; }

private:
    MotionState arc(double t) const;
    CircleTestOptions m_o;
    double m_dwell = 0, m_omega = 0, m_alpha = 0, m_tAcc = 0, m_tConst = 0, m_sAcc = 0;
    double m_phi0 = 0, m_sigma = 1, m_sFrom = 0, m_sTo = 0;
};

/// Refuses a plane that is not two distinct linear axes sharing the position and current periods
/// (BadInput naming both axes).
Status checkCirclePlane(const AxisSimulator& x, const AxisSimulator& y);

/// A circle on two existing axis simulators: begin() installs the commands at the axes' present
/// time (the axes should stand at the path's start point: the drive positions them there first),
/// step() advances both axes together by whole position periods and records the trace.
class CircleRun {
public:
    static Result<CircleRun> begin(AxisSimulator& x, AxisSimulator& y, const CirclePath& path);
    /// Samples a run of this path records at this position period (the path and 0.2 s after its end).
    static std::size_t sampleCount(const CirclePath& path, double positionPeriodS);

    /// Samples the run records: the path and 0.2 s after its end, one per position period.
    std::size_t totalSamples() const { return m_total; }
    std::size_t samplesDone() const { return m_t.size(); }
    bool done() const { return samplesDone() >= m_total; }
    double progress() const { return m_total ? static_cast<double>(samplesDone()) / static_cast<double>(m_total) : 1.0; }
    double samplePeriod() const { return m_tp; }
    /// Advances both axes by at most `samples` position periods.
    void step(std::size_t samples);
    /// The trace recorded so far (layout in the header comment).
    model::Capture trace() const;
    const CirclePath& path() const { return m_path; }

private:
    CircleRun(AxisSimulator& x, AxisSimulator& y, const CirclePath& path) : m_x(&x), m_y(&y), m_path(path) {}
    AxisSimulator* m_x;
    AxisSimulator* m_y;
    CirclePath m_path;
    double m_t0x = 0, m_tp = 0;
    std::int64_t m_ticksPerSample = 0;
    std::size_t m_total = 0;
    std::vector<double> m_t, m_s, m_cx, m_px, m_qx, m_tx, m_cy, m_py, m_qy, m_ty;
};

/// Channel names of the circle trace for an axis ("<axis>.<what>").
std::string circleChannel(const std::string& axis, const char* what);

/// The options a circle trace was run with, from its metadata (BadInput naming a missing or bad key).
/// Geometric errors and torque windows keep their defaults.
Result<CircleTestOptions> circleOptionsFromTrace(const model::Capture& trace);

} // namespace axistune::sim

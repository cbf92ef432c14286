// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Position command generator: a sequence of dwells and trapezoidal or rectangular-jerk (S-curve) moves,
// evaluated at any time for position, velocity and acceleration (axis units: m for linear axes, rad for
// rotary axes).

#include <vector>

namespace axistune::sim {

struct MotionState {
    double position = 0.0;
    double velocity = 0.0;
    double acceleration = 0.0;
};

class MotionProfile {
public:
    explicit MotionProfile(double startPosition = 0.0) : m_start(startPosition) {}

    /// Holds the position for `durationS`.
    void dwell(double durationS);
    /// Moves by `distance` with at most `velocity` (> 0) and `acceleration` (> 0), trapezoid or triangle.
    void move(double distance, double velocity, double acceleration);
    /// The same with the jerk limited to `jerk` (> 0; rectangular jerk, a 7-segment S-curve as in
    /// spec/lost-motion-and-two-inertia.md §4.13 TI-6): a_max is reached when the speed allows, v_max
    /// when the distance allows (else the largest peak speed that fits). jerk ≤ 0 or ∞: the trapezoid.
    void move(double distance, double velocity, double acceleration, double jerk);

    MotionState at(double tS) const;
    double duration() const { return m_pieces.empty() ? 0.0 : m_pieces.back().t0 + m_pieces.back().dt; }
    double startPosition() const { return m_start; }

private:
    struct Piece {  // constant jerk j from (t0, x0, v0, a)
        double t0, dt, x0, v0, a, j = 0.0;
    };
    void push(double dt, double a, double j = 0.0);
    double m_start;
    std::vector<Piece> m_pieces;
};

}  // namespace axistune::sim

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Position command generator: a sequence of dwells and trapezoidal moves, evaluated at any time for
// position, velocity and acceleration (axis units: m for linear axes, rad for rotary axes).

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

    MotionState at(double tS) const;
    double duration() const { return m_pieces.empty() ? 0.0 : m_pieces.back().t0 + m_pieces.back().dt; }
    double startPosition() const { return m_start; }

private:
    struct Piece {  // constant acceleration from (t0, x0, v0)
        double t0, dt, x0, v0, a;
    };
    void push(double dt, double a);
    double m_start;
    std::vector<Piece> m_pieces;
};

}  // namespace axistune::sim

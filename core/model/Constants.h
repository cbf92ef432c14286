// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Constants and unit conversions used across AxisTune, named by what they convert (kRadPerDeg
// multiplies degrees to give radians), and the motor-torque conversions every layer needs.

#include <numbers>

namespace axistune::model {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
/// rad = deg × kRadPerDeg
inline constexpr double kRadPerDeg = std::numbers::pi / 180.0;
/// deg = rad × kDegPerRad
inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;
/// rad/s = min⁻¹ × kRadPerSPerRpm
inline constexpr double kRadPerSPerRpm = 2.0 * std::numbers::pi / 60.0;
/// min⁻¹ = rad/s × kRpmPerRadPerS
inline constexpr double kRpmPerRadPerS = 60.0 / (2.0 * std::numbers::pi);

/// Rated torque of a motor [N·m] from its rated current [A] and torque constant [N·m/A]
/// (the drive parameters motor.rated_current and motor.torque_constant).
constexpr double ratedTorqueNm(double ratedCurrentA, double torqueConstantNmPerA)
{
    return ratedCurrentA * torqueConstantNmPerA;
}

/// A torque given in % of the rated torque, in N·m.
constexpr double torqueNmFromRatedPct(double percentOfRated, double ratedTorqueNm)
{
    return percentOfRated / 100.0 * ratedTorqueNm;
}

} // namespace axistune::model

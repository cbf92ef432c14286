// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The embedded simulated drive's own limits. Only the simulator and its Modbus server read these
// names (tests/layers/check_drive_limits.cmake fails elsewhere): every other component asks the
// drive, Drive::limits() and Drive::planTest() (docs/drive-seam.md).

#include <numbers>

namespace axistune::device {

/// Largest FRF excitation (the multisine's peak) [% of rated torque]; refused above, never clamped.
inline constexpr double kMaxFrfAmplitudePct = 50.0;
/// Largest current step as a fraction of motor.max_current.
inline constexpr double kMaxCurrentStepFraction = 0.5;
/// Longest current-step recording [s].
inline constexpr double kMaxCurrentStepS = 0.05;
/// Largest motor speed a current step may reach [rad/s], estimated as k_t·|I|·t / J_m with the rotor inertia
/// alone: the motor accelerates freely while the velocity loop is open (about 190 min⁻¹).
inline constexpr double kMaxCurrentStepSpeedRadS = 20.0;
/// After a current-step record the axis holds its position this long before the test completes [s], so the
/// next test starts at rest.
inline constexpr double kCurrentStepHoldS = 0.3;
/// Motor speed limit for steps, jogs and circles: 6000 min⁻¹ [rad/s].
inline constexpr double kMaxMotorSpeedRadS = 2.0 * std::numbers::pi * 6000.0 / 60.0;
/// Longest step, hold or current-step record and jog dwell [s].
inline constexpr double kMaxTestDurationS = 600.0;
/// Travel window of jog targets and circles on a linear axis [m] (the simulated table's travel).
inline constexpr double kTravelWindowM = 0.5;
/// The scope (docs/scope.md): channels traced at once, largest divider of the fastest rate (the velocity-loop
/// rate), values (channels × samples) of one triggered capture (64 MB of float64) and of the roll-mode ring
/// (32 MB: 131 s of 8 channels at 4 kHz).
inline constexpr int kScopeMaxChannels = 16;
inline constexpr int kScopeMaxDivider = 1000;
inline constexpr unsigned long long kScopeMaxValues = 8ull << 20;
inline constexpr unsigned long long kScopeRingValues = 4ull << 20;

} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The metadata keys of captures, FRFs, sweeps and ball-bar traces that more than one place writes or reads
// (docs/formats.md "Metadata: numbers as numbers"), each with the kind of its value: a number (double), a whole
// number or a text. Writers and readers use these constants, never the name spelled again, and Metadata's typed
// overloads (core/model/Metadata.h) take and give only the key's kind. tests/core/model/test_metadata_keys.cpp
// fails when a key listed here is spelled as a literal in a metadata call in core/, app/ or widgets/.

#include "core/model/Metadata.h"

namespace axistune::model::meta {

// What the record is and where it came from.
inline constexpr TextKey kTest{"test"};               ///< step, jog, hold, frf, circle, current_step, …
inline constexpr TextKey kMethod{"method"};           ///< FRF method: multisine, prbs, welch-h1, impact-h1, …
inline constexpr TextKey kAxis{"axis"};               ///< the drive's axis name
inline constexpr TextKey kMachine{"machine"};         ///< the machine (preset) the drive reported
inline constexpr TextKey kConnection{"connection"};   ///< the URI the record was taken through
inline constexpr TextKey kSource{"source"};           ///< the input file or device a record was made from
inline constexpr TextKey kSourceFormat{"source_format"}; ///< the foreign format an import read (uff58)
inline constexpr TextKey kContent{"content"};         ///< what a stored capture holds (frf, ballbar)
inline constexpr TextKey kContentOf{"content_of"};    ///< what a predicted FRF is (predicted open loop, …)
inline constexpr IntegerKey kSeed{"seed"};            ///< the simulator's noise seed
inline constexpr IntegerKey kFirstDataLine{"first_data_line"}; ///< imports: the file's line of the first data row

// Sampling and timing.
inline constexpr NumberKey kFsHz{"fs_Hz"};                    ///< the trace's sample rate [Hz]
inline constexpr NumberKey kMotionTimeS{"motion_time_s"};     ///< machine time of the test [s]
inline constexpr NumberKey kSettleS{"settle_s"};              ///< settling before the record [s]
inline constexpr NumberKey kEngageS{"engage_s"};              ///< a simulated cut: when the tool engages [s]
inline constexpr NumberKey kCurrentPeriodS{"current_period_s"};   ///< the drive's current-loop period [s]
inline constexpr NumberKey kVelocityPeriodS{"velocity_period_s"}; ///< the drive's velocity-loop period [s]
inline constexpr NumberKey kPeriodS{"period_s"};              ///< one multisine period [s]
inline constexpr NumberKey kMinMeasureS{"min_measure_s"};     ///< sine stream: shortest measurement per frequency [s]
inline constexpr NumberKey kLoopTimeConstantS{"loop_time_constant_s"}; ///< the loop's slowest time constant [s]
inline constexpr NumberKey kSettlePeriods{"settle_periods"}; ///< sine stream: settling of at least this many periods
inline constexpr IntegerKey kNperseg{"nperseg"};              ///< Welch/PRBS segment length [samples]
inline constexpr TextKey kScopeMode{"scope_mode"};            ///< triggered, roll

// FRF quantity.
inline constexpr TextKey kMeasurement{"measurement"}; ///< complementary, sensitivity, open-loop, plant (LoopMeasurement)
inline constexpr TextKey kQuantity{"quantity"};       ///< what the FRF relates, as the backend names it
inline constexpr TextKey kUnits{"units"};             ///< the FRF's units, output/input (docs/formats.md)
inline constexpr TextKey kInput{"input"};             ///< the FRF's input signal
inline constexpr TextKey kOutput{"output"};           ///< the FRF's output signal
inline constexpr TextKey kLoop{"loop"};               ///< how a loop FRF was derived (open-loop, plant-from-…)
inline constexpr NumberKey kAmplitudeNm{"amplitude_Nm"};     ///< injection amplitude [N m]
inline constexpr NumberKey kAmplitudePeak{"amplitude_peak"}; ///< injection peak in the drive's units
inline constexpr NumberKey kPeakNm{"peak_Nm"};               ///< multisine peak torque [N m]
inline constexpr IntegerKey kNoiseInvalidLines{"noise_invalid_lines"}; ///< lines left invalid by noise

// Injection hold and voltage limit of the simulated drive (dsp::InjectionHold, the FRF tests).
inline constexpr TextKey kInjectionHoldCorrected{"injection_hold_corrected"}; ///< "true" once corrected
inline constexpr IntegerKey kInjectionHoldTicks{"injection_hold_ticks"};      ///< hold of the injection [ticks]
inline constexpr NumberKey kInjectionHoldPeriodS{"injection_hold_period_s"};  ///< one tick [s]
inline constexpr IntegerKey kVoltageClampedTicks{"voltage_clamped_ticks"};    ///< current-loop ticks at the limit
inline constexpr IntegerKey kVoltageClampedSamples{"voltage_clamped_samples"}; ///< trace samples at the limit
inline constexpr NumberKey kExpWindowDecay{"exp_window_decay_1_s"};           ///< impact test: window decay [1/s]

// LinuxCNC (hal:).
inline constexpr TextKey kPid{"pid"};           ///< the HAL PID component of the axis
inline constexpr TextKey kThread{"thread"};     ///< the HAL thread the test ran in
inline constexpr TextKey kIni{"ini"};           ///< the machine's INI file
inline constexpr TextKey kHalUnits{"hal_units"}; ///< what the HAL signals' units are

// Ball bar and machining.
inline constexpr NumberKey kRadiusM{"radius_m"};       ///< circle radius [m]
inline constexpr TextKey kDirection{"direction"};      ///< circle direction (model::circleDirectionName)
inline constexpr TextKey kPlane{"plane"};              ///< circle plane (XY, …)
inline constexpr NumberKey kSpindleRpm{"spindle_rpm"}; ///< [min^-1]
inline constexpr NumberKey kAxialDepthM{"axial_depth_m"}; ///< [m]
inline constexpr IntegerKey kSpindleCommandLimited{"spindle_command_limited"}; ///< commands the spindle limited
inline constexpr TextKey kCuttingForceSign{"cutting_force_sign"};             ///< the sign convention, in words
inline constexpr TextKey kAvoid{"avoid"};                    ///< chatter avoidance method (esc, adaptive, …)
inline constexpr TextKey kAvoidPowerUnit{"avoid_power_unit"}; ///< unit of the avoidance's chatter power
inline constexpr TextKey kAvoidCostUnit{"avoid_cost_unit"};   ///< unit of its cost

} // namespace axistune::model::meta

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Amplitude dependence of the closed velocity loop (issue 18 item 3; docs/tuning.md "Amplitude map and backlash"): the
// same multisine band measured at three or more excitation peaks through the drive seam; a line whose response changes
// between the amplitudes beyond its noise is non-linear (Coulomb friction at low frequency, backlash). The rule:
// for every pair of amplitudes a, b at which the line was measured below the voltage limit,
//   z_ab = |H_a − H_b| / √(σ_a² + σ_b²),   σ = (σ_H/|H|)·|H| of the multisine's scatter over its periods;
// the line is non-linear when max z_ab > kNonlinearSigmas (5, the adaptive FRF's consistency test).
// Plus the reversal lost motion (backlash) of a linear axis with motor and table position in its trace
// (backlashFromReversal). No Qt.

#include "core/device/Drive.h"
#include "core/device/TestRunner.h"
#include "core/model/Result.h"

#include <complex>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

namespace axistune::autotune {

/// A line is non-linear when two amplitudes differ by more than this many combined standard errors.
inline constexpr double kNonlinearSigmas = 5.0;

struct AmplitudeMapOptions {
    std::string axis;
    std::vector<double> amplitudesPct; ///< multisine peaks [% of rated torque], at least 3, increasing, distinct
    double fminHz = 20.0;
    double fmaxHz = 0.0;      ///< 0: 0.975 × the drive's trace rate
    double spacingHz = 10.0;  ///< line spacing
    int periods = 4;          ///< averaged periods per amplitude (the noise of each line from their scatter)
    double timeBudgetS = 0.0; ///< motion time of all amplitudes together; 0: no limit
};

struct AmplitudeRun {
    double amplitudePct = 0.0;
    double peakNm = 0.0; ///< the multisine's peak torque as the drive stated it (NaN when it did not)
    double motionTimeS = 0.0;
    bool voltageLimited = false; ///< the current loop reached its voltage limit: left out of the comparison
    std::size_t validLines = 0;
};

struct AmplitudeLine {
    double freqHz = 0.0;
    std::vector<std::complex<double>> h; ///< per amplitude (NaN when not measured)
    std::vector<double> relativeNoise;   ///< σ_H/|H| per amplitude (NaN when not known)
    double maxZ = 0.0;                   ///< largest z_ab over the compared pairs (NaN: fewer than two)
    double magnitudeSpreadDb = 0.0;      ///< max − min of 20 log |H| over the compared amplitudes
    double phaseSpreadDeg = 0.0;         ///< max − min of the phase (wrapped around the first) over them
    bool compared = false;               ///< at least two amplitudes below the voltage limit with a noise estimate
    bool nonlinear = false;
};

struct AmplitudeMap {
    std::string axis;
    std::vector<AmplitudeRun> runs;
    std::vector<AmplitudeLine> lines;
    std::size_t compared = 0;  ///< lines with at least two comparable amplitudes
    std::size_t nonlinear = 0; ///< of them, flagged
    double motionTimeS = 0.0;
    double nonlinearFraction() const
    {
        return compared > 0 ? static_cast<double>(nonlinear) / static_cast<double>(compared) : 0.0;
    }
};

/// At least three amplitudes, finite, > 0 and increasing; BadInput naming the value otherwise.
Status checkAmplitudeList(const std::vector<double>& pct);

/// Measures the map. Errors: fewer than three amplitudes, non-increasing or non-positive ones, a band the drive
/// cannot excite, a drive without multisine FRF, the drive's refusals and faults (runTest's), the time budget.
Result<AmplitudeMap> measureAmplitudeMap(device::Drive& drive, const AmplitudeMapOptions& options,
                                         const device::RunOptions& run = {});

/// The per-line rule on measured responses (the part of measureAmplitudeMap after the tests; for tests and
/// for maps built from files): lines[i].h and relativeNoise filled, runs[a].voltageLimited set.
void classifyAmplitudeLines(AmplitudeMap& map);

/// The amplitude the tuner designs from: the one of the map nearest (in log) to the torque the axis sees in use,
/// `useTorquePct` [% of rated torque] (the move evaluation's acceleration torque J·a). Index into runs; nullopt when
/// every amplitude is voltage-limited.
std::optional<std::size_t> amplitudeInUse(const AmplitudeMap& map, double useTorquePct);

/// The map as JSON (docs/formats.md "Amplitude map"): axis, rule, threshold_sigmas, amplitudes[] {amplitude_pct,
/// peak_Nm, motion_time_s, voltage_limited, valid_lines}, lines[] {f_Hz, at[] {amplitude_pct, magnitude_dB, phase_deg,
/// relative_noise}, max_z, magnitude_spread_dB, phase_spread_deg, compared, nonlinear}, lines_compared,
/// nonlinear_lines, nonlinear_fraction, motion_time_s. A value not defined is left out and named in `undefined`.
nlohmann::json amplitudeMapJson(const AmplitudeMap& map);

/// Reversal lost motion (backlash) of a linear axis whose trace has the motor and the table position: one jog forth
/// by d and back (a reversal). While the axis moves at ≥ half the jog's peak speed the play is taken up on one flank,
/// so x_m − x_t = c_± + k·T (one intercept per direction, a common elastic slope k on the motor torque T); the
/// backlash is c_+ − c_−, the lost motion at zero motor torque. Friction on the motor side (before the elastic
/// transmission) winds the screw the other way in each direction and lowers it by 2·F_m times the torsional
/// compliance (vmc X: about 2.5 µm; docs/tuning.md "Backlash"): the estimate is the play minus that wind-up.
inline constexpr double kBacklashDwellS = 0.02;
struct BacklashEstimate {
    double backlashM = 0.0;        ///< c_+ − c_− [m]
    double complianceMPerNm = 0.0; ///< k [m/(N m)]
    std::size_t samples = 0;       ///< moving samples in the regression
    double residualRmsM = 0.0;     ///< rms of the regression's residual [m]
};

/// The reversal jog (forth by distanceM, back to the start, kBacklashDwellS of standstill before and after).
device::TestRequest backlashReversal(const std::string& axis, double distanceM, double velocityMPerS,
                                     double accelerationMPerS2);
/// Errors: a trace without position_cmd_m, motor_pos_m, table_pos_m or torque_Nm; fewer than 10 moving samples in a
/// direction; a torque that does not vary.
Result<BacklashEstimate> backlashFromReversal(const model::Capture& trace);
/// Runs the reversal and evaluates it; `motionS` gets its motion time.
Result<BacklashEstimate> measureBacklash(device::Drive& drive, const std::string& axis, double distanceM,
                                         double velocityMPerS, double accelerationMPerS2, const device::RunOptions& run,
                                         double& motionS);

/// The move evaluation's point-to-point move (AutoTune's `move` step): 10 mm at 50 mm/s and 1 m/s² on a linear axis,
/// 0.2 rad at 1 rad/s and 20 rad/s² on a rotary one, 0.15 s of standstill before and after.
device::TestRequest moveEvaluationRequest(const std::string& axis, bool linear);

/// The amplitude map inside autotune's FRF step: the move evaluation's move once with the running gains (the torque
/// the axis sees in use: its peak |torque_cmd|), then the map; the tuner designs from the map's amplitude nearest
/// that torque (amplitudeInUse).
struct InUseMap {
    AmplitudeMap map;
    double peakTorqueNm = 0.0;      ///< of the move with the running gains
    double useTorquePct = 0.0;      ///< the same in % of rated torque
    std::optional<std::size_t> use; ///< index into map.runs
    double motionTimeS = 0.0;       ///< the move and every amplitude
};
/// Errors: as measureAmplitudeMap; a drive fault (runTest's Safety) is "drive fault during ..."; the budget.
Result<InUseMap> amplitudeMapInUse(device::Drive& drive, const AmplitudeMapOptions& options, bool linear,
                                   double ratedTorqueNm, const device::RunOptions& run = {});
/// `amplitude_map` of the frf step: the map's JSON plus move_peak_torque_Nm, use_torque_pct, design_amplitude_pct.
nlohmann::json inUseJson(const InUseMap& m);

} // namespace axistune::autotune

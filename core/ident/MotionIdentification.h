// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Rigid-body inertia and friction from a recorded motion (docs/identification.md): inverse-dynamic
// least squares (IDIM-LS, Gautier) of
//     force = M·q̈ + Fv·q̇ + Fc·sign(q̇) + offset
// with q̇, q̈ from a zero-phase low-passed position by central differences and the regressor and the
// force decimated in parallel; and the validation of the identified model by simulating it in closed
// loop under the record's own position controller. Linear axes: q [m], force [N], M [kg];
// rotary axes: q [rad], force [N·m], M [kg·m²].

#include "core/model/Result.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace axistune::ident {

enum class AxisMotion { Linear, Rotary };

/// Sample period of a time column: the median step, accepted when every step lies within
/// `relTolerance`·median of it (time stamps with jitter). Errors name the offending data row (1-based).
Result<double> uniformSamplePeriod(const std::vector<double>& timeS, double relTolerance);

struct IdentificationOptions {
    double cutoffHz = 100.0; ///< zero-phase Butterworth (order 4) on the position
    int decimation = 0;      ///< 0: round(fs / cutoff)
    int borderSamples = -1;  ///< dropped at each end; −1: 5·decimation
    bool asymmetric = false; ///< also fit per-direction viscous and Coulomb friction
    /// Equations (after decimation) with a slower velocity are left out: at rest the friction is
    /// anything within ±Fc. minSpeed > 0 in m/s or rad/s, else minSpeedFraction of the largest speed.
    double minSpeed = 0.0;
    double minSpeedFraction = 0.01;
    /// Refusal thresholds (docs/identification.md "When the identification is refused").
    double maxScaledCondition = 1000.0;
    double minDirectionFraction = 0.05; ///< of the samples moving each way, for Coulomb
    double maxInertiaStdPct = 20.0;
};

struct MotionRecord {
    double periodS = 0.0;
    std::vector<double> position; ///< m or rad
    std::vector<double> force;    ///< N or N·m (already scaled)
    std::vector<double> velocity; ///< optional measured velocity (m/s or rad/s); empty = from position
};

struct Estimate {
    double value = 0.0;
    double std = 0.0; ///< standard deviation from the LS covariance σ²(WᵀW)⁻¹
    double stdPct() const;
};

struct AsymmetricFriction {
    Estimate inertia, viscousPositive, viscousNegative, coulombPositive, coulombNegative;
    double residualRms = 0.0;
    double scaledCondition = 0.0;
};

struct IdentificationResult {
    double sampleRateHz = 0.0;
    int decimation = 1;
    int borderSamples = 0;
    std::size_t rows = 0;  ///< equations after decimation and leaving out the ones at rest
    double minSpeed = 0.0; ///< the speed below which equations were left out
    Estimate inertia, viscous, coulomb, offset;
    double residualRms = 0.0;     ///< force units
    double residualRelPct = 0.0;  ///< 100·|e|/|y|
    double condition = 0.0;       ///< 2-norm condition number of the decimated regressor (as published)
    double scaledCondition = 0.0; ///< the same with unit-norm columns (independent of units; the gate)
    double positiveFraction = 0.0, negativeFraction = 0.0;
    std::optional<AsymmetricFriction> asymmetric;
};

/// Errors (ErrorCode::BadInput, the reason in the detail) when the data cannot identify the model:
/// too short, no velocity reversal for Coulomb friction, ill-conditioned regressor, inertia not
/// excited (relative standard deviation) or not positive.
Result<IdentificationResult> identifyRigidBody(const MotionRecord& record, const IdentificationOptions& options);

/// The model the simulator runs: force = M·q̈ + F_fric(q̇) + offset, F_fric = Fv⁺·q̇ + Fc⁺ (q̇ > 0),
/// Fv⁻·q̇ − Fc⁻ (q̇ < 0), and at rest while −Fc⁻ ≤ F − offset ≤ Fc⁺.
struct RigidBodyModel {
    double inertia = 0.0;
    double viscousPositive = 0.0, viscousNegative = 0.0;
    double coulombPositive = 0.0, coulombNegative = 0.0;
    double offset = 0.0;
    static RigidBodyModel symmetric(double m, double fv, double fc, double offset);
};

/// A position P + velocity P cascade as on the EMPS rig: u_k = sat(kv·(kp·(r_k − q_k) − v_k)) + extra_k,
/// v_k = (q_k − q_{k−2})/(2h) (two-tap average of q, backward difference), the command computed at
/// sample k held over [t_{k+delay}, t_{k+delay+1}); force = forceScale·u.
struct PositionController {
    double kpPerS = 0.0;
    double kv = 0.0;         ///< command units per (position unit/s)
    double saturation = 0.0; ///< |sat| limit in command units, > 0
    int delaySamples = 0;
    double forceScale = 1.0; ///< force units per command unit
};

struct ValidationRecord {
    double periodS = 0.0;
    std::vector<double> reference, position, command; ///< command: the recorded u (for the force error)
    std::vector<double> extra;                        ///< added to u (e.g. force pulses); may be empty
};

struct ValidationResult {
    std::size_t firstSample = 0; ///< errors are taken from here to the end
    double positionErrorRms = 0.0, positionErrorMax = 0.0;
    double positionErrorPctOfMotion = 0.0; ///< 100·rms(e)/rms(q − mean q)
    double benchmarkPositionPct = 0.0;     ///< 100·‖q_f − q_sim‖/‖q_f‖ (EMPS benchmark script, q_f filtered)
    double benchmarkForcePct = 0.0;        ///< 100·‖F − F_sim‖/‖F‖
    std::vector<double> simulatedPosition, simulatedCommand;
};

/// Simulates `model` in closed loop (`substeps` explicit steps per sample, Karnopp stiction at zero
/// velocity) driven by the record's reference; errors from `firstSample` on, the benchmark position
/// error on the position filtered like the identification (`cutoffHz`).
Result<ValidationResult> validateClosedLoop(const RigidBodyModel& model, const PositionController& controller,
                                            const ValidationRecord& record, double cutoffHz, std::size_t firstSample,
                                            int substeps = 10);

} // namespace axistune::ident

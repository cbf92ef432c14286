// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Cutting force observer (CFO) of a two-inertia feed drive, seed 003 eqs. (1)–(3)
// (spec/cutting-force-observer-and-chatter-detection.md §1.3, §1.4, §3.2 CF-1, §3.3 CF-2 "motor model"):
//   T̂_sM  = Q T_M − J_M [sQ]ω_M − B_M [Q]ω_M − F_CM [Q]sgn(ω_M)                       (3)
//   F̂_cut = T̂_s − (Ĵ_L [sQ]ω_L + B̂_L [Q]ω_L + F̂_CL [Q]sgn(ω_L))                     (2)
// Parameters multiply filtered signals (spec §3.2), so changing them online never upsets filter states.
// Q(s) is a second-order Butterworth low-pass, Tustin with pre-warping at the cutoff (spec §3.10).
// Sign convention of eq. (1): F_cut is a load torque on the load side with the sign of friction,
// J_L ω̇_L = T_s − B_L ω_L − F_CL sgn(ω_L) − F_cut. Deterministic; step() never allocates.

#include "core/dsp/DigitalFilter.h"
#include "core/model/Result.h"

namespace axistune::machining {

/// 2nd-order Butterworth low-pass Q(s) = ω²/(s² + √2 ω s + ω²), Tustin pre-warped at fc.
/// Errors: fc ≤ 0 or fc ≥ Nyquist, period ≤ 0.
Result<dsp::Biquad> butterworth2LowPass(double cutoffHz, double periodS);
/// The band-limited differentiator s·Q(s) with the same Q (one proper filter).
Result<dsp::Biquad> butterworth2Derivative(double cutoffHz, double periodS);

/// sgn(ω) with a dead band: inside |ω| ≤ deadband the last non-zero sign is held (0 before any motion).
class SignWithHold {
public:
    explicit SignWithHold(double deadband = 0.0) : m_deadband(deadband) {}
    double step(double omega)
    {
        if (omega > m_deadband)
            m_last = 1.0;
        else if (omega < -m_deadband)
            m_last = -1.0;
        return m_last;
    }
    double value() const { return m_last; }
    void reset() { m_last = 0.0; }

private:
    double m_deadband;
    double m_last = 0.0;
};

/// Load-side parameters of eq. (1) (rotary units: kg·m², N·m·s/rad, N·m).
struct LoadParameters {
    double inertia = 0.0; ///< J_L
    double viscous = 0.0; ///< B_L
    double coulomb = 0.0; ///< F_CL
};

/// Motor-side parameters of eq. (3).
struct MotorParameters {
    double inertia = 0.0; ///< J_M
    double viscous = 0.0; ///< B_M
    double coulomb = 0.0; ///< F_CM
};

struct ObserverOptions {
    double qCutoffHz = 250.0;       ///< Q(s), Table 2
    double signDeadbandRadS = 0.05; ///< sgn(ω) dead band with hold (spec §3.2)
};

class CuttingForceObserver {
public:
    CuttingForceObserver() = default; ///< unusable until assigned from create()
    static Result<CuttingForceObserver> create(const MotorParameters& motor, const LoadParameters& load,
                                               const ObserverOptions& options, double periodS);
    void reset();
    void setLoadParameters(const LoadParameters& load) { m_load = load; }
    const LoadParameters& loadParameters() const { return m_load; }

    /// Eq. (3): the torsion torque estimate from the motor torque T_M and the motor velocity ω_M.
    double torsionTorque(double motorTorqueNm, double omegaM);
    /// Eq. (2) with a given T̂_s and the load velocity ω_L; returns F̂_cut.
    double stepWithTorsion(double torsionTorqueHat, double omegaL);
    /// Eqs. (3) then (2).
    double step(double motorTorqueNm, double omegaM, double omegaL)
    {
        return stepWithTorsion(torsionTorque(motorTorqueNm, omegaM), omegaL);
    }
    /// The sign of ω_L used by the last step (dead band with hold).
    double loadSign() const { return m_signL.value(); }

private:
    MotorParameters m_motor;
    LoadParameters m_load;
    SignWithHold m_signM, m_signL;
    dsp::Biquad m_qT, m_dM, m_qM, m_qSM; // motor side: Q T_M, sQ ω_M, Q ω_M, Q sgn ω_M
    dsp::Biquad m_dL, m_qL, m_qSL;       // load side: sQ ω_L, Q ω_L, Q sgn ω_L
};

} // namespace axistune::machining

// SPDX-License-Identifier: GPL-3.0-or-later
// Cutting force observer, seed 003 eqs. (1)–(3), spec/cutting-force-observer-and-chatter-detection.md
// §1.3–§1.4 and §3.2 (CF-1): parameters multiply filtered signals; Q(s) 2nd-order Butterworth, Tustin
// pre-warped at the cutoff (the filters of the reference simulation, spec §3.10 / Appendix A).
#include "core/machining/CuttingForceObserver.h"

#include <cmath>
#include <numbers>
#include <string>

namespace axistune::machining {
namespace {

Result<dsp::Biquad> butterworth2(double fc, double ts, bool derivative)
{
    if (!(ts > 0.0) || !std::isfinite(ts))
        return makeError(ErrorCode::OutOfRange, "sample period must be > 0 (got " + std::to_string(ts) + " s)");
    if (!(fc > 0.0) || fc >= 0.5 / ts)
        return makeError(ErrorCode::OutOfRange, "filter cutoff " + std::to_string(fc) + " Hz must be in (0, Nyquist " +
                                                    std::to_string(0.5 / ts) + " Hz)");
    // Q(s) = wd²/(s² + 2ζ wd s + wd²), ζ = 1/√2, s = c (1 − z⁻¹)/(1 + z⁻¹), c = 2/ts, wd pre-warped.
    const double wd = 2.0 / ts * std::tan(std::numbers::pi * fc * ts);
    const double c = 2.0 / ts;
    const double z = std::sqrt(0.5);
    const double a0 = c * c + 2.0 * z * wd * c + wd * wd;
    const double a1 = (2.0 * wd * wd - 2.0 * c * c) / a0;
    const double a2 = (c * c - 2.0 * z * wd * c + wd * wd) / a0;
    if (derivative) {
        const double g = wd * wd * c / a0;
        return dsp::Biquad(g, 0.0, -g, a1, a2);
    }
    const double g = wd * wd / a0;
    return dsp::Biquad(g, 2.0 * g, g, a1, a2);
}

} // namespace

Result<dsp::Biquad> butterworth2LowPass(double cutoffHz, double periodS)
{
    return butterworth2(cutoffHz, periodS, false);
}

Result<dsp::Biquad> butterworth2Derivative(double cutoffHz, double periodS)
{
    return butterworth2(cutoffHz, periodS, true);
}

Result<CuttingForceObserver> CuttingForceObserver::create(const MotorParameters& motor, const LoadParameters& load,
                                                          const ObserverOptions& options, double periodS)
{
    auto q = butterworth2LowPass(options.qCutoffHz, periodS);
    if (!q)
        return makeError(q.error().code, "observer Q(s): " + q.error().detail);
    auto d = butterworth2Derivative(options.qCutoffHz, periodS);
    if (!d)
        return makeError(d.error().code, "observer sQ(s): " + d.error().detail);
    if (!(options.signDeadbandRadS >= 0.0))
        return makeError(ErrorCode::OutOfRange, "sign dead band must be >= 0");
    CuttingForceObserver o;
    o.m_motor = motor;
    o.m_load = load;
    o.m_signM = SignWithHold(options.signDeadbandRadS);
    o.m_signL = SignWithHold(options.signDeadbandRadS);
    o.m_qT = o.m_qM = o.m_qSM = o.m_qL = o.m_qSL = *q;
    o.m_dM = o.m_dL = *d;
    return o;
}

void CuttingForceObserver::reset()
{
    for (auto* f : {&m_qT, &m_dM, &m_qM, &m_qSM, &m_dL, &m_qL, &m_qSL})
        f->reset();
    m_signM.reset();
    m_signL.reset();
}

double CuttingForceObserver::torsionTorque(double motorTorqueNm, double omegaM)
{
    const double s = m_signM.step(omegaM);
    return m_qT.process(motorTorqueNm) - m_motor.inertia * m_dM.process(omegaM) -
           m_motor.viscous * m_qM.process(omegaM) - m_motor.coulomb * m_qSM.process(s);
}

double CuttingForceObserver::stepWithTorsion(double torsionTorqueHat, double omegaL)
{
    const double s = m_signL.step(omegaL);
    return torsionTorqueHat - (m_load.inertia * m_dL.process(omegaL) + m_load.viscous * m_qL.process(omegaL) +
                               m_load.coulomb * m_qSL.process(s));
}

} // namespace axistune::machining

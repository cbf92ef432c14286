// SPDX-License-Identifier: GPL-3.0-or-later
// Runtime of the two-inertia suppression filters: F_m (5.7) as the command shaper of TI-3
// (y_m* = y* + LPF_{T1}(a*)/ω₀², spec/lost-motion-and-two-inertia.md §2.5 [DERIVED] decomposition and
// §4.10) and F_L (5.9) by Tustin as in TI-4 (§4.11). The equations are in docs/simulator.md.
#include "core/sim/SuppressionFilter.h"

#include "core/model/Constants.h"
#include "core/model/Units.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace axistune::sim {
namespace {

using model::kTwoPi;

std::string num(double v) { return model::formatNumber(v, 6); }

}  // namespace

Status checkSuppressionSettings(const SuppressionSettings& s, bool fullClosed, double positionPeriodS)
{
    if (s.mode == SuppressionFilterMode::Off)
        return Status::success();
    if (s.mode == SuppressionFilterMode::SemiClosedFm && fullClosed)
        return makeError(ErrorCode::BadInput,
                         "suppression.mode 1 (semi-closed F_m on the position command) needs position.feedback 0 "
                         "(semi-closed), but position.feedback is 1 (full-closed): use suppression.mode 2 (F_L)");
    if (s.mode == SuppressionFilterMode::FullClosedFl && !fullClosed)
        return makeError(ErrorCode::BadInput,
                         "suppression.mode 2 (full-closed F_L in the position loop) needs position.feedback 1 "
                         "(full-closed), but position.feedback is 0 (semi-closed): use suppression.mode 1 (F_m)");
    const double nyquist = 0.5 / positionPeriodS;
    if (!(s.f0Hz > 0.0) || !(s.f0Hz < nyquist))
        return makeError(ErrorCode::OutOfRange, "suppression.f0 " + num(s.f0Hz) +
                                                    " Hz must lie above 0 and below half the position-loop rate (" +
                                                    num(nyquist) + " Hz at position.period " +
                                                    num(positionPeriodS * 1e3) + " ms)");
    if (s.mode == SuppressionFilterMode::FullClosedFl) {
        if (!(s.zeta > 0.0) || !(s.tauS > 0.0))
            return makeError(ErrorCode::OutOfRange, "suppression.mode 2 (F_L) needs suppression.zeta > 0 and "
                                                    "suppression.tau > 0 (got " +
                                                        num(s.zeta) + " and " + num(s.tauS) + " s): F_L must be proper");
        const double hf = 1.0 / (2.0 * s.zeta * kTwoPi * s.f0Hz * s.tauS);
        if (hf > kMaxFlHighFrequencyGain)
            return makeError(ErrorCode::OutOfRange,
                             "F_L high-frequency gain 1/(2·suppression.zeta·ω₀·suppression.tau) = " + num(hf) +
                                 " exceeds " + num(kMaxFlHighFrequencyGain) + ": raise suppression.zeta or suppression.tau");
    }
    return Status::success();
}

Result<dsp::Biquad> designFlTustin(double f0Hz, double zeta, double tauS, double periodS)
{
    if (!(f0Hz > 0.0) || !(zeta > 0.0) || !(tauS > 0.0) || !(periodS > 0.0))
        return makeError(ErrorCode::BadInput, "F_L needs f0 > 0, zeta > 0, tau > 0 and a period > 0");
    const double w0 = kTwoPi * f0Hz;
    // N(s) = s² + 2ζω₀s + ω₀², D(s) = (2ζω₀s + ω₀²)(τs + 1); s = K(z − 1)/(z + 1), K = 2/T.
    const double n2 = 1.0, n1 = 2.0 * zeta * w0, n0 = w0 * w0;
    const double d2 = 2.0 * zeta * w0 * tauS, d1 = 2.0 * zeta * w0 + w0 * w0 * tauS, d0 = w0 * w0;
    const double k = 2.0 / periodS, k2 = k * k;
    const double a0 = d2 * k2 + d1 * k + d0;
    const double b0 = (n2 * k2 + n1 * k + n0) / a0;
    const double b1 = 2.0 * (n0 - n2 * k2) / a0;
    const double b2 = (n2 * k2 - n1 * k + n0) / a0;
    const double a1 = 2.0 * (d0 - d2 * k2) / a0;
    const double a2 = (d2 * k2 - d1 * k + d0) / a0;
    return dsp::Biquad(b0, b1, b2, a1, a2);
}

Status FmCommandShaper::configure(double f0Hz, double zeta, double periodS)
{
    if (!(f0Hz > 0.0) || !(zeta >= 0.0) || !(periodS > 0.0))
        return makeError(ErrorCode::BadInput, "F_m needs f0 > 0, zeta >= 0 and a period > 0");
    const double w0 = kTwoPi * f0Hz;
    m_w0sq = w0 * w0;
    m_t1 = 2.0 * zeta / w0;
    m_lambda = m_t1 > 0.0 ? std::exp(-periodS / m_t1) : 0.0;
    m_period = periodS;
    m_on = true;
    reset();
    return Status::success();
}

void FmCommandShaper::reset() { m_q = m_prevA = 0.0; }

MotionState FmCommandShaper::process(const MotionState& c)
{
    if (!m_on)
        return c;
    const double a = c.acceleration;
    const double slope = (a - m_prevA) / m_period;  // a* linear between the samples
    double dq = slope;
    if (m_t1 > 0.0) {
        // q' = (a − q)/T₁ with a ramp input over the period: q = a − T₁·s + (q₀ − a₀ + T₁·s)·e^{−T/T₁}.
        m_q = a - m_t1 * slope + (m_q - m_prevA + m_t1 * slope) * m_lambda;
        dq = (a - m_q) / m_t1;
    } else {
        m_q = a;  // ζ = 0: F_m = 1 + s²/ω₀² (5.8); q' is the slope of a*
    }
    m_prevA = a;
    return {c.position + m_q / m_w0sq, c.velocity + dq / m_w0sq, c.acceleration};
}

}  // namespace axistune::sim

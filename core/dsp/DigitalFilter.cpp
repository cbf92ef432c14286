// SPDX-License-Identifier: GPL-3.0-or-later
// Notch and low-pass by the Tustin transform with pre-warping; see the header for the conventions
// (notch placement: spec/current-loop-and-multisweep-frf.md §3.8 and §4.4).
#include "core/dsp/DigitalFilter.h"

#include <cmath>
#include <numbers>
#include <string>

namespace axistune::dsp {

using cd = std::complex<double>;

cd Biquad::response(double fHz, double periodS) const
{
    const cd z1 = std::polar(1.0, -2.0 * std::numbers::pi * fHz * periodS);  // z^-1
    return (m_b0 + m_b1 * z1 + m_b2 * z1 * z1) / (1.0 + m_a1 * z1 + m_a2 * z1 * z1);
}

cd FilterCascade::response(double fHz, double periodS) const
{
    cd h = 1.0;
    for (const auto& s : m_stages)
        h *= s.response(fHz, periodS);
    return h;
}

Result<Biquad> designNotch(const NotchSpec& spec, double periodS)
{
    const double nyquist = 0.5 / periodS;
    if (!(periodS > 0.0))
        return makeError(ErrorCode::BadInput, "notch: execution period must be positive");
    if (!(spec.centerHz > 0.0) || spec.centerHz >= nyquist) {
        return makeError(ErrorCode::OutOfRange, "notch centre " + std::to_string(spec.centerHz)
                                                    + " Hz must lie between 0 and the Nyquist frequency "
                                                    + std::to_string(nyquist) + " Hz of its execution rate");
    }
    if (!(spec.widthHz > 0.0))
        return makeError(ErrorCode::OutOfRange, "notch width must be positive");
    if (!(spec.depth >= 0.0 && spec.depth <= 1.0))
        return makeError(ErrorCode::OutOfRange, "notch depth must lie in [0, 1]");

    const double w0 = 2.0 * std::numbers::pi * spec.centerHz;
    const double zeta = spec.widthHz / (2.0 * spec.centerHz);
    // s = K (1 - z^-1)/(1 + z^-1) with K chosen so that the analogue w0 maps onto the digital w0.
    const double k = w0 / std::tan(w0 * periodS / 2.0);
    const double k2 = k * k, w02 = w0 * w0;
    const double bn1 = 2.0 * spec.depth * zeta * w0 * k;
    const double an1 = 2.0 * zeta * w0 * k;
    const double a0 = k2 + an1 + w02;
    return Biquad((k2 + bn1 + w02) / a0, 2.0 * (w02 - k2) / a0, (k2 - bn1 + w02) / a0, 2.0 * (w02 - k2) / a0,
                  (k2 - an1 + w02) / a0);
}

Result<Biquad> designLowPass(double cutoffHz, double periodS)
{
    const double nyquist = 0.5 / periodS;
    if (!(periodS > 0.0))
        return makeError(ErrorCode::BadInput, "low-pass: execution period must be positive");
    if (!(cutoffHz > 0.0) || cutoffHz >= nyquist) {
        return makeError(ErrorCode::OutOfRange, "low-pass cutoff " + std::to_string(cutoffHz)
                                                    + " Hz must lie between 0 and the Nyquist frequency "
                                                    + std::to_string(nyquist) + " Hz");
    }
    const double wc = 2.0 * std::numbers::pi * cutoffHz;
    const double k = wc / std::tan(wc * periodS / 2.0);
    // wc / (s + wc) with s = K (1 - z^-1)/(1 + z^-1)
    const double a0 = k + wc;
    return Biquad(wc / a0, wc / a0, 0.0, (wc - k) / a0, 0.0);
}

}  // namespace axistune::dsp

namespace axistune::dsp {

Result<Biquad> designNotchDigitalWidth(const NotchSpec& spec, double periodS)
{
    if (!(periodS > 0.0))
        return makeError(ErrorCode::BadInput, "notch: execution period must be positive");
    if (!(spec.centerHz > 0.0) || spec.centerHz >= 0.5 / periodS)
        return designNotch(spec, periodS);  // same refusal and message
    const double x = std::numbers::pi * spec.centerHz * periodS;
    NotchSpec corrected = spec;
    corrected.widthHz = spec.widthHz * x / (std::sin(x) * std::cos(x));
    return designNotch(corrected, periodS);
}

}  // namespace axistune::dsp

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Low-pass IIR design in second-order sections and zero-phase (forward-backward) filtering, for the
// off-line processing of recorded motion (docs/identification.md):
//  * Butterworth and Chebyshev type I low-pass of even order, analog prototype → bilinear transform
//    with pre-warping at the cutoff; each section's zeros at z = −1, unity DC gain per section
//    (Chebyshev: the overall DC gain is 10^(−ripple/20) for even orders, as in the usual definition);
//  * filtfiltSos: forward then backward through the sections, the signal extended at both ends by
//    odd reflection over 3·(2·sections + 1) samples, and each pass started from the steady state of
//    its first sample (the convention of scipy.signal.sosfiltfilt).

#include "core/model/Result.h"

#include <array>
#include <vector>

namespace axistune::dsp {

/// One section: y = (b0 + b1 z⁻¹ + b2 z⁻²)/(1 + a1 z⁻¹ + a2 z⁻²) x.
struct SosSection {
    std::array<double, 3> b{1.0, 0.0, 0.0};
    std::array<double, 2> a{0.0, 0.0}; ///< a1, a2 (a0 = 1)
};
using Sos = std::vector<SosSection>;

/// `order` even, 2..16; cutoff as a fraction of the Nyquist frequency, in (0, 1).
Result<Sos> butterworthLowPass(int order, double cutoffNyquist);
/// Chebyshev type I with `rippleDb` pass-band ripple; cutoff (end of the ripple band) as for Butterworth.
Result<Sos> chebyshev1LowPass(int order, double rippleDb, double cutoffNyquist);

/// Zero-phase filtering; BadInput when the signal is not longer than the padding 3·(2·sections+1).
Result<std::vector<double>> filtfiltSos(const Sos& sos, const std::vector<double>& x);

} // namespace axistune::dsp

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The plant of an axis in motion from the plant measured at standstill (docs/tuning.md "Friction at standstill").
//
// A small excitation may not make the axis slide: below the breakaway torque, Coulomb friction (and the pre-sliding
// of a real guide, or the sign smoothing of a simulated one) acts as a stiff damper, and the measured plant
// P = ω/T looks heavy and damped. A PI designed on it gets a gain that is far too high for the same axis in motion,
// where Coulomb friction is a constant torque and damps nothing. At low frequencies every mechanical plant is
// 1/P = J·jω + b (the inertias move together; the resonances add only through their own small damping), so
// b = Re(1/P) on the lowest lines is the damping the friction adds at standstill (plus the small viscous one), and
// P_s = 1/(1/P − b) = P/(1 − b·P) is the plant with it removed. The tuner keeps its margins on both.

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Result.h"

#include <complex>
#include <cstddef>

namespace axistune::autotune {

struct StandstillDamping {
    double bNmsPerRad = 0.0;  ///< median of Re(1/P) over the lines used [N·m·s/rad] (≥ 0)
    double inertiaKgm2 = 0.0; ///< median of Im(1/P)/ω over the same lines [kg·m²]
    std::size_t lines = 0;    ///< valid lines used
    double upToHz = 0.0;      ///< highest line used [Hz]
};

/// Lowest lines used: the valid lines up to this factor of the lowest valid line's frequency (at least 3 lines).
inline constexpr double kStandstillBandFactor = 3.0;

/// b and J of the lowest valid lines of a plant (torque → velocity). Refused with fewer than 3 valid lines, or when
/// Im(1/P) is not positive there (not the plant of an inertia: the FRF is not a plant, or the lines are noise).
Result<StandstillDamping> standstillDamping(const dsp::FrequencyResponse& plant);

/// P with the damping b removed: P / (1 − b·P).
inline std::complex<double> slidingPlant(std::complex<double> p, double b)
{
    return p / (1.0 - b * p);
}

} // namespace axistune::autotune

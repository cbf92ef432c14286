// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Injection-hold factor of a drive's frequency-response test (docs/frequency-response-sim.md,
// "Injection hold"). A disturbance d sampled at every current-loop tick (period h) is added to the
// velocity-controller output T_c, which is held over the velocity period N·h. A sine e^{jωt} held
// over N ticks has the fundamental (1/N)·Σ_{m<N} e^{−jωmh} relative to its value at the first tick,
// so d reaches the loop G times stronger than the held T_c would:
//     G(ω) = N / Σ_{m<N} e^{−jωmh}   (≈ e^{jω(N−1)h/2}; G = 1 for N = 1),
// and −T_c/d = G·PC/(1+PC). Dividing a measured −T_c/d by G gives the closed loop T = PC/(1+PC)
// (P: plant seen from the held torque command, C: velocity controller).

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Result.h"

#include <complex>

namespace axistune::dsp {

/// G = N / Σ_{m<N} e^{−j2πf·m·h} with N = ticksPerVelocity, h = currentPeriodS.
/// Returns 1 for N = 1; NaN+NaN·j for N < 1, h not positive/finite, f not finite, or where the sum
/// vanishes (f a nonzero multiple of 1/(N·h) not a multiple of 1/h).
std::complex<double> injectionHoldFactor(double fHz, double currentPeriodS, int ticksPerVelocity);

/// Divides every point of a measured −T_c/d by G (points where G is not finite become invalid) and
/// records the correction in the metadata: injection_hold_corrected=true,
/// injection_hold_period_s=h, injection_hold_ticks=N. BadInput when N < 1 or h is not positive, or
/// when the metadata already says injection_hold_corrected=true (never corrected twice).
Status correctInjectionHold(FrequencyResponse& frf, double currentPeriodS, int ticksPerVelocity);

/// True when the FRF's metadata says injection_hold_corrected=true.
bool isInjectionHoldCorrected(const FrequencyResponse& frf);

} // namespace axistune::dsp

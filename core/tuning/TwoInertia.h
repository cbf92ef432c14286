// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Two-inertia model of a feed axis (spec/lost-motion-and-two-inertia.md chapter 5, eqs. 5.1–5.11)
// and its fit to a measured torque → motor-velocity FRF (algorithm TI-1, §4.8).
//   P_m(s) = e^{−τs}/s · (J_L s² + C s + K) / (J_m J_L s² + C (J_m + J_L) s + K (J_m + J_L))
//   P_L(s) = e^{−τs}/s · (C s + K)          / (the same denominator)
// ω_0 = √(K/J_L) (anti-resonance, zero), ω_p = √(K (J_m + J_L)/(J_m J_L)) (resonance, pole);
// ζ_0 = C/(2 J_L ω_0) (zero) and ζ_p = C (J_m + J_L)/(J_m J_L)/(2 ω_p) (pole) are different numbers.

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Result.h"

#include <complex>

namespace axistune::tuning {

struct TwoInertiaParams {
    double jmKgm2 = 0.0;       ///< motor-side inertia J_m
    double jlKgm2 = 0.0;       ///< load inertia J_L
    double kNmPerRad = 0.0;    ///< spring constant K_m
    double cNmsPerRad = 0.0;   ///< damper constant C_m
    double delayS = 0.0;       ///< dead time of the measured transfer function (measurement path)
};

/// Torque → motor velocity P_m(j2πf), including the delay. [rad/s per N·m]
std::complex<double> motorVelocityResponse(const TwoInertiaParams& p, double fHz);
/// Torque → load velocity P_L(j2πf), including the delay.
std::complex<double> loadVelocityResponse(const TwoInertiaParams& p, double fHz);
/// Motor position → load position P_L/P_m (5.6); the delay cancels.
std::complex<double> motorToLoadResponse(const TwoInertiaParams& p, double fHz);

double antiresonanceRadS(const TwoInertiaParams& p);
double resonanceRadS(const TwoInertiaParams& p);
double zetaZero(const TwoInertiaParams& p);
double zetaPole(const TwoInertiaParams& p);

struct TwoInertiaFitOptions {
    double fminHz = 5.0;          ///< fit band (thesis: 5–300 Hz)
    double fmaxHz = 300.0;
    double minCoherence = 0.0;    ///< points with a defined coherence below this are not used
};

struct TwoInertiaFit {
    TwoInertiaParams params;
    TwoInertiaParams initial;     ///< start values from the resonance and anti-resonance in the data
    double fitError = 0.0;        ///< RMS of |H_model − H_meas|/|H_meas| over the points used
    int pointsUsed = 0;
    int iterations = 0;
    double dataAntiresonanceHz = 0.0;  ///< minimum of |H|·ω found in the data
    double dataResonanceHz = 0.0;      ///< maximum of |H|·ω above it
};

/// Weighted nonlinear least squares (Levenberg–Marquardt on the complex log ratio of model and data,
/// log-parameters for J_m, J_L, K, C and a linear delay), started from the data's resonance pair.
/// BadInput when the band holds too few points or no anti-resonance/resonance pair.
Result<TwoInertiaFit> fitTwoInertia(const dsp::FrequencyResponse& frf, const TwoInertiaFitOptions& options);

}  // namespace axistune::tuning

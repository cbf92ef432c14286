// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Position PID with velocity and acceleration feedforward for an axis whose position loop is closed by the NC
// (LinuxCNC's `pid` component; docs/linuxcnc.md "Tuning"), designed from a measured frequency response.
//
// The controller is LinuxCNC's discrete PID, exactly as `pid.N.do-pid-calcs` computes it each period T:
//   e_I += e·T;  e_D = (e − e_prev)/T;  out = P·e + I·e_I + D·e_D + FF1·ċmd + FF2·c̈md
// so C(z) = P + I·T/(1 − z⁻¹) + D·(1 − z⁻¹)/T from error to output.
//
// The design works on the effective plant P_eff = L/C: the open loop L = −(PID output)/(drive input) measured with
// the gains that were running, divided by their C(z). P_eff holds whatever the configuration adds around the PID
// (the drive, a period of delay or none, depending on where the feedback is read in the thread), so the new
// open loop C_new·P_eff is predicted without knowing the thread's function order.

#include "core/dsp/LoopAnalysis.h"
#include "core/model/Result.h"
#include "core/tuning/Resonance.h"

#include <complex>
#include <optional>
#include <string>
#include <vector>

namespace axistune::tuning {

struct PositionPid {
    double p = 0.0;   ///< output per unit of following error
    double i = 0.0;   ///< output per (error·s)
    double d = 0.0;   ///< output per (error/s)
    double ff1 = 0.0; ///< output per (command/s)
    double ff2 = 0.0; ///< output per (command/s²)
};

/// C(e^{j2πfT}) of the PID from error to output (feedforward not included).
std::complex<double> pidResponse(const PositionPid& pid, double periodS, double fHz);

/// P_eff = L / C_running at each line; lines where C_running is 0 are an error.
Result<std::vector<std::complex<double>>> effectivePlant(const std::vector<double>& freqHz,
                                                         const std::vector<std::complex<double>>& openLoop,
                                                         const PositionPid& running, double periodS);

/// LinuxCNC's `biquad` component with type 2, a notch: the second-order IIR notch of the audio-EQ cookbook (zero at
/// f0, bandwidth set by Q) that the component computes from f0 and Q on a rising edge of its enable pin. The component
/// accepts 0.5 ≤ Q ≤ 2 and f0 below half the servo rate.
struct BiquadNotch {
    double f0Hz = 0.0;
    double q = 1.0;
};
/// N(e^{j2πfT}) = (1 − 2cos w0·z⁻¹ + z⁻²) / ((1+α) − 2cos w0·z⁻¹ + (1−α)·z⁻²), w0 = 2π f0 T, α = sin w0 / (2Q).
std::complex<double> biquadNotchResponse(const BiquadNotch& notch, double periodS, double fHz);

/// What the PID output commands at the drive.
enum class DriveInput {
    Torque,   ///< torque or current: P_eff ~ 1/(J s²) at low frequency; PID with D, FF2 = J, FF1 = viscous
    Velocity, ///< velocity: P_eff ~ K/s at low frequency; P with a little I, FF1 = 1/K, no D, FF2 = 0
};

/// Reads the drive input type from the slope of |P_eff| over the lowest decade of the measured lines: about
/// −40 dB/decade is torque, about −20 dB/decade velocity. OutOfRange when the slope is neither (the user chooses).
Result<DriveInput> driveInputFromSlope(const std::vector<double>& freqHz,
                                       const std::vector<std::complex<double>>& plant);

struct PositionPidOptions {
    DriveInput input = DriveInput::Torque;
    double phaseMarginDeg = 50.0;   ///< target (issue 17 asks ≥ 45°)
    double gainMarginDb = 8.0;      ///< target (issue 17 asks ≥ 6 dB)
    double integralRatio = 0.2;     ///< integral corner ω_I = ratio·ω_c (torque) or ratio/2·ω_c (velocity)
    double feedforwardBandHz = 0.0; ///< upper end of the rigid-body fit for FF1/FF2; 0: the crossover
};

/// Margins of a position loop that may be conditionally stable (a PID with I on a double integrator has its phase
/// below −180° at low frequency, where |L| > 1).
struct PositionLoopMargins {
    double crossoverHz = 0.0;    ///< the gain crossover with the smallest phase margin
    double phaseMarginDeg = 0.0; ///< smallest over the gain crossovers
    double gainMarginDb =
        dsp::LoopMargins::kInf; ///< gain increase: smallest −20·log|L| over −180° crossings with |L| < 1
    double gainMarginFreqHz = 0.0;
    double reductionMarginDb =
        dsp::LoopMargins::kInf; ///< gain decrease: smallest 20·log|L| over −180° crossings with |L| > 1
};
PositionLoopMargins positionLoopMargins(const std::vector<double>& freqHz,
                                        const std::vector<std::complex<double>>& openLoop);

struct PositionPidDesign {
    PositionPid gains;
    double crossoverHz = 0.0;
    PositionLoopMargins predicted;              ///< of C_new·P_eff over the measured lines
    std::vector<std::complex<double>> openLoop; ///< predicted C_new·P_eff
    double inertia = 0.0;                       ///< rigid-body fit 1/P ≈ −J ω² + j b ω (torque) …
    double viscous = 0.0;                       ///< … its b; velocity drives: the gain K of P ≈ K/(jω)
    std::vector<std::string> rules;             ///< one sentence per number: which rule chose it
};

/// The strongest resonance of a measured plant above `aboveHz`: the line where |P|·ω² (torque drive: flat for the
/// rigid body) or |P|·ω (velocity drive) peaks, when that peak stands at least `minRiseDb` above the median of the
/// same quantity over the lines above `aboveHz`; nullopt when there is none (or fewer than 5 lines there).
std::optional<double> plantResonanceHz(const std::vector<double>& freqHz, const std::vector<std::complex<double>>& plant,
                                       DriveInput input, double aboveHz, double minRiseDb = 6.0);

/// plantResonanceHz with what a resonance table shows, on L(f) = 20·log10(|P|·ω^order) (order 2 torque, 1 velocity):
/// freqHz the peak line, levelDb L there, baselineDb the median of L over the lines above `aboveHz`, peakDb the rise
/// above it, widthHz between the lines where L first falls 3 dB below the peak on each side (twice the one half
/// found, widthOneSided, when the band ends first); nullopt as plantResonanceHz.
std::optional<Resonance> plantResonance(const std::vector<double>& freqHz,
                                        const std::vector<std::complex<double>>& plant, DriveInput input,
                                        double aboveHz, double minRiseDb = 6.0);

/// The highest crossover at which a PID meets both margins over every measured line. Errors: too few lines, a
/// non-finite line, no crossover that meets the margins (the reason says which margin failed where).
Result<PositionPidDesign> designPositionPid(const std::vector<double>& freqHz,
                                            const std::vector<std::complex<double>>& plant, double periodS,
                                            const PositionPidOptions& options = {});

} // namespace axistune::tuning

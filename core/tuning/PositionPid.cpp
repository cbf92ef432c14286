// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/tuning/PositionPid.h"

#include "core/model/Constants.h"
#include "core/model/Number.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

namespace axistune::tuning {
namespace {

using cd = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::string num(double v)
{
    return model::formatNumber(v, 4);
}

/// The PID shape c = C/P with ω_I = I/P and T_d = D/P.
cd pidShape(double omegaI, double td, double periodS, double fHz)
{
    const cd zInv = std::polar(1.0, -kTwoPi * fHz * periodS);
    return 1.0 + omegaI * periodS / (1.0 - zInv) + td * (1.0 - zInv) / periodS;
}

double argDeg(cd c)
{
    return std::arg(c) * model::kDegPerRad;
}

double wrapDeg(double a)
{
    while (a > 180.0)
        a -= 360.0;
    while (a <= -180.0)
        a += 360.0;
    return a;
}

/// The ω² and ω coefficients of 1/P ≈ (−a₂ω² + j·a₁ω)·e^{jωτ} on the given lines, τ the loop's delay: expanded in
/// ωτ, Re ≈ −a₂ω² + (a₂τ²/2)ω⁴ and Im ≈ a₁ω − (a₂τ + a₁τ²/2)ω³ + (a₂τ³/6)ω⁵, each fitted linearly by least squares.
struct RigidFit {
    double omega2 = 0.0, omega1 = 0.0;
};

RigidFit fitInverse(const std::vector<double>& freqHz, std::span<const cd> plant, const std::vector<std::size_t>& lines)
{
    const auto m = static_cast<Eigen::Index>(lines.size());
    Eigen::MatrixXd ar(m, 2), ai(m, 3);
    Eigen::VectorXd yr(m), yi(m);
    for (Eigen::Index r = 0; r < m; ++r) {
        const std::size_t k = lines[static_cast<std::size_t>(r)];
        const double w = kTwoPi * freqHz[k];
        const cd inv = 1.0 / plant[k];
        ar(r, 0) = -w * w, ar(r, 1) = w * w * w * w;
        ai(r, 0) = w, ai(r, 1) = -w * w * w, ai(r, 2) = w * w * w * w * w;
        yr(r) = inv.real(), yi(r) = inv.imag();
    }
    return {ar.colPivHouseholderQr().solve(yr)(0), ai.colPivHouseholderQr().solve(yi)(0)};
}

} // namespace

PositionLoopMargins positionLoopMargins(const std::vector<double>& freqHz,
                                        const std::vector<std::complex<double>>& openLoop)
{
    dsp::FrequencyResponse l;
    l.freqHz = freqHz;
    l.h = openLoop;
    l.coherence.assign(freqHz.size(), std::nan(""));
    l.valid.assign(freqHz.size(), true);
    const dsp::LoopMargins m = dsp::loopMargins(l);
    PositionLoopMargins r;
    r.phaseMarginDeg = m.phaseMarginDeg;
    r.crossoverHz = m.phaseMarginFreqHz;
    for (const auto& c : m.phaseCrossovers) {
        if (c.marginDb > 0.0 && c.marginDb < r.gainMarginDb) {
            r.gainMarginDb = c.marginDb;
            r.gainMarginFreqHz = c.freqHz;
        } else if (c.marginDb <= 0.0) {
            r.reductionMarginDb = std::min(r.reductionMarginDb, -c.marginDb);
        }
    }
    return r;
}

std::complex<double> pidResponse(const PositionPid& pid, double periodS, double fHz)
{
    const cd zInv = std::polar(1.0, -kTwoPi * fHz * periodS);
    return pid.p + pid.i * periodS / (1.0 - zInv) + pid.d * (1.0 - zInv) / periodS;
}

std::complex<double> biquadNotchResponse(const BiquadNotch& n, double periodS, double fHz)
{
    const double w0 = kTwoPi * n.f0Hz * periodS;
    const double alpha = std::sin(w0) / (2.0 * n.q);
    const cd z1 = std::polar(1.0, -kTwoPi * fHz * periodS);
    const cd z2 = z1 * z1;
    return (1.0 - 2.0 * std::cos(w0) * z1 + z2) / ((1.0 + alpha) - 2.0 * std::cos(w0) * z1 + (1.0 - alpha) * z2);
}

namespace {

/// |P|·ω² (torque) or |P|·ω (velocity) on the finite, positive lines above `aboveHz`.
void plantLevels(const std::vector<double>& freqHz, const std::vector<std::complex<double>>& plant, DriveInput input,
                 double aboveHz, std::vector<double>& f, std::vector<double>& v)
{
    for (std::size_t k = 0; k < freqHz.size() && k < plant.size(); ++k) {
        if (!(freqHz[k] > aboveHz))
            continue;
        const double w = kTwoPi * freqHz[k];
        const double x = std::abs(plant[k]) * (input == DriveInput::Torque ? w * w : w);
        if (!std::isfinite(x) || !(x > 0.0))
            continue;
        f.push_back(freqHz[k]);
        v.push_back(x);
    }
}

} // namespace

std::optional<double> plantResonanceHz(const std::vector<double>& freqHz,
                                       const std::vector<std::complex<double>>& plant, DriveInput input, double aboveHz,
                                       double minRiseDb)
{
    std::vector<double> f, v;
    plantLevels(freqHz, plant, input, aboveHz, f, v);
    if (v.size() < 5)
        return std::nullopt;
    std::vector<double> sorted = v;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
    const double median = sorted[sorted.size() / 2];
    const auto peak = std::max_element(v.begin(), v.end());
    if (!(20.0 * std::log10(*peak / median) >= minRiseDb))
        return std::nullopt;
    return f[static_cast<std::size_t>(peak - v.begin())];
}

std::optional<Resonance> plantResonance(const std::vector<double>& freqHz,
                                        const std::vector<std::complex<double>>& plant, DriveInput input,
                                        double aboveHz, double minRiseDb)
{
    const auto at = plantResonanceHz(freqHz, plant, input, aboveHz, minRiseDb);
    if (!at)
        return std::nullopt;
    std::vector<double> f, level;
    plantLevels(freqHz, plant, input, aboveHz, f, level);
    for (double& x : level)
        x = 20.0 * std::log10(x);
    const auto peak = static_cast<std::size_t>(std::find(f.begin(), f.end(), *at) - f.begin());
    std::vector<double> sorted = level;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
    Resonance r;
    r.freqHz = *at;
    r.levelDb = level[peak];
    r.baselineDb = sorted[sorted.size() / 2];
    r.peakDb = r.levelDb - r.baselineDb;
    r.index = peak;
    // The −3 dB points, interpolated linearly in f between the lines that bracket them.
    const double cut = r.levelDb - 3.0;
    std::optional<double> lo, hi;
    for (std::size_t k = peak; k-- > 0;)
        if (level[k] < cut) {
            lo = f[k] + (cut - level[k]) / (level[k + 1] - level[k]) * (f[k + 1] - f[k]);
            break;
        }
    for (std::size_t k = peak + 1; k < level.size(); ++k)
        if (level[k] < cut) {
            hi = f[k - 1] + (level[k - 1] - cut) / (level[k - 1] - level[k]) * (f[k] - f[k - 1]);
            break;
        }
    if (lo && hi) {
        r.widthHz = *hi - *lo;
    } else if (lo || hi) {
        r.widthHz = 2.0 * (lo ? r.freqHz - *lo : *hi - r.freqHz);
        r.widthOneSided = true;
    }
    return r;
}

Result<std::vector<std::complex<double>>> effectivePlant(const std::vector<double>& freqHz,
                                                         const std::vector<std::complex<double>>& openLoop,
                                                         const PositionPid& running, double periodS)
{
    if (freqHz.size() != openLoop.size())
        return makeError(ErrorCode::BadInput, "open loop: frequencies and responses differ in number");
    std::vector<cd> out(freqHz.size());
    for (std::size_t k = 0; k < freqHz.size(); ++k) {
        const cd c = pidResponse(running, periodS, freqHz[k]);
        if (std::abs(c) == 0.0 || !std::isfinite(std::abs(c)))
            return makeError(ErrorCode::BadInput, "the running PID has no gain at " + num(freqHz[k]) +
                                                      " Hz: the plant cannot be recovered from the open loop");
        out[k] = openLoop[k] / c;
    }
    return out;
}

Result<DriveInput> driveInputFromSlope(const std::vector<double>& freqHz,
                                       const std::vector<std::complex<double>>& plant)
{
    if (freqHz.size() != plant.size() || freqHz.size() < 3 || !(freqHz.front() > 0.0))
        return makeError(ErrorCode::BadInput, "too few lines to read the plant's slope");
    const double f0 = freqHz.front();
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    std::size_t n = 0;
    for (std::size_t k = 0; k < freqHz.size() && freqHz[k] <= 10.0 * f0; ++k) {
        const double m = std::abs(plant[k]);
        if (!(m > 0.0) || !std::isfinite(m))
            continue;
        const double x = std::log10(freqHz[k]), y = std::log10(m);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
        ++n;
    }
    if (n < 3 || sxx * static_cast<double>(n) - sx * sx <= 0.0)
        return makeError(ErrorCode::BadInput, "too few lines in the lowest decade to read the plant's slope");
    const double slope = (static_cast<double>(n) * sxy - sx * sy) / (static_cast<double>(n) * sxx - sx * sx);
    if (slope <= -1.5 && slope >= -2.5)
        return DriveInput::Torque;
    if (slope <= -0.6 && slope > -1.5)
        return DriveInput::Velocity;
    return makeError(ErrorCode::OutOfRange, "the plant falls by " + num(20.0 * slope) +
                                                " dB/decade at low frequency, neither about −40 (torque drive) nor "
                                                "about −20 (velocity drive): choose the drive input");
}

Result<PositionPidDesign> designPositionPid(const std::vector<double>& freqHz,
                                            const std::vector<std::complex<double>>& plant, double periodS,
                                            const PositionPidOptions& o)
{
    const std::size_t n = freqHz.size();
    if (n != plant.size() || n < 8)
        return makeError(ErrorCode::BadInput, "at least 8 measured lines are needed to design a PID");
    for (std::size_t k = 0; k < n; ++k)
        if (!std::isfinite(freqHz[k]) || !std::isfinite(plant[k].real()) || !std::isfinite(plant[k].imag()) ||
            std::abs(plant[k]) == 0.0 || (k > 0 && !(freqHz[k] > freqHz[k - 1])))
            return makeError(ErrorCode::BadInput,
                             "measured line " + std::to_string(k) + " (" + num(freqHz[k]) +
                                 " Hz) is not a finite, non-zero response at an increasing frequency");
    if (!(periodS > 0.0) || !(o.phaseMarginDeg > 0.0 && o.phaseMarginDeg < 90.0) || !(o.gainMarginDb > 0.0) ||
        !(o.integralRatio >= 0.0 && o.integralRatio < 1.0))
        return makeError(ErrorCode::OutOfRange,
                         "PID design options: period > 0, 0° < PM < 90°, GM > 0 dB, 0 ≤ integral ratio < 1");

    const bool torque = o.input == DriveInput::Torque;
    PositionPidDesign best;
    bool found = false;
    std::string lastReason = "no line";
    std::string refusedAbove; ///< why the first candidate above the chosen one failed
    std::size_t bestIndex = 0;
    // Candidates: every measured line from the third on, up to the half of the measured band.
    for (std::size_t c = 2; c < n; ++c) {
        const double fc = freqHz[c];
        if (fc > 0.5 * freqHz.back())
            break;
        if (found && refusedAbove.empty() && c > bestIndex + 1)
            refusedAbove = lastReason; // the candidate right after the accepted one failed for this reason
        const double wc = kTwoPi * fc;
        const double ratio = torque ? o.integralRatio : 0.5 * o.integralRatio;
        const double omegaI = ratio * wc;
        double td = 0.0;
        if (torque) {
            const double want = wrapDeg(-180.0 + o.phaseMarginDeg - argDeg(plant[c]));
            const double lo = argDeg(pidShape(omegaI, 0.0, periodS, fc));
            const double hiTd = 1e3 / wc;
            const double hi = argDeg(pidShape(omegaI, hiTd, periodS, fc));
            if (want < lo || want > hi) {
                lastReason = "at " + num(fc) + " Hz a PID cannot give the phase the margin needs";
                continue;
            }
            double a = 0.0, b = hiTd;
            for (int it = 0; it < 200; ++it) {
                const double m = 0.5 * (a + b);
                (argDeg(pidShape(omegaI, m, periodS, fc)) < want ? a : b) = m;
            }
            td = 0.5 * (a + b);
        }
        const double kp = 1.0 / (std::abs(plant[c]) * std::abs(pidShape(omegaI, td, periodS, fc)));
        PositionPid g{kp, kp * omegaI, kp * td, 0.0, 0.0};
        std::vector<cd> loop(n);
        for (std::size_t k = 0; k < n; ++k)
            loop[k] = pidResponse(g, periodS, freqHz[k]) * plant[k];
        const PositionLoopMargins m = positionLoopMargins(freqHz, loop);
        // Beyond the measured band nothing is known: the loop must be below the gain margin there already, and
        // cross 0 dB once (a crossover in an anti-resonance dip leaves |L| > 1 on both sides of it).
        const double tailDb = 20.0 * std::log10(std::abs(loop.back()));
        if (tailDb > -o.gainMarginDb) {
            lastReason = "at " + num(fc) + " Hz the loop would still have " + num(tailDb) +
                         " dB at the end of the measured band (" + num(freqHz.back()) + " Hz)";
            continue;
        }
        std::size_t crossings = 0;
        for (std::size_t k = 1; k < n; ++k)
            if ((std::abs(loop[k - 1]) >= 1.0) != (std::abs(loop[k]) >= 1.0))
                ++crossings;
        if (crossings != 1) {
            lastReason = "at " + num(fc) + " Hz the loop would cross 0 dB " + std::to_string(crossings) + " times";
            continue;
        }
        if (m.phaseMarginDeg < o.phaseMarginDeg - 0.5) {
            lastReason = "at " + num(fc) + " Hz the phase margin would be " + num(m.phaseMarginDeg) + "° (crossover " +
                         num(m.crossoverHz) + " Hz)";
            continue;
        }
        if (m.gainMarginDb < o.gainMarginDb) {
            lastReason = "at " + num(fc) + " Hz the gain margin would be " + num(m.gainMarginDb) + " dB at " +
                         num(m.gainMarginFreqHz) + " Hz";
            continue;
        }
        if (m.reductionMarginDb < o.gainMarginDb) {
            lastReason =
                "at " + num(fc) + " Hz a gain " + num(m.reductionMarginDb) + " dB lower would make the loop unstable";
            continue;
        }
        best.gains = g;
        best.crossoverHz = fc;
        best.predicted = m;
        best.openLoop = std::move(loop);
        found = true;
        bestIndex = c;
        refusedAbove.clear();
    }
    if (!found)
        return makeError(ErrorCode::OutOfRange, "no crossover meets PM ≥ " + num(o.phaseMarginDeg) + "° and GM ≥ " +
                                                    num(o.gainMarginDb) + " dB over the measured " +
                                                    num(freqHz.front()) + "–" + num(freqHz.back()) +
                                                    " Hz (last: " + lastReason + ")");

    if (refusedAbove.empty() && bestIndex + 1 < n && freqHz[bestIndex + 1] <= 0.5 * freqHz.back())
        refusedAbove = lastReason;
    const std::string band = num(freqHz.front()) + "–" + num(freqHz.back()) + " Hz";
    best.rules.push_back(
        "crossover " + num(best.crossoverHz) + " Hz: the highest measured line at which the PID meets PM ≥ " +
        num(o.phaseMarginDeg) + "° and GM ≥ " + num(o.gainMarginDb) + " dB on every measured line (" + band +
        "), crossing 0 dB once and at least " + num(o.gainMarginDb) + " dB below it at the end of the band" +
        (refusedAbove.empty() ? std::string{} : "; the next line up was refused: " + refusedAbove));
    best.rules.push_back("P = " + num(best.gains.p) + ": |C·P_eff| = 1 at the crossover");
    best.rules.push_back("I = " + num(best.gains.i) + ": integral corner at " +
                         num(torque ? o.integralRatio : 0.5 * o.integralRatio) + " × the crossover (I = P·ω_I)");
    best.rules.push_back(torque ? "D = " + num(best.gains.d) +
                                      ": the phase lead that gives PM = " + num(o.phaseMarginDeg) + "° at the crossover"
                                : "D = 0: a velocity drive needs no derivative in the position loop");

    // Feedforward from the rigid-body part of the plant below the feedforward band.
    const double ffBand = o.feedforwardBandHz > 0.0 ? o.feedforwardBandHz : best.crossoverHz;
    std::vector<std::size_t> ffLines;
    for (std::size_t k = 0; k < n && freqHz[k] <= ffBand; ++k)
        ffLines.push_back(k);
    if (ffLines.size() < (torque ? 4u : 2u)) {
        best.rules.push_back("FF1 = FF2 = 0: too few measured lines below " + num(ffBand) +
                             " Hz to fit the rigid body");
    } else if (torque) {
        const RigidFit fit = fitInverse(freqHz, plant, ffLines);
        best.inertia = fit.omega2;
        best.viscous = fit.omega1;
        const std::string how = "1/P ≈ (−Jω² + jbω)·e^{jωτ} (τ the loop's delay) fitted on " +
                                std::to_string(ffLines.size()) + " lines up to " + num(ffBand) + " Hz";
        if (best.inertia > 0.0) {
            best.gains.ff2 = best.inertia;
            best.rules.push_back("FF2 = " + num(best.gains.ff2) + ": the inertia J of " + how);
        } else {
            best.rules.push_back("FF2 = 0: the rigid-body fit gave no positive inertia");
        }
        if (best.viscous > 0.0) {
            best.gains.ff1 = best.viscous;
            best.rules.push_back("FF1 = " + num(best.gains.ff1) + ": the viscous friction b of the same fit");
        } else {
            best.rules.push_back("FF1 = 0: the fit gave no positive viscous friction");
        }
    } else if (ffLines.size() >= 4u) {
        // A velocity drive with its own velocity loop, a lag T, and the loop's delay τ: P ≈ K/(jω(1 + jωT))·e^{−jωτ},
        // so 1/P ≈ (jω/K − ω²T/K)·e^{jωτ}: the torque case's fit with b = 1/K (and J = T/K). Averaging |P|·ω instead
        // would read K low by the lag's 1/√(1 + (ωT)²) near the crossover.
        const RigidFit fit = fitInverse(freqHz, plant, ffLines);
        if (fit.omega1 > 0.0) {
            best.viscous = 1.0 / fit.omega1; // K of P ≈ K/(jω)
            best.gains.ff1 = fit.omega1;
            best.rules.push_back("FF1 = " + num(best.gains.ff1) +
                                 ": 1/K of P ≈ K/(jω(1 + jωT))·e^{−jωτ} (T the drive's velocity-loop lag, τ the loop's "
                                 "delay) fitted on " +
                                 std::to_string(ffLines.size()) + " lines up to " + num(ffBand) + " Hz");
        } else {
            best.rules.push_back("FF1 = 0: the fit gave no positive 1/K");
        }
        best.rules.push_back("FF2 = 0: a velocity drive follows the velocity command itself");
    } else {
        double sum = 0.0;
        for (std::size_t k : ffLines)
            sum += std::abs(plant[k]) * kTwoPi * freqHz[k];
        best.viscous = sum / static_cast<double>(ffLines.size()); // K of P ≈ K/(jω)
        best.gains.ff1 = 1.0 / best.viscous;
        best.rules.push_back("FF1 = " + num(best.gains.ff1) + ": 1/K of P ≈ K/(jω) averaged over " +
                             std::to_string(ffLines.size()) + " lines up to " + num(ffBand) + " Hz");
        best.rules.push_back("FF2 = 0: a velocity drive follows the velocity command itself");
    }
    return best;
}

} // namespace axistune::tuning

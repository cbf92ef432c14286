// SPDX-License-Identifier: GPL-3.0-or-later
// Velocity PI (corrected (5.13), spec/lost-motion-and-two-inertia.md §2.8 and TI-5 §4.12), loop
// margins on sampled frequency responses, PI from target margins on a measured FRF, and the
// position-gain stability limit on the fitted two-inertia model (§2.11 [DERIVED] limits, §4.11).
#include "core/tuning/VelocityLoop.h"

#include "core/model/Constants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace axistune::tuning {

namespace {

using model::kDegPerRad;
using model::kTwoPi;

std::vector<double> unwrappedPhase(const std::vector<std::complex<double>>& h)
{
    std::vector<double> ph(h.size());
    double offset = 0.0;
    for (std::size_t i = 0; i < h.size(); ++i) {
        const double p = std::arg(h[i]);
        if (i > 0) {
            while (p + offset - ph[i - 1] > std::numbers::pi) offset -= kTwoPi;
            while (p + offset - ph[i - 1] < -std::numbers::pi) offset += kTwoPi;
        }
        ph[i] = p + offset;
    }
    return ph;
}

double wrapDeg(double d)
{
    d = std::fmod(d + 180.0, 360.0);
    if (d <= 0.0) {
        d += 360.0;
    }
    return d - 180.0;
}

}  // namespace

VelocityPi velocityPiFromInertia(double jm, double wl, double k)
{
    return VelocityPi{k * std::sqrt(2.0) * wl * jm, k * wl * wl * jm};
}

std::complex<double> piResponse(const VelocityPi& pi, double fHz)
{
    return pi.kpNmsPerRad + pi.kiNmPerRad / std::complex<double>(0.0, kTwoPi * fHz);
}

LoopMargins loopMargins(const std::vector<double>& f, const std::vector<std::complex<double>>& L)
{
    LoopMargins m;
    m.gainMarginDb = std::numeric_limits<double>::infinity();
    if (f.size() < 2 || f.size() != L.size()) {
        return m;
    }
    const auto ph = unwrappedPhase(L);
    double peakS = 0.0;
    double minGm = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < f.size(); ++i) {
        peakS = std::max(peakS, 1.0 / std::abs(1.0 + L[i]));
        if (i == 0) {
            continue;
        }
        const double g0 = std::log(std::abs(L[i - 1]));
        const double g1 = std::log(std::abs(L[i]));
        const double lf0 = std::log(f[i - 1]);
        const double lf1 = std::log(f[i]);
        if ((g0 >= 0.0) != (g1 >= 0.0)) {  // gain crossover; keep the highest one
            const double t = g0 / (g0 - g1);
            m.crossoverHz = std::exp(lf0 + t * (lf1 - lf0));
            m.phaseMarginDeg = wrapDeg((ph[i - 1] + t * (ph[i] - ph[i - 1])) * kDegPerRad + 180.0);
        }
        const double im0 = L[i - 1].imag();
        const double im1 = L[i].imag();
        if ((im0 >= 0.0) != (im1 >= 0.0)) {
            const double t = im0 / (im0 - im1);
            const std::complex<double> Lc = L[i - 1] + t * (L[i] - L[i - 1]);
            if (Lc.real() < 0.0) {
                const double gm = -20.0 * std::log10(std::abs(Lc));
                if (gm < minGm) {
                    minGm = gm;
                    m.phaseCrossoverHz = std::exp(lf0 + t * (lf1 - lf0));
                }
            }
        }
    }
    m.gainMarginDb = minGm;
    m.peakSensitivityDb = 20.0 * std::log10(peakS);
    return m;
}

Result<VelocityPi> velocityPiFromFrf(const dsp::FrequencyResponse& plant, double fc, double pmDeg)
{
    std::vector<double> f;
    std::vector<std::complex<double>> h;
    for (std::size_t i = 0; i < plant.size(); ++i) {
        const bool valid = i < plant.valid.size() ? plant.valid[i] : true;
        if (valid && plant.freqHz[i] > 0.0 && std::abs(plant.h[i]) > 0.0 && std::isfinite(std::abs(plant.h[i]))) {
            f.push_back(plant.freqHz[i]);
            h.push_back(plant.h[i]);
        }
    }
    if (f.size() < 2 || !(fc >= f.front()) || !(fc <= f.back())) {
        return makeError(ErrorCode::OutOfRange, "crossover " + std::to_string(fc) +
                                                    " Hz is outside the valid band of the measured FRF");
    }
    if (!(pmDeg > 0.0) || pmDeg >= 180.0) {
        return makeError(ErrorCode::OutOfRange, "phase margin must be in (0, 180) deg");
    }
    const auto ph = unwrappedPhase(h);
    const auto it = std::upper_bound(f.begin(), f.end(), fc);
    const std::size_t i1 = std::min<std::size_t>(static_cast<std::size_t>(it - f.begin()), f.size() - 1);
    const std::size_t i0 = i1 - 1;
    const double t = (std::log(fc) - std::log(f[i0])) / (std::log(f[i1]) - std::log(f[i0]));
    const double mag = std::exp(std::log(std::abs(h[i0])) + t * (std::log(std::abs(h[i1])) - std::log(std::abs(h[i0]))));
    const double phase = (ph[i0] + t * (ph[i1] - ph[i0])) * kDegPerRad;
    const double d = wrapDeg(-180.0 + pmDeg - phase);  // phase the PI must contribute
    if (d > 0.0 || d <= -89.0) {
        return makeError(ErrorCode::OutOfRange, "a PI cannot give " + std::to_string(pmDeg) + " deg phase margin at " +
                                                    std::to_string(fc) + " Hz: it would need " + std::to_string(d) +
                                                    " deg (a PI gives 0 … −90 deg)");
    }
    const double dRad = d / kDegPerRad;
    VelocityPi pi;
    pi.kpNmsPerRad = std::cos(dRad) / mag;
    pi.kiNmPerRad = pi.kpNmsPerRad * kTwoPi * fc * std::tan(-dRad);
    return pi;
}

PositionGainDesign positionGain(const TwoInertiaParams& p, const VelocityPi& pi, FeedbackMode mode,
                                const std::optional<SuppressionFilter>& filter, bool includeDelay, double gmDb)
{
    TwoInertiaParams plant = p;
    if (!includeDelay) {
        plant.delayS = 0.0;
    }
    constexpr int kPoints = 20000;
    std::vector<double> f(kPoints);
    std::vector<std::complex<double>> vel(kPoints);
    std::vector<std::complex<double>> G(kPoints);
    for (int i = 0; i < kPoints; ++i) {
        f[i] = 0.1 * std::pow(10.0, 5.3 * i / (kPoints - 1.0));  // 0.1 Hz … 20 kHz
        const auto pm = motorVelocityResponse(plant, f[i]);
        vel[i] = piResponse(pi, f[i]) * pm;
        const auto T = vel[i] / (1.0 + vel[i]);
        auto g = T / std::complex<double>(0.0, kTwoPi * f[i]);
        if (mode == FeedbackMode::Full) {
            g *= motorToLoadResponse(p, f[i]);
        }
        if (filter) {
            g *= suppressionFilterResponse(*filter, f[i]);
        }
        G[i] = g;
    }
    PositionGainDesign d;
    d.limitPerS = std::numeric_limits<double>::infinity();
    const LoopMargins m = loopMargins(f, G);
    if (std::isfinite(m.gainMarginDb)) {
        const double lim = std::pow(10.0, m.gainMarginDb / 20.0);  // K with |K G| = 1 at the crossing
        if (lim < 1e5) {
            d.limitPerS = lim;
            d.limitFrequencyHz = m.phaseCrossoverHz;
        }
    }
    const LoopMargins v = loopMargins(f, vel);
    const double bwLimit = v.crossoverHz > 0.0 ? kTwoPi * v.crossoverHz / 5.0 : std::numeric_limits<double>::infinity();
    d.recommendedPerS = std::min(d.limitPerS * std::pow(10.0, -gmDb / 20.0), bwLimit);
    return d;
}

}  // namespace axistune::tuning

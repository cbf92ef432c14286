// SPDX-License-Identifier: GPL-3.0-or-later
// Two-inertia transfer functions, spec/lost-motion-and-two-inertia.md §2.2 (5.1)–(5.5), §2.5 (5.6)
// and the damping of the zero and of the pole (§2.7 [DERIVED], Table 5.1 "damping factor" = ζ_p).
#include "core/tuning/TwoInertia.h"

#include <cmath>
#include <numbers>

namespace axistune::tuning {

namespace {

std::complex<double> jw(double fHz) { return {0.0, 2.0 * std::numbers::pi * fHz}; }

std::complex<double> denominator(const TwoInertiaParams& p, std::complex<double> s)
{
    const double jsum = p.jmKgm2 + p.jlKgm2;
    return p.jmKgm2 * p.jlKgm2 * s * s + p.cNmsPerRad * jsum * s + p.kNmPerRad * jsum;
}

}  // namespace

std::complex<double> motorVelocityResponse(const TwoInertiaParams& p, double fHz)
{
    const auto s = jw(fHz);
    const auto num = p.jlKgm2 * s * s + p.cNmsPerRad * s + p.kNmPerRad;
    return std::exp(-s * p.delayS) * num / (s * denominator(p, s));
}

std::complex<double> loadVelocityResponse(const TwoInertiaParams& p, double fHz)
{
    const auto s = jw(fHz);
    const auto num = p.cNmsPerRad * s + p.kNmPerRad;
    return std::exp(-s * p.delayS) * num / (s * denominator(p, s));
}

std::complex<double> motorToLoadResponse(const TwoInertiaParams& p, double fHz)
{
    const auto s = jw(fHz);
    return (p.cNmsPerRad * s + p.kNmPerRad) / (p.jlKgm2 * s * s + p.cNmsPerRad * s + p.kNmPerRad);
}

double antiresonanceRadS(const TwoInertiaParams& p) { return std::sqrt(p.kNmPerRad / p.jlKgm2); }

double resonanceRadS(const TwoInertiaParams& p)
{
    return std::sqrt(p.kNmPerRad * (p.jmKgm2 + p.jlKgm2) / (p.jmKgm2 * p.jlKgm2));
}

double zetaZero(const TwoInertiaParams& p) { return p.cNmsPerRad / (2.0 * p.jlKgm2 * antiresonanceRadS(p)); }

double zetaPole(const TwoInertiaParams& p)
{
    return p.cNmsPerRad * (p.jmKgm2 + p.jlKgm2) / (p.jmKgm2 * p.jlKgm2) / (2.0 * resonanceRadS(p));
}

}  // namespace axistune::tuning

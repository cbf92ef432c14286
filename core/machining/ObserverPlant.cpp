// SPDX-License-Identifier: GPL-3.0-or-later
// Two-inertia plant P_n(s) of seed 003, spec/cutting-force-observer-and-chatter-detection.md §1.2 (reconstructed
// transfer function from the model equations) with the Table 1 values.
#include "core/machining/ObserverPlant.h"

#include <numbers>

namespace axistune::machining {

ObserverPlant ObserverPlant::table1()
{
    ObserverPlant p;
    p.torqueConstantNmPerA = 0.5710;
    p.motorInertia = 0.0028;
    p.loadInertia = 0.0032;
    p.motorViscous = 0.002;
    p.loadViscous = 0.002;
    p.stiffnessNmPerRad = 24000.0;
    return p;
}

std::complex<double> ObserverPlant::response(double fHz) const
{
    const std::complex<double> s(0.0, 2.0 * std::numbers::pi * fHz);
    const double jm = motorInertia, jl = loadInertia, bm = motorViscous, bl = loadViscous, k = stiffnessNmPerRad;
    const std::complex<double> num = torqueConstantNmPerA * (jl * s * s + bl * s + k);
    const std::complex<double> den =
        jm * jl * s * s * s + (jm * bl + jl * bm) * s * s + (k * (jm + jl) + bm * bl) * s + k * (bm + bl);
    return num / den;
}

} // namespace axistune::machining

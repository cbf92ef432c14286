// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The zero-order (Altintas–Budak) stability limit, computed independently of core/machining for the tests:
// the time-averaged cutting matrix K0 (midpoint quadrature of eq. (1-6)), the eigenvalues Λ of K0·G(jω_c)
// for a direct compliance G (the same in x and y, no cross terms), a_lim = |−1/Λ|/(2 sin(ψ/2)) with
// ψ = ω_c τ = π − 2 arg(−1/Λ) + 2πm (spec/chatter-stability-and-spindle-speed.md §6.1 "cross-check option").
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <functional>
#include <numbers>

namespace axistune::testing {

/// Mean over one spindle revolution of Σ_j g_j M(φ_j) for entry/exit angles st, en: midpoint rule on the
/// spec's element formulas.
inline Eigen::Matrix2d meanCuttingMatrix(int teeth, double kt, double kr, double st, double en)
{
    const int n = 200000;
    Eigen::Matrix2d sum = Eigen::Matrix2d::Zero();
    for (int i = 0; i < n; ++i) {
        const double p = st + (en - st) * (i + 0.5) / n;
        const double s = std::sin(p), c = std::cos(p);
        Eigen::Matrix2d m;
        m << (kt * c + kr * s) * s, (kt * c + kr * s) * c, (-kt * s + kr * c) * s, (-kt * s + kr * c) * c;
        sum += m;
    }
    // each tooth spends (en − st)/(2π) of the revolution in the cut
    return sum / n * (en - st) / (2.0 * std::numbers::pi) * teeth;
}

struct ZoaBottom {
    double depthM = 1e9;
    double omegaC = 0.0;
    double psi = 0.0;
};

/// Smallest zero-order limit depth over the chatter frequencies ω visited by `sweep` (it calls the visitor
/// with each ω [rad/s] and G(jω) [m/N]).
inline ZoaBottom zoaMinimum(const std::function<void(const std::function<void(double, std::complex<double>)>&)>& sweep,
                            const Eigen::Matrix2d& k0)
{
    ZoaBottom best;
    sweep([&](double w, std::complex<double> g) {
        Eigen::ComplexEigenSolver<Eigen::Matrix2cd> es(k0.cast<std::complex<double>>() * g);
        for (int e = 0; e < 2; ++e) {
            const std::complex<double> target = -1.0 / es.eigenvalues()(e);
            if (target.real() <= 0.0)
                continue;
            const double psi = std::numbers::pi - 2.0 * std::arg(target);
            const double a = std::abs(target) / (2.0 * std::sin(0.5 * psi));
            if (a < best.depthM)
                best = {a, w, psi};
        }
    });
    return best;
}

} // namespace axistune::testing

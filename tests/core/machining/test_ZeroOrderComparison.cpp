// SPDX-License-Identifier: GPL-3.0-or-later
// The SDM lobes against the zero-order (Altintas–Budak) analytic solution, computed here independently:
// the time-averaged cutting matrix K0 (midpoint quadrature of eq. (1-6)), the eigenvalues Λ of K0·G(jω_c),
// a_lim = 1/(|Λ|·2 sin(ψ/2)) with ψ = ω_c τ = π − 2 arg(−1/Λ) + 2πm (spec §6.1 "cross-check option").
// Valid where K_f(t) stays close to its mean: full slotting with four teeth, single-mode tool.
#include "core/machining/StabilityLobes.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <complex>
#include <numbers>

using namespace axistune::machining;

namespace {

constexpr double kPi = std::numbers::pi;

// Mean over one spindle revolution of Σ_j g_j M(φ_j), midpoint rule on the spec's element formulas.
Eigen::Matrix2d meanCuttingMatrix(int teeth, double kt, double kr, double st, double en)
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
    return sum / n * (en - st) / (2.0 * kPi) * teeth;
}

struct ZoaBottom {
    double depthM;
    double omegaC;
    double psi;
};

ZoaBottom zoaMinimum(const ModalParameters& m, const Eigen::Matrix2d& k0)
{
    ZoaBottom best{1e9, 0.0, 0.0};
    const double wn = std::sqrt(m.stiffnessNPerM / m.massKg);
    for (double w = 0.9 * wn; w < 1.2 * wn; w += 1e-5 * wn) {
        const std::complex<double> g = 1.0 / std::complex<double>(m.stiffnessNPerM - m.massKg * w * w, m.dampingNsPerM * w);
        Eigen::ComplexEigenSolver<Eigen::Matrix2cd> es(k0.cast<std::complex<double>>() * g);
        for (int e = 0; e < 2; ++e) {
            const std::complex<double> target = -1.0 / es.eigenvalues()(e);
            if (target.real() <= 0.0)
                continue;
            const double psi = kPi - 2.0 * std::arg(target);
            const double a = std::abs(target) / (2.0 * std::sin(0.5 * psi));
            if (a < best.depthM)
                best = {a, w, psi};
        }
    }
    return best;
}

}  // namespace

TEST(ZeroOrderComparison, SlottingLobeBottomsAgreeWithSdm)
{
    const ModalParameters m{0.40, 83.0, 30.1e6};
    const ToolModes tool{{m}, {m}};
    CuttingConditions cut;
    cut.teeth = 4;
    cut.ktNPerM2 = 0.980e9;
    cut.krNPerM2 = 0.294e9;
    cut.radialImmersion = 1.0;
    cut.milling = MillingDirection::Down;
    const auto k0 = meanCuttingMatrix(4, cut.ktNPerM2, cut.krNPerM2, 0.0, kPi);
    const auto bottom = zoaMinimum(m, k0);
    LobeOptions opt;
    opt.stepsPerPeriod = 120;
    for (int lobe = 1; lobe <= 4; ++lobe) {
        const double tau = (bottom.psi + 2.0 * kPi * lobe) / bottom.omegaC;
        const double rpm = 60.0 / (cut.teeth * tau);
        auto sdm = limitDepth(tool, cut, rpm, opt);
        ASSERT_TRUE(sdm.ok());
        // ZOA neglects the harmonics of K_f(t); at full immersion with 4 teeth they are small: 2 %.
        EXPECT_NEAR(*sdm, bottom.depthM, 0.02 * bottom.depthM) << "lobe " << lobe << " at " << rpm << " rpm";
    }
}

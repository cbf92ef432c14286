// SPDX-License-Identifier: GPL-3.0-or-later
// The SDM lobes against the zero-order (Altintas–Budak) analytic solution, computed here independently:
// the time-averaged cutting matrix K0 (midpoint quadrature of eq. (1-6)), the eigenvalues Λ of K0·G(jω_c),
// a_lim = 1/(|Λ|·2 sin(ψ/2)) with ψ = ω_c τ = π − 2 arg(−1/Λ) + 2πm (spec §6.1 "cross-check option").
// Valid where K_f(t) stays close to its mean: full slotting with four teeth, single-mode tool.
#include "core/machining/StabilityLobes.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <gtest/gtest.h>
#include <numbers>

#include "tests/core/machining/ZeroOrderReference.h"

using namespace axistune::machining;

namespace {

constexpr double kPi = std::numbers::pi;
using axistune::testing::meanCuttingMatrix;
using axistune::testing::ZoaBottom;

ZoaBottom zoaMinimum(const ModalParameters& m, const Eigen::Matrix2d& k0)
{
    const double wn = std::sqrt(m.stiffnessNPerM / m.massKg);
    return axistune::testing::zoaMinimum(
        [&](const auto& visit) {
            for (double w = 0.9 * wn; w < 1.2 * wn; w += 1e-5 * wn)
                visit(w, 1.0 / std::complex<double>(m.stiffnessNPerM - m.massKg * w * w, m.dampingNsPerM * w));
        },
        k0);
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

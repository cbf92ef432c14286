// SPDX-License-Identifier: GPL-3.0-or-later
// Tool modes and the specific cutting force matrix K_f(t) of 2-DOF milling,
// spec/chatter-stability-and-spindle-speed.md §1.3 (eq. (1-6) expanded, (1-8), (1-9)).
// The interval average of K_f used by the semi-discretization (eq. (3-9)) is computed in closed form
// instead of the reference's 20-point quadrature.
#include "core/machining/ToolModel.h"

#include "core/model/Constants.h"

#include <cmath>
#include <numbers>
#include <string>

namespace axistune::machining {

namespace {

Status checkModes(const std::vector<ModalParameters>& modes, const char* key)
{
    for (std::size_t i = 0; i < modes.size(); ++i) {
        const auto& m = modes[i];
        const std::string where = std::string(key) + "[" + std::to_string(i) + "]";
        // A mode with mass, damping and stiffness all negative is a negative residue (the second term of a
        // product of two resonances, e.g. the thesis's cascade (5-1)); its pole is the same as with all positive.
        if (!std::isfinite(m.massKg) || m.massKg == 0.0)
            return makeError(ErrorCode::OutOfRange, where + ".mass_kg must be non-zero (got " +
                                                        std::to_string(m.massKg) +
                                                        "; > 0, or < 0 with negative damping and stiffness)");
        const double sign = m.massKg > 0.0 ? 1.0 : -1.0;
        if (!std::isfinite(m.dampingNsPerM) || sign * m.dampingNsPerM < 0.0)
            return makeError(ErrorCode::OutOfRange, where + ".damping_Ns_per_m must have the sign of mass_kg (got " +
                                                        std::to_string(m.dampingNsPerM) + ")");
        if (!std::isfinite(m.stiffnessNPerM) || sign * m.stiffnessNPerM <= 0.0)
            return makeError(ErrorCode::OutOfRange, where +
                                                        ".stiffness_N_per_m must be non-zero with the sign of "
                                                        "mass_kg (got " +
                                                        std::to_string(m.stiffnessNPerM) + ")");
    }
    return Status::success();
}

// Antiderivatives of sin·cos, sin², cos².
struct Prim {
    double sc, ss, cc;
};
Prim prim(double p)
{
    const double s = std::sin(p);
    return {0.5 * s * s, 0.5 * p - 0.25 * std::sin(2.0 * p), 0.5 * p + 0.25 * std::sin(2.0 * p)};
}

} // namespace

Status validateTool(const ToolModes& tool)
{
    if (tool.modesX.empty() && tool.modesY.empty())
        return makeError(ErrorCode::BadInput,
                         "modes_x, modes_y: at least one mode is required (an empty list is a rigid direction)");
    if (auto s = checkModes(tool.modesX, "modes_x"); !s)
        return s;
    return checkModes(tool.modesY, "modes_y");
}

Status validateCut(const CuttingConditions& cut)
{
    if (cut.teeth < 1 || cut.teeth > 100)
        return makeError(ErrorCode::OutOfRange,
                         "teeth must be between 1 and 100 (got " + std::to_string(cut.teeth) + ")");
    if (!std::isfinite(cut.ktNPerM2) || cut.ktNPerM2 <= 0.0)
        return makeError(ErrorCode::OutOfRange, "Kt_N_per_m2 must be > 0 (got " + std::to_string(cut.ktNPerM2) + ")");
    if (!std::isfinite(cut.krNPerM2) || cut.krNPerM2 < 0.0)
        return makeError(ErrorCode::OutOfRange, "Kr_N_per_m2 must be >= 0 (got " + std::to_string(cut.krNPerM2) + ")");
    if (!std::isfinite(cut.radialImmersion) || cut.radialImmersion <= 0.0 || cut.radialImmersion > 1.0)
        return makeError(ErrorCode::OutOfRange,
                         "radial_immersion must be in (0, 1] (got " + std::to_string(cut.radialImmersion) + ")");
    return Status::success();
}

double naturalFrequencyHz(const ModalParameters& m)
{
    return std::sqrt(m.stiffnessNPerM / m.massKg) / (2.0 * std::numbers::pi);
}

double dampingRatio(const ModalParameters& m)
{
    return std::abs(m.dampingNsPerM) / (2.0 * std::sqrt(m.stiffnessNPerM * m.massKg)); // also a negative residue
}

std::complex<double> compliance(const std::vector<ModalParameters>& modes, double omegaRadS)
{
    std::complex<double> g = 0.0;
    for (const auto& m : modes)
        g += 1.0 /
             std::complex<double>(m.stiffnessNPerM - m.massKg * omegaRadS * omegaRadS, m.dampingNsPerM * omegaRadS);
    return g;
}

std::pair<double, double> engagementAngles(const CuttingConditions& cut)
{
    const double r = cut.radialImmersion;
    if (cut.milling == MillingDirection::Up)
        return {0.0, std::acos(1.0 - 2.0 * r)};
    return {std::acos(2.0 * r - 1.0), std::numbers::pi};
}

Eigen::Matrix2d integrateToothMatrix(const CuttingConditions& cut, double a, double b)
{
    using model::kTwoPi;
    const auto [st, en] = engagementAngles(cut);
    Eigen::Matrix2d sum = Eigen::Matrix2d::Zero();
    const long mLo = static_cast<long>(std::floor((a - en) / kTwoPi));
    const long mHi = static_cast<long>(std::ceil((b - st) / kTwoPi));
    for (long m = mLo; m <= mHi; ++m) {
        const double lo = std::max(a, st + kTwoPi * static_cast<double>(m));
        const double hi = std::min(b, en + kTwoPi * static_cast<double>(m));
        if (hi <= lo)
            continue;
        const Prim p1 = prim(hi);
        const Prim p0 = prim(lo);
        const double sc = p1.sc - p0.sc, ss = p1.ss - p0.ss, cc = p1.cc - p0.cc;
        const double kt = cut.ktNPerM2, kr = cut.krNPerM2;
        sum(0, 0) += kt * sc + kr * ss;
        sum(0, 1) += kt * cc + kr * sc;
        sum(1, 0) += -kt * ss + kr * sc;
        sum(1, 1) += -kt * sc + kr * cc;
    }
    return sum;
}

Eigen::Matrix2d averageCuttingMatrix(const CuttingConditions& cut, double thetaA, double thetaB)
{
    Eigen::Matrix2d sum = Eigen::Matrix2d::Zero();
    for (int j = 0; j < cut.teeth; ++j) {
        const double off = 2.0 * std::numbers::pi * j / cut.teeth;
        sum += integrateToothMatrix(cut, thetaA + off, thetaB + off);
    }
    return sum / (thetaB - thetaA);
}

} // namespace axistune::machining

// SPDX-License-Identifier: GPL-3.0-or-later
// Velocity-loop step prediction: sampled PI on the two-inertia model (5.1) of
// spec/lost-motion-and-two-inertia.md, RK4 between the samples (VelocityStep.h).
#include "core/tuning/VelocityStep.h"

#include <array>
#include <cmath>

namespace axistune::tuning {

namespace {

using State = std::array<double, 4>; // θ_m, ω_m, θ_L, ω_L

State derivative(const TwoInertiaParams& p, bool rigid, double torque, const State& x)
{
    if (rigid)
        return {x[1], torque / (p.jmKgm2 + p.jlKgm2), x[3], torque / (p.jmKgm2 + p.jlKgm2)};
    const double shaft = p.kNmPerRad * (x[0] - x[2]) + p.cNmsPerRad * (x[1] - x[3]);
    return {x[1], (torque - shaft) / p.jmKgm2, x[3], shaft / p.jlKgm2};
}

State rk4(const TwoInertiaParams& p, bool rigid, double torque, const State& x, double h)
{
    auto add = [](const State& a, const State& b, double k) {
        return State{a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2], a[3] + k * b[3]};
    };
    const State k1 = derivative(p, rigid, torque, x);
    const State k2 = derivative(p, rigid, torque, add(x, k1, h / 2));
    const State k3 = derivative(p, rigid, torque, add(x, k2, h / 2));
    const State k4 = derivative(p, rigid, torque, add(x, k3, h));
    State y;
    for (int i = 0; i < 4; ++i)
        y[i] = x[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    return y;
}

} // namespace

Result<VelocityStepPrediction> predictVelocityStep(const TwoInertiaParams& p, const VelocityPi& pi, double periodS,
                                                   double stepRadS, double stepTimeS, double durationS)
{
    if (!(p.jmKgm2 > 0.0) || !(p.jlKgm2 >= 0.0) || !(p.kNmPerRad >= 0.0) || !(p.cNmsPerRad >= 0.0))
        return makeError(ErrorCode::BadInput, "velocity step: J_m must be > 0 and J_L, K, C ≥ 0");
    if (!(periodS > 0.0) || !(durationS >= periodS) || !std::isfinite(stepRadS) || !std::isfinite(stepTimeS))
        return makeError(ErrorCode::BadInput, "velocity step: period > 0, duration ≥ one period, finite step");
    if (!std::isfinite(pi.kpNmsPerRad) || !std::isfinite(pi.kiNmPerRad))
        return makeError(ErrorCode::BadInput, "velocity step: the PI gains must be finite");
    const bool rigid = p.kNmPerRad == 0.0 || p.jlKgm2 == 0.0;
    // Substeps: resolve the spring mode (and the period) well.
    int sub = 8;
    if (!rigid) {
        const double wp = resonanceRadS(p);
        sub = std::max(sub, static_cast<int>(std::ceil(periodS * wp / 0.05)));
    }
    const double h = periodS / sub;
    const auto n = static_cast<std::size_t>(std::floor(durationS / periodS)) + 1;
    VelocityStepPrediction out;
    out.tS.reserve(n);
    State x{0.0, 0.0, 0.0, 0.0};
    double integral = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = static_cast<double>(k) * periodS;
        const double cmd = t >= stepTimeS ? stepRadS : 0.0;
        const double e = cmd - x[1];
        integral += pi.kiNmPerRad * periodS * e;
        const double torque = pi.kpNmsPerRad * e + integral;
        out.tS.push_back(t);
        out.commandRadS.push_back(cmd);
        out.motorVelRadS.push_back(x[1]);
        out.loadVelRadS.push_back(x[3]);
        out.torqueNm.push_back(torque);
        for (int s = 0; s < sub; ++s)
            x = rk4(p, rigid, torque, x, h);
    }
    return out;
}

} // namespace axistune::tuning

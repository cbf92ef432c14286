// SPDX-License-Identifier: GPL-3.0-or-later
// The independent lifted model of the simulated velocity loop (LiftedModel.h). Compiled once into the
// test-support library axistune_test_lifted (tests/CMakeLists.txt): its matrix exponential
// (unsupported/Eigen/MatrixFunctions) took 12 s to compile in each of the four tests that use it.
#include "tests/core/sim/LiftedModel.h"

#include "core/dsp/DigitalFilter.h"

#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>

namespace axistune::simtest {

std::complex<double> LiftedVelocityLoop::response(double fHz) const
{
    const std::complex<double> z = std::polar(1.0, 2.0 * std::numbers::pi * fHz * periodS);
    const Eigen::MatrixXcd m = z * Eigen::MatrixXcd::Identity(a.rows(), a.cols()) - a.cast<std::complex<double>>();
    const Eigen::VectorXcd x = m.partialPivLu().solve(b.cast<std::complex<double>>());
    return (c.cast<std::complex<double>>() * x)(0);
}

LiftedCurrentTick buildLiftedCurrentTick(const sim::AxisDefinition& axis)
{
    const auto& v = axis.values;
    const double h = v.at("current.period");
    const int velDiv = static_cast<int>(std::lround(v.at("velocity.period") / h));
    const int dead = static_cast<int>(std::lround(v.at("current.dead_time") / h));
    const double kt = v.at("motor.torque_constant");
    const double l = v.at("plant.motor.inductance_q"), r = v.at("plant.motor.resistance");
    const double ke = v.at("plant.motor.back_emf_constant");
    const double jm = v.at("plant.inertia_motor"), jl = v.at("plant.inertia_load");
    const double k = v.at("plant.coupling_stiffness"), cc = v.at("plant.coupling_damping");
    const double bm = v.at("plant.viscous_motor"), bl = v.at("plant.viscous_load");
    const bool rigid = k <= 0.0;
    const int nm = static_cast<int>(axis.modes.size());
    // Plant states: i, θm, ωm, [θL, ωL], (q, q̇) per mode. Input: voltage. Output: encoder angle.
    const int np = (rigid ? 3 : 5) + 2 * nm;
    Eigen::MatrixXd ac = Eigen::MatrixXd::Zero(np, np);
    Eigen::VectorXd bc = Eigen::VectorXd::Zero(np);
    ac(0, 0) = -r / l;
    ac(0, 2) = -ke / l;
    bc(0) = 1.0 / l;
    ac(1, 2) = 1.0;
    if (rigid) {
        ac(2, 0) = kt / (jm + jl);
        ac(2, 2) = -(bm + bl) / (jm + jl);
    } else {
        ac(2, 0) = kt / jm;
        ac(2, 1) = -k / jm;
        ac(2, 3) = k / jm;
        ac(2, 2) = -(cc + bm) / jm;
        ac(2, 4) = cc / jm;
        ac(3, 4) = 1.0;
        ac(4, 1) = k / jl;
        ac(4, 3) = -k / jl;
        ac(4, 2) = cc / jl;
        ac(4, 4) = -(cc + bl) / jl;
    }
    Eigen::RowVectorXd encoder = Eigen::RowVectorXd::Zero(np);
    encoder(1) = 1.0;
    for (int m = 0; m < nm; ++m) {
        const int q = (rigid ? 3 : 5) + 2 * m;
        const double w = 2.0 * std::numbers::pi * axis.modes[m].frequencyHz;
        ac(q, q + 1) = 1.0;
        ac(q + 1, q) = -w * w;
        ac(q + 1, q + 1) = -2.0 * axis.modes[m].damping * w;
        ac(q + 1, 0) = kt / axis.modes[m].modalInertiaKgm2;
        encoder(q) = 1.0;
    }
    Eigen::MatrixXd aug = Eigen::MatrixXd::Zero(np + 1, np + 1);
    aug.topLeftCorner(np, np) = ac * h;
    aug.topRightCorner(np, 1) = bc * h;
    const Eigen::MatrixXd e = aug.exp();
    const Eigen::MatrixXd phi = e.topLeftCorner(np, np);
    const Eigen::VectorXd gam = e.topRightCorner(np, 1);

    // Torque filters as a state-space (direct form II transposed biquads in cascade).
    std::vector<dsp::Biquad> stages;
    for (int n = 1; n <= sim::kNotchCount; ++n) {
        const std::string key = "filter.notch" + std::to_string(n);
        if (v.at(key + ".center") > 0.0)
            stages.push_back(*dsp::designNotch({v.at(key + ".center"), v.at(key + ".width"), v.at(key + ".depth")}, h));
    }
    if (v.at("filter.lowpass.cutoff") > 0.0)
        stages.push_back(*dsp::designLowPass(v.at("filter.lowpass.cutoff"), h));
    const int nf = 2 * static_cast<int>(stages.size());

    // Per-tick map on z = [plant, current integral, delay line (dead), filter states], input T_cmd.
    const int iInt = np, iDelay = np + 1, iFilt = np + 1 + dead;
    const int nz = np + 1 + dead + nf;
    Eigen::MatrixXd mz = Eigen::MatrixXd::Zero(nz, nz);
    Eigen::VectorXd nzv = Eigen::VectorXd::Zero(nz);
    // Filter output y = f_z·z + f_u·u, and the filter state update, stage by stage.
    Eigen::RowVectorXd fz = Eigen::RowVectorXd::Zero(nz);
    double fu = 1.0;
    for (std::size_t s = 0; s < stages.size(); ++s) {
        const auto& q = stages[s];
        const int s1 = iFilt + 2 * static_cast<int>(s), s2 = s1 + 1;
        // input x = fz·z + fu·u ; y = b0 x + s1 ; s1' = b1 x − a1 y + s2 ; s2' = b2 x − a2 y
        Eigen::RowVectorXd yz = q.b0() * fz;
        yz(s1) += 1.0;
        const double yu = q.b0() * fu;
        mz.row(s1) = q.b1() * fz - q.a1() * yz;
        mz(s1, s2) += 1.0;
        nzv(s1) = q.b1() * fu - q.a1() * yu;
        mz.row(s2) = q.b2() * fz - q.a2() * yz;
        nzv(s2) = q.b2() * fu - q.a2() * yu;
        fz = yz;
        fu = yu;
    }
    const double kp = v.at("current.kp"), ki = v.at("current.ki"), alpha = v.at("current.alpha");
    // i* = (fz z + fu u)/kt ; e = i* − i ; I' = I + ki h e ; vcmd = I' + kp(α i* − i)
    Eigen::RowVectorXd istarZ = fz / kt;
    const double istarU = fu / kt;
    Eigen::RowVectorXd iZ = Eigen::RowVectorXd::Zero(nz);
    iZ(0) = 1.0;
    Eigen::RowVectorXd intZ = Eigen::RowVectorXd::Zero(nz);
    intZ(iInt) = 1.0;
    const Eigen::RowVectorXd intNextZ = intZ + ki * h * (istarZ - iZ);
    const double intNextU = ki * h * istarU;
    const Eigen::RowVectorXd vcmdZ = intNextZ + kp * (alpha * istarZ - iZ);
    const double vcmdU = intNextU + kp * alpha * istarU;
    mz.row(iInt) = intNextZ;
    nzv(iInt) = intNextU;
    Eigen::RowVectorXd appliedZ = vcmdZ;
    double appliedU = vcmdU;
    if (dead > 0) {
        appliedZ = Eigen::RowVectorXd::Zero(nz);
        appliedZ(iDelay) = 1.0;
        appliedU = 0.0;
        for (int d = 0; d + 1 < dead; ++d)
            mz(iDelay + d, iDelay + d + 1) = 1.0;
        mz.row(iDelay + dead - 1) = vcmdZ;
        nzv(iDelay + dead - 1) = vcmdU;
    }
    mz.topLeftCorner(np, np) += phi;
    mz.topRows(np) += gam * appliedZ;
    nzv.head(np) += gam * appliedU;

    LiftedCurrentTick out;
    out.mz = mz;
    out.nzv = nzv;
    out.encoder = Eigen::RowVectorXd::Zero(nz);
    out.encoder.head(np) = encoder;
    out.velDiv = velDiv;
    out.currentPeriodS = h;
    return out;
}

namespace {

/// The velocity PI with the backward-difference velocity on Z = [z, θprev, Iv] (z: the current tick's state), as rows
/// over Z without the reference: ω = (enc·z − θprev)/T, e = −ω, Iv' = Iv + kiv T e, T_c = kpv e + Iv'.
struct VelocityPiRows {
    double tv = 0.0, kpv = 0.0, kiv = 0.0;
    Eigen::RowVectorXd encZ, wZ, ivNextZ, tcZ;
};

VelocityPiRows velocityPiRows(const sim::AxisDefinition& axis, const Eigen::RowVectorXd& encoder)
{
    const auto& v = axis.values;
    VelocityPiRows r;
    r.tv = v.at("velocity.period");
    r.kpv = v.at("velocity.kp");
    r.kiv = v.at("velocity.ki");
    const auto nz = static_cast<int>(encoder.size());
    const int nZ = nz + 2;
    r.encZ = Eigen::RowVectorXd::Zero(nZ);
    r.encZ.head(nz) = encoder;
    r.wZ = r.encZ / r.tv;
    r.wZ(nz) = -1.0 / r.tv;
    const Eigen::RowVectorXd eZ = -r.wZ;
    Eigen::RowVectorXd ivZ = Eigen::RowVectorXd::Zero(nZ);
    ivZ(nz + 1) = 1.0;
    r.ivNextZ = ivZ + r.kiv * r.tv * eZ;
    r.tcZ = r.kpv * eZ + r.ivNextZ;
    return r;
}

}  // namespace

LiftedVelocityLoop buildLiftedVelocityLoop(const sim::AxisDefinition& axis)
{
    const LiftedCurrentTick tick = buildLiftedCurrentTick(axis);
    const auto nz = static_cast<int>(tick.mz.rows());
    Eigen::MatrixXd m4 = Eigen::MatrixXd::Identity(nz, nz);
    Eigen::VectorXd n4 = Eigen::VectorXd::Zero(nz);
    for (int t = 0; t < tick.velDiv; ++t) {
        n4 = tick.mz * n4 + tick.nzv;
        m4 = tick.mz * m4;
    }
    // Velocity loop on Z = [z, θprev, Iv], input r, output ω_meas = (enc·z − θprev)/T; the reference enters e = r − w
    // with weight 1: Iv' gets kiv T r, T_c gets (kpv + kiv T) r.
    const VelocityPiRows pi = velocityPiRows(axis, tick.encoder);
    const int nZ = nz + 2;
    const double ivNextR = pi.kiv * pi.tv;
    const double tcR = pi.kpv + ivNextR;
    LiftedVelocityLoop out;
    out.a = Eigen::MatrixXd::Zero(nZ, nZ);
    out.b = Eigen::VectorXd::Zero(nZ);
    out.a.topLeftCorner(nz, nz) = m4;
    out.a.topRows(nz) += n4 * pi.tcZ;
    out.b.head(nz) = n4 * tcR;
    out.a.row(nz) = pi.encZ;
    out.a.row(nz + 1) = pi.ivNextZ;
    out.b(nz + 1) = ivNextR;
    out.c = pi.wZ;
    out.periodS = pi.tv;
    return out;
}

Eigen::VectorXcd LiftedInjectionLoop::state(double fHz) const
{
    const double w = 2.0 * std::numbers::pi * fHz;
    const std::complex<double> z = std::polar(1.0, w * periodS);
    Eigen::VectorXcd rhs = Eigen::VectorXcd::Zero(a.rows());
    for (int i = 0; i < g.cols(); ++i)
        rhs += g.col(i).cast<std::complex<double>>() * std::polar(1.0, w * i * currentPeriodS);
    const Eigen::MatrixXcd m = z * Eigen::MatrixXcd::Identity(a.rows(), a.cols()) - a.cast<std::complex<double>>();
    return m.partialPivLu().solve(rhs);
}

double LiftedInjectionLoop::slowestTimeConstantS() const
{
    Eigen::EigenSolver<Eigen::MatrixXd> es(a);
    double slowest = 0.0;
    for (int i = 0; i < a.rows(); ++i) {
        const double r = std::abs(es.eigenvalues()(i));
        if (r > 1e-12 && r < 1.0 - 1e-14)
            slowest = std::max(slowest, -periodS / std::log(r));
    }
    return slowest;
}

LiftedInjectionLoop buildLiftedInjectionLoop(const sim::AxisDefinition& axis)
{
    const auto tick = buildLiftedCurrentTick(axis);
    const int nz = static_cast<int>(tick.mz.rows());
    const int velDiv = tick.velDiv;
    // Over one velocity period with inputs u_i (i = 0..velDiv−1): z' = m4 z + Σ_i mz^{velDiv−1−i} nzv u_i.
    Eigen::MatrixXd m4 = Eigen::MatrixXd::Identity(nz, nz);
    for (int t = 0; t < velDiv; ++t)
        m4 = tick.mz * m4;
    Eigen::MatrixXd gz(nz, velDiv);
    for (int i = 0; i < velDiv; ++i) {
        Eigen::VectorXd col = tick.nzv;
        for (int t = i + 1; t < velDiv; ++t)
            col = tick.mz * col;
        gz.col(i) = col;
    }
    const Eigen::VectorXd n4 = gz.rowwise().sum();
    // Z = [z, θprev, Iv]; ω = (enc·z − θprev)/T ; e = −ω ; Iv' = Iv + kiv T e ; T_c = kpv e + Iv'.
    const VelocityPiRows pi = velocityPiRows(axis, tick.encoder);
    const int nZ = nz + 2;
    LiftedInjectionLoop out;
    out.a = Eigen::MatrixXd::Zero(nZ, nZ);
    out.a.topLeftCorner(nz, nz) = m4;
    out.a.topRows(nz) += n4 * pi.tcZ;
    out.a.row(nz) = pi.encZ;
    out.a.row(nz + 1) = pi.ivNextZ;
    out.g = Eigen::MatrixXd::Zero(nZ, velDiv);
    out.g.topRows(nz) = gz;
    out.torqueCmd = pi.tcZ;
    out.velocity = pi.wZ;
    out.periodS = pi.tv;
    out.currentPeriodS = tick.currentPeriodS;
    return out;
}

}  // namespace axistune::simtest

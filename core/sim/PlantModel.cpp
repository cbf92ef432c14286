// SPDX-License-Identifier: GPL-3.0-or-later
// Feed-axis plant: PMSM q-axis circuit, two-inertia mechanics (seed 001 ch. 5, eq. 5.1/5.11) and
// collocated higher modes (seed 001 ch. 3), exact ZOH discretization per current-loop period.
#include "core/sim/PlantModel.h"

#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace axistune::sim {

namespace {
constexpr int kLevels = 256;  // inductance cache resolution over |i| in [0, I_max]
constexpr int kBuckets = 256; // screw cache resolution over L_n in [0, screw length]
} // namespace

double screwCouplingStiffness(const ScrewStiffness& s, double leadMPerRad, double positionM)
{
    const double ln = std::clamp(s.nutDistanceAtZeroM + positionM, 0.0, s.lengthM);
    const double area = 0.25 * std::numbers::pi * s.rootDiameterM * s.rootDiameterM;
    const double axialCompliance =
        1.0 / s.bearingStiffnessNPerM + 1.0 / s.nutStiffnessNPerM + ln / (s.youngsModulusPa * area);
    return 1.0 / (1.0 / s.torsionalStiffnessNmPerRad + axialCompliance / (leadMPerRad * leadMPerRad));
}

PlantModel::PlantModel(PlantConfig config, double periodS)
    : m_cfg(std::move(config)), m_h(periodS), m_rigid(m_cfg.stiffnessNmPerRad <= 0.0 && !m_cfg.screw.enabled())
{
    m_modeOffset = m_rigid ? 3 : 5;
    m_n = m_modeOffset + 2 * static_cast<int>(m_cfg.modes.size());
    m_tmp.resize(m_n);
}

void PlantModel::continuousModel(double inductanceH, Eigen::MatrixXd& a, Eigen::MatrixXd& b) const
{
    continuousModel(inductanceH, m_cfg.screw.enabled() ? bucketStiffness(bucketOf(0.0)) : m_cfg.stiffnessNmPerRad, a,
                    b);
}

int PlantModel::bucketOf(double loadAngleRad) const
{
    if (!m_cfg.screw.enabled())
        return 0;
    const double ln = m_cfg.screw.nutDistanceAtZeroM + m_cfg.screwLeadMPerRad * loadAngleRad;
    const double b = std::floor(ln / m_cfg.screw.lengthM * kBuckets);
    return static_cast<int>(std::clamp(b, 0.0, static_cast<double>(kBuckets - 1)));
}

double PlantModel::bucketStiffness(int bucket) const
{
    // K at the bucket's centre.
    const double ln = (bucket + 0.5) / kBuckets * m_cfg.screw.lengthM;
    return screwCouplingStiffness(m_cfg.screw, m_cfg.screwLeadMPerRad, ln - m_cfg.screw.nutDistanceAtZeroM);
}

double PlantModel::stiffnessAt(double loadAngleRad) const
{
    return m_cfg.screw.enabled() ? bucketStiffness(bucketOf(loadAngleRad)) : m_cfg.stiffnessNmPerRad;
}

void PlantModel::continuousModel(double inductanceH, double stiffnessNmPerRad, Eigen::MatrixXd& a,
                                 Eigen::MatrixXd& b) const
{
    a.setZero(m_n, m_n);
    b.setZero(m_n, 3);
    const auto& c = m_cfg;
    // Electrical
    a(0, 0) = -c.resistanceOhm / inductanceH;
    a(0, 2) = -c.backEmfVsPerRad / inductanceH;
    b(0, 0) = 1.0 / inductanceH;
    a(1, 2) = 1.0;
    if (m_rigid) {
        const double j = c.inertiaMotorKgm2 + c.inertiaLoadKgm2;
        a(2, 0) = c.torqueConstantNmPerA / j;
        a(2, 2) = -(c.viscousMotorNmsPerRad + c.viscousLoadNmsPerRad) / j;
        b(2, 1) = 1.0 / j;
        b(2, 2) = 1.0 / j;
    } else {
        const double jm = c.inertiaMotorKgm2, jl = c.inertiaLoadKgm2, k = stiffnessNmPerRad, d = c.dampingNmsPerRad;
        a(2, 0) = c.torqueConstantNmPerA / jm;
        a(2, 1) = -k / jm;
        a(2, 2) = -(d + c.viscousMotorNmsPerRad) / jm;
        a(2, 3) = k / jm;
        a(2, 4) = d / jm;
        b(2, 1) = 1.0 / jm;
        a(3, 4) = 1.0;
        a(4, 1) = k / jl;
        a(4, 2) = d / jl;
        a(4, 3) = -k / jl;
        a(4, 4) = -(d + c.viscousLoadNmsPerRad) / jl;
        b(4, 2) = 1.0 / jl;
    }
    for (std::size_t m = 0; m < c.modes.size(); ++m) {
        const int q = m_modeOffset + 2 * static_cast<int>(m);
        const double w = 2.0 * std::numbers::pi * c.modes[m].frequencyHz;
        a(q, q + 1) = 1.0;
        a(q + 1, q) = -w * w;
        a(q + 1, q + 1) = -2.0 * c.modes[m].damping * w;
        a(q + 1, 0) = c.torqueConstantNmPerA / c.modes[m].modalInertiaKgm2;
    }
}

const PlantModel::Discrete& PlantModel::discreteFor(int level, int bucket)
{
    const int key = bucket * (kLevels + 1) + level; // bucket 0 without a screw: the key is the level
    auto it = m_cache.find(key);
    if (it != m_cache.end())
        return it->second;
    const double frac = static_cast<double>(level) / kLevels;
    const double l = m_cfg.inductanceH * std::max(0.05, 1.0 - m_cfg.inductanceDropAtMax * frac);
    Eigen::MatrixXd a, b;
    continuousModel(l, m_cfg.screw.enabled() ? bucketStiffness(bucket) : m_cfg.stiffnessNmPerRad, a, b);
    // exp([[A B];[0 0]] h) = [[Φ Γ];[0 I]]
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(m_n + 3, m_n + 3);
    m.topLeftCorner(m_n, m_n) = a * m_h;
    m.topRightCorner(m_n, 3) = b * m_h;
    const Eigen::MatrixXd e = m.exp();
    Discrete d{e.topLeftCorner(m_n, m_n), e.topRightCorner(m_n, 3)};
    return m_cache.emplace(key, std::move(d)).first->second;
}

void PlantModel::step(Eigen::VectorXd& x, double voltageV, double torqueMotorNm, double torqueLoadNm,
                      bool currentDependentInductance)
{
    int level = 0;
    if (currentDependentInductance && m_cfg.inductanceDropAtMax > 0.0) {
        const double frac = std::min(1.0, std::abs(x[0]) / m_cfg.maxCurrentA);
        level = static_cast<int>(std::lround(frac * kLevels));
    }
    const Discrete& d = discreteFor(level, m_cfg.screw.enabled() ? bucketOf(x[3]) : 0);
    m_u << voltageV, torqueMotorNm, torqueLoadNm;
    m_tmp.noalias() = d.phi * x;
    m_tmp.noalias() += d.gamma * m_u;
    x.swap(m_tmp);
}

double PlantModel::encoderAngle(const Eigen::VectorXd& x) const
{
    double th = x[1];
    for (std::size_t m = 0; m < m_cfg.modes.size(); ++m)
        th += x[m_modeOffset + 2 * static_cast<int>(m)];
    return th;
}

}  // namespace axistune::sim

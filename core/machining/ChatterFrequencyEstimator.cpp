// SPDX-License-Identifier: GPL-3.0-or-later
// Kalman-filter chatter-frequency estimator (van Dijk et al.), spec/chatter-stability-and-spindle-speed.md
// §3.0.1 eqs. (1-13)–(1-19). The "dominant" root is read as the largest |α| (least damped pole), as the
// spec recommends; the frequency is |arg α|/(2π t_s).
#include "core/machining/ChatterFrequencyEstimator.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace axistune::machining {

ChatterFrequencyEstimator::ChatterFrequencyEstimator(const KalmanAROptions& opt, double samplePeriodS)
    : m_opt(opt), m_ts(samplePeriodS)
{
    reset();
}

void ChatterFrequencyEstimator::reset()
{
    const int n = m_opt.order;
    m_theta = Eigen::VectorXd::Zero(n);
    m_phi = Eigen::VectorXd::Zero(n);
    m_p = m_opt.p0 * Eigen::MatrixXd::Identity(n, n);
}

void ChatterFrequencyEstimator::step(double au)
{
    // P⁻ = P + R_v; g = P⁻φ/(φᵀP⁻φ + R_w); θ += g(a − φᵀθ); P = (I − gφᵀ)P⁻   (1-16)–(1-18)
    m_p.diagonal().array() += m_opt.rv;
    const Eigen::VectorXd pphi = m_p * m_phi;
    const double den = m_phi.dot(pphi) + m_opt.rw;
    const Eigen::VectorXd g = pphi / den;
    m_theta += g * (au - m_phi.dot(m_theta));
    m_p -= g * pphi.transpose();
    m_p = 0.5 * (m_p + m_p.transpose());
    // φ[i+1] = [−a[i], −a[i−1], …]   (1-15)
    for (int i = m_opt.order - 1; i > 0; --i)
        m_phi(i) = m_phi(i - 1);
    m_phi(0) = -au;
}

std::vector<double> ChatterFrequencyEstimator::frequenciesHz() const
{
    const int n = m_opt.order;
    // Companion matrix of z^n + d1 z^{n−1} + … + dn.
    Eigen::MatrixXd c = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i)
        c(0, i) = -m_theta(i);
    for (int i = 1; i < n; ++i)
        c(i, i - 1) = 1.0;
    Eigen::EigenSolver<Eigen::MatrixXd> es(c, false);
    std::vector<std::complex<double>> roots;
    for (int i = 0; i < n; ++i)
        if (es.eigenvalues()(i).imag() >= 0.0)  // one root of each conjugate pair
            roots.push_back(es.eigenvalues()(i));
    std::sort(roots.begin(), roots.end(), [](auto a, auto b) { return std::abs(a) > std::abs(b); });
    std::vector<double> f;
    for (const auto& r : roots)
        f.push_back(std::abs(std::arg(r)) / (2.0 * std::numbers::pi * m_ts));
    return f;
}

Result<std::vector<double>> estimateChatterFrequencies(const std::vector<double>& signal, double samplePeriodS,
                                                       const KalmanAROptions& opt)
{
    if (!(samplePeriodS > 0.0) || !std::isfinite(samplePeriodS))
        return makeError(ErrorCode::OutOfRange, "sample period must be > 0 s");
    if (opt.order < 2 || opt.order % 2 != 0 || opt.order > 20)
        return makeError(ErrorCode::OutOfRange, "AR order N_d must be even, 2..20");
    if (signal.size() < static_cast<std::size_t>(10 * opt.order))
        return makeError(ErrorCode::BadInput, "signal too short for the chatter-frequency estimate");
    for (double v : signal)
        if (!std::isfinite(v))
            return makeError(ErrorCode::BadInput, "signal contains a non-finite value");
    const double mean = std::accumulate(signal.begin(), signal.end(), 0.0) / static_cast<double>(signal.size());
    ChatterFrequencyEstimator kf(opt, samplePeriodS);
    for (double v : signal)
        kf.step(v - mean);
    return kf.frequenciesHz();
}

}  // namespace axistune::machining

// SPDX-License-Identifier: GPL-3.0-or-later
// Switching-type adaptive identification for the cutting force observer, seed 003 §3.3 eqs. (11)–(12),
// Fig. 6 (spec/cutting-force-observer-and-chatter-detection.md §1.6–§1.9, §3.4 CF-3 per-sample pseudo-code).
// The RLS law, P(0), the trace clamp and the handover options are the reconstructions of spec §1.7/§1.9.
#include "core/machining/SwitchingRls.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <string>

namespace axistune::machining {

Result<SwitchingRls> SwitchingRls::create(const LoadParameters& nominal, const SwitchingRlsOptions& options,
                                          double periodS)
{
    if (options.windowL < 1)
        return makeError(ErrorCode::OutOfRange,
                         "RLS window L must be >= 1 (got " + std::to_string(options.windowL) + ")");
    if (!(options.lambda > 0.0 && options.lambda <= 1.0))
        return makeError(ErrorCode::OutOfRange,
                         "forgetting factor must be in (0, 1] (got " + std::to_string(options.lambda) + ")");
    if (!(options.p0 > 0.0))
        return makeError(ErrorCode::OutOfRange, "P(0) scale must be > 0");
    if (!(options.accelThreshold >= 0.0))
        return makeError(ErrorCode::OutOfRange, "acceleration threshold must be >= 0");
    auto q = butterworth2LowPass(options.qCutoffHz, periodS);
    if (!q)
        return makeError(q.error().code, "Q(s): " + q.error().detail);
    auto qr = butterworth2LowPass(options.qRlsCutoffHz, periodS);
    if (!qr)
        return makeError(qr.error().code, "Q_RLS(s): " + qr.error().detail);
    auto dr = butterworth2Derivative(options.qRlsCutoffHz, periodS);
    if (!dr)
        return makeError(dr.error().code, "sQ_RLS(s): " + dr.error().detail);
    ObserverOptions oo;
    oo.qCutoffHz = options.qCutoffHz;
    oo.signDeadbandRadS = options.signDeadbandRadS;
    auto obs = CuttingForceObserver::create({}, nominal, oo, periodS);
    if (!obs)
        return obs.error();

    SwitchingRls s;
    s.m_nominal = nominal;
    s.m_opt = options;
    s.m_ts = periodS;
    for (auto& f : s.m_mq)
        f = *q;
    s.m_r[0] = *dr;
    s.m_r[1] = s.m_r[2] = s.m_r[3] = s.m_ry = *qr;
    s.m_observer = *obs;
    s.m_sign = SignWithHold(options.signDeadbandRadS);
    s.reset();
    return s;
}

void SwitchingRls::reset()
{
    for (auto& f : m_mq)
        f.reset();
    for (auto& f : m_r)
        f.reset();
    m_ry.reset();
    m_observer.reset();
    m_observer.setLoadParameters(m_nominal);
    m_sign.reset();
    m_r4 = RecursiveLeastSquares<4>(m_opt.lambda, m_opt.p0, m_opt.traceMax,
                                    Eigen::Vector4d(m_nominal.inertia, m_nominal.viscous, 0.0, m_nominal.coulomb));
    m_r3 = RecursiveLeastSquares<3>(m_opt.lambda, m_opt.p0, m_opt.traceMax,
                                    Eigen::Vector3d(m_nominal.inertia, m_nominal.viscous, 0.0));
    m_est = m_nominal;
    m_prev = RlsMode::Hold;
    m_lastSign = 0.0;
    m_sinceReversal = std::int64_t{1} << 40;
    m_counts[0] = m_counts[1] = m_counts[2] = 0;
    m_phi.setZero();
    m_y = 0.0;
}

void SwitchingRls::handover(RlsMode mode)
{
    if (mode == RlsMode::Rls3) { // 11 → 12 (or HOLD → 12): the leading block of the 4-parameter RLS
        m_r3.theta() = m_r4.theta().head<3>();
        m_r3.covariance() = m_r4.covariance().topLeftCorner<3, 3>();
    } else if (mode == RlsMode::Rls4) { // → 11
        if (m_opt.handover == Handover::Substitute) {
            m_r4.theta().head<3>() = m_r3.theta();
            m_r4.covariance().topLeftCorner<3, 3>() = m_r3.covariance();
            // A P4 assembled from two runs need not be positive definite (spec §1.9 item 3): repair.
            Eigen::LLT<Eigen::Matrix4d> llt(m_r4.covariance());
            if (m_opt.repairCovariance && llt.info() != Eigen::Success) {
                m_r4.covariance().block<3, 1>(0, 3).setZero();
                m_r4.covariance().block<1, 3>(3, 0).setZero();
            }
        } else {
            m_r4.theta()[0] = m_r3.theta()[0];
            m_r4.theta()[1] = m_r3.theta()[1];
        }
    }
}

AdaptiveSample SwitchingRls::step(double torsionTorqueHat, double omegaL)
{
    // Observer with the estimates of the previous sample (eq. (2)).
    m_observer.setLoadParameters(m_est);
    const double force = m_observer.stepWithTorsion(torsionTorqueHat, omegaL);

    const double s = m_sign.step(omegaL);
    double u[4] = {omegaL, omegaL, 1.0, s};
    if (m_opt.matchQ) {
        for (int i = 0; i < 4; ++i)
            u[i] = m_mq[i].process(u[i]);
    }
    for (int i = 0; i < 4; ++i)
        m_phi[i] = m_r[i].process(u[i]);
    m_y = m_ry.process(torsionTorqueHat);

    if (m_lastSign != 0.0 && s != 0.0 && s != m_lastSign)
        m_sinceReversal = 0;
    else
        ++m_sinceReversal;
    if (s != 0.0)
        m_lastSign = s;

    const long windowL = m_opt.windowL;
    const bool accel = std::abs(m_phi[0]) > m_opt.accelThreshold;
    RlsMode mode = RlsMode::Hold;
    switch (m_opt.method) {
    case RlsMethod::Fixed:
        mode = RlsMode::Hold;
        break;
    case RlsMethod::Conventional:
        mode = accel ? RlsMode::Rls4 : RlsMode::Hold;
        break;
    case RlsMethod::Switching:
        mode = m_sinceReversal < windowL ? RlsMode::Rls4 : (accel ? RlsMode::Rls3 : RlsMode::Hold);
        break;
    }
    if (m_opt.method == RlsMethod::Switching && mode != m_prev)
        handover(mode);

    if (mode == RlsMode::Rls4) {
        m_r4.update(m_phi, m_y);
        const bool inWindow = m_sinceReversal < windowL - 1;
        if (!(m_opt.method == RlsMethod::Switching && m_opt.commitAtEnd && inWindow)) {
            const auto& th = m_r4.theta();
            m_est = {th[0], th[1], th[3]};
        }
    } else if (mode == RlsMode::Rls3) {
        m_r3.update(m_phi.head<3>(), m_y - m_est.coulomb * m_phi[3]);
        m_r4.update(m_phi, m_y); // shadow eq. (11), not used by the observer
        m_est.inertia = m_r3.theta()[0];
        m_est.viscous = m_r3.theta()[1];
    }
    m_prev = mode;
    ++m_counts[static_cast<int>(mode)];

    AdaptiveSample out;
    out.forceHat = force;
    out.mode = mode;
    out.estimate = m_est;
    out.dcForce = mode == RlsMode::Rls3 ? m_r3.theta()[2] : m_r4.theta()[2];
    return out;
}

} // namespace axistune::machining

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Switching recursive least squares for the adaptive cutting force observer, seed 003 §3.3
// (spec/cutting-force-observer-and-chatter-detection.md §1.6–§1.9, §3.4 CF-3):
//   eq. (11)  y = Q_RLS T̂_s,                 φ4 = Q_RLS[ω̇_L, ω_L, 1, sgn ω_L], θ4 = [J_L, B_L, F_DC, F_CL]
//   eq. (12)  y = Q_RLS (T̂_s − F̂_CL sgn ω_L), φ3 = Q_RLS[ω̇_L, ω_L, 1],         θ3 = [J_L, B_L, F_DC]
// State machine (spec §1.9): RLS4 for L samples after a velocity reversal, else RLS3 when the filtered
// acceleration exceeds a_th, else HOLD. RLS3 also runs the shadow eq. (11). Handover 11→12 copies θ4[0:3]
// and P4[0:3,0:3]; 12→11 either substitutes θ3/P3 (option A) or keeps the shadow and copies Ĵ_L, B̂_L
// (option B, default). The RLS update law (not in the paper's OCR) is the reconstruction of spec §1.7:
// exponential forgetting λ with a trace clamp on P. Deterministic; step() never allocates.

#include "core/machining/CuttingForceObserver.h"
#include "core/model/Result.h"

#include <Eigen/Core>
#include <cstdint>

namespace axistune::machining {

/// Exponentially forgetting RLS with a trace clamp, N parameters (spec §1.7, Appendix A `RLS`).
template <int N> class RecursiveLeastSquares {
public:
    using Vec = Eigen::Matrix<double, N, 1>;
    using Mat = Eigen::Matrix<double, N, N>;

    RecursiveLeastSquares() = default;
    /// traceMax ≤ 0 disables the clamp.
    RecursiveLeastSquares(double lambda, double p0, double traceMax, const Vec& theta0)
        : m_lambda(lambda), m_traceMax(traceMax), m_theta(theta0), m_p(Mat::Identity() * p0)
    {
    }
    /// One update with regressor φ and output y; returns the a-priori error y − φᵀθ.
    double update(const Vec& phi, double y)
    {
        const Vec pp = m_p * phi;
        const double den = m_lambda + phi.dot(pp);
        const Vec k = pp / den;
        const double e = y - phi.dot(m_theta);
        m_theta += k * e;
        m_p = (m_p - k * pp.transpose()) / m_lambda;
        m_p = 0.5 * (m_p + m_p.transpose()).eval();
        const double tr = m_p.trace();
        if (m_traceMax > 0.0 && tr > m_traceMax) {
            m_p *= m_traceMax / tr;
            ++m_clamps;
        }
        return e;
    }
    Vec& theta() { return m_theta; }
    const Vec& theta() const { return m_theta; }
    Mat& covariance() { return m_p; }
    const Mat& covariance() const { return m_p; }
    std::uint64_t clampCount() const { return m_clamps; }

private:
    double m_lambda = 1.0;
    double m_traceMax = 0.0;
    Vec m_theta = Vec::Zero();
    Mat m_p = Mat::Identity();
    std::uint64_t m_clamps = 0;
};

enum class RlsMode { Hold, Rls3, Rls4 };
enum class RlsMethod {
    Fixed,        ///< no identification: the nominal observer
    Conventional, ///< ref. [9]: one eq. (11) RLS whenever |acceleration| > a_th
    Switching,    ///< the proposal: eqs. (11)/(12) switched by the motion
};
enum class Handover {
    Substitute, ///< option A: θ3, P3 written into the 3×3 part of θ4, P4 at 12→11
    Shadow,     ///< option B: keep the shadow θ4 (F_DC, F_CL) and P4, copy Ĵ_L and B̂_L
};

struct SwitchingRlsOptions {
    RlsMethod method = RlsMethod::Switching;
    double qCutoffHz = 250.0;    ///< Q(s) (regressor matching and observer)
    double qRlsCutoffHz = 40.0;  ///< Q_RLS(s), Table 2
    int windowL = 100;           ///< RLS4 samples after a reversal, Table 2
    double lambda = 0.99;        ///< forgetting factor, default 1 − 1/L (spec §1.7)
    double p0 = 100.0;           ///< P(0) = p0 I
    double traceMax = 100.0;     ///< trace(P) ≤ traceMax (≤ 0: off)
    double accelThreshold = 5.0; ///< a_th on the filtered acceleration [rad/s²]
    double signDeadbandRadS = 0.05;
    bool matchQ = true; ///< regressors also through Q(s) (spec §1.6 recommendation)
    Handover handover = Handover::Shadow;
    bool commitAtEnd = true;      ///< F̂_CL handed to the observer only at the end of the RLS4 window
    bool repairCovariance = true; ///< option A: zero the cross-blocks of P4 when it is not positive definite
};

/// One sample of the adaptive observer.
struct AdaptiveSample {
    double forceHat = 0.0; ///< F̂_cut of eq. (2) with the current estimates
    RlsMode mode = RlsMode::Hold;
    LoadParameters estimate; ///< Ĵ_L, B̂_L, F̂_CL used by the observer
    double dcForce = 0.0;    ///< F̂_DC (θ3[2] in RLS3, θ4[2] otherwise)
};

/// The adaptive cutting force observer: eq. (2) with parameters from the switching RLS (Fig. 3).
class SwitchingRls {
public:
    static Result<SwitchingRls> create(const LoadParameters& nominal, const SwitchingRlsOptions& options,
                                       double periodS);
    void reset();
    /// One sample: torsion torque estimate T̂_s and measured load velocity ω_L.
    AdaptiveSample step(double torsionTorqueHat, double omegaL);

    const RecursiveLeastSquares<4>& rls4() const { return m_r4; }
    const RecursiveLeastSquares<3>& rls3() const { return m_r3; }
    const LoadParameters& estimate() const { return m_est; }
    RlsMode mode() const { return m_prev; }
    /// Samples spent in each mode since reset (HOLD, RLS3, RLS4): the identification-opportunity KPI.
    const std::uint64_t* modeCounts() const { return m_counts; }
    /// Regressor φ4 and output y of the last step (for diagnostics and tests).
    const Eigen::Vector4d& lastRegressor() const { return m_phi; }
    double lastOutput() const { return m_y; }

private:
    SwitchingRls() = default;
    void handover(RlsMode mode);

    LoadParameters m_nominal;
    SwitchingRlsOptions m_opt;
    double m_ts = 0.0;
    dsp::Biquad m_mq[4];      // Q on the raw regressors (matchQ)
    dsp::Biquad m_r[4], m_ry; // sQ_RLS, Q_RLS, Q_RLS, Q_RLS; Q_RLS on y
    CuttingForceObserver m_observer;
    SignWithHold m_sign;
    RecursiveLeastSquares<4> m_r4;
    RecursiveLeastSquares<3> m_r3;
    LoadParameters m_est;
    RlsMode m_prev = RlsMode::Hold;
    double m_lastSign = 0.0;
    std::int64_t m_sinceReversal = 0;
    std::uint64_t m_counts[3] = {0, 0, 0};
    Eigen::Vector4d m_phi = Eigen::Vector4d::Zero();
    double m_y = 0.0;
};

} // namespace axistune::machining

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Chatter-frequency estimation by a Kalman filter on a time-varying all-pole (AR) model,
// spec/chatter-stability-and-spindle-speed.md §3.0.1, eqs. (1-10)–(1-19). Sample by sample, no allocation
// in step().

#include "core/model/Result.h"

#include <Eigen/Core>

#include <vector>

namespace axistune::machining {

struct KalmanAROptions {
    int order = 2;          ///< N_d: 2 per chatter frequency
    double rv = 1e-16;      ///< random-walk covariance R_v (times I)
    double rw = 0.3;        ///< measurement covariance R_w
    double p0 = 1e-4;       ///< initial covariance P[0] (times I)
};

class ChatterFrequencyEstimator {
public:
    ChatterFrequencyEstimator(const KalmanAROptions& opt, double samplePeriodS);
    void reset();
    void step(double au);
    /// Estimated frequencies [Hz] of the model poles, one per conjugate pair (real poles give 0 or Nyquist),
    /// ordered by descending pole radius (least damped first, spec §3.3 (5-2)).
    std::vector<double> frequenciesHz() const;
    const Eigen::VectorXd& theta() const { return m_theta; }

private:
    KalmanAROptions m_opt;
    double m_ts;
    Eigen::VectorXd m_theta, m_phi;
    Eigen::MatrixXd m_p;
};

/// Runs the estimator over a signal (mean removed first) and returns the frequencies at the end.
Result<std::vector<double>> estimateChatterFrequencies(const std::vector<double>& signal, double samplePeriodS,
                                                       const KalmanAROptions& opt);

}  // namespace axistune::machining

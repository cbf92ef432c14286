// SPDX-License-Identifier: GPL-3.0-or-later
// Two-inertia model fit to a torque → motor-velocity FRF, spec/lost-motion-and-two-inertia.md §4.8
// (algorithm TI-1). The thesis only says "fit near the resonance"; this implementation [ANALYST]:
//  * start values from the data: anti-resonance = minimum of |H|·ω in the band, resonance = maximum
//    of |H|·ω above it; J_total from the low-frequency asymptote 1/(J_total ω), J_m from the high-
//    frequency asymptote 1/(J_m ω) (or from the ratio ω_p²/ω_0² = 1 + J_L/J_m), K = J_L ω_0²; the
//    delay from the phase slope of data/model; C from a few damping guesses (multi-start);
//  * Levenberg–Marquardt on r = w·ln(H_model/H_meas) (real: log-magnitude, imaginary: phase), which
//    weights every decade alike; w = √coherence where defined, else 1; parameters ln J_m, ln J_L,
//    ln K, ln C (kept positive) and the delay in ms.
#include "core/model/Constants.h"
#include "core/tuning/TwoInertia.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace axistune::tuning {

namespace {

using model::kTwoPi;

struct Point {
    double fHz;
    std::complex<double> h;
    double w;
};

TwoInertiaParams fromVector(const Eigen::Matrix<double, 5, 1>& x)
{
    return TwoInertiaParams{std::exp(x(0)), std::exp(x(1)), std::exp(x(2)), std::exp(x(3)), x(4) * 1e-3};
}

Eigen::Matrix<double, 5, 1> toVector(const TwoInertiaParams& p)
{
    Eigen::Matrix<double, 5, 1> x;
    x << std::log(p.jmKgm2), std::log(p.jlKgm2), std::log(p.kNmPerRad), std::log(p.cNmsPerRad), p.delayS * 1e3;
    return x;
}

Eigen::VectorXd residuals(const std::vector<Point>& pts, const Eigen::Matrix<double, 5, 1>& x)
{
    const TwoInertiaParams p = fromVector(x);
    Eigen::VectorXd r(2 * static_cast<Eigen::Index>(pts.size()));
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const auto ratio = std::log(motorVelocityResponse(p, pts[i].fHz) / pts[i].h);
        r(2 * static_cast<Eigen::Index>(i)) = pts[i].w * ratio.real();
        r(2 * static_cast<Eigen::Index>(i) + 1) = pts[i].w * ratio.imag();
    }
    return r;
}

struct LmResult {
    Eigen::Matrix<double, 5, 1> x;
    double cost = 0.0;
    int iterations = 0;
};

LmResult levenbergMarquardt(const std::vector<Point>& pts, Eigen::Matrix<double, 5, 1> x)
{
    Eigen::VectorXd r = residuals(pts, x);
    double cost = r.squaredNorm();
    double lambda = 1e-3;
    int it = 0;
    for (; it < 200; ++it) {
        Eigen::MatrixXd J(r.size(), 5);
        for (int k = 0; k < 5; ++k) {
            const double h = 1e-6;
            Eigen::Matrix<double, 5, 1> xp = x;
            Eigen::Matrix<double, 5, 1> xm = x;
            xp(k) += h;
            xm(k) -= h;
            J.col(k) = (residuals(pts, xp) - residuals(pts, xm)) / (2.0 * h);
        }
        const Eigen::Matrix<double, 5, 5> JtJ = J.transpose() * J;
        const Eigen::Matrix<double, 5, 1> g = J.transpose() * r;
        bool improved = false;
        for (int tries = 0; tries < 12; ++tries) {
            Eigen::Matrix<double, 5, 5> A = JtJ;
            for (int k = 0; k < 5; ++k) {
                A(k, k) += lambda * std::max(JtJ(k, k), 1e-12);
            }
            const Eigen::Matrix<double, 5, 1> step = A.ldlt().solve(-g);
            const Eigen::Matrix<double, 5, 1> xn = x + step;
            const Eigen::VectorXd rn = residuals(pts, xn);
            const double cn = rn.squaredNorm();
            if (std::isfinite(cn) && cn < cost) {
                const double rel = (cost - cn) / std::max(cost, 1e-300);
                x = xn;
                r = rn;
                cost = cn;
                lambda = std::max(lambda / 3.0, 1e-9);
                improved = true;
                if (rel < 1e-12 || step.norm() < 1e-10) {
                    return {x, cost, it + 1};
                }
                break;
            }
            lambda *= 4.0;
        }
        if (!improved) {
            break;
        }
    }
    return {x, cost, it};
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

Result<TwoInertiaFit> fitTwoInertia(const dsp::FrequencyResponse& frf, const TwoInertiaFitOptions& o)
{
    if (!(o.fminHz > 0.0) || !(o.fmaxHz > o.fminHz)) {
        return makeError(ErrorCode::OutOfRange, "fit band must satisfy 0 < fmin < fmax, got " +
                                                    std::to_string(o.fminHz) + " .. " + std::to_string(o.fmaxHz) + " Hz");
    }
    std::vector<Point> pts;
    for (std::size_t i = 0; i < frf.size(); ++i) {
        const double f = frf.freqHz[i];
        const auto h = frf.h[i];
        const bool valid = i < frf.valid.size() ? frf.valid[i] : true;
        const double coh = i < frf.coherence.size() ? frf.coherence[i] : std::nan("");
        if (!valid || f < o.fminHz || f > o.fmaxHz || !std::isfinite(h.real()) || !std::isfinite(h.imag()) ||
            std::abs(h) <= 0.0) {
            continue;
        }
        if (std::isfinite(coh) && coh < o.minCoherence) {
            continue;
        }
        pts.push_back(Point{f, h, std::isfinite(coh) ? std::sqrt(std::clamp(coh, 0.0, 1.0)) : 1.0});
    }
    if (pts.size() < 10) {
        return makeError(ErrorCode::BadInput, "only " + std::to_string(pts.size()) +
                                                  " valid FRF points in the fit band; need at least 10");
    }
    // g = |H|·ω is 1/J_total below the anti-resonance and 1/J_m above the resonance.
    std::vector<double> g(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
        g[i] = std::abs(pts[i].h) * kTwoPi * pts[i].fHz;
    }
    const auto iMin = static_cast<std::size_t>(std::min_element(g.begin(), g.end()) - g.begin());
    const auto iMax = static_cast<std::size_t>(std::max_element(g.begin() + static_cast<long>(iMin), g.end()) - g.begin());
    const std::size_t edge = 2;
    if (iMin < edge || iMax + edge >= pts.size() || iMax <= iMin || g[iMax] < 1.5 * g[iMin]) {
        return makeError(ErrorCode::BadInput,
                         "no usable anti-resonance/resonance pair in " + std::to_string(o.fminHz) + " .. " +
                             std::to_string(o.fmaxHz) + " Hz (|H|·ω needs a dip followed by a peak at least 3.5 dB "
                             "higher, both inside the band)");
    }
    TwoInertiaFit fit;
    fit.dataAntiresonanceHz = pts[iMin].fHz;
    fit.dataResonanceHz = pts[iMax].fHz;
    const double w0 = kTwoPi * fit.dataAntiresonanceHz;
    const double wp = kTwoPi * fit.dataResonanceHz;
    const double ratio = (wp * wp) / (w0 * w0);  // = J_total / J_m
    std::vector<double> low;
    std::vector<double> high;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        if (pts[i].fHz < 0.5 * fit.dataAntiresonanceHz) {
            low.push_back(1.0 / g[i]);
        } else if (pts[i].fHz > 2.0 * fit.dataResonanceHz) {
            high.push_back(1.0 / g[i]);
        }
    }
    double jm = 0.0;
    double jTotal = 0.0;
    if (!low.empty()) {
        jTotal = median(low);
        jm = high.empty() ? jTotal / ratio : median(high);
    } else if (!high.empty()) {
        jm = median(high);
        jTotal = jm * ratio;
    } else {
        jTotal = 1.0 / g.front();
        jm = jTotal / ratio;
    }
    if (!(jTotal > jm) || !(jm > 0.0)) {
        jm = jTotal / ratio;
    }
    TwoInertiaParams start{jm, jTotal - jm, (jTotal - jm) * w0 * w0, 0.0, 0.0};
    // Delay from the phase slope of data / delay-free model (through the origin).
    double best = std::numeric_limits<double>::infinity();
    for (double z0 : {0.02, 0.05, 0.1, 0.2}) {
        TwoInertiaParams p = start;
        p.cNmsPerRad = 2.0 * z0 * p.jlKgm2 * w0;
        double num = 0.0;
        double den = 0.0;
        double unwrap = 0.0;
        double prev = 0.0;
        for (std::size_t i = 0; i < pts.size(); ++i) {
            double ph = std::arg(pts[i].h / motorVelocityResponse(p, pts[i].fHz));
            if (i > 0) {
                while (ph + unwrap - prev > std::numbers::pi) unwrap -= 2.0 * std::numbers::pi;
                while (ph + unwrap - prev < -std::numbers::pi) unwrap += 2.0 * std::numbers::pi;
            }
            prev = ph + unwrap;
            const double w = kTwoPi * pts[i].fHz;
            num += w * prev;
            den += w * w;
        }
        p.delayS = std::max(0.0, -num / den);
        if (z0 == 0.02) {
            fit.initial = p;
        }
        const LmResult lm = levenbergMarquardt(pts, toVector(p));
        if (lm.cost < best) {
            best = lm.cost;
            fit.params = fromVector(lm.x);
            fit.iterations = lm.iterations;
        }
    }
    double sum = 0.0;
    for (const auto& pt : pts) {
        const double e = std::abs(motorVelocityResponse(fit.params, pt.fHz) - pt.h) / std::abs(pt.h);
        sum += e * e;
    }
    fit.pointsUsed = static_cast<int>(pts.size());
    fit.fitError = std::sqrt(sum / static_cast<double>(pts.size()));
    return fit;
}

}  // namespace axistune::tuning

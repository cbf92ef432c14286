// SPDX-License-Identifier: GPL-3.0-or-later
// Modal fit of a tool-tip receptance FRF (issue 10 item 1). Model: the independent-mode receptance of
// spec/chatter-stability-and-spindle-speed.md §1.3, G(jω) = Σ 1/(k − mω² + jcω).
// 1. Peak picking: the largest interior local maximum of −Im H gives ω_n; the half-power points of |H|
//    around it give ζ = (ω₂ − ω₁)/(2ω_n); at resonance −Im H = 1/(c ω_n) gives c; m = c/(2ζω_n), k = mω_n².
//    The mode is subtracted and the next peak is picked from the remainder.
// 2. Levenberg–Marquardt (Marquardt's diagonal scaling) on r_i = H_model(ω_i)/H_i − 1 (real and imaginary
//    parts) over p = log(m, c, k); analytic Jacobian dG/dk = −G², dG/dm = ω²G², dG/dc = −jωG².
#include "core/machining/ToolModeFit.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>

namespace axistune::machining {

namespace {

using cd = std::complex<double>;

struct Points {
    std::vector<double> w;   // rad/s
    std::vector<cd> h;       // m/N
};

// Largest interior local maximum of y (strictly greater than the left neighbour, not less than the right,
// at least `floor`, and not masked); -1 if none.
int largestPeak(const std::vector<double>& y, const std::vector<bool>& masked, double floor)
{
    int best = -1;
    for (std::size_t i = 1; i + 1 < y.size(); ++i) {
        if (masked[i] || !(y[i] > 0.0) || y[i] < floor || !(y[i] > y[i - 1]) || !(y[i] >= y[i + 1]))
            continue;
        if (best < 0 || y[i] > y[static_cast<std::size_t>(best)])
            best = static_cast<int>(i);
    }
    return best;
}

// Frequency where |r| falls to level, searching from index i0 in direction dir; linear interpolation.
// Returns NaN if the edge of the data is reached first.
double halfPowerCrossing(const Points& p, const std::vector<cd>& r, int i0, int dir, double level)
{
    for (int i = i0; i + dir >= 0 && i + dir < static_cast<int>(r.size()); i += dir) {
        const double a = std::abs(r[static_cast<std::size_t>(i)]);
        const double b = std::abs(r[static_cast<std::size_t>(i + dir)]);
        if (b <= level) {
            const double t = (a - level) / (a - b);
            const double wa = p.w[static_cast<std::size_t>(i)];
            const double wb = p.w[static_cast<std::size_t>(i + dir)];
            return wa + t * (wb - wa);
        }
    }
    return std::numeric_limits<double>::quiet_NaN();
}

// A further mode must peak at ≥ kMinPeakFraction of the first mode's −Im H and outside
// ω_j·(1 ± kExclusionZetas·ζ_j) of every mode found so far (what remains there is the start-value error).
constexpr double kMinPeakFraction = 0.05;
constexpr double kExclusionZetas = 5.0;

Result<ModalParameters> pickMode(const Points& p, const std::vector<cd>& remainder, const std::vector<ModalParameters>& found,
                                 double firstPeak)
{
    std::vector<double> negIm(remainder.size());
    std::vector<bool> masked(remainder.size(), false);
    for (std::size_t i = 0; i < remainder.size(); ++i) {
        negIm[i] = -remainder[i].imag();
        for (const auto& m : found) {
            const double wn = std::sqrt(m.stiffnessNPerM / m.massKg);
            if (std::abs(p.w[i] - wn) <= kExclusionZetas * dampingRatio(m) * wn)
                masked[i] = true;
        }
    }
    const int ip = largestPeak(negIm, masked, kMinPeakFraction * firstPeak);
    if (ip < 0)
        return makeError(ErrorCode::BadInput,
                         "tool FRF: no resonance peak for mode " + std::to_string(found.size() + 1)
                             + (found.empty() ? std::string(" (no local maximum of -Im H inside the band)")
                                              : std::string(" (no further local maximum of -Im H above 5 % of the first peak)")));
    const auto i = static_cast<std::size_t>(ip);
    // Parabolic interpolation of the peak frequency on a log-frequency axis.
    double wn = p.w[i];
    {
        const double y0 = negIm[i - 1], y1 = negIm[i], y2 = negIm[i + 1];
        const double den = y0 - 2.0 * y1 + y2;
        if (den < 0.0) {
            const double d = std::clamp(0.5 * (y0 - y2) / den, -0.5, 0.5);
            const double l1 = std::log(p.w[i]);
            const double step = d >= 0 ? std::log(p.w[i + 1]) - l1 : l1 - std::log(p.w[i - 1]);
            wn = std::exp(l1 + d * step);
        }
    }
    const double peakIm = negIm[i];
    const double level = std::abs(remainder[i]) / std::sqrt(2.0);
    const double w1 = halfPowerCrossing(p, remainder, ip, -1, level);
    const double w2 = halfPowerCrossing(p, remainder, ip, +1, level);
    double zeta = 0.02;  // fallback when a half-power point lies outside the band
    if (std::isfinite(w1) && std::isfinite(w2) && w2 > w1)
        zeta = (w2 - w1) / (2.0 * wn);
    else if (std::isfinite(w1))
        zeta = (wn - w1) / wn;
    else if (std::isfinite(w2))
        zeta = (w2 - wn) / wn;
    zeta = std::clamp(zeta, 1e-4, 0.5);
    ModalParameters m;
    m.dampingNsPerM = 1.0 / (wn * peakIm);
    m.massKg = m.dampingNsPerM / (2.0 * zeta * wn);
    m.stiffnessNPerM = m.massKg * wn * wn;
    return m;
}

cd modeG(const ModalParameters& m, double w)
{
    return 1.0 / cd(m.stiffnessNPerM - m.massKg * w * w, m.dampingNsPerM * w);
}

std::vector<ModalParameters> fromParams(const Eigen::VectorXd& x)
{
    std::vector<ModalParameters> modes(static_cast<std::size_t>(x.size() / 3));
    for (std::size_t j = 0; j < modes.size(); ++j) {
        const auto o = static_cast<Eigen::Index>(3 * j);
        modes[j] = {std::exp(x[o]), std::exp(x[o + 1]), std::exp(x[o + 2])};
    }
    return modes;
}

// Residual vector (re, im interleaved) and optionally its Jacobian in log-parameters.
void evaluate(const Points& p, const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd* J)
{
    const auto modes = fromParams(x);
    const auto n = p.w.size();
    r.resize(static_cast<Eigen::Index>(2 * n));
    if (J)
        J->resize(static_cast<Eigen::Index>(2 * n), x.size());
    for (std::size_t i = 0; i < n; ++i) {
        const double w = p.w[i];
        const cd inv = 1.0 / p.h[i];
        cd sum = 0.0;
        for (std::size_t j = 0; j < modes.size(); ++j) {
            const cd g = modeG(modes[j], w);
            sum += g;
            if (J) {
                const cd g2 = g * g * inv;
                const cd dm = w * w * g2 * modes[j].massKg;
                const cd dc = cd(0.0, -w) * g2 * modes[j].dampingNsPerM;
                const cd dk = -g2 * modes[j].stiffnessNPerM;
                const auto row = static_cast<Eigen::Index>(2 * i);
                const auto col = static_cast<Eigen::Index>(3 * j);
                (*J)(row, col) = dm.real();
                (*J)(row + 1, col) = dm.imag();
                (*J)(row, col + 1) = dc.real();
                (*J)(row + 1, col + 1) = dc.imag();
                (*J)(row, col + 2) = dk.real();
                (*J)(row + 1, col + 2) = dk.imag();
            }
        }
        const cd res = sum * inv - 1.0;
        r[static_cast<Eigen::Index>(2 * i)] = res.real();
        r[static_cast<Eigen::Index>(2 * i + 1)] = res.imag();
    }
}

}  // namespace

Result<ToolModeFitResult> fitToolModes(const dsp::FrequencyResponse& frf, const ToolModeFitOptions& options)
{
    if (options.modes < 1)
        return makeError(ErrorCode::OutOfRange, "tool FRF fit: modes must be >= 1 (got " + std::to_string(options.modes) + ")");
    Points p;
    for (std::size_t i = 0; i < frf.size(); ++i) {
        const bool isValid = i < frf.valid.size() ? frf.valid[i] : true;
        const double f = frf.freqHz[i];
        if (!isValid || !(f > 0.0) || f < options.minHz || f > options.maxHz || i >= frf.h.size())
            continue;
        const cd h = frf.h[i];
        if (!std::isfinite(h.real()) || !std::isfinite(h.imag()) || h == 0.0)
            continue;
        p.w.push_back(2.0 * std::numbers::pi * f);
        p.h.push_back(h);
    }
    const auto nParams = static_cast<std::size_t>(3 * options.modes);
    if (p.w.size() < nParams + 1)
        return makeError(ErrorCode::BadInput, "tool FRF: " + std::to_string(p.w.size()) + " valid points in the band, "
                                                  + std::to_string(nParams + 1) + " needed for " + std::to_string(options.modes)
                                                  + " mode(s)");

    ToolModeFitResult out;
    out.points = p.w.size();
    std::vector<cd> remainder = p.h;
    double firstPeak = 0.0;
    for (int j = 0; j < options.modes; ++j) {
        auto m = pickMode(p, remainder, out.startModes, firstPeak);
        if (!m)
            return m.error();
        if (j == 0)
            firstPeak = 1.0 / (m->dampingNsPerM * std::sqrt(m->stiffnessNPerM / m->massKg));
        out.startModes.push_back(*m);
        for (std::size_t i = 0; i < remainder.size(); ++i)
            remainder[i] -= modeG(*m, p.w[i]);
    }

    Eigen::VectorXd x(static_cast<Eigen::Index>(nParams));
    for (std::size_t j = 0; j < out.startModes.size(); ++j) {
        const auto& m = out.startModes[j];
        if (!(m.massKg > 0.0) || !(m.dampingNsPerM > 0.0) || !(m.stiffnessNPerM > 0.0) || !std::isfinite(m.massKg)
            || !std::isfinite(m.dampingNsPerM) || !std::isfinite(m.stiffnessNPerM))
            return makeError(ErrorCode::BadInput, "tool FRF: peak picking gave no positive start values for mode " + std::to_string(j + 1));
        const auto o = static_cast<Eigen::Index>(3 * j);
        x[o] = std::log(m.massKg);
        x[o + 1] = std::log(m.dampingNsPerM);
        x[o + 2] = std::log(m.stiffnessNPerM);
    }

    Eigen::VectorXd r, rTry;
    Eigen::MatrixXd J;
    evaluate(p, x, r, &J);
    double cost = r.squaredNorm();
    double lambda = 1e-3;
    int it = 0;
    bool converged = false;
    for (; it < options.maxIterations && !converged; ++it) {
        const Eigen::MatrixXd A = J.transpose() * J;
        const Eigen::VectorXd g = J.transpose() * r;
        bool accepted = false;
        for (int tries = 0; tries < 30 && !accepted; ++tries) {
            Eigen::MatrixXd Ad = A;
            for (Eigen::Index d = 0; d < A.rows(); ++d)
                Ad(d, d) += lambda * std::max(A(d, d), 1e-12);
            const Eigen::VectorXd step = Ad.ldlt().solve(-g);
            const Eigen::VectorXd xTry = x + step;
            evaluate(p, xTry, rTry, nullptr);
            const double costTry = rTry.squaredNorm();
            if (std::isfinite(costTry) && costTry < cost) {
                const double gain = (cost - costTry) / std::max(cost, 1e-300);
                x = xTry;
                cost = costTry;
                lambda = std::max(lambda / 3.0, 1e-12);
                accepted = true;
                converged = gain < 1e-12 || step.cwiseAbs().maxCoeff() < 1e-12;
            } else {
                lambda *= 4.0;
            }
        }
        if (!accepted)
            break;  // no descent direction left: converged to the numerical floor
        evaluate(p, x, r, &J);
    }
    out.iterations = it;
    evaluate(p, x, r, nullptr);
    out.modes = fromParams(x);
    for (std::size_t j = 0; j < out.modes.size(); ++j) {
        const auto& m = out.modes[j];
        if (!std::isfinite(m.massKg) || !std::isfinite(m.dampingNsPerM) || !std::isfinite(m.stiffnessNPerM) || !(m.massKg > 0.0)
            || !(m.stiffnessNPerM > 0.0) || !(m.dampingNsPerM > 0.0))
            return makeError(ErrorCode::BadInput, "tool FRF: the fit gave a non-finite or non-positive mode " + std::to_string(j + 1));
    }
    std::sort(out.modes.begin(), out.modes.end(),
              [](const ModalParameters& a, const ModalParameters& b) { return naturalFrequencyHz(a) < naturalFrequencyHz(b); });
    out.rmsRelativeError = std::sqrt(r.squaredNorm() / static_cast<double>(p.w.size()));
    return out;
}

}  // namespace axistune::machining

// SPDX-License-Identifier: GPL-3.0-or-later
// Modal fit of a tool-tip receptance FRF (issue 10 item 1, issue 19 item 1). Model: the independent-mode
// receptance of spec/chatter-stability-and-spindle-speed.md §1.3, G(jω) = Σ (ω_n²/k)/(ω_n² − ω² + 2jζω_nω)
// (= 1/(k − mω² + jcω) with m = k/ω_n², c = 2ζ√(km)), plus residual terms R_u − L/ω² (Ewins, Modal
// Testing, §4.4: the modes above the band act as a constant compliance, those below as a mass line).
// Why not the relative error: on a measured FRF |H| spans three decades between the resonances and the
// anti-resonances and the noise floor; weighting by 1/|H| makes the fit chase those (issue 19). The
// absolute error weighted by √|H| keeps the resonances, which decide the limit depth, in charge.
#include "core/machining/ToolModeFit.h"

#include "core/model/Units.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace axistune::machining {

namespace {

using cd = std::complex<double>;
using model::formatNumber;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Peak detection and the gate; docs/machining.md lists them.
constexpr double kMinPeakFraction = 0.05;          // a peak for an explicit mode count: ≥ 5 % of the largest −Im H
constexpr double kSignificantPeakFraction = 0.25;  // a peak counted automatically: ≥ 25 %
constexpr double kMaxPeakZeta = 0.25;              // half-power bandwidth of a resonance: ζ ≤ 0.25
constexpr double kBandHalfWidths = 3.0;            // automatic band: 3 half-power half-widths beyond the peaks
constexpr double kZetaMin = 1e-4, kZetaMax = 0.25; // plausible fitted damping ratios
constexpr double kMinModePeakFraction = 0.05;      // a fitted mode's peak ≥ 5 % of the largest |H| in the band
constexpr double kMaxLocalResidual = 0.35;         // ‖G − H‖/‖H‖ within f_n(1 ± ζ)

struct Points {
    std::vector<double> f; // Hz
    std::vector<cd> h;     // m/N
};

Points collect(const dsp::FrequencyResponse& frf, double lo, double hi)
{
    Points p;
    for (std::size_t i = 0; i < frf.size() && i < frf.h.size(); ++i) {
        const bool isValid = i < frf.valid.size() ? frf.valid[i] : true;
        const double f = frf.freqHz[i];
        const cd h = frf.h[i];
        if (!isValid || !(f > 0.0) || f < lo || f > hi || !std::isfinite(h.real()) || !std::isfinite(h.imag()) ||
            h == 0.0)
            continue;
        p.f.push_back(f);
        p.h.push_back(h);
    }
    return p;
}

std::vector<double> movingAverage(const std::vector<double>& y, std::size_t half)
{
    std::vector<double> out(y.size());
    for (std::size_t i = 0; i < y.size(); ++i) {
        const std::size_t a = i >= half ? i - half : 0;
        const std::size_t b = std::min(y.size() - 1, i + half);
        double s = 0.0;
        for (std::size_t j = a; j <= b; ++j)
            s += y[j];
        out[i] = s / static_cast<double>(b - a + 1);
    }
    return out;
}

// Frequency where mag falls below level walking from i0 in direction dir (linear interpolation); NaN at the edge.
double crossing(const std::vector<double>& f, const std::vector<double>& mag, std::size_t i0, int dir, double level)
{
    for (auto i = static_cast<long>(i0); i + dir >= 0 && i + dir < static_cast<long>(mag.size()); i += dir) {
        const double a = mag[static_cast<std::size_t>(i)];
        const double b = mag[static_cast<std::size_t>(i + dir)];
        if (b < level) {
            const double t = (a - level) / (a - b);
            return f[static_cast<std::size_t>(i)] +
                   t * (f[static_cast<std::size_t>(i + dir)] - f[static_cast<std::size_t>(i)]);
        }
    }
    return std::numeric_limits<double>::quiet_NaN();
}

struct Candidate {
    ResonancePeak peak;
    std::size_t index = 0;
    double mag = 0.0; // smoothed |H| at the peak
};

std::vector<ResonancePeak> peaksOf(const Points& p)
{
    const std::size_t n = p.f.size();
    if (n < 5)
        return {};
    std::vector<double> negIm(n), mag(n);
    for (std::size_t i = 0; i < n; ++i) {
        negIm[i] = -p.h[i].imag();
        mag[i] = std::abs(p.h[i]);
    }
    const std::size_t half = std::max<std::size_t>(1, n / 1000);
    const auto sNegIm = movingAverage(negIm, half);
    const auto sMag = movingAverage(mag, half);
    std::vector<Candidate> cands;
    for (std::size_t i = 1; i + 1 < n; ++i) {
        if (!(sNegIm[i] > 0.0) || !(sNegIm[i] > sNegIm[i - 1]) || !(sNegIm[i] >= sNegIm[i + 1]))
            continue;
        const double level = sMag[i] / std::sqrt(2.0);
        const double f1 = crossing(p.f, sMag, i, -1, level);
        const double f2 = crossing(p.f, sMag, i, +1, level);
        if (!std::isfinite(f1) || !std::isfinite(f2) || (f2 - f1) / (2.0 * p.f[i]) > kMaxPeakZeta)
            continue; // not resolved inside the data, or too wide to be a resonance
        // the raw −Im maximum near the smoothed one
        std::size_t ip = i;
        for (std::size_t j = i >= half ? i - half : 0; j <= std::min(n - 1, i + half); ++j)
            if (negIm[j] > negIm[ip])
                ip = j;
        Candidate c;
        c.peak = {p.f[ip], f1, f2, negIm[ip], 0.5 * (f2 - f1)};
        c.index = i;
        c.mag = sMag[i];
        cands.push_back(c);
    }
    if (cands.empty())
        return {};
    double largest = 0.0;
    for (const auto& c : cands)
        largest = std::max(largest, c.peak.negIm);
    std::erase_if(cands, [&](const Candidate& c) { return c.peak.negIm < kMinPeakFraction * largest; });
    // Merge neighbours that the |H| between them does not separate by a half-power dip.
    std::vector<Candidate> merged;
    for (const auto& c : cands) {
        if (!merged.empty()) {
            auto& last = merged.back();
            double dip = std::numeric_limits<double>::infinity();
            for (std::size_t j = last.index; j <= c.index; ++j)
                dip = std::min(dip, sMag[j]);
            if (dip >= std::min(last.mag, c.mag) / std::sqrt(2.0)) {
                ResonancePeak joined = c.peak.negIm > last.peak.negIm ? c.peak : last.peak;
                joined.lowHz = std::min(last.peak.lowHz, c.peak.lowHz);
                joined.highHz = std::max(last.peak.highHz, c.peak.highHz);
                const bool takeNew = c.peak.negIm > last.peak.negIm;
                last.peak = joined;
                if (takeNew) {
                    last.index = c.index;
                    last.mag = c.mag;
                }
                continue;
            }
        }
        merged.push_back(c);
    }
    std::vector<ResonancePeak> out;
    for (const auto& c : merged)
        out.push_back(c.peak);
    std::sort(out.begin(), out.end(), [](const ResonancePeak& a, const ResonancePeak& b) { return a.negIm > b.negIm; });
    return out;
}

// Parameters: per mode ln ω_n, q (ζ = 0.5/(1+e^−q)), ln k; then the residual terms a, b, c (scaled):
// R = S·(a + jb) − S·c·(ω_ref/ω)².
struct Model {
    int modes = 0;
    bool residuals = false;
    double scale = 1.0; // S [m/N]
    double omegaRef = 1.0;

    static double zetaOf(double q) { return 0.5 / (1.0 + std::exp(-q)); }

    cd eval(const Eigen::VectorXd& x, double w) const
    {
        cd g = 0.0;
        for (int j = 0; j < modes; ++j) {
            const double wn = std::exp(x[3 * j]);
            const double z = zetaOf(x[3 * j + 1]);
            const double k = std::exp(x[3 * j + 2]);
            g += (wn * wn / k) / cd(wn * wn - w * w, 2.0 * z * wn * w);
        }
        if (residuals) {
            const auto o = 3 * modes;
            g += scale * cd(x[o], x[o + 1]) - scale * x[o + 2] * (omegaRef / w) * (omegaRef / w);
        }
        return g;
    }
};

ModalParameters toModal(double wn, double zeta, double k)
{
    const double m = k / (wn * wn);
    return {m, 2.0 * zeta * std::sqrt(k * m), k};
}

std::string hz(double f)
{
    return formatNumber(f, 5) + " Hz";
}

} // namespace

std::vector<ResonancePeak> findResonancePeaks(const dsp::FrequencyResponse& frf, double minHz, double maxHz)
{
    const double lo = std::isnan(minHz) ? 0.0 : minHz;
    const double hi = std::isnan(maxHz) ? std::numeric_limits<double>::infinity() : maxHz;
    return peaksOf(collect(frf, lo, hi));
}

std::complex<double> fittedCompliance(const ToolModeFitResult& fit, double omegaRadS)
{
    return compliance(fit.modes, omegaRadS) + fit.upperResidual - fit.lowerResidual / (omegaRadS * omegaRadS);
}

Result<ToolModeFitResult> fitToolModes(const dsp::FrequencyResponse& frf, const ToolModeFitOptions& options)
{
    if (options.modes < 0 || options.modes > 20)
        return makeError(ErrorCode::OutOfRange,
                         "tool FRF fit: modes must be 0 (automatic) to 20 (got " + std::to_string(options.modes) + ")");
    const bool automatic = std::isnan(options.minHz) && std::isnan(options.maxHz);
    const double lo = std::isnan(options.minHz) ? 0.0 : options.minHz;
    const double hi = std::isnan(options.maxHz) ? std::numeric_limits<double>::infinity() : options.maxHz;
    if (!(hi > lo))
        return makeError(ErrorCode::OutOfRange,
                         "tool FRF fit: the band's upper edge must be above its lower edge (got " +
                             formatNumber(lo, 6) + " to " + formatNumber(hi, 6) + " Hz)");
    const Points all = collect(frf, lo, hi);
    const std::size_t minPoints = static_cast<std::size_t>(3 * std::max(options.modes, 1) + 1);
    if (all.f.size() < minPoints)
        return makeError(ErrorCode::BadInput, "tool FRF: " + std::to_string(all.f.size()) +
                                                  " valid points in the band, " + std::to_string(minPoints) +
                                                  " needed for " + std::to_string(std::max(options.modes, 1)) +
                                                  " mode(s)");

    // 1. Peaks and the number of modes.
    auto peaks = peaksOf(all);
    if (peaks.empty())
        return makeError(ErrorCode::BadInput, "tool FRF: no resonance peak for mode 1 (no maximum of -Im H with both "
                                              "half-power points inside " +
                                                  hz(all.f.front()) + " to " + hz(all.f.back()) + ")");
    if (options.modes > 0) {
        if (static_cast<int>(peaks.size()) < options.modes)
            return makeError(ErrorCode::BadInput, "tool FRF: no resonance peak for mode " +
                                                      std::to_string(peaks.size() + 1) + " (only " +
                                                      std::to_string(peaks.size()) +
                                                      " resonance peak(s) above 5 % of the largest -Im H between " +
                                                      hz(all.f.front()) + " and " + hz(all.f.back()) + ")");
        peaks.resize(static_cast<std::size_t>(options.modes));
    } else {
        const double largest = peaks.front().negIm;
        std::erase_if(peaks, [&](const ResonancePeak& pk) { return pk.negIm < kSignificantPeakFraction * largest; });
    }
    std::sort(peaks.begin(), peaks.end(), [](const ResonancePeak& a, const ResonancePeak& b) { return a.hz < b.hz; });
    const int nModes = static_cast<int>(peaks.size());

    // 2. The band.
    ToolModeFitResult out;
    out.automaticBand = automatic;
    out.bandMinHz = all.f.front();
    out.bandMaxHz = all.f.back();
    if (automatic) {
        out.bandMinHz = std::max(out.bandMinHz, peaks.front().lowHz - kBandHalfWidths * peaks.front().halfWidthHz);
        out.bandMaxHz = std::min(out.bandMaxHz, peaks.back().highHz + kBandHalfWidths * peaks.back().halfWidthHz);
    }
    Points p;
    for (std::size_t i = 0; i < all.f.size(); ++i)
        if (all.f[i] >= out.bandMinHz && all.f[i] <= out.bandMaxHz) {
            p.f.push_back(all.f[i]);
            p.h.push_back(all.h[i]);
        }
    const bool residuals = options.residualTerms;
    const int nParams = 3 * nModes + (residuals ? 3 : 0);
    if (static_cast<int>(p.f.size()) < nParams + 1)
        return makeError(ErrorCode::BadInput,
                         "tool FRF: " + std::to_string(p.f.size()) + " valid points in the band " + hz(out.bandMinHz) +
                             " to " + hz(out.bandMaxHz) + ", " + std::to_string(nParams + 1) + " needed for " +
                             std::to_string(nModes) + " mode(s)" + (residuals ? " and the residual terms" : ""));
    out.points = p.f.size();
    out.peaks = peaks;

    // 3. Start values and the weighted least squares.
    Model model;
    model.modes = nModes;
    model.residuals = residuals;
    model.scale = 0.0;
    for (const auto& h : p.h)
        model.scale = std::max(model.scale, std::abs(h));
    model.omegaRef = kTwoPi * p.f.front();
    const double scale = model.scale;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(nParams);
    for (int j = 0; j < nModes; ++j) {
        const auto& pk = peaks[static_cast<std::size_t>(j)];
        const double zeta = std::clamp(pk.halfWidthHz / pk.hz, 0.002, 0.2);
        const double k = 1.0 / (2.0 * zeta * pk.negIm);
        x[3 * j] = std::log(kTwoPi * pk.hz);
        x[3 * j + 1] = -std::log(0.5 / zeta - 1.0);
        x[3 * j + 2] = std::log(k);
        out.startModes.push_back(toModal(kTwoPi * pk.hz, zeta, k));
    }
    const auto n = p.f.size();
    std::vector<double> w(n), omega(n);
    for (std::size_t i = 0; i < n; ++i) {
        w[i] = std::sqrt(std::abs(p.h[i]) / scale);
        omega[i] = kTwoPi * p.f[i];
    }
    auto residualOf = [&](const Eigen::VectorXd& xx, Eigen::VectorXd& r) {
        r.resize(static_cast<Eigen::Index>(2 * n));
        for (std::size_t i = 0; i < n; ++i) {
            const cd e = w[i] * (model.eval(xx, omega[i]) - p.h[i]) / scale;
            r[static_cast<Eigen::Index>(2 * i)] = e.real();
            r[static_cast<Eigen::Index>(2 * i + 1)] = e.imag();
        }
    };
    auto jacobianOf = [&](const Eigen::VectorXd& xx, const Eigen::VectorXd& r0, Eigen::MatrixXd& J) {
        J.resize(r0.size(), xx.size());
        Eigen::VectorXd xp = xx, rp;
        for (Eigen::Index c = 0; c < xx.size(); ++c) {
            const double step = 1e-7 * std::max(1.0, std::abs(xx[c]));
            xp[c] = xx[c] + step;
            residualOf(xp, rp);
            J.col(c) = (rp - r0) / step;
            xp[c] = xx[c];
        }
    };
    Eigen::VectorXd r, rTry;
    Eigen::MatrixXd J;
    residualOf(x, r);
    jacobianOf(x, r, J);
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
            residualOf(xTry, rTry);
            const double costTry = rTry.squaredNorm();
            if (step.allFinite() && std::isfinite(costTry) && costTry < cost) {
                const double gain = (cost - costTry) / std::max(cost, 1e-300);
                x = xTry;
                r = rTry;
                cost = costTry;
                lambda = std::max(lambda / 3.0, 1e-12);
                accepted = true;
                converged = gain < 1e-12 || step.cwiseAbs().maxCoeff() < 1e-10;
            } else {
                lambda *= 4.0;
            }
        }
        if (!accepted)
            break; // no descent direction left: converged to the numerical floor
        jacobianOf(x, r, J);
    }
    out.iterations = it;

    // 4. Results and the quality gate.
    struct Fitted {
        double wn, zeta, k;
        ResonancePeak peak;
        ModalParameters start;
    };
    std::vector<Fitted> fitted;
    for (int j = 0; j < nModes; ++j)
        fitted.push_back({std::exp(x[3 * j]), Model::zetaOf(x[3 * j + 1]), std::exp(x[3 * j + 2]),
                          peaks[static_cast<std::size_t>(j)], out.startModes[static_cast<std::size_t>(j)]});
    std::sort(fitted.begin(), fitted.end(), [](const Fitted& a, const Fitted& b) { return a.wn < b.wn; });
    out.modes.clear();
    out.startModes.clear();
    out.peaks.clear();
    for (const auto& fm : fitted) {
        out.modes.push_back(toModal(fm.wn, fm.zeta, fm.k));
        out.startModes.push_back(fm.start);
        out.peaks.push_back(fm.peak);
    }
    if (residuals) {
        const auto o = 3 * nModes;
        out.upperResidual = scale * cd(x[o], x[o + 1]);
        out.lowerResidual = scale * x[o + 2] * model.omegaRef * model.omegaRef;
    }
    double rel = 0.0, num = 0.0, den = 0.0, maxMag = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const cd g = model.eval(x, omega[i]);
        rel += std::norm(g / p.h[i] - 1.0);
        num += w[i] * w[i] * std::norm(g - p.h[i]);
        den += w[i] * w[i] * std::norm(p.h[i]);
        maxMag = std::max(maxMag, std::abs(p.h[i]));
    }
    out.rmsRelativeError = std::sqrt(rel / static_cast<double>(n));
    out.residualRatio = std::sqrt(num / den);

    const std::string where =
        " (band " + hz(out.bandMinHz) + " to " + hz(out.bandMaxHz) + ", " + std::to_string(nModes) + " mode(s))";
    for (std::size_t j = 0; j < fitted.size(); ++j) {
        const auto& m = out.modes[j];
        if (!std::isfinite(m.massKg) || !std::isfinite(m.dampingNsPerM) || !std::isfinite(m.stiffnessNPerM) ||
            !(m.massKg > 0.0) || !(m.stiffnessNPerM > 0.0))
            return makeError(ErrorCode::BadInput,
                             "tool FRF fit refused: the fit diverged (mode " + std::to_string(j + 1) +
                                 " has no finite mass, damping or stiffness)" + where +
                                 "; the band holds more than these modes explain: choose a band around the "
                                 "resonances or another number of modes");
    }
    if (!(out.residualRatio <= options.maxResidual))
        return makeError(ErrorCode::BadInput,
                         "tool FRF fit refused: the model misses the measured receptance by " +
                             formatNumber(100.0 * out.residualRatio, 3) + " % (weighted residual; at most " +
                             formatNumber(100.0 * options.maxResidual, 3) + " % accepted)" + where +
                             "; choose a band around the resonances or another number of modes");
    for (std::size_t j = 0; j < fitted.size(); ++j) {
        const auto& fm = fitted[j];
        const double fn = fm.wn / kTwoPi;
        const std::string mode = "mode " + std::to_string(j + 1) + " (" + hz(fn) + ")";
        if (fm.zeta > kZetaMax || fm.zeta < kZetaMin)
            return makeError(ErrorCode::BadInput, "tool FRF fit refused: " + mode + " has damping ratio " +
                                                      formatNumber(fm.zeta, 3) + ", outside the plausible " +
                                                      formatNumber(kZetaMin, 2) + " to " + formatNumber(kZetaMax, 2) +
                                                      where);
        if (fn < out.bandMinHz || fn > out.bandMaxHz)
            return makeError(ErrorCode::BadInput, "tool FRF fit refused: " + mode + " lies outside the band" + where);
        if (1.0 / (2.0 * fm.zeta * fm.k) < kMinModePeakFraction * maxMag)
            return makeError(ErrorCode::BadInput, "tool FRF fit refused: " + mode +
                                                      " has a peak compliance below 5 % of the largest |H| "
                                                      "in the band, it is not a resonance of the data" +
                                                      where);
        if (j > 0) {
            const auto& prev = fitted[j - 1];
            if (fm.wn - prev.wn < (fm.zeta * fm.wn + prev.zeta * prev.wn))
                return makeError(ErrorCode::BadInput,
                                 "tool FRF fit refused: modes " + std::to_string(j) + " and " + std::to_string(j + 1) +
                                     " (" + hz(prev.wn / kTwoPi) + ", " + hz(fn) +
                                     ") overlap within their half-power bandwidths: one resonance fitted twice" +
                                     where);
        }
        double ln = 0.0, ld = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            if (std::abs(omega[i] - fm.wn) <= fm.zeta * fm.wn) {
                ln += std::norm(model.eval(x, omega[i]) - p.h[i]);
                ld += std::norm(p.h[i]);
            }
        if (ld > 0.0 && std::sqrt(ln / ld) > kMaxLocalResidual)
            return makeError(ErrorCode::BadInput, "tool FRF fit refused: " + mode + " misses the measured peak by " +
                                                      formatNumber(100.0 * std::sqrt(ln / ld), 3) +
                                                      " % within its half-power band (at most " +
                                                      formatNumber(100.0 * kMaxLocalResidual, 3) + " %)" + where);
    }
    return out;
}

} // namespace axistune::machining

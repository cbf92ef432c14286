// SPDX-License-Identifier: GPL-3.0-or-later
// Inverse-dynamic identification model with least squares (IDIM-LS: M. Gautier, "Dynamic
// identification of robots with power model", ICRA 1997; the procedure of the EMPS benchmark,
// A. Janot, M. Gautier, M. Brunot, "Data set and reference models of EMPS", 2019 Workshop on
// Nonlinear System Identification Benchmarks): zero-phase Butterworth on the position, central
// differences, parallel decimation (Chebyshev I, order 8, 0.05 dB, 0.8·Nyquist/r), LS with the
// covariance σ²(WᵀW)⁻¹. docs/identification.md states every step and the refusals.
#include "core/ident/MotionIdentification.h"

#include "core/dsp/IirDesign.h"

#include <Eigen/Dense>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

namespace axistune::ident {
namespace {

std::string num(double v)
{
    char buf[32];
    auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 4);
    return std::string(buf, ec == std::errc() ? p : buf);
}

std::vector<double> gradient(const std::vector<double>& x, double h)
{
    const std::size_t n = x.size();
    std::vector<double> g(n);
    g[0] = (x[1] - x[0]) / h;
    g[n - 1] = (x[n - 1] - x[n - 2]) / h;
    for (std::size_t i = 1; i + 1 < n; ++i)
        g[i] = (x[i + 1] - x[i - 1]) / (2.0 * h);
    return g;
}

double sign(double v)
{
    return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0);
}

struct LsFit {
    Eigen::VectorXd theta, std;
    double residualRms = 0.0, residualRelPct = 0.0, condition = 0.0, scaledCondition = 0.0;
};

Result<LsFit> leastSquares(const Eigen::MatrixXd& w, const Eigen::VectorXd& y)
{
    const auto n = w.rows(), p = w.cols();
    if (n <= p + 1)
        return makeError(ErrorCode::BadInput, "refused: " + std::to_string(n) + " equations after decimation for " +
                                                  std::to_string(p) + " parameters (record too short)");
    LsFit f;
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(w);
    const auto& s = svd.singularValues();
    f.condition = s(s.size() - 1) > 0.0 ? s(0) / s(s.size() - 1) : INFINITY;
    Eigen::MatrixXd wn = w;
    for (Eigen::Index j = 0; j < p; ++j) {
        const double norm = w.col(j).norm();
        if (!(norm > 0.0))
            return makeError(ErrorCode::BadInput, "refused: regressor column " + std::to_string(j + 1) + " is zero");
        wn.col(j) /= norm;
    }
    Eigen::JacobiSVD<Eigen::MatrixXd> svdn(wn);
    const auto& sn = svdn.singularValues();
    f.scaledCondition = sn(sn.size() - 1) > 0.0 ? sn(0) / sn(sn.size() - 1) : INFINITY;
    if (!std::isfinite(f.scaledCondition))
        return f; // the caller refuses with its reason
    f.theta = w.colPivHouseholderQr().solve(y);
    const Eigen::VectorXd e = y - w * f.theta;
    const double s2 = e.squaredNorm() / static_cast<double>(n - p);
    const Eigen::MatrixXd cov = s2 * (w.transpose() * w).inverse();
    f.std = cov.diagonal().cwiseSqrt();
    f.residualRms = std::sqrt(e.squaredNorm() / static_cast<double>(n));
    f.residualRelPct = 100.0 * e.norm() / y.norm();
    return f;
}

Result<std::vector<double>> decimate(const dsp::Sos& sos, const std::vector<double>& x, int r)
{
    if (r == 1)
        return x;
    auto f = dsp::filtfiltSos(sos, x);
    if (!f)
        return f.error();
    std::vector<double> out;
    for (std::size_t i = 0; i < f->size(); i += static_cast<std::size_t>(r))
        out.push_back((*f)[i]);
    return out;
}

// Parallel decimation of the force and every regressor column, then LS over the rows whose decimated
// velocity is at least `minSpeed`: at rest the friction is anything within ±Fc, not Fc·sign(q̇).
Result<LsFit> fitColumns(const std::vector<std::vector<double>>& cols, const std::vector<double>& y,
                         const std::vector<double>& velocity, int r, double minSpeed, std::size_t* rowsUsed)
{
    auto dec = dsp::chebyshev1LowPass(8, 0.05, 0.8 / r);
    if (!dec)
        return dec.error();
    auto yd = decimate(*dec, y, r);
    auto vd = decimate(*dec, velocity, r);
    if (!yd || !vd)
        return (!yd ? yd : vd).error();
    std::vector<std::vector<double>> cd;
    for (const auto& c : cols) {
        auto d = decimate(*dec, c, r);
        if (!d)
            return d.error();
        cd.push_back(std::move(d).value());
    }
    std::vector<std::size_t> keep;
    for (std::size_t i = 0; i < vd->size(); ++i) {
        if (std::abs((*vd)[i]) >= minSpeed)
            keep.push_back(i);
    }
    *rowsUsed = keep.size();
    Eigen::MatrixXd w(static_cast<Eigen::Index>(keep.size()), static_cast<Eigen::Index>(cols.size()));
    Eigen::VectorXd yv(static_cast<Eigen::Index>(keep.size()));
    for (std::size_t i = 0; i < keep.size(); ++i) {
        yv(static_cast<Eigen::Index>(i)) = (*yd)[keep[i]];
        for (std::size_t j = 0; j < cd.size(); ++j)
            w(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = cd[j][keep[i]];
    }
    return leastSquares(w, yv);
}

double maxAbsDecimated(const std::vector<double>& v, int r)
{
    auto dec = dsp::chebyshev1LowPass(8, 0.05, 0.8 / r);
    auto d = dec ? decimate(*dec, v, r) : Result<std::vector<double>>(dec.error());
    double m = 0.0;
    if (d) {
        for (double x : *d)
            m = std::max(m, std::abs(x));
    }
    return m;
}

Estimate est(const LsFit& f, int i)
{
    return {f.theta(i), f.std(i)};
}

} // namespace

double Estimate::stdPct() const
{
    return value != 0.0 ? 100.0 * std / std::abs(value) : INFINITY;
}

RigidBodyModel RigidBodyModel::symmetric(double m, double fv, double fc, double offset)
{
    return {m, fv, fv, fc, fc, offset};
}

Result<double> uniformSamplePeriod(const std::vector<double>& t, double relTolerance)
{
    if (t.size() < 3)
        return makeError(ErrorCode::BadInput, "fewer than 3 time stamps");
    std::vector<double> steps(t.size() - 1);
    for (std::size_t i = 1; i < t.size(); ++i)
        steps[i - 1] = t[i] - t[i - 1];
    std::vector<double> sorted = steps;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    const double median = sorted[sorted.size() / 2];
    if (!(median > 0.0))
        return makeError(ErrorCode::BadInput, "time does not increase (median step " + num(median) + " s)");
    for (std::size_t i = 0; i < steps.size(); ++i) {
        if (std::abs(steps[i] - median) > relTolerance * median) {
            return makeError(ErrorCode::BadInput, "not uniformly sampled: the step between data rows " +
                                                      std::to_string(i + 1) + " and " + std::to_string(i + 2) + " is " +
                                                      num(steps[i]) + " s, the median step " + num(median) +
                                                      " s (tolerance " + num(100.0 * relTolerance) + " %)");
        }
    }
    return median;
}

Result<IdentificationResult> identifyRigidBody(const MotionRecord& rec, const IdentificationOptions& o)
{
    const std::size_t n = rec.position.size();
    if (!(rec.periodS > 0.0) || !std::isfinite(rec.periodS))
        return makeError(ErrorCode::BadInput, "sample period must be positive");
    if (rec.force.size() != n || (!rec.velocity.empty() && rec.velocity.size() != n))
        return makeError(ErrorCode::BadInput, "position, force and velocity have different lengths");
    const double fs = 1.0 / rec.periodS;
    if (!(o.cutoffHz > 0.0) || o.cutoffHz >= 0.5 * fs)
        return makeError(ErrorCode::OutOfRange, "cutoff " + num(o.cutoffHz) + " Hz must lie in (0, " + num(0.5 * fs) +
                                                    ") Hz, below the Nyquist frequency");
    IdentificationResult res;
    res.sampleRateHz = fs;
    res.decimation = o.decimation > 0 ? o.decimation : std::max(1, static_cast<int>(std::lround(fs / o.cutoffHz)));
    res.borderSamples = o.borderSamples >= 0 ? o.borderSamples : 5 * res.decimation;
    const auto border = static_cast<std::size_t>(res.borderSamples);
    if (n < 2 * border + 20 * static_cast<std::size_t>(res.decimation))
        return makeError(ErrorCode::BadInput, "refused: " + std::to_string(n) +
                                                  " samples are too few for a border of " + std::to_string(border) +
                                                  " and decimation by " + std::to_string(res.decimation));
    auto lp = dsp::butterworthLowPass(4, o.cutoffHz / (0.5 * fs));
    if (!lp)
        return lp.error();
    std::vector<double> qd;
    if (rec.velocity.empty()) {
        auto qf = dsp::filtfiltSos(*lp, rec.position);
        if (!qf)
            return qf.error();
        qd = gradient(*qf, rec.periodS);
    } else {
        auto vf = dsp::filtfiltSos(*lp, rec.velocity);
        if (!vf)
            return vf.error();
        qd = std::move(vf).value();
    }
    std::vector<double> qdd = gradient(qd, rec.periodS);
    const std::size_t m = n - 2 * border;
    std::vector<double> cA(m), cV(m), cS(m), cOne(m, 1.0), y(m);
    std::size_t pos = 0, neg = 0;
    for (std::size_t i = 0; i < m; ++i) {
        cA[i] = qdd[border + i];
        cV[i] = qd[border + i];
        cS[i] = sign(cV[i]);
        y[i] = rec.force[border + i];
        pos += cV[i] > 0.0;
        neg += cV[i] < 0.0;
    }
    res.positiveFraction = static_cast<double>(pos) / static_cast<double>(m);
    res.negativeFraction = static_cast<double>(neg) / static_cast<double>(m);
    if (std::min(res.positiveFraction, res.negativeFraction) < o.minDirectionFraction) {
        return makeError(ErrorCode::BadInput,
                         "refused: the motion does not reverse enough to separate Coulomb friction from the offset (" +
                             num(100.0 * res.positiveFraction) + " % of the samples move forward, " +
                             num(100.0 * res.negativeFraction) + " % backward; each needs at least " +
                             num(100.0 * o.minDirectionFraction) + " %)");
    }
    res.minSpeed = o.minSpeed > 0.0 ? o.minSpeed : o.minSpeedFraction * maxAbsDecimated(cV, res.decimation);
    auto fit = fitColumns({cA, cV, cS, cOne}, y, cV, res.decimation, res.minSpeed, &res.rows);
    if (!fit)
        return fit.error();
    res.condition = fit->condition;
    res.scaledCondition = fit->scaledCondition;
    if (!(fit->scaledCondition <= o.maxScaledCondition)) {
        return makeError(ErrorCode::BadInput,
                         "refused: the regressor [q'', q', sign(q'), 1] is ill-conditioned (scaled condition number " +
                             num(fit->scaledCondition) + " > " + num(o.maxScaledCondition) +
                             "): the motion does not excite inertia, viscous and Coulomb friction separately");
    }
    res.inertia = est(*fit, 0);
    res.viscous = est(*fit, 1);
    res.coulomb = est(*fit, 2);
    res.offset = est(*fit, 3);
    res.residualRms = fit->residualRms;
    res.residualRelPct = fit->residualRelPct;
    if (!(res.inertia.value > 0.0) || res.inertia.stdPct() > o.maxInertiaStdPct) {
        return makeError(ErrorCode::BadInput, "refused: the inertia is not identified (" + num(res.inertia.value) +
                                                  " ± " + num(res.inertia.std) + ", relative standard deviation " +
                                                  num(res.inertia.stdPct()) + " % > " + num(o.maxInertiaStdPct) +
                                                  " % or not positive): the record has too little acceleration");
    }
    for (const auto& [name, e] : {std::pair{"viscous", res.viscous}, std::pair{"Coulomb", res.coulomb}}) {
        if (e.value < -3.0 * e.std) {
            return makeError(ErrorCode::BadInput, std::string("refused: negative ") + name + " friction " +
                                                      num(e.value) + " ± " + num(e.std) +
                                                      " is not physical; the force or position sign is probably wrong");
        }
    }
    if (o.asymmetric) {
        std::vector<double> vPos(m), vNeg(m), sPos(m), sNeg(m);
        for (std::size_t i = 0; i < m; ++i) {
            vPos[i] = cV[i] > 0.0 ? cV[i] : 0.0;
            vNeg[i] = cV[i] < 0.0 ? cV[i] : 0.0;
            sPos[i] = cV[i] > 0.0 ? 1.0 : 0.0;
            sNeg[i] = cV[i] < 0.0 ? -1.0 : 0.0;
        }
        std::size_t rowsAsym = 0;
        auto af = fitColumns({cA, vPos, vNeg, sPos, sNeg}, y, cV, res.decimation, res.minSpeed, &rowsAsym);
        if (!af)
            return af.error();
        if (!(af->scaledCondition <= o.maxScaledCondition)) {
            return makeError(ErrorCode::BadInput,
                             "refused: the asymmetric regressor is ill-conditioned (scaled condition number " +
                                 num(af->scaledCondition) + ")");
        }
        res.asymmetric = AsymmetricFriction{est(*af, 0), est(*af, 1),     est(*af, 2),        est(*af, 3),
                                            est(*af, 4), af->residualRms, af->scaledCondition};
    }
    return res;
}

Result<ValidationResult> validateClosedLoop(const RigidBodyModel& model, const PositionController& c,
                                            const ValidationRecord& rec, double cutoffHz, std::size_t firstSample,
                                            int substeps)
{
    const std::size_t n = rec.position.size();
    if (rec.reference.size() != n || rec.command.size() != n || (!rec.extra.empty() && rec.extra.size() != n))
        return makeError(ErrorCode::BadInput, "validation columns have different lengths");
    if (n < 10 || firstSample + 10 > n)
        return makeError(ErrorCode::BadInput, "validation record too short");
    if (!(model.inertia > 0.0))
        return makeError(ErrorCode::BadInput, "model inertia must be positive");
    if (!(c.kpPerS > 0.0) || !(c.kv > 0.0) || !std::isfinite(c.kpPerS * c.kv * c.forceScale) || !(c.forceScale > 0.0))
        return makeError(ErrorCode::OutOfRange, "controller: kp, kv and the force scale must be positive numbers");
    if (!(c.saturation > 0.0) || c.delaySamples < 0 || c.delaySamples > 100 || substeps < 1)
        return makeError(ErrorCode::OutOfRange, "controller: saturation must be > 0 and delay in 0..100 samples");
    const double h = rec.periodS;
    const double dt = h / substeps;
    const auto d = static_cast<std::size_t>(c.delaySamples);
    ValidationResult out;
    out.firstSample = firstSample;
    auto& q = out.simulatedPosition;
    auto& u = out.simulatedCommand;
    q.assign(n, 0.0);
    u.assign(n, 0.0);
    for (std::size_t k = 0; k < 3; ++k)
        q[k] = rec.position[k];
    for (std::size_t k = 0; k < std::min(n, 2 + d); ++k)
        u[k] = rec.command[k]; // commands issued before the simulated loop starts
    double v = (rec.position[3] - rec.position[1]) / (2.0 * h);
    for (std::size_t k = 2; k + 1 < n; ++k) {
        const double raw = c.kv * (c.kpPerS * (rec.reference[k] - q[k]) - (q[k] - q[k - 2]) / (2.0 * h));
        if (k + d < n)
            u[k + d] = std::clamp(raw, -c.saturation, c.saturation) + (rec.extra.empty() ? 0.0 : rec.extra[k + d]);
        const double net = c.forceScale * u[k] - model.offset;
        double x = q[k];
        for (int s = 0; s < substeps; ++s) {
            double vn = 0.0;
            if (v == 0.0) {
                if (net <= model.coulombPositive && net >= -model.coulombNegative)
                    continue; // sticks
                vn = dt / model.inertia * (net > 0.0 ? net - model.coulombPositive : net + model.coulombNegative);
            } else {
                const double fr = v > 0.0 ? model.viscousPositive * v + model.coulombPositive
                                          : model.viscousNegative * v - model.coulombNegative;
                vn = v + dt / model.inertia * (net - fr);
                if (vn * v < 0.0)
                    vn = 0.0; // a velocity reversal passes through rest
            }
            x += 0.5 * dt * (v + vn);
            v = vn;
        }
        q[k + 1] = x;
        if (!std::isfinite(x))
            return makeError(ErrorCode::BadInput, "validation simulation diverged at sample " + std::to_string(k + 1));
    }
    auto lp = dsp::butterworthLowPass(4, cutoffHz * 2.0 * h);
    if (!lp)
        return lp.error();
    auto qf = dsp::filtfiltSos(*lp, rec.position);
    if (!qf)
        return qf.error();
    double se = 0.0, mean = 0.0, nf = 0.0, nfe = 0.0, nF = 0.0, nFe = 0.0;
    const auto cnt = static_cast<double>(n - firstSample);
    for (std::size_t k = firstSample; k < n; ++k)
        mean += rec.position[k] / cnt;
    double sc = 0.0;
    for (std::size_t k = firstSample; k < n; ++k) {
        const double e = rec.position[k] - q[k];
        se += e * e;
        sc += (rec.position[k] - mean) * (rec.position[k] - mean);
        out.positionErrorMax = std::max(out.positionErrorMax, std::abs(e));
        nf += (*qf)[k] * (*qf)[k];
        nfe += ((*qf)[k] - q[k]) * ((*qf)[k] - q[k]);
        const double fm = c.forceScale * rec.command[k], fsim = c.forceScale * u[k];
        nF += fm * fm;
        nFe += (fm - fsim) * (fm - fsim);
    }
    out.positionErrorRms = std::sqrt(se / cnt);
    out.positionErrorPctOfMotion = sc > 0.0 ? 100.0 * std::sqrt(se / sc) : INFINITY;
    out.benchmarkPositionPct = nf > 0.0 ? 100.0 * std::sqrt(nfe / nf) : INFINITY;
    out.benchmarkForcePct = nF > 0.0 ? 100.0 * std::sqrt(nFe / nF) : INFINITY;
    return out;
}

} // namespace axistune::ident

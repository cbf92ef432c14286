// SPDX-License-Identifier: GPL-3.0-or-later
// Ball-bar diagnostics. Lost-motion extraction at reversals follows spec/lost-motion-and-two-inertia.md
// §4.3 (LM-1: step across the reversal from fits just before and after it, leaving out the transient);
// the other diagnostics use the first-order radial-deviation model derived in docs/ballbar.md
// (ISO 230-4 least-squares circle for centre, radius and circularity).
#include "core/tuning/BallBarDiagnostics.h"

#include "core/model/Constants.h"
#include "core/model/Number.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace axistune::tuning {
namespace {

using model::kPi;
using model::kRadPerDeg;
constexpr std::size_t kMinSideSamples = 4;

double wrapPi(double a)
{
    a = std::fmod(a + kPi, 2.0 * kPi);
    if (a <= 0.0)
        a += 2.0 * kPi;
    return a - kPi;
}

/// Mean angular spacing of the samples.
double meanStepRad(const io::BallBarTrace& t)
{
    return std::abs(t.angleRad.back() - t.angleRad.front()) /
           static_cast<double>(std::max<std::size_t>(t.size() - 1, 1));
}

double sgn(double v)
{
    return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0);
}

double axisProjection(int axis, double theta)
{
    return axis == 0 ? std::cos(theta) : std::sin(theta);
}

const char* axisName(int axis)
{
    return axis == 0 ? "X" : "Y";
}

std::string fmt(double v, int prec = 2)
{
    return model::formatFixed(v, prec);
}

/// Least squares with a design matrix; returns coefficients and the inverse normal matrix diagonal.
struct LsFit {
    Eigen::VectorXd coef;
    Eigen::VectorXd resid;
    Eigen::VectorXd varDiag; ///< diag((AᵀA)⁻¹)
    double rms = 0.0;
};

LsFit leastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& y)
{
    LsFit f;
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
    f.coef = qr.solve(y);
    f.resid = y - a * f.coef;
    f.rms = std::sqrt(f.resid.squaredNorm() / std::max<Eigen::Index>(1, y.size()));
    const Eigen::MatrixXd ata = a.transpose() * a;
    f.varDiag = ata.ldlt().solve(Eigen::MatrixXd::Identity(a.cols(), a.cols())).diagonal();
    return f;
}

/// Reversal angles of an axis: x at 0 and π, y at π/2 and 3π/2.
std::array<double, 2> reversalAngles(int axis)
{
    return axis == 0 ? std::array<double, 2>{0.0, kPi} : std::array<double, 2>{0.5 * kPi, 1.5 * kPi};
}

bool inAnySpikeZone(double theta, double sigma, double excludeRad)
{
    for (int axis = 0; axis < 2; ++axis) {
        for (double r : reversalAngles(axis)) {
            if (std::abs(sigma * wrapPi(theta - r)) < excludeRad)
                return true;
        }
    }
    return false;
}

/// Spike = largest residual against the step's transition inside the spike zone (fitReversal); width = full
/// width at half height (travel angle).
void findSpike(ReversalEvent& ev, const std::vector<std::pair<double, double>>& zone /* (d, resid) sorted by d */,
               double reversalAngle, double sigma)
{
    if (zone.empty())
        return;
    std::size_t k = 0;
    for (std::size_t i = 1; i < zone.size(); ++i) {
        if (std::abs(zone[i].second) > std::abs(zone[k].second))
            k = i;
    }
    const double peak = zone[k].second;
    const double threshold = std::max(4.0 * ev.noiseRmsM, kMinSpikeM);
    if (std::abs(peak) <= threshold)
        return;
    const double half = 0.5 * peak;
    auto crossing = [&](int dir) {
        std::size_t i = k;
        while (true) {
            const std::size_t j = dir > 0 ? i + 1 : i - 1;
            if ((dir > 0 && i + 1 >= zone.size()) || (dir < 0 && i == 0))
                return zone[i].first;
            if (sgn(zone[j].second) != sgn(peak) || std::abs(zone[j].second) < std::abs(half)) {
                const double f = (zone[i].second - half) / (zone[i].second - zone[j].second);
                return zone[i].first + f * (zone[j].first - zone[i].first);
            }
            i = j;
        }
    };
    ev.spike = true;
    ev.spikeHeightM = peak;
    ev.spikeAngleRad = reversalAngle + sigma * zone[k].first;
    ev.spikeWidthRad = crossing(+1) - crossing(-1);
}

} // namespace

double lostMotionBasis(int axis, double theta, double sigma)
{
    if (axis == 0)
        return 0.5 * sigma * sgn(std::sin(theta)) * std::cos(theta); // −½ sgn(ẋ) cosθ, sgn(ẋ) = −σ sgn(sinθ)
    return -0.5 * sigma * sgn(std::cos(theta)) * std::sin(theta);    // −½ sgn(ẏ) sinθ, sgn(ẏ) = σ sgn(cosθ)
}

namespace {

/// Angular coverage of a trace: the largest gap and where the covered arc starts and ends (rad, CCW).
struct Coverage {
    double maxGap = 2.0 * kPi;
    double from = 0.0;
    double to = 0.0;
};

Coverage coverageOf(const io::BallBarTrace& t)
{
    std::vector<double> a;
    a.reserve(t.size());
    for (double v : t.angleRad) {
        double w = std::fmod(v, 2.0 * kPi);
        a.push_back(w < 0.0 ? w + 2.0 * kPi : w);
    }
    Coverage c;
    if (a.empty())
        return c;
    std::sort(a.begin(), a.end());
    double maxGap = a.front() + 2.0 * kPi - a.back();
    double gapEnd = a.front();
    for (std::size_t i = 1; i < a.size(); ++i) {
        if (a[i] - a[i - 1] > maxGap) {
            maxGap = a[i] - a[i - 1];
            gapEnd = a[i];
        }
    }
    c.maxGap = maxGap;
    c.from = gapEnd;
    c.to = std::fmod(gapEnd + 2.0 * kPi - maxGap, 2.0 * kPi);
    return c;
}

/// Arguments of the "full_circle" refusal: source, covered °, from °, to °, largest gap °, allowed gap °.
std::vector<std::string> coverageArgs(const io::BallBarTrace& t, const Coverage& c, const BallBarOptions& opt)
{
    return {t.source,
            fmt((2.0 * kPi - c.maxGap) / kRadPerDeg, 1),
            fmt(c.from / kRadPerDeg, 1),
            fmt(c.to / kRadPerDeg, 1),
            fmt(c.maxGap / kRadPerDeg, 1),
            fmt(opt.maxGapDeg, 1)};
}

} // namespace

Status requireFullCircle(const io::BallBarTrace& t, const BallBarOptions& opt, const std::string& what)
{
    const Coverage c = coverageOf(t);
    if (c.maxGap <= opt.maxGapDeg * kRadPerDeg)
        return Status::success();
    const auto a = coverageArgs(t, c, opt);
    return makeError(ErrorCode::BadInput, a[0] + ": " + what +
                                              " refused: requires a full 360° circle, but the trace is a partial arc "
                                              "covering " +
                                              a[1] + "° (from " + a[2] + "° to " + a[3] + "° CCW; largest gap " + a[4] +
                                              "°, at most " + a[5] + "° allowed)");
}

namespace {

/// ISO 230-4 least-squares circle Δr = r0 + a cosθ + b sinθ.
LsFit fitCircle(std::span<const double> angle, std::span<const double> dev)
{
    const auto n = static_cast<Eigen::Index>(angle.size());
    Eigen::MatrixXd a(n, 3);
    Eigen::VectorXd y(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        a.row(i) << 1.0, std::cos(angle[i]), std::sin(angle[i]);
        y(i) = dev[i];
    }
    return leastSquares(a, y);
}

} // namespace

Result<double> circularityOf(std::span<const double> angle, std::span<const double> dev)
{
    if (angle.size() != dev.size() || angle.size() < 4)
        return makeError(ErrorCode::BadInput, "circularity needs at least 4 samples");
    const auto f = fitCircle(angle, dev);
    return f.resid.maxCoeff() - f.resid.minCoeff();
}

Result<ReversalEvent> fitReversal(const io::BallBarTrace& t, int axis, double rev, const BallBarOptions& opt)
{
    const double sigma = t.directionSign();
    const double ex = opt.excludeDeg * kRadPerDeg;
    const double outer = ex + opt.fitWindowDeg * kRadPerDeg;
    std::vector<std::size_t> fitIdx, zoneIdx;
    std::size_t before = 0, after = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const double d = sigma * wrapPi(t.angleRad[i] - rev);
        if (std::abs(d) < ex) {
            zoneIdx.push_back(i);
        } else if (std::abs(d) <= outer) {
            fitIdx.push_back(i);
            (d < 0.0 ? before : after)++;
        }
    }
    if (before < kMinSideSamples || after < kMinSideSamples)
        return makeError(ErrorCode::BadInput,
                         t.source + ": the " + axisName(axis) + " reversal at " + fmt(rev / kRadPerDeg, 0) +
                             "° is not covered (needs at least " + std::to_string(kMinSideSamples) + " samples from " +
                             fmt(opt.excludeDeg, 1) + "° to " + fmt(opt.excludeDeg + opt.fitWindowDeg, 1) +
                             "° on each side; found " + std::to_string(before) + " before, " + std::to_string(after) +
                             " after)");
    auto row = [&](std::size_t i) {
        const double d = sigma * wrapPi(t.angleRad[i] - rev);
        Eigen::Matrix<double, 1, 5> r;
        r << 1.0, d, d * d, d * d * d, 0.5 * sgn(d) * std::abs(axisProjection(axis, t.angleRad[i]));
        return r;
    };
    Eigen::MatrixXd a(static_cast<Eigen::Index>(fitIdx.size()), 5);
    Eigen::VectorXd y(a.rows());
    for (Eigen::Index k = 0; k < a.rows(); ++k) {
        a.row(k) = row(fitIdx[k]);
        y(k) = t.deviationM[fitIdx[k]];
    }
    const auto f = leastSquares(a, y);
    ReversalEvent ev;
    ev.axis = axis;
    ev.angleRad = rev;
    const double centre = axis == 0 ? t.centerXM : t.centerYM;
    ev.tableCoordM = centre + t.radiusM * axisProjection(axis, rev);
    ev.stepM = f.coef(4);
    const double dof = std::max<double>(1.0, static_cast<double>(a.rows() - a.cols()));
    ev.noiseRmsM = std::sqrt(f.resid.squaredNorm() / dof);
    ev.stepStdErrM = ev.noiseRmsM * std::sqrt(f.varDiag(4));
    ev.poly = {f.coef(0), f.coef(1), f.coef(2), f.coef(3)};

    // Step and spike told apart inside the zone (docs/ballbar.md "Reversal spikes"): relative to the
    // local smooth part, the deviation is at the level before the step, L0 = −h/2·|u_a|, until the
    // reversal and ends at the level after it, L1 = +h/2·|u_a|. A backlash (or lost motion) moves it from
    // L0 to L1 monotonically and stays there: the transition is the running extreme towards L1, clamped to
    // [L0, L1]. A spike is what departs from that transition and comes back: the residual against it.
    // Before the reversal (more than 1.5 samples, the uncertainty of the reversal instant) the transition
    // has not started and the spike is the residual against L0.
    const double sampleStep = meanStepRad(t);
    std::vector<std::pair<double, double>> rel; // (d, deviation − smooth part) sorted by d
    for (std::size_t i : zoneIdx) {
        const double d = sigma * wrapPi(t.angleRad[i] - rev);
        const double smooth = f.coef(0) + d * (f.coef(1) + d * (f.coef(2) + d * f.coef(3)));
        rel.emplace_back(d, t.deviationM[i] - smooth);
    }
    std::vector<std::size_t> order(rel.size());
    for (std::size_t k = 0; k < order.size(); ++k)
        order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return rel[i].first < rel[j].first; });
    std::vector<std::pair<double, double>> zone;
    const double h = f.coef(4);
    const double towards = h >= 0.0 ? 1.0 : -1.0; // direction from L0 to L1
    double progress = 0.0;                        // running extreme of the transition, 0 (L0) … |h| (L1)
    for (std::size_t k : order) {
        const auto [d, r] = rel[k];
        const double u = std::abs(axisProjection(axis, rev + sigma * d));
        const double l0 = -0.5 * h * u;
        if (d <= -1.5 * sampleStep) {
            zone.emplace_back(d, r - l0);
            continue;
        }
        progress = std::clamp(std::max(progress, towards * (r - l0)), 0.0, std::abs(h) * u);
        zone.emplace_back(d, r - (l0 + towards * progress));
    }
    findSpike(ev, zone, rev, sigma);
    return ev;
}

namespace {

/// Least-squares cyclic error of one axis on a residual: e_a = α cos(2πx/p) + β sin(2πx/p) projected
/// radially (× u_a), scanned over pitch p from 4 samples at full axis speed up to R/2.
struct CyclicScan {
    int axis = 0;
    double k = 0.0; ///< wavenumber 1/p [1/m]
    double alpha = 0.0, beta = 0.0, power = 0.0;
    double kLo = 0.0, kHi = 0.0;
};

class CyclicScanner {
public:
    CyclicScanner(int axis, const std::vector<double>& theta, double radius, double meanStepRad)
        : m_axis(axis), m_u(theta.size()), m_x(theta.size()), m_radius(radius)
    {
        for (std::size_t i = 0; i < theta.size(); ++i) {
            m_u[i] = axisProjection(axis, theta[i]);
            m_x[i] = radius * m_u[i];
            m_nEff += m_u[i] * m_u[i];
        }
        m_kLo = 2.0 / radius;
        m_kHi = 1.0 / std::max(0.5e-3, 4.0 * radius * meanStepRad);
    }

    CyclicScan project(double k, const Eigen::VectorXd& y) const
    {
        double scc = 0, sss = 0, scs = 0, yc = 0, ys = 0;
        for (std::size_t i = 0; i < m_u.size(); ++i) {
            const double ph = 2.0 * kPi * k * m_x[i];
            const double c = m_u[i] * std::cos(ph), s = m_u[i] * std::sin(ph);
            scc += c * c, sss += s * s, scs += c * s;
            yc += c * y(static_cast<Eigen::Index>(i)), ys += s * y(static_cast<Eigen::Index>(i));
        }
        CyclicScan r{m_axis, k, 0.0, 0.0, 0.0, m_kLo, m_kHi};
        const double det = scc * sss - scs * scs;
        if (det <= 1e-12 * scc * sss)
            return r;
        r.alpha = (sss * yc - scs * ys) / det;
        r.beta = (scc * ys - scs * yc) / det;
        r.power = r.alpha * yc + r.beta * ys;
        return r;
    }

    /// Grid over the wavenumber (8 points per resolution cell 1/(2R)), then golden-section refinement.
    /// The grid advances every sample's phasor by a fixed rotation instead of calling sin/cos.
    CyclicScan scan(const Eigen::VectorXd& y) const
    {
        if (!(m_kHi > m_kLo))
            return CyclicScan{m_axis};
        const double dk = 1.0 / (16.0 * m_radius);
        const std::size_t n = m_u.size();
        std::vector<std::complex<double>> z(n), w(n);
        CyclicScan best{m_axis};
        best.power = -1.0;
        int step = 0;
        for (double k = m_kLo; k <= m_kHi; k += dk, ++step) {
            if (step % 64 == 0) { // fresh phasors now and then, so rounding never accumulates
                for (std::size_t i = 0; i < n; ++i) {
                    z[i] = std::polar(1.0, 2.0 * kPi * k * m_x[i]);
                    w[i] = std::polar(1.0, 2.0 * kPi * dk * m_x[i]);
                }
            }
            double scc = 0, sss = 0, scs = 0, yc = 0, ys = 0;
            for (std::size_t i = 0; i < n; ++i) {
                const double c = m_u[i] * z[i].real(), s = m_u[i] * z[i].imag();
                const double yi = y(static_cast<Eigen::Index>(i));
                scc += c * c, sss += s * s, scs += c * s, yc += c * yi, ys += s * yi;
                z[i] *= w[i];
            }
            const double det = scc * sss - scs * scs;
            if (det <= 1e-12 * scc * sss)
                continue;
            const double al = (sss * yc - scs * ys) / det, be = (scc * ys - scs * yc) / det;
            if (al * yc + be * ys > best.power)
                best = CyclicScan{m_axis, k, al, be, al * yc + be * ys, m_kLo, m_kHi};
        }
        if (best.power < 0.0)
            return CyclicScan{m_axis};
        double lo = std::max(m_kLo, best.k - dk), hi = std::min(m_kHi, best.k + dk);
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        for (int it = 0; it < 24; ++it) {
            const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
            if (project(m1, y).power > project(m2, y).power)
                hi = m2;
            else
                lo = m1;
        }
        auto refined = project(0.5 * (lo + hi), y);
        return refined.power > best.power ? refined : best;
    }

    Eigen::VectorXd model(const CyclicScan& c) const
    {
        Eigen::VectorXd m(static_cast<Eigen::Index>(m_u.size()));
        for (std::size_t i = 0; i < m_u.size(); ++i) {
            const double ph = 2.0 * kPi * c.k * m_x[i];
            m(static_cast<Eigen::Index>(i)) = m_u[i] * (c.alpha * std::cos(ph) + c.beta * std::sin(ph));
        }
        return m;
    }

    /// The two regressors u_a·cos(2πkx), u_a·sin(2πkx) of sample i.
    std::pair<double, double> columns(double k, std::size_t i) const
    {
        const double ph = 2.0 * kPi * k * m_x[i];
        return {m_u[i] * std::cos(ph), m_u[i] * std::sin(ph)};
    }

    CyclicFit result(const CyclicScan& c, double restVar) const
    {
        CyclicFit f;
        f.amplitudeM = std::hypot(c.alpha, c.beta);
        f.pitchM = c.k > 0.0 ? 1.0 / c.k : 0.0;
        // Max over ~M independent pitches of a 2-dof chi-square: false alarm 1e-3 at ≈ 2 ln(1000 M).
        const double m = std::max(1.0, (m_kHi - m_kLo) * 2.0 * m_radius);
        f.thresholdM = std::sqrt(2.0 * std::log(1000.0 * m)) * std::sqrt(restVar) * std::sqrt(2.0 / m_nEff);
        f.detected = f.amplitudeM > f.thresholdM;
        return f;
    }

private:
    int m_axis;
    std::vector<double> m_u, m_x;
    double m_radius;
    double m_nEff = 0.0;
    double m_kLo = 0.0, m_kHi = 0.0;
};

/// Pitches of both axes: the stronger one first, then the other on what is left, then the first again,
/// so the cyclic error of one axis is not attributed to the other.
std::array<CyclicScan, 2> scanCyclic(const std::array<CyclicScanner, 2>& sc, const Eigen::VectorXd& resid)
{
    std::array<CyclicScan, 2> s{sc[0].scan(resid), sc[1].scan(resid)};
    const int first = s[0].power >= s[1].power ? 0 : 1, second = 1 - first;
    s[second] = sc[second].scan(resid - sc[first].model(s[first]));
    s[first] = sc[first].scan(resid - sc[second].model(s[second]));
    return s;
}

/// scanCyclic on a dense trace: the pitch scan costs (grid points) × (samples), and the grid grows with
/// the sample density up to the 0.5 mm shortest pitch, so a 10^6-row file took minutes. Samples closer
/// than an eighth of the shortest pitch add nothing to locating the pitch: consecutive samples are
/// averaged in groups that span at most 0.5 mm / 8 along the bar (a sinusoid of the shortest pitch keeps
/// over 97 % of its amplitude), the pitch is found on the averages, and the amplitudes are then fitted on
/// every sample by the caller. Traces sampled coarser than that are scanned as they are.
std::array<CyclicScan, 2> scanCyclicDecimated(const std::array<CyclicScanner, 2>& sc, const std::vector<double>& theta,
                                              const Eigen::VectorXd& resid, double radius, double stepRad)
{
    const double groupLen = 0.5e-3 / 8.0;
    const auto group = static_cast<std::size_t>(std::floor(groupLen / std::max(radius * stepRad, 1e-300)));
    if (group <= 1 || theta.size() < 4 * group)
        return scanCyclic(sc, resid);
    const std::size_t n = theta.size(), m = (n + group - 1) / group;
    std::vector<double> thetaR(m);
    Eigen::VectorXd residR(static_cast<Eigen::Index>(m));
    for (std::size_t g = 0; g < m; ++g) {
        const std::size_t b = g * group, e = std::min(n, b + group);
        double st = 0.0, sr = 0.0;
        for (std::size_t i = b; i < e; ++i) {
            st += theta[i];
            sr += resid(static_cast<Eigen::Index>(i));
        }
        thetaR[g] = st / static_cast<double>(e - b);
        residR(static_cast<Eigen::Index>(g)) = sr / static_cast<double>(e - b);
    }
    const double stepR = stepRad * static_cast<double>(group);
    const std::array<CyclicScanner, 2> scR{CyclicScanner(0, thetaR, radius, stepR),
                                           CyclicScanner(1, thetaR, radius, stepR)};
    return scanCyclic(scR, residR);
}

} // namespace

namespace {

/// Joint smooth fit outside the spike zones: circle + second harmonics + lost motion (constant and
/// linear in the axis coordinate, for position-dependent lost motion), then the cyclic pitches from its
/// residual and one refit with the cyclic regressors, so smooth terms and cyclic amplitudes do not
/// absorb each other.
Status jointFit(const io::BallBarTrace& t, const BallBarOptions& opt, RunDiagnostics& run)
{
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (!inAnySpikeZone(t.angleRad[i], run.sigma, opt.excludeDeg * kRadPerDeg))
            idx.push_back(i);
    }
    constexpr Eigen::Index kSmooth = 9;
    Eigen::MatrixXd a(static_cast<Eigen::Index>(idx.size()), kSmooth + 4);
    Eigen::VectorXd y(a.rows());
    std::vector<double> theta(idx.size());
    for (Eigen::Index k = 0; k < a.rows(); ++k) {
        const double th = t.angleRad[idx[k]];
        const double c = std::cos(th), s = std::sin(th);
        const double lx = lostMotionBasis(0, th, run.sigma), ly = lostMotionBasis(1, th, run.sigma);
        a.row(k).head(kSmooth) << 1.0, c, s, std::cos(2.0 * th), std::sin(2.0 * th), lx, lx * c, ly, ly * s;
        y(k) = t.deviationM[idx[k]];
        theta[k] = th;
    }
    if (a.rows() < 2 * a.cols())
        return makeError(ErrorCode::BadInput,
                         t.source + ": too few samples outside the reversal zones for the diagnostics");
    const std::array<CyclicScanner, 2> sc{CyclicScanner(0, theta, t.radiusM, meanStepRad(t)),
                                          CyclicScanner(1, theta, t.radiusM, meanStepRad(t))};
    const auto scans =
        scanCyclicDecimated(sc, theta, leastSquares(a.leftCols(kSmooth), y).resid, t.radiusM, meanStepRad(t));
    for (Eigen::Index k = 0; k < a.rows(); ++k) {
        for (int axis = 0; axis < 2; ++axis) {
            const auto [c, s] = sc[axis].columns(scans[axis].k, static_cast<std::size_t>(k));
            a(k, kSmooth + 2 * axis) = c;
            a(k, kSmooth + 2 * axis + 1) = s;
        }
    }
    const auto f = leastSquares(a, y);
    run.cos2M = f.coef(3);
    run.sin2M = f.coef(4);
    run.lostMotionM = {f.coef(5), f.coef(7)};
    run.residualRmsM = f.rms;
    for (int axis = 0; axis < 2; ++axis) {
        CyclicScan c = scans[axis];
        c.alpha = f.coef(kSmooth + 2 * axis);
        c.beta = f.coef(kSmooth + 2 * axis + 1);
        run.cyclic[axis] = sc[axis].result(c, f.rms * f.rms);
    }
    return Status::success();
}

} // namespace

Result<RunDiagnostics> analyzeRun(const io::BallBarTrace& t, const BallBarOptions& opt)
{
    RunDiagnostics run;
    run.source = t.source;
    run.sigma = t.directionSign();
    run.radiusM = t.radiusM;
    run.feedMPerS = t.feedMPerS;
    for (int axis = 0; axis < 2; ++axis) {
        for (double rev : reversalAngles(axis)) {
            if (auto ev = fitReversal(t, axis, rev, opt))
                run.events.push_back(*ev);
        }
    }
    const char* what = "centre, radius, circularity, scale mismatch, squareness, servo mismatch and cyclic error";
    if (auto s = requireFullCircle(t, opt, what); !s) {
        run.refusal = s.error().detail;
        run.refusalArgs = coverageArgs(t, coverageOf(t), opt);
        return run;
    }
    run.fullCircle = true;
    const auto circle = fitCircle(t.angleRad, t.deviationM);
    run.circularityM = circle.resid.maxCoeff() - circle.resid.minCoeff();
    run.radiusDeviationM = circle.coef(0);
    run.centerXM = circle.coef(1);
    run.centerYM = circle.coef(2);
    if (auto s = jointFit(t, opt, run); !s)
        return s.error();
    return run;
}

} // namespace axistune::tuning

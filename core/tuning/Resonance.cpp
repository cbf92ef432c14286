// SPDX-License-Identifier: GPL-3.0-or-later
// Resonance peaks of a measured loop FRF: robust local baseline (Tukey bisquare iteratively
// reweighted least squares, Holland & Welsch 1977) in dB against log f, coherence-weighted
// (inverse variance γ²/(1−γ²) of the magnitude estimate, Bendat & Piersol §9.2), peak by parabolic
// interpolation, −3 dB width; spec/current-loop-and-multisweep-frf.md §4.3 step 7. Rule: Resonance.h.
#include "core/tuning/Resonance.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace axistune::tuning {

namespace {

struct Point {
    double x = 0.0;  ///< log10 f
    double y = 0.0;  ///< dB
    double w = 1.0;  ///< weight
    std::size_t index = 0;
};

struct Line {
    double intercept = 0.0;  ///< value at the centre x0
    double slope = 0.0;
    double x0 = 0.0;
    double noise = 0.0;
    bool ok = false;
    double at(double x) const { return intercept + slope * (x - x0); }
};

double median(std::vector<double>& v)
{
    if (v.empty())
        return 0.0;
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    double m = *mid;
    if (v.size() % 2 == 0)
        m = 0.5 * (m + *std::max_element(v.begin(), mid));
    return m;
}

/// Weighted least-squares line through pts[lo, hi) with extra weights r (x centred at x0).
bool weightedLine(const std::vector<Point>& pts, std::size_t lo, std::size_t hi, const std::vector<double>& r,
                  double x0, double& a, double& b)
{
    double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t k = lo; k < hi; ++k) {
        const double w = pts[k].w * r[k - lo];
        const double x = pts[k].x - x0;
        sw += w;
        sx += w * x;
        sy += w * pts[k].y;
        sxx += w * x * x;
        sxy += w * x * pts[k].y;
    }
    if (!(sw > 0.0))
        return false;
    const double det = sw * sxx - sx * sx;
    if (det <= 1e-12 * sw * sw * 1e-6) {  // all weight at one abscissa: constant
        a = sy / sw;
        b = 0.0;
        return true;
    }
    b = (sw * sxy - sx * sy) / det;
    a = (sy - b * sx) / sw;
    return true;
}

/// Robust line through pts[lo, hi), evaluated around x0.
Line robustLine(const std::vector<Point>& pts, std::size_t lo, std::size_t hi, double x0)
{
    Line line;
    line.x0 = x0;
    const std::size_t n = hi - lo;
    if (n < 5)
        return line;
    std::vector<double> rw(n, 1.0);
    std::vector<double> absRes(n);
    // Start from medians of the two halves (breakdown 50 %), so that a few wild points (near-zero
    // magnitudes far below the trend) cannot pull the starting line where the bisquare keeps it.
    std::vector<double> yl, yr, xl, xr;
    for (std::size_t k = lo; k < hi; ++k) {
        auto& ys = k - lo < n / 2 ? yl : yr;
        auto& xs = k - lo < n / 2 ? xl : xr;
        ys.push_back(pts[k].y);
        xs.push_back(pts[k].x);
    }
    const double mxl = median(xl), mxr = median(xr), myl = median(yl), myr = median(yr);
    double b = mxr > mxl ? (myr - myl) / (mxr - mxl) : 0.0;
    double a = 0.5 * (myl + myr) + b * (x0 - 0.5 * (mxl + mxr));
    double scale = 0.0;
    for (int it = 0; it < 30; ++it) {
        for (std::size_t k = 0; k < n; ++k)
            absRes[k] = std::abs(pts[lo + k].y - (a + b * (pts[lo + k].x - x0)));
        std::vector<double> tmp = absRes;
        scale = 1.4826 * median(tmp);
        const double c = 4.685 * std::max(scale, 1e-6);
        for (std::size_t k = 0; k < n; ++k) {
            const double u = absRes[k] / c;
            rw[k] = u < 1.0 ? (1.0 - u * u) * (1.0 - u * u) : 0.0;
        }
        double a2 = 0.0, b2 = 0.0;
        if (!weightedLine(pts, lo, hi, rw, x0, a2, b2))
            break;
        const bool converged = std::abs(a2 - a) < 1e-9 && std::abs(b2 - b) < 1e-9;
        a = a2;
        b = b2;
        if (converged)
            break;
    }
    // Noise: second differences of neighbouring points remove the smooth structure (trend, peaks
    // several points wide) and leave sqrt(6)·σ of independent scatter.
    std::vector<double> d2;
    for (std::size_t k = lo + 1; k + 1 < hi; ++k)
        d2.push_back(std::abs(pts[k + 1].y - 2.0 * pts[k].y + pts[k - 1].y));
    line.intercept = a;
    line.slope = b;
    line.noise = 1.4826 * median(d2) / std::sqrt(6.0);
    line.ok = true;
    return line;
}

/// Most points a baseline fit uses. A wider window (a dense FRF, 10^5 points) is fitted through every
/// stride-th point, and the fit is reused for the next stride points: near-linear time in the FRF's size
/// (bench/bench_notch.cpp) where every point with its full window was quadratic. FRFs whose windows hold
/// at most this many points (every measured FRF so far) are fitted exactly as before.
constexpr std::size_t kMaxBaselinePoints = 512;

/// robustLine through every stride-th point of pts[lo, hi); the noise from second differences of
/// neighbouring points at every stride-th position.
Line sampledRobustLine(const std::vector<Point>& pts, std::size_t lo, std::size_t hi, double x0, std::size_t stride)
{
    if (stride <= 1)
        return robustLine(pts, lo, hi, x0);
    std::vector<Point> sub;
    sub.reserve((hi - lo) / stride + 1);
    for (std::size_t k = lo; k < hi; k += stride)
        sub.push_back(pts[k]);
    Line line = robustLine(sub, 0, sub.size(), x0);
    std::vector<double> d2;
    for (std::size_t k = lo + 1; k + 1 < hi; k += stride)
        d2.push_back(std::abs(pts[k + 1].y - 2.0 * pts[k].y + pts[k - 1].y));
    line.noise = 1.4826 * median(d2) / std::sqrt(6.0);
    return line;
}

/// Position (in x) where the excess crosses `level` walking from k outwards by `dir`; NaN if the
/// walk leaves the contiguous usable run or the window before crossing.
double crossing(const std::vector<Point>& pts, const Line& base, std::size_t k, int dir, double level, double xLimit)
{
    std::size_t cur = k;
    while (true) {
        const std::ptrdiff_t next = static_cast<std::ptrdiff_t>(cur) + dir;
        if (next < 0 || next >= static_cast<std::ptrdiff_t>(pts.size()))
            return std::nan("");
        const auto nx = static_cast<std::size_t>(next);
        // Contiguity: the next usable point must be the next raw point.
        const auto gap = dir > 0 ? pts[nx].index - pts[cur].index : pts[cur].index - pts[nx].index;
        if (gap != 1)
            return std::nan("");
        if (std::abs(pts[nx].x - pts[k].x) > xLimit)
            return std::nan("");
        const double e0 = pts[cur].y - base.at(pts[cur].x);
        const double e1 = pts[nx].y - base.at(pts[nx].x);
        if (e1 <= level) {
            const double t = (e0 - level) / (e0 - e1);
            return pts[cur].x + t * (pts[nx].x - pts[cur].x);
        }
        cur = nx;
    }
}

/// Vertex of the parabola through the excess over `base` at k and its neighbours, when they are
/// contiguous usable points and the parabola opens downwards; xp/ep unchanged otherwise.
void parabolicPeak(const std::vector<Point>& pts, const Line& base, std::size_t k, double& xp, double& ep)
{
    if (k == 0 || k + 1 >= pts.size() || pts[k].index - pts[k - 1].index != 1 || pts[k + 1].index - pts[k].index != 1)
        return;
    const double x0 = pts[k - 1].x, x1 = pts[k].x, x2 = pts[k + 1].x;
    const double e0 = pts[k - 1].y - base.at(x0), e1 = pts[k].y - base.at(x1), e2 = pts[k + 1].y - base.at(x2);
    const double d01 = (e1 - e0) / (x1 - x0), d12 = (e2 - e1) / (x2 - x1);
    const double curv = (d12 - d01) / (x2 - x0);  // Newton form: e0 + d01(x−x0) + curv(x−x0)(x−x1)
    if (!(curv < 0.0))
        return;
    const double xc = std::clamp(0.5 * (x0 + x1) - d01 / (2.0 * curv), x0, x2);
    xp = xc;
    ep = e0 + d01 * (xc - x0) + curv * (xc - x0) * (xc - x1);
}

}  // namespace

Result<std::vector<Resonance>> findResonances(const dsp::FrequencyResponse& frf, const ResonanceOptions& o)
{
    if (!(o.halfWindowOctaves > 0.0) || !(o.minHeightDb > 3.0) || !(o.noiseFactor >= 0.0) || !(o.minCoherence >= 0.0)
        || !(o.minCoherence < 1.0) || !(o.fmaxHz > o.fminHz))
        return makeError(ErrorCode::BadInput, "resonance options: need half window > 0, min height > 3 dB, noise factor "
                                              ">= 0, 0 <= min coherence < 1, fmax > fmin");
    std::vector<Point> pts;
    for (std::size_t i = 0; i < frf.size(); ++i) {
        const double f = frf.freqHz[i];
        const double mag = std::abs(frf.h[i]);
        const double coh = i < frf.coherence.size() ? frf.coherence[i] : std::nan("");
        const bool isValid = i >= frf.valid.size() || frf.valid[i];
        if (!isValid || !(f > 0.0) || !std::isfinite(mag) || !(mag > 0.0))
            continue;
        if (!std::isnan(coh) && !(coh >= o.minCoherence))
            continue;
        double w = 1.0;
        if (!std::isnan(coh)) {
            const double g2 = std::min(coh, 0.999);
            w = g2 / (1.0 - g2);
        }
        pts.push_back({std::log10(f), 20.0 * std::log10(mag), w, i});
    }
    if (pts.size() < 5)
        return makeError(ErrorCode::BadInput, "only " + std::to_string(pts.size())
                                                  + " usable points (valid, finite, coherence >= "
                                                  + std::to_string(o.minCoherence) + "); need at least 5");

    const double halfDec = o.halfWindowOctaves * std::log10(2.0);
    std::vector<Line> base(pts.size());
    std::size_t lo = 0, hi = 0;
    std::size_t lastFit = 0;
    for (std::size_t k = 0; k < pts.size(); ++k) {
        while (pts[lo].x < pts[k].x - halfDec)
            ++lo;
        while (hi < pts.size() && pts[hi].x <= pts[k].x + halfDec)
            ++hi;
        const std::size_t stride = (hi - lo + kMaxBaselinePoints - 1) / kMaxBaselinePoints;
        if (stride <= 1 || k == 0 || k - lastFit >= stride) {
            base[k] = sampledRobustLine(pts, lo, hi, pts[k].x, stride);
            lastFit = k;
        } else {
            base[k] = base[lastFit]; // a line: evaluated at pts[k].x through its own x0
        }
    }
    auto excess = [&](std::size_t k, const Line& l) { return pts[k].y - l.at(pts[k].x); };

    struct Cand {
        std::size_t k;
        double e;
    };
    std::vector<Cand> cands;
    const double xmin = o.fminHz > 0.0 ? std::log10(o.fminHz) : -1e300;
    const double xmax = std::log10(std::min(o.fmaxHz, 1e300));
    for (std::size_t k = 0; k < pts.size(); ++k) {
        if (!base[k].ok || pts[k].x < xmin || pts[k].x > xmax)
            continue;
        const double e = excess(k, base[k]);
        const bool leftOk = k == 0 || excess(k - 1, base[k]) <= e;
        const bool rightOk = k + 1 == pts.size() || excess(k + 1, base[k]) < e;
        if (leftOk && rightOk && e >= o.minHeightDb && e >= o.noiseFactor * base[k].noise)
            cands.push_back({k, e});
    }
    std::sort(cands.begin(), cands.end(), [](const Cand& a, const Cand& b) { return a.e > b.e; });

    std::vector<Resonance> out;
    std::vector<std::pair<double, double>> bands;  // accepted −3 dB bands in x
    for (const auto& c : cands) {
        const std::size_t k = c.k;
        const Line& l = base[k];
        double xp = pts[k].x, ep = c.e;
        parabolicPeak(pts, l, k, xp, ep);
        const double level = ep - 3.0;
        const double xl = crossing(pts, l, k, -1, level, halfDec);
        const double xr = crossing(pts, l, k, +1, level, halfDec);
        if (std::isnan(xl) && std::isnan(xr))
            continue;
        const double fp = std::pow(10.0, xp);
        double fl = std::isnan(xl) ? std::nan("") : std::pow(10.0, xl);
        double fr = std::isnan(xr) ? std::nan("") : std::pow(10.0, xr);
        const bool oneSided = std::isnan(fl) || std::isnan(fr);
        if (std::isnan(fl))
            fl = fp - (fr - fp);
        if (std::isnan(fr))
            fr = fp + (fp - fl);
        const double bl = std::log10(std::max(fl, 1e-300)), br = std::log10(fr);
        bool inside = false;
        for (const auto& [a, b] : bands)
            inside = inside || (xp >= a && xp <= b) || (a >= bl && a <= br) || (b >= bl && b <= br);
        if (inside)
            continue;
        bands.emplace_back(bl, br);
        Resonance r;
        r.freqHz = fp;
        r.peakDb = ep;
        r.widthHz = fr - fl;
        r.baselineDb = l.at(xp);
        r.levelDb = r.baselineDb + ep;
        r.noiseDb = l.noise;
        r.widthOneSided = oneSided;
        r.index = pts[k].index;
        out.push_back(r);
    }
    std::sort(out.begin(), out.end(), [](const Resonance& a, const Resonance& b) { return a.freqHz < b.freqHz; });
    return out;
}

}  // namespace axistune::tuning

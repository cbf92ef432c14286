// SPDX-License-Identifier: GPL-3.0-or-later
// Lost-motion identification and compensation, spec/lost-motion-and-two-inertia.md §1.5 (LM-0, eq. 4.5),
// §4.3 (LM-1), §1.8/§4.4 (LM-2: Δx = (A + B·x)·ΔT, eq. 4.12, with the corrected general two-point form
// of §1.8 instead of the printed (4.13), which is exact only for ΔT₁ = ΔT₂), §1.9/§4.5 (LM-3, eq. 4.14).
#include "core/tuning/LostMotion.h"

#include "core/model/Constants.h"
#include "core/model/Number.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace axistune::tuning {
namespace {

using model::kPi;
using model::kRadPerDeg;
constexpr double kDistinctXM = 1e-6;           ///< x values closer than this count as one position
constexpr double kApparentThesisUmPerNmM = 17; ///< Fig. 4.4(a), spec §1.4

std::string fmtG(double v)
{
    return model::formatNumber(v, 3);
}

double wrapPi(double a)
{
    return std::remainder(a, 2.0 * kPi);
}
double sgn(double v)
{
    return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0);
}
double axisProjection(int axis, double theta)
{
    return axis == 0 ? std::cos(theta) : std::sin(theta);
}

void addGuards(LostMotionFit& f, std::span<const LostMotionPoint> pts)
{
    if (!(f.aMPerNm > 0.0))
        f.warnings.push_back("A = " + fmtG(f.aMPerNm * 1e6) +
                             " um/(N m) is not positive: elastic lost motion gives A > 0 (check the step sign and dT)");
    if (f.bPerNm < 0.0)
        f.warnings.push_back("B = " + fmtG(f.bPerNm) +
                             " 1/(N m) is negative: lost motion should grow with the spring length (check x0 and the "
                             "screw direction sign)");
    double xMax = 0.0;
    for (const auto& p : pts)
        xMax = std::max(xMax, std::abs(p.xM));
    if (std::abs(f.bPerNm) * xMax > 10.0 * std::abs(f.aMPerNm))
        f.warnings.push_back("B·x_max = " + fmtG(std::abs(f.bPerNm) * xMax * 1e6) +
                             " um/(N m) exceeds 10·A: typical of a "
                             "unit error such as the thesis's B = 2.39e-4 (spec §1.11.2)");
    if (f.method != LostMotionMethod::BFree)
        f.warnings.push_back("apparent position-dependent compliance B = " + fmtG(f.bPerNm * 1e6) +
                             " um/(N m m) (thesis test rig, Fig. 4.4(a): about " + fmtG(kApparentThesisUmPerNmM) + ")");
}

/// General exact two-point form (spec §1.8, corrected (4.13)) and the printed form for comparison.
void fitTwoPoint(LostMotionFit& f, const LostMotionPoint& p1, const LostMotionPoint& p2)
{
    f.method = LostMotionMethod::TwoPoint;
    f.bPerNm = (p1.dxM / p1.dTNm - p2.dxM / p2.dTNm) / (p1.xM - p2.xM);
    f.aMPerNm = p1.dxM / p1.dTNm - f.bPerNm * p1.xM;
    const double den = p1.xM * p1.dTNm - p2.xM * p2.dTNm;
    if (std::abs(den) > 0.0) {
        f.printedB = (p1.dxM - p2.dxM) / den;
        f.printedA = p1.dxM / p1.dTNm - *f.printedB * p1.xM;
    }
    if (std::abs(p1.dTNm - p2.dTNm) / (0.5 * (p1.dTNm + p2.dTNm)) > 0.05)
        f.warnings.push_back("the two torque changes differ by more than 5 %: the printed two-point form (4.13) "
                             "would be wrong; the general form is used");
}

/// Linear least squares on the regressors [ΔT_i, x_i·ΔT_i] (spec §1.8), with standard errors.
void fitLeastSquares(LostMotionFit& f, std::span<const LostMotionPoint> pts)
{
    f.method = LostMotionMethod::LeastSquares;
    const auto n = static_cast<Eigen::Index>(pts.size());
    Eigen::MatrixXd a(n, 2);
    Eigen::VectorXd y(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        a.row(i) << pts[i].dTNm, pts[i].xM * pts[i].dTNm;
        y(i) = pts[i].dxM;
    }
    const Eigen::Vector2d c = a.colPivHouseholderQr().solve(y);
    f.aMPerNm = c(0);
    f.bPerNm = c(1);
    const double rss = (y - a * c).squaredNorm();
    const Eigen::Matrix2d cov = (a.transpose() * a).inverse() * (rss / static_cast<double>(n - 2));
    f.aStdErr = std::sqrt(cov(0, 0));
    f.bStdErr = std::sqrt(cov(1, 1));
}

} // namespace

const char* lostMotionMethodName(LostMotionMethod m)
{
    switch (m) {
    case LostMotionMethod::BFree:
        return "b-free";
    case LostMotionMethod::TwoPoint:
        return "two-point";
    case LostMotionMethod::LeastSquares:
        return "least-squares";
    }
    return "?";
}

Result<LostMotionFit> fitLostMotion(std::span<const LostMotionPoint> pts, bool bFree)
{
    if (pts.empty())
        return makeError(ErrorCode::BadInput, "lost-motion fit: no reversal events");
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const auto& p = pts[i];
        if (!std::isfinite(p.xM) || !std::isfinite(p.dTNm) || !std::isfinite(p.dxM))
            return makeError(ErrorCode::BadInput,
                             "lost-motion point " + std::to_string(i) + " (" + p.source + "): not finite");
        if (!(p.dTNm > 0.0))
            return makeError(ErrorCode::BadInput, "lost-motion point " + std::to_string(i) + " (" + p.source +
                                                      "): torque change dT must be positive (is " + fmtG(p.dTNm) +
                                                      " N m)");
    }
    std::vector<double> xs;
    for (const auto& p : pts) {
        if (std::none_of(xs.begin(), xs.end(), [&](double x) { return std::abs(x - p.xM) < kDistinctXM; }))
            xs.push_back(p.xM);
    }
    LostMotionFit f;
    if (bFree || xs.size() < 2) {
        f.method = LostMotionMethod::BFree;
        double s = 0.0;
        for (const auto& p : pts)
            s += p.dxM / p.dTNm;
        f.aMPerNm = s / static_cast<double>(pts.size()); // spec §4.4: A = mean(Δx_i/ΔT_i)
        if (!bFree)
            f.warnings.push_back("all events at one screw position: B cannot be identified and is fixed at 0");
    } else if (pts.size() == 2) {
        fitTwoPoint(f, pts[0], pts[1]);
    } else {
        fitLeastSquares(f, pts);
    }
    double ss = 0.0;
    for (const auto& p : pts) {
        const double r = p.dxM - (f.aMPerNm + f.bPerNm * p.xM) * p.dTNm;
        f.residualsM.push_back(r);
        ss += r * r;
    }
    f.residualRmsM = std::sqrt(ss / static_cast<double>(pts.size()));
    addGuards(f, pts);
    return f;
}

Result<std::vector<LostMotionPoint>> extractLostMotionPoints(const io::BallBarTrace& t, const LostMotionSetup& setup,
                                                             const BallBarOptions& opt)
{
    const char* axisKey = setup.axis == 0 ? "dT_x_Nm" : "dT_y_Nm";
    const auto& dT = setup.axis == 0 ? t.dTxNm : t.dTyNm;
    if (!dT)
        return makeError(ErrorCode::BadInput, t.source + ": metadata '" + axisKey +
                                                  "' missing (the reversal torque change of that axis, from the servo "
                                                  "trace, is needed for lost-motion identification)");
    std::vector<LostMotionPoint> pts;
    std::string lastError;
    const std::array<double, 2> revs =
        setup.axis == 0 ? std::array<double, 2>{0.0, kPi} : std::array<double, 2>{0.5 * kPi, 1.5 * kPi};
    for (double rev : revs) {
        auto ev = fitReversal(t, setup.axis, rev, opt);
        if (!ev) {
            lastError = ev.error().detail;
            continue;
        }
        pts.push_back({setup.screwOffsetM + setup.screwSign * ev->tableCoordM, *dT, ev->stepM, t.source, rev});
    }
    if (pts.empty())
        return makeError(ErrorCode::BadInput, lastError);
    return pts;
}

double conventionalCompensation(double velocity, double backlashM, bool holdLast, double lastDirection)
{
    double dir = sgn(velocity);
    if (dir == 0.0 && holdLast)
        dir = sgn(lastDirection);
    return 0.5 * backlashM * dir;
}

double proposedCompensation(double a, double b, double x, double torque)
{
    return (a + b * x) * torque;
}

double compensationAngleRad(double xc, double lead)
{
    return xc / (lead / (2.0 * kPi));
}

double materialComplianceSlope(double lead, double rootDiameter, double shearModulus, double m)
{
    return 16.0 * lead / (m * kPi * kPi * shearModulus * std::pow(rootDiameter, 4));
}

namespace {

/// Deepest inward notch (≥ 0) in the zone just after each reversal of the axis, below the lower level of
/// the local step fit of that reversal: the "cut-in" of spec §1.10.
double cutIn(const io::BallBarTrace& t, int axis, const BallBarOptions& opt)
{
    double worst = 0.0;
    const double sigma = t.directionSign();
    for (double rev : axis == 0 ? std::array<double, 2>{0.0, kPi} : std::array<double, 2>{0.5 * kPi, 1.5 * kPi}) {
        auto ev = fitReversal(t, axis, rev, opt);
        if (!ev)
            continue;
        for (std::size_t i = 0; i < t.size(); ++i) {
            const double d = sigma * wrapPi(t.angleRad[i] - rev);
            if (d <= 0.0 || d >= opt.excludeDeg * kRadPerDeg)
                continue;
            const auto& c = ev->poly;
            // Inward of the lower of the two levels either side of the step: a gradual transition
            // between the levels is lost motion, not a cut-in.
            const double lower = c[0] + d * (c[1] + d * (c[2] + d * c[3])) -
                                 0.5 * std::abs(ev->stepM) * std::abs(axisProjection(axis, t.angleRad[i]));
            worst = std::max(worst, lower - t.deviationM[i]);
        }
    }
    return worst;
}

} // namespace

Result<CompensationPrediction> predictCompensation(const io::BallBarTrace& t, const LostMotionSetup& setup,
                                                   const LostMotionFit& fit, double xbl, const BallBarOptions& opt)
{
    const auto& dT = setup.axis == 0 ? t.dTxNm : t.dTyNm;
    if (!dT)
        return makeError(ErrorCode::BadInput, t.source + ": metadata '" + (setup.axis == 0 ? "dT_x_Nm" : "dT_y_Nm") +
                                                  "' missing (needed to predict the compensation)");
    const int axis = setup.axis;
    const double sigma = t.directionSign();
    const double ex = opt.excludeDeg * kRadPerDeg;
    std::vector<ReversalEvent> events;
    for (double rev : axis == 0 ? std::array<double, 2>{0.0, kPi} : std::array<double, 2>{0.5 * kPi, 1.5 * kPi}) {
        if (auto ev = fitReversal(t, axis, rev, opt))
            events.push_back(*ev);
    }
    const double centre = axis == 0 ? t.centerXM : t.centerYM;
    CompensationPrediction p;
    p.conventionalBacklashM = xbl;
    p.angleRad = t.angleRad;
    p.measuredM = t.deviationM;
    for (std::size_t i = 0; i < t.size(); ++i) {
        const double th = t.angleRad[i];
        const double u = axisProjection(axis, th);
        // G: normalised radial deformation, 2·lm(θ) away from reversals (= ±|u| steps), and the measured
        // transition shape inside a reversal zone (the deformation follows the torque, §1.9).
        double g = 2.0 * lostMotionBasis(axis, th, sigma);
        for (const auto& ev : events) {
            const double d = sigma * wrapPi(th - ev.angleRad);
            if (std::abs(d) >= ex || std::abs(ev.stepM) <= std::max(3.0 * ev.stepStdErrM, 0.05e-6))
                continue;
            const auto& c = ev.poly;
            const double smooth = c[0] + d * (c[1] + d * (c[2] + d * c[3]));
            g = (t.deviationM[i] - smooth) / (0.5 * ev.stepM);
        }
        const double x = setup.screwOffsetM + setup.screwSign * (centre + t.radiusM * u);
        const double proposed = (fit.aMPerNm + fit.bPerNm * x) * 0.5 * *dT * g;
        const double conventional = xbl * lostMotionBasis(axis, th, sigma);
        p.proposedM.push_back(t.deviationM[i] - proposed);
        p.conventionalM.push_back(t.deviationM[i] - conventional);
    }
    if (requireFullCircle(t, opt, "circularity").ok()) {
        p.measuredCircularityM = circularityOf(p.angleRad, p.measuredM).value();
        p.proposedCircularityM = circularityOf(p.angleRad, p.proposedM).value();
        p.conventionalCircularityM = circularityOf(p.angleRad, p.conventionalM).value();
    }
    io::BallBarTrace tmp = t;
    p.measuredCutInM = cutIn(tmp, axis, opt);
    tmp.deviationM = p.proposedM;
    p.proposedCutInM = cutIn(tmp, axis, opt);
    tmp.deviationM = p.conventionalM;
    p.conventionalCutInM = cutIn(tmp, axis, opt);
    return p;
}

} // namespace axistune::tuning

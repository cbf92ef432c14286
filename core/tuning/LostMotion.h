// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Lost motion of ball-screw axes (spec/lost-motion-and-two-inertia.md chapter 4 and §4.2–4.5):
//   LM-0 conventional step compensation ±x_bl/2 (4.5),
//   LM-1 reversal events (x, ΔT, Δx) from ball-bar traces,
//   LM-2 identification of Δx = (A + B·x)·ΔT (4.12) by least squares, the general two-point form or B = 0,
//   LM-3 the torque-synchronous compensation x_c = (A + B·x_bs)·T_m (4.14),
// and the prediction of both compensations on a measured trace (cut-in of the conventional step).
// SI throughout: x in m, ΔT in N·m, A in m/(N·m), B in 1/(N·m).

#include "core/io/BallBarCsv.h"
#include "core/model/Result.h"
#include "core/tuning/BallBarDiagnostics.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace axistune::tuning {

/// One reversal event: screw spring length x, torque change ΔT (peak-to-peak), lost motion Δx.
struct LostMotionPoint {
    double xM = 0.0;
    double dTNm = 0.0;
    double dxM = 0.0;
    std::string source;    ///< trace it came from (empty for hand-entered points)
    double angleRad = 0.0; ///< reversal angle in that trace
};

struct LostMotionSetup {
    int axis = 0;              ///< 0 = first plane axis ("x"), 1 = second ("y")
    double screwOffsetM = 0.0; ///< x₀: spring length at table coordinate 0
    double screwSign = 1.0;    ///< s: x_bs = x₀ + s·X_t (spec §4.1; the thesis has s = +1)
};

enum class LostMotionMethod { BFree, TwoPoint, LeastSquares };
const char* lostMotionMethodName(LostMotionMethod m);

struct LostMotionFit {
    double aMPerNm = 0.0;
    double bPerNm = 0.0;
    LostMotionMethod method = LostMotionMethod::BFree;
    std::vector<double> residualsM; ///< Δx_i − (A + B x_i) ΔT_i
    double residualRmsM = 0.0;
    std::optional<double> aStdErr, bStdErr;   ///< least squares with more points than unknowns
    std::optional<double> printedA, printedB; ///< thesis (4.13) as printed, for comparison (two points)
    std::vector<std::string> warnings;        ///< plausibility guards of spec §4.4
};

/// LM-2. `bFree` forces B = 0 (A = mean Δx/ΔT); a single distinct x forces it too, with a warning.
Result<LostMotionFit> fitLostMotion(std::span<const LostMotionPoint> points, bool bFree = false);

/// LM-1: the events of one axis in one trace (both reversals where covered); needs dT of that axis.
Result<std::vector<LostMotionPoint>>
extractLostMotionPoints(const io::BallBarTrace& trace, const LostMotionSetup& setup, const BallBarOptions& opt = {});

/// LM-0 (4.5) with the reading of spec §6 #6: +x_bl/2 moving forward, −x_bl/2 backward, and at
/// standstill 0 (as printed) or, when holdLast, the value for `lastDirection` (not from the source).
double conventionalCompensation(double velocity, double backlashM, bool holdLast = false, double lastDirection = 1.0);
/// LM-3 (4.14): x_c = (A + B·x_bs)·T_m [m].
double proposedCompensation(double aMPerNm, double bPerNm, double screwLengthM, double torqueNm);
/// Position compensation as a motor angle θ_c = x_c / R, R = lead / 2π [m/rad].
double compensationAngleRad(double compensationM, double leadMPerRev);

/// Material-mechanics slope of A(x) (spec §1.4, eq. 4.4): 16·p / (m·π²·G·d_r⁴) [1/(N·m)] — the torsional
/// compliance of the screw converted to the table, per metre of spring length, with the empirical factor m.
/// The thesis finds measured compliances ~10× this value with m = 1 (m ≈ 0.09 on its rig).
double materialComplianceSlope(double leadMPerRev, double rootDiameterM, double shearModulusPa, double m = 1.0);

/// Both compensations applied to a measured trace (the prediction drawn over the measured one).
struct CompensationPrediction {
    std::vector<double> angleRad;
    std::vector<double> measuredM;
    std::vector<double> proposedM;     ///< measured − torque-synchronous compensation
    std::vector<double> conventionalM; ///< measured − step compensation
    double conventionalBacklashM = 0.0;
    std::optional<double> measuredCircularityM, proposedCircularityM, conventionalCircularityM;
    double proposedCutInM = 0.0; ///< deepest inward notch right after a reversal (≥ 0)
    double conventionalCutInM = 0.0;
    double measuredCutInM = 0.0;
};

/// Predicts both compensations of one axis on a trace. The deformation follows the torque (§1.9), and
/// the ball-bar file carries only ΔT, so the transient shape of the torque is taken from the measured
/// transition itself; the step compensation switches at the reversal (`conventionalBacklashM` = x_bl).
Result<CompensationPrediction> predictCompensation(const io::BallBarTrace& trace, const LostMotionSetup& setup,
                                                   const LostMotionFit& fit, double conventionalBacklashM,
                                                   const BallBarOptions& opt = {});

} // namespace axistune::tuning

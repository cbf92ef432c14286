// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one-button tuner over the travel (internal to core/autotune; AutoTune.h Options::positions; docs/tuning.md
// "Over the travel"): the sequence's class and what its steps share. The steps live in files of their own:
//   AutoTunePositions.cpp        the sequence (safety envelope ... apply), moving between the positions, the JSON;
//   AutoTunePositionsFrf.cpp     the measurements: the FRF at every position, the move, the verification;
//   AutoTunePositionsNotches.cpp the notch designs for a resonance that moves over the travel and the rule that
//                                picks one (AutoTunePositionsNotches.h);
//   AutoTunePositionsDesign.cpp  the PI search over every position's plant, the velocity PI and position gain.

#include "core/autotune/AutoTune.h"
#include "core/autotune/AutoTuneRun.h"
#include "core/device/AdaptiveFrf.h"
#include "core/dsp/DigitalFilter.h"
#include "core/dsp/FrequencyResponse.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/tuning/Notch.h"
#include "core/tuning/Resonance.h"
#include "core/tuning/VelocityLoop.h"

#include <complex>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace axistune::autotune::detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
/// Smallest integral corner k_i/k_p [rad/s] (1 Hz) of a PI the search considers: a slower integrator leaves the
/// loop seconds to settle (the drive's FRF settle time follows the slowest closed-loop pole and refuses beyond 10 s).
inline constexpr double kMinIntegralCornerRadS = kTwoPi;
/// Crossover grid of the PI search (log steps).
inline constexpr int kGridSteps = 96;

/// An integer as text, without the locale.
std::string wholeText(long long n);

/// One position's measured loop: the valid lines of the plant (with the new notches) and of the measured T.
struct Site {
    double x = 0.0;
    device::AdaptiveFrfResult frf;
    dsp::FrequencyResponse plant; ///< P·Π N_new on the measured lines
    std::vector<double> f;
    std::vector<std::complex<double>> p;      ///< valid lines of `plant`
    std::vector<std::complex<double>> pSlide; ///< the same lines in motion: P/(1 − b·P) (SlidingPlant.h)
    double standstillDampingNmsPerRad = 0.0;  ///< b = Re(1/P) on the plant's lowest lines
    std::optional<tuning::Resonance> first;
    PositionFinal fin;
};

/// Margins of the open loop `l` on the lines `f`.
dsp::LoopMargins loopMarginsOn(const std::vector<double>& f, const std::vector<std::complex<double>>& l);
std::optional<double> finiteOr(double v);
/// Closed velocity loop and open loop of PI `pi` on a site's plant lines.
void piLoops(const tuning::VelocityPi& pi, const Site& s, std::vector<std::complex<double>>& l,
             std::vector<std::complex<double>>& t);
/// Open position loop K_p·T_v/(jω) at K_p = 1.
std::vector<std::complex<double>> positionOpen(const std::vector<double>& f,
                                               const std::vector<std::complex<double>>& tv);
std::vector<std::complex<double>> positionClosed(const std::vector<double>& f,
                                                 const std::vector<std::complex<double>>& tv, double kp);
/// The valid, finite lines of `r`.
void validOf(const dsp::FrequencyResponse& r, std::vector<double>& f, std::vector<std::complex<double>>& h);

/// The best PI over every position's plant (AutoTunePositionsDesign.cpp): PIs from tuning::velocityPiFromFrf on each
/// site's plant for a crossover on the log grid fBottom ... min(fTop, capHz) and a phase margin of the style plus
/// the reserve steps; one counts when it keeps the style's phase margin and gain margin + reserve on EVERY site's
/// plant; the one with the widest worst-case closed-loop bandwidth at a crossover of at least fReq wins.
struct PiSearch {
    bool found = false;
    tuning::VelocityPi pi;
    double crossoverHz = 0.0;
    double worstBandwidthHz = 0.0;
    std::size_t base = 0;                  ///< the site whose plant the PI was designed on
    std::vector<dsp::LoopMargins> margins; ///< per site
    double highestOkHz = 0.0;              ///< the highest crossover that kept the margins (any bandwidth)
    double fBottom = 0.0, fTop = 0.0;      ///< the grid searched
};
/// Errors: a site without a valid plant line.
Result<PiSearch> searchPi(const std::vector<Site>& sites, const StyleTargets& t, double traceRateHz, double capHz);

class Positions : public Run {
public:
    using Run::Run;
    Result<AutoTuneResult> run();

private:
    void afterRefusal() override { returnToStart(); }
    void returnToStart();
    /// Moves to x within the budget; the step's motion time grows by the move's.
    Status moveTo(double x, double& motionS);
    Result<device::AdaptiveFrfResult> measure(double pct, double& motionS);
    Result<Step> measurePositions(double pct);
    Result<Step> notches();
    Result<Step> velocityPi(double capHz);
    Result<Step> position();
    Result<Step> move();
    /// Empty when every position keeps the style's margins; else why not.
    Result<std::string> verify(Step& s);
    /// Each site's plant P = L/C of its measurement at the running PI, times every notch of `specs` (their
    /// prediction L_after/L_before on every line), and its valid lines.
    Status plantsWith(const std::vector<dsp::NotchSpec>& specs, double execRateHz);

    double m_start = 0.0; ///< where the axis stood
    bool m_moved = false;
    double m_pct = 0.0;
    std::vector<Site> m_sites;
    tuning::LoopForm m_form;
    tuning::VelocityPi m_pi;
    double m_fc = 0.0, m_kpPos = 0.0;
    double m_worstVelocityBwHz = 0.0; ///< the narrowest predicted closed velocity loop over the positions [Hz]
    Final m_fin;
};

} // namespace axistune::autotune::detail

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one-position sequence of the one-button tuner (internal to core/autotune). `Sequence::run` (AutoTune.cpp)
// runs its steps in order; they are in AutoTuneMeasure.cpp (safety envelope, current loop, FRF, notches),
// AutoTuneDesign.cpp (the plant, velocity PI, position gain) and AutoTuneCheck.cpp (move evaluation, verify). A step
// returns a refusal (every parameter already restored by `refuse`) or nothing and leaves what it found in the members.

#include "core/autotune/AutoTuneRun.h"
#include "core/autotune/SlidingPlant.h"
#include "core/device/AdaptiveFrf.h"
#include "core/dsp/FrequencyResponse.h"
#include "core/model/Capture.h"
#include "core/tuning/Notch.h"
#include "core/tuning/VelocityLoopDesign.h"

#include <complex>
#include <limits>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

namespace axistune::autotune::detail {

/// Non-linear fraction above which the FRF is measured again at twice the amplitude (friction).
inline constexpr double kRetryNonlinearFraction = 0.05;
/// Voltage-limited fraction above which the FRF is measured again at half the amplitude.
inline constexpr double kRetryVoltageFraction = 0.2;
inline constexpr double kMinFrfAmplitudePct = 2.5;
inline constexpr int kMaxFrfTries = 3;
/// Largest FRF peak the ladder goes to [% rated torque] (and never above the drive's own limit).
inline constexpr double kLadderPeakCapPct = 30.0;
/// Distance of the reversal that measures the backlash [m] (back and forth).
inline constexpr double kBacklashReversalM = 0.002;

/// An integer as text, without the locale.
std::string count(long long n);
bool finitePositive(double v);

struct Margins {
    double phaseMarginDeg = std::numeric_limits<double>::infinity();
    double phaseMarginFreqHz = 0.0;
    double gainMarginDb = std::numeric_limits<double>::infinity();
    double gainMarginFreqHz = 0.0;
    std::size_t gainCrossovers = 0;
};
Margins marginsOf(const std::vector<double>& f, const std::vector<std::complex<double>>& open);
nlohmann::json marginsJson(const Margins& m);
/// Valid lines of a response.
void validLines(const dsp::FrequencyResponse& r, std::vector<double>& f, std::vector<std::complex<double>>& h);
/// Closed position loop (position feedback K_p/s around the closed velocity loop T_v) on T_v's lines.
std::vector<std::complex<double>> positionClosedLoop(const std::vector<double>& f,
                                                     const std::vector<std::complex<double>>& tv, double kp);
const model::Channel* channelWithPrefix(const model::Capture& c, const std::string& prefix);

struct FrfFigures {
    std::size_t lines = 0, valid = 0, nonlinear = 0;
    std::map<std::string, std::size_t> invalidByReason;
};
FrfFigures figuresOf(const device::AdaptiveFrfResult& a);
nlohmann::json frfJson(const device::AdaptiveFrfResult& a, double amplitudePct);
/// The FRF step's refusal, if any: more than kMaxNonlinearFraction of the lines non-linear ("strong non-linearity"),
/// else fewer than kMinValidFraction valid ("coherence too low").
std::optional<std::string> frfRefusal(const FrfFigures& f);

class Sequence : public Run {
public:
    using Run::Run;

    Result<AutoTuneResult> run();

private:
    using Refusal = std::optional<AutoTuneResult>;

    AutoTuneResult aborted(const char* name)
    {
        return refuse(std::string("aborted by the user before the step ") + name, ErrorCode::Aborted);
    }
    /// Runs one test within the budget; a refusal reason on failure.
    Result<device::TestRun> test(const device::TestRequest& r, const std::string& what, double& motionS);

    Refusal safetyEnvelope();
    Refusal currentLoop();
    Refusal measureFrf();
    Refusal notches();
    /// The plant the PI is designed on: P = L/C of the measurement times the new notches, and P in motion.
    Refusal plant();
    Refusal velocityPi(double capHz);
    Refusal position();
    Refusal move();
    /// Sets m_again (and m_capHz) when the re-measured loop misses the margins and another design may run.
    Refusal verify(int attempt);

    device::DriveLimits m_limits;
    double m_ratedA = 0.0, m_maxTorqueNm = 0.0, m_amplitudePct = 0.0, m_stepA = 0.0;
    device::AdaptiveFrfResult m_measured;
    tuning::LoopForm m_form; ///< the drive's closed velocity loop T (complementary)
    tuning::NotchAnalysis m_notches;
    dsp::FrequencyResponse m_plant;
    StandstillDamping m_standstill;
    std::vector<double> m_pf;                          ///< the plant's valid lines [Hz]
    std::vector<std::complex<double>> m_ph, m_phSlide; ///< the plant on them, as measured and in motion
    tuning::VelocityLoopDesign m_design;
    Margins m_predicted;
    Margins m_predictedInMotion; ///< the same PI on the plant in motion (standstill damping removed)
    double m_fc = 0.0, m_kpPos = 0.0;
    std::optional<double> m_velocityBwHz; ///< −3 dB of the predicted closed velocity loop (nullopt: none in the band)
    double m_capHz = std::numeric_limits<double>::infinity();
    bool m_again = false;
    Final m_fin;
};

} // namespace axistune::autotune::detail

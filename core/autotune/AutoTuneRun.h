// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the one-position sequence (AutoTune.cpp) and the sequence over positions (AutoTunePositions.cpp) share
// (internal to core/autotune): the rules' constants, and a run's bookkeeping — the parameters before, what the run
// wrote (restored with read-back on a refusal), the motion time against the budget, step announcements and the
// adaptive FRF with the sequence's band.

#include "core/autotune/AutoTune.h"
#include "core/device/AdaptiveFrf.h"
#include "core/device/Drive.h"
#include "core/model/Number.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace axistune::autotune::detail {

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
/// A resonance within this factor of the required crossover (either side) can be neither notched (the notch's
/// phase lag at the crossover) nor dominated by the loop gain: refused.
inline constexpr double kResonanceSeparation = 3.0;
/// Lines of the FRF that must be valid (σ_H/|H| below the limit; else "coherence too low").
inline constexpr double kMinValidFraction = 0.6;
/// Lines flagged non-linear (passes disagreeing beyond their noise) above which the loop is not tuned.
inline constexpr double kMaxNonlinearFraction = 0.2;
/// Motion budget of one adaptive FRF [s].
inline constexpr double kFrfBudgetS = 5.0;
/// The multisine band: lines at (m + 1/3)·10 Hz from 20 Hz to 0.975 of the trace rate (docs/multisine.md).
inline constexpr double kFrfMinHz = 20.0;
inline constexpr double kFrfSpacingHz = 10.0;
/// The PI is designed for the style's phase margin plus this, so that the measured loop keeps the style's.
inline constexpr double kDesignPhaseReserveDeg = 1.0;
/// The PI is designed for the style's phase margin plus each of these; the design with the widest predicted
/// closed-loop bandwidth that keeps the margins is chosen.
inline constexpr double kDesignPhaseSteps[] = {0.0, 5.0, 10.0, 15.0, 20.0};
/// The design keeps this much more gain margin than the style asks of the measured loop.
inline constexpr double kDesignGainReserveDb = 1.0;
/// Designs tried (velocity PI, position gain, move, verify) before the run refuses.
inline constexpr int kMaxDesignAttempts = 3;
/// Read-back tolerance (a Modbus drive stores float32).
inline constexpr double kReadBackRel = 1e-6;
/// A value read back equals the one written within kReadBackRel (relative, absolute below 1).
inline bool readsBackAs(double read, double written)
{
    return std::abs(read - written) <= kReadBackRel * std::max(1.0, std::abs(written));
}

/// A number as text, without the locale.
inline std::string num(double v, int significant = 4)
{
    return model::formatNumber(v, significant);
}

/// A run's bookkeeping; the sequences derive from it.
class Run {
public:
    Run(device::Drive& drive, const Options& o);
    virtual ~Run() = default;

protected:
    /// A refusal: restores every parameter written so far (and whatever afterRefusal() adds), returns the result.
    AutoTuneResult refuse(const std::string& reason, ErrorCode code = ErrorCode::Safety);
    AutoTuneResult refuseWith(const Error& e) { return refuse(e.detail, e.code); }
    /// After a refusal's restore: the sequence over positions moves the axis back where it stood.
    virtual void afterRefusal() {}
    /// Writes back what the run wrote, reads every parameter back and says in the result what differs.
    void restore();
    /// Before a step: false when the abort token is set (the caller refuses with Aborted); else announces it.
    bool begin(const char* name);
    /// A step's record goes into steps[] and to the listener.
    void done(const Step& s);
    /// Writes parameters the axis has and may write; remembers them for restore().
    Status write(const model::ParameterValues& v);
    /// What the drive holds now, as the run wrote it (NaN for an unknown key).
    double value(const std::string& key) const;
    /// The adaptive multisine FRF of the sequence's band at a peak [% rated torque], within `budgetS` and what is
    /// left of the run's budget; `motionS` is set to its motion time, which also counts against the budget.
    Result<device::AdaptiveFrfResult> frf(double amplitudePct, double budgetS, double& motionS);
    /// The apply step's end: a dry run restores everything and reads it back; else every written parameter must
    /// read back as written. Records the step (its rule ends with `ruleSuffix`); a refusal when either fails.
    std::optional<AutoTuneResult> keepOrRestore(Step& s, const std::string& ruleSuffix);

    device::Drive& m_drive;
    Options m_o;
    StyleTargets m_t;
    AutoTuneResult m_r;
    device::DriveCapabilities m_caps;
    std::vector<std::string> m_keys; ///< every parameter of the axis
    std::set<std::string> m_writable;
    model::ParameterValues m_now;     ///< what the drive holds now (as the run wrote it)
    model::ParameterValues m_written; ///< every key the run wrote, with its new value
    double m_motion = 0.0;
    bool m_linear = true; ///< axis units m (else rad)
};

} // namespace axistune::autotune::detail

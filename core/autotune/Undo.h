// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Undoing an applied tune (docs/tuning.md "Undo"): the parameters a run applied go back to the values they had
// before it, when the drive still holds what the run applied; every one is read back.

#include "core/device/Drive.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

namespace axistune::autotune {

/// What an applied run changed: its axis, and for every parameter it applied the value before and after.
struct AppliedTune {
    std::string axis;
    model::ParameterValues before;
    model::ParameterValues applied;
};

/// Reads an applied run from its result JSON (resultJson's form: `outcome` "applied", `final.parameters`, and the
/// apply step's `measured` "before.KEY"). Refused, naming the field, for another outcome or a missing value.
Result<AppliedTune> appliedTuneFromJson(const nlohmann::json& result);

struct UndoneParameter {
    std::string key;
    /// What the drive held just before the undo wrote over it: what the run applied, or, after an undo with
    /// `force`, the later change (the run's value only for a key the drive did not report)
    double applied = 0.0;
    double restored = 0.0; ///< what the drive holds after the undo (read back; equals the value before the run)
};

/// A parameter the drive no longer holds as the run applied it.
struct ChangedParameter {
    std::string key;
    double applied = 0.0;      ///< what the run applied
    std::optional<double> now; ///< what the drive holds now (none: the axis has no such parameter)
};

/// The parameters of `tune.applied` whose value in `now` (the drive's, read just before) is not what the run applied
/// (within the read-back tolerance), in key order; empty when the drive holds every one as applied.
std::vector<ChangedParameter> changedSinceApplied(const model::ParameterValues& now, const AppliedTune& tune);

/// The refusal of undoTune without `force` for the first of `changed` (non-empty): NotFound for a missing key,
/// Safety naming the key, its value now and the value applied.
Error changedRefusal(const AppliedTune& tune, const std::vector<ChangedParameter>& changed);

/// Writes `tune.before` for every key of `tune.applied`. Refused, with nothing written, when the drive does not hold
/// what the run applied (within the read-back tolerance: a later change would be overwritten) unless `force`;
/// refused when a value does not read back as written. The values are written in one call (the drive's own
/// validation refuses all of them or none).
Result<std::vector<UndoneParameter>> undoTune(device::Drive& drive, const AppliedTune& tune, bool force);

} // namespace axistune::autotune

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Undoing an applied tune (docs/tuning.md "Undo"): the parameters a run applied go back to the values they had
// before it, when the drive still holds what the run applied; every one is read back.

#include "core/device/Drive.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"

#include <nlohmann/json_fwd.hpp>
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
    double applied = 0.0;  ///< what the run applied (and the drive held before the undo)
    double restored = 0.0; ///< what the drive holds after the undo (read back; equals the value before the run)
};

/// Writes `tune.before` for every key of `tune.applied`. Refused, with nothing written, when the drive does not hold
/// what the run applied (within the read-back tolerance: a later change would be overwritten) unless `force`;
/// refused when a value does not read back as written. The values are written in one call (the drive's own
/// validation refuses all of them or none).
Result<std::vector<UndoneParameter>> undoTune(device::Drive& drive, const AppliedTune& tune, bool force);

} // namespace axistune::autotune

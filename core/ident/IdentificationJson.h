// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The identification result file (format "axistune-identification", docs/formats.md) and the small
// controller file used for validation; both JSON, SI units named in a "units" block.

#include "core/ident/MotionIdentification.h"
#include "core/model/Result.h"

#include <nlohmann/json_fwd.hpp>
#include <string>

namespace axistune::ident {

inline constexpr const char* kIdentificationFormat = "axistune-identification";
inline constexpr int kIdentificationVersion = 1;

const char* axisMotionName(AxisMotion m); ///< "linear" / "rotary"
/// The units block: position, force, inertia, viscous, coulomb, offset, velocity.
nlohmann::json unitsJson(AxisMotion m);

nlohmann::json estimateJson(const Estimate& e);
/// The identification part of the result file (no source, no validation).
nlohmann::json identificationToJson(const IdentificationResult& r, AxisMotion motion);
nlohmann::json validationToJson(const ValidationResult& v);
nlohmann::json controllerToJson(const PositionController& c);

/// Controller file: {"kp_per_s", "kv", "saturation", "delay_samples", "force_scale"}; every key
/// required, errors name the source and the key.
Result<PositionController> controllerFromJson(const nlohmann::json& j, const std::string& sourceName);

struct IdentifiedModel {
    AxisMotion motion = AxisMotion::Linear;
    RigidBodyModel model; ///< the symmetric fit (inertia, viscous, coulomb, offset)
};
/// Reads a result file written by `axistune-cli identify`; errors name the file and the field.
Result<IdentifiedModel> identifiedModelFromJson(const nlohmann::json& j, const std::string& sourceName);
Result<IdentifiedModel> readIdentifiedModelFile(const std::string& path);

} // namespace axistune::ident

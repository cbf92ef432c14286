// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Machine profile: a machine, its axes in order, each axis's current parameters (SI, keyed as in
// core/model/Parameter.h) and its identified models (motor, two_inertia, lost_motion, modal) as JSON.
// The JSON form is documented in docs/formats-profile.md; the CSV parameter list is the flat
// "machine,axis,key,value" form used by `axistune-cli export --format csv`.

#include "core/io/AtomicFile.h"
#include "core/model/Parameter.h"
#include "core/model/Result.h"

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

namespace axistune::io {

inline constexpr const char* kProfileFormat = "axistune-profile";
inline constexpr int kProfileVersion = 1;

/// The model kinds a profile and the store know, in their canonical order.
const std::vector<std::string>& modelKinds();
bool isModelKind(const std::string& kind);

struct AxisProfile {
    std::string name;                              ///< "X", "Y", "Z", "C", ...
    model::ParameterValues parameters;             ///< key -> SI value
    std::map<std::string, nlohmann::json> models;  ///< kind -> model object (SI, units in key names)
};

struct MachineProfile {
    std::string name;
    std::string description;
    std::vector<AxisProfile> axes;  ///< in the machine's order (A1, A2, ... in NC files)

    const AxisProfile* axis(const std::string& axisName) const;
};

/// Canonical JSON: keys sorted, axes in order. Equal profiles give byte-identical dumps.
nlohmann::json profileToJson(const MachineProfile& profile);
/// Validates and converts; errors name `sourceName` and the offending field.
Result<MachineProfile> profileFromJson(const nlohmann::json& j, const std::string& sourceName);

/// The canonical text (2-space indent, trailing newline).
std::string profileToText(const MachineProfile& profile);
Result<MachineProfile> readProfileFile(const std::string& path);
Status writeProfileFile(const std::string& path, const MachineProfile& profile);

/// Flat parameter list: "# format=axistune-parameters", header "machine,axis,key,value", one row per
/// parameter, values with 17 significant digits (exact double round trip). Models are not included.
std::string parametersToCsv(const MachineProfile& profile);
/// Reads the flat list back; errors name the source, the line and the column.
Result<MachineProfile> parametersFromCsv(const std::string& text, const std::string& sourceName);

/// Reads a whole file into a string; NotFound/Io errors name the path.
Result<std::string> readTextFile(const std::string& path);
// writeTextFileAtomic: core/io/AtomicFile.h (included above).

}  // namespace axistune::io

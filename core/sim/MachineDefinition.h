// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Simulated machines as data (resources/machines/*.json): every parameter with its value, unit and
// source. See docs/simulator.md for the file format.

#include "core/model/Parameter.h"
#include "core/model/Result.h"
#include "core/sim/AxisParameters.h"
#include "core/sim/PlantModel.h"

#include <map>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace axistune::sim {

struct AxisDefinition {
    std::string name;  ///< "X", "Y", "Z", "C", "A"
    AxisKind kind = AxisKind::Linear;
    model::ParameterValues values;               ///< every key of axisParameterMetas(kind), SI
    std::map<std::string, std::string> sources;  ///< key → where the number comes from
    std::vector<ResonanceMode> modes;
    ScrewStiffness screw;       ///< "screw": K follows the table position (docs/simulator.md "Long axis"); else off
    double travelWindowM = 0.0; ///< "travel_window": |position| of the simulated drive's jogs [m]; 0: the default
};

struct MachineDefinition {
    std::string name;
    std::string description;
    std::vector<AxisDefinition> axes;

    const AxisDefinition* axis(const std::string& axisName) const;
};

/// The folder with machines/, drives/, nc/, samples/: $AXISTUNE_RESOURCE_DIR, else the source tree.
std::string resourceDir();
/// Names of the presets in resources/machines/ (file names without .json), sorted.
std::vector<std::string> presetNames();
Result<MachineDefinition> loadPreset(const std::string& name);
Result<MachineDefinition> loadMachineDefinitionFile(const std::string& path);
/// Validates a parsed machine file; errors name `source` and the axis and key.
Result<MachineDefinition> machineDefinitionFromJson(const nlohmann::json& j, const std::string& source);

}  // namespace axistune::sim

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// tool.json / cut.json (docs/machining.md): keys in SI with the unit in the key name.
//   tool.json: {"modes_x": [{"mass_kg": 0.4, "damping_Ns_per_m": 83.0, "stiffness_N_per_m": 30.1e6}], "modes_y": [...]}
//   cut.json:  {"teeth": 4, "Kt_N_per_m2": 0.98e9, "Kr_N_per_m2": 0.294e9, "radial_immersion": 0.5833, "milling": "down"}
// Errors name the source and the key; values are validated (validateTool / validateCut), never clamped.

#include "core/machining/ToolModel.h"
#include "core/model/Result.h"

#include <string>

namespace axistune::machining {

Result<ToolModes> parseToolJson(const std::string& text, const std::string& sourceName);
Result<CuttingConditions> parseCutJson(const std::string& text, const std::string& sourceName);
Result<ToolModes> readToolJsonFile(const std::string& path);
Result<CuttingConditions> readCutJsonFile(const std::string& path);

}  // namespace axistune::machining

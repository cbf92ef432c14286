// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// NC parameter-file export driven by map files (resources/nc/<family>.json, docs/formats-profile.md
// "NC map files"). A map names, for each AxisTune parameter key, the NC's parameter number, the NC
// unit and scaling, and the file syntax as text templates, so a family is added or a number corrected
// without code. The maps are templates to verify against the machine's parameter manual.

#include "core/io/Profile.h"
#include "core/model/Result.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace axistune::io {

struct NcMapEntry {
    std::string key;       ///< AxisTune key, e.g. "position.kp"
    std::string number;    ///< NC parameter number or name as written, e.g. "01825", "POSCTRL_GAIN"
    std::string siUnit;    ///< unit token of the AxisTune value ("1/s"), "1" for plain numbers
    std::string unit;      ///< unit token the NC value is expressed in before `scale`
    double scale = 1.0;    ///< NC value = convert(value, siUnit -> unit) * scale
    int decimals = 0;      ///< digits after the decimal point; 0 writes an integer
    std::string line;      ///< optional per-entry line template (overrides the map's)
    std::string description;
};

enum class NcLayout {
    ByParameter,        ///< one line per parameter with every axis (FANUC tape: N01825A1P3000A2P3000)
    ByParameterPerAxis, ///< one line per parameter and axis, grouped by parameter (Heidenhain MP)
    ByAxis,             ///< one line per parameter and axis, grouped by axis with an axis header (Siemens)
};

struct NcMap {
    std::string family;   ///< "fanuc"
    std::string title;
    std::string verify;   ///< the "verify against the manual" notice, written into every file
    std::string comment;  ///< comment template with {text}, e.g. "({text})" or "; {text}"
    std::vector<std::string> commentForbidden;  ///< characters replaced by ' ' in comment text
    std::vector<std::string> header;
    std::vector<std::string> footer;
    NcLayout layout = NcLayout::ByParameter;
    std::string line;           ///< line template
    std::string axisItem;       ///< ByParameter: one axis's part of the line
    std::string axisSeparator;  ///< ByParameter: between axis items
    std::string axisHeader;     ///< ByAxis: a line before each axis's block (may be empty)
    std::vector<NcMapEntry> entries;
};

/// Validates a map (known fields, units convertible, templates non-empty); errors name the source.
Result<NcMap> ncMapFromJson(const nlohmann::json& j, const std::string& sourceName);
Result<NcMap> readNcMapFile(const std::string& path);

struct NcExport {
    std::string text;                    ///< the file, ending with a newline
    std::vector<std::string> unmapped;   ///< keys present in the profile without a map entry
};

/// Writes the profile's current parameters in the map's syntax. Keys without a mapping are listed in
/// the file as comments (with their SI values) and in `unmapped`; nothing is dropped silently.
/// Placeholders: {machine} {family} {title} {number} {value} {key} {unit} {axis} {axis_index}
/// (1-based) {axis_index0} (0-based) {axes} (ByParameter: the joined axis items) {text} (comments).
Result<NcExport> exportNc(const MachineProfile& profile, const NcMap& map);

/// Formats one value as the NC expects it (unit conversion, scale, fixed decimals); OutOfRange when
/// an integer parameter would overflow.
Result<std::string> formatNcValue(const NcMapEntry& entry, double valueSi);

/// resources/nc/<family>.json under $AXISTUNE_RESOURCE_DIR, else under the source tree's resources/.
std::string defaultNcMapPath(const std::string& family);

}  // namespace axistune::io

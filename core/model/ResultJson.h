// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Values that are not defined in result JSON (docs/formats.md "Undefined values"). No result JSON holds
// NaN, Inf or null where a number belongs: such a value is left out and its key is named, with the
// reason, in the "undefined" member of the same object, e.g.
//   {"gain_margin_dB": 12.1, "undefined": {"phase_margin_deg": "no gain crossover: ..."}}.
// model::dumpResultJson (InputLimits.h), the output boundary of every JSON result, refuses NaN, Inf
// and null anywhere.

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

namespace axistune::model {

/// `key` left out of the object `obj`, obj["undefined"][key] = reason.
void putUndefined(nlohmann::json& obj, const std::string& key, const std::string& reason);
/// obj[key] = v when v is finite (and the key no longer in "undefined"), else putUndefined.
void putNumber(nlohmann::json& obj, const std::string& key, double v, const std::string& reason);
/// An array of numbers when every one is finite; else the key is left out (putUndefined) with the
/// reason and the index of the first value that is not finite.
void putNumbers(nlohmann::json& obj, const std::string& key, const std::vector<double>& v, const std::string& reason);
/// obj[key] = *v · scale when v holds a finite value, else putUndefined(obj, key, reason).
void putOptional(nlohmann::json& obj, const std::string& key, const std::optional<double>& v, double scale,
                 const std::string& reason);

} // namespace axistune::model

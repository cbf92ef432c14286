// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Metadata as JSON (sessions in the store, the session export, the CLI's summaries): an object whose
// numbers are JSON numbers (a whole number below 2^53 without a fraction: 4000, not 4000.0) and whose texts
// are strings. JSON has no inf or nan: those are written as their
// text ("inf", "nan") and read back as numbers.

#include "core/model/Metadata.h"
#include "core/model/Result.h"

#include <nlohmann/json_fwd.hpp>

namespace axistune::model {

void to_json(nlohmann::json& j, const MetadataValue& value);
void to_json(nlohmann::json& j, const Metadata& metadata);
/// Reads an object of numbers and strings (a string as MetadataValue::fromText, so metadata stored as text
/// by older versions reads the same); anything else is BadInput naming the key.
Result<Metadata> metadataFromJson(const nlohmann::json& j);

} // namespace axistune::model

// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/MetadataJson.h"

#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>

namespace axistune::model {

void to_json(nlohmann::json& j, const MetadataValue& value)
{
    const auto v = value.number(); // finite only
    if (!value.isNumber() || !v)
        j = value.text();
    else if (*v == std::trunc(*v) && std::fabs(*v) < 9007199254740992.0) // whole, below 2^53: 4000, not 4000.0
        j = static_cast<std::int64_t>(*v);
    else
        j = *v;
}

void to_json(nlohmann::json& j, const Metadata& metadata)
{
    j = nlohmann::json::object();
    for (const auto& [key, value] : metadata)
        j[key] = value;
}

Result<Metadata> metadataFromJson(const nlohmann::json& j)
{
    if (!j.is_object())
        return makeError(ErrorCode::BadInput, "metadata is not a JSON object");
    Metadata m;
    for (const auto& [key, value] : j.items()) {
        if (value.is_string())
            m.setFromText(key, value.get<std::string>());
        else if (value.is_number())
            m.set(key, value.get<double>());
        else
            return makeError(ErrorCode::BadInput, "metadata '" + key + "' is neither a number nor a text");
    }
    return m;
}

} // namespace axistune::model

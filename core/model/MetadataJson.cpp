// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/MetadataJson.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune::model {

void to_json(nlohmann::json& j, const MetadataValue& value)
{
    if (const auto v = value.number(); value.isNumber() && std::isfinite(*v))
        j = *v;
    else
        j = value.text();
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

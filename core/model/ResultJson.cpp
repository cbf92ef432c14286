// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/ResultJson.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace axistune::model {

void putUndefined(nlohmann::json& obj, const std::string& key, const std::string& reason)
{
    if (obj.is_object())
        obj.erase(key);
    obj["undefined"][key] = reason;
}

namespace {

/// A key given a value is no longer undefined (a key is never both present and in "undefined").
void clearUndefined(nlohmann::json& obj, const std::string& key)
{
    if (!obj.is_object() || !obj.contains("undefined"))
        return;
    obj["undefined"].erase(key);
    if (obj["undefined"].empty())
        obj.erase("undefined");
}

} // namespace

void putNumber(nlohmann::json& obj, const std::string& key, double v, const std::string& reason)
{
    if (!std::isfinite(v)) {
        putUndefined(obj, key, reason);
        return;
    }
    clearUndefined(obj, key);
    obj[key] = v;
}

void putNumbers(nlohmann::json& obj, const std::string& key, const std::vector<double>& v, const std::string& reason)
{
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (!std::isfinite(v[i])) {
            putUndefined(obj, key, reason + " (first at index " + std::to_string(i) + ")");
            return;
        }
    }
    clearUndefined(obj, key);
    obj[key] = v;
}

void putOptional(nlohmann::json& obj, const std::string& key, const std::optional<double>& v, double scale,
                 const std::string& reason)
{
    putNumber(obj, key, v ? *v * scale : std::numeric_limits<double>::quiet_NaN(), reason);
}

} // namespace axistune::model

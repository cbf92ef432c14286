// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/Metadata.h"

#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"

#include <cmath>

namespace axistune::model {

MetadataValue MetadataValue::fromText(std::string text)
{
    // Only the spelling text() writes becomes a number, so that writing it again gives the same bytes.
    if (const auto v = parseNumber(text, true); v && MetadataValue(*v).text() == text)
        return MetadataValue(*v);
    return MetadataValue(std::move(text));
}

// Finite numbers only: inf and nan (numbers to isNumber(), as a file can hold them) give nullopt, so that no caller
// turns them into an index, a rate or a length.
std::optional<double> MetadataValue::number() const
{
    const auto* v = std::get_if<double>(&m_value);
    const auto x = v ? std::optional<double>(*v) : parseNumber(std::get<std::string>(m_value));
    if (x && std::isfinite(*x))
        return x;
    return std::nullopt;
}

std::string MetadataValue::text() const
{
    if (const auto* v = std::get_if<double>(&m_value)) {
        // A whole number is written whole ("100000", as printf's %.17g does; the shortest form would be "1e+05").
        if (std::isfinite(*v) && *v == std::trunc(*v) && std::fabs(*v) < 1e17)
            return formatFixed(*v, 0);
        return formatShortest(*v);
    }
    return std::get<std::string>(m_value);
}

void Metadata::set(std::string_view key, MetadataValue value)
{
    if (auto it = m_entries.find(key); it != m_entries.end())
        it->second = std::move(value);
    else
        m_entries.emplace(std::string(key), std::move(value));
}

void Metadata::setFromText(std::string_view key, std::string text)
{
    set(key, MetadataValue::fromText(std::move(text)));
}

bool Metadata::erase(std::string_view key)
{
    const auto it = m_entries.find(key);
    if (it == m_entries.end())
        return false;
    m_entries.erase(it);
    return true;
}

const MetadataValue* Metadata::find(std::string_view key) const
{
    const auto it = m_entries.find(key);
    return it == m_entries.end() ? nullptr : &it->second;
}

std::optional<std::string> Metadata::text(std::string_view key) const
{
    if (const auto* v = find(key))
        return v->text();
    return std::nullopt;
}

std::string Metadata::textOr(std::string_view key, std::string_view fallback) const
{
    if (const auto* v = find(key))
        return v->text();
    return std::string(fallback);
}

Result<std::optional<double>> Metadata::optionalNumber(std::string_view key) const
{
    const auto* value = find(key);
    if (!value)
        return std::optional<double>{};
    const auto v = value->number();
    if (!v)
        return makeError(ErrorCode::BadInput,
                         "metadata '" + std::string(key) + "' is not a number ('" + value->text() + "')");
    return std::optional<double>{*v};
}

Result<double> Metadata::number(std::string_view key) const
{
    auto v = optionalNumber(key);
    if (!v)
        return v.error();
    if (!v->has_value())
        return makeError(ErrorCode::NotFound, "metadata '" + std::string(key) + "' is missing");
    return **v;
}

Result<long long> Metadata::integer(std::string_view key) const
{
    const auto* value = find(key);
    if (!value)
        return makeError(ErrorCode::NotFound, "metadata '" + std::string(key) + "' is missing");
    const auto text = value->text();
    const auto v = parseInteger(text);
    if (!v)
        return makeError(ErrorCode::BadInput,
                         "metadata '" + std::string(key) + "' is not a whole number ('" + text + "')");
    return *v;
}

Result<std::optional<double>> Metadata::samplePeriodS() const
{
    auto fs = optionalNumber(meta::kFsHz);
    if (!fs || !fs->has_value())
        return fs;
    if (!(**fs > 0.0))
        return makeError(ErrorCode::BadInput,
                         "metadata 'fs_Hz' is not a positive number ('" + textOr(meta::kFsHz, "") + "')");
    return std::optional<double>{1.0 / **fs};
}

} // namespace axistune::model

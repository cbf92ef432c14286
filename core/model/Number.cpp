// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/Number.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>

namespace axistune::model {
namespace {

// Large enough for any double in %f form with up to 40 decimals (1.8e308 has 309 integer digits).
constexpr std::size_t kBuf = 360;

std::string finish(const char* buf, std::to_chars_result r)
{
    return r.ec == std::errc() ? std::string(buf, static_cast<const char*>(r.ptr)) : std::string("?");
}

} // namespace

std::string formatShortest(double v)
{
    char buf[kBuf];
    return finish(buf, std::to_chars(buf, buf + sizeof buf, v));
}

std::string formatNumber(double v, int significant)
{
    char buf[kBuf];
    // %g with precision 0 means 1 significant digit; to_chars follows printf there too.
    return finish(
        buf, std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, significant < 0 ? 6 : significant));
}

std::string formatFixed(double v, int decimals)
{
    char buf[kBuf];
    if (decimals < 0)
        decimals = 0;
    if (decimals > 40)
        decimals = 40;
    return finish(buf, std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals));
}

std::string formatScientific(double v, int decimals)
{
    char buf[kBuf];
    return finish(buf,
                  std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific, std::clamp(decimals, 0, 40)));
}

std::optional<double> parseNumber(std::string_view text, bool allowNonFinite)
{
    if (text.empty())
        return std::nullopt;
    const char* b = text.data();
    const char* e = b + text.size();
    // from_chars takes '-' but not '+'; a "+-1" must not pass.
    if (*b == '+') {
        ++b;
        if (b == e || *b == '-')
            return std::nullopt;
    }
    double v = 0.0;
    const auto r = std::from_chars(b, e, v);
    if (r.ec != std::errc() || r.ptr != e)
        return std::nullopt;
    if (!allowNonFinite && !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::optional<long long> parseInteger(std::string_view text)
{
    if (text.empty())
        return std::nullopt;
    const char* b = text.data();
    const char* e = b + text.size();
    if (*b == '+') {
        ++b;
        if (b == e || *b == '-')
            return std::nullopt;
    }
    long long v = 0;
    const auto r = std::from_chars(b, e, v);
    if (r.ec != std::errc() || r.ptr != e)
        return std::nullopt;
    return v;
}

Result<std::optional<double>> optionalMetadataNumber(const Metadata& metadata, const std::string& key)
{
    const auto it = metadata.find(key);
    if (it == metadata.end())
        return std::optional<double>{};
    const auto v = parseNumber(it->second);
    if (!v)
        return makeError(ErrorCode::BadInput, "metadata '" + key + "' is not a number ('" + it->second + "')");
    return std::optional<double>{*v};
}

Result<double> metadataNumber(const Metadata& metadata, const std::string& key)
{
    auto v = optionalMetadataNumber(metadata, key);
    if (!v)
        return v.error();
    if (!v->has_value())
        return makeError(ErrorCode::NotFound, "metadata '" + key + "' is missing");
    return **v;
}

Result<long long> metadataInteger(const Metadata& metadata, const std::string& key)
{
    const auto it = metadata.find(key);
    if (it == metadata.end())
        return makeError(ErrorCode::NotFound, "metadata '" + key + "' is missing");
    const auto v = parseInteger(it->second);
    if (!v)
        return makeError(ErrorCode::BadInput, "metadata '" + key + "' is not a whole number ('" + it->second + "')");
    return *v;
}

void setMetadataNumber(Metadata& metadata, const std::string& key, double v)
{
    metadata[key] = formatNumber(v, 17);
}

} // namespace axistune::model

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

namespace {

// The digits of a number: the text without one leading '+' (from_chars takes '-' but not '+');
// nullopt for "", "+" and "+-1".
std::optional<std::string_view> unsignedPlus(std::string_view text)
{
    if (!text.empty() && text.front() == '+') {
        text.remove_prefix(1);
        if (!text.empty() && text.front() == '-')
            return std::nullopt;
    }
    if (text.empty())
        return std::nullopt;
    return text;
}

template <typename T> std::optional<T> parseWhole(std::string_view text)
{
    const auto t = unsignedPlus(text);
    if (!t)
        return std::nullopt;
    T v{};
    const auto r = std::from_chars(t->data(), t->data() + t->size(), v);
    if (r.ec != std::errc() || r.ptr != t->data() + t->size())
        return std::nullopt;
    return v;
}

} // namespace

std::optional<double> parseNumber(std::string_view text, bool allowNonFinite)
{
    const auto v = parseWhole<double>(text);
    if (!v || (!allowNonFinite && !std::isfinite(*v)))
        return std::nullopt;
    return v;
}

std::optional<long long> parseInteger(std::string_view text)
{
    return parseWhole<long long>(text);
}

} // namespace axistune::model

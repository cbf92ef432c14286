// SPDX-License-Identifier: GPL-3.0-or-later
// Guarded input reading and JSON parsing (docs/robustness.md).
#include "core/model/InputLimits.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sys/stat.h>
#include <nlohmann/json.hpp>

namespace axistune::model {
namespace {

Error bad(std::string detail)
{
    return makeError(ErrorCode::BadInput, std::move(detail));
}

/// Length of the valid UTF-8 sequence at s[i], 0 when invalid.
std::size_t utf8Length(const std::string& s, std::size_t i)
{
    const auto c = static_cast<unsigned char>(s[i]);
    std::size_t n = 0;
    std::uint32_t cp = 0;
    if (c < 0x80)
        return 1;
    if ((c & 0xE0) == 0xC0) {
        n = 2;
        cp = c & 0x1F;
    } else if ((c & 0xF0) == 0xE0) {
        n = 3;
        cp = c & 0x0F;
    } else if ((c & 0xF8) == 0xF0) {
        n = 4;
        cp = c & 0x07;
    } else {
        return 0;
    }
    if (i + n > s.size())
        return 0;
    for (std::size_t k = 1; k < n; ++k) {
        const auto d = static_cast<unsigned char>(s[i + k]);
        if ((d & 0xC0) != 0x80)
            return 0;
        cp = (cp << 6) | (d & 0x3F);
    }
    const bool overlong = (n == 2 && cp < 0x80) || (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000);
    if (overlong || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
        return 0;
    return n;
}

std::string lineAt(const std::string& text, std::size_t pos)
{
    std::size_t line = 1;
    const std::size_t end = std::min(pos, text.size());
    for (std::size_t i = 0; i < end; ++i)
        line += text[i] == '\n';
    return std::to_string(line);
}

/// One pass over the text outside the parser: nesting depth and the range of every number, so the
/// error can name the line and the key (nlohmann's own errors carry neither for numbers).
Status prescanJson(const std::string& text, const std::string& src)
{
    int depth = 0;
    std::size_t line = 1;
    std::string lastString, lastKey;
    auto where = [&] {
        return src + " line " + std::to_string(line) + (lastKey.empty() ? "" : ", key '" + displayPath(lastKey) + "'");
    };
    const std::size_t n = text.size();
    for (std::size_t i = 0; i < n; ++i) {
        const char c = text[i];
        if (c == '\n') {
            ++line;
        } else if (c == '"') {
            std::string s;
            for (++i; i < n && text[i] != '"'; ++i) {
                if (text[i] == '\\' && i + 1 < n)
                    ++i;
                if (text[i] == '\n')
                    ++line;
                if (s.size() < 200)
                    s.push_back(text[i]);
            }
            lastString = std::move(s);
        } else if (c == ':') {
            lastKey = lastString;
        } else if (c == '{' || c == '[') {
            if (++depth > kMaxJsonDepth)
                return bad(where() + ": nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        } else if (c == '}' || c == ']') {
            --depth;
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            std::size_t e = i + 1;
            while (e < n && (std::strchr("0123456789.eE+-", text[e]) != nullptr && text[e] != '\0'))
                ++e;
            double v = 0.0;
            const auto [p, ec] = std::from_chars(text.data() + i, text.data() + e, v);
            const std::string token = text.substr(i, std::min<std::size_t>(e - i, 40));
            if (ec == std::errc::result_out_of_range)
                return bad(where() + ": number " + token + " does not fit a double (about ±2.2e-308 to ±1.8e308)");
            if (ec == std::errc() && isDenormal(v))
                return bad(where() + ": number " + token + " is denormal (below 2.2e-308 in magnitude)");
            i = e - 1;
        }
    }
    return Status::success();
}

} // namespace

std::string displayPath(const std::string& path)
{
    std::string out;
    out.reserve(path.size());
    static const char kHex[] = "0123456789ABCDEF";
    for (std::size_t i = 0; i < path.size();) {
        const std::size_t n = utf8Length(path, i);
        if (n == 0) {
            const auto b = static_cast<unsigned char>(path[i]);
            out += "\\x";
            out.push_back(kHex[b >> 4]);
            out.push_back(kHex[b & 15]);
            ++i;
        } else {
            out.append(path, i, n);
            i += n;
        }
    }
    return out;
}

Result<std::string> readInputFile(const std::string& path, std::size_t maxBytes)
{
    const std::string shown = displayPath(path);
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        if (errno == ENOENT || errno == ENOTDIR)
            return makeError(ErrorCode::NotFound, shown + ": cannot open (no such file)");
        return makeError(ErrorCode::Io, shown + ": cannot be read (" + std::strerror(errno) + ")");
    }
    if (S_ISDIR(st.st_mode))
        return bad(shown + ": is a directory, not a file");
    if (!S_ISREG(st.st_mode))
        return bad(shown + ": is not a regular file (a pipe, socket or device); copy the data into a file");
    if (static_cast<std::uint64_t>(st.st_size) > maxBytes) {
        return bad(shown + ": " + std::to_string(st.st_size) + " bytes, larger than the limit of " +
                   std::to_string(maxBytes) + " bytes");
    }
    std::ifstream f(path, std::ios::binary);
    if (!f)
        return makeError(ErrorCode::Io, shown + ": cannot be opened for reading");
    std::string text(static_cast<std::size_t>(st.st_size), '\0');
    f.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(f.gcount()));
    if (f.bad())
        return makeError(ErrorCode::Io, shown + ": read failed");
    // A file that grew while being read: read the rest up to the limit, then refuse.
    char extra[4096];
    while (f.read(extra, sizeof extra) || f.gcount() > 0) {
        text.append(extra, static_cast<std::size_t>(f.gcount()));
        if (text.size() > maxBytes)
            return bad(shown + ": larger than the limit of " + std::to_string(maxBytes) + " bytes");
    }
    return text;
}

Result<nlohmann::json> parseJsonText(const std::string& text, const std::string& source)
{
    const std::string src = displayPath(source);
    if (auto st = prescanJson(text, src); !st)
        return st.error();
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        return bad(src + " line " + lineAt(text, e.byte > 0 ? e.byte - 1 : 0) + ": not valid JSON (" + e.what() + ")");
    } catch (const nlohmann::json::exception& e) {
        return bad(src + ": not valid JSON (" + e.what() + ")");
    } catch (const std::bad_alloc&) {
        return bad(src + ": too large to parse");
    }
}

Result<nlohmann::json> readJsonFile(const std::string& path)
{
    auto text = readInputFile(path);
    if (!text)
        return text.error();
    return parseJsonText(*text, path);
}

bool findNonFinite(const nlohmann::json& j, std::string& pointer)
{
    if (j.is_null()) {
        if (pointer.empty())
            pointer = "/";
        return true;
    }
    if (j.is_number_float()) {
        if (!std::isfinite(j.get<double>())) {
            if (pointer.empty())
                pointer = "/";
            return true;
        }
        return false;
    }
    if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it) {
            std::string sub;
            if (findNonFinite(it.value(), sub)) {
                pointer = "/" + it.key() + (sub == "/" ? "" : sub);
                return true;
            }
        }
    } else if (j.is_array()) {
        for (std::size_t i = 0; i < j.size(); ++i) {
            std::string sub;
            if (findNonFinite(j[i], sub)) {
                pointer = "/" + std::to_string(i) + (sub == "/" ? "" : sub);
                return true;
            }
        }
    }
    return false;
}

Result<std::string> dumpResultJson(const nlohmann::json& j, int indent)
{
    std::string pointer;
    if (findNonFinite(j, pointer))
        return makeError(ErrorCode::Internal, "result value " + displayPath(pointer) +
                                                  " is not a finite number (NaN, Inf or null); nothing written");
    return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

bool isDenormal(double v)
{
    return std::fpclassify(v) == FP_SUBNORMAL;
}

std::string badNumberText(std::string_view cell)
{
    std::string_view t = cell;
    while (!t.empty() && (t.front() == ' ' || t.front() == '\t'))
        t.remove_prefix(1);
    while (!t.empty() && (t.back() == ' ' || t.back() == '\t' || t.back() == '\r'))
        t.remove_suffix(1);
    if (!t.empty() && t.front() == '+')
        t.remove_prefix(1);
    const std::string shown(cell.substr(0, 40));
    double v = 0.0;
    const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (p == t.data() + t.size() && !t.empty()) {
        if (ec == std::errc::result_out_of_range)
            return "'" + shown + "' does not fit a double (about ±2.2e-308 to ±1.8e308)";
        if (ec == std::errc() && isDenormal(v))
            return "'" + shown + "' is denormal (below 2.2e-308 in magnitude)";
    }
    return "not a number ('" + shown + "')";
}

Status checkCsvLine(const std::string& source, std::size_t lineNo, std::size_t lineBytes)
{
    if (lineBytes > kMaxLineBytes) {
        return bad(displayPath(source) + " line " + std::to_string(lineNo) + ": longer than " +
                   std::to_string(kMaxLineBytes) + " bytes");
    }
    if (lineNo > kMaxCsvLines)
        return bad(displayPath(source) + " line " + std::to_string(lineNo) + ": more than " +
                   std::to_string(kMaxCsvLines) + " lines");
    return Status::success();
}

} // namespace axistune::model

// SPDX-License-Identifier: GPL-3.0-or-later
// Ball-bar CSV reader and writer (format: DESIGN.md "File formats", docs/ballbar.md).
#include "core/io/BallBarCsv.h"

#include "core/io/TextFile.h"
#include "core/model/CircleDirectionName.h"
#include "core/model/Constants.h"
#include "core/model/InputLimits.h"
#include "core/model/Number.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <set>
#include <sstream>

namespace axistune::io {
namespace {

using model::kRadPerDeg;

std::string trim(std::string s)
{
    auto notSpace = [](unsigned char c) { return !std::isspace(c); };
    s.erase(s.begin(), std::find_if(s.begin(), s.end(), notSpace));
    s.erase(std::find_if(s.rbegin(), s.rend(), notSpace).base(), s.end());
    return s;
}

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

/// Parses a whole field as a double; std::nullopt when it is not a number.
std::optional<double> parseNumber(const std::string& text)
{
    const std::string t = trim(text);
    if (t.empty())
        return std::nullopt;
    const auto x = model::parseNumber(t, true);
    if (!x || model::isDenormal(*x))
        return std::nullopt;
    return x;
}

struct MetaLine {
    std::string value;
    int line = 0;
};

Error bad(const std::string& what)
{
    return makeError(ErrorCode::BadInput, what);
}

/// A required or optional positive, finite number from metadata.
Result<std::optional<double>> metaNumber(const std::map<std::string, MetaLine>& meta, const std::string& src,
                                         const std::string& key, bool required, bool positive, const std::string& hint)
{
    auto it = meta.find(key);
    if (it == meta.end()) {
        if (required)
            return bad(src + ": metadata '" + key + "' missing (" + hint + ")");
        return std::optional<double>{};
    }
    auto v = parseNumber(it->second.value);
    const std::string where = src + " line " + std::to_string(it->second.line) + ", metadata '" + key + "'";
    if (!v)
        return bad(where + ": " + model::badNumberText(it->second.value));
    if (!std::isfinite(*v))
        return bad(where + ": not a finite number ('" + it->second.value + "')");
    if (positive && *v <= 0.0)
        return bad(where + ": must be greater than zero (is " + it->second.value + ")");
    return std::optional<double>{*v};
}

Status applyMetadata(const std::map<std::string, MetaLine>& meta, const std::string& src, BallBarTrace& t)
{
    if (meta.empty())
        return bad(src + ": no metadata; a ball-bar trace needs at least '# radius_mm=', '# feed_mm_min=' and "
                         "'# direction=ccw|cw' before the header");
    auto radius = metaNumber(meta, src, "radius_mm", true, true, "the nominal ball-bar radius, e.g. '# radius_mm=100'");
    if (!radius)
        return radius.error();
    auto feed = metaNumber(meta, src, "feed_mm_min", true, true, "the programmed feed, e.g. '# feed_mm_min=1000'");
    if (!feed)
        return feed.error();
    auto cx = metaNumber(meta, src, "center_x_mm", false, false, "");
    if (!cx)
        return cx.error();
    auto cy = metaNumber(meta, src, "center_y_mm", false, false, "");
    if (!cy)
        return cy.error();
    auto dtx = metaNumber(meta, src, "dT_x_Nm", false, true, "");
    if (!dtx)
        return dtx.error();
    auto dty = metaNumber(meta, src, "dT_y_Nm", false, true, "");
    if (!dty)
        return dty.error();
    t.radiusM = **radius * 1e-3;
    t.feedMPerS = **feed * 1e-3 / 60.0;
    t.centerXM = cx->value_or(0.0) * 1e-3;
    t.centerYM = cy->value_or(0.0) * 1e-3;
    t.dTxNm = *dtx;
    t.dTyNm = *dty;

    auto dir = meta.find("direction");
    if (dir == meta.end())
        return bad(src +
                   ": metadata 'direction' missing (the travel direction, '# direction=ccw' or '# direction=cw')");
    if (const auto d = model::circleDirectionFromName(lower(trim(dir->second.value))))
        t.direction = *d;
    else
        return bad(src + " line " + std::to_string(dir->second.line) +
                   ", metadata 'direction': must be 'ccw' or 'cw' (is '" + dir->second.value + "')");

    if (auto p = meta.find("plane"); p != meta.end()) {
        std::string plane = trim(p->second.value);
        std::transform(plane.begin(), plane.end(), plane.begin(),
                       [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
        static const std::set<std::string> kPlanes{"XY", "YZ", "ZX", "XZ", "YX", "ZY"};
        if (!kPlanes.count(plane))
            return bad(src + " line " + std::to_string(p->second.line) +
                       ", metadata 'plane': must name two axes such as XY, YZ or ZX (is '" + p->second.value + "')");
        t.plane = plane;
    }
    return Status::success();
}

/// Checks samples: count, finiteness and strict monotonicity. `lineOf(i)` names the line of sample i.
template <typename LineOf> Status checkSamples(const BallBarTrace& t, const std::string& src, LineOf lineOf)
{
    if (t.size() < kBallBarMinSamples)
        return bad(src + ": has " + std::to_string(t.size()) + " sample" + (t.size() == 1 ? "" : "s") +
                   "; a ball-bar trace needs at least " + std::to_string(kBallBarMinSamples));
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (!std::isfinite(t.angleRad[i]))
            return bad(src + lineOf(i) + ", column 'angle_deg': not a finite number");
        if (!std::isfinite(t.deviationM[i]))
            return bad(src + lineOf(i) + ", column 'deviation_um': not a finite number");
    }
    const double sign = t.angleRad[1] > t.angleRad[0] ? 1.0 : -1.0;
    for (std::size_t i = 1; i < t.size(); ++i) {
        if (sign * (t.angleRad[i] - t.angleRad[i - 1]) <= 0.0) {
            return bad(src + lineOf(i) + ", column 'angle_deg': angles must be strictly " +
                       (sign > 0 ? "increasing" : "decreasing") + " (" +
                       model::formatNumber(t.angleRad[i - 1] / kRadPerDeg, 6) + " then " +
                       model::formatNumber(t.angleRad[i] / kRadPerDeg, 6) + ")");
        }
    }
    return Status::success();
}

} // namespace

Result<BallBarTrace> readBallBarCsv(std::istream& in, const std::string& sourceName)
{
    BallBarTrace t;
    t.source = sourceName;
    std::map<std::string, MetaLine> meta;
    std::vector<int> sampleLines;
    bool headerSeen = false;
    std::string raw;
    int lineNo = 0;
    while (std::getline(in, raw)) {
        ++lineNo;
        if (auto lim = model::checkCsvLine(sourceName, static_cast<std::size_t>(lineNo), raw.size()); !lim)
            return lim.error();
        if (!raw.empty() && raw.back() == '\r')
            raw.pop_back();
        const std::string line = trim(raw);
        if (line.empty())
            continue;
        const std::string where = sourceName + " line " + std::to_string(lineNo);
        if (line.front() == '#') {
            const auto eq = line.find('=');
            if (eq == std::string::npos)
                continue; // a plain comment
            const std::string key = trim(line.substr(1, eq - 1));
            if (key.empty())
                return bad(where + ": metadata line without a key ('" + line + "')");
            if (meta.count(key))
                return bad(where + ", metadata '" + key + "': given twice (first on line " +
                           std::to_string(meta[key].line) + ")");
            meta[key] = MetaLine{trim(line.substr(eq + 1)), lineNo};
            t.metadata.setFromText(key, meta[key].value);
            continue;
        }
        std::vector<std::string> fields;
        for (std::size_t start = 0;;) {
            const auto comma = line.find(',', start);
            fields.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
            if (comma == std::string::npos)
                break;
            start = comma + 1;
        }
        if (!line.empty() && line.back() == ',')
            fields.pop_back(); // "a,b," splits like getline did: no empty last field
        if (!headerSeen) {
            if (fields.size() != 2 || fields[0] != "angle_deg" || fields[1] != "deviation_um")
                return bad(where + ": expected the header 'angle_deg,deviation_um' (found '" + line + "')");
            headerSeen = true;
            continue;
        }
        if (fields.size() != 2)
            return bad(where + ": expected 2 columns (angle_deg, deviation_um), found " +
                       std::to_string(fields.size()));
        static const char* kCols[2] = {"angle_deg", "deviation_um"};
        double v[2] = {0.0, 0.0};
        for (int c = 0; c < 2; ++c) {
            auto n = parseNumber(fields[c]);
            if (!n)
                return bad(where + ", column '" + kCols[c] + "': " + model::badNumberText(fields[c]));
            if (!std::isfinite(*n))
                return bad(where + ", column '" + kCols[c] + "': not a finite number ('" + fields[c] + "')");
            v[c] = *n;
        }
        t.angleRad.push_back(v[0] * kRadPerDeg);
        t.deviationM.push_back(v[1] * 1e-6);
        sampleLines.push_back(lineNo);
    }
    if (!headerSeen)
        return bad(sourceName + ": no header 'angle_deg,deviation_um' (empty file or metadata only)");
    if (auto s = applyMetadata(meta, sourceName, t); !s)
        return s.error();
    auto lineOf = [&](std::size_t i) { return " line " + std::to_string(sampleLines[i]); };
    if (auto s = checkSamples(t, sourceName, lineOf); !s)
        return s.error();
    return t;
}

Result<BallBarTrace> readBallBarCsvFile(const std::string& path)
{
    auto text = model::readInputFile(path);
    if (!text)
        return text.error();
    std::istringstream in(std::move(text).value());
    return readBallBarCsv(in, path);
}

Status writeBallBarCsv(std::ostream& out, const BallBarTrace& t)
{
    const std::string src = t.source.empty() ? std::string("ball-bar trace") : t.source;
    if (!(t.radiusM > 0.0) || !std::isfinite(t.radiusM))
        return bad(src + ": radius must be a positive number to be written");
    if (!(t.feedMPerS > 0.0) || !std::isfinite(t.feedMPerS))
        return bad(src + ": feed must be a positive number to be written");
    if (t.angleRad.size() != t.deviationM.size())
        return bad(src + ": angle and deviation arrays differ in length");
    auto lineOf = [](std::size_t i) { return " sample " + std::to_string(i); };
    if (auto s = checkSamples(t, src, lineOf); !s)
        return s;
    const auto g = [](double v) { return model::formatNumber(v, 17); };
    out << "# radius_mm=" << g(t.radiusM * 1e3) << '\n';
    out << "# feed_mm_min=" << g(t.feedMPerS * 60.0e3) << '\n';
    out << "# direction=" << model::circleDirectionName(t.direction) << '\n';
    out << "# plane=" << t.plane << '\n';
    out << "# center_x_mm=" << g(t.centerXM * 1e3) << '\n';
    out << "# center_y_mm=" << g(t.centerYM * 1e3) << '\n';
    if (t.dTxNm)
        out << "# dT_x_Nm=" << g(*t.dTxNm) << '\n';
    if (t.dTyNm)
        out << "# dT_y_Nm=" << g(*t.dTyNm) << '\n';
    static const std::set<std::string> kWritten{"radius_mm",   "feed_mm_min", "direction", "plane",
                                                "center_x_mm", "center_y_mm", "dT_x_Nm",   "dT_y_Nm"};
    for (const auto& [k, v] : t.metadata) {
        if (!kWritten.count(k))
            out << "# " << k << '=' << v.text() << '\n';
    }
    out << "angle_deg,deviation_um\n";
    for (std::size_t i = 0; i < t.size(); ++i)
        out << g(t.angleRad[i] / kRadPerDeg) << ',' << g(t.deviationM[i] * 1e6) << '\n';
    if (!out)
        return makeError(ErrorCode::Io, src + ": write failed");
    return Status::success();
}

Status writeBallBarCsvFile(const std::string& path, const BallBarTrace& trace)
{
    return writeTextFile(path, [&](std::ostream& out) { return writeBallBarCsv(out, trace); });
}

} // namespace axistune::io

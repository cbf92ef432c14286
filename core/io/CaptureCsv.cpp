// SPDX-License-Identifier: GPL-3.0-or-later
// Capture CSV reader/writer (DESIGN.md "File formats").
#include "core/io/CaptureCsv.h"

#include "core/io/TextFile.h"
#include "core/model/InputLimits.h"
#include "core/model/Number.h"

#include <cmath>
#include <fstream>

namespace axistune::io {
namespace {

std::string_view trimView(std::string_view s) { return trimBlanks(s); }

std::string trim(std::string_view s) { return std::string(trimView(s)); }

std::vector<std::string> splitComma(const std::string& line)
{
    std::vector<std::string> out;
    std::size_t start = 0;
    while (true) {
        const auto pos = line.find(',', start);
        out.push_back(trim(std::string_view(line).substr(start, pos == std::string::npos ? std::string::npos : pos - start)));
        if (pos == std::string::npos)
            break;
        start = pos + 1;
    }
    return out;
}

bool parseDouble(std::string_view s, double& v)
{
    const auto x = model::parseNumber(s, true);
    if (!x || model::isDenormal(*x))
        return false;
    v = *x;
    return true;
}

}  // namespace

Result<model::Capture> readCaptureCsv(std::istream& in, const std::string& sourceName)
{
    model::Capture cap;
    std::string line;
    std::size_t lineNo = 0;
    bool haveHeader = false;
    auto where = [&](std::size_t ln) { return sourceName + " line " + std::to_string(ln); };
    while (std::getline(in, line)) {
        ++lineNo;
        if (auto lim = model::checkCsvLine(sourceName, static_cast<std::size_t>(lineNo), line.size()); !lim)
            return lim.error();
        const std::string_view t = trimView(line);
        if (t.empty())
            continue;
        if (t[0] == '#') {
            const std::string_view body = trimView(t.substr(1));
            const auto eq = body.find('=');
            if (eq != std::string_view::npos)
                cap.metadata.setFromText(trimView(body.substr(0, eq)), std::string(trimView(body.substr(eq + 1))));
            continue;  // a plain comment otherwise
        }
        if (!haveHeader) {
            for (const auto& name : splitComma(std::string(t))) {
                if (name.empty())
                    return makeError(ErrorCode::BadInput, where(lineNo) + ": empty column name in the header");
                if (cap.channel(name))
                    return makeError(ErrorCode::BadInput, where(lineNo) + ": column '" + name + "' appears twice");
                cap.channels.push_back({name, {}});
            }
            haveHeader = true;
            continue;
        }
        // Data row: parse the fields in place, without a string per cell.
        std::size_t col = 0, pos = 0;
        while (true) {
            const auto comma = t.find(',', pos);
            const std::string_view cell = trimView(t.substr(pos, comma == std::string_view::npos ? std::string_view::npos : comma - pos));
            if (col >= cap.channels.size()) {
                return makeError(ErrorCode::BadInput, where(lineNo) + ": more fields than the "
                                                          + std::to_string(cap.channels.size()) + " columns of the header");
            }
            double v = 0.0;
            if (!parseDouble(cell, v)) {
                return makeError(ErrorCode::BadInput, where(lineNo) + ", column '" + cap.channels[col].name +
                                                          "': " + model::badNumberText(cell));
            }
            if (!std::isfinite(v)) {
                return makeError(ErrorCode::BadInput, where(lineNo) + ", column '" + cap.channels[col].name
                                                          + "': value is not finite");
            }
            cap.channels[col].data.push_back(v);
            ++col;
            if (comma == std::string_view::npos)
                break;
            pos = comma + 1;
        }
        if (col != cap.channels.size()) {
            return makeError(ErrorCode::BadInput, where(lineNo) + ": " + std::to_string(col) + " fields, the header has "
                                                      + std::to_string(cap.channels.size()));
        }
    }
    if (!haveHeader)
        return makeError(ErrorCode::BadInput, sourceName + ": no header line (the file is empty)");
    if (cap.size() == 0)
        return makeError(ErrorCode::BadInput, sourceName + ": the header has no data rows");
    return cap;
}

Result<model::Capture> readCaptureCsvFile(const std::string& path)
{
    auto text = model::readInputFile(path);
    if (!text)
        return text.error();
    std::istringstream in(std::move(text).value());
    return readCaptureCsv(in, path);
}

Status writeCaptureCsv(std::ostream& out, const model::Capture& capture)
{
    const std::size_t n = capture.size();
    for (const auto& c : capture.channels) {
        if (c.data.size() != n)
            return makeError(ErrorCode::Internal, "capture channel '" + c.name + "' has a different length");
    }
    for (const auto& [k, v] : capture.metadata)
        out << "# " << k << '=' << v.text() << '\n';
    for (std::size_t i = 0; i < capture.channels.size(); ++i)
        out << (i ? "," : "") << capture.channels[i].name;
    out << '\n';
    for (std::size_t r = 0; r < n; ++r) {
        for (std::size_t i = 0; i < capture.channels.size(); ++i) {
            if (i)
                out << ',';
            out << model::formatShortest(capture.channels[i].data[r]);
        }
        out << '\n';
    }
    if (!out)
        return makeError(ErrorCode::Io, "writing the capture failed");
    return Status::success();
}

Status writeCaptureCsvFile(const std::string& path, const model::Capture& capture)
{
    return writeTextFile(path, [&](std::ostream& out) { return writeCaptureCsv(out, capture); });
}

}  // namespace axistune::io

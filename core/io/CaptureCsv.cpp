// SPDX-License-Identifier: GPL-3.0-or-later
// Capture CSV reader/writer (DESIGN.md "File formats").
#include "core/io/CaptureCsv.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace axistune::io {
namespace {

std::string trim(std::string_view s)
{
    std::size_t b = 0, e = s.size();
    while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\r'))
        ++b;
    while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r'))
        --e;
    return std::string(s.substr(b, e - b));
}

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

bool parseDouble(const std::string& s, double& v)
{
    if (s.empty())
        return false;
    const char* b = s.data();
    const char* e = s.data() + s.size();
    if (*b == '+')
        ++b;
    auto [p, ec] = std::from_chars(b, e, v);
    return ec == std::errc() && p == e;
}

}  // namespace

Result<model::Capture> readCaptureCsv(std::istream& in, const std::string& sourceName)
{
    model::Capture cap;
    std::string line;
    std::size_t lineNo = 0;
    bool haveHeader = false;
    while (std::getline(in, line)) {
        ++lineNo;
        const std::string t = trim(line);
        if (t.empty())
            continue;
        if (t[0] == '#') {
            const auto body = trim(std::string_view(t).substr(1));
            const auto eq = body.find('=');
            if (eq == std::string::npos) {
                continue;  // a plain comment
            }
            cap.metadata[trim(std::string_view(body).substr(0, eq))] = trim(std::string_view(body).substr(eq + 1));
            continue;
        }
        const auto cells = splitComma(t);
        if (!haveHeader) {
            for (const auto& name : cells) {
                if (name.empty()) {
                    return makeError(ErrorCode::BadInput,
                                     sourceName + " line " + std::to_string(lineNo) + ": empty column name in the header");
                }
                for (const auto& c : cap.channels) {
                    if (c.name == name) {
                        return makeError(ErrorCode::BadInput, sourceName + " line " + std::to_string(lineNo)
                                                                  + ": column '" + name + "' appears twice");
                    }
                }
                cap.channels.push_back({name, {}});
            }
            haveHeader = true;
            continue;
        }
        if (cells.size() != cap.channels.size()) {
            return makeError(ErrorCode::BadInput, sourceName + " line " + std::to_string(lineNo) + ": "
                                                      + std::to_string(cells.size()) + " fields, the header has "
                                                      + std::to_string(cap.channels.size()));
        }
        for (std::size_t i = 0; i < cells.size(); ++i) {
            double v = 0.0;
            if (!parseDouble(cells[i], v)) {
                return makeError(ErrorCode::BadInput, sourceName + " line " + std::to_string(lineNo) + ", column '"
                                                          + cap.channels[i].name + "': '" + cells[i]
                                                          + "' is not a number");
            }
            if (!std::isfinite(v)) {
                return makeError(ErrorCode::BadInput, sourceName + " line " + std::to_string(lineNo) + ", column '"
                                                          + cap.channels[i].name + "': value is not finite");
            }
            cap.channels[i].data.push_back(v);
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
    std::ifstream f(path);
    if (!f)
        return makeError(ErrorCode::NotFound, path + ": cannot open the file");
    return readCaptureCsv(f, path);
}

Status writeCaptureCsv(std::ostream& out, const model::Capture& capture)
{
    const std::size_t n = capture.size();
    for (const auto& c : capture.channels) {
        if (c.data.size() != n)
            return makeError(ErrorCode::Internal, "capture channel '" + c.name + "' has a different length");
    }
    for (const auto& [k, v] : capture.metadata)
        out << "# " << k << '=' << v << '\n';
    for (std::size_t i = 0; i < capture.channels.size(); ++i)
        out << (i ? "," : "") << capture.channels[i].name;
    out << '\n';
    char buf[32];
    for (std::size_t r = 0; r < n; ++r) {
        for (std::size_t i = 0; i < capture.channels.size(); ++i) {
            auto [p, ec] = std::to_chars(buf, buf + sizeof buf, capture.channels[i].data[r]);
            if (i)
                out << ',';
            out.write(buf, p - buf);
        }
        out << '\n';
    }
    if (!out)
        return makeError(ErrorCode::Io, "writing the capture failed");
    return Status::success();
}

Status writeCaptureCsvFile(const std::string& path, const model::Capture& capture)
{
    std::ofstream f(path);
    if (!f)
        return makeError(ErrorCode::Io, path + ": cannot open the file for writing");
    auto st = writeCaptureCsv(f, capture);
    if (!st)
        return makeError(st.error().code, path + ": " + st.error().detail);
    return st;
}

}  // namespace axistune::io

// SPDX-License-Identifier: GPL-3.0-or-later
// Universal file dataset 58 (ASCII) reader, from the dataset specification (core/io/Uff58.h).
#include "core/io/Uff58.h"

#include "core/io/FrfCsv.h"
#include "core/io/TextFile.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/model/Units.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

namespace axistune::io {

namespace {

std::string trim(std::string_view s) { return std::string(trimBlanks(s)); }

std::string field(const std::string& line, std::size_t pos, std::size_t width)
{
    if (pos >= line.size())
        return {};
    return trim(std::string_view(line).substr(pos, width));
}

bool parseFortranDouble(std::string s, double& v)
{
    for (char& c : s) {
        if (c == 'D' || c == 'd')
            c = 'E';
    }
    return detail::parseDouble(s, v);
}

struct LineReader {
    std::istream& in;
    const std::string& source;
    std::size_t lineNo = 0;
    bool next(std::string& line)
    {
        if (!std::getline(in, line))
            return false;
        ++lineNo;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        return true;
    }
    std::string at() const { return source + " line " + std::to_string(lineNo); }
};

bool isDelimiter(const std::string& line)
{
    return trim(line) == "-1";
}

Status parseInt(const std::string& text, const std::string& where, const char* what, int& v)
{
    const std::string t = trim(text);
    const auto x = model::parseInteger(t.size() > 1 && t.front() == '+' ? std::string_view(t).substr(1) : t);
    if (!x || *x < std::numeric_limits<int>::min() || *x > std::numeric_limits<int>::max())
        return makeError(ErrorCode::BadInput, where + ", " + what + ": '" + t + "' is not an integer");
    v = static_cast<int>(*x);
    return {};
}

Status parseAxis(const std::string& line, const std::string& where, UffAxis& a)
{
    // Format(I10,3I5,2(1X,20A1))
    if (auto s = parseInt(field(line, 0, 10), where, "data type (field 1)", a.dataType); !s)
        return s;
    if (auto s = parseInt(field(line, 10, 5), where, "length unit exponent (field 2)", a.lengthExp); !s)
        return s;
    if (auto s = parseInt(field(line, 15, 5), where, "force unit exponent (field 3)", a.forceExp); !s)
        return s;
    if (auto s = parseInt(field(line, 20, 5), where, "temperature unit exponent (field 4)", a.temperatureExp); !s)
        return s;
    a.label = field(line, 26, 20);
    a.unitsLabel = field(line, 47, 20);
    return {};
}

// One dataset 58 after its "58" line; the reader stands on that line.
Result<Uff58Record> readRecord(LineReader& r, double lengthFactor, double forceFactor)
{
    Uff58Record rec;
    rec.line = r.lineNo;
    rec.lengthFactor = lengthFactor;
    rec.forceFactor = forceFactor;
    std::string line;
    auto need = [&](const char* what) -> Status {
        if (!r.next(line))
            return makeError(ErrorCode::BadInput, r.source + ": the file ends inside dataset 58 (line " +
                                                      std::to_string(rec.line) + ") before " + what);
        if (isDelimiter(line))
            return makeError(ErrorCode::BadInput, r.at() + ": dataset 58 ends before " + what);
        return {};
    };
    for (int i = 1; i <= 5; ++i) {
        if (auto s = need("its 5 ID lines"); !s)
            return s.error();
        rec.idLines.push_back(trim(line));
    }
    if (auto s = need("record 6"); !s)
        return s.error();
    {
        const std::string w = r.at() + " (record 6)";
        if (auto s = parseInt(field(line, 0, 5), w, "function type", rec.functionType); !s)
            return s.error();
        if (auto s = parseInt(field(line, 5, 10), w, "function identification", rec.functionId); !s)
            return s.error();
        if (auto s = parseInt(field(line, 15, 5), w, "version", rec.version); !s)
            return s.error();
        if (auto s = parseInt(field(line, 20, 10), w, "load case", rec.loadCase); !s)
            return s.error();
        rec.responseName = field(line, 31, 10);
        if (auto s = parseInt(field(line, 41, 10), w, "response node", rec.responseNode); !s)
            return s.error();
        if (auto s = parseInt(field(line, 51, 4), w, "response direction", rec.responseDirection); !s)
            return s.error();
        rec.referenceName = field(line, 56, 10);
        if (auto s = parseInt(field(line, 66, 10), w, "reference node", rec.referenceNode); !s)
            return s.error();
        if (auto s = parseInt(field(line, 76, 4), w, "reference direction", rec.referenceDirection); !s)
            return s.error();
    }
    if (auto s = need("record 7"); !s)
        return s.error();
    int n = 0, spacing = 0;
    {
        const std::string w = r.at() + " (record 7)";
        if (auto s = parseInt(field(line, 0, 10), w, "ordinate data type", rec.ordinateType); !s)
            return s.error();
        if (rec.ordinateType != 2 && rec.ordinateType != 4 && rec.ordinateType != 5 && rec.ordinateType != 6)
            return makeError(ErrorCode::BadInput, w + ", ordinate data type: " + std::to_string(rec.ordinateType) +
                                                      " (expected 2, 4 real or 5, 6 complex)");
        if (auto s = parseInt(field(line, 10, 10), w, "number of points", n); !s)
            return s.error();
        if (n < 1)
            return makeError(ErrorCode::BadInput, w + ", number of points: " + std::to_string(n));
        if (auto s = parseInt(field(line, 20, 10), w, "abscissa spacing", spacing); !s)
            return s.error();
        if (spacing != 0 && spacing != 1)
            return makeError(ErrorCode::BadInput,
                             w + ", abscissa spacing: " + std::to_string(spacing) + " (expected 0 or 1)");
        rec.evenSpacing = spacing == 1;
        const char* names[] = {"abscissa minimum", "abscissa increment", "z-axis value"};
        double* dst[] = {&rec.xMin, &rec.xStep, &rec.zValue};
        for (int k = 0; k < 3; ++k) {
            const std::string cell = field(line, 30 + 13 * static_cast<std::size_t>(k), 13);
            if (!parseFortranDouble(cell, *dst[k]) || !std::isfinite(*dst[k]))
                return makeError(ErrorCode::BadInput, w + ", " + names[k] + ": '" + cell + "' is not a number");
        }
        if (rec.evenSpacing && !(rec.xStep > 0.0))
            return makeError(ErrorCode::BadInput, w + ", abscissa increment: must be > 0 for even spacing");
    }
    UffAxis* axes[] = {&rec.abscissa, &rec.numerator, &rec.denominator, &rec.zAxis};
    for (int k = 0; k < 4; ++k) {
        const std::string rn = "record " + std::to_string(8 + k);
        if (auto s = need(rn.c_str()); !s)
            return s.error();
        if (auto s = parseAxis(line, r.at() + " (" + rn + ")", *axes[k]); !s)
            return s.error();
    }
    // record 12: whitespace-separated values until the closing "-1"
    const bool cplx = rec.isComplex();
    const std::size_t perPoint = (cplx ? 2u : 1u) + (rec.evenSpacing ? 0u : 1u);
    const std::size_t want = perPoint * static_cast<std::size_t>(n);
    std::vector<double> v;
    v.reserve(want);
    bool closed = false;
    while (r.next(line)) {
        if (isDelimiter(line)) {
            closed = true;
            break;
        }
        std::size_t i = 0;
        int fieldNo = 0;
        while (i < line.size()) {
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
                ++i;
            if (i >= line.size())
                break;
            const std::size_t b = i;
            while (i < line.size() && line[i] != ' ' && line[i] != '\t')
                ++i;
            ++fieldNo;
            double d = 0.0;
            const std::string cell = line.substr(b, i - b);
            if (!parseFortranDouble(cell, d) || !std::isfinite(d))
                return makeError(ErrorCode::BadInput, r.at() + " (record 12), field " + std::to_string(fieldNo) +
                                                          ": '" + cell + "' is not a finite number");
            v.push_back(d);
        }
    }
    if (!closed)
        return makeError(ErrorCode::BadInput, r.source + ": the file ends inside dataset 58 of line " +
                                                  std::to_string(rec.line) + " (no closing -1)");
    if (v.size() != want)
        return makeError(ErrorCode::BadInput, r.source + " line " + std::to_string(rec.line) +
                                                  " (dataset 58, record 12): " + std::to_string(v.size()) +
                                                  " values, record 7 announces " + std::to_string(n) +
                                                  " points = " + std::to_string(want) + " values");
    for (std::size_t p = 0; p < static_cast<std::size_t>(n); ++p) {
        const double* q = v.data() + p * perPoint;
        double x = 0.0;
        if (rec.evenSpacing) {
            x = rec.xMin + static_cast<double>(p) * rec.xStep;
        } else {
            x = *q++;
        }
        rec.x.push_back(x);
        rec.y.emplace_back(q[0], cplx ? q[1] : 0.0);
    }
    return rec;
}

// Unit token of an axis from its units label (empty: unknown label, "" label: none given).
std::string tokenFromLabel(std::string label)
{
    label.erase(std::remove(label.begin(), label.end(), ' '), label.end());
    if (label == "m/s^2" || label == "m/s**2" || label == "m/s2" || label == "m/sec^2" || label == "m/s/s")
        return "m/s2";
    if (label == "mm/s^2" || label == "mm/s**2" || label == "mm/s2")
        return "mm/s2";
    if (label == "g" || label == "G")
        return "g";
    if (label == "µm" || label == "um" || label == "micron")
        return "um";
    for (const char* t : {"m", "mm", "nm", "m/s", "mm/s", "N", "kN", "s", "ms", "Hz"}) {
        if (label == t)
            return t;
    }
    return {};
}

bool noLabel(const std::string& label)
{
    return label.empty() || label == "NONE" || label == "none";
}

const char* siOfType(int dataType)
{
    switch (dataType) {
    case 8:
        return "m";
    case 11:
        return "m/s";
    case 12:
        return "m/s2";
    case 9:
    case 13:
        return "N";
    case 17:
        return "s";
    case 18:
        return "Hz";
    default:
        return nullptr;
    }
}

// Factor to SI of an axis: dataset 164 when it is not SI, else the units label, else SI by data type.
Result<double> axisToSi(const Uff58Record& rec, const UffAxis& a, const std::string& where, std::string& token,
                        bool& assumed)
{
    if (rec.lengthFactor != 1.0 || rec.forceFactor != 1.0) {
        token = siOfType(a.dataType) ? siOfType(a.dataType) : "";
        return 1.0 / (std::pow(rec.lengthFactor, a.lengthExp) * std::pow(rec.forceFactor, a.forceExp));
    }
    if (!noLabel(a.unitsLabel)) {
        token = tokenFromLabel(a.unitsLabel);
        if (token.empty())
            return makeError(ErrorCode::BadInput, where + ": units label '" + a.unitsLabel + "' is not a known unit");
        return model::findUnit(token)->toSi;
    }
    assumed = true;
    token = siOfType(a.dataType) ? siOfType(a.dataType) : "";
    return 1.0;
}

} // namespace

Result<std::vector<Uff58Record>> readUff58(std::istream& in, const std::string& sourceName)
{
    std::vector<Uff58Record> out;
    LineReader r{in, sourceName};
    std::string line;
    double lengthFactor = 1.0, forceFactor = 1.0;
    bool any = false;
    while (r.next(line)) {
        if (trim(line).empty())
            continue;
        if (!isDelimiter(line))
            return makeError(ErrorCode::BadInput,
                             r.at() + ": expected '    -1' opening a dataset, found '" + trim(line) + "'");
        if (!r.next(line))
            break;
        const std::string id = trim(line);
        any = true;
        if (id == "58") {
            auto rec = readRecord(r, lengthFactor, forceFactor);
            if (!rec)
                return rec.error();
            out.push_back(std::move(*rec));
            continue;
        }
        if (id.rfind("58", 0) == 0 && id.size() > 2 && (id[2] == 'b' || id[2] == 'B'))
            return makeError(ErrorCode::BadInput,
                             r.at() + ": binary dataset 58b is not supported; export ASCII dataset 58");
        const bool units = id == "164";
        std::vector<std::string> body;
        bool closed = false;
        while (r.next(line)) {
            if (isDelimiter(line)) {
                closed = true;
                break;
            }
            body.push_back(line);
        }
        if (!closed)
            return makeError(ErrorCode::BadInput,
                             sourceName + ": the file ends inside dataset " + id + " (no closing -1)");
        if (units) {
            // record 2: length, force, temperature factors Format(3D25.17)
            if (body.size() < 2)
                return makeError(ErrorCode::BadInput, r.at() + ": dataset 164 without its factor record");
            double f[3] = {0, 0, 0};
            for (int k = 0; k < 3; ++k) {
                const std::string cell = field(body[1], 25 * static_cast<std::size_t>(k), 25);
                if (!parseFortranDouble(cell, f[k]) || !(f[k] > 0.0))
                    return makeError(ErrorCode::BadInput, sourceName + ": dataset 164 record 2, factor " +
                                                              std::to_string(k + 1) + ": '" + cell +
                                                              "' is not a positive number");
            }
            lengthFactor = f[0];
            forceFactor = f[1];
        }
    }
    if (!any)
        return makeError(ErrorCode::BadInput, sourceName + ": no universal-file datasets");
    if (out.empty())
        return makeError(ErrorCode::BadInput, sourceName + ": no dataset 58 in the file");
    return out;
}

Result<std::vector<Uff58Record>> readUff58File(const std::string& path)
{
    return readFromFile(path, [&](std::istream& in, const std::string& p) { return readUff58(in, p); });
}

Result<dsp::FrequencyResponse> frfFromUff(const Uff58Record& rec, const std::string& sourceName)
{
    const std::string where = sourceName + " line " + std::to_string(rec.line) + " (dataset 58)";
    if (!rec.isComplex() || (rec.functionType != 4 && rec.abscissa.dataType != 18))
        return makeError(ErrorCode::BadInput, where + ": function type " + std::to_string(rec.functionType) +
                                                  " is not a complex frequency response");
    std::string num, den;
    bool assumed = false;
    auto fn = axisToSi(rec, rec.numerator, where + " record 9", num, assumed);
    if (!fn)
        return fn.error();
    auto fd = axisToSi(rec, rec.denominator, where + " record 10", den, assumed);
    if (!fd)
        return fd.error();
    dsp::FrequencyResponse frf;
    const double scale = *fn / *fd;
    for (std::size_t i = 0; i < rec.x.size(); ++i) {
        if (i > 0 && !(rec.x[i] > rec.x[i - 1]))
            return makeError(ErrorCode::BadInput,
                             where + ", point " + std::to_string(i + 1) + ": frequencies must increase strictly");
        if (rec.x[i] < 0.0)
            return makeError(ErrorCode::BadInput, where + ", point " + std::to_string(i + 1) + ": negative frequency");
        frf.push(rec.x[i], rec.y[i] * scale, std::nan(""), true);
    }
    auto siToken = [](const std::string& t) -> std::string {
        if (t.empty())
            return {};
        auto u = model::findUnit(t);
        return u ? std::string(u->si) : t;
    };
    const std::string n = siToken(num), d = siToken(den);
    if (!n.empty() && !d.empty())
        frf.metadata.set(model::meta::kUnits, n + "/" + d);
    if (assumed)
        frf.metadata.set("units_assumed", "SI");
    frf.metadata.set(model::meta::kSourceFormat, "uff58");
    frf.metadata.setFromText("uff_id1", rec.idLines.empty() ? "" : rec.idLines[0]);
    frf.metadata.set("uff_response", std::to_string(rec.responseNode) + ":" + std::to_string(rec.responseDirection));
    frf.metadata.set("uff_reference", std::to_string(rec.referenceNode) + ":" + std::to_string(rec.referenceDirection));
    return frf;
}

Result<model::Capture> captureFromUff(const std::vector<Uff58Record>& records, const std::string& sourceName)
{
    model::Capture cap;
    const Uff58Record* first = nullptr;
    for (const auto& rec : records) {
        const std::string where = sourceName + " line " + std::to_string(rec.line) + " (dataset 58)";
        if (rec.functionType != 1)
            continue;
        if (rec.isComplex() || !rec.evenSpacing)
            return makeError(ErrorCode::BadInput, where + ": a time response must be real and evenly spaced");
        if (first && (rec.x.size() != first->x.size() || std::abs(rec.xStep - first->xStep) > 1e-9 * first->xStep))
            return makeError(ErrorCode::BadInput, where + ": length or time step differs from the record of line " +
                                                      std::to_string(first->line));
        if (!first) {
            first = &rec;
            cap.channels.push_back({"t_s", rec.x});
        }
        std::string token;
        bool assumed = false;
        auto f = axisToSi(rec, rec.numerator, where + " record 9", token, assumed);
        if (!f)
            return f.error();
        std::string name =
            rec.idLines.empty() || rec.idLines[0].empty() || rec.idLines[0] == "NONE"
                ? "node" + std::to_string(rec.responseNode) + "_dir" + std::to_string(rec.responseDirection)
                : rec.idLines[0];
        for (char& c : name) {
            if (c == ' ' || c == ',' || c == ';')
                c = '_';
        }
        if (cap.channel(name))
            name += "_" + std::to_string(cap.channels.size());
        model::Channel ch{name, {}};
        for (const auto& y : rec.y)
            ch.data.push_back(y.real() * *f);
        cap.channels.push_back(std::move(ch));
    }
    if (!first)
        return makeError(ErrorCode::BadInput, sourceName + ": no time-response record (dataset 58 function type 1)");
    cap.metadata.set(model::meta::kFsHz, 1.0 / first->xStep);
    cap.metadata.set(model::meta::kSourceFormat, "uff58");
    return cap;
}

} // namespace axistune::io

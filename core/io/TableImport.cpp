// SPDX-License-Identifier: GPL-3.0-or-later
// Delimited-table, halscope-log and FRF-column imports (core/io/TableImport.h, docs/formats.md "Imports").
#include "core/io/TableImport.h"

#include "core/io/FrfCsv.h"
#include "core/io/TextFile.h"
#include "core/io/Uff58.h"
#include "core/model/Constants.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Units.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <set>
#include <sys/stat.h>

namespace axistune::io {

namespace {

std::string trimCell(std::string_view s)
{
    std::string out(trimBlanks(s));
    if (out.size() >= 2 && out.front() == '"' && out.back() == '"')
        out = out.substr(1, out.size() - 2);
    return out;
}

std::vector<std::string> splitLine(const std::string& line, char sep)
{
    std::vector<std::string> cells;
    if (sep == ' ') {
        std::size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
                ++i;
            if (i >= line.size())
                break;
            const std::size_t b = i;
            while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r')
                ++i;
            cells.push_back(trimCell(std::string_view(line).substr(b, i - b)));
        }
        return cells;
    }
    std::size_t start = 0;
    while (true) {
        const auto pos = line.find(sep, start);
        cells.push_back(
            trimCell(std::string_view(line).substr(start, pos == std::string::npos ? std::string::npos : pos - start)));
        if (pos == std::string::npos)
            break;
        start = pos + 1;
    }
    return cells;
}

char detectSeparator(const std::string& line)
{
    if (line.find('\t') != std::string::npos)
        return '\t';
    if (line.find(';') != std::string::npos)
        return ';';
    if (line.find(',') != std::string::npos)
        return ',';
    return ' ';
}

bool parseNumber(std::string cell, bool decimalComma, double& v)
{
    if (decimalComma) {
        for (char& c : cell) {
            if (c == ',')
                c = '.';
            else if (c == '.')
                return false; // a point in a decimal-comma file is a mistake, not a thousands mark
        }
    }
    return detail::parseDouble(cell, v);
}

std::string separatorName(char sep)
{
    switch (sep) {
    case '\t':
        return "tab";
    case ';':
        return "semicolon";
    case ',':
        return "comma";
    default:
        return "blanks";
    }
}

} // namespace

Result<model::Capture> readTable(std::istream& in, const std::string& sourceName, const TableImportOptions& options)
{
    model::Capture cap;
    std::string line;
    std::size_t lineNo = 0;
    char sep = options.separator;
    std::optional<bool> decimalComma;
    if (options.decimal != DecimalMark::Auto)
        decimalComma = options.decimal == DecimalMark::Comma;
    bool haveColumns = false;
    std::size_t firstDataLine = 0;
    auto where = [&](std::size_t ln) { return sourceName + " line " + std::to_string(ln); };
    std::vector<double> scale;

    auto addRow = [&](const std::vector<std::string>& cells, std::size_t ln) -> Status {
        if (cells.size() != cap.channels.size()) {
            return makeError(ErrorCode::BadInput, where(ln) + ": " + std::to_string(cells.size()) +
                                                      " fields, expected " + std::to_string(cap.channels.size()) +
                                                      " (separator " + separatorName(sep) + ")");
        }
        if (!decimalComma) {
            bool comma = false, point = false;
            for (const auto& c : cells) {
                comma = comma || c.find(',') != std::string::npos;
                point = point || c.find('.') != std::string::npos;
            }
            decimalComma = sep != ',' && comma && !point;
        }
        for (std::size_t i = 0; i < cells.size(); ++i) {
            double v = 0.0;
            if (!parseNumber(cells[i], *decimalComma, v)) {
                return makeError(ErrorCode::BadInput, where(ln) + ", column '" + cap.channels[i].name + "': '" +
                                                          cells[i] + "' is not a number" +
                                                          (*decimalComma ? " (decimal comma)" : " (decimal point)"));
            }
            if (!std::isfinite(v))
                return makeError(ErrorCode::BadInput,
                                 where(ln) + ", column '" + cap.channels[i].name + "': value is not finite");
            cap.channels[i].data.push_back(v * scale[i]);
        }
        if (firstDataLine == 0)
            firstDataLine = ln;
        return {};
    };

    auto setColumns = [&](const std::vector<std::string>& names, std::size_t ln) -> Status {
        std::set<std::string> seen;
        for (const auto& n : names) {
            if (n.empty())
                return makeError(ErrorCode::BadInput, where(ln) + ": empty column name in the header");
            if (!seen.insert(n).second)
                return makeError(ErrorCode::BadInput, where(ln) + ": column '" + n + "' appears twice");
            cap.channels.push_back({n, {}});
        }
        for (const auto& [col, unit] : options.units) {
            if (!seen.count(col))
                return makeError(ErrorCode::NotFound,
                                 sourceName + ": unit given for column '" + col + "', which the file does not have");
        }
        scale.assign(names.size(), 1.0);
        for (std::size_t i = 0; i < names.size(); ++i) {
            auto it = options.units.find(names[i]);
            if (it == options.units.end())
                continue;
            auto u = model::findUnit(it->second);
            if (!u)
                return makeError(ErrorCode::BadInput, sourceName + ", column '" + names[i] + "': unknown unit '" +
                                                          it->second + "' (docs/formats.md lists the units)");
            scale[i] = u->toSi;
            cap.metadata.set("unit." + names[i], std::string(u->si));
            cap.metadata.set("unit_in_file." + names[i], it->second);
        }
        haveColumns = true;
        return {};
    };

    while (std::getline(in, line)) {
        ++lineNo;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos)
            continue;
        if (line[line.find_first_not_of(" \t")] == '#') {
            std::string k, v;
            // "# key=value" with a one-word key is metadata; other comment lines are prose
            if (detail::parseMetadataLine(line.substr(line.find('#')), k, v) &&
                k.find_first_of(" \t") == std::string::npos)
                cap.metadata.setFromText(k, std::move(v));
            continue;
        }
        if (sep == 0)
            sep = detectSeparator(line);
        auto cells = splitLine(line, sep);
        if (!haveColumns) {
            bool numeric = true;
            for (const auto& c : cells) {
                double v = 0.0;
                numeric = numeric && (parseNumber(c, false, v) || parseNumber(c, true, v));
            }
            const bool header =
                options.header == HeaderMode::Present || (options.header == HeaderMode::Auto && !numeric);
            std::vector<std::string> names;
            if (header) {
                names = cells;
            } else if (!options.names.empty()) {
                names = options.names;
            } else {
                for (std::size_t i = 0; i < cells.size(); ++i)
                    names.push_back("col" + std::to_string(i + 1));
            }
            if (!options.names.empty() && header && options.header != HeaderMode::Present) {
                // names given for a file that has a header: the header wins, but both must agree in width
                if (options.names.size() != cells.size())
                    return makeError(ErrorCode::BadInput,
                                     where(lineNo) + ": the header has " + std::to_string(cells.size()) + " columns, " +
                                         std::to_string(options.names.size()) + " names were given");
            }
            if (!header && names.size() != cells.size())
                return makeError(ErrorCode::BadInput, where(lineNo) + ": " + std::to_string(cells.size()) +
                                                          " fields, " + std::to_string(names.size()) +
                                                          " column names were given");
            if (auto st = setColumns(names, lineNo); !st)
                return st.error();
            if (header)
                continue;
        }
        if (auto st = addRow(cells, lineNo); !st)
            return st.error();
    }
    if (!haveColumns)
        return makeError(ErrorCode::BadInput, sourceName + ": no data (the file is empty or has only comments)");
    if (cap.size() == 0)
        return makeError(ErrorCode::BadInput, sourceName + ": the header has no data rows");
    cap.metadata.set("separator", separatorName(sep));
    cap.metadata.set("decimal", decimalComma.value_or(false) ? "comma" : "point");
    cap.metadata.set(model::meta::kFirstDataLine, firstDataLine);
    return cap;
}

Result<model::Capture> readTableFile(const std::string& path, const TableImportOptions& options)
{
    return readFromFile(path, [&](std::istream& in, const std::string& p) { return readTable(in, p, options); });
}

bool looksLikeHalscope(const std::string& firstLine)
{
    return firstLine.rfind("Sampling period is", 0) == 0;
}

Result<model::Capture> readHalscope(std::istream& in, const std::string& sourceName)
{
    model::Capture cap;
    std::string line;
    std::size_t lineNo = 0;
    double periodNs = 0.0;
    std::size_t firstDataLine = 0;
    auto where = [&](std::size_t ln) { return sourceName + " line " + std::to_string(ln); };
    while (std::getline(in, line)) {
        ++lineNo;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (lineNo == 1) {
            // "Sampling period is <int> ns "
            auto cells = splitLine(line, ' ');
            if (!looksLikeHalscope(line) || cells.size() < 5 || cells[4] != "ns" ||
                !detail::parseDouble(cells[3], periodNs) || !(periodNs > 0.0))
                return makeError(ErrorCode::BadInput,
                                 where(1) + ": not a halscope log (expected 'Sampling period is <n> ns')");
            continue;
        }
        auto cells = splitLine(line, ' ');
        if (cells.empty())
            continue;
        if (cells.size() % 2 != 0)
            return makeError(ErrorCode::BadInput, where(lineNo) + ": expected pairs '<channel> <value>', found " +
                                                      std::to_string(cells.size()) + " fields");
        const std::size_t nch = cells.size() / 2;
        if (cap.channels.empty()) {
            for (std::size_t i = 0; i < nch; ++i) {
                if (cap.channel(cells[2 * i]))
                    return makeError(ErrorCode::BadInput,
                                     where(lineNo) + ": channel '" + cells[2 * i] + "' appears twice");
                cap.channels.push_back({cells[2 * i], {}});
            }
            firstDataLine = lineNo;
        }
        if (nch != cap.channels.size())
            return makeError(ErrorCode::BadInput, where(lineNo) + ": " + std::to_string(nch) +
                                                      " channels, the first row has " +
                                                      std::to_string(cap.channels.size()));
        for (std::size_t i = 0; i < nch; ++i) {
            if (cells[2 * i] != cap.channels[i].name)
                return makeError(ErrorCode::BadInput, where(lineNo) + ", field " + std::to_string(2 * i + 1) +
                                                          ": channel '" + cells[2 * i] + "' where '" +
                                                          cap.channels[i].name + "' was expected");
            double v = 0.0;
            if (!detail::parseDouble(cells[2 * i + 1], v) || !std::isfinite(v))
                return makeError(ErrorCode::BadInput, where(lineNo) + ", channel '" + cap.channels[i].name + "': '" +
                                                          cells[2 * i + 1] + "' is not a finite number");
            cap.channels[i].data.push_back(v);
        }
    }
    if (lineNo == 0)
        return makeError(ErrorCode::BadInput, sourceName + ": empty file");
    if (cap.size() == 0)
        return makeError(ErrorCode::BadInput, sourceName + ": no samples after the 'Sampling period' line");
    cap.metadata.set(model::meta::kFsHz, 1e9 / periodNs);
    cap.metadata.set("sample_period_ns", periodNs);
    cap.metadata.set("format", "halscope");
    cap.metadata.set(model::meta::kFirstDataLine, firstDataLine);
    return cap;
}

Result<model::Capture> readHalscopeFile(const std::string& path)
{
    return readFromFile(path, [&](std::istream& in, const std::string& p) { return readHalscope(in, p); });
}

std::string detectImportFormat(const std::string& path)
{
    const auto dot = path.rfind('.');
    std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == "unv" || ext == "uff")
        return "uff";
    // Sniff only a regular file, and only its first bytes: a FIFO would block here and /dev/zero has no
    // line end. Anything else goes to the CSV reader, which refuses it with the reason (readInputFile).
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
        return "csv";
    std::ifstream f(path, std::ios::binary);
    char head[64] = {};
    f.read(head, sizeof head);
    const std::string first(head, static_cast<std::size_t>(f.gcount()));
    if (looksLikeHalscope(first))
        return "halscope";
    return "csv";
}

Result<model::Capture> readTimeSeriesFile(const std::string& path, const TableImportOptions& options,
                                          const std::string& format)
{
    const std::string f = format == "auto" ? detectImportFormat(path) : format;
    if (f == "halscope")
        return readHalscopeFile(path);
    if (f == "uff") {
        auto recs = readUff58File(path);
        if (!recs)
            return recs.error();
        return captureFromUff(*recs, path);
    }
    return readTableFile(path, options);
}

Result<dsp::FrequencyResponse> frfFromTable(const model::Capture& table, const std::string& sourceName,
                                            const FrfColumnOptions& options)
{
    const model::Channel* f = nullptr;
    if (!options.frequencyColumn.empty()) {
        f = table.channel(options.frequencyColumn);
        if (!f)
            return makeError(ErrorCode::NotFound,
                             sourceName + ": no frequency column '" + options.frequencyColumn + "'");
    } else {
        for (const char* n : {"f_Hz", "freq_Hz", "f", "freq", "frequency", "Frequency", "Freq"}) {
            if ((f = table.channel(n)))
                break;
        }
        if (!f)
            return makeError(ErrorCode::NotFound, sourceName +
                                                      ": no frequency column (f_Hz, freq_Hz, f, freq or frequency); "
                                                      "name it with --freq-column");
    }
    std::string name = options.name;
    if (name.empty()) {
        // the only FRF of the file: the one prefix with _re and _im columns
        std::vector<std::string> prefixes;
        for (const auto& c : table.channels) {
            const auto& n = c.name;
            if (n.size() > 3 && n.compare(n.size() - 3, 3, "_re") == 0 &&
                table.channel(n.substr(0, n.size() - 3) + "_im"))
                prefixes.push_back(n.substr(0, n.size() - 3));
        }
        if (table.channel("re") && table.channel("im"))
            prefixes.push_back("");
        if (prefixes.size() > 1) {
            std::string list;
            for (const auto& p : prefixes)
                list += (list.empty() ? "" : ", ") + (p.empty() ? std::string("re/im") : p);
            return makeError(ErrorCode::BadInput,
                             sourceName + ": the file has several FRFs (" + list + "); choose one with --column");
        }
        if (prefixes.empty())
            return makeError(ErrorCode::BadInput,
                             sourceName + ": no FRF columns (<name>_re and <name>_im, or re and im)");
        name = prefixes.front();
    }
    const std::string pre = name.empty() ? "" : name + "_";
    const auto* re = table.channel(pre + "re");
    const auto* im = table.channel(pre + "im");
    const auto* magDb = table.channel(pre + "mag_dB");
    const auto* mag = table.channel(pre + "mag");
    const auto* ph = table.channel(pre + "phase_deg");
    if (!(re && im) && !((magDb || mag) && ph))
        return makeError(ErrorCode::NotFound, sourceName + ": no columns " + pre + "re/" + pre + "im (or " + pre +
                                                  "mag_dB/" + pre + "phase_deg, " + pre + "mag/" + pre + "phase_deg)");
    dsp::FrequencyResponse frf;
    frf.metadata = table.metadata;
    for (const char* k : {"separator", "decimal", "first_data_line"})
        frf.metadata.erase(k);
    std::size_t first = 0;
    if (table.metadata.contains(model::meta::kFirstDataLine)) {
        const auto line = table.metadata.integer(model::meta::kFirstDataLine);
        if (!line)
            return makeError(ErrorCode::BadInput, sourceName + ": " + line.error().detail);
        first = static_cast<std::size_t>(*line);
    }
    for (std::size_t i = 0; i < table.size(); ++i) {
        const double fi = f->data[i];
        const std::string at =
            sourceName + (first ? " line " + std::to_string(first + i) : " row " + std::to_string(i + 1));
        if (fi < 0.0)
            return makeError(ErrorCode::OutOfRange, at + ", column '" + f->name + "': negative frequency");
        if (!frf.freqHz.empty() && !(fi > frf.freqHz.back()))
            return makeError(ErrorCode::BadInput,
                             at + ", column '" + f->name + "': frequencies must increase strictly");
        std::complex<double> h;
        if (re && im) {
            h = {re->data[i], im->data[i]};
        } else {
            const double m = magDb ? std::pow(10.0, magDb->data[i] / 20.0) : mag->data[i];
            h = std::polar(m, ph->data[i] * model::kRadPerDeg);
        }
        frf.push(fi, h, std::nan(""), true);
    }
    frf.metadata.set("column", name.empty() ? "re/im" : name);
    std::string units = options.units;
    if (units.empty()) {
        if (const auto* u = table.metadata.find(model::meta::kUnits))
            units = u->text();
    }
    if (!units.empty()) {
        if (auto st = convertFrfUnits(frf, units, sourceName); !st)
            return st.error();
    }
    return frf;
}

} // namespace axistune::io

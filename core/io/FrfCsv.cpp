// SPDX-License-Identifier: GPL-3.0-or-later
// FRF CSV reader and writer (DESIGN.md "File formats").
#include "core/io/FrfCsv.h"

#include "core/io/TextFile.h"
#include "core/model/Constants.h"
#include "core/model/InputLimits.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/model/Units.h"

#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>

namespace axistune::io {

namespace detail {

std::vector<std::string> splitCsvLine(const std::string& line)
{
    std::vector<std::string> cells;
    std::string cur;
    auto flush = [&] {
        const auto b = cur.find_first_not_of(" \t");
        const auto e = cur.find_last_not_of(" \t\r");
        cells.push_back(b == std::string::npos ? std::string() : cur.substr(b, e - b + 1));
        cur.clear();
    };
    for (char c : line) {
        if (c == ',')
            flush();
        else
            cur.push_back(c);
    }
    flush();
    return cells;
}

bool parseDouble(const std::string& cell, double& value)
{
    const auto v = model::parseNumber(cell, true);
    if (!v || model::isDenormal(*v))
        return false;
    value = *v;
    return true;
}

std::string formatDouble(double v)
{
    return model::formatShortest(v);
}

bool parseMetadataLine(const std::string& line, std::string& key, std::string& value)
{
    if (line.empty() || line[0] != '#')
        return false;
    const auto eq = line.find('=');
    if (eq == std::string::npos)
        return false;
    auto trim = [](std::string s) {
        const auto b = s.find_first_not_of(" \t");
        const auto e = s.find_last_not_of(" \t\r");
        return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
    };
    key = trim(line.substr(1, eq - 1));
    value = trim(line.substr(eq + 1));
    return !key.empty();
}

}  // namespace detail

namespace {

struct Columns {
    std::optional<std::size_t> f, re, im, magDb, phaseDeg, coherence, valid;
};

std::string where(const std::string& source, std::size_t line, const std::string& column)
{
    return source + " line " + std::to_string(line) + (column.empty() ? "" : ", column '" + column + "'");
}

Result<Columns> parseHeader(const std::vector<std::string>& cells, const std::string& source, std::size_t line)
{
    Columns c;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const auto& n = cells[i];
        std::optional<std::size_t>* slot = nullptr;
        if (n == "f_Hz")
            slot = &c.f;
        else if (n == "re")
            slot = &c.re;
        else if (n == "im")
            slot = &c.im;
        else if (n == "mag_dB")
            slot = &c.magDb;
        else if (n == "phase_deg")
            slot = &c.phaseDeg;
        else if (n == "coherence")
            slot = &c.coherence;
        else if (n == "valid")
            slot = &c.valid;
        if (slot == nullptr)
            continue;  // unknown columns are ignored
        if (slot->has_value())
            return makeError(ErrorCode::BadInput, where(source, line, n) + ": duplicate column");
        *slot = i;
    }
    if (!c.f)
        return makeError(ErrorCode::BadInput, where(source, line, "") + ": missing column 'f_Hz' in header");
    const bool cartesian = c.re && c.im;
    const bool polar = c.magDb && c.phaseDeg;
    if (!cartesian && !polar) {
        return makeError(ErrorCode::BadInput,
                         where(source, line, "") + ": header needs columns 're' and 'im' (or 'mag_dB' and 'phase_deg')");
    }
    return c;
}

}  // namespace

Result<dsp::FrequencyResponse> readFrfCsv(std::istream& in, const std::string& sourceName)
{
    dsp::FrequencyResponse frf;
    std::optional<Columns> cols;
    std::size_t headerWidth = 0;
    std::string line;
    std::size_t lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (auto lim = model::checkCsvLine(sourceName, static_cast<std::size_t>(lineNo), line.size()); !lim)
            return lim.error();
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos)
            continue;
        if (line[0] == '#') {
            std::string k, v;
            if (detail::parseMetadataLine(line, k, v))
                frf.metadata.setFromText(k, std::move(v));
            continue;
        }
        const auto cells = detail::splitCsvLine(line);
        if (!cols) {
            auto h = parseHeader(cells, sourceName, lineNo);
            if (!h)
                return h.error();
            cols = h.value();
            headerWidth = cells.size();
            continue;
        }
        if (cells.size() != headerWidth) {
            return makeError(ErrorCode::BadInput, where(sourceName, lineNo, "") + ": " + std::to_string(cells.size())
                                                      + " cells, the header has " + std::to_string(headerWidth));
        }
        auto number = [&](std::size_t idx, const char* name, double& v) -> Status {
            if (!detail::parseDouble(cells[idx], v))
                return makeError(ErrorCode::BadInput,
                                 where(sourceName, lineNo, name) + ": " + model::badNumberText(cells[idx]));
            if (!std::isfinite(v))
                return makeError(ErrorCode::BadInput, where(sourceName, lineNo, name) + ": not finite ('" + cells[idx] + "')");
            return {};
        };
        double f = 0.0;
        if (auto s = number(*cols->f, "f_Hz", f); !s)
            return s.error();
        if (f < 0.0)
            return makeError(ErrorCode::OutOfRange, where(sourceName, lineNo, "f_Hz") + ": negative frequency");
        if (!frf.freqHz.empty() && !(f > frf.freqHz.back()))
            return makeError(ErrorCode::BadInput, where(sourceName, lineNo, "f_Hz") + ": frequencies must increase strictly");
        std::complex<double> h;
        if (cols->re && cols->im) {
            double re = 0.0, im = 0.0;
            if (auto s = number(*cols->re, "re", re); !s)
                return s.error();
            if (auto s = number(*cols->im, "im", im); !s)
                return s.error();
            h = {re, im};
        } else {
            double db = 0.0, deg = 0.0;
            if (auto s = number(*cols->magDb, "mag_dB", db); !s)
                return s.error();
            if (auto s = number(*cols->phaseDeg, "phase_deg", deg); !s)
                return s.error();
            h = std::polar(std::pow(10.0, db / 20.0), deg * model::kRadPerDeg);
            if (!std::isfinite(h.real()) || !std::isfinite(h.imag()))
                return makeError(ErrorCode::OutOfRange, where(sourceName, lineNo, "mag_dB") + ": " +
                                                            cells[*cols->magDb] + " dB does not fit a double");
        }
        double coh = std::nan("");
        if (cols->coherence && !cells[*cols->coherence].empty() && cells[*cols->coherence] != "nan") {
            if (auto s = number(*cols->coherence, "coherence", coh); !s)
                return s.error();
            if (coh < 0.0 || coh > 1.0 + 1e-9)
                return makeError(ErrorCode::OutOfRange, where(sourceName, lineNo, "coherence") + ": outside [0, 1]");
        }
        bool valid = true;
        if (cols->valid) {
            const auto& c = cells[*cols->valid];
            if (c == "1")
                valid = true;
            else if (c == "0")
                valid = false;
            else
                return makeError(ErrorCode::BadInput, where(sourceName, lineNo, "valid") + ": must be 0 or 1 ('" + c + "')");
        }
        frf.push(f, h, coh, valid);
    }
    if (!cols)
        return makeError(ErrorCode::BadInput, sourceName + ": no header line (expected " + kFrfCsvHeader + ")");
    if (frf.empty())
        return makeError(ErrorCode::BadInput, sourceName + ": no data rows");
    if (const auto* u = frf.metadata.find(model::meta::kUnits)) {
        const std::string unit = u->text();
        if (auto st = convertFrfUnits(frf, unit, sourceName); !st)
            return st.error();
    }
    return frf;
}

Status convertFrfUnits(dsp::FrequencyResponse& frf, const std::string& unit, const std::string& sourceName)
{
    auto u = model::findUnit(unit);
    if (!u) {
        return makeError(ErrorCode::BadInput, sourceName + ": units '" + unit
                                                  + "' is not a known unit (m/N, mm/N, um/N, nm/N, m/s/N, mm/s/N, m/s2/N, "
                                                    "mm/s2/N, g/N, ...: docs/formats.md)");
    }
    for (auto& h : frf.h)
        h *= u->toSi;
    frf.metadata.set(model::meta::kUnits, std::string(u->si));
    if (u->si != unit)
        frf.metadata.set("units_in_file", unit);
    return {};
}

Result<dsp::FrequencyResponse> readFrfCsvFile(const std::string& path)
{
    auto text = model::readInputFile(path);
    if (!text)
        return text.error();
    std::istringstream in(std::move(text).value());
    return readFrfCsv(in, path);
}

Status writeFrfCsv(std::ostream& out, const dsp::FrequencyResponse& frf)
{
    const std::size_t n = frf.size();
    if (frf.h.size() != n || frf.coherence.size() != n || frf.valid.size() != n)
        return makeError(ErrorCode::Internal, "FRF arrays of unequal length");
    // The output boundary: a point that is not finite is a bug upstream, never a row of the file.
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(frf.freqHz[i]) || !std::isfinite(frf.h[i].real()) || !std::isfinite(frf.h[i].imag()))
            return makeError(ErrorCode::Internal,
                             "FRF point " + std::to_string(i + 1) + " is not finite; nothing written");
    }
    for (const auto& [k, v] : frf.metadata)
        out << "# " << k << '=' << v.text() << '\n';
    out << kFrfCsvHeader << '\n';
    using detail::formatDouble;
    for (std::size_t i = 0; i < n; ++i) {
        const auto h = frf.h[i];
        out << formatDouble(frf.freqHz[i]) << ',' << formatDouble(h.real()) << ',' << formatDouble(h.imag()) << ',';
        // |h| = 0 (an invalid point) has no dB value: the cell stays empty like an undefined coherence.
        if (const double db = dsp::magnitudeDb(h); std::isfinite(db))
            out << formatDouble(db) << ',' << formatDouble(dsp::phaseDeg(h));
        else
            out << ',';
        out << ',';
        if (std::isfinite(frf.coherence[i]))
            out << formatDouble(frf.coherence[i]);
        out << ',' << (frf.valid[i] ? '1' : '0') << '\n';
    }
    if (!out)
        return makeError(ErrorCode::Io, "writing the FRF CSV failed");
    return {};
}

Status writeFrfCsvFile(const std::string& path, const dsp::FrequencyResponse& frf)
{
    return writeTextFile(path, [&](std::ostream& out) { return writeFrfCsv(out, frf); });
}

}  // namespace axistune::io

// SPDX-License-Identifier: GPL-3.0-or-later
// Sine-stream CSV reader and writer (DESIGN.md "File formats").
#include "core/io/SweepCsv.h"

#include "core/io/FrfCsv.h"
#include "core/io/TextFile.h"
#include "core/model/InputLimits.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace axistune::io {

namespace {

std::string where(const std::string& source, std::size_t line, const std::string& column)
{
    return source + " line " + std::to_string(line) + (column.empty() ? "" : ", column '" + column + "'");
}

}  // namespace

Result<dsp::SweepRecording> readSweepCsv(std::istream& in, const std::string& src)
{
    dsp::SweepRecording rec;
    static const char* kNames[5] = {"freq_Hz", "phase_offset_deg", "sample", "excitation", "response"};
    std::size_t col[5] = {};
    std::size_t width = 0;
    bool haveHeader = false;
    std::string line;
    std::size_t lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (auto lim = model::checkCsvLine(src, static_cast<std::size_t>(lineNo), line.size()); !lim)
            return lim.error();
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos)
            continue;
        if (line[0] == '#') {
            std::string k, v;
            if (detail::parseMetadataLine(line, k, v))
                rec.metadata.setFromText(k, std::move(v));
            continue;
        }
        const auto cells = detail::splitCsvLine(line);
        if (!haveHeader) {
            for (int c = 0; c < 5; ++c) {
                std::size_t i = 0;
                while (i < cells.size() && cells[i] != kNames[c])
                    ++i;
                if (i == cells.size()) {
                    return makeError(ErrorCode::BadInput, where(src, lineNo, "") + ": missing column '" + kNames[c]
                                                              + "' (expected " + kSweepCsvHeader + ")");
                }
                col[c] = i;
            }
            width = cells.size();
            haveHeader = true;
            continue;
        }
        if (cells.size() != width) {
            return makeError(ErrorCode::BadInput, where(src, lineNo, "") + ": " + std::to_string(cells.size())
                                                      + " cells, the header has " + std::to_string(width));
        }
        double v[5] = {};
        for (int c = 0; c < 5; ++c) {
            const auto& cell = cells[col[c]];
            if (!detail::parseDouble(cell, v[c]))
                return makeError(ErrorCode::BadInput,
                                 where(src, lineNo, kNames[c]) + ": " + model::badNumberText(cell));
            if (!std::isfinite(v[c]))
                return makeError(ErrorCode::BadInput, where(src, lineNo, kNames[c]) + ": not finite ('" + cell + "')");
        }
        std::int64_t k = 0;
        {
            const auto& cell = cells[col[2]];
            const char* b = cell.data();
            if (*b == '+')
                ++b;
            const auto r = std::from_chars(b, cell.data() + cell.size(), k);
            if (r.ec != std::errc() || r.ptr != cell.data() + cell.size())
                return makeError(ErrorCode::BadInput, where(src, lineNo, "sample") + ": not an integer ('" + cell + "')");
        }
        if (!(v[0] > 0.0))
            return makeError(ErrorCode::OutOfRange, where(src, lineNo, "freq_Hz") + ": frequency must be positive");
        if (rec.blocks.empty() || rec.blocks.back().freqHz != v[0] || rec.blocks.back().phaseOffsetDeg != v[1]) {
            dsp::SweepBlock b;
            b.freqHz = v[0];
            b.phaseOffsetDeg = v[1];
            rec.blocks.push_back(std::move(b));
        } else if (k != rec.blocks.back().sample.back() + 1) {
            return makeError(ErrorCode::BadInput, where(src, lineNo, "sample") + ": expected "
                                                      + std::to_string(rec.blocks.back().sample.back() + 1) + ", found "
                                                      + std::to_string(k));
        }
        auto& b = rec.blocks.back();
        b.sample.push_back(k);
        b.excitation.push_back(v[3]);
        b.response.push_back(v[4]);
    }
    if (!haveHeader)
        return makeError(ErrorCode::BadInput, src + ": no header line (expected " + kSweepCsvHeader + ")");
    if (rec.blocks.empty())
        return makeError(ErrorCode::BadInput, src + ": no data rows");
    const auto fs = rec.metadata.number(model::meta::kFsHz);
    if (!fs)
        return makeError(ErrorCode::BadInput, src + ": " + fs.error().detail);
    if (!(*fs > 0.0) || model::isDenormal(*fs))
        return makeError(ErrorCode::BadInput, src + ": metadata 'fs_Hz' is not a positive number ('" +
                                                  *rec.metadata.text(model::meta::kFsHz) + "')");
    rec.fsHz = *fs;
    const auto amplitude = rec.metadata.optionalNumber("amplitude");
    if (!amplitude)
        return makeError(ErrorCode::BadInput, src + ": " + amplitude.error().detail);
    rec.amplitude = amplitude->value_or(rec.amplitude);
    return rec;
}

Result<dsp::SweepRecording> readSweepCsvFile(const std::string& path)
{
    auto text = model::readInputFile(path);
    if (!text)
        return text.error();
    std::istringstream in(std::move(text).value());
    return readSweepCsv(in, path);
}

Status writeSweepCsv(std::ostream& out, const dsp::SweepRecording& rec)
{
    using detail::formatDouble;
    out << "# fs_Hz=" << formatDouble(rec.fsHz) << '\n';
    out << "# amplitude=" << formatDouble(rec.amplitude) << '\n';
    for (const auto& [k, v] : rec.metadata) {
        if (k != model::meta::kFsHz.name && k != "amplitude")
            out << "# " << k << '=' << v.text() << '\n';
    }
    out << kSweepCsvHeader << '\n';
    for (const auto& b : rec.blocks) {
        if (b.sample.size() != b.excitation.size() || b.sample.size() != b.response.size())
            return makeError(ErrorCode::Internal, "sine-stream block arrays of unequal length");
        const std::string prefix = formatDouble(b.freqHz) + ',' + formatDouble(b.phaseOffsetDeg) + ',';
        for (std::size_t i = 0; i < b.sample.size(); ++i) {
            out << prefix << b.sample[i] << ',' << formatDouble(b.excitation[i]) << ',' << formatDouble(b.response[i])
                << '\n';
        }
    }
    if (!out)
        return makeError(ErrorCode::Io, "writing the sine-stream CSV failed");
    return {};
}

Status writeSweepCsvFile(const std::string& path, const dsp::SweepRecording& rec)
{
    return writeTextFile(path, [&](std::ostream& out) { return writeSweepCsv(out, rec); });
}

}  // namespace axistune::io

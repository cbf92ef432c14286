// SPDX-License-Identifier: GPL-3.0-or-later
// Scope CSV reader: the capture reader plus the checks of the sample column (docs/formats.md).
#include "core/io/ScopeCsv.h"

#include "core/io/CaptureCsv.h"
#include "core/io/TextFile.h"
#include "core/model/InputLimits.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"

#include <cmath>
#include <sstream>

namespace axistune::io {
namespace {

/// Line numbers of the data rows (the lines after the header that are neither blank nor comments), as the
/// capture reader counts them.
std::vector<std::size_t> dataRowLines(const std::string& text)
{
    std::vector<std::size_t> lines;
    std::istringstream in(text);
    std::string line;
    std::size_t n = 0;
    bool header = false;
    while (std::getline(in, line)) {
        ++n;
        const std::string_view t = trimBlanks(line);
        if (t.empty() || t[0] == '#')
            continue;
        if (header)
            lines.push_back(n);
        header = true;
    }
    return lines;
}

} // namespace

Result<ScopeTable> readScopeCsv(std::istream& in, const std::string& sourceName)
{
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::istringstream again(text);
    auto cap = readCaptureCsv(again, sourceName);
    if (!cap)
        return cap.error();
    ScopeTable t;
    auto fs = cap->metadata.number(model::meta::kFsHz);
    if (!fs)
        return makeError(ErrorCode::BadInput,
                         sourceName + ": metadata " + fs.error().detail + " (a scope CSV starts with '# fs_Hz=RATE')");
    if (!(std::isfinite(*fs) && *fs > 0.0))
        return makeError(ErrorCode::BadInput, sourceName +
                                                  ": metadata fs_Hz=" + *cap->metadata.text(model::meta::kFsHz) +
                                                  " must be a positive sample rate");
    t.fsHz = *fs;
    const model::Channel* sample = cap->channel("sample");
    if (!sample)
        return makeError(ErrorCode::BadInput,
                         sourceName + ": no column 'sample' (the drive's sample number of every row)");
    const auto lines = dataRowLines(text);
    auto where = [&](std::size_t row) {
        return sourceName + " line " + std::to_string(row < lines.size() ? lines[row] : 0) + ", column 'sample'";
    };
    t.samples.reserve(sample->data.size());
    for (std::size_t i = 0; i < sample->data.size(); ++i) {
        const double v = sample->data[i];
        if (!(v >= 0.0 && v <= 9007199254740992.0 && v == std::floor(v)))
            return makeError(ErrorCode::BadInput, where(i) + ": " + model::formatShortest(v) +
                                                      " is not a sample number (a whole number >= 0)");
        const auto n = static_cast<std::uint64_t>(v);
        if (!t.samples.empty() && n <= t.samples.back())
            return makeError(ErrorCode::BadInput,
                             where(i) + ": sample " + std::to_string(n) +
                                 (n == t.samples.back()
                                      ? " repeats the row before"
                                      : " is below the row before (" + std::to_string(t.samples.back()) + ")"));
        if (!t.samples.empty())
            t.missingSamples += n - t.samples.back() - 1;
        t.samples.push_back(n);
    }
    t.capture = std::move(cap).value();
    return t;
}

Result<ScopeTable> readScopeCsvFile(const std::string& path)
{
    auto text = model::readInputFile(path);
    if (!text)
        return text.error();
    std::istringstream in(std::move(text).value());
    return readScopeCsv(in, path);
}

} // namespace axistune::io

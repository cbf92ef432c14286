// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading and writing one text file through a stream, with errors that name the path. Shared by the CSV
// writers (capture, FRF, sine stream, ball-bar). The text is built in memory and written atomically
// (core/io/AtomicFile.h): a failed or interrupted write never leaves half a file.

#include "core/io/AtomicFile.h"
#include "core/model/InputLimits.h"
#include "core/model/Result.h"

#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>

namespace axistune::io {

/// `s` without leading and trailing blanks (space, tab, carriage return): the cell trimming of every
/// text reader (CSV, UFF, tables, profiles).
inline std::string_view trimBlanks(std::string_view s)
{
    std::size_t b = 0, e = s.size();
    while (b < e && (s[b] == ' ' || s[b] == '\t' || s[b] == '\r'))
        ++b;
    while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t' || s[e - 1] == '\r'))
        --e;
    return s.substr(b, e - b);
}

/// Calls `write(std::ostream&) -> Status` into memory, then writes `path` atomically.
template <typename WriteFn>
Status writeTextFile(const std::string& path, WriteFn&& write)
{
    std::ostringstream text;
    if (Status s = write(static_cast<std::ostream&>(text)); !s)
        return makeError(s.error().code, path + ": " + s.error().detail);
    if (!text)
        return makeError(ErrorCode::Io, path + ": the text could not be composed");
    return writeFileAtomic(path, text.view());
}

/// Reads `path` through the input limits (model::readInputFile: a regular file, not a FIFO, device or
/// directory, at most kMaxInputFileBytes; errors name the path) and returns `read(std::istream&, path)`.
/// Shared by the import readers (table, halscope, UFF58).
template <typename ReadFn>
auto readFromFile(const std::string& path, ReadFn&& read) -> decltype(read(std::declval<std::istream&>(), path))
{
    auto text = model::readInputFile(path);
    if (!text)
        return text.error();
    std::istringstream f(std::move(text).value());
    return read(static_cast<std::istream&>(f), path);
}

}  // namespace axistune::io

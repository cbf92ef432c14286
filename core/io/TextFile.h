// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Writing one text file through a stream writer, with errors that name the path. Shared by the CSV
// writers (capture, FRF, sine stream, ball-bar).

#include "core/model/Result.h"

#include <fstream>
#include <ostream>
#include <string>

namespace axistune::io {

/// Opens `path`, calls `write(std::ostream&) -> Status`, closes and checks the stream.
template <typename WriteFn>
Status writeTextFile(const std::string& path, WriteFn&& write)
{
    std::ofstream f(path);
    if (!f)
        return makeError(ErrorCode::Io, path + ": cannot open for writing");
    if (Status s = write(static_cast<std::ostream&>(f)); !s)
        return makeError(s.error().code, path + ": " + s.error().detail);
    f.close();
    if (!f)
        return makeError(ErrorCode::Io, path + ": write failed");
    return Status::success();
}

/// Opens `path` for reading and returns `read(std::istream&, path)`; NotFound naming the path when it cannot
/// be opened. Shared by the import readers (table, halscope, UFF58).
template <typename ReadFn>
auto readFromFile(const std::string& path, ReadFn&& read) -> decltype(read(std::declval<std::istream&>(), path))
{
    std::ifstream f(path);
    if (!f)
        return makeError(ErrorCode::NotFound, path + ": cannot open the file");
    return read(static_cast<std::istream&>(f), path);
}

}  // namespace axistune::io

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

}  // namespace axistune::io

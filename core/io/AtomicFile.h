// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Every file AxisTune writes goes through here (docs/storage.md "Files the tool writes"): the bytes go
// to a temporary file in the same folder, which is flushed to the disk (fsync) and then renamed over
// the target, and the folder is synced. A crash, a kill or a full disk therefore leaves either the
// previous file or the complete new one, never half a file or an empty one; on any error the
// temporary file is removed and the message names the file and the cause.
//
// A symbolic link is followed (its target is replaced, the link kept). A target that exists and is
// not a regular file (/dev/stdout, /dev/null, a FIFO) is written in place: nothing to rename there.

#include "core/model/Result.h"

#include <functional>
#include <string>
#include <string_view>

namespace axistune::io {

/// Writes `bytes` to `path` atomically (see above).
Status writeFileAtomic(const std::string& path, std::string_view bytes);

/// The same for writers that need a file name (image, PDF and SVG writers of Qt): `produce(tempPath)`
/// writes the whole file at `tempPath` (an existing, empty file of the right permissions) and returns
/// its status; then it is synced and renamed over `path`. A failing `produce` leaves `path` unchanged.
Status writeFileAtomicVia(const std::string& path, const std::function<Status(const std::string& tempPath)>& produce);

/// Text files: the same as writeFileAtomic.
Status writeTextFileAtomic(const std::string& path, const std::string& text);

} // namespace axistune::io

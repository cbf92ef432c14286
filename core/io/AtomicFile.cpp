// SPDX-License-Identifier: GPL-3.0-or-later
// Atomic file replacement on POSIX: write a temporary file in the target's folder, fsync it, rename(2)
// it over the target (atomic within one file system), fsync the folder so the new name survives a
// power cut.
#include "core/io/AtomicFile.h"

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace axistune::io {
namespace {

namespace fs = std::filesystem;

std::string why(int err)
{
    return std::strerror(err);
}

/// ".NAME.axistune-PID-N.tmp" next to the target, created empty with mode 0666 & ~umask (O_EXCL).
int createTemp(const fs::path& target, std::string& tmp)
{
    static std::atomic<unsigned> counter{0};
    std::string base = target.filename().string();
    if (base.size() > 180)
        base.resize(180); // stay below NAME_MAX with the suffix
    for (int attempt = 0; attempt < 100; ++attempt) {
        const auto name =
            "." + base + ".axistune-" + std::to_string(getpid()) + "-" + std::to_string(counter++) + ".tmp";
        tmp = (target.parent_path() / name).string();
        const int fd = open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST)
            return fd;
    }
    errno = EEXIST;
    return -1;
}

Status writeAll(const std::string& path, std::string_view bytes)
{
    const int fd = open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0)
        return makeError(ErrorCode::Io, why(errno));
    std::size_t done = 0;
    while (done < bytes.size()) {
        const auto n = write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            const int err = n < 0 ? errno : EIO;
            close(fd);
            return makeError(ErrorCode::Io, why(err));
        }
        done += static_cast<std::size_t>(n);
    }
    if (close(fd) != 0)
        return makeError(ErrorCode::Io, why(errno));
    return Status::success();
}

} // namespace

Status writeFileAtomicVia(const std::string& path, const std::function<Status(const std::string&)>& produce)
{
    if (path.empty())
        return makeError(ErrorCode::BadInput, "no file name given");
    fs::path target(path);
    struct stat st {};
    if (lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
        if (char* real = realpath(path.c_str(), nullptr)) {
            target = real;
            std::free(real);
        }
    }
    const bool existed = stat(target.c_str(), &st) == 0;
    if (existed && S_ISDIR(st.st_mode))
        return makeError(ErrorCode::BadInput, path + ": is a folder, not a file");
    if (existed && !S_ISREG(st.st_mode)) {
        if (auto s = produce(target.string()); !s)
            return makeError(s.error().code, path + ": not written (" + s.error().detail + ")");
        return Status::success();
    }
    if (target.parent_path().empty())
        target = fs::path(".") / target;
    const std::string unchanged = existed ? "; the previous file is unchanged" : "; no file was written";
    std::string tmp;
    const int fd = createTemp(target, tmp);
    if (fd < 0)
        return makeError(ErrorCode::Io, path + ": cannot create a file in " + target.parent_path().string() + " (" +
                                            why(errno) + ")" + unchanged);
    if (existed)
        (void)fchmod(fd, st.st_mode & 07777); // the replacement keeps the permissions of the file it replaces
    close(fd);
    auto fail = [&](const std::string& cause) {
        unlink(tmp.c_str());
        return makeError(ErrorCode::Io, path + ": not written (" + cause + ")" + unchanged);
    };
    if (auto s = produce(tmp); !s)
        return fail(s.error().detail);
    // The data must be on the disk before the new name points at it.
    const int sfd = open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
    if (sfd < 0)
        return fail(why(errno));
    if (fsync(sfd) != 0) {
        const int err = errno;
        close(sfd);
        return fail(why(err));
    }
    close(sfd);
    if (rename(tmp.c_str(), target.c_str()) != 0)
        return fail(why(errno));
    const int dfd = open(target.parent_path().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
        (void)fsync(dfd); // best effort: the rename itself is done and atomic
        close(dfd);
    }
    return Status::success();
}

Status writeFileAtomic(const std::string& path, std::string_view bytes)
{
    return writeFileAtomicVia(path, [&](const std::string& p) { return writeAll(p, bytes); });
}

Status writeTextFileAtomic(const std::string& path, const std::string& text)
{
    return writeFileAtomic(path, text);
}

} // namespace axistune::io

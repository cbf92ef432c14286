// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/hal/HalCmd.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace axistune::device::hal {
namespace {

std::string commandText(const std::vector<std::string>& argv)
{
    std::string s;
    for (const auto& a : argv)
        s += (s.empty() ? "" : " ") + a;
    return s;
}

std::string trimmed(std::string s)
{
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '\r'))
        s.pop_back();
    return s;
}

} // namespace

Result<std::string> runHalcmd(const HalSessionOptions& options, std::span<const std::string> args)
{
    std::vector<std::string> argv = options.halcmd;
    argv.insert(argv.end(), args.begin(), args.end());
    if (argv.empty())
        return makeError(ErrorCode::BadInput, "no halcmd command configured");
    const std::string text = commandText(argv);

    int out[2], err[2];
    if (pipe2(out, O_CLOEXEC) != 0)
        return makeError(ErrorCode::Device, "cannot run '" + text + "': " + std::strerror(errno));
    if (pipe2(err, O_CLOEXEC) != 0) {
        close(out[0]);
        close(out[1]);
        return makeError(ErrorCode::Device, "cannot run '" + text + "': " + std::strerror(errno));
    }
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&fa, out[1], 1);
    posix_spawn_file_actions_adddup2(&fa, err[1], 2);
    std::vector<char*> cargv;
    for (auto& a : argv)
        cargv.push_back(a.data());
    cargv.push_back(nullptr);
    pid_t pid = -1;
    const int rc = posix_spawnp(&pid, cargv[0], &fa, nullptr, cargv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    close(out[1]);
    close(err[1]);
    if (rc != 0) {
        close(out[0]);
        close(err[0]);
        return makeError(ErrorCode::Device, "cannot run '" + text + "': " + std::strerror(rc));
    }

    std::string so, se;
    const auto deadline = std::chrono::steady_clock::now() + options.timeout;
    bool outOpen = true, errOpen = true, timedOut = false;
    char buf[4096];
    while (outOpen || errOpen) {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            timedOut = true;
            break;
        }
        pollfd fds[2] = {{outOpen ? out[0] : -1, POLLIN, 0}, {errOpen ? err[0] : -1, POLLIN, 0}};
        const int n = poll(fds, 2, static_cast<int>(left.count()));
        if (n < 0 && errno == EINTR)
            continue;
        for (int i = 0; i < 2; ++i) {
            if (fds[i].fd < 0 || fds[i].revents == 0)
                continue;
            const ssize_t r = read(fds[i].fd, buf, sizeof buf);
            if (r > 0)
                (i == 0 ? so : se).append(buf, static_cast<std::size_t>(r));
            else if (r == 0 || (r < 0 && errno != EINTR && errno != EAGAIN))
                (i == 0 ? outOpen : errOpen) = false;
        }
    }
    close(out[0]);
    close(err[0]);
    if (timedOut)
        kill(pid, SIGKILL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (timedOut)
        return makeError(ErrorCode::Device,
                         "'" + text + "' did not finish within " + std::to_string(options.timeout.count()) + " ms");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::string msg = trimmed(se.empty() ? so : se);
        return makeError(ErrorCode::Device, "'" + text + "' failed" + (msg.empty() ? std::string{} : ": " + msg));
    }
    return so;
}

Result<std::string> runHalcmd(const HalSessionOptions& options, std::initializer_list<std::string> args)
{
    return runHalcmd(options, std::span<const std::string>(args.begin(), args.size()));
}

} // namespace axistune::device::hal

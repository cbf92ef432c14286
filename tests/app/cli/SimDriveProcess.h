// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// axistune-simdrive in a child process on a free loopback port, for end-to-end tests.

#include "tests/app/cli/CliRunner.h"

#include <chrono>
#include <filesystem>
#include <poll.h>
#include <signal.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace axistune::testing {

/// axistune-simdrive in a child process on a free loopback port; stopped with SIGTERM at the end.
class SimDrive {
public:
    explicit SimDrive(const std::string& args)
    {
        m_errPath = (m_dir / "stderr.txt").string();
        int fds[2];
        if (pipe(fds) != 0)
            return;
        m_pid = fork();
        if (m_pid == 0) {
            dup2(fds[1], 1);
            close(fds[0]);
            const std::string cmd = std::string("exec ") + AXISTUNE_SIMDRIVE + " --port 0 " + args + " 2>" + m_errPath;
            execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
            _exit(127);
        }
        close(fds[1]);
        m_out = fds[0];
        // First stdout line: "axistune-simdrive listening on 127.0.0.1:PORT"; bounded to 10 s.
        std::string line;
        for (int i = 0; i < 100 && line.find('\n') == std::string::npos; ++i) {
            pollfd p{m_out, POLLIN, 0};
            if (poll(&p, 1, 100) > 0) {
                char buf[256];
                const auto n = read(m_out, buf, sizeof buf);
                if (n <= 0)
                    break;
                line.append(buf, static_cast<std::size_t>(n));
            }
        }
        const auto colon = line.rfind(':');
        if (colon != std::string::npos)
            m_port = std::atoi(line.c_str() + colon + 1);
    }
    ~SimDrive()
    {
        stop(SIGTERM);
        if (m_out >= 0)
            close(m_out);
    }
    /// Sends the signal and waits (at most 5 s) for the process; returns its exit status or -1.
    int stop(int sig)
    {
        if (m_pid <= 0)
            return -1;
        kill(m_pid, sig);
        int status = 0;
        for (int i = 0; i < 500; ++i) {
            if (waitpid(m_pid, &status, WNOHANG) == m_pid) {
                m_pid = -1;
                return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        kill(m_pid, SIGKILL);
        waitpid(m_pid, &status, 0);
        m_pid = -1;
        return -1;
    }
    int port() const { return m_port; }
    std::string uri(const std::string& query = "") const
    {
        return "modbus://127.0.0.1:" + std::to_string(m_port) + (query.empty() ? "" : "?" + query);
    }
    std::string log() const { return readFileText(m_errPath); }

private:
    ScopedTempDir m_dir{"simdrive"};
    std::string m_errPath;
    pid_t m_pid = -1;
    int m_out = -1;
    int m_port = 0;
};

}  // namespace axistune::testing

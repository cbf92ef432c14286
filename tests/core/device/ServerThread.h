// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// axistune-simdrive's server in-process on a thread, over a real loopback socket (the Modbus tests).

#include "core/device/SimDriveServer.h"

#include <gtest/gtest.h>

#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace axistune::devtest {

class ServerThread {
public:
    explicit ServerThread(device::SimDriveServerOptions o)
    {
        o.log = [this](const std::string& l) {
            std::lock_guard lock(m_mutex);
            m_log += l + "\n";
        };
        auto s = device::SimDriveServer::create(o);
        EXPECT_TRUE(s.ok()) << (s.ok() ? "" : s.error().detail);
        if (!s.ok())
            return;
        m_server = std::move(s).value();
        m_thread = std::thread([this] { (void)m_server->serve(); });
    }
    ~ServerThread() { stop(); }
    void stop()
    {
        if (m_server)
            m_server->requestStop();
        if (m_thread.joinable())
            m_thread.join();
    }
    int port() const { return m_server ? m_server->port() : 0; }
    std::string uri(int timeoutMs = 1000) const
    {
        return "modbus://127.0.0.1:" + std::to_string(port()) + "?timeout_ms=" + std::to_string(timeoutMs);
    }
    std::string log()
    {
        std::lock_guard lock(m_mutex);
        return m_log;
    }

private:
    std::unique_ptr<device::SimDriveServer> m_server;
    std::thread m_thread;
    std::mutex m_mutex;
    std::string m_log;
};

}  // namespace axistune::devtest

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// HAL is one per machine (its shared memory and realtime are global): two test processes that start the test machine
// at once, from one build's ctest -j or from two build trees, tear each other's HAL session down. Every test that
// starts it holds this lock (flock on a file in /tmp) from before the start until after the stop; the kernel
// releases it when the process ends, so a crashed test never leaves it held. `scripts/run --linuxcnc` holds it too,
// while its app runs: a test waits (and says so), and the script refuses to start while a test holds it.
#include <cstdio>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace axistune::testing {

class HalMachineLock {
public:
    HalMachineLock() : m_fd(::open("/tmp/axistune-hal-machine.lock", O_RDWR | O_CREAT | O_CLOEXEC, 0666))
    {
        if (m_fd >= 0 && ::flock(m_fd, LOCK_EX | LOCK_NB) != 0) {
            // Another test, or the test machine of `scripts/run --linuxcnc` (which holds it while the app runs).
            std::fprintf(stderr, "waiting for the HAL machine lock /tmp/axistune-hal-machine.lock (another HAL test "
                                 "or scripts/run --linuxcnc holds it)\n");
            (void)::flock(m_fd, LOCK_EX); // blocks until the other has stopped its HAL session
        }
    }
    ~HalMachineLock()
    {
        if (m_fd >= 0)
            ::close(m_fd);
    }
    HalMachineLock(const HalMachineLock&) = delete;
    HalMachineLock& operator=(const HalMachineLock&) = delete;
    bool held() const { return m_fd >= 0; }

private:
    int m_fd;
};

} // namespace axistune::testing

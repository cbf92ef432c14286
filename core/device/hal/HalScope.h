// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The scope of a `hal:` axis (docs/scope.md "LinuxCNC", docs/linuxcnc.md "Scope"): LinuxCNC's `sampler` loaded on
// the axis's servo thread with one float column per channel, each linked to the net of a pid pin, read by a host
// thread into a ScopeRecorder (trigger, pre-trigger and ring on the host, the same code as the embedded drive). The
// sampler's own sample numbers are the drive's sample numbers, so a lost row is a visible gap.
//
// LinuxCNC loads a component once, and AxisTune's tests load `sampler` too: while the scope runs no test starts,
// and while a test runs the scope is refused (both say so).

#include "core/device/Scope.h"
#include "core/device/hal/HalAxis.h"
#include "core/device/hal/HalCmd.h"
#include "core/device/hal/HalLink.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace axistune::device::hal {

/// The channels a `hal:` axis offers: the pid's command, feedback, output (the drive input net) and error, in the
/// configuration's units.
ScopeCapabilities halScopeCapabilities(const HalAxis& axis);

class HalScope {
public:
    /// Loads and links the sampler for a checked setup and starts reading. Refused when a sampler is loaded already
    /// (a test, or another program) or a channel's pin is an unlinked input (sampling it would change it).
    static Result<std::unique_ptr<HalScope>> start(const HalSessionOptions& options, const HalAxis& axis,
                                                   const ScopeCapabilities& caps, const ScopeSetup& setup);
    /// Stops reading and removes the sampler (every net as before).
    ~HalScope();
    HalScope(const HalScope&) = delete;
    HalScope& operator=(const HalScope&) = delete;

    Status stop();
    ScopeStatus status() const;
    ScopeRows rows(std::uint64_t from, std::size_t maxRows) const;
    Result<ScopeCapture> capture() const;
    /// The reader's failure (the HAL session stopped, the FIFO overran), empty while it reads.
    std::string failure() const;

private:
    HalScope() = default;
    void read();

    HalSessionOptions m_options;
    HalAxis m_axis;
    std::vector<std::vector<std::string>> m_undo; ///< halcmd argument lists, run last first
    std::unique_ptr<HalClient> m_client;
    std::unique_ptr<HalStream> m_stream;
    mutable std::mutex m_mutex;
    ScopeRecorder m_recorder; ///< guarded by m_mutex
    std::string m_failure;    ///< guarded by m_mutex
    std::atomic<bool> m_stop{false};
    std::thread m_thread;
};

} // namespace axistune::device::hal

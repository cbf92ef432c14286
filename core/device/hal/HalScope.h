// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The scope of a `hal:` axis (docs/scope.md "LinuxCNC", docs/linuxcnc.md "Scope"): instance sampler.1 of LinuxCNC's
// `sampler` (HalSampler.h) on the axis's servo thread, its pins linked to the pid's pins or to any float, bit, s32 or
// u32 pin of the HAL session, read by a host thread into a ScopeRecorder (trigger, pre-trigger and ring on the host,
// the same code as the embedded drive). The sampler's own sample numbers are the drive's sample numbers, so a lost row
// is a visible gap. The tests record through sampler.0 of the same load, so the scope runs while a test runs.

#include "core/device/Scope.h"
#include "core/device/hal/HalAxis.h"
#include "core/device/hal/HalCmd.h"
#include "core/device/hal/HalLink.h"
#include "core/device/hal/HalSampler.h"
#include "core/device/hal/HalText.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace axistune::device::hal {

/// The channels a `hal:` axis offers: the pid's command, feedback, output (the drive input net) and error, in the
/// configuration's units, then every float, bit, s32 and u32 pin of the session (`halcmd show pin`) that can be
/// sampled without changing it (an output, or an input on a net), named by the pin.
ScopeCapabilities halScopeCapabilities(const HalAxis& axis, const std::vector<HalPin>& pins);

class HalScope {
public:
    /// Links sampler.1 for a checked setup and starts reading. Refused when another program loaded a sampler, more
    /// pins of one type are asked than sampler.1 has, or a channel's pin is an unlinked input (sampling it would
    /// change it).
    static Result<std::unique_ptr<HalScope>> start(const HalSessionOptions& options, const HalAxis& axis,
                                                   const ScopeCapabilities& caps, const ScopeSetup& setup);
    /// Stops reading and removes the sampler (every net as before).
    ~HalScope();
    HalScope(const HalScope&) = delete;
    HalScope& operator=(const HalScope&) = delete;

    Status stop();
    /// Stops reading only (the capture stays readable); stop() later takes the pins and the function out of HAL.
    void stopReading();
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
    std::shared_ptr<HalSamplerModule> m_sampler;
    std::vector<std::size_t> m_pick; ///< the sampler.1 pin of each channel, in the channels' order
    std::unique_ptr<HalClient> m_client;
    std::unique_ptr<HalStream> m_stream;
    mutable std::mutex m_mutex;
    ScopeRecorder m_recorder; ///< guarded by m_mutex
    std::string m_failure;    ///< guarded by m_mutex
    std::atomic<bool> m_stop{false};
    std::thread m_thread;
};

} // namespace axistune::device::hal

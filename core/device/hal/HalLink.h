// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// AxisTune as a HAL component (LinuxCNC's user-space API, liblinuxcnchal): a heartbeat pin that the
// injection component watches, direct reads of any pin, and the streamer/sampler FIFOs that carry one row per
// servo period (docs/linuxcnc.md).

#include "core/model/Result.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace axistune::device::hal {

/// SysV shared-memory keys of LinuxCNC's streamer and sampler FIFOs, channel 0 (channel n adds n).
inline constexpr int kStreamerKey = 0x48535430;
inline constexpr int kSamplerKey = 0x48534130;

class HalClient {
public:
    /// hal_init(name), a u32 output pin NAME.heartbeat incremented every heartbeatPeriodMs by a thread while
    /// the client lives; errors name what HAL refused (no HAL session running, name in use).
    static Result<std::unique_ptr<HalClient>> open(const std::string& name, int heartbeatPeriodMs = 2);
    ~HalClient();
    HalClient(const HalClient&) = delete;
    HalClient& operator=(const HalClient&) = delete;

    const std::string& name() const { return m_name; }
    std::string heartbeatPin() const { return m_name + ".heartbeat"; }
    int componentId() const { return m_comp; }
    /// Whether the heartbeat thread got real-time priority (SCHED_FIFO); without it a heavily loaded machine can
    /// starve it past the injection's timeout, which stops the test (docs/linuxcnc.md "Safety").
    bool realtimeHeartbeat() const { return m_realtimeHeartbeat; }

    /// The value of a float, bit, s32 or u32 pin as double; NotFound when HAL has no such pin.
    Result<double> readPin(const std::string& pin) const;

private:
    HalClient() = default;
    std::string m_name;
    int m_comp = -1;
    void* m_heartbeat = nullptr; ///< hal_u32_t* in HAL shared memory
    std::atomic<bool> m_stop{false};
    bool m_realtimeHeartbeat = false;
    std::thread m_thread;
};

/// One row of a stream: values in the order of the stream's type string ("f" float, "b" bit, "s" s32, "u" u32).
class HalStream {
public:
    enum class Direction { ToHal, FromHal };
    /// Attaches to the FIFO of a loaded streamer (ToHal) or sampler (FromHal) with the given column types.
    static Result<std::unique_ptr<HalStream>> attach(const HalClient& client, Direction direction, int key,
                                                     const std::string& types);
    ~HalStream();
    HalStream(const HalStream&) = delete;
    HalStream& operator=(const HalStream&) = delete;

    std::size_t columns() const { return m_types.size(); }
    bool writable() const;
    bool readable() const;
    /// Writes one row (bits as 0/1); false when the FIFO is full.
    bool write(std::span<const double> row);
    /// Reads one row and its sample number; false when the FIFO is empty.
    bool read(std::vector<double>& row, std::uint32_t& sampleNumber);
    int underruns() const;
    int overruns() const;
    int depth() const;    ///< rows now in the FIFO
    int maxDepth() const; ///< capacity

private:
    HalStream() = default;
    std::string m_types;
    void* m_stream = nullptr; ///< hal_stream_t
};

} // namespace axistune::device::hal

// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/hal/HalLink.h"

#pragma GCC diagnostic push
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wvolatile"
#endif
#pragma GCC diagnostic ignored "-Wpedantic"
#include <hal.h>
#pragma GCC diagnostic pop

#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>
#include <mutex>
#include <pthread.h>
#include <sched.h>
#include <sys/ipc.h>
#include <sys/shm.h>

namespace axistune::device::hal {
namespace {

// hal_init and hal_exit keep their own process-wide state (a reference count, the shared memory's address) without a
// lock: the test's client and the scope's may open and close on different threads, so each call holds this mutex.
std::mutex& halLifecycleMutex()
{
    static std::mutex m;
    return m;
}

// LinuxCNC 2.9's user-space rtapi_init() (src/rtapi/uspace_common.h) keeps the address of its UUID shared memory (a
// mutex and a counter that number HAL components) in a static from the process's first call. When the process's last
// HAL component exits, that memory is unmapped; the next hal_init() maps it again, often at another address, and
// then locks the mutex and increments the counter through the stale pointer: a segfault, or a silent write into
// whatever the process mapped there since (a large vector). Seen as an intermittent crash when one test's client
// closed and the next one's opened. AxisTune therefore holds one RTAPI reference for the life of the process (it
// registers nothing in HAL) so that memory stays where rtapi_init remembers it; and when the HAL session is restarted
// under a running AxisTune (`realtime stop` removes the segment, the new session creates another), the new segment
// is attached at that same address in place of the old one, so the components AxisTune registers are numbered by
// the running session's counter.
constexpr key_t kRtapiUuidKey = 0x48484c34; // UUID_KEY in uspace_common.h and the `realtime` script

struct RtapiHold {
    int id = -1;        // the RTAPI module id of the hold
    int segment = -1;   // the UUID segment mapped at `address`
    void* address = nullptr;
    bool replaced = false; // a restarted session's segment is at `address`: the kernel detaches it at exit
    ~RtapiHold()
    {
        // rtapi_exit detaches the segment it mapped first and then looks it up: only while no stopped session has
        // removed it (marked it for destruction; LinuxCNC would print its failed lookup). The kernel detaches the
        // rest at exit.
        shmid_ds ds{};
        if (id >= 0 && !replaced && shmctl(segment, IPC_STAT, &ds) == 0 && (ds.shm_perm.mode & SHM_DEST) == 0)
            rtapi_exit(id);
    }
};

// The address at which this process maps SysV segment `segment` (/proc/self/maps names the segment by its key and
// gives its id as the inode); nullptr when it is not mapped.
void* mappedAddressOf(int segment)
{
    std::ifstream maps("/proc/self/maps");
    std::string line;
    while (std::getline(maps, line)) {
        if (line.find("/SYSV48484c34") == std::string::npos)
            continue;
        std::istringstream fields(line);
        std::string range, perms, offset, device;
        long long inode = -1;
        fields >> range >> perms >> offset >> device >> inode;
        if (inode != segment)
            continue;
        std::uintptr_t start = 0;
        const auto dash = range.find('-');
        const auto [end, ec] = std::from_chars(range.data(), range.data() + dash, start, 16);
        if (ec == std::errc() && end == range.data() + dash)
            return reinterpret_cast<void*>(start);
    }
    return nullptr;
}

// Called with halLifecycleMutex held; an empty string on success, else what failed (retried on the next open).
std::string holdRtapiForTheProcess()
{
    static RtapiHold hold;
    if (hold.id < 0) {
        hold.id = rtapi_init("AXISTUNE_HOLD");
        if (hold.id < 0)
            return "rtapi_init failed (LinuxCNC's UUID shared memory)";
        hold.segment = shmget(kRtapiUuidKey, 0, 0);
        hold.address = hold.segment >= 0 ? mappedAddressOf(hold.segment) : nullptr;
        if (!hold.address)
            return "LinuxCNC's UUID shared memory is not where rtapi_init mapped it";
        return {};
    }
    const int current = shmget(kRtapiUuidKey, 0, 0);
    if (current < 0 || current == hold.segment)
        return {}; // the same session (or none: hal_init then says so)
    // A new session: its segment replaces the old one at the address rtapi_init remembers.
    if (shmat(current, hold.address, SHM_REMAP) != hold.address)
        return std::string("the HAL session was restarted and its UUID shared memory cannot be attached where "
                           "LinuxCNC's library expects it (") +
               std::strerror(errno) + "): restart AxisTune";
    hold.segment = current;
    hold.replaced = true;
    return {};
}

} // namespace

Result<std::unique_ptr<HalClient>> HalClient::open(const std::string& name, int heartbeatPeriodMs)
{
    std::unique_lock lifecycle(halLifecycleMutex());
    if (const std::string held = holdRtapiForTheProcess(); !held.empty())
        return makeError(ErrorCode::Device, "cannot join the HAL session as '" + name + "': " + held);
    std::unique_ptr<HalClient> c(new HalClient);
    c->m_name = name;
    c->m_comp = hal_init(name.c_str());
    if (c->m_comp < 0)
        return makeError(ErrorCode::Device, "cannot join the HAL session as '" + name + "' (hal_init error " +
                                                std::to_string(c->m_comp) + "): is LinuxCNC or a HAL session running?");
    auto** pin = static_cast<hal_u32_t**>(hal_malloc(sizeof(hal_u32_t*)));
    if (!pin || hal_pin_u32_newf(HAL_OUT, pin, c->m_comp, "%s.heartbeat", name.c_str()) != 0) {
        hal_exit(c->m_comp);
        c->m_comp = -1;
        return makeError(ErrorCode::Device, "cannot create the HAL pin " + name + ".heartbeat");
    }
    **pin = 0;
    c->m_heartbeat = pin;
    hal_ready(c->m_comp);
    lifecycle.unlock();
    HalClient* self = c.get();
    c->m_thread = std::thread([self, heartbeatPeriodMs] {
        auto** p = static_cast<hal_u32_t**>(self->m_heartbeat);
        while (!self->m_stop.load()) {
            **p = **p + 1;
            std::this_thread::sleep_for(std::chrono::milliseconds(heartbeatPeriodMs));
        }
    });
    // The heartbeat must keep beating while the machine is busy: a thread starved for the injection's timeout
    // trips it (a false stop, never a false run). Real-time priority where the user may have it (root, or an
    // rtprio limit as LinuxCNC installations grant); otherwise normal scheduling.
    sched_param sp{};
    sp.sched_priority = 1;
    c->m_realtimeHeartbeat = pthread_setschedparam(c->m_thread.native_handle(), SCHED_FIFO, &sp) == 0;
    return c;
}

HalClient::~HalClient()
{
    m_stop = true;
    if (m_thread.joinable())
        m_thread.join();
    if (m_comp >= 0) {
        std::lock_guard lifecycle(halLifecycleMutex());
        hal_exit(m_comp);
    }
}

Result<double> HalClient::readPin(const std::string& pin) const
{
    hal_type_t type{};
    hal_data_u* data = nullptr;
    bool connected = false;
    if (hal_get_pin_value_by_name(pin.c_str(), &type, &data, &connected) != 0 || !data)
        return makeError(ErrorCode::NotFound, "HAL has no pin '" + pin + "'");
    switch (type) {
    case HAL_FLOAT:
        return static_cast<double>(data->f);
    case HAL_BIT:
        return data->b ? 1.0 : 0.0;
    case HAL_S32:
        return static_cast<double>(data->s);
    case HAL_U32:
        return static_cast<double>(data->u);
    default:
        return makeError(ErrorCode::Device, "HAL pin '" + pin + "' is not a number");
    }
}

Result<std::unique_ptr<HalStream>> HalStream::attach(const HalClient& client, Direction direction, int key,
                                                     const std::string& types)
{
    if (types.empty() || types.size() > HAL_STREAM_MAX_PINS || types.find_first_not_of("fbsu") != std::string::npos)
        return makeError(ErrorCode::BadInput,
                         "stream columns '" + types + "': use 1 to 20 of f (float), b (bit), s (s32) and u (u32)");
    std::unique_ptr<HalStream> s(new HalStream);
    s->m_types = types;
    auto* st = new hal_stream_t{};
    const int rc = hal_stream_attach(st, client.componentId(), key, types.c_str());
    if (rc < 0) {
        delete st;
        return makeError(ErrorCode::Device, std::string("cannot attach to the HAL ") +
                                                (direction == Direction::ToHal ? "streamer" : "sampler") +
                                                " FIFO (columns '" + types + "', error " + std::to_string(rc) +
                                                "): is it loaded with cfg=" + types + "?");
    }
    s->m_stream = st;
    return s;
}

HalStream::~HalStream()
{
    if (m_stream) {
        hal_stream_detach(static_cast<hal_stream_t*>(m_stream));
        delete static_cast<hal_stream_t*>(m_stream);
    }
}

bool HalStream::writable() const
{
    return hal_stream_writable(static_cast<hal_stream_t*>(m_stream));
}
bool HalStream::readable() const
{
    return hal_stream_readable(static_cast<hal_stream_t*>(m_stream));
}

bool HalStream::write(std::span<const double> row)
{
    if (row.size() != m_types.size() || !writable())
        return false;
    hal_stream_data data[HAL_STREAM_MAX_PINS];
    for (std::size_t i = 0; i < row.size(); ++i) {
        switch (m_types[i]) {
        case 'f':
            data[i].f = row[i];
            break;
        case 'b':
            data[i].b = row[i] != 0.0;
            break;
        case 's':
            data[i].s = static_cast<std::int32_t>(row[i]);
            break;
        default:
            data[i].u = static_cast<std::uint32_t>(row[i]);
        }
    }
    return hal_stream_write(static_cast<hal_stream_t*>(m_stream), data) == 0;
}

bool HalStream::read(std::vector<double>& row, std::uint32_t& sampleNumber)
{
    hal_stream_data data[HAL_STREAM_MAX_PINS];
    unsigned n = 0;
    if (hal_stream_read(static_cast<hal_stream_t*>(m_stream), data, &n) != 0)
        return false;
    row.resize(m_types.size());
    for (std::size_t i = 0; i < m_types.size(); ++i) {
        switch (m_types[i]) {
        case 'f':
            row[i] = static_cast<double>(data[i].f);
            break;
        case 'b':
            row[i] = data[i].b ? 1.0 : 0.0;
            break;
        case 's':
            row[i] = static_cast<double>(data[i].s);
            break;
        default:
            row[i] = static_cast<double>(data[i].u);
        }
    }
    sampleNumber = n;
    return true;
}

int HalStream::underruns() const
{
    return hal_stream_num_underruns(static_cast<hal_stream_t*>(m_stream));
}
int HalStream::overruns() const
{
    return hal_stream_num_overruns(static_cast<hal_stream_t*>(m_stream));
}
int HalStream::depth() const
{
    return hal_stream_depth(static_cast<hal_stream_t*>(m_stream));
}
int HalStream::maxDepth() const
{
    return hal_stream_maxdepth(static_cast<hal_stream_t*>(m_stream));
}

} // namespace axistune::device::hal

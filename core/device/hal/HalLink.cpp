// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/hal/HalLink.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wvolatile"
#pragma GCC diagnostic ignored "-Wpedantic"
#include <hal.h>
#pragma GCC diagnostic pop

#include <chrono>
#include <pthread.h>
#include <sched.h>

namespace axistune::device::hal {

Result<std::unique_ptr<HalClient>> HalClient::open(const std::string& name, int heartbeatPeriodMs)
{
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
    if (m_comp >= 0)
        hal_exit(m_comp);
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

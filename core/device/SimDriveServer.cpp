// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-simdrive's network side: a libmodbus TCP server with several clients multiplexed by
// select(), one request at a time, the simulation advanced between requests (docs/modbus.md).
#include "core/device/SimDriveServer.h"

#include "core/sim/MachineDefinition.h"

#include <arpa/inet.h>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <modbus/modbus.h>
#include <netinet/in.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <sys/select.h>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

namespace axistune::device {
namespace {

constexpr int kMaxClients = 8;
constexpr int kRegisterSpace = 65536;

modbus_t* mb(void* p)
{
    return static_cast<modbus_t*>(p);
}
modbus_mapping_t* mapping(void* p)
{
    return static_cast<modbus_mapping_t*>(p);
}

int be16(const std::uint8_t* p)
{
    return (p[0] << 8) | p[1];
}

} // namespace

Result<std::unique_ptr<SimDriveServer>> SimDriveServer::create(const SimDriveServerOptions& options)
{
    std::unique_ptr<SimDriveServer> s(new SimDriveServer());
    s->m_opt = options;
    auto def = sim::loadPreset(options.preset);
    if (!def)
        return def.error();
    auto drive = SimulatedDrive::create(*def, options.seed);
    if (!drive)
        return drive.error();
    s->m_drive = std::move(drive).value();
    s->m_machine = def->name;
    for (const auto& a : def->axes)
        s->m_axes.push_back(
            {a.name, a.kind == sim::AxisKind::Linear ? "linear" : "rotary", s->m_drive->simulator(a.name)});
    s->m_config.resize(s->m_axes.size());
    auto map = loadRegisterMap(options.mapFamily);
    if (!map)
        return map.error();
    s->m_map = std::move(map).value();
    // Register → slot table for the engine.
    s->m_owner.assign(kRegisterSpace, -1);
    for (const auto& [n, f] : s->m_map.fields) {
        s->m_slots.push_back({&f, nullptr, f.address, f.count});
        for (int a = f.address; a < f.address + f.count; ++a)
            s->m_owner[a] = static_cast<int>(s->m_slots.size()) - 1;
    }
    for (const auto& p : s->m_map.parameters) {
        s->m_slots.push_back({nullptr, &p, p.address, 2});
        s->m_owner[p.address] = s->m_owner[p.address + 1] = static_cast<int>(s->m_slots.size()) - 1;
    }
    if (auto st = s->loadState(); !st)
        return st.error();

    if (options.bind != "127.0.0.1" && options.bind != "localhost")
        return makeError(ErrorCode::BadInput,
                         "--bind " + options.bind + ": the simulated drive serves on 127.0.0.1 only");
    if (options.port < 0 || options.port > 65535)
        return makeError(ErrorCode::BadInput, "--port must lie in 0..65535 (0: a free port)");
    s->m_ctx = modbus_new_tcp("127.0.0.1", options.port);
    if (!s->m_ctx)
        return makeError(ErrorCode::Device, std::string("cannot create the Modbus context: ") + modbus_strerror(errno));
    modbus_set_indication_timeout(mb(s->m_ctx), 1, 0); // a request that stops half-way is dropped after 1 s
    s->m_listenFd = modbus_tcp_listen(mb(s->m_ctx), kMaxClients);
    if (s->m_listenFd < 0)
        return makeError(ErrorCode::Device,
                         "cannot listen on 127.0.0.1:" + std::to_string(options.port) + ": " + modbus_strerror(errno));
    sockaddr_in addr{};
    socklen_t len = sizeof addr;
    getsockname(s->m_listenFd, reinterpret_cast<sockaddr*>(&addr), &len);
    s->m_port = ntohs(addr.sin_port);
    s->m_mapping = modbus_mapping_new(0, 0, kRegisterSpace, 0);
    if (!s->m_mapping)
        return makeError(ErrorCode::Internal, "cannot allocate the register buffer");
    return s;
}

SimDriveServer::~SimDriveServer()
{
    if (m_listenFd >= 0)
        close(m_listenFd);
    if (m_mapping)
        modbus_mapping_free(mapping(m_mapping));
    if (m_ctx)
        modbus_free(mb(m_ctx));
}

void SimDriveServer::log(const std::string& line) const
{
    if (m_opt.log)
        m_opt.log(line);
}

Status SimDriveServer::loadState()
{
    if (m_opt.stateFile.empty())
        return Status::success();
    std::ifstream f(m_opt.stateFile);
    if (!f)
        return Status::success(); // first run: the preset's values
    try {
        const auto j = nlohmann::json::parse(f);
        for (const auto& [axis, values] : j.items()) {
            model::ParameterValues v;
            for (const auto& [k, x] : values.items())
                v[k] = x.get<double>();
            if (auto st = m_drive->writeParameters(axis, v); !st)
                return makeError(st.error().code, "state file " + m_opt.stateFile + ": " + st.error().detail);
        }
    } catch (const nlohmann::json::exception& e) {
        return makeError(ErrorCode::BadInput, "state file " + m_opt.stateFile + ": " + e.what());
    }
    log("parameters restored from " + m_opt.stateFile);
    return Status::success();
}

void SimDriveServer::saveState() const
{
    if (m_opt.stateFile.empty())
        return;
    nlohmann::json j;
    for (const auto& a : m_axes) {
        auto v = m_drive->readParameters(a.name, {});
        if (!v)
            continue;
        for (const auto& [k, x] : *v) {
            const auto* meta = model::findParameter(a.sim->parameterMetas(), k);
            if (meta && meta->writable)
                j[a.name][k] = x;
        }
    }
    const std::string tmp = m_opt.stateFile + ".tmp";
    {
        std::ofstream f(tmp);
        f << j.dump(1) << '\n';
    }
    std::rename(tmp.c_str(), m_opt.stateFile.c_str()); // atomic: a kill never leaves half a file
}

void SimDriveServer::reply(const std::uint8_t* query, int length)
{
    modbus_t* ctx = mb(m_ctx);
    const int hl = modbus_get_header_length(ctx);
    const std::uint8_t* q = query + hl; // function code
    const int unit = query[hl - 1];
    int ex = 0;
    const int fc = q[0];
    if (fc == 0x03) {
        const int addr = be16(q + 1), count = be16(q + 3);
        ex = count < 1 || count > 125 ? MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE
                                      : readRegisters(unit, addr, count, mapping(m_mapping)->tab_registers + addr);
    } else if (fc == 0x06) {
        const std::uint16_t v = static_cast<std::uint16_t>(be16(q + 3));
        ex = writeRegisters(unit, be16(q + 1), &v, 1);
    } else if (fc == 0x10 || fc == 0x17) {
        const int waddr = be16(q + (fc == 0x10 ? 1 : 5)), wcount = be16(q + (fc == 0x10 ? 3 : 7));
        const std::uint8_t* bytes = q + (fc == 0x10 ? 6 : 10);
        // The byte count (what libmodbus read) must be the word count × 2: a request that claims more
        // words than it carries is refused, never executed with whatever lies beyond it (issue 21).
        const int byteCount = q[fc == 0x10 ? 5 : 9];
        if (byteCount != 2 * wcount || length < hl + (fc == 0x10 ? 6 : 10) + byteCount) {
            log("refused function " + std::to_string(fc) + ": byte count " + std::to_string(byteCount) + " for " +
                std::to_string(wcount) + " registers");
            modbus_reply_exception(ctx, query, MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE);
            return;
        }
        std::vector<std::uint16_t> v(static_cast<std::size_t>(std::max(0, wcount)));
        for (int k = 0; k < wcount; ++k)
            v[static_cast<std::size_t>(k)] = static_cast<std::uint16_t>(be16(bytes + 2 * k));
        ex = wcount < 1 || wcount > 123 ? MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE
                                        : writeRegisters(unit, waddr, v.data(), wcount);
        if (!ex && fc == 0x17) {
            const int raddr = be16(q + 1), rcount = be16(q + 3);
            ex = rcount < 1 || rcount > 125
                     ? MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE
                     : readRegisters(unit, raddr, rcount, mapping(m_mapping)->tab_registers + raddr);
        }
    } else {
        ex = MODBUS_EXCEPTION_ILLEGAL_FUNCTION;
    }
    if (ex)
        modbus_reply_exception(ctx, query, static_cast<unsigned>(ex));
    else
        modbus_reply(ctx, query, length, mapping(m_mapping));
}

Status SimDriveServer::serve()
{
    struct Conn {
        int fd;
        int id;
        std::string peer;
        int requests = 0;
    };
    std::vector<Conn> conns;
    int nextId = 1;
    std::vector<std::uint8_t> query(MODBUS_TCP_MAX_ADU_LENGTH);
    modbus_t* ctx = mb(m_ctx);
    auto drop = [&](std::size_t i, const std::string& why) {
        log("connection " + std::to_string(conns[i].id) + " from " + conns[i].peer + " closed (" + why + ", " +
            std::to_string(conns[i].requests) + " requests)");
        close(conns[i].fd);
        conns.erase(conns.begin() + static_cast<std::ptrdiff_t>(i));
    };
    while (!m_stop.load()) {
        fd_set rd;
        FD_ZERO(&rd);
        FD_SET(m_listenFd, &rd);
        int maxFd = m_listenFd;
        for (const auto& c : conns) {
            FD_SET(c.fd, &rd);
            maxFd = std::max(maxFd, c.fd);
        }
        timeval tv{0, m_state == "running" ? 1000 : 20000};
        const int n = select(maxFd + 1, &rd, nullptr, nullptr, &tv);
        if (n < 0 && errno != EINTR)
            return makeError(ErrorCode::Device, std::string("select failed: ") + std::strerror(errno));
        if (n > 0 && FD_ISSET(m_listenFd, &rd)) {
            sockaddr_in peer{};
            socklen_t len = sizeof peer;
            const int fd = accept(m_listenFd, reinterpret_cast<sockaddr*>(&peer), &len);
            if (fd >= 0 && conns.size() >= kMaxClients) {
                close(fd);
                log("connection refused: already " + std::to_string(kMaxClients) + " clients");
            } else if (fd >= 0) {
                char ip[INET_ADDRSTRLEN] = "?";
                inet_ntop(AF_INET, &peer.sin_addr, ip, sizeof ip);
                conns.push_back({fd, nextId++, std::string(ip) + ":" + std::to_string(ntohs(peer.sin_port))});
                log("connection " + std::to_string(conns.back().id) + " from " + conns.back().peer);
            }
        }
        for (std::size_t i = 0; n > 0 && i < conns.size();) {
            if (!FD_ISSET(conns[i].fd, &rd)) {
                ++i;
                continue;
            }
            modbus_set_socket(ctx, conns[i].fd);
            const int rc = modbus_receive(ctx, query.data());
            if (rc < 0) {
                drop(i, errno == ECONNRESET || errno == 0 ? "by the client" : modbus_strerror(errno));
                continue;
            }
            if (rc == 0) {
                ++i;
                continue;
            }
            ++conns[i].requests;
            if (m_opt.faults.dropAfterRequests > 0 && conns[i].requests >= m_opt.faults.dropAfterRequests) {
                log("fault drop-after:" + std::to_string(m_opt.faults.dropAfterRequests) + ": dropping connection " +
                    std::to_string(conns[i].id));
                drop(i, "fault injected");
                continue;
            }
            if (m_opt.faults.delayMs > 0) {
                log("fault delay:" + std::to_string(m_opt.faults.delayMs) + ": answering late");
                std::this_thread::sleep_for(std::chrono::milliseconds(m_opt.faults.delayMs));
            }
            reply(query.data(), rc);
            ++i;
        }
        step();
    }
    while (!conns.empty())
        drop(0, "server shutting down");
    if (m_state == "running") {
        (void)m_drive->abortTest();
        log("shutdown during a test: test stopped, parameters restored");
    }
    return Status::success();
}

} // namespace axistune::device

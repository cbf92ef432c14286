// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-simdrive: the drive built from a preset and a register map, its state file, and one
// request frame answered (decoded and checked by ModbusTcpFrame, run through the register engine).
// The sockets are in SimDriveServerConnections.cpp (docs/modbus.md).
#include "core/device/SimDriveServer.h"

#include "core/device/ModbusTcpFrame.h"
#include "core/io/AtomicFile.h"
#include "core/model/InputLimits.h"
#include "core/sim/MachineDefinition.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <unistd.h>

namespace axistune::device {
namespace {

constexpr int kRegisterSpace = 65536;

} // namespace

Result<std::unique_ptr<SimDriveServer>> SimDriveServer::create(const SimDriveServerOptions& options)
{
    std::unique_ptr<SimDriveServer> s(new SimDriveServer());
    s->m_opt = options;
    auto def = options.machineFile.empty() ? sim::loadPreset(options.preset)
                                           : sim::loadMachineDefinitionFile(options.machineFile);
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
    s->m_refusedConfig.resize(s->m_axes.size());
    s->m_scopeConfig.resize(s->m_axes.size());
    auto map = loadRegisterMap(options.mapFamily);
    if (!map)
        return map.error();
    s->m_map = std::move(map).value();
    // Before anything is written the fields hold what an unset request holds (a 0.1 s record, 45° data start, ...):
    // the quantities of every kind at their defaults, test.type that of the default request (a step). A kind the
    // map cannot express (no test_type code, no circle block) leaves its fields unset.
    // The step, the default request, first: its values must exist (the map is refused otherwise).
    TestValues config;
    for (int t = 0; t < static_cast<int>(std::variant_size_v<TestKind>); ++t) {
        TestRequest kind;
        kind.test = testKindOf(static_cast<TestType>(t));
        auto values = testValuesOf(kind, s->m_map, [](const std::string&) -> Result<int> { return 0; });
        if (!values && t == 0)
            return values.error();
        if (values)
            config.insert(values->begin(), values->end()); // keeps what is there: test.type stays the step's
    }
    s->m_config.assign(s->m_axes.size(), config);
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
    if (auto st = s->listen(options.port); !st)
        return st.error();
    return s;
}

SimDriveServer::~SimDriveServer()
{
    if (m_listenFd >= 0)
        close(m_listenFd);
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
    // Through the input limits like every other reader (docs/robustness.md): a regular file (no FIFO,
    // device or directory), bounded size, depth and numbers. A missing file is the first run.
    auto parsed = model::readJsonFile(m_opt.stateFile);
    if (!parsed) {
        if (parsed.error().code == ErrorCode::NotFound)
            return Status::success(); // first run: the preset's values
        return makeError(parsed.error().code, "state file " + parsed.error().detail);
    }
    const std::string src = "state file " + model::displayPath(m_opt.stateFile);
    const nlohmann::json& j = *parsed;
    if (!j.is_object())
        return makeError(ErrorCode::BadInput, src + ": expected an object {axis: {parameter: value}}");
    for (const auto& [axis, values] : j.items()) {
        if (!values.is_object())
            return makeError(ErrorCode::BadInput, src + ", axis '" + axis + "': expected an object {parameter: value}");
        model::ParameterValues v;
        for (const auto& [k, x] : values.items()) {
            if (!x.is_number())
                return makeError(ErrorCode::BadInput, src + ", axis '" + axis + "', key '" + k + "': not a number");
            v[k] = x.get<double>();
        }
        if (auto st = m_drive->writeParameters(axis, v); !st)
            return makeError(st.error().code, src + ": " + st.error().detail);
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
    // Atomic (temporary file, fsync, rename): a kill or a full disk never leaves half a state file.
    if (auto st = io::writeFileAtomic(m_opt.stateFile, j.dump(1) + "\n"); !st)
        log("state not saved: " + st.error().detail);
}

std::vector<std::uint8_t> SimDriveServer::answer(std::span<const std::uint8_t> frame, const std::string& peer)
{
    const ModbusRequest req = decodeModbusRequest(frame);
    const int ui = req.unit - m_map.unitIdBase;
    const bool axis = ui >= 0 && ui < static_cast<int>(m_axes.size());
    std::vector<std::uint16_t> regs(static_cast<std::size_t>(std::max(0, req.readCount)));
    int ex = 0;
    if (req.exception) {
        // Malformed PDU in a well-framed request: nothing is executed. A write that meant the test
        // block still marks it refused, so a test never starts on what was there before.
        ex = refuse(req.exception, peer + ": " + req.why + "; nothing changed");
        if (axis && (req.function == 0x10 || req.function == 0x17) && req.writeCount > 0)
            markRefusedConfig(ui, req.writeAddress, std::min(req.writeCount, 65536 - req.writeAddress), req.why);
    } else if (req.function == 0x03) {
        ex = readRegisters(req.unit, req.readAddress, req.readCount, regs.data());
    } else {
        // Function 23: the read is checked (a dry read) before the write, so a read that would be
        // refused does not leave a write done behind an exception.
        if (req.function == 0x17)
            ex = readRegisters(req.unit, req.readAddress, req.readCount, regs.data());
        if (!ex)
            ex = writeRegisters(req.unit, req.writeAddress, req.values.data(), req.writeCount);
        if (!ex && req.function == 0x17)
            ex = readRegisters(req.unit, req.readAddress, req.readCount, regs.data());
    }
    return encodeModbusReply(req, ex, regs);
}

} // namespace axistune::device

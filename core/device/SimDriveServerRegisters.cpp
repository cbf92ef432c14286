// SPDX-License-Identifier: GPL-3.0-or-later
// The register engine of axistune-simdrive: field values encoded on read, writes validated as a
// whole before anything changes, commands deduplicated by their sequence token (docs/modbus.md).
#include "core/device/SimDriveServer.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <modbus/modbus.h>

namespace axistune::device {

int SimDriveServer::refuse(int exception, const std::string& message)
{
    m_message = message;
    log("refused (exception " + std::to_string(exception) + "): " + message);
    return exception;
}

bool SimDriveServer::encodeIdentity(const RegisterField& f, int ui, std::uint16_t* buf)
{
    const std::string& n = f.name;
    const Axis& ax = m_axes[static_cast<std::size_t>(ui)];
    auto u16 = [&](int v) {
        buf[0] = static_cast<std::uint16_t>(v);
        return true;
    };
    auto text = [&](const std::string& s) {
        encodeString(s, f.count, buf);
        return true;
    };
    if (n == "identity.magic")
        return u16(m_map.magic);
    if (n == "identity.map_version")
        return u16(m_map.version);
    if (n == "identity.axis_count")
        return u16(static_cast<int>(m_axes.size()));
    if (n == "identity.axis_index")
        return u16(ui);
    if (n == "identity.axis_kind")
        return u16(m_map.code("axis_kind", ax.kind));
    if (n == "identity.parameter_count") {
        int k = 0;
        for (const auto& p : m_map.parameters)
            k += p.availableOn(ax.kind) ? 1 : 0;
        return u16(k);
    }
    if (n == "identity.vendor")
        return text("AxisTune");
    if (n == "identity.model")
        return text("simulated drive");
    if (n == "identity.firmware")
        return text(AXISTUNE_VERSION);
    if (n == "identity.machine")
        return text(m_machine);
    if (n == "identity.axis_name")
        return text(ax.name);
    return false;
}

bool SimDriveServer::encodeDescription(const RegisterField& f, int ui, std::uint16_t* buf)
{
    const std::string& n = f.name;
    const WordOrder o = m_map.wordOrder;
    const Axis& ax = m_axes[static_cast<std::size_t>(ui)];
    if (n.rfind("describe.", 0) == 0) {
        auto caps = m_drive->capabilities(ax.name);
        if (!caps)
            return false;
        int tests = 0, methods = 0;
        for (const auto t : caps->testTypes)
            tests |= 1 << std::max(0, m_map.code("test_type", testTypeName(t)));
        for (const auto m : caps->frfMethods)
            methods |= 1 << std::max(0, m_map.code("frf_method", frfMethodName(m)));
        const int flags = (caps->evaluatesFrf ? m_map.code("describe_flag", "evaluates_frf") : 0) |
                          (caps->writesParameters ? m_map.code("describe_flag", "writes_parameters") : 0) |
                          (caps->scope && m_map.fields.count("scope.window") ? std::max(0, m_map.code("describe_flag", "scope")) : 0);
        if (n == "describe.test_types")
            buf[0] = static_cast<std::uint16_t>(tests);
        else if (n == "describe.frf_methods")
            buf[0] = static_cast<std::uint16_t>(methods);
        else if (n == "describe.flags")
            buf[0] = static_cast<std::uint16_t>(flags);
        else if (n == "describe.trace_rate_hz")
            encodeF64(caps->traceRateHz, o, buf);
        else if (n == "describe.current_trace_rate_hz")
            encodeF64(caps->currentTraceRateHz, o, buf);
        else
            buf[0] = 0;
        return true;
    }
    if (n.rfind("limits.", 0) == 0) {
        const DriveLimits l = axisLimits(ui);
        const std::pair<const char*, double> f64s[] = {
            {"limits.frf_amplitude_max_pct", l.frfAmplitudeMaxPct},
            {"limits.current_step_max_a", l.currentStepMaxA},
            {"limits.current_step_max_s", l.currentStepMaxS},
            {"limits.current_step_max_speed_rad_s", l.currentStepMaxSpeedRadS},
            {"limits.motor_speed_max_rad_s", l.motorSpeedMaxRadS},
            {"limits.test_duration_max_s", l.testDurationMaxS},
            {"limits.travel_window", l.travelWindow}};
        for (const auto& [key, v] : f64s) {
            if (n == key) {
                encodeF64(v, o, buf);
                return true;
            }
        }
        return false;
    }
    if (n.rfind("plan.", 0) == 0) {
        const bool mine = m_planUnit == ui;
        if (n == "plan.token")
            buf[0] = mine ? m_planToken : 0;
        else if (n == "plan.record_samples")
            encodeU32(mine ? static_cast<std::uint32_t>(m_plan.recordSamples) : 0u, o, buf);
        else if (n == "plan.motion_s")
            encodeF64(mine ? m_plan.motionTimeS : 0.0, o, buf);
        else if (n == "plan.trace_rate_hz")
            encodeF64(mine ? m_plan.traceRateHz : 0.0, o, buf);
        else
            buf[0] = 0;
        return true;
    }
    return false;
}

void SimDriveServer::encodeWindow(const RegisterField& f, std::uint16_t* buf)
{
    const WordOrder o = m_map.wordOrder;
    std::memset(buf, 0, sizeof(std::uint16_t) * static_cast<std::size_t>(f.count));
    const int namesSel = m_map.code("trace_channel", "names"), metaSel = m_map.code("trace_channel", "metadata");
    const int frfSel = m_map.code("trace_channel", "frf_data"),
              frfMetaSel = m_map.code("trace_channel", "frf_metadata");
    if (m_selChannel == namesSel || m_selChannel == metaSel || m_selChannel == frfMetaSel) {
        const std::string& s = m_selChannel == namesSel  ? m_traceNames
                               : m_selChannel == metaSel ? m_traceMeta
                                                         : m_frfMeta;
        encodeString(m_selOffset < s.size() ? s.substr(m_selOffset) : std::string(), f.count, buf);
    } else if (m_selChannel == frfSel) {
        for (int k = 0; k + 4 <= f.count; k += 4) {
            const std::size_t i = m_selOffset + static_cast<std::size_t>(k / 4);
            encodeF64(i < m_frfBlob.size() ? m_frfBlob[i] : std::numeric_limits<double>::quiet_NaN(), o, buf + k);
        }
    } else if (m_trace && m_selChannel < m_trace->channels.size()) {
        const auto& d = m_trace->channels[m_selChannel].data;
        for (int k = 0; k + 4 <= f.count; k += 4) {
            const std::size_t i = m_selOffset + static_cast<std::size_t>(k / 4);
            encodeF64(i < d.size() ? d[i] : std::numeric_limits<double>::quiet_NaN(), o, buf + k);
        }
    }
}

void SimDriveServer::encodeField(const RegisterField& f, int ui, std::uint16_t* buf)
{
    const WordOrder o = m_map.wordOrder;
    const std::string& n = f.name;
    const Axis& ax = m_axes[static_cast<std::size_t>(ui)];
    auto u16 = [&](int v) { buf[0] = static_cast<std::uint16_t>(v); };
    auto text = [&](const std::string& s) { encodeString(s, f.count, buf); };
    if (n.rfind("identity.", 0) == 0 && encodeIdentity(f, ui, buf))
        return;
    if (encodeDescription(f, ui, buf))
        return;
    if (n == "status.state")
        return u16(m_map.code("state", m_state));
    if (n == "status.fault_code")
        return u16(m_map.code("fault", m_fault));
    if (n == "status.position")
        return encodeF32(static_cast<float>(ax.sim->tablePosition()), o, buf);
    if (n == "status.velocity")
        return encodeF32(static_cast<float>(ax.sim->motorVelocity()), o, buf);
    if (n == "status.torque")
        return encodeF32(static_cast<float>(ax.sim->torque()), o, buf);
    if (n == "status.progress")
        return u16(static_cast<int>(std::lround(m_progress * 10000.0)));
    if (n == "status.heartbeat_echo")
        return u16(m_heartbeat);
    if (n == "status.command_token_echo" || n == "command.token")
        return u16(m_lastToken);
    if (n == "command.code")
        return u16(m_lastCode);
    if (n == "status.command_result")
        return u16(m_lastResult);
    if (n == "status.trace_samples")
        return encodeU32(m_trace ? static_cast<std::uint32_t>(m_trace->size()) : 0u, o, buf);
    if (n == "status.trace_channels")
        return u16(m_trace ? static_cast<int>(m_trace->channels.size()) : 0);
    if (n == "status.trace_rate_hz") {
        // 0 when there is no trace (or its rate is unreadable): the client then refuses the trace.
        const auto fs = m_trace ? m_trace->metadata.number(model::meta::kFsHz) : Result<double>(0.0);
        return encodeF64(fs ? *fs : 0.0, o, buf);
    }
    if (n == "status.message")
        return text(m_message);
    if (!f.carries.empty()) { // a test quantity: as written (TestRegisterCodec.h)
        const auto& values = m_config[static_cast<std::size_t>(ui)];
        const auto it = values.find(f.carries);
        return encodeCarried(f, it == values.end() ? 0.0 : it->second, o, buf);
    }
    if (n == "heartbeat.counter")
        return u16(m_heartbeat);
    if (n == "trace.select_offset")
        return encodeU32(m_selOffset, o, buf);
    if (n == "trace.select_channel")
        return u16(m_selChannel);
    if (n == "trace.window")
        return encodeWindow(f, buf);
    if (n.rfind("scope.", 0) == 0 && encodeScopeField(f, ui, buf))
        return;
    std::memset(buf, 0, sizeof(std::uint16_t) * static_cast<std::size_t>(f.count)); // a field this server does not use
}

int SimDriveServer::readRegisters(int unitId, int address, int count, std::uint16_t* out)
{
    const int ui = unitId - m_map.unitIdBase;
    if (ui < 0 || ui >= static_cast<int>(m_axes.size()))
        return refuse(MODBUS_EXCEPTION_GATEWAY_TARGET, "no axis on unit id " + std::to_string(unitId));
    if (address < 0 || address + count > static_cast<int>(m_owner.size()))
        return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS, "registers beyond 65535");
    std::vector<std::uint16_t> buf(128);
    for (int a = address; a < address + count;) {
        const int si = m_owner[static_cast<std::size_t>(a)];
        if (si < 0)
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS, "register " + std::to_string(a) + " is not mapped");
        const Slot& s = m_slots[static_cast<std::size_t>(si)];
        if (s.parameter) {
            if (m_opt.faults.illegalAddress) {
                log("fault illegal-address: parameter register " + std::to_string(a));
                return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS,
                              "parameter registers unavailable (fault injected)");
            }
            if (!s.parameter->availableOn(m_axes[static_cast<std::size_t>(ui)].kind))
                return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS, "parameter " + s.parameter->meta.key +
                                                                         " does not exist on axis " +
                                                                         m_axes[static_cast<std::size_t>(ui)].name);
            encodeF32(static_cast<float>(m_axes[static_cast<std::size_t>(ui)].sim->parameter(s.parameter->meta.key)),
                      m_map.wordOrder, buf.data());
        } else {
            encodeField(*s.field, ui, buf.data());
        }
        const int end = std::min(address + count, s.address + s.count);
        for (; a < end; ++a)
            out[a - address] = buf[static_cast<std::size_t>(a - s.address)];
    }
    return 0;
}

int SimDriveServer::writeField(const RegisterField& f, int ui, const std::uint16_t* w)
{
    const std::string& n = f.name;
    const WordOrder o = m_map.wordOrder;
    if (n == "heartbeat.counter") {
        m_heartbeat = w[0];
        m_lastHeartbeat = Clock::now();
        return 0;
    }
    if (n == "trace.select_offset") {
        m_selOffset = decodeU32(w, o);
        return 0;
    }
    if (n == "trace.select_channel") {
        m_selChannel = w[0];
        return 0;
    }
    if (n.rfind("scope.", 0) == 0)
        return writeScopeField(f, ui, w);
    if (f.carries.empty())
        return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS, "field " + n + " is read-only");
    if (m_state == "running")
        return refuse(MODBUS_EXCEPTION_SLAVE_OR_SERVER_BUSY, "test configuration cannot change while a test runs");
    if (f.carries == "reserved")
        return 0;
    const double v = decodeCarried(f, w, o);
    if (auto st = checkTestValue(f, m_map, v); !st)
        return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, st.error().detail);
    if (f.carries == "test.trace_divider" && v > 1000) // this drive's own limit
        return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE,
                      "trace divider " + model::formatNumber(v, 6) + " outside 0..1000");
    m_config[static_cast<std::size_t>(ui)][f.carries] = v;
    return 0;
}

void SimDriveServer::markRefusedConfig(int ui, int address, int count, const std::string& why)
{
    auto& refused = m_refusedConfig[static_cast<std::size_t>(ui)];
    for (int a = std::max(0, address); a < address + count && a < static_cast<int>(m_owner.size()); ++a) {
        const int si = m_owner[static_cast<std::size_t>(a)];
        if (si < 0 || !m_slots[static_cast<std::size_t>(si)].field)
            continue;
        const std::string& n = m_slots[static_cast<std::size_t>(si)].field->name;
        if (!m_slots[static_cast<std::size_t>(si)].field->carries.empty())
            refused[n] = why;
    }
}

int SimDriveServer::writeRegisters(int unitId, int address, const std::uint16_t* values, int count)
{
    const int ui = unitId - m_map.unitIdBase;
    if (ui < 0 || ui >= static_cast<int>(m_axes.size()))
        return refuse(MODBUS_EXCEPTION_GATEWAY_TARGET, "no axis on unit id " + std::to_string(unitId));
    if (address < 0 || count < 1 || address + count > static_cast<int>(m_owner.size()))
        return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS, "registers beyond 65535");
    // A write is all or nothing: what a refused write may have touched is put back.
    const TestValues config = m_config[static_cast<std::size_t>(ui)];
    const auto heartbeat = m_heartbeat;
    const auto lastHeartbeat = m_lastHeartbeat;
    const auto selOffset = m_selOffset;
    const auto selChannel = m_selChannel;
    const auto scopeConfig = m_scopeConfig[static_cast<std::size_t>(ui)];
    const auto scopeSource = m_scopeSource;
    const auto scopeFrom = m_scopeFrom;
    bool commandRan = false;
    const int ex = writeRegistersChecked(ui, address, values, count, commandRan);
    if (ex && !commandRan) {
        m_config[static_cast<std::size_t>(ui)] = config;
        m_heartbeat = heartbeat;
        m_lastHeartbeat = lastHeartbeat;
        m_selOffset = selOffset;
        m_selChannel = selChannel;
        m_scopeConfig[static_cast<std::size_t>(ui)] = scopeConfig;
        m_scopeSource = scopeSource;
        m_scopeFrom = scopeFrom;
        markRefusedConfig(ui, address, count, m_message);
    } else if (!ex || commandRan) {
        // Fields written successfully are no longer refused.
        auto& refused = m_refusedConfig[static_cast<std::size_t>(ui)];
        for (int a = address; a < address + count && !refused.empty(); ++a) {
            const int si = m_owner[static_cast<std::size_t>(a)];
            if (si >= 0 && m_slots[static_cast<std::size_t>(si)].field)
                refused.erase(m_slots[static_cast<std::size_t>(si)].field->name);
        }
    }
    return ex;
}

int SimDriveServer::writeRegistersChecked(int ui, int address, const std::uint16_t* values, int count, bool& commandRan)
{
    const Axis& ax = m_axes[static_cast<std::size_t>(ui)];
    // First pass: every touched field must be written whole and be valid; nothing changes on an error.
    std::vector<const Slot*> slots;
    model::ParameterValues params;
    const RegisterField* command = nullptr;
    for (int a = address; a < address + count;) {
        const int si = m_owner[static_cast<std::size_t>(a)];
        if (si < 0)
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS, "register " + std::to_string(a) + " is not mapped");
        const Slot& s = m_slots[static_cast<std::size_t>(si)];
        const std::string what = s.parameter ? "parameter " + s.parameter->meta.key : "field " + s.field->name;
        if (s.address < address || s.address + s.count > address + count)
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS, "a write must cover the whole " + what);
        const std::uint16_t* w = values + (s.address - address);
        if (s.parameter) {
            const auto& meta = s.parameter->meta;
            if (m_opt.faults.illegalAddress) {
                log("fault illegal-address: parameter register " + std::to_string(a));
                return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS,
                              "parameter registers unavailable (fault injected)");
            }
            if (!s.parameter->availableOn(ax.kind))
                return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS, what + " does not exist on axis " + ax.name);
            if (!meta.writable)
                return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS, what + " is read-only");
            if (m_state == "running" && !meta.writableDuringTest)
                return refuse(MODBUS_EXCEPTION_SLAVE_OR_SERVER_BUSY, what + " cannot be written while a test runs");
            const double v = decodeF32(w, m_map.wordOrder);
            if (auto st = model::checkParameterValue(meta, v); !st)
                return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, "axis " + ax.name + ": " + st.error().detail);
            params[meta.key] = v;
        } else if (s.field->name == "command.code" || s.field->name == "command.token") {
            if (s.field->name == "command.code") {
                if (address + count < s.address + 2)
                    return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS,
                                  "command.code and command.token are written together");
                command = s.field;
            } else if (!command) {
                return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS,
                              "command.code and command.token are written together");
            }
        } else {
            slots.push_back(&s);
        }
        a = s.address + s.count;
    }
    for (const Slot* s : slots) {
        if (int ex = writeField(*s->field, ui, values + (s->address - address)); ex)
            return ex;
    }
    if (!params.empty()) {
        if (auto st = m_drive->writeParameters(ax.name, params); !st)
            return refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, st.error().detail);
        saveState();
    }
    if (command) {
        const std::uint16_t* w = values + (command->address - address);
        commandRan = true;
        return runCommand(ui, w[0], w[1]);
    }
    return 0;
}

int SimDriveServer::runCommand(int ui, std::uint16_t code, std::uint16_t token)
{
    if (m_haveToken && token == m_lastToken && code == m_lastCode)
        return m_lastResult; // a retried command: answered again, not executed twice
    const std::string name = m_map.name("command", code);
    int result = 0;
    if (name == "start_test") {
        result = startTest(ui);
    } else if (name == "abort_test") {
        if (m_state == "running") {
            (void)m_drive->abortTest();
            m_state = "aborted";
            m_fault = "aborted";
            m_message = "aborted by the client";
            log("test aborted by the client; parameters restored");
        }
    } else if (name == "arm_scope") {
        result = armScope(ui);
    } else if (name == "stop_scope") {
        (void)m_drive->stopScope();
        m_scopeCapture.reset();
    } else if (name == "plan_test") {
        result = planTest(ui, token);
    } else if (name == "clear") {
        if (m_state != "running") {
            m_state = "idle";
            m_fault = "none";
            m_message.clear();
        }
    } else {
        result = refuse(MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE, "unknown command " + std::to_string(code));
    }
    m_haveToken = true;
    m_lastCode = code;
    m_lastToken = token;
    m_lastResult = result;
    return result;
}

} // namespace axistune::device

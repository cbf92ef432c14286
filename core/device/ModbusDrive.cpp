// SPDX-License-Identifier: GPL-3.0-or-later
// Modbus TCP client of the Drive seam; protocol and register map in docs/modbus.md.
#include "core/device/ModbusDrive.h"

#include "core/device/TestRegisterCodec.h"
#include "core/model/Number.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <modbus/modbus.h>
#include <sstream>
#include <thread>

namespace axistune::device {
namespace {

modbus_t* mb(void* p)
{
    return static_cast<modbus_t*>(p);
}

bool isException(int e)
{
    return e >= EMBXILFUN && e <= EMBXGTAR;
}

} // namespace

std::string modbusExceptionText(int code)
{
    switch (code) {
    case 1:
        return "exception 1 ILLEGAL FUNCTION: the drive does not support this request";
    case 2:
        return "exception 2 ILLEGAL DATA ADDRESS: register not available on this drive or axis (check the register "
               "map)";
    case 3:
        return "exception 3 ILLEGAL DATA VALUE: value refused by the drive (out of range or malformed)";
    case 4:
        return "exception 4 SERVER DEVICE FAILURE: the drive failed while executing the request";
    case 5:
        return "exception 5 ACKNOWLEDGE: accepted, still executing";
    case 6:
        return "exception 6 SERVER DEVICE BUSY: the drive is busy (a test is running)";
    case 7:
        return "exception 7 NEGATIVE ACKNOWLEDGE: the drive cannot execute the request";
    case 8:
        return "exception 8 MEMORY PARITY ERROR in the drive";
    case 10:
        return "exception 10 GATEWAY PATH UNAVAILABLE";
    case 11:
        return "exception 11 GATEWAY TARGET DEVICE FAILED TO RESPOND: no axis on this unit id";
    default:
        return "exception " + std::to_string(code) + " (not defined by Modbus)";
    }
}

Result<ModbusUri> parseModbusUri(const std::string& uri)
{
    const std::string prefix = "modbus://";
    auto bad = [&](const std::string& why) {
        return makeError(ErrorCode::BadInput, "connection '" + uri + "': " + why +
                                                  " (expected modbus://HOST:PORT[?timeout_ms=N&map=FAMILY])");
    };
    if (uri.rfind(prefix, 0) != 0)
        return bad("not a modbus:// URI");
    ModbusUri u;
    u.text = uri;
    std::string rest = uri.substr(prefix.size()), query;
    if (auto q = rest.find('?'); q != std::string::npos) {
        query = rest.substr(q + 1);
        rest = rest.substr(0, q);
    }
    const auto colon = rest.rfind(':');
    if (colon == std::string::npos || colon == 0)
        return bad("host and port are required");
    u.host = rest.substr(0, colon);
    const auto port = model::parseInteger(rest.substr(colon + 1));
    if (!port || *port < 1 || *port > 65535)
        return bad("port must be a number in 1..65535");
    u.port = static_cast<int>(*port);
    std::stringstream qs(query);
    for (std::string kv; std::getline(qs, kv, '&');) {
        const auto eq = kv.find('=');
        const std::string k = kv.substr(0, eq), v = eq == std::string::npos ? "" : kv.substr(eq + 1);
        if (k == "timeout_ms") {
            const auto ms = model::parseInteger(v);
            if (!ms || *ms < 10 || *ms > 60000)
                return bad("timeout_ms must lie in 10..60000");
            u.timeoutMs = static_cast<int>(*ms);
        } else if (k == "map" && !v.empty()) {
            u.family = v;
        } else {
            return bad("unknown option '" + kv + "'");
        }
    }
    return u;
}

Result<std::unique_ptr<ModbusDrive>> ModbusDrive::open(const ModbusUri& uri, RegisterMap map)
{
    std::unique_ptr<ModbusDrive> d(new ModbusDrive());
    d->m_uri = uri;
    d->m_map = std::move(map);
    d->m_ctx = modbus_new_tcp(uri.host.c_str(), uri.port);
    if (!d->m_ctx)
        return makeError(ErrorCode::BadInput, uri.text + ": " + modbus_strerror(errno));
    const auto sec = static_cast<std::uint32_t>(uri.timeoutMs / 1000),
               usec = static_cast<std::uint32_t>(uri.timeoutMs % 1000) * 1000;
    modbus_set_response_timeout(mb(d->m_ctx), sec, usec);
    modbus_set_byte_timeout(mb(d->m_ctx), sec, usec);
    if (auto st = d->connectOnce(); !st)
        return st.error();
    if (auto st = d->loadAxes(); !st)
        return st.error();
    // Continue the drive's command tokens: a new client starting again at 1 would repeat the token of
    // an earlier client's last command, and the drive would answer it without executing it.
    std::uint16_t echo = 0;
    if (auto st = d->readRegs(d->m_map.unitIdBase, d->m_map.field("status.command_token_echo").address, 1, &echo,
                              "reading the last command token");
        !st)
        return st.error();
    d->m_token = echo;
    return d;
}

ModbusDrive::~ModbusDrive()
{
    if (m_testRunning && m_connected)
        (void)abortTest(); // a drive left running would only stop by its watchdog
    disconnect();
    if (m_ctx)
        modbus_free(mb(m_ctx));
}

Status ModbusDrive::connectOnce()
{
    if (m_connected)
        return Status::success();
    if (modbus_connect(mb(m_ctx)) != 0)
        return makeError(ErrorCode::Device, m_uri.text + ": cannot connect: " + modbus_strerror(errno));
    m_connected = true;
    return Status::success();
}

void ModbusDrive::disconnect()
{
    if (m_connected)
        modbus_close(mb(m_ctx));
    m_connected = false;
}

Status ModbusDrive::transact(int unit, const std::string& what, Retry retry, const std::function<int(_modbus*)>& op)
{
    std::string lastError;
    const int attempts = retry == Retry::Idempotent ? kMaxAttempts : 1;
    for (int attempt = 0; attempt < attempts; ++attempt) {
        if (attempt > 0) {
            if (++m_reconnects > kMaxReconnects) {
                lastError += "; giving up after " + std::to_string(kMaxReconnects) + " reconnects in this session";
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(50 * attempt)); // bounded: at most 150 ms in all
        }
        if (!m_connected) {
            if (modbus_connect(mb(m_ctx)) != 0) {
                lastError += std::string(lastError.empty() ? "" : "; ") + "reconnect failed: " + modbus_strerror(errno);
                continue;
            }
            m_connected = true;
        }
        modbus_set_slave(mb(m_ctx), unit);
        ++m_requests;
        if (op(mb(m_ctx)) >= 0)
            return Status::success();
        const int e = errno;
        if (isException(e))
            return exceptionError(unit, e - MODBUS_ENOBASE, what);
        // Transport or framing failure: the link is in an unknown state, so start a fresh connection.
        const std::string why = e == ETIMEDOUT ? "no answer within " + std::to_string(m_uri.timeoutMs) + " ms"
                                               : std::string("connection lost (") + modbus_strerror(e) + ")";
        lastError += std::string(lastError.empty() ? "" : "; ") + why;
        disconnect();
    }
    return makeError(ErrorCode::Device, m_uri.text + " unit " + std::to_string(unit) + ": " + what + ": " + lastError);
}

Error ModbusDrive::exceptionError(int unit, int code, const std::string& what)
{
    std::string detail =
        m_uri.text + " unit " + std::to_string(unit) + ": " + what + ": drive answered " + modbusExceptionText(code);
    // The drive explains its refusals in status.message; one plain read, no retry.
    const auto& f = m_map.field("status.message");
    std::vector<std::uint16_t> buf(static_cast<std::size_t>(f.count));
    if (m_connected && modbus_read_registers(mb(m_ctx), f.address, f.count, buf.data()) == f.count) {
        ++m_requests;
        const std::string msg = decodeString(buf.data(), f.count);
        if (!msg.empty())
            detail += " — " + msg;
    }
    const ErrorCode ec = code == 3 ? ErrorCode::OutOfRange : code == 6 ? ErrorCode::Busy : ErrorCode::Device;
    return makeError(ec, detail);
}

Status ModbusDrive::readRegs(int unit, int address, int count, std::uint16_t* out, const std::string& what)
{
    return transact(unit, what, Retry::Idempotent,
                    [&](modbus_t* c) { return modbus_read_registers(c, address, count, out); });
}

Status ModbusDrive::writeRegs(int unit, int address, const std::uint16_t* values, int count, const std::string& what)
{
    // Absolute values: writing them twice leaves the same state, so a retry is harmless.
    return transact(unit, what, Retry::Idempotent,
                    [&](modbus_t* c) { return modbus_write_registers(c, address, count, values); });
}

Status ModbusDrive::command(int unit, const std::string& name)
{
    const int code = m_map.code("command", name);
    if (code < 0)
        return makeError(ErrorCode::Internal, "register map " + m_map.family + " has no command '" + name + "'");
    // The token makes the command idempotent: the drive answers a repeated (code, token) without executing it again.
    const std::uint16_t w[2] = {static_cast<std::uint16_t>(code), ++m_token};
    return writeRegs(unit, m_map.field("command.code").address, w, 2, "command " + name);
}

Status ModbusDrive::loadAxes()
{
    const auto& last = m_map.field("identity.axis_name");
    const int n = last.address + last.count;
    std::vector<std::uint16_t> r(static_cast<std::size_t>(n));
    auto get = [&](const std::string& f) { return r[static_cast<std::size_t>(m_map.field(f).address)]; };
    auto text = [&](const std::string& f) {
        return decodeString(&r[static_cast<std::size_t>(m_map.field(f).address)], m_map.field(f).count);
    };
    if (auto st = readRegs(m_map.unitIdBase, 0, n, r.data(), "reading the identity block"); !st)
        return st;
    if (get("identity.magic") != m_map.magic)
        return makeError(ErrorCode::Device, m_uri.text + ": identity.magic is " +
                                                std::to_string(get("identity.magic")) + ", not " +
                                                std::to_string(m_map.magic) + ": not a " + m_map.family + " drive");
    m_identity = {
        text("identity.vendor"), text("identity.model"), text("identity.firmware"), text("identity.machine"), {}};
    const int axes = get("identity.axis_count");
    if (axes < 1 || axes > 32)
        return makeError(ErrorCode::Device, m_uri.text + ": implausible axis count " + std::to_string(axes));
    m_axes.clear();
    for (int i = 0; i < axes; ++i) {
        const int unit = m_map.unitIdBase + i;
        if (auto st = readRegs(unit, 0, n, r.data(), "reading the identity block of axis " + std::to_string(i)); !st)
            return st;
        m_axes.push_back({text("identity.axis_name"), m_map.name("axis_kind", get("identity.axis_kind")), unit});
        m_identity.axes.push_back(m_axes.back().name);
    }
    return Status::success();
}

Result<ModbusDrive::AxisInfo> ModbusDrive::axisInfo(const std::string& axis)
{
    for (const auto& a : m_axes) {
        if (a.name == axis)
            return a;
    }
    std::string known;
    for (const auto& a : m_axes)
        known += (known.empty() ? "" : ", ") + a.name;
    return makeError(ErrorCode::NotFound, "no axis '" + axis + "' on " + m_uri.text + " (axes: " + known + ")");
}

Result<DriveIdentity> ModbusDrive::identify()
{
    if (auto st = loadAxes(); !st)
        return st.error();
    return m_identity;
}

Result<std::vector<model::ParameterMeta>> ModbusDrive::parameterMetadata(const std::string& axis)
{
    auto a = axisInfo(axis);
    if (!a)
        return a.error();
    std::vector<model::ParameterMeta> out;
    for (const auto& p : m_map.parameters) {
        if (p.availableOn(a->kind))
            out.push_back(p.meta);
    }
    return out;
}

Result<model::ParameterValues> ModbusDrive::readParameters(const std::string& axis, std::span<const std::string> keys)
{
    auto a = axisInfo(axis);
    if (!a)
        return a.error();
    std::vector<const ParameterRegister*> regs;
    if (keys.empty()) {
        for (const auto& p : m_map.parameters) {
            if (p.availableOn(a->kind))
                regs.push_back(&p);
        }
    }
    for (const auto& k : keys) {
        const auto* p = m_map.parameter(k);
        if (!p || !p->availableOn(a->kind))
            return makeError(ErrorCode::NotFound, "axis " + axis + ": unknown parameter '" + k + "'");
        regs.push_back(p);
    }
    std::sort(regs.begin(), regs.end(), [](auto* x, auto* y) { return x->address < y->address; });
    model::ParameterValues out;
    const int maxRegs = m_map.maxRegistersPerRead;
    for (std::size_t i = 0; i < regs.size();) {
        // One read per run of adjacent parameter registers, at most maxRegistersPerRead long.
        std::size_t j = i + 1;
        while (j < regs.size() && regs[j]->address == regs[j - 1]->address + 2 &&
               regs[j]->address + 2 - regs[i]->address <= maxRegs)
            ++j;
        const int first = regs[i]->address, count = regs[j - 1]->address + 2 - first;
        std::vector<std::uint16_t> buf(static_cast<std::size_t>(count));
        if (auto st = readRegs(a->unit, first, count, buf.data(), "reading parameter " + regs[i]->meta.key); !st)
            return st.error();
        for (std::size_t k = i; k < j; ++k)
            out[regs[k]->meta.key] =
                decodeF32(&buf[static_cast<std::size_t>(regs[k]->address - first)], m_map.wordOrder);
        i = j;
    }
    return out;
}

Status ModbusDrive::writeParameters(const std::string& axis, const model::ParameterValues& values)
{
    auto a = axisInfo(axis);
    if (!a)
        return a.error();
    // Everything is checked before the first byte goes out (limits are the map's).
    for (const auto& [k, v] : values) {
        const auto* p = m_map.parameter(k);
        if (!p || !p->availableOn(a->kind))
            return makeError(ErrorCode::NotFound, "axis " + axis + ": unknown parameter '" + k + "'");
        if (!p->meta.writable)
            return makeError(ErrorCode::BadInput, "axis " + axis + ": parameter '" + k + "' is read-only");
        if (m_testRunning && !p->meta.writableDuringTest)
            return makeError(ErrorCode::Busy,
                             "axis " + axis + ": parameter '" + k + "' cannot be written while a test runs");
        for (const double x : {v, static_cast<double>(static_cast<float>(v))}) {
            if (auto st = model::checkParameterValue(p->meta, x); !st)
                return makeError(st.error().code, "axis " + axis + ": " + st.error().detail + " (not sent)");
        }
    }
    for (const auto& [k, v] : values) {
        const auto* p = m_map.parameter(k);
        std::uint16_t w[2];
        encodeF32(static_cast<float>(v), m_map.wordOrder, w);
        if (auto st = writeRegs(a->unit, p->address, w, 2, "writing parameter " + k); !st)
            return st;
    }
    // Read back: the drive must hold exactly the float32 that was sent.
    std::vector<std::string> keys;
    for (const auto& [k, v] : values)
        keys.push_back(k);
    auto back = readParameters(axis, keys);
    if (!back)
        return back.error();
    for (const auto& [k, v] : values) {
        const double sent = static_cast<float>(v);
        if (back->at(k) != sent)
            return makeError(ErrorCode::Device, m_uri.text + ": read-back of " + k + " gave " +
                                                    std::to_string(back->at(k)) + " after writing " +
                                                    std::to_string(sent));
    }
    return Status::success();
}

Status ModbusDrive::startTest(const TestRequest& request)
{
    auto unit = writeTestBlock(request);
    if (!unit)
        return unit.error();
    if (auto st = command(*unit, "start_test"); !st)
        return st;
    m_testRunning = true;
    m_testUnit = *unit;
    m_lastHeartbeat = m_lastPoll = Clock::now();
    return Status::success();
}

Result<int> ModbusDrive::writeTestBlock(const TestRequest& request)
{
    auto a = axisInfo(request.axis);
    if (!a)
        return a.error();
    if (request.type() == TestType::Frf) {
        if (auto st = checkRatedTorqueFrfRequest(request); !st)
            return st.error();
    }
    // The request as the quantities the map's fields carry (TestRegisterCodec.h), every carrying field written:
    // the test block and, after the circle block, the jog's jerk and the FRF amplitude.
    auto values = testValuesOf(request, m_map, [this](const std::string& axis) -> Result<int> {
        auto i = axisInfo(axis);
        if (!i)
            return i.error();
        return i->unit - m_map.unitIdBase;
    });
    if (!values)
        return values.error();
    auto writes = encodeTestRegisters(*values, m_map);
    if (!writes)
        return writes.error();
    for (const auto& w : *writes) {
        if (auto st = writeRegs(a->unit, w.address, w.words.data(), static_cast<int>(w.words.size()),
                                "writing the test configuration");
            !st)
            return st.error();
    }
    return a->unit;
}

Result<std::vector<std::uint16_t>> ModbusDrive::readFields(int unit, const std::vector<std::string>& names, int& first,
                                                           const std::string& what)
{
    int lo = 65536, hi = 0;
    for (const auto& n : names) {
        if (!m_map.fields.count(n))
            return makeError(ErrorCode::NotFound, "drive family " + m_map.family + " has no field " + n + ": " + what +
                                                      " is not available from this drive");
        lo = std::min(lo, m_map.field(n).address);
        hi = std::max(hi, m_map.field(n).address + m_map.field(n).count);
    }
    if (hi - lo > m_map.maxRegistersPerRead)
        return makeError(ErrorCode::Internal, "register map " + m_map.family + ": " + what + " must fit one read");
    std::vector<std::uint16_t> r(static_cast<std::size_t>(hi - lo));
    if (auto st = readRegs(unit, lo, hi - lo, r.data(), "reading " + what); !st)
        return st.error();
    first = lo;
    return r;
}

Result<DriveCapabilities> ModbusDrive::capabilities(const std::string& axis)
{
    auto a = axisInfo(axis);
    if (!a)
        return a.error();
    int lo = 0;
    auto r = readFields(a->unit,
                        {"describe.test_types", "describe.frf_methods", "describe.flags", "describe.trace_rate_hz",
                         "describe.current_trace_rate_hz"},
                        lo, "the capabilities of axis " + axis);
    if (!r)
        return r.error();
    auto at = [&](const char* f) { return &(*r)[static_cast<std::size_t>(m_map.field(f).address - lo)]; };
    DriveCapabilities c;
    for (const auto t :
         {TestType::Step, TestType::Jog, TestType::Hold, TestType::Frf, TestType::Circle, TestType::CurrentStep}) {
        const int code = m_map.code("test_type", testTypeName(t));
        if (code >= 0 && code < 16 && (*at("describe.test_types") >> code & 1))
            c.testTypes.push_back(t);
    }
    for (const auto m : {FrfMethod::MultiSweep, FrfMethod::Conventional, FrfMethod::Prbs, FrfMethod::Multisine}) {
        const int code = m_map.code("frf_method", frfMethodName(m));
        if (code >= 0 && code < 16 && (*at("describe.frf_methods") >> code & 1))
            c.frfMethods.push_back(m);
    }
    const int flags = *at("describe.flags");
    c.evaluatesFrf = (flags & std::max(0, m_map.code("describe_flag", "evaluates_frf"))) != 0;
    c.writesParameters = (flags & std::max(0, m_map.code("describe_flag", "writes_parameters"))) != 0;
    c.hasLink = true;
    c.scope = m_map.fields.count("scope.window") && m_map.code("describe_flag", "scope") > 0 &&
              (flags & m_map.code("describe_flag", "scope")) != 0;
    c.traceRateHz = decodeF64(at("describe.trace_rate_hz"), m_map.wordOrder);
    c.currentTraceRateHz = decodeF64(at("describe.current_trace_rate_hz"), m_map.wordOrder);
    return c;
}

Result<DriveLimits> ModbusDrive::limits(const std::string& axis)
{
    auto a = axisInfo(axis);
    if (!a)
        return a.error();
    const std::vector<std::pair<std::string, double DriveLimits::*>> fields{
        {"limits.frf_amplitude_max_pct", &DriveLimits::frfAmplitudeMaxPct},
        {"limits.current_step_max_a", &DriveLimits::currentStepMaxA},
        {"limits.current_step_max_s", &DriveLimits::currentStepMaxS},
        {"limits.current_step_max_speed_rad_s", &DriveLimits::currentStepMaxSpeedRadS},
        {"limits.motor_speed_max_rad_s", &DriveLimits::motorSpeedMaxRadS},
        {"limits.test_duration_max_s", &DriveLimits::testDurationMaxS},
        {"limits.travel_window", &DriveLimits::travelWindow}};
    std::vector<std::string> names;
    for (const auto& [n, m] : fields)
        names.push_back(n);
    int lo = 0;
    auto r = readFields(a->unit, names, lo, "the limits of axis " + axis);
    if (!r)
        return r.error();
    DriveLimits l;
    for (const auto& [n, member] : fields) {
        const double v = decodeF64(&(*r)[static_cast<std::size_t>(m_map.field(n).address - lo)], m_map.wordOrder);
        if (std::isnan(v) || v < 0.0)
            return makeError(ErrorCode::Device, m_uri.text + ": " + n + " of axis " + axis + " reads " +
                                                    model::formatNumber(v, 6) + ", not a limit");
        l.*member = v;
    }
    return l;
}

Result<TestPlan> ModbusDrive::planTest(const TestRequest& request)
{
    if (m_map.code("command", "plan_test") < 0)
        return makeError(ErrorCode::NotFound, "drive family " + m_map.family + " has no command plan_test");
    auto unit = writeTestBlock(request);
    if (!unit)
        return unit.error();
    if (auto st = command(*unit, "plan_test"); !st)
        return st.error();
    int lo = 0;
    auto r = readFields(*unit, {"plan.token", "plan.record_samples", "plan.motion_s", "plan.trace_rate_hz"}, lo,
                        "the test plan");
    if (!r)
        return r.error();
    auto at = [&](const char* f) { return &(*r)[static_cast<std::size_t>(m_map.field(f).address - lo)]; };
    if (*at("plan.token") != m_token)
        return makeError(ErrorCode::Device, m_uri.text + ": the plan block answers command token " +
                                                std::to_string(*at("plan.token")) + ", not " + std::to_string(m_token));
    TestPlan p;
    p.recordSamples = decodeU32(at("plan.record_samples"), m_map.wordOrder);
    p.motionTimeS = decodeF64(at("plan.motion_s"), m_map.wordOrder);
    p.traceRateHz = decodeF64(at("plan.trace_rate_hz"), m_map.wordOrder);
    return p;
}

Status ModbusDrive::heartbeat()
{
    const int unit = m_testUnit >= 0 ? m_testUnit : m_map.unitIdBase;
    const std::uint16_t v = ++m_heartbeat;
    m_lastHeartbeat = Clock::now();
    return writeRegs(unit, m_map.field("heartbeat.counter").address, &v, 1, "heartbeat");
}

Result<TestStatus> ModbusDrive::pollTest()
{
    const int unit = m_testUnit >= 0 ? m_testUnit : m_map.unitIdBase;
    if (m_testRunning) {
        // Callers poll in a loop; pace them so the link carries status requests, not a flood.
        const auto next = m_lastPoll + kMinPollInterval;
        if (Clock::now() < next)
            std::this_thread::sleep_until(next);
        if (Clock::now() - m_lastHeartbeat >= kHeartbeatPeriod) {
            if (auto st = heartbeat(); !st)
                return st.error();
        }
    }
    m_lastPoll = Clock::now();
    const auto& f0 = m_map.field("status.state");
    const auto& fm = m_map.field("status.message");
    const int n = fm.address + fm.count - f0.address;
    std::vector<std::uint16_t> r(static_cast<std::size_t>(n));
    if (auto st = readRegs(unit, f0.address, n, r.data(), "reading the status block"); !st)
        return st.error();
    auto at = [&](const std::string& f) { return &r[static_cast<std::size_t>(m_map.field(f).address - f0.address)]; };
    const std::string state = m_map.name("state", *at("status.state"));
    const std::string fault = m_map.name("fault", *at("status.fault_code"));
    TestStatus s;
    s.progress = *at("status.progress") / 10000.0;
    s.state = state == "running"     ? TestState::Running
              : state == "completed" ? TestState::Completed
              : state == "aborted"   ? TestState::Aborted
              : state == "faulted"   ? TestState::Faulted
                                     : TestState::Idle;
    if (s.state == TestState::Aborted || s.state == TestState::Faulted)
        s.detail = "drive " + m_uri.text + " stopped the test (" + fault +
                   "): " + decodeString(at("status.message"), fm.count);
    if (s.state != TestState::Running)
        m_testRunning = false;
    return s;
}

Status ModbusDrive::abortTest()
{
    const int unit = m_testUnit >= 0 ? m_testUnit : m_map.unitIdBase;
    m_testRunning = false;
    return command(unit, "abort_test");
}

Result<std::unique_ptr<Drive>> connectAny(const ConnectionSettings& settings)
{
    return connect(settings);  // connect() dispatches sim: and modbus: alike
}

Result<std::unique_ptr<Drive>> connectModbus(const ConnectionSettings& settings)
{
    auto uri = parseModbusUri(settings.uri);
    if (!uri)
        return uri.error();
    auto map = loadRegisterMap(uri->family);
    if (!map)
        return makeError(map.error().code, "connection '" + settings.uri + "': " + map.error().detail);
    auto d = ModbusDrive::open(*uri, std::move(map).value());
    if (!d)
        return d.error();
    return std::unique_ptr<Drive>(std::move(d).value());
}

} // namespace axistune::device

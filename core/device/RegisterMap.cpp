// SPDX-License-Identifier: GPL-3.0-or-later
// Register map loader and register encodings; the format is described in docs/modbus.md.
#include "core/device/RegisterMap.h"
#include "core/device/TestRegisterCodec.h"

#include "core/model/InputLimits.h"
#include "core/sim/MachineDefinition.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace axistune::device {

int registerCount(RegisterType type)
{
    switch (type) {
    case RegisterType::U16:
        return 1;
    case RegisterType::U32:
    case RegisterType::F32:
        return 2;
    case RegisterType::F64:
        return 4;
    case RegisterType::String:
    case RegisterType::Window:
        return 0;
    }
    return 0;
}

const char* registerTypeName(RegisterType type)
{
    switch (type) {
    case RegisterType::U16:
        return "u16";
    case RegisterType::U32:
        return "u32";
    case RegisterType::F32:
        return "f32";
    case RegisterType::F64:
        return "f64";
    case RegisterType::String:
        return "string";
    case RegisterType::Window:
        return "window";
    }
    return "?";
}

bool ParameterRegister::availableOn(const std::string& axisKind) const
{
    return axisKinds.empty() || std::find(axisKinds.begin(), axisKinds.end(), axisKind) != axisKinds.end();
}

const RegisterField& RegisterMap::field(const std::string& n) const
{
    static const RegisterField kNone{"", -1, RegisterType::U16, 0, "", ""};
    auto it = fields.find(n);
    return it == fields.end() ? kNone : it->second;
}

const ParameterRegister* RegisterMap::parameter(const std::string& key) const
{
    for (const auto& p : parameters) {
        if (p.meta.key == key)
            return &p;
    }
    return nullptr;
}

const ParameterRegister* RegisterMap::parameterAt(int address) const
{
    for (const auto& p : parameters) {
        if (p.address == address)
            return &p;
    }
    return nullptr;
}

int RegisterMap::code(const std::string& group, const std::string& n) const
{
    auto g = enums.find(group);
    if (g == enums.end())
        return -1;
    auto it = g->second.find(n);
    return it == g->second.end() ? -1 : it->second;
}

std::string RegisterMap::name(const std::string& group, int c) const
{
    auto g = enums.find(group);
    if (g == enums.end())
        return {};
    for (const auto& [n, v] : g->second) {
        if (v == c)
            return n;
    }
    return {};
}

const std::vector<std::string>& requiredRegisterFields()
{
    static const std::vector<std::string> k{"identity.magic",
                                            "identity.map_version",
                                            "identity.axis_count",
                                            "identity.axis_index",
                                            "identity.vendor",
                                            "identity.model",
                                            "identity.firmware",
                                            "identity.machine",
                                            "identity.axis_name",
                                            "identity.axis_kind",
                                            "identity.parameter_count",
                                            "status.state",
                                            "status.fault_code",
                                            "status.position",
                                            "status.velocity",
                                            "status.torque",
                                            "status.progress",
                                            "status.heartbeat_echo",
                                            "status.command_token_echo",
                                            "status.command_result",
                                            "status.trace_samples",
                                            "status.trace_channels",
                                            "status.trace_rate_hz",
                                            "status.message",
                                            "test.type",
                                            "command.code",
                                            "command.token",
                                            "heartbeat.counter",
                                            "trace.select_offset",
                                            "trace.select_channel",
                                            "trace.window"};
    return k;
}

namespace {

Result<RegisterType> parseType(const std::string& s)
{
    static const std::map<std::string, RegisterType> k{
        {"u16", RegisterType::U16}, {"u32", RegisterType::U32},       {"f32", RegisterType::F32},
        {"f64", RegisterType::F64}, {"string", RegisterType::String}, {"window", RegisterType::Window}};
    auto it = k.find(s);
    if (it == k.end())
        return makeError(ErrorCode::BadInput, "unknown type '" + s + "' (u16, u32, f32, f64, string, window)");
    return it->second;
}

Status checkLayout(const RegisterMap& m, const std::string& source)
{
    // Every register belongs to at most one field or parameter.
    std::map<int, std::string> owner;
    auto claim = [&](int addr, int count, const std::string& who) -> Status {
        if (addr < 0 || count <= 0 || addr + count > 65536)
            return makeError(ErrorCode::BadInput, source + ": '" + who + "' lies outside the register space 0..65535");
        for (int a = addr; a < addr + count; ++a) {
            auto [it, fresh] = owner.emplace(a, who);
            if (!fresh)
                return makeError(ErrorCode::BadInput, source + ": register " + std::to_string(a) +
                                                          " is used by both '" + it->second + "' and '" + who + "'");
        }
        return Status::success();
    };
    for (const auto& [n, f] : m.fields) {
        if (auto st = claim(f.address, f.count, n); !st)
            return st;
    }
    for (const auto& p : m.parameters) {
        if (auto st = claim(p.address, 2, "parameter " + p.meta.key); !st)
            return st;
    }
    for (const auto& req : requiredRegisterFields()) {
        if (!m.fields.count(req))
            return makeError(ErrorCode::BadInput, source + ": required field '" + req + "' is missing");
    }
    const auto& win = m.field("trace.window");
    if (win.type != RegisterType::Window || win.count < 4 || win.count > m.maxRegistersPerRead)
        return makeError(ErrorCode::BadInput, source + ": 'trace.window' must be a window of 4.." +
                                                  std::to_string(m.maxRegistersPerRead) + " registers");
    const auto& off = m.field("trace.select_offset");
    const auto& ch = m.field("trace.select_channel");
    if (ch.address != off.address + off.count)
        return makeError(ErrorCode::BadInput, source + ": 'trace.select_channel' must follow 'trace.select_offset'");
    if (m.field("test.type").carries != "test.type")
        return makeError(ErrorCode::BadInput,
                         source + ": 'test.type' must carry test.type (register map version 2 and "
                                  "later: every test field names the quantity it carries, docs/modbus.md)");
    const auto& code = m.field("command.code");
    if (m.field("command.token").address != code.address + 1)
        return makeError(ErrorCode::BadInput, source + ": 'command.token' must follow 'command.code'");
    return Status::success();
}

} // namespace

Result<RegisterMap> parseRegisterMap(const std::string& jsonText, const std::string& source)
{
    using nlohmann::json;
    auto parsed = model::parseJsonText(jsonText, source);
    if (!parsed)
        return parsed.error();
    const json& j = *parsed;
    RegisterMap m;
    std::string where = "top level";
    try {
        m.family = j.at("family").get<std::string>();
        m.version = j.at("version").get<int>();
        const auto wo = j.value("word_order", std::string("high_word_first"));
        if (wo != "high_word_first" && wo != "low_word_first")
            return makeError(ErrorCode::BadInput, source + ": word_order must be high_word_first or low_word_first");
        m.wordOrder = wo == "high_word_first" ? WordOrder::HighWordFirst : WordOrder::LowWordFirst;
        m.unitIdBase = j.value("unit_id_base", 1);
        m.maxRegistersPerRead = j.value("max_registers_per_read", 125);
        m.magic = j.at("magic").get<std::uint16_t>();
        if (m.unitIdBase < 1 || m.unitIdBase > 247 || m.maxRegistersPerRead < 4 || m.maxRegistersPerRead > 125)
            return makeError(ErrorCode::BadInput,
                             source + ": unit_id_base must lie in 1..247, max_registers_per_read in 4..125");
        for (const auto& [n, f] : j.at("fields").items()) {
            where = "field '" + n + "'";
            RegisterField rf;
            rf.name = n;
            rf.address = f.at("address").get<int>();
            auto t = parseType(f.at("type").get<std::string>());
            if (!t)
                return makeError(ErrorCode::BadInput, source + ": " + where + ": " + t.error().detail);
            rf.type = *t;
            rf.count = registerCount(rf.type) > 0 ? registerCount(rf.type) : f.at("count").get<int>();
            rf.description = f.value("description", std::string());
            rf.carries = f.value("carries", std::string());
            if (!rf.carries.empty()) {
                const TestQuantity* q = findTestQuantity(rf.carries);
                if (!q)
                    return makeError(ErrorCode::BadInput,
                                     source + ": " + where + ": carries unknown quantity '" + rf.carries + "'");
                const bool whole = rf.type == RegisterType::U16 || rf.type == RegisterType::U32;
                const bool real = rf.type == RegisterType::F32 || rf.type == RegisterType::F64;
                if (q->whole ? !whole : !real)
                    return makeError(ErrorCode::BadInput, source + ": " + where + ": " + rf.carries + " needs a " +
                                                              (q->whole ? "u16 or u32" : "f32 or f64") + " field");
                for (const auto& [other, of] : m.fields) {
                    if (of.carries == rf.carries && rf.carries != "reserved")
                        return makeError(ErrorCode::BadInput, source + ": " + where + " and field '" + other +
                                                                  "' both carry " + rf.carries);
                }
            }
            m.fields[n] = rf;
        }
        for (const auto& [g, values] : j.at("enums").items()) {
            where = "enum '" + g + "'";
            std::map<int, std::string> named;
            for (const auto& [n, v] : values.items()) {
                const int code = v.get<int>();
                if (auto [it, fresh] = named.emplace(code, n); !fresh)
                    return makeError(ErrorCode::BadInput, source + ": " + where + ": '" + it->second + "' and '" + n +
                                                              "' have the same code " + std::to_string(code));
                m.enums[g][n] = code;
            }
        }
        for (const auto& p : j.at("parameters")) {
            ParameterRegister pr;
            pr.meta.key = p.at("key").get<std::string>();
            where = "parameter '" + pr.meta.key + "'";
            pr.address = p.at("address").get<int>();
            pr.meta.label = p.value("label", pr.meta.key);
            pr.meta.siUnit = p.at("si_unit").get<std::string>();
            pr.meta.displayUnit = p.value("display_unit", pr.meta.siUnit);
            pr.meta.minSi = p.at("min").get<double>();
            pr.meta.maxSi = p.at("max").get<double>();
            pr.meta.writable = p.value("writable", true);
            pr.meta.writableDuringTest = p.value("writable_during_test", false);
            pr.meta.integer = p.value("integer", false);
            pr.meta.group = p.value("group", std::string());
            pr.meta.description = p.value("description", std::string());
            pr.axisKinds = p.value("axis_kinds", std::vector<std::string>{});
            if (p.value("type", std::string("f32")) != "f32")
                return makeError(ErrorCode::BadInput,
                                 source + ": " + where + ": parameters are float32 pairs (type f32)");
            if (!(pr.meta.minSi <= pr.meta.maxSi))
                return makeError(ErrorCode::BadInput, source + ": " + where + ": min exceeds max");
            m.parameters.push_back(std::move(pr));
        }
    } catch (const json::exception& e) {
        return makeError(ErrorCode::BadInput, source + ": " + where + ": " + e.what());
    }
    if (auto st = checkLayout(m, source); !st)
        return st.error();
    return m;
}

Result<RegisterMap> loadRegisterMapFile(const std::string& path)
{
    auto text = model::readInputFile(path);
    if (!text)
        return text.error();
    return parseRegisterMap(*text, path);
}

Result<RegisterMap> loadRegisterMap(const std::string& family)
{
    return loadRegisterMapFile(sim::resourceDir() + "/drives/" + family + ".json");
}

void encodeU32(std::uint32_t v, WordOrder o, std::uint16_t* out)
{
    const auto hi = static_cast<std::uint16_t>(v >> 16), lo = static_cast<std::uint16_t>(v & 0xFFFFu);
    out[0] = o == WordOrder::HighWordFirst ? hi : lo;
    out[1] = o == WordOrder::HighWordFirst ? lo : hi;
}

std::uint32_t decodeU32(const std::uint16_t* in, WordOrder o)
{
    const std::uint32_t hi = o == WordOrder::HighWordFirst ? in[0] : in[1];
    const std::uint32_t lo = o == WordOrder::HighWordFirst ? in[1] : in[0];
    return (hi << 16) | lo;
}

void encodeF32(float v, WordOrder o, std::uint16_t* out)
{
    std::uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    encodeU32(bits, o, out);
}

float decodeF32(const std::uint16_t* in, WordOrder o)
{
    const std::uint32_t bits = decodeU32(in, o);
    float v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}

void encodeF64(double v, WordOrder o, std::uint16_t* out)
{
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    for (int i = 0; i < 4; ++i) {
        const auto w = static_cast<std::uint16_t>(bits >> (16 * (3 - i))); // most significant first
        out[o == WordOrder::HighWordFirst ? i : 3 - i] = w;
    }
}

double decodeF64(const std::uint16_t* in, WordOrder o)
{
    std::uint64_t bits = 0;
    for (int i = 0; i < 4; ++i)
        bits = (bits << 16) | in[o == WordOrder::HighWordFirst ? i : 3 - i];
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}

void encodeString(const std::string& s, int registers, std::uint16_t* out)
{
    for (int r = 0; r < registers; ++r) {
        const std::size_t i = 2 * static_cast<std::size_t>(r);
        const auto hi = i < s.size() ? static_cast<unsigned char>(s[i]) : 0u;
        const auto lo = i + 1 < s.size() ? static_cast<unsigned char>(s[i + 1]) : 0u;
        out[r] = static_cast<std::uint16_t>((hi << 8) | lo);
    }
}

std::string decodeString(const std::uint16_t* in, int registers)
{
    std::string s;
    for (int r = 0; r < registers; ++r) {
        for (const char c : {static_cast<char>(in[r] >> 8), static_cast<char>(in[r] & 0xFF)}) {
            if (c == '\0')
                return s;
            s += c;
        }
    }
    return s;
}

} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A drive family's Modbus register map as data (resources/drives/<family>.json, docs/modbus.md):
// named fields (identity, status, test configuration, command, heartbeat, trace window) with an
// address, a type and a size in registers, enumerations (states, faults, commands, test types) and
// every drive parameter as a float32 pair with its metadata. Client and simulated server both
// read the same file, so another drive family is another JSON file, not code.

#include "core/model/Parameter.h"
#include "core/model/Result.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace axistune::device {

enum class RegisterType { U16, U32, F32, F64, String, Window };

/// Registers a value of the type occupies (String and Window: as declared in the map).
int registerCount(RegisterType type);
const char* registerTypeName(RegisterType type);

struct RegisterField {
    std::string name; ///< "status.state", "trace.window"
    int address = 0;  ///< PDU address (0-based) of the first holding register
    RegisterType type = RegisterType::U16;
    int count = 1; ///< registers
    std::string description;
    /// The test request quantity the field holds ("step.velocity_rad_s", TestRegisterCodec.h); empty: none.
    std::string carries;
};

struct ParameterRegister {
    model::ParameterMeta meta;
    int address = 0;                    ///< float32 pair at address, address+1
    std::vector<std::string> axisKinds; ///< "linear", "rotary"; empty: every axis
    bool availableOn(const std::string& axisKind) const;
};

enum class WordOrder { HighWordFirst, LowWordFirst };

struct RegisterMap {
    std::string family;
    int version = 0;
    WordOrder wordOrder = WordOrder::HighWordFirst;
    int unitIdBase = 1;            ///< axis i (identity order) answers on unit id unitIdBase + i
    int maxRegistersPerRead = 125; ///< Modbus limit for function code 3
    std::uint16_t magic = 0;       ///< expected value of identity.magic
    std::map<std::string, RegisterField> fields;
    std::vector<ParameterRegister> parameters;
    /// Enumerations by group ("state", "fault", "command", "test_type", "axis_kind", "trace_channel"): name → code.
    std::map<std::string, std::map<std::string, int>> enums;

    /// The field (must exist: loadRegisterMap checks the required ones).
    const RegisterField& field(const std::string& name) const;
    const ParameterRegister* parameter(const std::string& key) const;
    const ParameterRegister* parameterAt(int address) const;
    /// Enumeration lookup; -1 when absent.
    int code(const std::string& group, const std::string& name) const;
    /// Reverse lookup; "" when absent.
    std::string name(const std::string& group, int code) const;
};

/// Parses a map; errors name `source` and the offending entry (missing field, overlap, bad type).
Result<RegisterMap> parseRegisterMap(const std::string& jsonText, const std::string& source);
Result<RegisterMap> loadRegisterMapFile(const std::string& path);
/// resources/drives/<family>.json under sim::resourceDir().
Result<RegisterMap> loadRegisterMap(const std::string& family);

/// Names of the fields every map must define (the protocol's vocabulary).
const std::vector<std::string>& requiredRegisterFields();

// Encoding of values into registers in the map's word order (bytes within a register are big endian
// as Modbus defines; strings carry two ASCII characters per register, first in the high byte, NUL padded).
void encodeU32(std::uint32_t v, WordOrder o, std::uint16_t* out);
std::uint32_t decodeU32(const std::uint16_t* in, WordOrder o);
void encodeF32(float v, WordOrder o, std::uint16_t* out);
float decodeF32(const std::uint16_t* in, WordOrder o);
void encodeF64(double v, WordOrder o, std::uint16_t* out);
double decodeF64(const std::uint16_t* in, WordOrder o);
void encodeString(const std::string& s, int registers, std::uint16_t* out);
std::string decodeString(const std::uint16_t* in, int registers);

} // namespace axistune::device

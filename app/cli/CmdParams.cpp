// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli params: reads a drive axis's parameters as JSON (SI units) and writes some with
// read-back, over the embedded simulated drive (sim:PRESET) or Modbus TCP (modbus://HOST:PORT).
#include "app/cli/CliCommand.h"
#include "core/device/ModbusDrive.h"
#include "core/model/Number.h"

#include <charconv>
#include <iostream>
#include <memory>

namespace axistune::cli {
namespace {

struct ParamsOptions {
    std::string connect = "sim:vmc";
    std::string axis;
    std::vector<std::string> set;
    std::vector<std::string> get;
    std::uint64_t seed = 1;
};

/// Shortest text that reads back to the same value; float32 values (Modbus) as floats.
std::string numberText(double v)
{
    char buf[64];
    const auto f = static_cast<float>(v);
    const auto r =
        static_cast<double>(f) == v ? std::to_chars(buf, buf + sizeof buf, f) : std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

std::string jsonString(const std::string& s)
{
    std::string o = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\')
            o += '\\';
        o += c;
    }
    return o + "\"";
}

Result<model::ParameterValues> parseSets(const std::vector<std::string>& sets)
{
    model::ParameterValues v;
    for (const auto& s : sets) {
        const auto eq = s.find('=');
        const auto x = eq == std::string::npos ? std::nullopt : model::parseNumber(std::string_view(s).substr(eq + 1));
        if (eq == std::string::npos || eq == 0 || !x)
            return makeError(ErrorCode::BadInput,
                             "--set '" + s + "': expected KEY=VALUE with VALUE a number in SI units");
        v[s.substr(0, eq)] = *x;
    }
    return v;
}

int runParams(const ParamsOptions& o)
{
    const std::string cmd = "params";
    auto sets = parseSets(o.set);
    if (!sets)
        return reportError(cmd, sets.error());
    auto drive = device::connectAny({o.connect, o.seed});
    if (!drive)
        return reportError(cmd, drive.error());
    auto metas = (*drive)->parameterMetadata(o.axis);
    if (!metas)
        return reportError(cmd, metas.error());
    if (!sets->empty()) {
        if (auto st = (*drive)->writeParameters(o.axis, *sets); !st)
            return reportError(cmd, st.error());
    }
    auto values = (*drive)->readParameters(o.axis, o.get);
    if (!values)
        return reportError(cmd, values.error());
    std::cout << "{\n  \"connection\": " << jsonString(o.connect) << ",\n  \"axis\": " << jsonString(o.axis)
              << ",\n  \"parameters\": {";
    const char* sep = "\n";
    for (const auto& [k, v] : *values) {
        std::cout << sep << "    " << jsonString(k) << ": " << numberText(v);
        sep = ",\n";
    }
    std::cout << "\n  },\n  \"units\": {";
    sep = "\n";
    for (const auto& [k, v] : *values) {
        const auto* m = model::findParameter(*metas, k);
        std::cout << sep << "    " << jsonString(k) << ": " << jsonString(m ? m->siUnit : "");
        sep = ",\n";
    }
    std::cout << "\n  },\n  \"written\": [";
    sep = "";
    for (const auto& [k, v] : *sets) {
        std::cout << sep << jsonString(k);
        sep = ", ";
    }
    std::cout << "]\n}\n";
    return 0;
}

const CliRegistrar kRegistrar{
    {"params", "Read (JSON, SI units) and write drive parameters with read-back", [](CLI::App& sub) {
         auto o = std::make_shared<ParamsOptions>();
         sub.add_option("--connect", o->connect, connectOptionHelp())->capture_default_str();
         sub.add_option("--axis", o->axis, "axis name, e.g. X")->required();
         sub.add_option("--set", o->set,
                        "KEY=VALUE in SI units (repeatable); checked against the limits before sending");
         sub.add_option("--get", o->get, "read only these keys (repeatable; default: all)");
         sub.add_option("--seed", o->seed, "noise seed of an embedded simulated machine")->capture_default_str();
         return [o] { return runParams(*o); };
     }}};

} // namespace
} // namespace axistune::cli

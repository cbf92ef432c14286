// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/FaultInjection.h"

#include "core/model/Number.h"

#include <cmath>
#include <cstdlib>

namespace axistune::device {
namespace {

constexpr const char* kForms = "drop-after:N (1..100000), delay:MS (1..10000), illegal-address, drive-fault:S (0..600)";

bool parseNumber(const std::string& s, double& out)
{
    const auto v = model::parseNumber(s);
    if (v)
        out = *v;
    return v.has_value();
}

} // namespace

Status addFaultMode(FaultInjection& f, const std::string& mode)
{
    const auto colon = mode.find(':');
    const std::string name = mode.substr(0, colon);
    const std::string arg = colon == std::string::npos ? "" : mode.substr(colon + 1);
    double v = 0.0;
    auto bad = [&] { return makeError(ErrorCode::BadInput, "fault mode '" + mode + "': expected one of " + kForms); };
    if (name == "illegal-address" && arg.empty()) {
        f.illegalAddress = true;
    } else if (name == "drop-after" && parseNumber(arg, v) && v >= 1 && v <= 100000 && v == std::floor(v)) {
        f.dropAfterRequests = static_cast<int>(v);
    } else if (name == "delay" && parseNumber(arg, v) && v >= 1 && v <= 10000 && v == std::floor(v)) {
        f.delayMs = static_cast<int>(v);
    } else if (name == "drive-fault" && parseNumber(arg, v) && v >= 0 && v <= 600) {
        f.driveFaultAfterS = v;
    } else {
        return bad();
    }
    return Status::success();
}

Result<FaultInjection> parseFaultModes(const std::vector<std::string>& modes)
{
    FaultInjection f;
    for (const auto& m : modes) {
        if (auto st = addFaultMode(f, m); !st)
            return st.error();
    }
    return f;
}

std::string describeFaults(const FaultInjection& f)
{
    std::string s;
    auto add = [&s](const std::string& x) { s += (s.empty() ? "" : ", ") + x; };
    if (f.dropAfterRequests > 0)
        add("drop-after:" + std::to_string(f.dropAfterRequests));
    if (f.delayMs > 0)
        add("delay:" + std::to_string(f.delayMs));
    if (f.illegalAddress)
        add("illegal-address");
    if (f.driveFaultAfterS >= 0)
        add("drive-fault:" + std::to_string(f.driveFaultAfterS));
    return s.empty() ? "none" : s;
}

} // namespace axistune::device

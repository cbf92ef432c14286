// SPDX-License-Identifier: GPL-3.0-or-later
// The backend registry (DriveRegistry.h) and device::connect(), which dispatches through it.
#include "core/device/DriveRegistry.h"

#include "core/model/Number.h"

#include <algorithm>

namespace axistune::device {

#define AXISTUNE_DRIVE_BACKEND(fn) DriveBackend fn();
#include "core/device/Backends.def"
#undef AXISTUNE_DRIVE_BACKEND

const std::vector<DriveBackend>& registeredBackends()
{
    static const std::vector<DriveBackend> k{
#define AXISTUNE_DRIVE_BACKEND(fn) fn(),
#include "core/device/Backends.def"
#undef AXISTUNE_DRIVE_BACKEND
    };
    return k;
}

const DriveBackend* findBackend(const std::string& uri)
{
    for (const auto& b : registeredBackends()) {
        if (uri.rfind(b.scheme, 0) == 0)
            return &b;
    }
    return nullptr;
}

std::string registeredUriForms()
{
    const auto& all = registeredBackends();
    std::string out;
    for (std::size_t i = 0; i < all.size(); ++i)
        out += (i == 0 ? "" : i + 1 == all.size() ? " or " : ", ") + all[i].uriForm;
    return out;
}

BackendSetting makeSetting(std::string name, std::string label, BackendSetting::Type type, std::string defaultValue,
                           std::string unit)
{
    BackendSetting s;
    s.name = std::move(name);
    s.label = std::move(label);
    s.type = type;
    s.defaultValue = std::move(defaultValue);
    s.unit = std::move(unit);
    return s;
}

void setFileSetting(DriveBackend& backend, std::string label, std::string hint)
{
    BackendSetting file = makeSetting("file", std::move(label), BackendSetting::Type::File);
    file.required = true;
    file.hint = std::move(hint);
    backend.settings = {file};
    backend.uriFromSettings = [b = backend](const SettingValues& v) -> Result<std::string> {
        if (auto st = checkSettings(b, v); !st)
            return st.error();
        return b.scheme + v.at("file");
    };
}

SettingValues defaultSettings(const DriveBackend& backend)
{
    SettingValues v;
    for (const auto& s : backend.settings)
        v[s.name] = s.defaultValue;
    return v;
}

Status checkSettings(const DriveBackend& backend, const SettingValues& values)
{
    for (const auto& s : backend.settings) {
        const auto it = values.find(s.name);
        const std::string v = it == values.end() ? std::string() : it->second;
        if (v.empty()) {
            if (s.required)
                return makeError(ErrorCode::BadInput, backend.label + ": " + s.label + " is required");
            continue;
        }
        if (s.type == BackendSetting::Type::Integer) {
            const auto n = model::parseInteger(v);
            if (!n || *n < s.minimum || *n > s.maximum)
                return makeError(ErrorCode::BadInput, backend.label + ": " + s.label + " '" + v +
                                                          "' must be a whole number in " + std::to_string(s.minimum) +
                                                          ".." + std::to_string(s.maximum));
        }
        if (s.type == BackendSetting::Type::Choice &&
            std::find(s.choices.begin(), s.choices.end(), v) == s.choices.end())
            return makeError(ErrorCode::BadInput,
                             backend.label + ": " + s.label + " '" + v + "' is not one of the choices");
    }
    return Status::success();
}

Result<SettingValues> parseUriQuery(const std::string& query)
{
    SettingValues out;
    std::size_t start = 0;
    while (start < query.size()) {
        const auto amp = query.find('&', start);
        const std::string item = query.substr(start, amp == std::string::npos ? std::string::npos : amp - start);
        const auto eq = item.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
            return makeError(ErrorCode::BadInput, "option '" + item + "' is not KEY=VALUE");
        out[item.substr(0, eq)] = item.substr(eq + 1);
        if (amp == std::string::npos)
            break;
        start = amp + 1;
    }
    return out;
}

Result<std::unique_ptr<Drive>> connect(const ConnectionSettings& settings)
{
    if (const auto* b = findBackend(settings.uri))
        return b->open(settings);
    return makeError(ErrorCode::BadInput,
                     "connection '" + settings.uri + "': unknown scheme; expected " + registeredUriForms());
}

const char* testTypeName(TestType t)
{
    switch (t) {
    case TestType::Step:
        return "step";
    case TestType::Jog:
        return "jog";
    case TestType::Hold:
        return "hold";
    case TestType::Frf:
        return "frf";
    case TestType::Circle:
        return "circle";
    case TestType::CurrentStep:
        return "current_step";
    }
    return "?";
}

static_assert(
    std::is_same_v<std::variant_alternative_t<static_cast<std::size_t>(TestType::CurrentStep), TestKind>,
                   CurrentStepTest> &&
        std::is_same_v<std::variant_alternative_t<static_cast<std::size_t>(TestType::Circle), TestKind>, CircleTest>,
    "TestKind's alternatives follow TestType's order");

TestKind testKindOf(TestType type)
{
    switch (type) {
    case TestType::Step:
        return StepTest{};
    case TestType::Jog:
        return JogTest{};
    case TestType::Hold:
        return HoldTest{};
    case TestType::Frf:
        return FrfTest{};
    case TestType::Circle:
        return CircleTest{};
    case TestType::CurrentStep:
        return CurrentStepTest{};
    }
    return StepTest{};
}

double recordOrDwellS(const TestRequest& r)
{
    switch (r.type()) {
    case TestType::Step:
        return r.step().recordS;
    case TestType::Jog:
        return r.jog().dwellS;
    case TestType::Hold:
        return r.hold().recordS;
    case TestType::CurrentStep:
        return r.currentStep().recordS;
    case TestType::Circle:
        return r.circle().dwellS;
    case TestType::Frf:
        break;
    }
    return 0.0;
}

bool DriveCapabilities::offers(TestType t) const
{
    return std::find(testTypes.begin(), testTypes.end(), t) != testTypes.end();
}

bool DriveCapabilities::offers(FrfMethod m) const
{
    return offers(TestType::Frf) && std::find(frfMethods.begin(), frfMethods.end(), m) != frfMethods.end();
}

bool isNcPositionPid(const DriveCapabilities& caps)
{
    return caps.frfPeakInOutputUnits && std::find(caps.frfQuantities.begin(), caps.frfQuantities.end(),
                                                  FrfQuantity::OpenLoop) != caps.frfQuantities.end();
}

} // namespace axistune::device

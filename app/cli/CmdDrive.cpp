// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli drive: what a drive says about itself (docs/cli.md "drive", docs/drive-seam.md):
// identity, and per axis its capabilities (tests, FRF methods, trace rates) and the limits it
// enforces; --list-backends prints the registered connection schemes with their settings.
#include "app/cli/CliCommand.h"
#include "core/device/DriveRegistry.h"
#include "core/device/FrfQuantityName.h"

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {
namespace {

struct DriveOptions {
    std::string connect = "sim:vmc";
    std::string axis;
    std::uint64_t seed = 1;
    bool listBackends = false;
};

/// A limit as JSON: a number, or null for "no limit of its own" (+inf; JSON has no infinity).
nlohmann::json limitJson(double v)
{
    return std::isinf(v) ? nlohmann::json(nullptr) : nlohmann::json(v);
}

const char* settingTypeName(device::BackendSetting::Type t)
{
    switch (t) {
    case device::BackendSetting::Type::Text:
        return "text";
    case device::BackendSetting::Type::Integer:
        return "integer";
    case device::BackendSetting::Type::Choice:
        return "choice";
    case device::BackendSetting::Type::File:
        return "file";
    }
    return "?";
}

int listBackends()
{
    nlohmann::json out = nlohmann::json::array();
    for (const auto& b : device::registeredBackends()) {
        nlohmann::json settings = nlohmann::json::array();
        for (const auto& s : b.settings) {
            nlohmann::json j{{"name", s.name},
                             {"label", s.label},
                             {"type", settingTypeName(s.type)},
                             {"default", s.defaultValue},
                             {"unit", s.unit},
                             {"required", s.required}};
            if (!s.choices.empty())
                j["choices"] = s.choices;
            if (s.type == device::BackendSetting::Type::Integer)
                j["range"] = {s.minimum, s.maximum};
            settings.push_back(j);
        }
        out.push_back({{"scheme", b.scheme},
                       {"uri", b.uriForm},
                       {"label", b.label},
                       {"description", b.description},
                       {"settings", settings}});
    }
    return writeJsonResult("drive", {{"backends", out}}, "");
}

int runDrive(const DriveOptions& o)
{
    const std::string cmd = "drive";
    if (o.listBackends)
        return listBackends();
    auto drive = device::connect({o.connect, o.seed});
    if (!drive)
        return reportError(cmd, drive.error());
    auto id = (*drive)->identify();
    if (!id)
        return reportError(cmd, id.error());
    std::vector<std::string> axes = id->axes;
    if (!o.axis.empty())
        axes = {o.axis};
    nlohmann::json axesJson = nlohmann::json::object();
    for (const auto& a : axes) {
        auto caps = (*drive)->capabilities(a);
        if (!caps)
            return reportError(cmd, caps.error());
        auto lim = (*drive)->limits(a);
        if (!lim)
            return reportError(cmd, lim.error());
        std::vector<std::string> tests, methods;
        for (const auto t : caps->testTypes)
            tests.emplace_back(device::testTypeName(t));
        std::vector<std::string> quantities;
        for (const auto q : caps->frfQuantities)
            quantities.emplace_back(device::frfQuantityMetadataName(q));
        for (const auto m : caps->frfMethods)
            methods.emplace_back(device::frfMethodName(m));
        axesJson[a] = {{"capabilities",
                        {{"tests", tests},
                         {"frf_methods", methods},
                         {"trace_rate_Hz", caps->traceRateHz},
                         {"current_trace_rate_Hz", caps->currentTraceRateHz},
                         {"evaluates_frf", caps->evaluatesFrf},
                         {"writes_parameters", caps->writesParameters},
                         {"has_link", caps->hasLink},
                         {"frf_peak_in_output_units", caps->frfPeakInOutputUnits},
                         {"jog_in_command_units", caps->jogInCommandUnits},
                         {"step_is_position_step", caps->stepIsPositionStep},
                         {"frf_quantities", quantities},
                         {"scope", caps->scope}}},
                       {"limits",
                        {{"frf_amplitude_max_pct", limitJson(lim->frfAmplitudeMaxPct)},
                         {"current_step_max_A", limitJson(lim->currentStepMaxA)},
                         {"current_step_max_s", limitJson(lim->currentStepMaxS)},
                         {"current_step_max_speed_rad_s", limitJson(lim->currentStepMaxSpeedRadS)},
                         {"motor_speed_max_rad_s", limitJson(lim->motorSpeedMaxRadS)},
                         {"test_duration_max_s", limitJson(lim->testDurationMaxS)},
                         {"travel_window", limitJson(lim->travelWindow)}}}};
        if (caps->scope) {
            // The scope's channels with their units (docs/scope.md): what `scope --channels` takes.
            auto sc = (*drive)->scopeCapabilities(a);
            if (!sc)
                return reportError(cmd, sc.error());
            nlohmann::json channels = nlohmann::json::array();
            for (const auto& c : sc->channels)
                channels.push_back({{"name", c.name}, {"unit", c.unit}, {"description", c.description}});
            axesJson[a]["scope"] = {{"fastest_rate_Hz", sc->fastestRateHz},
                                    {"max_channels", sc->maxChannels},
                                    {"max_divider", sc->maxDivider},
                                    {"max_values", sc->maxValues},
                                    {"ring_values", sc->ringValues},
                                    {"channels", channels}};
        }
    }
    nlohmann::json out{{"connection", o.connect},
                       {"identity",
                        {{"vendor", id->vendor},
                         {"model", id->model},
                         {"firmware", id->firmware},
                         {"machine", id->machine},
                         {"axes", id->axes}}},
                       {"axes", axesJson}};
    return writeJsonResult(cmd, out, "");
}

const CliRegistrar kRegistrar{
    {"drive", "Show what a drive says about itself: identity, capabilities and limits per axis", [](CLI::App& sub) {
         auto o = std::make_shared<DriveOptions>();
         sub.add_option("--connect", o->connect, connectOptionHelp())->capture_default_str();
         sub.add_option("--axis", o->axis, "only this axis (default: every axis)");
         sub.add_option("--seed", o->seed, "noise seed of an embedded simulated machine")->capture_default_str();
         sub.add_flag("--list-backends", o->listBackends,
                      "list the registered connection schemes with their settings instead (JSON)");
         return [o] { return runDrive(*o); };
     }}};

} // namespace
} // namespace axistune::cli

// SPDX-License-Identifier: GPL-3.0-or-later
// Registration of the embedded simulated drive, "sim:PRESET[?model=PATH&axis=NAME&fault=MODE]"
// (DriveRegistry.h, docs/drive-seam.md).
#include "core/device/DriveRegistry.h"
#include "core/device/SimulatedDrive.h"
#include "core/sim/IdentifiedPlant.h"
#include "core/sim/MachineDefinition.h"

namespace axistune::device {
namespace {

// "model=PATH[&axis=NAME]": the identified rigid-body model of `axistune-cli identify` as the
// plant of one axis (docs/identification.md "Using the result"). The axis may be left out when the
// machine has one axis of the model's kind.
Status applyIdentifiedModel(sim::MachineDefinition& def, const std::string& modelPath, const std::string& axisName)
{
    auto m = ident::readIdentifiedModelFile(modelPath);
    if (!m)
        return m.error();
    const auto kind = m->motion == ident::AxisMotion::Linear ? sim::AxisKind::Linear : sim::AxisKind::Rotary;
    sim::AxisDefinition* target = nullptr;
    int candidates = 0;
    for (auto& a : def.axes) {
        if (axisName.empty() ? a.kind == kind : a.name == axisName) {
            target = &a;
            ++candidates;
        }
    }
    if (target == nullptr)
        return makeError(ErrorCode::NotFound, axisName.empty() ? "no axis of the model's kind on machine " + def.name
                                                               : "no axis '" + axisName + "' on machine " + def.name);
    if (candidates > 1)
        return makeError(ErrorCode::BadInput, "machine " + def.name + " has several such axes: give axis=NAME");
    return sim::applyIdentifiedModel(*target, *m, modelPath);
}

Result<std::unique_ptr<Drive>> openSim(const ConnectionSettings& settings)
{
    const std::string rest = settings.uri.substr(4);
    const auto q = rest.find('?');
    auto fail = [&](const Error& e) { return makeError(e.code, "connection '" + settings.uri + "': " + e.detail); };
    auto preset = sim::loadPreset(rest.substr(0, q));
    if (!preset)
        return fail(preset.error());
    sim::MachineDefinition def = *preset;
    SettingValues options;
    if (q != std::string::npos) {
        auto parsed = parseUriQuery(rest.substr(q + 1));
        if (!parsed)
            return fail(
                Error{ErrorCode::BadInput, parsed.error().detail + " (expected model=PATH, axis=NAME, fault=MODE)"});
        options = *parsed;
    }
    FaultInjection faults;
    for (const auto& [k, v] : options) {
        if (k != "model" && k != "axis" && k != "fault")
            return fail(Error{ErrorCode::BadInput, "unknown or empty option '" + k + "=" + v +
                                                       "' (expected model=PATH, axis=NAME, fault=MODE)"});
        if (k == "fault") {
            if (auto st = addFaultMode(faults, v); !st)
                return fail(st.error());
            if (faults.delayMs > 0 || faults.illegalAddress || faults.driveFaultAfterS >= 0)
                return fail(
                    Error{ErrorCode::BadInput, "fault '" + v + "': the embedded drive injects drop-after:N only"});
        }
    }
    if (options.count("axis") && !options.count("model"))
        return fail(Error{ErrorCode::BadInput, "axis=NAME needs model=PATH"});
    if (options.count("model")) {
        if (auto st = applyIdentifiedModel(def, options["model"], options.count("axis") ? options["axis"] : ""); !st)
            return fail(st.error());
    }
    auto d = SimulatedDrive::create(def, settings.seed);
    if (!d)
        return d.error();
    (*d)->setFaults(faults);
    return std::unique_ptr<Drive>(std::move(d).value());
}

} // namespace

DriveBackend simBackend()
{
    DriveBackend b;
    b.scheme = "sim:";
    b.label = AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "Built-in simulated machine");
    b.uriForm = "sim:PRESET[?model=PATH&axis=NAME]";
    b.description = AXISTUNE_TRANSLATE_NOOP(
        "DriveRegistry", "The embedded simulated drive on a machine preset (docs/simulator.md); model=PATH puts an "
                         "identified rigid-body model in place of one axis's plant.");
    b.usesSeed = true;
    BackendSetting preset = makeSetting("preset", AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "Machine preset"),
                                        BackendSetting::Type::Choice, "vmc");
    preset.choices = sim::presetNames();
    preset.required = true;
    BackendSetting model = makeSetting("model", AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "Identified model (optional)"),
                                       BackendSetting::Type::File);
    model.hint = AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "result JSON of Identify from motion");
    BackendSetting axis =
        makeSetting("axis", AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "Axis of the model"), BackendSetting::Type::Text);
    b.settings = {preset, model, axis};
    b.uriFromSettings = [b](const SettingValues& v) -> Result<std::string> {
        if (auto st = checkSettings(b, v); !st)
            return st.error();
        std::string u = "sim:" + v.at("preset");
        const std::string m = v.count("model") ? v.at("model") : "", a = v.count("axis") ? v.at("axis") : "";
        if (!m.empty())
            u += "?model=" + m + (a.empty() ? "" : "&axis=" + a);
        return u;
    };
    b.open = openSim;
    return b;
}

} // namespace axistune::device

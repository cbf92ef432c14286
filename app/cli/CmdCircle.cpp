// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli circle: a ball-bar circle test, written as a ball-bar CSV (docs/ballbar.md "Simulated
// circle tests"); also reachable as `capture --test circle`. On sim:PRESET it runs core/sim/CircleTest
// on the preset; on modbus://HOST:PORT it is a Circle test of the drive (docs/ballbar.md "Circle tests
// through the drive"), the trace of both axes evaluated here.
#include "app/cli/CircleCommand.h"
#include "app/cli/CliCommand.h"
#include "core/device/CircleDriveTest.h"
#include "core/device/Drive.h"
#include "core/device/TestRunner.h"
#include "core/io/BallBarCsv.h"
#include "core/io/CaptureCsv.h"
#include "core/model/CircleDirectionName.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/model/Parameter.h"
#include "core/sim/AxisParameters.h"
#include "core/sim/CircleTest.h"
#include "core/sim/MachineDefinition.h"

#include <iostream>
#include <memory>

namespace axistune::cli {
sim::CircleTestOptions circleOptions(const CircleCliOptions& o)
{
    sim::CircleTestOptions c;
    c.axisX = o.plane.substr(0, 1);
    c.axisY = o.plane.substr(1, 1);
    c.radiusM = o.radiusMm * 1e-3;
    c.feedMPerS = o.feedMmMin / 60000.0;
    c.direction = model::circleDirectionFromName(o.direction).value_or(model::CircleDirection::Ccw); // CLI11 checked it
    c.centerXM = o.centerXMm * 1e-3;
    c.centerYM = o.centerYMm * 1e-3;
    c.squarenessPerM = o.squarenessUmPerM * 1e-6;
    c.scaleX = o.scaleXPpm * 1e-6;
    c.scaleY = o.scaleYPpm * 1e-6;
    c.leadArcDeg = o.leadArcDeg;
    c.dataStartDeg = o.startDeg;
    c.seed = o.seed;
    return c;
}

namespace {

struct SetItem {
    std::vector<std::string> axes;
    std::string key;
    double value = 0.0;
};

/// "X:lostmotion.mode=2" (or "lostmotion.mode=2" for both plane axes).
Result<SetItem> parseSet(const std::string& item, const std::string& plane)
{
    const auto eq = item.find('=');
    if (eq == std::string::npos)
        return makeError(ErrorCode::BadInput, "--set '" + item + "': expected AXIS:KEY=VALUE");
    SetItem out;
    out.key = item.substr(0, eq);
    if (const auto colon = out.key.find(':'); colon != std::string::npos) {
        out.axes.push_back(out.key.substr(0, colon));
        out.key = out.key.substr(colon + 1);
    } else {
        out.axes = {plane.substr(0, 1), plane.substr(1, 1)};
    }
    const auto v = model::parseNumber(std::string_view(item).substr(eq + 1));
    if (!v)
        return makeError(ErrorCode::BadInput, "--set '" + item + "': value is not a number");
    out.value = *v;
    return out;
}

} // namespace

Result<DriveCircle> measureCircleOnDrive(device::Drive& drive, const sim::CircleTestOptions& c)
{
    auto run = device::runTest(drive, device::circleRequestOf(c));
    if (!run)
        return run.error();
    auto& trace = run->trace;
    auto res = sim::evaluateCircleTrace(*trace, c);
    if (!res)
        return res.error();
    return DriveCircle{std::move(*trace), std::move(res).value()};
}

namespace {

/// The circle through a drive (modbus://): --set written to the drive, one Circle test, the trace
/// evaluated on this side. Injected geometric errors and the second servo trace are simulator-only.
int runCircleOnDrive(const CircleCliOptions& o, const sim::CircleTestOptions& c)
{
    const std::string cmd = "circle";
    if (c.squarenessPerM != 0.0 || c.scaleX != 0.0 || c.scaleY != 0.0 || !o.servoOutY.empty())
        return reportError(cmd, makeError(ErrorCode::BadInput, "--connect '" + o.connect +
                                                                   "': injected geometric errors and --servo-out-y "
                                                                   "are for sim: connections only"));
    auto drive = device::connect({o.connect, o.seed});
    if (!drive)
        return reportError(cmd, drive.error());
    for (const auto& item : o.sets) {
        auto set = parseSet(item, o.plane);
        if (!set)
            return reportError(cmd, set.error());
        for (const auto& axis : set->axes)
            if (auto st = (*drive)->writeParameters(axis, {{set->key, set->value}}); !st)
                return reportError(cmd, makeError(st.error().code, "--set '" + item + "': " + st.error().detail));
    }
    auto measured = measureCircleOnDrive(**drive, c);
    if (!measured)
        return reportError(cmd, measured.error());
    auto& res = measured->result;
    auto& trace = measured->trace;
    model::BallBarTrace bb = res.ballbar;
    bb.metadata.set(model::meta::kConnection, o.connect);
    if (auto st = io::writeBallBarCsvFile(o.out, bb); !st)
        return reportError(cmd, st.error());
    if (!o.servoOutX.empty())
        if (auto st = io::writeCaptureCsvFile(o.servoOutX, trace); !st)
            return reportError(cmd, st.error());
    std::cout << "{\"out\": \"" << o.out << "\", \"samples\": " << bb.size() << ", \"dT_x_Nm\": " << res.dTxNm
              << ", \"dT_y_Nm\": " << res.dTyNm << "}\n";
    return 0;
}

/// "X:lostmotion.mode=2" (or "lostmotion.mode=2" for both plane axes), range-checked against the metadata.
Status applySet(sim::MachineDefinition& m, const std::string& item, const std::string& plane)
{
    auto set = parseSet(item, plane);
    if (!set)
        return set.error();
    const std::string& key = set->key;
    const double value = set->value;
    for (const auto& name : set->axes) {
        sim::AxisDefinition* axis = nullptr;
        for (auto& a : m.axes)
            if (a.name == name)
                axis = &a;
        if (!axis)
            return makeError(ErrorCode::BadInput, "--set '" + item + "': machine has no axis '" + name + "'");
        const auto* meta = model::findParameter(sim::axisParameterMetas(axis->kind), key);
        if (!meta)
            return makeError(ErrorCode::BadInput, "--set '" + item + "': unknown parameter '" + key + "'");
        if (auto st = model::checkParameterValue(*meta, value); !st)
            return makeError(ErrorCode::BadInput, "--set '" + item + "': " + st.error().detail);
        axis->values[key] = value;
    }
    return Status::success();
}

} // namespace

int runCircle(const CircleCliOptions& o)
{
    const std::string cmd = "circle";
    if (o.connect.rfind("modbus://", 0) == 0) {
        if (o.plane.size() != 2)
            return reportError(cmd, makeError(ErrorCode::BadInput, "--plane '" + o.plane + "': two axis letters, e.g. XY"));
        return runCircleOnDrive(o, circleOptions(o));
    }
    if (o.connect.rfind("sim:", 0) != 0)
        return reportError(
            cmd, makeError(ErrorCode::BadInput,
                           "--connect '" + o.connect + "': expected sim:PRESET or modbus://HOST:PORT"));
    auto loaded = sim::loadPreset(o.connect.substr(4));
    if (!loaded)
        return reportError(cmd, makeError(ErrorCode::BadInput, loaded.error().detail));
    sim::MachineDefinition machine = *loaded;
    if (o.plane.size() != 2)
        return reportError(cmd, makeError(ErrorCode::BadInput, "--plane '" + o.plane + "': two axis letters, e.g. XY"));
    for (const auto& s : o.sets)
        if (auto st = applySet(machine, s, o.plane); !st)
            return reportError(cmd, st.error());
    const sim::CircleTestOptions c = circleOptions(o);
    auto ran = sim::runCircleTest(machine, c);
    if (!ran)
        return reportError(cmd, ran.error());
    sim::CircleTestResult result = *ran;
    auto* res = &result;
    res->ballbar.metadata.set(model::meta::kConnection, o.connect);
    if (auto st = io::writeBallBarCsvFile(o.out, res->ballbar); !st)
        return reportError(cmd, st.error());
    if (!o.servoOutX.empty())
        if (auto st = io::writeCaptureCsvFile(o.servoOutX, res->traceX); !st)
            return reportError(cmd, st.error());
    if (!o.servoOutY.empty())
        if (auto st = io::writeCaptureCsvFile(o.servoOutY, res->traceY); !st)
            return reportError(cmd, st.error());
    std::cout << "{\"out\": \"" << o.out << "\", \"samples\": " << res->ballbar.size()
              << ", \"dT_x_Nm\": " << res->dTxNm << ", \"dT_y_Nm\": " << res->dTyNm << "}\n";
    return 0;
}

namespace {

const CliRegistrar kRegistrar{
    {"circle", "Ball-bar circle test (simulated machine or a drive), written as a ball-bar CSV", [](CLI::App& sub) {
         auto o = std::make_shared<CircleCliOptions>();
         sub.add_option("--connect", o->connect, connectOptionHelp() + "; two linear axes (sim:vmc)")
             ->capture_default_str();
         sub.add_option("--plane", o->plane, "the two axes, first = x role")->capture_default_str();
         sub.add_option("--radius-mm", o->radiusMm, "circle radius [mm]")
             ->capture_default_str()
             ->check(CLI::PositiveNumber);
         sub.add_option("--feed-mm-min", o->feedMmMin, "feed [mm/min]")
             ->capture_default_str()
             ->check(CLI::PositiveNumber);
         sub.add_option("--direction", o->direction, "ccw | cw")
             ->capture_default_str()
             ->check(CLI::IsMember({"ccw", "cw"}));
         sub.add_option("--center-x-mm", o->centerXMm, "circle centre, first axis [mm]")->capture_default_str();
         sub.add_option("--center-y-mm", o->centerYMm, "circle centre, second axis [mm]")->capture_default_str();
         sub.add_option("--squareness-um-per-m", o->squarenessUmPerM, "injected squareness (angle below 90 deg > 0)");
         sub.add_option("--scale-x-ppm", o->scaleXPpm, "injected scale error of the first axis [ppm]");
         sub.add_option("--scale-y-ppm", o->scaleYPpm, "injected scale error of the second axis [ppm]");
         sub.add_option("--lead-arc-deg", o->leadArcDeg, "lead-in and lead-out arc [deg]")->capture_default_str();
         sub.add_option("--start-deg", o->startDeg, "angle where the 360 deg data arc starts")->capture_default_str();
         sub.add_option("--set", o->sets,
                        "AXIS:KEY=VALUE drive parameter in SI, e.g. Y:lostmotion.mode=2 (repeatable)");
         sub.add_option("--seed", o->seed, "noise seed")->capture_default_str();
         sub.add_option("--servo-out-x", o->servoOutX, "servo trace of the first axis (capture CSV)");
         sub.add_option("--servo-out-y", o->servoOutY, "servo trace of the second axis (capture CSV)");
         sub.add_option("--out", o->out, "ball-bar CSV to write")->required();
         return [o] { return runCircle(*o); };
     }}};

} // namespace
} // namespace axistune::cli

// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli capture: runs a test on a drive and writes the trace as a capture CSV.
#include "app/cli/CliCommand.h"
#include "core/device/Drive.h"
#include "core/io/CaptureCsv.h"

#include <iostream>
#include <memory>

namespace axistune::cli {
namespace {

struct CaptureOptions {
    std::string connect = "sim:vmc";
    std::string axis;
    std::string test = "step";
    double amplitude = 0.0;
    double distance = 0.0;
    double velocity = 0.0;
    double acceleration = 1.0;
    bool back = false;
    double duration = 0.2;
    int divider = 0;
    std::uint64_t seed = 1;
    std::string out;
};

int runCapture(const CaptureOptions& o)
{
    const std::string cmd = "capture";
    auto drive = device::connect({o.connect, o.seed});
    if (!drive)
        return reportError(cmd, drive.error());
    device::TestRequest req;
    req.axis = o.axis;
    req.durationS = o.duration;
    req.traceDivider = o.divider;
    if (o.test == "step") {
        req.type = device::TestType::Step;
        req.amplitude = o.amplitude;
    } else if (o.test == "jog") {
        req.type = device::TestType::Jog;
        req.distance = o.distance;
        req.velocity = o.velocity;
        req.acceleration = o.acceleration;
        req.returnToStart = o.back;
    } else if (o.test == "hold") {
        req.type = device::TestType::Hold;
    } else {
        return reportError(cmd, makeError(ErrorCode::BadInput, "--test must be step, jog or hold (got '" + o.test + "')"));
    }
    if (auto st = (*drive)->startTest(req); !st)
        return reportError(cmd, st.error());
    while (true) {
        auto status = (*drive)->pollTest();
        if (!status)
            return reportError(cmd, status.error());
        if (status->state == device::TestState::Completed)
            break;
        if (status->state != device::TestState::Running)
            return reportError(cmd, makeError(ErrorCode::Safety, std::string("test ") + device::testStateName(status->state)
                                                                     + ": " + status->detail));
    }
    auto trace = (*drive)->readTrace();
    if (!trace)
        return reportError(cmd, trace.error());
    auto cap = std::move(trace).value();
    cap.metadata["test"] = o.test;
    cap.metadata["connection"] = o.connect;
    if (auto st = io::writeCaptureCsvFile(o.out, cap); !st)
        return reportError(cmd, st.error());
    std::cout << "{\"out\": \"" << o.out << "\", \"samples\": " << cap.size() << ", \"fs_Hz\": " << cap.metadata["fs_Hz"]
              << "}\n";
    return 0;
}

const CliRegistrar kRegistrar{{"capture", "Run a test on a drive and write the trace as a capture CSV",
    [](CLI::App& sub) {
        auto o = std::make_shared<CaptureOptions>();
        sub.add_option("--connect", o->connect, "sim:PRESET (vmc, dd-table, two-inertia)")->capture_default_str();
        sub.add_option("--axis", o->axis, "axis name, e.g. X")->required();
        sub.add_option("--test", o->test, "step | jog | hold")->capture_default_str();
        sub.add_option("--amplitude", o->amplitude, "step: motor velocity step [rad/s]");
        sub.add_option("--distance", o->distance, "jog: distance [m or rad]");
        sub.add_option("--velocity", o->velocity, "jog: velocity [m/s or rad/s]");
        sub.add_option("--acceleration", o->acceleration, "jog: acceleration [m/s^2 or rad/s^2]")->capture_default_str();
        sub.add_flag("--back", o->back, "jog: return to the start (a reversal)");
        sub.add_option("--duration", o->duration, "step/hold: recording length; jog: dwell before and after [s]")
            ->capture_default_str();
        sub.add_option("--trace-divider", o->divider, "trace every N velocity periods (0: drive setting)");
        sub.add_option("--seed", o->seed, "noise seed of the simulated machine")->capture_default_str();
        sub.add_option("--out", o->out, "capture CSV to write")->required();
        return [o] { return runCapture(*o); };
    }}};

}  // namespace
}  // namespace axistune::cli

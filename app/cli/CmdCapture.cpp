// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli capture: runs a test on a drive and writes the trace as a capture CSV.
#include "app/cli/CircleCommand.h"
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/device/AdaptiveFrf.h"
#include "core/device/AdaptiveFrfJson.h"
#include "core/device/Drive.h"
#include "core/device/FrfQuantityName.h"
#include "core/device/MoveTo.h"
#include "core/device/MultisineTest.h"
#include "core/device/SimulatedDrive.h"
#include "core/device/TestRunner.h"
#include "core/io/CaptureCsv.h"
#include "core/io/FrfCsv.h"
#include "core/io/SweepCsv.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

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
    // --test frf
    std::string method = "multisweep";
    double fmin = 10.0;
    double fmax = 3900.0;
    int points = 60;
    double amplitudePct = 5.0;
    std::string quantity = "default";
    double settle = 0.0;
    double minMeasure = 0.0;
    std::string sweepOut;
    std::string traceOut;
    // --method multisine (docs/multisine.md)
    double spacing = 0.0;
    std::vector<std::string> bands;
    int periods = 0;
    std::string phases = "clipping";
    std::string shapeFrom;
    double shapeRangeDb = 20.0;
    bool adaptive = false;    ///< re-excite the invalid lines (core/device/AdaptiveFrf.h)
    double timeBudgetS = 5.0; ///< --adaptive: motion time of all passes
    // Parameters written before the test, and the simulator's linear switch (test/diagnostic).
    std::vector<std::string> set;
    bool linear = false;
    CircleCliOptions circle;  ///< --test circle
    std::string at;           ///< --at: move the axis there first (device::moveAxisTo)
};

/// Parses the --set KEY=VALUE options (VALUE a number in SI units) and checks each key and value
/// against the axis's parameter metadata: unknown, read-only or out-of-range → BadInput (exit 2).
Result<model::ParameterValues> parseSets(device::Drive& drive, const std::string& axis, const std::vector<std::string>& sets)
{
    model::ParameterValues v;
    if (sets.empty())
        return v;
    auto metas = drive.parameterMetadata(axis);
    if (!metas)
        return metas.error();
    for (const auto& s : sets) {
        const auto eq = s.find('=');
        const auto parsed =
            eq == std::string::npos ? std::nullopt : model::parseNumber(std::string_view(s).substr(eq + 1));
        if (eq == std::string::npos || eq == 0 || !parsed)
            return makeError(ErrorCode::BadInput, "--set '" + s + "': expected KEY=VALUE with VALUE a number in SI units");
        const double x = *parsed;
        const std::string key = s.substr(0, eq);
        const auto* meta = model::findParameter(*metas, key);
        if (!meta || !meta->writable)
            return makeError(ErrorCode::BadInput, "--set '" + s + "': axis " + axis + " has no writable parameter '" + key + "'");
        if (auto st = model::checkParameterValue(*meta, x); !st)
            return makeError(ErrorCode::BadInput, "--set '" + s + "': " + st.error().detail);
        v[key] = x;
    }
    return v;
}

/// Applies --set and --linear before the test.
Status prepareDrive(device::Drive& drive, const CaptureOptions& o)
{
    auto sets = parseSets(drive, o.axis, o.set);
    if (!sets)
        return sets.error();
    if (!sets->empty()) {
        if (auto st = drive.writeParameters(o.axis, *sets); !st)
            return makeError(ErrorCode::BadInput, "--set: " + st.error().detail);
    }
    if (o.linear) {
        auto* simDrive = dynamic_cast<device::SimulatedDrive*>(&drive);
        sim::AxisSimulator* sim = simDrive ? simDrive->simulator(o.axis) : nullptr;
        if (!sim)
            return makeError(ErrorCode::BadInput, "--linear needs a simulated drive (sim:PRESET) and one of its axes");
        sim->setNonlinearities({false, false, false, false, false});
    }
    return {};
}

bool parseDouble(const std::string& s, double& x)
{
    const auto v = model::parseNumber(s);
    if (v)
        x = *v;
    return v.has_value();
}

/// The multisine fields of the request from --band, --spacing-hz, --periods, --phases, --shape-from.
/// The shape from a previous FRF: relative amplitude ∝ 1/|H| (more excitation where the loop answers
/// less), limited to a range of shapeRangeDb below the largest weight.
Status multisineRequest(const CaptureOptions& o, device::FrfTest& req)
{
    const bool multisine = o.method == "multisine";
    if (!multisine) {
        if (!o.bands.empty() || o.spacing != 0.0 || o.periods != 0 || !o.shapeFrom.empty() || o.phases != "clipping")
            return makeError(ErrorCode::BadInput, "--band, --spacing-hz, --periods, --phases and --shape-from are only for --method multisine");
        return Status::success();
    }
    for (const auto& b : o.bands) {
        dsp::MultisineBand band;
        const auto c1 = b.find(':'), c2 = c1 == std::string::npos ? c1 : b.find(':', c1 + 1);
        if (c2 == std::string::npos || !parseDouble(b.substr(0, c1), band.fminHz)
            || !parseDouble(b.substr(c1 + 1, c2 - c1 - 1), band.fmaxHz) || !parseDouble(b.substr(c2 + 1), band.spacingHz))
            return makeError(ErrorCode::BadInput, "--band '" + b + "': expected FMIN:FMAX:SPACING in Hz");
        req.multisineBands.push_back(band);
    }
    if (!(o.spacing >= 0.0))
        return makeError(ErrorCode::BadInput, "--spacing-hz must not be negative");
    if (o.periods < 0 || o.periods > device::kMaxMultisinePeriods)
        return makeError(ErrorCode::BadInput, "--periods must lie in [1, " + std::to_string(device::kMaxMultisinePeriods) + "] (0: from the loop)");
    if (o.phases != "clipping" && o.phases != "schroeder")
        return makeError(ErrorCode::BadInput, "--phases must be clipping or schroeder (got '" + o.phases + "')");
    req.multisineSpacingHz = o.spacing;
    req.multisinePeriods = o.periods;
    req.multisinePhases = o.phases == "schroeder" ? dsp::MultisinePhases::Schroeder : dsp::MultisinePhases::Clipping;
    if (!o.shapeFrom.empty()) {
        if (!(o.shapeRangeDb > 0.0))
            return makeError(ErrorCode::BadInput, "--shape-range-db must be positive");
        auto frf = io::readFrfCsvFile(o.shapeFrom);
        if (!frf)
            return makeError(ErrorCode::BadInput, "--shape-from: " + frf.error().detail);
        double top = 0.0;
        for (std::size_t i = 0; i < frf->size(); ++i) {
            if (frf->valid[i] && std::abs(frf->h[i]) > 0.0) {
                req.multisineShape.emplace_back(frf->freqHz[i], 1.0 / std::abs(frf->h[i]));
                top = std::max(top, req.multisineShape.back().second);
            }
        }
        if (req.multisineShape.empty())
            return makeError(ErrorCode::BadInput, "--shape-from " + o.shapeFrom + ": no valid point with a nonzero response");
        const double floor = top * std::pow(10.0, -o.shapeRangeDb / 20.0);
        for (auto& [f, w] : req.multisineShape)
            w = std::max(w, floor) / top;
    }
    return Status::success();
}

/// Writes the FRF (and the sine-stream recording) of a completed FRF test; prints a JSON summary.
int writeFrfResult(const std::string& cmd, device::FrfMeasurement measurement, const CaptureOptions& o,
                   const device::AdaptiveFrfResult* adaptive = nullptr)
{
    auto m = std::make_unique<device::FrfMeasurement>(std::move(measurement));
    m->frf.metadata.set(model::meta::kConnection, o.connect);
    if (auto st = io::writeFrfCsvFile(o.out, m->frf); !st)
        return reportError(cmd, st.error());
    if (!o.sweepOut.empty()) {
        if (m->sweep.blocks.empty())
            return reportError(cmd, makeError(ErrorCode::BadInput, "--sweep-out needs a sine-stream method (multisweep or conventional)"));
        if (auto st = io::writeSweepCsvFile(o.sweepOut, m->sweep); !st)
            return reportError(cmd, st.error());
    }
    std::size_t valid = 0;
    for (bool v : m->frf.valid)
        valid += v ? 1 : 0;
    std::cout << "{\"out\": \"" << o.out << "\", \"method\": \"" << o.method << "\", \"points\": " << m->frf.size()
              << ", \"valid_points\": " << valid << ", \"motion_time_s\": " << m->motionTimeS;
    // Numbers of the drive's metadata, those it gave (hal: states its amplitude in the PID output's units).
    for (const char* key : {"amplitude_Nm", "amplitude_peak", "fs_Hz", "crest_factor", "rms_Nm", "amplitude_rms",
                            "spacing_Hz", "periods", "settle_s"}) {
        if (const auto* v = m->frf.metadata.find(key); v && v->number())
            std::cout << ", \"" << key << "\": " << v->text();
    }
    if (adaptive)
        std::cout << ", \"adaptive\": " << device::adaptiveFrfJson(*adaptive, o.timeBudgetS).dump();
    if (const auto* q = m->frf.metadata.find(model::meta::kQuantity))
        std::cout << ", \"quantity\": \"" << q->text() << "\"";
    std::cout << "}\n";
    return 0;
}

int runCapture(const CaptureOptions& o)
{
    if (o.test == "circle") {
        if (o.linear)
            return reportError("capture", makeError(ErrorCode::BadInput, "--linear is not available for --test circle"));
        CircleCliOptions c = o.circle;
        c.connect = o.connect;
        c.seed = o.seed;
        c.out = o.out;
        c.sets = o.set;
        return runCircle(c);
    }
    if (o.axis.empty())
        return reportError("capture", makeError(ErrorCode::BadInput, "--axis is required for --test " + o.test));
    const std::string cmd = "capture";
    auto drive = device::connect({o.connect, o.seed});
    if (!drive)
        return reportError(cmd, drive.error());
    device::TestRequest req;
    req.axis = o.axis;
    req.traceDivider = o.divider;
    if (o.test == "step") {
        auto& s = req.test.emplace<device::StepTest>();
        s.velocityRadS = o.amplitude;
        s.recordS = o.duration;
    } else if (o.test == "jog") {
        auto& j = req.test.emplace<device::JogTest>();
        j.distance = o.distance;
        j.velocity = o.velocity;
        j.acceleration = o.acceleration;
        j.returnToStart = o.back;
        j.dwellS = o.duration;
    } else if (o.test == "hold") {
        req.test.emplace<device::HoldTest>().recordS = o.duration;
    } else if (o.test == "current-step") {
        auto& c = req.test.emplace<device::CurrentStepTest>();
        c.currentA = o.amplitude;
        c.recordS = o.duration;
    } else if (o.test == "frf") {
        auto& f = req.test.emplace<device::FrfTest>();
        if (o.method == "multisweep")
            f.method = device::FrfMethod::MultiSweep;
        else if (o.method == "conventional")
            f.method = device::FrfMethod::Conventional;
        else if (o.method == "prbs")
            f.method = device::FrfMethod::Prbs;
        else if (o.method == "multisine")
            f.method = device::FrfMethod::Multisine;
        else
            return reportError(cmd, makeError(ErrorCode::BadInput, "--method must be multisweep, conventional, prbs or multisine (got '"
                                                                       + o.method + "')"));
        if (auto st = multisineRequest(o, f); !st)
            return reportError(cmd, st.error());
        f.fminHz = o.fmin;
        f.fmaxHz = o.fmax;
        f.points = o.points;
        f.amplitudePct = o.amplitudePct;
        f.amplitudePeak = o.amplitude; // 0 unless given: the peak in the injection point's own units (hal:)
        if (const auto q = device::frfQuantityFromMetadataName(o.quantity))
            f.quantity = *q;
        else
            return reportError(cmd, makeError(ErrorCode::BadInput, "--quantity must be default, plant or open-loop (got '" +
                                                                       o.quantity + "')"));
        f.settleS = o.settle;
        f.minMeasureS = o.minMeasure;
    } else {
        return reportError(cmd, makeError(ErrorCode::BadInput, "--test must be step, jog, hold, current-step, frf or circle (got '" + o.test + "')"));
    }
    if (o.adaptive && (o.test != "frf" || o.method != "multisine"))
        return reportError(cmd, makeError(ErrorCode::BadInput, "--adaptive is only for --test frf --method multisine"));
    if (!o.adaptive && o.timeBudgetS != 5.0)
        return reportError(cmd, makeError(ErrorCode::BadInput, "--time-budget is only for --adaptive"));
    if (o.adaptive && !(o.timeBudgetS > 0.0 && std::isfinite(o.timeBudgetS)))
        return reportError(cmd, makeError(ErrorCode::BadInput, "--time-budget must be > 0 s"));
    if (o.adaptive && !o.traceOut.empty())
        return reportError(
            cmd, makeError(ErrorCode::BadInput, "--trace-out is not available with --adaptive (one trace per pass)"));
    if (o.adaptive && !o.shapeFrom.empty())
        return reportError(cmd, makeError(ErrorCode::BadInput,
                                          "--shape-from is not available with --adaptive (it shapes each "
                                          "pass from what it measured)"));
    if (o.test != "frf" && !o.sweepOut.empty())
        return reportError(cmd, makeError(ErrorCode::BadInput, "--sweep-out is only for --test frf"));
    if (!o.at.empty()) {
        // --at: the axis moves there first by a jog the drive checks (device/MoveTo.h), with the parameters as found.
        const auto x = model::parseNumber(o.at);
        if (!x || !std::isfinite(*x))
            return reportError(cmd, makeError(ErrorCode::BadInput, "--at: '" + o.at + "' is not a number"));
        if (o.test == "circle" || o.test == "jog")
            return reportError(cmd, makeError(ErrorCode::BadInput, "--at is not available for --test " + o.test));
        auto moved = device::moveAxisTo(**drive, o.axis, *x);
        if (!moved)
            return reportError(cmd, makeError(moved.error().code, "--at: " + moved.error().detail));
        std::cerr << "axistune-cli capture: axis " << o.axis << " moved from " << model::formatNumber(moved->from, 6)
                  << " to " << model::formatNumber(moved->to, 6) << (moved->linear ? " m" : " rad") << " ("
                  << model::formatNumber(moved->motionTimeS, 3) << " s of motion)\n";
    }
    if (auto st = prepareDrive(**drive, o); !st)
        return reportError(cmd, st.error());
    if (req.type() == device::TestType::Step) {
        // On a drive whose step is a position step of the command (hal:), --amplitude is that step in the command's
        // units (docs/cli.md); elsewhere a motor velocity step.
        if (auto caps = (*drive)->capabilities(o.axis); caps && caps->stepIsPositionStep)
            std::swap(req.step().position, req.step().velocityRadS);
    }
    // The drive plans the test first (Drive::planTest): a request beyond its limits is refused with the
    // drive's own words before anything moves, and the planned motion time is reported.
    auto plan = (*drive)->planTest(req);
    if (!plan)
        return reportError(cmd, plan.error());
    device::RunOptions run;
    if (o.adaptive) {
        device::AdaptiveFrfOptions ao;
        ao.timeBudgetS = o.timeBudgetS;
        auto res = device::runAdaptiveFrf(**drive, req, ao, run);
        if (!res)
            return reportError(cmd, res.error());
        auto m = res->measurement;
        return writeFrfResult(cmd, std::move(m), o, &*res);
    }
    run.readTrace = o.test != "frf" || !o.traceOut.empty();
    auto done = device::runTest(**drive, req, run);
    if (!done)
        return reportError(cmd, done.error());
    if (o.test == "frf") {
        if (!o.traceOut.empty()) {
            if (auto st = io::writeCaptureCsvFile(o.traceOut, *done->trace); !st)
                return reportError(cmd, st.error());
        }
        return writeFrfResult(cmd, std::move(*done->frf), o);
    }
    auto cap = std::move(*done->trace);
    cap.metadata.set(model::meta::kTest, o.test);
    cap.metadata.set(model::meta::kConnection, o.connect);
    if (auto st = io::writeCaptureCsvFile(o.out, cap); !st)
        return reportError(cmd, st.error());
    std::cout << "{\"out\": \"" << o.out << "\", \"samples\": " << cap.size()
              << ", \"fs_Hz\": " << cap.metadata.textOr(model::meta::kFsHz, "")
              << ", \"planned_motion_s\": " << model::formatNumber(plan->motionTimeS, 10)
              << ", \"planned_samples\": " << plan->recordSamples << "}\n";
    return 0;
}

const CliRegistrar kRegistrar{{"capture", "Run a test on a drive and write the trace as a capture CSV",
    [](CLI::App& sub) {
        auto o = std::make_shared<CaptureOptions>();
        sub.add_option("--connect", o->connect, connectOptionHelp())->capture_default_str();
        sub.add_option("--axis", o->axis, "axis name, e.g. X (all tests but circle)");
        sub.add_option("--test", o->test, "step | jog | hold | current-step | frf | circle")->capture_default_str();
        sub.add_option("--amplitude", o->amplitude, "step: motor velocity step [rad/s]; current-step: q-axis current step [A]; "
                                                    "frf on hal:: the multisine's peak in the PID output's units (instead of --amplitude-pct)");
        sub.add_option("--distance", o->distance, "jog: distance [m or rad; hal:/linuxcnc: the command's units]");
        sub.add_option("--velocity", o->velocity, "jog: velocity [m/s or rad/s; hal:/linuxcnc: command units/s]");
        sub.add_option("--acceleration", o->acceleration, "jog: acceleration [m/s^2 or rad/s^2]")->capture_default_str();
        sub.add_flag("--back", o->back, "jog: return to the start (a reversal)");
        sub.add_option("--duration", o->duration, "step/hold/current-step: recording length; jog: dwell before and after [s]")
            ->capture_default_str();
        sub.add_option("--trace-divider", o->divider, "trace every N velocity periods (0: drive setting)");
        sub.add_option("--seed", o->seed, "noise seed of the simulated machine")->capture_default_str();
        sub.add_option("--at", o->at,
                       "move the axis to this position [m or rad] first (a hold finds it, a jog at 0.5 m/s or 2 rad/s "
                       "moves it; within the drive's travel window), then write --set and run the test");
        sub.add_option("--method", o->method, "frf: multisweep | conventional | prbs | multisine")->capture_default_str();
        sub.add_option("--fmin", o->fmin, "frf: lowest frequency [Hz]")->capture_default_str();
        sub.add_option("--fmax", o->fmax, "frf: highest frequency [Hz] (below fs; prbs: at most fs/2)")->capture_default_str();
        sub.add_option("--points", o->points, "frf: log-spaced frequencies")->capture_default_str();
        sub.add_option("--quantity", o->quantity,
                       "frf: default (the drive's own), plant or open-loop (hal:, linuxcnc:)")->capture_default_str();
        sub.add_option("--amplitude-pct", o->amplitudePct, "frf: excitation amplitude (multisine: its peak), % of rated torque (at most 50)")
            ->capture_default_str();
        sub.add_option("--spacing-hz", o->spacing, "multisine: line spacing from --fmin to --fmax [Hz] (0: fmin/2)");
        sub.add_option("--band", o->bands, "multisine: FMIN:FMAX:SPACING [Hz], repeatable (replaces --fmin/--fmax/--spacing-hz)");
        sub.add_option("--periods", o->periods, "multisine: averaged periods (0: from the loop dynamics, at least 2)");
        sub.add_option("--phases", o->phases, "multisine: clipping | schroeder")->capture_default_str();
        sub.add_option("--shape-from", o->shapeFrom, "multisine: amplitude shaped by 1/|H| of a previous FRF CSV");
        sub.add_option("--shape-range-db", o->shapeRangeDb, "multisine: range of the shaped amplitudes [dB]")->capture_default_str();
        sub.add_flag("--adaptive", o->adaptive,
                     "multisine: re-excite the invalid lines (1/|H| and noise shaped, more periods) "
                     "until every line is valid or --time-budget is spent");
        sub.add_option("--time-budget", o->timeBudgetS, "--adaptive: motion time of all passes [s] (default 5)");
        sub.add_option("--settle-s", o->settle, "frf: settle time per frequency [s] (0: from the loop dynamics)");
        sub.add_option("--min-measure-s", o->minMeasure, "frf: measured time per frequency at least [s] (0: from the loop dynamics)");
        sub.add_option("--sweep-out", o->sweepOut, "frf: sine-stream CSV of the excitation and response");
        sub.add_option("--trace-out", o->traceOut, "frf: the whole trace as a capture CSV");
        sub.add_option("--set", o->set, "write parameter KEY=VALUE (SI units) before the test; repeatable");
        sub.add_flag("--linear", o->linear, "simulator only, test/diagnostic: friction, inductance drop, quantization, "
                                            "noise and lost motion off");
        sub.add_option("--plane", o->circle.plane, "circle: the two axes, first = x role")->capture_default_str();
        sub.add_option("--radius-mm", o->circle.radiusMm, "circle: radius [mm]")->capture_default_str();
        sub.add_option("--feed-mm-min", o->circle.feedMmMin, "circle: feed [mm/min]")->capture_default_str();
        sub.add_option("--direction", o->circle.direction, "circle: ccw | cw")->capture_default_str();
        sub.add_option("--center-x-mm", o->circle.centerXMm, "circle: centre, first axis [mm]");
        sub.add_option("--center-y-mm", o->circle.centerYMm, "circle: centre, second axis [mm]");
        sub.add_option("--squareness-um-per-m", o->circle.squarenessUmPerM, "circle: injected squareness [um/m]");
        sub.add_option("--scale-x-ppm", o->circle.scaleXPpm, "circle: injected scale error, first axis [ppm]");
        sub.add_option("--scale-y-ppm", o->circle.scaleYPpm, "circle: injected scale error, second axis [ppm]");
        sub.add_option("--servo-out-x", o->circle.servoOutX, "circle: servo trace of the first axis (capture CSV)");
        sub.add_option("--servo-out-y", o->circle.servoOutY, "circle: servo trace of the second axis (capture CSV)");
        sub.add_option("--out", o->out, "capture CSV to write (frf: FRF CSV, circle: ball-bar CSV)")->required();
        return recordSessions(sub, [o] { return runCapture(*o); });
    }}};

}  // namespace
}  // namespace axistune::cli

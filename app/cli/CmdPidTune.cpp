// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli pid-tune: tunes a position PID that the NC closes (LinuxCNC's `pid`, through hal: or linuxcnc:),
// docs/linuxcnc.md "Tuning from the command line": measures the open loop with the running gains (multisine), takes
// the effective plant L/C, proposes P, I, D, FF1, FF2 for the margins asked (core/tuning/PositionPid.h) with the rule
// behind each number, and with --apply writes them live and measures again: the measured margins against the
// prediction. If the measured loop misses the margins, the gains from before are put back (exit 4).
#include "app/cli/CliCommand.h"
#include "core/autotune/PidTune.h"
#include "core/autotune/Undo.h"
#include "core/device/Drive.h"
#include "core/device/TestRunner.h"
#include "core/device/hal/AxisNotch.h"
#include "core/device/hal/HalDrive.h"
#include "core/model/InputLimits.h"
#include "core/model/Number.h"
#include "core/model/ResultJson.h"
#include "core/sim/MotionProfile.h"
#include "core/tuning/MovePrediction.h"
#include "core/tuning/PositionPid.h"

#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

namespace axistune::cli {
namespace {

struct PidTuneOptions {
    std::string connect;
    std::string axis;
    double fmin = 2.0;
    double fmax = 0.0;
    double amplitude = 0.0;
    double amplitudePct = 0.0;
    int periods = 0;
    std::string driveInput = "auto";
    double phaseMarginDeg = 50.0;
    double gainMarginDb = 8.0;
    bool apply = false;
    std::string notch = "auto";
    bool removeNotch = false;
    std::string move; ///< DIST:VEL:ACC in the command's units
    std::string out;
    std::string undoPath; ///< --undo RESULT.json
    bool force = false;
};

/// A move out and back (--move DIST:VEL:ACC, the command's units), dwelling kMoveDwellS before and after.
struct MoveSpec {
    double distance = 0.0, velocity = 0.0, acceleration = 0.0;
};
constexpr double kMoveDwellS = 0.05;

Result<MoveSpec> parseMove(const std::string& text)
{
    MoveSpec m;
    double* fields[] = {&m.distance, &m.velocity, &m.acceleration};
    const char* names[] = {"DIST", "VEL", "ACC"};
    std::size_t start = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t end = i < 2 ? text.find(':', start) : text.size();
        if (end == std::string::npos)
            return makeError(ErrorCode::BadInput, "--move '" + text + "': expected DIST:VEL:ACC");
        auto x = model::parseNumber(std::string_view(text).substr(start, end - start));
        if (!x || (i > 0 && !(*x > 0.0)) || (i == 0 && *x == 0.0))
            return makeError(ErrorCode::BadInput, "--move '" + text + "': " + names[i] + " must be a " +
                                                      (i == 0 ? "non-zero" : "positive") + " number");
        *fields[i] = *x;
        start = end + 1;
    }
    return m;
}

/// The move's position command sampled once per servo period, as hal: streams it (planHalMove).
std::vector<double> moveCommand(const MoveSpec& m, double periodS)
{
    sim::MotionProfile p;
    p.dwell(kMoveDwellS);
    p.move(m.distance, m.velocity, m.acceleration);
    p.move(-m.distance, m.velocity, m.acceleration);
    p.dwell(kMoveDwellS);
    std::vector<double> r(static_cast<std::size_t>(std::ceil(p.duration() / periodS)) + 1);
    for (std::size_t i = 0; i < r.size(); ++i)
        r[i] = p.at(static_cast<double>(i) * periodS).position;
    r.back() = 0.0;
    return r;
}

/// Runs `fn` with the HAL session and the axis's pid (hal: names the pid, linuxcnc: maps the letter to it).
template <typename Fn> Status withHalAxis(device::Drive& drive, const PidTuneOptions& o, Fn&& fn)
{
    auto a = device::hal::halAxisOf(drive, o.axis);
    if (!a)
        return a.error();
    return fn(a->session, a->axis);
}

/// --undo RESULT.json: the gains an applied pid-tune wrote go back to the ones that ran before it (`running.gains`),
/// when HAL still holds what it applied (`proposed.gains`, `proposed.notch`) or with --force; the notch is put back as
/// it ran before (`running.notch`: inserted with its f0 and Q, or removed when there was none).
int runPidTuneUndo(const PidTuneOptions& o)
{
    const std::string cmd = "pid-tune --undo";
    const std::string from = model::displayPath(o.undoPath);
    auto bad = [&](const std::string& what) { return reportError(cmd, makeError(ErrorCode::BadInput, what)); };
    if (o.apply || o.removeNotch || !o.move.empty())
        return bad("--apply, --remove-notch and --move are options of a tune, not of --undo");
    auto j = model::readJsonFile(o.undoPath);
    if (!j)
        return reportError(cmd, j.error());
    if (!j->contains("applied") || !(*j)["applied"].is_boolean() || !(*j)["applied"].get<bool>())
        return bad(from + ": field 'applied' is not true: that run wrote nothing to undo");
    if (!j->contains("axis") || !(*j)["axis"].is_string())
        return bad(from + ": field 'axis' is missing");
    autotune::AppliedTune tune;
    tune.axis = (*j)["axis"].get<std::string>();
    if (tune.axis != o.axis)
        return bad("--axis " + o.axis + " but " + from + " tuned axis " + tune.axis);
    for (const std::string& key : autotune::pidGainKeys()) {
        const auto was = j->value(nlohmann::json::json_pointer("/running/gains/" + key), nlohmann::json());
        const auto now = j->value(nlohmann::json::json_pointer("/proposed/gains/" + key), nlohmann::json());
        if (!was.is_number())
            return bad(from + ": field 'running.gains." + key + "' is missing or not a number");
        if (!now.is_number())
            return bad(from + ": field 'proposed.gains." + key + "' is missing or not a number");
        tune.before[key] = was.get<double>();
        tune.applied[key] = now.get<double>();
    }
    autotune::PidTuneNotchUndo notch{tune.axis, std::nullopt, std::nullopt};
    for (auto [part, to] : {std::pair{"running", &notch.before}, std::pair{"proposed", &notch.applied}}) {
        const auto n = j->value(nlohmann::json::json_pointer(std::string("/") + part + "/notch"), nlohmann::json());
        if (n.is_null())
            continue;
        const auto f0 = n.is_object() ? n.value("f0_Hz", nlohmann::json()) : nlohmann::json();
        const auto q = n.is_object() ? n.value("Q", nlohmann::json()) : nlohmann::json();
        if (!f0.is_number() || !q.is_number())
            return bad(from + ": field '" + part + ".notch' must hold the numbers f0_Hz and Q");
        *to = tuning::BiquadNotch{f0.get<double>(), q.get<double>()};
    }
    auto drive = device::connect({o.connect, 1});
    if (!drive)
        return reportError(cmd, drive.error());
    // The notch is checked first: a refusal there leaves the gains as they are, too.
    if (auto st = autotune::checkPidTuneNotchUndo(**drive, notch, o.force); !st)
        return reportError(cmd, st.error());
    auto undone = autotune::undoTune(**drive, tune, o.force);
    if (!undone)
        return reportError(cmd, undone.error());
    nlohmann::json out{{"axis", tune.axis}, {"connection", o.connect}, {"from", from}, {"notch_removed", false}};
    auto notchDone = autotune::undoPidTuneNotch(**drive, notch);
    if (!notchDone)
        return reportError(cmd,
                           makeError(notchDone.error().code, "the gains were put back, but putting the notch back: " +
                                                                 notchDone.error().detail));
    if (notchDone->changed) {
        if (notch.before)
            out["notch_restored"] = {{"f0_Hz", notch.before->f0Hz}, {"Q", notch.before->q}};
        else
            out["notch_removed"] = true;
    }
    // What HAL held just before (after --force: the later change) → what it holds now, as the GUI's session journal.
    out["journal"] = autotune::pidTuneWritesJson(autotune::pidTuneUndoWrites(*undone, *notchDone));
    return writeUndone(cmd, out, *undone, o.out);
}

int runPidTune(const PidTuneOptions& o)
{
    if (!o.undoPath.empty())
        return runPidTuneUndo(o);
    const std::string cmd = "pid-tune";
    if (!o.removeNotch && o.amplitude <= 0.0 && o.amplitudePct <= 0.0)
        return reportError(cmd,
                           makeError(ErrorCode::BadInput,
                                     "give the excitation: --amplitude PEAK (PID output units) or --amplitude-pct P"));
    autotune::PidTuneRequest req;
    req.axis = o.axis;
    req.fminHz = o.fmin;
    req.fmaxHz = o.fmax;
    req.amplitude = o.amplitude;
    req.amplitudePct = o.amplitudePct;
    req.periods = o.periods;
    req.phaseMarginDeg = o.phaseMarginDeg;
    req.gainMarginDb = o.gainMarginDb;
    if (o.driveInput == "torque" || o.driveInput == "velocity")
        req.driveInput = o.driveInput == "torque" ? tuning::DriveInput::Torque : tuning::DriveInput::Velocity;
    else if (o.driveInput != "auto")
        return reportError(cmd, makeError(ErrorCode::BadInput, "--drive-input must be auto, torque or velocity"));
    if (o.notch != "auto" && o.notch != "none")
        return reportError(cmd, makeError(ErrorCode::BadInput, "--notch must be auto or none"));
    req.notch = o.notch == "auto";
    if (!o.removeNotch)
        if (auto st = autotune::checkPidTuneRequest(req, {"--axis", "--amplitude / --amplitude-pct", "--pm", "--gm",
                                                          "--fmin", "--fmax"});
            !st)
            return reportError(cmd, st.error());
    auto drive = device::connect({o.connect, 1});
    if (!drive)
        return reportError(cmd, drive.error());
    if (o.removeNotch) {
        if (auto st = device::hal::removeAxisNotch(**drive, o.axis); !st)
            return reportError(cmd, st.error());
        std::cout << "{\"notch_removed\": true}\n";
        return 0;
    }

    std::cerr << "pid-tune: measuring the open loop with the running gains\n";
    auto measured = autotune::measurePidLoop(**drive, req, {});
    if (!measured)
        return reportError(cmd, measured.error());
    auto proposal = autotune::proposePidTune(*measured, req);
    if (!proposal)
        return reportError(cmd, proposal.error());
    const std::string inputRule = req.driveInput ? "given by --drive-input" : proposal->inputRule;
    const double fs = measured->servoRateHz;
    const double periodS = 1.0 / fs;
    const auto& freq = measured->freqHz;
    const auto& plant = measured->plant;
    const tuning::PositionPid& running = measured->running;
    const auto& notch = proposal->notch;

    // The following error of the move, predicted for the running and the proposed gains.
    std::optional<MoveSpec> move;
    std::optional<tuning::MovePrediction> movePredicted;
    nlohmann::json moveJson;
    if (!o.move.empty()) {
        auto m = parseMove(o.move);
        if (!m)
            return reportError(cmd, m.error());
        move = *m;
        const auto command = moveCommand(*move, periodS);
        tuning::MovePredictionOptions mo;
        mo.input = proposal->input;
        auto ept = withHalAxis(**drive, o, [&](const device::hal::HalSessionOptions&, const device::hal::HalAxis& a) {
            mo.errorPreviousTarget = a.errorPreviousTarget;
            return Status::success();
        });
        if (!ept)
            return reportError(cmd, ept.error());
        auto now = tuning::predictMove(freq, plant, running, periodS, command, mo);
        mo.notch = notch;
        auto proposed = tuning::predictMove(freq, plant, proposal->gains, periodS, command, mo);
        if (!proposed)
            return reportError(cmd, makeError(proposed.error().code, "--move: " + proposed.error().detail));
        // A move that drives the output into its limit is not linear: the prediction would not hold, and the
        // integrator stops (LinuxCNC's anti-windup).
        auto limit = (*drive)->readParameters(o.axis, std::vector<std::string>{"maxoutput"});
        if (limit && limit->at("maxoutput") > 0.0 && proposed->peakOutput > 0.9 * limit->at("maxoutput"))
            return reportError(cmd, makeError(ErrorCode::OutOfRange,
                                              "--move: the predicted PID output peaks at " +
                                                  model::formatNumber(proposed->peakOutput, 4) + ", above 90 % of " +
                                                  "maxoutput (" + model::formatNumber(limit->at("maxoutput"), 4) +
                                                  "): the loop would saturate; choose a gentler move"));
        movePredicted = *proposed;
        moveJson = {
            {"distance", move->distance},
            {"velocity", move->velocity},
            {"acceleration", move->acceleration},
            {"dwell_s", kMoveDwellS},
            {"error_previous_target", mo.errorPreviousTarget},
            {"units", "the command's (the configuration's position units)"},
            {"rule",
             "Y = P N (C_r + F) R / (1 + P N C) on the measured plant lines, error = R delayed by the pid minus Y "
             "(docs/linuxcnc.md \"Following error of a move\")"}};
        if (now)
            moveJson["running"] = {{"predicted_peak_following_error", now->peakError},
                                   {"predicted_peak_output", now->peakOutput}};
        moveJson["proposed"] = {{"predicted_peak_following_error", proposed->peakError},
                                {"predicted_peak_output", proposed->peakOutput},
                                {"extrapolated_share", proposed->extrapolatedShare},
                                {"low_decade_order", proposed->lowDecadeOrder}};
    }

    int rc = 0;
    std::optional<autotune::PidTuneApplied> applied;
    if (o.apply) {
        auto a = autotune::applyPidTune(**drive, req, *measured, *proposal, {});
        if (!a)
            return reportError(cmd, a.error());
        applied = std::move(a).value();
        if (!applied->applied) {
            rc = exitCodeFor(ErrorCode::Safety);
        } else if (move) {
            // Verify by the move: the measured peak following error against the prediction.
            device::TestRequest r;
            r.axis = o.axis;
            auto& j = r.test.emplace<device::JogTest>();
            j.distance = move->distance;
            j.velocity = move->velocity;
            j.acceleration = move->acceleration;
            j.returnToStart = true;
            j.dwellS = kMoveDwellS;
            std::cerr << "pid-tune: running the move to verify the predicted following error\n";
            auto ran = device::runTest(**drive, r);
            if (!ran) {
                moveJson["proposed"]["measured_error"] = ran.error().detail;
            } else {
                const model::Channel* fe = ran->trace->channel("following_error");
                double peak = 0.0;
                if (fe)
                    for (double e : fe->data)
                        peak = std::max(peak, std::abs(e));
                moveJson["proposed"]["measured_peak_following_error"] = peak;
                moveJson["proposed"]["difference_pct"] =
                    100.0 * (peak - movePredicted->peakError) / movePredicted->peakError;
            }
        }
    }
    nlohmann::json out = autotune::pidTuneJson(req, *measured, *proposal, applied ? &*applied : nullptr);
    out["connection"] = o.connect;
    out["drive_input_rule"] = inputRule;
    if (move)
        out["move"] = moveJson;
    if (const int w = writeJsonResult(cmd, out, o.out); w != 0)
        return w;
    if (rc != 0)
        std::cerr << "axistune-cli pid-tune: " << out["refused"].get<std::string>() << "\n";
    return rc;
}

const CliRegistrar kRegistrar{
    {"pid-tune", "Tune a position PID the NC closes (LinuxCNC): measure, propose with rules, apply and verify",
     [](CLI::App& sub) {
         auto o = std::make_shared<PidTuneOptions>();
         sub.add_option("--connect", o->connect, "hal: or linuxcnc:PATH/machine.ini")->required();
         sub.add_option("--axis", o->axis, "pid instance (hal:) or axis letter (linuxcnc:)")->required();
         sub.add_option("--fmin", o->fmin, "lowest line [Hz]")->capture_default_str();
         sub.add_option("--fmax", o->fmax, "highest line [Hz]; 0: 0.45 × servo rate")->capture_default_str();
         sub.add_option("--amplitude", o->amplitude, "multisine peak in the PID output's units");
         sub.add_option("--amplitude-pct", o->amplitudePct, "multisine peak, % of the pid's maxoutput (at most 50)");
         sub.add_option("--periods", o->periods, "averaged periods; 0: 3")->capture_default_str();
         sub.add_option("--drive-input", o->driveInput, "auto, torque or velocity")->capture_default_str();
         sub.add_option("--pm", o->phaseMarginDeg, "phase margin asked [deg]")->capture_default_str();
         sub.add_option("--gm", o->gainMarginDb, "gain margin asked [dB]")->capture_default_str();
         sub.add_flag("--apply", o->apply,
                      "write the gains live (setp, read back), insert the notch, and verify by measuring again");
         sub.add_option("--notch", o->notch,
                        "auto (a biquad notch at a resonance when it raises the crossover) or none")
             ->capture_default_str();
         sub.add_flag("--remove-notch", o->removeNotch, "remove AxisTune's notch from the HAL session and exit");
         sub.add_option("--move", o->move,
                        "DIST:VEL:ACC (command units): predict the following error of this move out and back; with "
                        "--apply, run it and report the measured peak");
         sub.add_option("--out", o->out, "result JSON (also printed)");
         sub.add_option("--undo", o->undoPath,
                        "RESULT.json of an applied run: put back the gains that ran before it (running.gains) and "
                        "remove its notch; refused when HAL no longer holds what it applied");
         sub.add_flag("--force", o->force, "with --undo: put them back even when the gains changed since");
         return [o] { return runPidTune(*o); };
     }}};

} // namespace
} // namespace axistune::cli

// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli scope: a triggered or continuous (roll-mode) capture of drive signals into a scope CSV
// (docs/scope.md, docs/cli.md "scope", docs/formats.md "Scope CSV").
#include "app/cli/CliCommand.h"
#include "core/device/Drive.h"
#include "core/device/TestRunner.h"
#include "core/io/CaptureCsv.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <thread>

namespace axistune::cli {
namespace {

struct ScopeOptions {
    std::string connect = "sim:vmc";
    std::string axis;
    std::string channels;
    std::string trigger;
    double prePct = 0.0;
    double lengthS = 0.0;
    double continuousS = 0.0;
    int divider = 1;
    double timeoutS = 30.0;
    double stepRadS = 0.0;
    std::string out;
    std::uint64_t seed = 1;
};

std::vector<std::string> splitList(const std::string& s, char sep)
{
    std::vector<std::string> out;
    std::size_t start = 0;
    while (true) {
        const auto pos = s.find(sep, start);
        out.push_back(s.substr(start, pos == std::string::npos ? std::string::npos : pos - start));
        if (pos == std::string::npos)
            break;
        start = pos + 1;
    }
    return out;
}

/// --trigger CHANNEL:LEVEL:EDGE
Status parseTrigger(const std::string& text, device::ScopeRequest& r)
{
    const auto parts = splitList(text, ':');
    const auto level = parts.size() == 3 ? model::parseNumber(parts[1]) : std::nullopt;
    const std::string& edge = parts.size() == 3 ? parts[2] : std::string();
    if (parts.size() != 3 || parts[0].empty() || !level || (edge != "rising" && edge != "falling" && edge != "either"))
        return makeError(ErrorCode::BadInput, "--trigger '" + text +
                                                  "': expected CHANNEL:LEVEL:EDGE with LEVEL a number in the channel's "
                                                  "SI unit and EDGE rising, falling or either");
    r.triggerChannel = parts[0];
    r.triggerLevel = *level;
    r.edge = edge == "rising"    ? device::ScopeEdge::Rising
             : edge == "falling" ? device::ScopeEdge::Falling
                                 : device::ScopeEdge::Either;
    return Status::success();
}

std::string num(double v)
{
    return model::formatNumber(v, 6);
}

using Clock = std::chrono::steady_clock;

Clock::time_point after(double seconds)
{
    return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

/// The options as a scope request (the length follows from the drive's rate); errors name the option.
Result<device::ScopeRequest> requestFromOptions(const ScopeOptions& o)
{
    auto bad = [](const std::string& why) { return makeError(ErrorCode::BadInput, why); };
    const bool triggered = o.lengthS > 0.0;
    if ((o.lengthS > 0.0) == (o.continuousS > 0.0))
        return bad("give either --length S (a triggered capture) or --continuous S (roll mode)");
    if (!std::isfinite(o.lengthS) || o.lengthS < 0.0 || !std::isfinite(o.continuousS) || o.continuousS < 0.0)
        return bad("--length and --continuous must be finite seconds > 0");
    if (triggered && o.trigger.empty())
        return bad("--length needs --trigger CHANNEL:LEVEL:EDGE (use --continuous S to record without a trigger)");
    if (!triggered && !o.trigger.empty())
        return bad("--trigger applies to --length captures, not to --continuous");
    if (!(o.prePct >= 0.0 && o.prePct <= 100.0))
        return bad("--pre " + num(o.prePct) + ": the pre-trigger share must lie in 0..100 %");
    if (!(o.timeoutS > 0.0) || !std::isfinite(o.timeoutS))
        return bad("--timeout must be finite seconds > 0");
    if (!std::isfinite(o.stepRadS))
        return bad("--step must be a finite motor velocity [rad/s]");
    device::ScopeRequest r;
    r.axis = o.axis;
    r.divider = o.divider;
    r.mode = triggered ? device::ScopeMode::Single : device::ScopeMode::Roll;
    r.preTriggerPct = o.prePct;
    r.channels = splitList(o.channels, ',');
    if (triggered) {
        if (auto st = parseTrigger(o.trigger, r); !st)
            return st.error();
    }
    return r;
}

/// Waits for the single capture (running the --step event once the pre-trigger rows are in) and reads it.
Result<device::ScopeCapture> captureTriggered(device::Drive& drive, const ScopeOptions& o)
{
    const auto deadline = after(o.timeoutS);
    bool stepped = o.stepRadS == 0.0;
    while (true) {
        auto s = drive.pollScope();
        if (!s)
            return s.error();
        if (s->state == device::ScopeState::Done)
            break;
        if (!stepped && s->state == device::ScopeState::Waiting) {
            device::TestRequest step;
            step.axis = o.axis;
            auto& stepTest = step.test.emplace<device::StepTest>();
            stepTest.velocityRadS = o.stepRadS;
            stepTest.recordS = std::max(0.05, 1.2 * o.lengthS);
            if (auto run = device::runTest(drive, step, {}); !run)
                return run.error();
            stepped = true;
            continue;
        }
        if (Clock::now() > deadline) {
            (void)drive.stopScope();
            return makeError(ErrorCode::Device, "no trigger within --timeout " + num(o.timeoutS) + " s (scope " +
                                                    device::scopeStateName(s->state) + ", " + o.trigger + ")");
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return drive.readScopeCapture();
}

/// Roll mode: `rows` consecutive rows (a gap where the drive overwrote rows before they were read).
Result<device::ScopeCapture> captureRoll(device::Drive& drive, const device::ScopeRequest& r,
                                         const device::ScopeCapabilities& caps, std::size_t rows, double rate,
                                         const ScopeOptions& o)
{
    device::ScopeCapture capture;
    capture.triggered = false;
    capture.rateHz = rate;
    for (const auto& name : r.channels) {
        for (const auto& ch : caps.channels) {
            if (ch.name == name)
                capture.channels.push_back(ch);
        }
    }
    capture.columns.assign(r.channels.size(), {});
    std::uint64_t next = 0;
    // The record's own length plus --timeout of wall time at most.
    const auto deadline = after(o.continuousS + o.timeoutS);
    while (capture.rows() < rows) {
        if (auto s = drive.pollScope(); !s)
            return s.error();
        auto got = drive.readScopeRows(next, rows - capture.rows());
        if (!got)
            return got.error();
        device::appendScopeRows(capture, *got);
        if (got->rows > 0)
            next = got->firstSample + got->rows;
        if (Clock::now() > deadline) {
            (void)drive.stopScope();
            return makeError(ErrorCode::Device, "roll mode delivered " + std::to_string(capture.rows()) + " of " +
                                                    std::to_string(rows) + " rows within " +
                                                    num(o.continuousS + o.timeoutS) + " s");
        }
        if (got->rows == 0)
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    (void)drive.stopScope();
    return capture;
}

int runScope(const ScopeOptions& o)
{
    const std::string cmd = "scope";
    auto req = requestFromOptions(o);
    if (!req)
        return reportError(cmd, req.error());
    device::ScopeRequest r = std::move(req).value();
    const bool triggered = r.mode != device::ScopeMode::Roll;
    auto opened = device::connect({o.connect, o.seed});
    if (!opened)
        return reportError(cmd, opened.error());
    device::Drive& drive = **opened;
    auto caps = drive.scopeCapabilities(o.axis);
    if (!caps)
        return reportError(cmd, caps.error());
    const double rate = caps->fastestRateHz / std::max(1, o.divider);
    const double seconds = triggered ? o.lengthS : o.continuousS;
    const double rows = std::round(seconds * rate);
    if (!(rows >= 2.0))
        return reportError(cmd, makeError(ErrorCode::BadInput, std::string(triggered ? "--length " : "--continuous ") +
                                                                   num(seconds) + " s is shorter than two samples at " +
                                                                   num(rate) + " Hz"));
    r.lengthSamples = triggered ? static_cast<std::uint64_t>(rows) : 0;
    if (auto st = drive.armScope(r); !st)
        return reportError(cmd, st.error());
    auto captured =
        triggered ? captureTriggered(drive, o) : captureRoll(drive, r, *caps, static_cast<std::size_t>(rows), rate, o);
    if (!captured)
        return reportError(cmd, captured.error());
    const device::ScopeCapture& capture = *captured;
    model::Metadata extra{{"divider", static_cast<double>(o.divider)}};
    extra.set(model::meta::kConnection, o.connect);
    auto table = device::scopeCaptureToTable(capture, o.axis, extra);
    if (triggered) {
        table.metadata.set("trigger", o.trigger);
        table.metadata.set("pre_trigger_pct", o.prePct);
    }
    if (auto st = io::writeCaptureCsvFile(o.out, table); !st)
        return reportError(cmd, st.error());
    nlohmann::json j{{"connection", o.connect},
                     {"axis", o.axis},
                     {"mode", triggered ? "triggered" : "roll"},
                     {"fs_Hz", capture.rateHz},
                     {"rows", capture.rows()},
                     {"first_sample", capture.samples.empty() ? 0 : capture.samples.front()},
                     {"missing_samples", capture.missingSamples()},
                     {"out", o.out}};
    if (triggered) {
        j["trigger_sample"] = capture.triggerSample;
        j["trigger_row"] = capture.triggerRow();
    }
    if (const int rc = writeJsonResult(cmd, j, ""); rc != 0)
        return rc;
    if (capture.missingSamples() > 0)
        return reportError(cmd, makeError(ErrorCode::Device,
                                          std::to_string(capture.missingSamples()) +
                                              " samples were lost (overwritten in the drive before they were read); "
                                              "the gaps are visible in the sample column of " +
                                              o.out));
    return 0;
}

const CliRegistrar kRegistrar{
    {"scope", "Capture drive signals: triggered (--length) or continuous roll mode (--continuous) into a scope CSV",
     [](CLI::App& sub) {
         auto o = std::make_shared<ScopeOptions>();
         sub.add_option("--connect", o->connect, connectOptionHelp())->capture_default_str();
         sub.add_option("--axis", o->axis, "axis name, e.g. X")->required();
         sub.add_option("--channels", o->channels,
                        "comma-separated channel names as the drive lists them (axistune-cli drive shows them)")
             ->required();
         sub.add_option("--trigger", o->trigger, "CHANNEL:LEVEL:EDGE, EDGE rising, falling or either (with --length)");
         sub.add_option("--pre", o->prePct, "share of the capture before the trigger [%], 0..100")
             ->capture_default_str();
         sub.add_option("--length", o->lengthS, "triggered capture of this many seconds");
         sub.add_option("--continuous", o->continuousS, "roll mode: record this many seconds, every sample");
         sub.add_option("--divider", o->divider, "sample every N-th period of the drive's fastest scope rate")
             ->capture_default_str();
         sub.add_option("--timeout", o->timeoutS, "wall-clock seconds to wait for the trigger")->capture_default_str();
         sub.add_option("--step", o->stepRadS,
                        "run a velocity step of this amplitude [rad/s] once the pre-trigger is filled (an event to "
                        "trigger on)");
         sub.add_option("--out", o->out, "scope CSV to write")->required();
         sub.add_option("--seed", o->seed, "noise seed of an embedded simulated machine")->capture_default_str();
         return [o] { return runScope(*o); };
     }}};

} // namespace
} // namespace axistune::cli

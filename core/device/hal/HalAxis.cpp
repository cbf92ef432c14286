// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/hal/HalAxis.h"

#include "core/model/Number.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace axistune::device::hal {
namespace {

constexpr const char* kInject = "axistune-inject";
constexpr const char* kPidOutNet = "axistune-pid-out";
constexpr const char* kExcNet = "axistune-exc";
constexpr const char* kValidNet = "axistune-valid";
constexpr const char* kInjectedNet = "axistune-injected";
constexpr const char* kErrorNet = "axistune-ferror";
constexpr const char* kCommandNet = "axistune-cmd";
constexpr const char* kBeatNet = "axistune-heartbeat";

Result<std::vector<HalPin>> pins(const HalSessionOptions& o)
{
    auto text = runHalcmd(o, {"-s", "show", "pin"});
    if (!text)
        return text.error();
    return parsePins(*text);
}

/// `halcmd -s show thread [NAME]`, parsed.
Result<std::vector<HalThread>> threads(const HalSessionOptions& o, const std::string& name = {})
{
    std::vector<std::string> args{"-s", "show", "thread"};
    if (!name.empty())
        args.push_back(name);
    auto text = runHalcmd(o, args);
    if (!text)
        return text.error();
    return parseThreads(*text);
}

Result<std::vector<HalSignal>> signals(const HalSessionOptions& o)
{
    auto text = runHalcmd(o, {"-s", "show", "sig"});
    if (!text)
        return text.error();
    return parseSignals(*text);
}

double pinNumber(const std::vector<HalPin>& ps, const std::string& name)
{
    const HalPin* p = findPin(ps, name);
    if (!p)
        return 0.0;
    return model::parseNumber(p->value).value_or(0.0);
}

std::string num(double v)
{
    return model::formatShortest(v);
}

void waitPeriods(std::int64_t periodNs)
{
    std::this_thread::sleep_for(std::max(std::chrono::nanoseconds(2 * periodNs), std::chrono::nanoseconds(20'000'000)));
}

/// The 1-based position of the axis's pid function in its thread (halcmd addf takes positions from 1).
Result<long> pidPlace(const HalSessionOptions& options, const HalAxis& axis)
{
    auto ts = threads(options, axis.thread);
    if (!ts || ts->empty())
        return makeError(ErrorCode::Device, "cannot read thread " + axis.thread);
    const auto& fns = ts->front().functions;
    const auto it = std::find(fns.begin(), fns.end(), axis.pidFunction);
    if (it == fns.end())
        return makeError(ErrorCode::Device, axis.pidFunction + " is no longer on " + axis.thread);
    return static_cast<long>(it - fns.begin()) + 1;
}

/// Waits until AxisTune's injection adds nothing (a move's offset, returning to zero at its return speed).
Status waitOffsetReturned(const HalSessionOptions& options, double timeoutS)
{
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutS);
    for (;;) {
        auto v = runHalcmd(options, {"getp", std::string(kInject) + ".injected"});
        if (!v)
            return v.error();
        auto x = model::parseNumber(std::string_view(*v).substr(0, v->find_first_of(" \n")));
        if (x && *x == 0.0)
            return {};
        if (std::chrono::steady_clock::now() > end)
            return makeError(ErrorCode::Device, "AxisTune's position offset did not return to zero within " +
                                                    num(timeoutS) + " s (" + *v + ")");
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

} // namespace

const char* halColumnName(HalColumn c)
{
    switch (c) {
    case DriveInput:
        return "drive_input";
    case Feedback:
        return "feedback";
    case PidOutput:
        return "pid_output";
    case Injection:
        return "injection";
    case FollowingError:
        return "following_error";
    case kHalColumns:
        break;
    }
    return "?";
}

Result<HalAxis> discoverAxis(const HalSessionOptions& options, const std::string& pid)
{
    auto ps = pins(options);
    if (!ps)
        return ps.error();
    HalAxis a;
    a.pid = pid;
    const HalPin* out = findPin(*ps, pid + ".output");
    if (!out)
        return makeError(ErrorCode::NotFound, "HAL has no PID '" + pid + "' (no pin " + pid + ".output)");
    if (out->signal.empty())
        return makeError(ErrorCode::BadInput, pid + ".output drives no net: nothing to inject into");
    a.outputSignal = out->signal;
    const HalPin* fb = findPin(*ps, pid + ".feedback");
    if (!fb || fb->signal.empty())
        return makeError(ErrorCode::BadInput, pid + ".feedback is not linked to a net: no feedback to record");
    a.feedbackSignal = fb->signal;
    if (const HalPin* e = findPin(*ps, pid + ".error"))
        a.errorSignal = e->signal;
    if (const HalPin* c = findPin(*ps, pid + ".command"))
        a.commandSignal = c->signal;
    if (const HalPin* t = findPin(*ps, pid + ".error-previous-target"))
        a.errorPreviousTarget = t->value == "TRUE";
    a.maxOutput = std::abs(pinNumber(*ps, pid + ".maxoutput"));
    a.maxError = std::abs(pinNumber(*ps, pid + ".maxerror"));

    auto ts = threads(options);
    if (!ts)
        return ts.error();
    a.pidFunction = pid + ".do-pid-calcs";
    for (const auto& t : *ts) {
        if (std::find(t.functions.begin(), t.functions.end(), a.pidFunction) != t.functions.end()) {
            a.thread = t.name;
            a.periodNs = t.periodNs;
        }
    }
    if (a.thread.empty())
        return makeError(ErrorCode::BadInput, a.pidFunction + " runs on no thread");
    return a;
}

Result<std::unique_ptr<HalInjection>> HalInjection::insert(const HalSessionOptions& options, const HalAxis& axis,
                                                           const InjectionSettings& settings, const HalClient& client)
{
    if (!(settings.limit > 0.0) || !std::isfinite(settings.limit))
        return makeError(ErrorCode::OutOfRange, "injection limit must be a positive number in the PID output's units");
    const bool atCommand = settings.point == InjectionPoint::PidCommand;
    if (atCommand && (!(settings.returnRate > 0.0) || !std::isfinite(settings.returnRate)))
        return makeError(ErrorCode::OutOfRange, "a move's injection needs a positive return speed");
    if (atCommand && axis.commandSignal.empty())
        return makeError(ErrorCode::BadInput, axis.pid + ".command is not linked to a net: AxisTune adds its move "
                                                         "to the net the NC (or the HAL file) drives");
    if (!atCommand && axis.maxOutput > 0.0 && settings.limit > 0.5 * axis.maxOutput)
        return makeError(ErrorCode::OutOfRange, "injection peak " + num(settings.limit) + " exceeds half of " +
                                                    axis.pid + ".maxoutput (" + num(axis.maxOutput) + ")");
    if (settings.fifoDepth < 64 || settings.fifoDepth > 1 << 20)
        return makeError(ErrorCode::OutOfRange, "FIFO depth must be 64 to 1048576 rows");

    std::unique_ptr<HalInjection> inj(new HalInjection);
    inj->m_options = options;
    inj->m_axis = axis;
    inj->m_settings = settings;
    // The sampler is loaded once for the tests and the scope (HalSampler.h): loaded now, or the scope's load.
    auto sampler = HalSamplerModule::acquire(options, axis.periodNs);
    if (!sampler)
        return sampler.error();
    inj->m_sampler = std::move(sampler).value();

    // Function order in the thread: streamer before the PID, the injection right after it (at the PID output) or
    // between the two (at the command), sampler last.
    auto place = pidPlace(options, axis);
    if (!place)
        return place.error();
    const long pidPos = *place;

    const double maxError = settings.maxError > 0.0 ? settings.maxError : axis.maxError;
    const std::string depth = std::to_string(settings.fifoDepth);
    struct Step {
        std::vector<std::string> doArgs;
        std::vector<std::string> undoArgs;
    };
    std::vector<Step> steps = {
        {{"loadrt", "axistune_inject", std::string("names=") + kInject}, {"unloadrt", "axistune_inject"}},
        {{"loadrt", "streamer", "depth=" + depth, "cfg=fb"}, {"unloadrt", "streamer"}},
        {{"setp", std::string(kInject) + ".limit", num(settings.limit)}, {}},
        {{"setp", std::string(kInject) + ".maxerror", num(maxError)}, {}},
        {{"setp", std::string(kInject) + ".timeout", num(settings.heartbeatTimeoutS)}, {}},
        {{"setp", std::string(kInject) + ".rate", num(atCommand ? settings.returnRate : 0.0)}, {}},
        {{"addf", "streamer.0", axis.thread, std::to_string(pidPos)}, {"delf", "streamer.0", axis.thread}},
        {{"addf", kInject, axis.thread, std::to_string(atCommand ? pidPos + 1 : pidPos + 2)},
         {"delf", kInject, axis.thread}},
        {{"addf", "sampler.0", axis.thread}, {"delf", "sampler.0", axis.thread}},
        {{"net", kBeatNet, client.heartbeatPin(), std::string(kInject) + ".heartbeat"}, {"delsig", kBeatNet}},
        {{"net", kExcNet, "streamer.0.pin.0", std::string(kInject) + ".excitation"}, {"delsig", kExcNet}},
        // sampler.0.enable starts TRUE, and a new net takes that value until the streamer writes its first row:
        // the sampler would record rows of nothing while the insertion goes on.
        {{"setp", "sampler.0.enable", "0"}, {}},
        {{"net", kValidNet, "streamer.0.pin.1", "sampler.0.enable"}, {"delsig", kValidNet}},
        {{"net", kInjectedNet, std::string(kInject) + ".injected", "sampler.0.pin.3"}, {"delsig", kInjectedNet}},
        {{"linksp", axis.outputSignal, "sampler.0.pin.0"}, {"unlinkp", "sampler.0.pin.0"}},
        {{"linksp", axis.feedbackSignal, "sampler.0.pin.1"}, {"unlinkp", "sampler.0.pin.1"}},
    };
    const std::vector<Step> wiring =
        atCommand ? std::vector<Step>{
                        // command net -> inject.in; inject.out -> pid.command (its own net); the PID output is
                        // recorded as it is.
                        {{"unlinkp", axis.pid + ".command"}, {"linkps", axis.pid + ".command", axis.commandSignal}},
                        {{"linksp", axis.commandSignal, std::string(kInject) + ".in"},
                         {"unlinkp", std::string(kInject) + ".in"}},
                        {{"net", kCommandNet, std::string(kInject) + ".out", axis.pid + ".command"},
                         {"delsig", kCommandNet}},
                        {{"linksp", axis.outputSignal, "sampler.0.pin.2"}, {"unlinkp", "sampler.0.pin.2"}},
                    }
                  : std::vector<Step>{
                        {{"unlinkp", axis.pid + ".output"}, {"linkps", axis.pid + ".output", axis.outputSignal}},
                        {{"linkps", std::string(kInject) + ".out", axis.outputSignal},
                         {"unlinkp", std::string(kInject) + ".out"}},
                        {{"net", kPidOutNet, axis.pid + ".output", std::string(kInject) + ".in"},
                         {"delsig", kPidOutNet}},
                        {{"linksp", kPidOutNet, "sampler.0.pin.2"}, {"unlinkp", "sampler.0.pin.2"}},
                    };
    steps.insert(steps.end(), wiring.begin(), wiring.end());
    if (axis.errorSignal.empty()) {
        steps.push_back({{"net", kErrorNet, axis.pid + ".error", std::string(kInject) + ".error", "sampler.0.pin.4"},
                         {"delsig", kErrorNet}});
    } else {
        steps.push_back({{"linksp", axis.errorSignal, std::string(kInject) + ".error"},
                         {"unlinkp", std::string(kInject) + ".error"}});
        steps.push_back({{"linksp", axis.errorSignal, "sampler.0.pin.4"}, {"unlinkp", "sampler.0.pin.4"}});
    }
    for (auto& s : steps) {
        auto r = runHalcmd(options, s.doArgs);
        if (!r) {
            (void)inj->remove();
            std::string what;
            for (const auto& a : s.doArgs)
                what += (what.empty() ? "" : " ") + a;
            return makeError(ErrorCode::Device, "inserting AxisTune's injection into " + axis.pid + " failed at '" +
                                                    what + "' (nothing left changed): " + r.error().detail);
        }
        if (!s.undoArgs.empty())
            inj->m_undo.push_back(std::move(s.undoArgs));
    }
    return inj;
}

HalInjection::~HalInjection()
{
    (void)remove();
}

Status HalInjection::remove()
{
    Status first;
    // Disarm first so that nothing more is added while the nets change.
    if (!m_undo.empty()) {
        (void)runHalcmd(m_options, {"setp", std::string(kInject) + ".enable", "0"});
        // A move's offset returns to zero at its return speed before the command is handed back.
        if (m_settings.point == InjectionPoint::PidCommand)
            first = waitOffsetReturned(m_options, m_settings.limit / m_settings.returnRate + 1.0);
    }
    bool waited = false;
    bool halChecked = false, halRuns = true;
    while (!m_undo.empty()) {
        auto args = std::move(m_undo.back());
        m_undo.pop_back();
        if (args.front() == "unloadrt" && !waited) {
            // A function taken off the thread may still be running this period: unloading frees the FIFO it
            // reads (LinuxCNC's streamer and sampler then crash the servo thread). Wait two periods.
            waitPeriods(m_axis.periodNs);
            waited = true;
        }
        auto r = runHalcmd(m_options, args);
        if (!r) {
            // Once more after a pause: halcmd can fail transiently on a loaded machine (seen once in a CI run at
            // ctest -j2). Not when HAL no longer runs (a lost session: every step fails, and retries would only
            // delay the report). A step that fails twice is reported, and the remaining steps still run.
            if (!halChecked) {
                halChecked = true;
                auto t = runHalcmd(m_options, {"-s", "show", "thread"});
                halRuns = t && t->find_first_not_of(" \t\r\n") != std::string::npos;
            }
            if (halRuns) {
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
                r = runHalcmd(m_options, args);
                // The first unloadrt can report a failure and still unload (seen in CI at ctest -j2: the retry then
                // says "streamer: not loaded"): what was to be unloaded is gone, which is the step's aim.
                if (!r && args.front() == "unloadrt" && args.size() == 2 &&
                    r.error().detail.find(args[1] + ": not loaded") != std::string::npos)
                    r = std::string();
            }
        }
        if (!r && first)
            first = r.error();
    }
    // Unloads the sampler unless the scope still holds it (two periods after sampler.0 left the thread).
    m_sampler.reset();
    return first;
}

Status removeNotch(const HalSessionOptions& options)
{
    auto ps = pins(options);
    if (!ps)
        return ps.error();
    const std::string notch = kNotchComponent;
    const HalPin* out = findPin(*ps, notch + ".out");
    const HalPin* in = findPin(*ps, notch + ".in");
    if (!out)
        return Status::success();
    // The pid whose output feeds the notch: the writer of the notch's input net.
    std::string pidOutput;
    if (in && !in->signal.empty()) {
        auto sigs = signals(options);
        if (!sigs)
            return sigs.error();
        if (const HalSignal* s = findSignal(*sigs, in->signal))
            pidOutput = s->writer;
    }
    std::vector<std::vector<std::string>> cmds;
    cmds.push_back({"setp", notch + ".enable", "0"});
    const std::string drove = out->signal;
    if (!drove.empty())
        cmds.push_back({"unlinkp", notch + ".out"});
    if (in && !in->signal.empty()) {
        cmds.push_back({"unlinkp", notch + ".in"});
        if (!pidOutput.empty())
            cmds.push_back({"unlinkp", pidOutput});
        cmds.push_back({"delsig", in->signal});
    }
    if (!drove.empty() && !pidOutput.empty())
        cmds.push_back({"linkps", pidOutput, drove});
    for (const auto& c : cmds)
        if (auto r = runHalcmd(options, c); !r)
            return r.error();
    // Off its thread, two periods, then unloaded (as the injection).
    auto ts = threads(options);
    if (!ts)
        return ts.error();
    std::int64_t period = 0;
    for (const auto& t : *ts)
        if (std::find(t.functions.begin(), t.functions.end(), notch) != t.functions.end()) {
            if (auto r = runHalcmd(options, {"delf", notch, t.name}); !r)
                return r.error();
            period = std::max(period, t.periodNs);
        }
    waitPeriods(period);
    if (auto r = runHalcmd(options, {"unloadrt", "biquad"}); !r)
        return r.error();
    return Status::success();
}

Result<std::optional<HalNotch>> readNotch(const HalSessionOptions& options)
{
    auto ps = pins(options);
    if (!ps)
        return ps.error();
    const std::string notch = kNotchComponent;
    if (!findPin(*ps, notch + ".out"))
        return std::optional<HalNotch>();
    HalNotch n;
    if (const HalPin* in = findPin(*ps, notch + ".in"); in && !in->signal.empty()) {
        auto sigs = signals(options);
        if (!sigs)
            return sigs.error();
        if (const HalSignal* s = findSignal(*sigs, in->signal))
            n.pidOutput = s->writer;
    }
    // f0 and Q are the component's parameters (not pins): getp prints the value alone.
    for (auto [name, to] : {std::pair{".f0", &n.f0Hz}, std::pair{".Q", &n.q}}) {
        auto text = runHalcmd(options, {"getp", notch + name});
        if (!text)
            return text.error();
        auto x = model::parseNumber(std::string_view(*text).substr(0, text->find_first_of(" \n")));
        if (!x)
            return makeError(ErrorCode::Device, "halcmd getp " + notch + name + " printed '" + *text +
                                                    "', not a number");
        *to = *x;
    }
    return std::optional<HalNotch>(n);
}

Status insertNotch(const HalSessionOptions& options, const HalAxis& axis, double f0Hz, double q)
{
    const double fs = axis.periodNs > 0 ? 1e9 / static_cast<double>(axis.periodNs) : 0.0;
    if (!(f0Hz > 0.0) || !(f0Hz < 0.5 * fs))
        return makeError(ErrorCode::OutOfRange, "notch at " + num(f0Hz) +
                                                    " Hz refused: it must lie below half the servo "
                                                    "rate (" +
                                                    num(0.5 * fs) + " Hz)");
    if (!(q >= 0.5 && q <= 2.0))
        return makeError(ErrorCode::OutOfRange, "notch Q " + num(q) + " refused: LinuxCNC's biquad takes 0.5 to 2");
    auto ps = pins(options);
    if (!ps)
        return ps.error();
    const std::string notch = kNotchComponent;
    if (findPin(*ps, notch + ".out")) {
        if (auto st = removeNotch(options); !st)
            return st;
        auto again = discoverAxis(options, axis.pid);
        if (!again)
            return again.error();
        return insertNotch(options, *again, f0Hz, q);
    }
    for (const auto& p : *ps)
        if (p.owner == "biquad")
            return makeError(ErrorCode::BadInput, "this configuration loads biquad itself (" + p.name +
                                                      "): AxisTune's notch needs the component; add the notch to the "
                                                      "configuration's own biquad instead");
    auto place = pidPlace(options, axis);
    if (!place)
        return place.error();
    const long after = *place + 1; // right after the pid
    const std::string inNet = "axistune-notch-in";
    const std::vector<std::vector<std::string>> steps = {
        {"loadrt", "biquad", "names=" + notch},
        {"setp", notch + ".type", "2"},
        {"setp", notch + ".f0", num(f0Hz)},
        {"setp", notch + ".Q", num(q)},
        {"setp", notch + ".enable", "0"},
        {"addf", notch, axis.thread, std::to_string(after)},
        {"unlinkp", axis.pid + ".output"},
        {"linkps", notch + ".out", axis.outputSignal},
        {"net", inNet, axis.pid + ".output", notch + ".in"},
        {"setp", notch + ".enable", "1"},
    };
    for (const auto& s : steps) {
        if (auto r = runHalcmd(options, s); !r) {
            (void)removeNotch(options);
            // removeNotch relinks only what it finds; a failure before the relink leaves the pid output unlinked.
            auto check = pins(options);
            if (check)
                if (const HalPin* o = findPin(*check, axis.pid + ".output"); o && o->signal.empty())
                    (void)runHalcmd(options, {"linkps", axis.pid + ".output", axis.outputSignal});
            std::string what;
            for (const auto& a : s)
                what += (what.empty() ? "" : " ") + a;
            return makeError(ErrorCode::Device, "inserting the notch after " + axis.pid + " failed at '" + what +
                                                    "' (removed again): " + r.error().detail);
        }
    }
    // The component computes its coefficients on the enable edge in the next period; valid says whether it could.
    waitPeriods(axis.periodNs);
    auto valid = runHalcmd(options, {"getp", notch + ".valid"});
    if (!valid || valid->find("TRUE") == std::string::npos) {
        (void)removeNotch(options);
        return makeError(ErrorCode::Device, "LinuxCNC's biquad refused the notch at " + num(f0Hz) + " Hz, Q " + num(q) +
                                                " (valid is FALSE); it was removed again");
    }
    return Status::success();
}

Status removeLeftoverInjection(const HalSessionOptions& options)
{
    auto ps = pins(options);
    if (!ps)
        return ps.error();
    const HalPin* injOut = findPin(*ps, std::string(kInject) + ".out");
    if (!injOut)
        return {};
    auto sigs = signals(options);
    if (!sigs)
        return sigs.error();
    std::vector<std::vector<std::string>> cmds;
    cmds.push_back({"setp", std::string(kInject) + ".enable", "0"});
    // The PID output sits on axistune-pid-out; its drive net is the one the injection writes.
    const HalSignal* pidOut = findSignal(*sigs, kPidOutNet);
    if (pidOut && !pidOut->writer.empty() && !injOut->signal.empty()) {
        cmds.push_back({"unlinkp", std::string(kInject) + ".out"});
        cmds.push_back({"unlinkp", pidOut->writer});
        cmds.push_back({"linkps", pidOut->writer, injOut->signal});
    }
    // A move's injection: the pid's command sits on axistune-cmd, the NC's command net feeds the injection's input.
    // The offset first returns to zero at the component's return speed (it does so by itself once disarmed).
    const HalSignal* cmdNet = findSignal(*sigs, kCommandNet);
    const HalPin* injIn = findPin(*ps, std::string(kInject) + ".in");
    if (cmdNet && injIn && !injIn->signal.empty()) {
        if (auto st = runHalcmd(options, cmds.front()); !st)
            return st.error();
        auto rateText = runHalcmd(options, {"getp", std::string(kInject) + ".rate"});
        auto parsedRate =
            rateText ? model::parseNumber(std::string_view(*rateText).substr(0, rateText->find_first_of(" \n")))
                     : std::optional<double>();
        const double rate = parsedRate ? *parsedRate : 0.0;
        const double held = std::abs(pinNumber(*ps, std::string(kInject) + ".injected"));
        if (auto st = waitOffsetReturned(options, rate > 0.0 ? held / rate + 1.0 : 1.0); !st)
            return st;
        cmds.push_back({"unlinkp", std::string(kInject) + ".in"});
        for (const auto& reader : cmdNet->readers) {
            cmds.push_back({"unlinkp", reader});
            cmds.push_back({"linkps", reader, injIn->signal});
        }
    }
    for (const auto& s : *sigs)
        if (s.name.rfind("axistune-", 0) == 0)
            cmds.push_back({"delsig", s.name});
    // Off the thread first; unloaded two periods later (see HalInjection::remove).
    auto ts = threads(options);
    if (!ts)
        return ts.error();
    std::int64_t longestPeriod = 0;
    const bool ours[] = {true, findSignal(*sigs, kExcNet) != nullptr, findSignal(*sigs, kValidNet) != nullptr};
    const char* fns[] = {kInject, "streamer.0", "sampler.0"};
    for (const auto& t : *ts)
        for (std::size_t i = 0; i < 3; ++i)
            if (ours[i] && std::find(t.functions.begin(), t.functions.end(), fns[i]) != t.functions.end()) {
                cmds.push_back({"delf", fns[i], t.name});
                longestPeriod = std::max(longestPeriod, t.periodNs);
            }
    for (const auto& c : cmds)
        if (auto r = runHalcmd(options, c); !r)
            return makeError(ErrorCode::Device, "removing a leftover AxisTune injection failed: " + r.error().detail);
    cmds.clear();
    waitPeriods(longestPeriod);
    cmds.push_back({"unloadrt", "axistune_inject"});
    // streamer and sampler are AxisTune's when they feed AxisTune's nets.
    if (findPin(*ps, "streamer.0.pin.0") && findSignal(*sigs, kExcNet))
        cmds.push_back({"unloadrt", "streamer"});
    if (findPin(*ps, "sampler.0.pin.0") && findSignal(*sigs, kValidNet) && !HalSamplerModule::heldByThisProcess())
        cmds.push_back({"unloadrt", "sampler"});
    for (const auto& c : cmds)
        if (auto r = runHalcmd(options, c); !r)
            return makeError(ErrorCode::Device, "removing a leftover AxisTune injection failed: " + r.error().detail);
    return {};
}

Result<HalRecord> runExcitation(HalClient& client, HalInjection& injection, std::span<const double> excitation,
                                const HalRunControl& control)
{
    const auto& o = injection.options();
    const auto& s = injection.settings();
    const std::string inj = kInject;
    if (excitation.empty())
        return makeError(ErrorCode::BadInput, "empty excitation");
    double peak = 0.0;
    for (double v : excitation) {
        if (!std::isfinite(v))
            return makeError(ErrorCode::BadInput, "the excitation holds a value that is not a finite number");
        peak = std::max(peak, std::abs(v));
    }
    if (peak > s.limit)
        return makeError(ErrorCode::OutOfRange,
                         "excitation peak " + num(peak) + " exceeds the injection limit " + num(s.limit));

    auto writer = HalStream::attach(client, HalStream::Direction::ToHal, kStreamerKey, "fb");
    if (!writer)
        return writer.error();
    auto reader = HalStream::attach(client, HalStream::Direction::FromHal, kSamplerKey, kTestSamplerTypes);
    if (!reader)
        return reader.error();
    // The heartbeat must be seen before the injection is armed (the component latches a missing beat).
    std::this_thread::sleep_for(std::chrono::duration<double>(2.0 * s.heartbeatTimeoutS));
    // Rows recorded before this excitation (none, unless an earlier run left some) are not part of it.
    {
        std::vector<double> stale;
        std::uint32_t n = 0;
        while ((*reader)->read(stale, n)) {
        }
    }
    if (auto r = runHalcmd(o, {"setp", inj + ".enable", "1"}); !r)
        return r.error();
    auto disarm = [&] { (void)runHalcmd(o, {"setp", inj + ".enable", "0"}); };

    HalRecord rec;
    rec.sampleRateHz = 1e9 / static_cast<double>(injection.axis().periodNs);
    rec.columns.assign(kHalColumns, {});
    for (auto& c : rec.columns)
        c.reserve(excitation.size());
    const int underrunsBefore = (*writer)->underruns();
    std::size_t written = 0, read = 0;
    std::uint32_t last = 0;
    std::vector<double> row;
    const double rowsEnd[2] = {0.0, 0.0};
    bool endWritten = false;
    auto nextCheck = std::chrono::steady_clock::now();
    // A HAL session that stops (or a thread that no longer runs) delivers no rows: after this long without one the
    // test fails instead of waiting forever. 1 s was too short on the 2-core machine at load 7 (a non-realtime servo
    // thread starved that long); the injection's own heartbeat watchdog is what keeps the axis safe meanwhile.
    const auto stallLimit = std::max(std::chrono::nanoseconds(std::chrono::seconds(3)),
                                     std::chrono::nanoseconds(200 * injection.axis().periodNs));
    auto lastRow = std::chrono::steady_clock::now();
    double lastProgress = -1.0;
    while (read < excitation.size()) {
        if (control.abort && control.abort->load()) {
            disarm();
            return makeError(ErrorCode::Aborted, "aborted; the injection was removed from " + injection.axis().pid);
        }
        bool moved = false;
        while (written < excitation.size() && (*writer)->writable()) {
            const double r[2] = {excitation[written], 1.0};
            if (!(*writer)->write(r))
                break;
            ++written;
            moved = true;
        }
        if (written == excitation.size() && !endWritten && (*writer)->writable())
            endWritten = (*writer)->write(rowsEnd);
        std::uint32_t n = 0;
        while (read < excitation.size() && (*reader)->read(row, n)) {
            if (read > 0 && n != last + 1) {
                disarm();
                return makeError(ErrorCode::Device, "lost " + std::to_string(static_cast<long long>(n) - last - 1) +
                                                        " rows of the HAL sampler after sample " +
                                                        std::to_string(last) +
                                                        " (AxisTune did not read the FIFO in time)");
            }
            if (read == 0)
                rec.firstSample = n;
            last = n;
            for (std::size_t c = 0; c < kHalColumns; ++c)
                rec.columns[c].push_back(row[c]);
            ++read;
            moved = true;
            lastRow = std::chrono::steady_clock::now();
        }
        if (written < excitation.size() && (*writer)->underruns() != underrunsBefore) {
            disarm();
            return makeError(ErrorCode::Device, "the HAL streamer ran empty after " + std::to_string(written) +
                                                    " rows: AxisTune did not keep the excitation coming in time");
        }
        const auto now = std::chrono::steady_clock::now();
        if (now - lastRow > stallLimit) {
            disarm();
            return makeError(ErrorCode::Device, "the HAL sampler delivered no row for " +
                                                    num(std::chrono::duration<double>(now - lastRow).count()) +
                                                    " s: the HAL session stopped or " + injection.axis().thread +
                                                    " no longer runs");
        }
        if (now >= nextCheck) {
            nextCheck = now + std::chrono::milliseconds(10);
            auto trip = client.readPin(inj + ".trip");
            if (trip && *trip != 0.0) {
                disarm();
                const int t = static_cast<int>(*trip);
                const char* why = t == 1   ? "the heartbeat was lost"
                                  : t == 2 ? "the excitation exceeded its limit"
                                           : "the following error exceeded maxerror";
                return makeError(ErrorCode::Safety,
                                 std::string("the injection tripped: ") + why + "; the test was stopped");
            }
            const double p = static_cast<double>(read) / static_cast<double>(excitation.size());
            if (control.progress && p > lastProgress) {
                control.progress(p);
                lastProgress = p;
            }
        }
        if (!moved)
            std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
    disarm();
    if (control.progress)
        control.progress(1.0);
    return rec;
}

} // namespace axistune::device::hal

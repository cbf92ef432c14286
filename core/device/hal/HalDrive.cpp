// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/hal/HalDrive.h"

#include "core/device/FrfQuantityName.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/sim/MotionProfile.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <unistd.h>

namespace axistune::device::hal {
namespace {

const std::string kScheme = "hal:";
constexpr const char* kInject = "axistune-inject";

std::string num(double v)
{
    return model::formatShortest(v);
}

struct PidPin {
    const char* key;
    const char* label;
    double minimum;
    const char* description;
};

// output = bias + P·e + I·∫e + D·ė + FF0·cmd + FF1·ċmd + FF2·c̈md + FF3·c⃛md (LinuxCNC's pid, 2.9). Units are the
// HAL's: "output" is the PID output's unit (torque, current or velocity command), "position" the command's.
constexpr double kGainMax = 1e9;
const PidPin kPidPins[] = {
    {"Pgain", "Proportional gain P", 0.0, "output per unit of following error"},
    {"Igain", "Integral gain I", 0.0, "output per (following error · s)"},
    {"Dgain", "Derivative gain D", 0.0, "output per (following error / s)"},
    {"FF0", "Feedforward FF0", -kGainMax, "output per unit of position command"},
    {"FF1", "Velocity feedforward FF1", -kGainMax, "output per (position command / s)"},
    {"FF2", "Acceleration feedforward FF2", -kGainMax, "output per (position command / s²)"},
    {"FF3", "Jerk feedforward FF3", -kGainMax, "output per (position command / s³)"},
    {"bias", "Output bias", -kGainMax, "constant added to the output"},
    {"deadband", "Deadband", 0.0, "following error below which the error counts as zero"},
    {"maxerror", "Error limit", 0.0, "largest following error the P term sees; 0: no limit"},
    {"maxerrorI", "Integrator limit", 0.0, "largest integrated error; 0: no limit"},
    {"maxerrorD", "Error-rate limit", 0.0, "largest error rate the D term sees; 0: no limit"},
    {"maxoutput", "Output limit", 0.0, "largest |output|; 0: no limit (AxisTune then refuses tests)"},
};

Result<std::vector<HalPin>> pinsOf(const HalSessionOptions& o, const std::string& prefix)
{
    auto text = runHalcmd(o, {"-s", "show", "pin", prefix});
    if (!text)
        return text.error();
    return parsePins(*text);
}

Status noTestRunning(const TestStatus& s, const char* what)
{
    if (s.state == TestState::Running)
        return makeError(ErrorCode::Safety, std::string(what) + " refused: a test is running");
    return Status::success();
}

} // namespace

Result<HalSessionOptions> halSessionFromEnvironment()
{
    // AXISTUNE_HALCMD: the halcmd command line, words separated by blanks (scripts/hal-testbed halcmd for the
    // repository's test machine run as root, docs/linuxcnc.md).
    HalSessionOptions o;
    const char* env = std::getenv("AXISTUNE_HALCMD");
    if (env && *env) {
        o.halcmd = splitWords(env);
        if (o.halcmd.empty())
            return makeError(ErrorCode::BadInput, "AXISTUNE_HALCMD is blank");
    }
    return o;
}

std::vector<model::ParameterMeta> pidParameterMetadata()
{
    std::vector<model::ParameterMeta> out;
    for (const auto& p : kPidPins) {
        model::ParameterMeta m;
        m.key = p.key;
        m.label = p.label;
        m.siUnit = "1";
        m.displayUnit = "1";
        m.minSi = p.minimum;
        m.maxSi = kGainMax;
        m.group = "pid";
        m.description = std::string(p.description) + " (HAL units)";
        out.push_back(std::move(m));
    }
    return out;
}

Result<HalFrfPlan> planHalFrf(const TestRequest& r, const HalAxis& axis)
{
    if (r.type() != TestType::Frf)
        return makeError(ErrorCode::BadInput,
                         std::string("hal: runs FRF, jog and step tests only (not ") + testTypeName(r.type()) + ")");
    const auto& f = r.frf();
    if (f.method != FrfMethod::Multisine && f.method != FrfMethod::MultiSweep && f.method != FrfMethod::Prbs)
        return makeError(ErrorCode::BadInput,
                         std::string("hal: measures FRFs by multisine, multi-sweep or PRBS (not ") +
                             frfMethodName(f.method) + ")");
    if (!(axis.periodNs > 0))
        return makeError(ErrorCode::BadInput, axis.thread + " has no period");
    HalFrfPlan plan;
    plan.axis = axis;
    plan.method = f.method;
    plan.quantity = f.quantity == FrfQuantity::OpenLoop ? FrfQuantity::OpenLoop : FrfQuantity::Plant;
    plan.fsHz = 1e9 / static_cast<double>(axis.periodNs);
    if (!(axis.maxOutput > 0.0))
        return makeError(ErrorCode::Safety, axis.pid + ".maxoutput is 0 (no output limit): AxisTune bounds its "
                                                       "excitation by half of it; set maxoutput first");
    double peak = 0.0;
    if (f.amplitudePeak != 0.0) {
        if (!std::isfinite(f.amplitudePeak) || !(f.amplitudePeak > 0.0))
            return makeError(ErrorCode::OutOfRange, "FRF peak must be a positive number in the PID output's units");
        peak = f.amplitudePeak;
    } else {
        if (!std::isfinite(f.amplitudePct) || !(f.amplitudePct > 0.0))
            return makeError(ErrorCode::OutOfRange, "FRF amplitude must be a positive % of " + axis.pid + ".maxoutput");
        peak = f.amplitudePct / 100.0 * axis.maxOutput;
    }
    if (peak > HalDrive::kMaxAmplitudePct / 100.0 * axis.maxOutput)
        return makeError(ErrorCode::OutOfRange, "FRF peak " + num(peak) + " refused: at most half of " + axis.pid +
                                                    ".maxoutput (" + num(0.5 * axis.maxOutput) + ")");
    if (f.method != FrfMethod::Multisine)
        return planHalStreams(r, std::move(plan), peak);
    dsp::MultisineDesignOptions mo;
    mo.fsHz = plan.fsHz;
    mo.ticksPerSample = 1;
    mo.peak = peak;
    mo.phases = f.multisinePhases;
    mo.shape = f.multisineShape;
    mo.crestThrough = f.multisineCrestThrough;
    if (!f.multisineBands.empty()) {
        mo.bands = f.multisineBands;
    } else {
        if (!(f.fminHz > 0.0) || !std::isfinite(f.fminHz) || !(f.fmaxHz > f.fminHz) || !std::isfinite(f.fmaxHz))
            return makeError(ErrorCode::OutOfRange, "FRF band: fmin must be positive and below fmax");
        const double spacing = f.multisineSpacingHz > 0.0 ? f.multisineSpacingHz : f.fminHz / 2.0;
        mo.bands = {{f.fminHz, f.fmaxHz, spacing}};
    }
    // The excitation is generated at the servo rate and the plant input is seen only there: a line above half the
    // rate would fold onto another.
    for (const auto& b : mo.bands)
        if (!(b.fmaxHz < 0.5 * plan.fsHz))
            return makeError(ErrorCode::OutOfRange, "FRF band up to " + num(b.fmaxHz) +
                                                        " Hz refused: lines must lie below half the servo rate (" +
                                                        num(0.5 * plan.fsHz) + " Hz on " + axis.thread + ")");
    auto design = dsp::designMultisine(mo);
    if (!design)
        return design.error();
    plan.design = std::move(*design);
    const double periodS = static_cast<double>(plan.design.periodSamples()) / plan.fsHz;
    if (f.multisinePeriods < 0 || f.multisinePeriods > 1000)
        return makeError(ErrorCode::OutOfRange, "multisine periods must lie in 1..1000");
    plan.periods = f.multisinePeriods > 0 ? static_cast<std::size_t>(f.multisinePeriods) : 3;
    if (!(f.settleS >= 0.0) || !std::isfinite(f.settleS))
        return makeError(ErrorCode::OutOfRange, "FRF settle time must not be negative");
    plan.settlePeriods = f.settleS > 0.0 ? static_cast<std::size_t>(std::ceil(f.settleS / periodS)) : 1;
    const double motion = static_cast<double>(plan.totalSamples()) / plan.fsHz;
    if (motion > HalDrive::kMaxTestS)
        return makeError(ErrorCode::OutOfRange, "FRF test of " + num(motion) + " s refused: at most " +
                                                    num(HalDrive::kMaxTestS) + " s (fewer periods or a wider spacing)");
    return plan;
}

namespace {
Result<FrfMeasurement> evaluateHalMultisine(const HalFrfPlan& plan, const HalRecord& record);
} // namespace

Result<FrfMeasurement> evaluateHalFrf(const HalFrfPlan& plan, const HalRecord& record)
{
    const std::size_t n = plan.totalSamples();
    if (record.columns.size() != kHalColumns || record.columns[DriveInput].size() != n ||
        record.columns[Feedback].size() != n || record.columns[PidOutput].size() != n)
        return makeError(ErrorCode::Internal, "HAL record does not match the plan");
    const bool openLoop = plan.quantity == FrfQuantity::OpenLoop;
    Result<FrfMeasurement> measured =
        plan.streams ? evaluateHalStreams(plan, record) : evaluateHalMultisine(plan, record);
    if (!measured)
        return measured.error();
    FrfMeasurement out = std::move(measured).value();
    out.motionTimeS = static_cast<double>(n) / plan.fsHz;
    auto& md = out.frf.metadata;
    md.set(model::meta::kMethod, frfMethodName(plan.method));
    md.set(model::meta::kFsHz, plan.fsHz);
    md.set(model::meta::kQuantity,
           std::string(frfQuantityMetadataName(openLoop ? FrfQuantity::OpenLoop : FrfQuantity::Plant)));
    md.set(model::meta::kInput, "drive_input"); // <pid>.output + injection: what the drive receives
    md.set(model::meta::kOutput, openLoop ? "-pid_output" : "feedback");
    md.set(model::meta::kHalUnits,
           openLoop ? "none (PID output per PID output)" : "feedback per PID-output unit (the configuration's units)");
    md.set(model::meta::kPid, plan.axis.pid);
    md.set(model::meta::kThread, plan.axis.thread);
    md.set("servo_period_ns", static_cast<double>(plan.axis.periodNs));
    md.set(model::meta::kAmplitudePeak, plan.peak());
    md.set("first_sample", static_cast<double>(record.firstSample));
    md.set(model::meta::kMotionTimeS, out.motionTimeS);
    return out;
}

namespace {
/// The multisine part of evaluateHalFrf: dsp::analyzeMultisine over the averaged periods.
Result<FrfMeasurement> evaluateHalMultisine(const HalFrfPlan& plan, const HalRecord& record)
{
    const std::size_t skip = plan.settlePeriods * plan.design.periodSamples();
    const std::size_t len = plan.periods * plan.design.periodSamples();
    const std::span<const double> u(record.columns[DriveInput].data() + skip, len);
    const bool openLoop = plan.quantity == FrfQuantity::OpenLoop;
    std::vector<double> minusPid;
    if (openLoop) {
        minusPid.resize(len);
        for (std::size_t i = 0; i < len; ++i)
            minusPid[i] = -record.columns[PidOutput][skip + i];
    }
    const std::span<const double> y = openLoop ? std::span<const double>(minusPid)
                                               : std::span<const double>(record.columns[Feedback].data() + skip, len);
    auto a = dsp::analyzeMultisine(plan.design, u, y, plan.periods);
    if (!a)
        return a.error();
    FrfMeasurement out;
    out.frf = std::move(a->frf);
    out.relativeNoise = std::move(a->stats.relativeNoise);
    auto& md = out.frf.metadata;
    md.set("amplitude_rms", plan.design.rms);
    md.set(model::meta::kSettleS, static_cast<double>(skip) / plan.fsHz);
    md.set(model::meta::kPeriodS, static_cast<double>(plan.design.periodSamples()) / plan.fsHz);
    return out;
}
} // namespace

Result<std::unique_ptr<HalDrive>> HalDrive::open(const HalSessionOptions& options)
{
    std::unique_ptr<HalDrive> d(new HalDrive(options));
    auto names = d->pidNames();
    if (!names)
        return makeError(names.error().code, "no HAL session answers: " + names.error().detail);
    // The installed LinuxCNC's version (HAL itself states none).
    HalSessionOptions var;
    var.halcmd = {"linuxcnc_var"};
    var.timeout = std::chrono::milliseconds(5000);
    auto version = runHalcmd(var, {"LINUXCNCVERSION"});
    const std::string first =
        version ? version->substr(0, std::min(version->find_first_of(" \t\r\n"), version->size())) : std::string();
    d->m_firmware = first.empty() ? "LinuxCNC (version not stated)" : "LinuxCNC " + first;
    return d;
}

HalDrive::~HalDrive()
{
    m_abort = true;
    joinWorker();
}

void HalDrive::joinWorker()
{
    if (m_worker.joinable())
        m_worker.join();
}

Result<std::vector<std::string>> HalDrive::pidNames() const
{
    auto text = runHalcmd(m_options, {"-s", "show", "thread"});
    if (!text)
        return text.error();
    auto threads = parseThreads(*text);
    if (!threads)
        return threads.error();
    if (threads->empty())
        return makeError(ErrorCode::Device, "HAL runs no thread: the HAL session has stopped (or its realtime was "
                                            "never started)");
    static const std::string suffix = ".do-pid-calcs";
    std::vector<std::string> names;
    for (const auto& t : *threads)
        for (const auto& f : t.functions)
            if (f.size() > suffix.size() && f.compare(f.size() - suffix.size(), suffix.size(), suffix) == 0)
                names.push_back(f.substr(0, f.size() - suffix.size()));
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

Status HalDrive::checkAxis(const std::string& axis) const
{
    auto names = pidNames();
    if (!names)
        return names.error();
    if (std::find(names->begin(), names->end(), axis) == names->end()) {
        std::string list;
        for (const auto& n : *names)
            list += (list.empty() ? "" : ", ") + n;
        return makeError(ErrorCode::NotFound, "axis '" + axis + "': no pid of that name runs on a HAL thread (" +
                                                  (list.empty() ? std::string("none runs") : list) + ")");
    }
    return Status::success();
}

Result<DriveIdentity> HalDrive::identify()
{
    auto names = pidNames();
    if (!names)
        return names.error();
    DriveIdentity id;
    id.vendor = "LinuxCNC";
    id.model = "HAL session";
    id.firmware = m_firmware;
    id.machine = "hal";
    id.axes = *names;
    return id;
}

Result<std::vector<model::ParameterMeta>> HalDrive::parameterMetadata(const std::string& axis)
{
    if (auto st = checkAxis(axis); !st)
        return st.error();
    auto ps = pinsOf(m_options, axis + ".");
    if (!ps)
        return ps.error();
    std::vector<model::ParameterMeta> out;
    for (auto& m : pidParameterMetadata())
        if (findPin(*ps, axis + "." + m.key))
            out.push_back(std::move(m));
    return out;
}

Result<model::ParameterValues> HalDrive::readParameters(const std::string& axis, std::span<const std::string> keys)
{
    auto ps = pinsOf(m_options, axis + ".");
    if (!ps)
        return ps.error();
    const auto metas = pidParameterMetadata();
    std::vector<std::string> all; // no keys: every parameter the pid has
    if (keys.empty()) {
        for (const auto& m : metas)
            if (findPin(*ps, axis + "." + m.key))
                all.push_back(m.key);
        keys = all;
    }
    model::ParameterValues out;
    for (const auto& k : keys) {
        if (!model::findParameter(metas, k))
            return makeError(ErrorCode::NotFound,
                             "axis " + axis + ": no parameter '" + k + "' (hal: offers the pid's gains)");
        const HalPin* p = findPin(*ps, axis + "." + k);
        if (!p)
            return makeError(ErrorCode::NotFound, "axis " + axis + ": HAL has no pin " + axis + "." + k);
        // halcmd prints floats with seven significant digits (writeParameters compares at that precision).
        auto x = model::parseNumber(p->value);
        if (!x)
            return makeError(ErrorCode::Device, "halcmd shows " + axis + "." + k + " as '" + p->value + "'");
        out[k] = *x;
    }
    return out;
}

Status HalDrive::writeParameters(const std::string& axis, const model::ParameterValues& values)
{
    {
        std::lock_guard lock(m_mutex);
        if (auto st = noTestRunning(m_status, "parameter write"); !st)
            return st;
    }
    auto metas = parameterMetadata(axis);
    if (!metas)
        return metas.error();
    std::vector<std::string> keys;
    for (const auto& [k, v] : values) {
        const model::ParameterMeta* m = model::findParameter(*metas, k);
        if (!m)
            return makeError(ErrorCode::NotFound, "axis " + axis + ": no parameter '" + k + "'");
        if (auto st = model::checkParameterValue(*m, v); !st)
            return st;
        keys.push_back(k);
    }
    auto before = readParameters(axis, keys);
    if (!before)
        return before.error();
    // halcmd prints pins with seven significant digits: the read-back compares the value as printed.
    auto printed = [](double v) { return model::formatNumber(v, 7); };
    std::string failure;
    for (const auto& [k, v] : values) {
        const std::string pin = axis + "." + k;
        if (auto st = runHalcmd(m_options, {"setp", pin, num(v)}); !st) {
            failure = st.error().detail;
            break;
        }
        auto back = runHalcmd(m_options, {"getp", pin});
        if (!back) {
            failure = back.error().detail;
            break;
        }
        auto x = model::parseNumber(std::string_view(*back).substr(0, back->find_first_of(" \n")));
        if (!x || printed(*x) != printed(v)) {
            failure = pin + " reads back " + *back + " after setp " + num(v);
            break;
        }
    }
    if (failure.empty())
        return Status::success();
    // Put back what was there, so a refused write changes nothing.
    for (const auto& [k, v] : *before)
        (void)runHalcmd(m_options, {"setp", axis + "." + k, num(v)});
    return makeError(ErrorCode::Device, "parameter write on " + axis + " failed, values restored: " + failure);
}

Result<DriveCapabilities> HalDrive::capabilities(const std::string& axis)
{
    auto a = discoverAxis(m_options, axis);
    if (!a)
        return a.error();
    DriveCapabilities c;
    c.testTypes = {TestType::Frf, TestType::Jog, TestType::Step};
    c.frfMethods = {FrfMethod::Multisine, FrfMethod::MultiSweep, FrfMethod::Prbs};
    c.traceRateHz = a->periodNs > 0 ? 1e9 / static_cast<double>(a->periodNs) : 0.0;
    c.currentTraceRateHz = 0.0;
    c.evaluatesFrf = true;
    c.writesParameters = true;
    c.hasLink = true;
    c.frfPeakInOutputUnits = true;
    c.jogInCommandUnits = true;
    c.stepIsPositionStep = true;
    c.scope = true;
    c.frfQuantities = {FrfQuantity::Plant, FrfQuantity::OpenLoop};
    c.frfOutputSignal = a->pid + ".output";
    c.frfMaxHz = 0.5 * c.traceRateHz; // planHalFrf: every line below half the servo rate
    return c;
}

Result<DriveLimits> HalDrive::limits(const std::string& axis)
{
    if (auto st = checkAxis(axis); !st)
        return st.error();
    auto a = discoverAxis(m_options, axis); // its maxoutput bounds the FRF peak
    if (!a)
        return a.error();
    DriveLimits l;
    l.frfAmplitudeMaxPct = kMaxAmplitudePct;
    l.frfPeakMax = kMaxAmplitudePct / 100.0 * a->maxOutput; // planHalFrf's limit; 0 when maxoutput is 0 (no test)
    l.testDurationMaxS = kMaxTestS;
    return l;
}

Result<HalFrfPlan> HalDrive::plan(const TestRequest& request) const
{
    auto a = discoverAxis(m_options, request.axis);
    if (!a)
        return a.error();
    return planHalFrf(request, *a);
}

Result<HalMovePlan> HalDrive::movePlan(const TestRequest& request) const
{
    auto a = discoverAxis(m_options, request.axis);
    if (!a)
        return a.error();
    if (request.type() == TestType::Step)
        return planHalStep(request, *a, followingErrorTrip(*a));
    return planHalMove(request, *a);
}

double HalDrive::followingErrorTrip(const HalAxis& axis) const
{
    const auto f = m_ferror.find(axis.pid);
    const double ferror = f != m_ferror.end() ? f->second : 0.0;
    if (ferror > 0.0 && axis.maxError > 0.0)
        return std::min(ferror, axis.maxError);
    return ferror > 0.0 ? ferror : std::max(axis.maxError, 0.0);
}

Result<TestPlan> HalDrive::planTest(const TestRequest& request)
{
    if (request.type() == TestType::Jog || request.type() == TestType::Step) {
        auto move = movePlan(request);
        if (!move)
            return move.error();
        TestPlan p;
        p.traceRateHz = move->fsHz;
        p.recordSamples = move->offset.size();
        p.motionTimeS = static_cast<double>(p.recordSamples) / move->fsHz;
        return p;
    }
    auto plan = this->plan(request);
    if (!plan)
        return plan.error();
    TestPlan p;
    p.traceRateHz = plan->fsHz;
    p.recordSamples = plan->totalSamples();
    p.motionTimeS = static_cast<double>(p.recordSamples) / plan->fsHz;
    return p;
}

Status HalDrive::startTest(const TestRequest& request)
{
    return start(request, {}, 0.0);
}

Status HalDrive::startExternalJog(const TestRequest& request, double recordS, ExternalMove move)
{
    if (request.type() != TestType::Jog || !move)
        return makeError(ErrorCode::Internal, "startExternalJog: a jog and a mover");
    if (!(recordS > 0.0) || !(recordS <= kMaxTestS))
        return makeError(ErrorCode::OutOfRange, "a recorded move of " + num(recordS) + " s: at most " +
                                                    num(kMaxTestS) + " s");
    return start(request, std::move(move), recordS);
}

Status HalDrive::start(const TestRequest& request, ExternalMove external, double recordS)
{
    {
        std::lock_guard lock(m_mutex);
        if (auto st = noTestRunning(m_status, "test start"); !st)
            return st;
    }
    joinWorker();
    finishDeferredScopeStop();
    // The scope may run on: the test records through sampler.0, the scope through sampler.1 (HalSampler.h).
    std::optional<HalFrfPlan> frf;
    std::optional<HalMovePlan> move;
    if (request.type() == TestType::Jog || request.type() == TestType::Step) {
        auto m = movePlan(request);
        if (!m)
            return m.error();
        move = std::move(*m);
        if (external) {
            // Someone else moves the axis: AxisTune only records, its offset to the command held at 0.
            move->offset.assign(static_cast<std::size_t>(std::ceil(recordS * move->fsHz)) + 1, 0.0);
            move->external = true;
        }
    } else {
        auto f = this->plan(request);
        if (!f)
            return f.error();
        frf = std::move(*f);
    }
    // An injection already loaded is a test of another AxisTune, or one left behind by an AxisTune that died: an
    // armed one is not touched, a disarmed one (tripped, its heartbeat gone) is removed first.
    auto injPins = pinsOf(m_options, std::string(kInject) + ".");
    if (!injPins)
        return injPins.error();
    if (const HalPin* armed = findPin(*injPins, std::string(kInject) + ".armed")) {
        if (armed->value == "TRUE")
            return makeError(ErrorCode::Safety,
                             "another AxisTune is running a test on this HAL (" + std::string(kInject) + " is armed)");
        if (auto st = removeLeftoverInjection(m_options); !st)
            return st;
    }
    std::vector<double> excitation;
    InjectionSettings settings;
    HalAxis axis;
    if (frf) {
        excitation = frf->excitation();
        settings.limit = frf->peak();
        axis = frf->axis;
    } else {
        excitation = move->offset;
        settings.point = InjectionPoint::PidCommand;
        settings.limit = std::abs(move->distance) * (1.0 + 1e-9); // an external move's offset stays 0
        settings.returnRate = move->returnRate;
        axis = move->axis;
    }
    settings.maxError = followingErrorTrip(axis);
    m_plan = std::move(frf);
    m_move = std::move(move);
    m_record.reset();
    m_abort = false;
    {
        std::lock_guard lock(m_mutex);
        m_linkLost = false;
        m_status = TestStatus{TestState::Running, 0.0, ""};
    }
    m_worker = std::thread(
        [this, a = std::move(axis), settings, x = std::move(excitation), e = std::move(external)]() mutable {
            run(std::move(a), settings, std::move(x), std::move(e));
        });
    return Status::success();
}

void HalDrive::run(HalAxis axis, InjectionSettings settings, std::vector<double> excitation, ExternalMove external)
{
    auto finish = [&](TestState state, std::string detail) {
        // A failure after which HAL no longer answers, or no longer runs the axis's pid on a thread (a stopped
        // session whose shared memory AxisTune still holds), is a lost connection (pollTest reports it as such).
        bool lost = false;
        if (state == TestState::Faulted && !m_abort.load()) {
            auto names = pidNames();
            lost = !names || std::find(names->begin(), names->end(), axis.pid) == names->end();
        }
        std::lock_guard lock(m_mutex);
        m_linkLost = lost;
        m_status.state = state;
        m_status.detail = std::move(detail);
        if (state == TestState::Completed)
            m_status.progress = 1.0;
        m_changed.notify_all();
    };
    auto client = HalClient::open("axistune-" + std::to_string(::getpid()));
    if (!client)
        return finish(TestState::Faulted, client.error().detail);
    auto injection = HalInjection::insert(m_options, axis, settings, **client);
    if (!injection)
        return finish(TestState::Faulted, injection.error().detail);
    HalRunControl control;
    control.abort = &m_abort;
    control.progress = [this](double p) {
        std::lock_guard lock(m_mutex);
        m_status.progress = std::max(m_status.progress, std::min(p, 1.0));
        m_changed.notify_all();
    };
    // An external move runs beside the recording. It is stopped when the test is aborted or the record ends first;
    // when it fails, the recording stops too (through the abort flag) and the test fails with the move's reason.
    std::atomic<bool> stopMove{false}, moveDone{false}, moveFailed{false};
    Status moved = Status::success();
    std::thread mover;
    if (external)
        mover = std::thread([&] {
            moved = external(stopMove);
            if (!moved && !stopMove.load()) {
                moveFailed = true;
                m_abort = true;
            }
            moveDone = true;
        });
    auto record = runExcitation(**client, **injection, excitation, control);
    if (mover.joinable()) {
        const bool endedFirst = !moveDone.load();
        stopMove = true;
        mover.join();
        if (moveFailed)
            record = moved.error();
        else if (record && endedFirst)
            record = makeError(ErrorCode::Device, "the move did not end within the record of " +
                                                      num(static_cast<double>(excitation.size()) * 1e-9 *
                                                          static_cast<double>(axis.periodNs)) +
                                                      " s; it was stopped");
    }
    const Status removed = (*injection)->remove();
    if (!record) {
        const bool aborted = m_abort.load() && !moveFailed.load();
        return finish(aborted ? TestState::Aborted : TestState::Faulted,
                      record.error().detail + (removed ? "" : "; removing the injection: " + removed.error().detail));
    }
    if (!removed)
        return finish(TestState::Faulted, "removing the injection: " + removed.error().detail);
    m_record = std::move(*record);
    finish(TestState::Completed, "");
}

void HalDrive::setFollowingErrorLimit(const std::string& pid, double limit)
{
    if (limit > 0.0 && std::isfinite(limit))
        m_ferror[pid] = limit;
    else
        m_ferror.erase(pid);
}

Result<TestStatus> HalDrive::pollTest()
{
    std::unique_lock lock(m_mutex);
    if (m_status.state == TestState::Running)
        m_changed.wait_for(lock, std::chrono::milliseconds(20));
    const TestStatus s = m_status;
    const bool lost = m_linkLost;
    lock.unlock();
    if (s.state != TestState::Running) {
        joinWorker();
        finishDeferredScopeStop();
    }
    if (lost)
        return makeError(ErrorCode::Device, "connection hal: lost: " + s.detail);
    return s;
}

Status HalDrive::abortTest()
{
    m_abort = true;
    joinWorker();
    std::lock_guard lock(m_mutex);
    if (m_status.state == TestState::Running) {
        m_status.state = TestState::Aborted;
        m_status.detail = "aborted";
    }
    return Status::success();
}

Result<model::Capture> HalDrive::readTrace()
{
    {
        std::lock_guard lock(m_mutex);
        if (m_status.state != TestState::Completed || !m_record || !(m_plan || m_move))
            return makeError(ErrorCode::NotFound, "no trace: no test has completed");
    }
    model::Capture c;
    const std::size_t n = m_record->columns[DriveInput].size();
    const double fsHz = m_plan ? m_plan->fsHz : m_move->fsHz;
    const HalAxis& axis = m_plan ? m_plan->axis : m_move->axis;
    model::Channel t{"t_s", {}};
    t.data.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        t.data[i] = static_cast<double>(i) / fsHz;
    model::Channel sample{"sample", {}};
    sample.data.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        sample.data[i] = static_cast<double>(m_record->firstSample + static_cast<std::uint32_t>(i));
    c.channels.push_back(std::move(t));
    c.channels.push_back(std::move(sample));
    for (std::size_t col = 0; col < kHalColumns; ++col) {
        // A move: the injection is the position offset added to the command.
        const bool offset = m_move && col == Injection;
        c.channels.push_back({offset ? std::string("position_offset") : halColumnName(static_cast<HalColumn>(col)),
                              m_record->columns[col]});
    }
    auto& md = c.metadata;
    if (m_plan) {
        md.set(model::meta::kTest, "frf");
        md.set(model::meta::kMethod, frfMethodName(m_plan->method));
        md.set(model::meta::kAmplitudePeak, m_plan->peak());
    } else if (m_move->type == TestType::Step) {
        md.set(model::meta::kTest, "step");
        md.set("step", m_move->distance); // a position step of the command, in its units
        md.set("step_sample", static_cast<double>(m_move->stepAt));
        md.set("step_back_sample", static_cast<double>(m_move->backAt));
    } else {
        md.set(model::meta::kTest, "jog");
        md.set("distance", m_move->distance);
        md.set("velocity", m_move->velocity);
        md.set("moved_by", m_move->external ? "LinuxCNC's motion (a joint jog through NML)"
                                            : "AxisTune's offset to the pid's command");
    }
    md.set(model::meta::kAxis, axis.pid);
    md.set(model::meta::kFsHz, fsHz);
    md.set(model::meta::kHalUnits, "the configuration's (PID output and position units)");
    md.set(model::meta::kThread, axis.thread);
    md.set(model::meta::kMotionTimeS, static_cast<double>(n) / fsHz);
    return c;
}

Result<FrfMeasurement> HalDrive::readFrequencyResponse()
{
    {
        std::lock_guard lock(m_mutex);
        if (m_status.state != TestState::Completed || !m_record || !m_plan)
            return makeError(ErrorCode::NotFound, "no frequency response: no FRF test has completed");
    }
    return evaluateHalFrf(*m_plan, *m_record);
}

} // namespace axistune::device::hal

namespace axistune::device {

DriveBackend halBackend()
{
    using namespace hal;
    DriveBackend b;
    b.scheme = kScheme;
    b.label = AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "LinuxCNC HAL session");
    b.uriForm = "hal:";
    b.description = AXISTUNE_TRANSLATE_NOOP(
        "DriveRegistry", "Attaches to the running HAL session of LinuxCNC (or a bare HAL loop): an axis is a pid "
                         "instance, units are the HAL's; halcmd from AXISTUNE_HALCMD (docs/linuxcnc.md).");
    b.uriFromSettings = [b](const SettingValues& v) -> Result<std::string> {
        if (auto st = checkSettings(b, v); !st)
            return st.error();
        return kScheme;
    };
    b.open = [](const ConnectionSettings& s) -> Result<std::unique_ptr<Drive>> {
        if (s.uri != kScheme)
            return makeError(ErrorCode::BadInput, "connection '" + s.uri + "': expected hal: (nothing after it)");
        auto o = halSessionFromEnvironment();
        if (!o)
            return o.error();
        auto d = HalDrive::open(*o);
        if (!d)
            return makeError(d.error().code, "connection '" + s.uri + "': " + d.error().detail);
        return std::unique_ptr<Drive>(std::move(d).value());
    };
    return b;
}

} // namespace axistune::device

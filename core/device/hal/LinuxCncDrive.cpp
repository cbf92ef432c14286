// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/hal/LinuxCncDrive.h"

#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/sim/MotionProfile.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <thread>

namespace axistune::device::hal {
namespace {

const std::string kScheme = "linuxcnc:";
constexpr double kMotionJogMarginS = 1.0; ///< a jog through motion: the task's replies and settling in position [s]

std::string axisList(const std::vector<std::pair<std::string, std::string>>& axes)
{
    std::string out;
    for (const auto& [name, pid] : axes)
        out += (out.empty() ? "" : ", ") + name + " (" + pid + ")";
    return out.empty() ? std::string("none") : out;
}

} // namespace

std::string linuxCncAxisName(const PidInstance& pid)
{
    if (!pid.axisLetter.empty())
        return pid.axisLetter;
    if (pid.joint >= 0)
        return "joint" + std::to_string(pid.joint);
    return pid.name;
}

Result<std::unique_ptr<LinuxCncDrive>> LinuxCncDrive::open(const std::string& iniPath, const HalSessionOptions& options)
{
    auto cfg = readLinuxCncConfig(iniPath);
    if (!cfg)
        return cfg.error();
    auto hal = HalDrive::open(options);
    if (!hal)
        return hal.error();
    auto id = (*hal)->identify();
    if (!id)
        return id.error();
    std::unique_ptr<LinuxCncDrive> d(new LinuxCncDrive);
    d->m_config = std::move(cfg).value();
    d->m_hal = std::move(hal).value();
    std::vector<const PidInstance*> pids;
    for (const auto& p : d->m_config.pids)
        pids.push_back(&p);
    std::stable_sort(pids.begin(), pids.end(), [](const PidInstance* a, const PidInstance* b) {
        return (a->joint < 0 ? 1000 : a->joint) < (b->joint < 0 ? 1000 : b->joint);
    });
    for (const PidInstance* p : pids) {
        if (std::find(id->axes.begin(), id->axes.end(), p->name) == id->axes.end())
            continue;
        d->m_axes.emplace_back(linuxCncAxisName(*p), p->name);
        // The joint's FERROR (LinuxCNC's following-error limit at speed) also trips AxisTune's injection.
        if (p->joint >= 0) {
            const IniEntry* ferror = d->m_config.ini.find("JOINT_" + std::to_string(p->joint), "FERROR");
            if (ferror) {
                auto v = model::parseNumber(ferror->value);
                if (!v || !(*v > 0.0))
                    return makeError(ErrorCode::BadInput, iniPath + ":" + std::to_string(ferror->line) + ": [JOINT_" +
                                                              std::to_string(p->joint) + "]FERROR '" + ferror->value +
                                                              "' is not a positive number");
                d->m_hal->setFollowingErrorLimit(p->name, *v);
            }
        }
    }
    if (d->m_axes.empty()) {
        std::string configured;
        for (const auto& p : d->m_config.pids)
            configured += (configured.empty() ? "" : ", ") + p.name;
        return makeError(ErrorCode::NotFound, iniPath + ": none of its pid instances (" +
                                                  (configured.empty() ? std::string("none") : configured) +
                                                  ") runs in the HAL session: is LinuxCNC running from this INI?");
    }
    const IniEntry* machine = d->m_config.ini.find("EMC", "MACHINE");
    d->m_machine = machine && !machine->value.empty() ? machine->value : std::filesystem::path(iniPath).stem().string();
    return d;
}

Result<std::string> LinuxCncDrive::pidOf(const std::string& axis) const
{
    for (const auto& [name, pid] : m_axes)
        if (name == axis)
            return pid;
    return makeError(ErrorCode::NotFound,
                     "axis '" + axis + "': not an axis of " + m_config.ini.path + " (" + axisList(m_axes) + ")");
}

Result<TestRequest> LinuxCncDrive::onPid(const TestRequest& request) const
{
    auto pid = pidOf(request.axis);
    if (!pid)
        return pid.error();
    TestRequest r = request;
    r.axis = *pid;
    return r;
}

Result<DriveIdentity> LinuxCncDrive::identify()
{
    auto id = m_hal->identify();
    if (!id)
        return id.error();
    DriveIdentity out;
    out.vendor = id->vendor;
    out.model = "LinuxCNC configuration";
    out.firmware = id->firmware;
    out.machine = m_machine;
    for (const auto& [name, pid] : m_axes)
        out.axes.push_back(name);
    return out;
}

Result<std::vector<model::ParameterMeta>> LinuxCncDrive::parameterMetadata(const std::string& axis)
{
    auto pid = pidOf(axis);
    if (!pid)
        return pid.error();
    auto read = m_hal->parameterMetadata(*pid);
    if (!read)
        return read.error();
    auto metas = std::move(read).value();
    // Where each gain comes from: the INI key Persist writes, or the HAL file that holds it as a literal.
    if (const PidInstance* p = m_config.findPid(*pid)) {
        for (auto& m : metas) {
            const auto g = p->gains.find(m.key);
            if (g == p->gains.end())
                continue;
            if (!g->second.key.empty())
                m.description += "; INI [" + g->second.section + "]" + g->second.key;
            else
                m.description += "; a literal in " + g->second.halFile + ":" + std::to_string(g->second.halLine);
        }
    }
    return metas;
}

Result<model::ParameterValues> LinuxCncDrive::readParameters(const std::string& axis, std::span<const std::string> keys)
{
    auto pid = pidOf(axis);
    if (!pid)
        return pid.error();
    return m_hal->readParameters(*pid, keys);
}

Status LinuxCncDrive::writeParameters(const std::string& axis, const model::ParameterValues& values)
{
    auto pid = pidOf(axis);
    if (!pid)
        return pid.error();
    return m_hal->writeParameters(*pid, values);
}

Status LinuxCncDrive::startTest(const TestRequest& request)
{
    auto r = onPid(request);
    if (!r)
        return r.error();
    m_lastAxis = request.axis;
    // A jog of a joint goes through LinuxCNC's own motion where a LinuxCNC task answers on the configuration's NML
    // channels (a full LinuxCNC); on a bare HAL loop started from the INI it is AxisTune's offset to the pid's command,
    // as on hal: (the trace's `moved_by` says which).
    auto viaMotion = motionJog(*r);
    if (!viaMotion)
        return viaMotion.error();
    if (*viaMotion) {
        const MotionJog jog = **viaMotion;
        LinuxCncMotion* motion = m_motion.get();
        return m_hal->startExternalJog(
            jog.request, jog.recordS, [motion, jog](const std::atomic<bool>& stop) -> Status {
                const JogTest& q = jog.request.jog();
                const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(q.dwellS);
                while (std::chrono::steady_clock::now() < until) {
                    if (stop.load())
                        return makeError(ErrorCode::Aborted, "aborted");
                    std::this_thread::sleep_for(std::chrono::milliseconds(5));
                }
                if (auto st = motion->jogIncrement(jog.joint, q.distance, q.velocity, stop, jog.moveTimeout); !st)
                    return st;
                return motion->jogIncrement(jog.joint, -q.distance, q.velocity, stop, jog.moveTimeout);
            });
    }
    return m_hal->startTest(*r);
}

Result<double> LinuxCncDrive::jointNumber(int joint, const char* key) const
{
    const std::string section = "JOINT_" + std::to_string(joint);
    const IniEntry* e = m_config.ini.find(section, key);
    if (!e)
        return makeError(ErrorCode::NotFound, m_config.ini.path + ": [" + section + "]" + key + " is not set");
    auto v = model::parseNumber(e->value);
    if (!v || !(*v > 0.0))
        return makeError(ErrorCode::BadInput, m_config.ini.path + ":" + std::to_string(e->line) + ": [" + section +
                                                  "]" + key + " '" + e->value + "' is not a positive number");
    return *v;
}

Result<std::optional<LinuxCncDrive::MotionJog>> LinuxCncDrive::motionJog(const TestRequest& r)
{
    if (r.type() != TestType::Jog)
        return std::optional<MotionJog>{};
    const PidInstance* pid = m_config.findPid(r.axis);
    if (!pid || pid->joint < 0)
        return std::optional<MotionJog>{};
    if (!m_motion) {
        const IniEntry* nml = m_config.ini.find("EMC", "NML_FILE");
        auto motion = LinuxCncMotion::open(nml ? nml->value : LinuxCncMotion::kDefaultNmlFile);
        if (!motion)
            return std::optional<MotionJog>{}; // no LinuxCNC task: a bare HAL loop from this INI
        m_motion = std::move(motion).value();
    }
    const int joint = pid->joint;
    // Motion jogs at the request's speed (at most the joint's MAX_VELOCITY) with the joint's own acceleration
    // (MAX_ACCELERATION): a request for a gentler acceleration cannot be honoured and is refused, never changed.
    auto maxVelocity = jointNumber(joint, "MAX_VELOCITY");
    if (!maxVelocity)
        return maxVelocity.error();
    auto acceleration = jointNumber(joint, "MAX_ACCELERATION");
    if (!acceleration)
        return acceleration.error();
    const std::string section = "[JOINT_" + std::to_string(joint) + "]";
    const JogTest& j = r.jog();
    if (j.velocity > *maxVelocity)
        return makeError(ErrorCode::OutOfRange, "jog velocity " + model::formatShortest(j.velocity) +
                                                    " refused: LinuxCNC's motion limits joint " +
                                                    std::to_string(joint) + " to " + section +
                                                    "MAX_VELOCITY = " + model::formatShortest(*maxVelocity));
    if (j.acceleration < *acceleration)
        return makeError(ErrorCode::OutOfRange,
                         "jog acceleration " + model::formatShortest(j.acceleration) +
                             " refused: LinuxCNC's motion jogs joint " + std::to_string(joint) + " with " + section +
                             "MAX_ACCELERATION = " + model::formatShortest(*acceleration) +
                             " and cannot jog more gently (ask for that acceleration or more; hal: moves with an "
                             "offset at any acceleration)");
    if (j.jerk > 0.0)
        return makeError(ErrorCode::BadInput, "a jerk limit cannot be asked of LinuxCNC's jog (it jogs a trapezoid)");
    if (!(j.dwellS >= 0.0) || !std::isfinite(j.dwellS))
        return makeError(ErrorCode::OutOfRange, "jog dwell must not be negative");
    // The request is checked first (the same answer whatever state the machine is in), then the machine.
    auto on = m_motion->machineOn();
    if (!on)
        return on.error();
    if (!*on)
        return makeError(ErrorCode::Safety, "LinuxCNC's machine is not on (E-stop or off): no jog");
    sim::MotionProfile profile;
    profile.dwell(j.dwellS);
    profile.move(j.distance, j.velocity, *acceleration);
    profile.move(-j.distance, j.velocity, *acceleration);
    profile.dwell(j.dwellS);
    MotionJog jog;
    jog.joint = joint;
    jog.request = r;
    // What motion uses; planHalMove checks the rest as for an offset move.
    jog.request.jog().acceleration = *acceleration;
    // The record: the move and its dwells, plus a second for the task's replies and the joint settling in position.
    jog.recordS = profile.duration() + kMotionJogMarginS;
    jog.moveTimeout =
        std::chrono::milliseconds(static_cast<long long>(1000.0 * (0.5 * profile.duration() + kMotionJogMarginS)));
    return std::optional<MotionJog>(jog);
}

Result<TestStatus> LinuxCncDrive::pollTest()
{
    auto s = m_hal->pollTest();
    if (!s)
        return makeError(s.error().code, kScheme + m_config.ini.path + ": " + s.error().detail);
    return s;
}

Result<model::Capture> LinuxCncDrive::readTrace()
{
    auto read = m_hal->readTrace();
    if (!read)
        return read;
    auto c = std::move(read).value();
    const auto* pid = c.metadata.find(model::meta::kAxis);
    c.metadata.set(model::meta::kPid, pid ? pid->text() : std::string());
    c.metadata.set(model::meta::kAxis, m_lastAxis);
    c.metadata.set(model::meta::kIni, m_config.ini.path);
    return c;
}

Status LinuxCncDrive::abortTest()
{
    return m_hal->abortTest();
}

Result<FrfMeasurement> LinuxCncDrive::readFrequencyResponse()
{
    auto read = m_hal->readFrequencyResponse();
    if (!read)
        return read;
    auto m = std::move(read).value();
    m.frf.metadata.set(model::meta::kAxis, m_lastAxis);
    m.frf.metadata.set(model::meta::kIni, m_config.ini.path);
    if (const IniEntry* u = m_config.ini.find("TRAJ", "LINEAR_UNITS"))
        m.frf.metadata.set("linear_units", u->value);
    return m;
}

Result<DriveCapabilities> LinuxCncDrive::capabilities(const std::string& axis)
{
    auto pid = pidOf(axis);
    if (!pid)
        return pid.error();
    return m_hal->capabilities(*pid);
}

Result<ScopeCapabilities> LinuxCncDrive::scopeCapabilities(const std::string& axis)
{
    auto pid = pidOf(axis);
    if (!pid)
        return pid.error();
    return m_hal->scopeCapabilities(*pid);
}

Status LinuxCncDrive::armScope(const ScopeRequest& request)
{
    auto pid = pidOf(request.axis);
    if (!pid)
        return pid.error();
    ScopeRequest r = request;
    r.axis = *pid;
    return m_hal->armScope(r);
}

Result<DriveLimits> LinuxCncDrive::limits(const std::string& axis)
{
    auto pid = pidOf(axis);
    if (!pid)
        return pid.error();
    return m_hal->limits(*pid);
}

Result<TestPlan> LinuxCncDrive::planTest(const TestRequest& request)
{
    auto r = onPid(request);
    if (!r)
        return r.error();
    auto viaMotion = motionJog(*r);
    if (!viaMotion)
        return viaMotion.error();
    if (*viaMotion)
        return m_hal->planExternalJog((*viaMotion)->request, (*viaMotion)->recordS);
    return m_hal->planTest(*r);
}

} // namespace axistune::device::hal

namespace axistune::device {

DriveBackend linuxcncBackend()
{
    using namespace hal;
    DriveBackend b;
    b.scheme = kScheme;
    b.label = AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "LinuxCNC machine (INI file)");
    b.uriForm = "linuxcnc:PATH/machine.ini";
    b.description = AXISTUNE_TRANSLATE_NOOP(
        "DriveRegistry",
        "Attaches to a LinuxCNC running from this INI: its joints' pid instances and the INI keys "
        "that feed their gains are read from its HAL files; axes by their letters (docs/linuxcnc.md).");
    setFileSetting(b, AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "INI file"),
                   AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "the INI LinuxCNC was started from"));
    b.open = [](const ConnectionSettings& s) -> Result<std::unique_ptr<Drive>> {
        const std::string path = s.uri.substr(kScheme.size());
        if (path.empty())
            return makeError(ErrorCode::BadInput, "connection '" + s.uri + "': expected linuxcnc:PATH/machine.ini");
        auto o = halSessionFromEnvironment();
        if (!o)
            return o.error();
        auto d = LinuxCncDrive::open(path, *o);
        if (!d)
            return makeError(d.error().code, "connection '" + s.uri + "': " + d.error().detail);
        return std::unique_ptr<Drive>(std::move(d).value());
    };
    return b;
}

} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
// The replay backend (ReplayDrive.h) and its registration.
#include "core/device/replay/ReplayDrive.h"

#include "core/device/DriveRegistry.h"
#include "core/io/CaptureCsv.h"
#include "core/model/MetadataKeys.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace axistune::device {
namespace {

const std::string kScheme = "replay:";

/// The test a capture records, from its "test" metadata (the names of `axistune-cli capture --test`
/// and of the drive's own trace metadata).
Result<TestType> recordedTest(const std::string& name)
{
    if (name == "step")
        return TestType::Step;
    if (name == "jog")
        return TestType::Jog;
    if (name == "hold")
        return TestType::Hold;
    if (name == "current-step" || name == "current_step")
        return TestType::CurrentStep;
    if (name == "circle")
        return TestType::Circle;
    return makeError(ErrorCode::BadInput,
                     "metadata test=" + name + " cannot be replayed (step, jog, hold, current-step or circle)");
}

/// The SI unit of a metadata key from its suffix ("fs_Hz" → Hz, "current_period_s" → s).
std::string unitOfKey(const std::string& key)
{
    for (const auto& [suffix, unit] : std::vector<std::pair<std::string, std::string>>{
             {"_Hz", "Hz"}, {"_s", "s"}, {"_A", "A"}, {"_Nm", "N*m"}, {"_m", "m"}, {"_rad_s", "rad/s"}}) {
        if (key.size() > suffix.size() && key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0)
            return unit;
    }
    return "";
}

constexpr const char* kParameterPrefix = "capture.";

} // namespace

Result<std::unique_ptr<ReplayDrive>> ReplayDrive::open(const std::string& path)
{
    auto cap = io::readCaptureCsvFile(path);
    if (!cap)
        return cap.error();
    std::unique_ptr<ReplayDrive> d(new ReplayDrive());
    d->m_path = path;
    d->m_capture = std::move(cap).value();
    const auto& md = d->m_capture.metadata;
    auto need = [&](model::TextKey key) -> Result<std::string> {
        auto text = md.text(key);
        if (!text || text->empty())
            return makeError(ErrorCode::BadInput, path + ": metadata '" + std::string(key.name) +
                                                      "' is missing: a replayed capture needs "
                                                      "test, axis and fs_Hz");
        return std::move(*text);
    };
    auto test = need(model::meta::kTest);
    if (!test)
        return test.error();
    auto type = recordedTest(*test);
    if (!type)
        return makeError(ErrorCode::BadInput, path + ": " + type.error().detail);
    auto axis = need(model::meta::kAxis);
    if (!axis)
        return axis.error();
    auto fs = md.number(model::meta::kFsHz);
    if (!fs || !(*fs > 0.0)) // number(): finite only
        return makeError(ErrorCode::BadInput, path + ": metadata 'fs_Hz' must be a positive number");
    if (d->m_capture.size() < 2)
        return makeError(ErrorCode::BadInput, path + ": the capture has fewer than 2 samples");
    d->m_test = *type;
    d->m_axis = *axis;
    d->m_fsHz = *fs;
    auto motion = md.optionalNumber(model::meta::kMotionTimeS);
    if (!motion)
        return makeError(ErrorCode::BadInput, path + ": " + motion.error().detail);
    d->m_motionS = motion->has_value() ? **motion : d->recordS();
    if (!(d->m_motionS > 0.0) || !std::isfinite(d->m_motionS))
        return makeError(ErrorCode::BadInput, path + ": metadata '" + std::string(model::meta::kMotionTimeS.name) +
                                                  "' must be a positive number of seconds");
    return d;
}

double ReplayDrive::recordS() const
{
    return static_cast<double>(m_capture.size()) / m_fsHz;
}

Status ReplayDrive::checkAxis(const std::string& axis) const
{
    if (axis != m_axis)
        return makeError(ErrorCode::NotFound,
                         "no axis '" + axis + "' in the replayed capture " + m_path + " (axis: " + m_axis + ")");
    return Status::success();
}

Status ReplayDrive::checkRequest(const TestRequest& request) const
{
    if (auto st = checkAxis(request.axis); !st)
        return st;
    if (request.type() != m_test)
        return makeError(ErrorCode::BadInput, std::string("replay ") + m_path + " recorded a " + testTypeName(m_test) +
                                                  " test; it cannot run a " + testTypeName(request.type()) + " test");
    return Status::success();
}

Result<DriveIdentity> ReplayDrive::identify()
{
    return DriveIdentity{
        "AxisTune", "replay", AXISTUNE_VERSION, m_capture.metadata.textOr(model::meta::kMachine, m_path), {m_axis}};
}

Result<std::vector<model::ParameterMeta>> ReplayDrive::parameterMetadata(const std::string& axis)
{
    if (auto st = checkAxis(axis); !st)
        return st.error();
    std::vector<model::ParameterMeta> out;
    for (const auto& [k, v] : m_capture.metadata) {
        auto x = v.number();
        if (!x)
            continue; // text metadata (machine, connection) is in identify()
        model::ParameterMeta m;
        m.key = kParameterPrefix + k;
        m.label = "Recorded " + k;
        m.siUnit = m.displayUnit = unitOfKey(k);
        m.minSi = m.maxSi = *x;
        m.writable = false;
        m.group = "capture";
        m.description = "metadata of the replayed capture " + m_path;
        out.push_back(std::move(m));
    }
    return out;
}

Result<model::ParameterValues> ReplayDrive::readParameters(const std::string& axis, std::span<const std::string> keys)
{
    auto metas = parameterMetadata(axis);
    if (!metas)
        return metas.error();
    model::ParameterValues out;
    for (const auto& m : *metas)
        out[m.key] = m.minSi;
    if (keys.empty())
        return out;
    model::ParameterValues some;
    for (const auto& k : keys) {
        const auto it = out.find(k);
        if (it == out.end())
            return makeError(ErrorCode::NotFound,
                             "axis " + axis + ": unknown parameter '" + k + "' (replay " + m_path + ")");
        some[k] = it->second;
    }
    return some;
}

Status ReplayDrive::writeParameters(const std::string& axis, const model::ParameterValues& values)
{
    if (auto st = checkAxis(axis); !st)
        return st;
    const std::string key = values.empty() ? std::string("(none)") : values.begin()->first;
    return makeError(ErrorCode::BadInput, "axis " + axis + ": parameter '" + key + "' is read-only: replay " + m_path +
                                              " plays a recording and writes no parameters");
}

Status ReplayDrive::startTest(const TestRequest& request)
{
    if (m_status.state == TestState::Running)
        return makeError(ErrorCode::Busy, "a test is already running");
    if (auto st = checkRequest(request); !st)
        return st;
    m_played = 0.0;
    m_haveTrace = false;
    m_status = {TestState::Running, 0.0, {}};
    return Status::success();
}

Result<TestStatus> ReplayDrive::pollTest()
{
    if (m_status.state != TestState::Running)
        return m_status;
    m_played = std::min(m_motionS, m_played + m_slice);
    m_status.progress = m_played / m_motionS;
    if (m_played >= m_motionS) {
        m_status = {TestState::Completed, 1.0, {}};
        m_haveTrace = true;
    }
    return m_status;
}

Result<model::Capture> ReplayDrive::readTrace()
{
    if (!m_haveTrace)
        return makeError(ErrorCode::NotFound, "no trace: no replayed test has completed");
    model::Capture c = m_capture;
    c.metadata.set(model::meta::kConnection, kScheme + m_path);
    return c;
}

Status ReplayDrive::abortTest()
{
    if (m_status.state == TestState::Running)
        m_status = {TestState::Aborted, m_status.progress, "aborted by the user"};
    return Status::success();
}

Result<DriveCapabilities> ReplayDrive::capabilities(const std::string& axis)
{
    if (auto st = checkAxis(axis); !st)
        return st.error();
    DriveCapabilities c;
    c.testTypes = {m_test};
    c.traceRateHz = m_fsHz;
    c.currentTraceRateHz = m_test == TestType::CurrentStep ? m_fsHz : 0.0;
    c.evaluatesFrf = false;
    c.writesParameters = false;
    c.hasLink = false;
    return c;
}

Result<DriveLimits> ReplayDrive::limits(const std::string& axis)
{
    if (auto st = checkAxis(axis); !st)
        return st.error();
    // A replay moves nothing: it allows no excitation and no motion of its own (every limit 0); the
    // recorded test is played whatever it asked.
    return DriveLimits{};
}

Result<TestPlan> ReplayDrive::planTest(const TestRequest& request)
{
    if (auto st = checkRequest(request); !st)
        return st.error();
    return TestPlan{m_motionS, m_capture.size(), m_fsHz};
}

DriveBackend replayBackend()
{
    DriveBackend b;
    b.scheme = kScheme;
    b.label = AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "Replay of a recorded capture");
    b.uriForm = "replay:FILE.csv";
    b.description = AXISTUNE_TRANSLATE_NOOP(
        "DriveRegistry", "Plays back a capture CSV of `axistune-cli capture` as a drive: only the recorded test on the "
                         "recorded axis, parameters read-only (docs/drive-seam.md).");
    setFileSetting(b, AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "Capture file"),
                   AXISTUNE_TRANSLATE_NOOP("DriveRegistry", "capture CSV with test, axis and fs_Hz metadata"));
    b.open = [](const ConnectionSettings& s) -> Result<std::unique_ptr<Drive>> {
        const std::string path = s.uri.substr(kScheme.size());
        if (path.empty())
            return makeError(ErrorCode::BadInput, "connection '" + s.uri + "': expected replay:FILE.csv");
        auto d = ReplayDrive::open(path);
        if (!d)
            return makeError(d.error().code, "connection '" + s.uri + "': " + d.error().detail);
        return std::unique_ptr<Drive>(std::move(d).value());
    };
    return b;
}

} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The replay backend, "replay:PATH/capture.csv" (docs/drive-seam.md "The replay: backend"): a capture
// CSV written by `axistune-cli capture` (or any capture with "test", "axis" and "fs_Hz" metadata)
// played back as a drive. It identifies itself from the file, offers the capture's numeric metadata as
// read-only parameters, advertises only the recorded test on the recorded axis, plays it back with
// progress (in slices of recorded time per poll) and hands out the recorded trace. Everything else
// (other tests, other axes, parameter writes, FRF evaluation) is refused with the reason.
//
// This backend is the example of the drive seam: it lives in this folder and is registered by one
// line in core/device/Backends.def; its tests are tests/core/device/test_replay_drive.cpp and the
// conformance suite (tests/conformance/).

#include "core/device/Drive.h"

#include <memory>
#include <string>

namespace axistune::device {

class ReplayDrive : public Drive {
public:
    /// Reads the capture; errors name the file and the metadata key that is missing or wrong.
    static Result<std::unique_ptr<ReplayDrive>> open(const std::string& path);

    Result<DriveIdentity> identify() override;
    Result<std::vector<model::ParameterMeta>> parameterMetadata(const std::string& axis) override;
    Result<model::ParameterValues> readParameters(const std::string& axis, std::span<const std::string> keys) override;
    Status writeParameters(const std::string& axis, const model::ParameterValues& values) override;
    Status startTest(const TestRequest& request) override;
    Result<TestStatus> pollTest() override;
    Result<model::Capture> readTrace() override;
    Status abortTest() override;
    Result<DriveCapabilities> capabilities(const std::string& axis) override;
    Result<DriveLimits> limits(const std::string& axis) override;
    Result<TestPlan> planTest(const TestRequest& request) override;

    /// Recorded time played per pollTest() call [s].
    void setSliceSeconds(double s) { m_slice = s; }

private:
    ReplayDrive() = default;
    Status checkAxis(const std::string& axis) const;
    Status checkRequest(const TestRequest& request) const;
    double recordS() const;

    std::string m_path;
    model::Capture m_capture;
    std::string m_axis;
    TestType m_test = TestType::Step;
    double m_fsHz = 0.0;
    double m_motionS = 0.0; ///< recorded motion time (metadata motion_time_s, else the record's length)
    double m_slice = 0.05;
    double m_played = 0.0;
    TestStatus m_status;
    bool m_haveTrace = false;
};

} // namespace axistune::device

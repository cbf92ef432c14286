// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One test run to its end through the drive seam (docs/device.md "Running a test to completion"):
// start, poll with monotone progress, stop on an abort token, on a lost connection or when the drive
// makes no progress within the timeout, then read the trace and, for FRF tests, the frequency response.
// A drive that only streams samples (readFrequencyResponse() answers NotFound) gets its FRF evaluated
// here, on the host, from the trace with the same core code the simulated drive uses (FrfRequestPlan.h).
// Used by the CLI, the GUI's drive worker, the benchmarks and the tests: the only poll loop outside
// the drives themselves.

#include "core/device/Drive.h"
#include "core/model/Capture.h"
#include "core/model/Result.h"

#include <atomic>
#include <chrono>
#include <functional>
#include <optional>
#include <string>

namespace axistune::device {

struct RunOptions {
    /// Called with a progress that never falls, 0..1, and the drive's detail text; at least once with 1
    /// when the test completes. Called on the thread that runs the test.
    std::function<void(double fraction, const std::string& detail)> progress;
    /// Checked before the start and between polls: when set, the test is not started, or the drive's
    /// abortTest() stops it (the drive restores the parameters from before the test). Error Aborted.
    const std::atomic<bool>* abort = nullptr;
    /// A test whose progress does not advance for this long (wall clock) is aborted with a Device error;
    /// so is a drive whose pollTest() fails (a lost connection: the error of the drive is passed on).
    std::chrono::milliseconds stallTimeout{30000};
    /// Pause between polls (0: poll at once again; the simulated drive advances inside each poll).
    std::chrono::milliseconds pollInterval{0};
    /// Read the trace of the completed test (an FRF evaluated on the host reads it in any case, but hands it
    /// out only with this set).
    bool readTrace = true;
};

struct TestRun {
    std::optional<model::Capture> trace; ///< when RunOptions::readTrace
    std::optional<FrfMeasurement> frf;   ///< Frf tests
    bool frfEvaluatedOnHost = false;     ///< the drive handed out samples only (metadata evaluated_by=host)
};

/// Runs the request on the drive to its end. Errors: the drive's refusal of the request; Aborted when the
/// token was set (not started, or stopped with the parameters restored); the drive's own error when a poll
/// fails (after a best-effort abortTest); Device when the progress stalls for stallTimeout; Safety when the
/// drive reports the test Faulted, Aborted when the drive aborted it on its own, each with the drive's detail.
Result<TestRun> runTest(Drive& drive, const TestRequest& request, const RunOptions& options = {});

/// The machine time a completed run took: the trace's motion_time_s where the drive recorded one, else the plan's
/// (Drive::planTest), else 0.
double motionTimeS(const TestRun& run, const Result<TestPlan>& plan);
/// As above without a plan: 0 when the trace does not say.
double motionTimeS(const TestRun& run);

} // namespace axistune::device

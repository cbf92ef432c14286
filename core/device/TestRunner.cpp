// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/TestRunner.h"

#include "core/device/FrfRequestPlan.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"

#include <algorithm>
#include <thread>
#include <vector>

namespace axistune::device {

namespace {

bool aborted(const RunOptions& o)
{
    return o.abort && o.abort->load();
}

Error abortedError(const Status& abortStatus)
{
    if (!abortStatus)
        return makeError(abortStatus.error().code,
                         "aborted by the user, but the drive did not confirm the stop: " + abortStatus.error().detail);
    return makeError(ErrorCode::Aborted, "aborted by the user; the drive restored the parameters from before the test");
}

/// What the host needs to evaluate an FRF itself: the parameters the drive plans from, read before it starts.
Result<model::ParameterValues> planParameters(Drive& drive, const TestRequest& request)
{
    const auto keys = frfPlanParameterKeys();
    return drive.readParameters(request.axis, std::span<const std::string>(keys.data(), keys.size()));
}

Result<FrfMeasurement> evaluateOnHost(const TestRequest& request, const model::ParameterValues& values,
                                      const model::Capture& trace)
{
    auto clock = axisClockFromParameters(values, request.traceDivider);
    if (!clock)
        return clock.error();
    auto plan = planFrfRequest(request, values, *clock);
    if (!plan)
        return plan.error();
    auto m = evaluateFrfRequestTrace(*plan, trace);
    if (!m)
        return makeError(m.error().code, "FRF evaluation on the host: " + m.error().detail);
    m.value().frf.metadata.set("evaluated_by", "host");
    m.value().frf.metadata.set(model::meta::kAxis, request.axis);
    if (const auto* machine = trace.metadata.find(model::meta::kMachine))
        m.value().frf.metadata.set(model::meta::kMachine, machine->text());
    return m;
}

} // namespace

Result<TestRun> runTest(Drive& drive, const TestRequest& request, const RunOptions& options)
{
    if (aborted(options))
        return makeError(ErrorCode::Aborted, "aborted by the user before the test started; nothing was changed");
    const bool frf = request.type() == TestType::Frf;
    std::optional<model::ParameterValues> planValues;
    if (frf) {
        // Read before the start: the values the drive plans from. A drive that cannot tell them still runs
        // the test; it must then evaluate the FRF itself.
        if (auto v = planParameters(drive, request); v)
            planValues = std::move(v).value();
    }
    if (auto st = drive.startTest(request); !st)
        return st.error();
    double reported = 0.0;
    bool first = true;
    auto lastAdvance = std::chrono::steady_clock::now();
    for (;;) {
        if (aborted(options))
            return abortedError(drive.abortTest());
        auto st = drive.pollTest();
        if (!st) {
            (void)drive.abortTest(); // stop the motion if the drive still listens
            return st.error();
        }
        const auto now = std::chrono::steady_clock::now();
        const double p = std::clamp(st->progress, 0.0, 1.0);
        if (p > reported || first) {
            if (p > reported)
                lastAdvance = now;
            reported = std::max(reported, p);
            first = false;
            if (options.progress && st->state == TestState::Running)
                options.progress(reported, st->detail);
        }
        if (st->state == TestState::Completed)
            break;
        if (st->state != TestState::Running) {
            (void)drive.abortTest();
            const bool faulted = st->state == TestState::Faulted;
            return makeError(faulted ? ErrorCode::Safety : ErrorCode::Aborted,
                             std::string("test ") + testStateName(st->state) +
                                 (st->detail.empty() ? "" : ": " + st->detail));
        }
        if (now - lastAdvance > options.stallTimeout) {
            (void)drive.abortTest();
            return makeError(ErrorCode::Device,
                             "the drive reported no progress for " +
                                 model::formatNumber(std::chrono::duration<double>(options.stallTimeout).count(), 6) +
                                 " s; the test was aborted");
        }
        if (options.pollInterval.count() > 0)
            std::this_thread::sleep_for(options.pollInterval);
    }
    if (options.progress)
        options.progress(1.0, {});
    TestRun run;
    if (frf) {
        auto m = drive.readFrequencyResponse();
        if (m) {
            run.frf = std::move(m).value();
        } else if (m.error().code != ErrorCode::NotFound) {
            return m.error();
        } else {
            // Samples only: the host evaluates the trace with the plan the drive ran.
            if (!planValues)
                return makeError(ErrorCode::NotFound, "the drive does not evaluate the FRF and did not tell the "
                                                      "parameters to evaluate it on the host");
            auto trace = drive.readTrace();
            if (!trace)
                return makeError(trace.error().code,
                                 "the drive does not evaluate the FRF and its trace could not be read: " +
                                     trace.error().detail);
            auto h = evaluateOnHost(request, *planValues, *trace);
            if (!h)
                return h.error();
            run.frf = std::move(h).value();
            run.frfEvaluatedOnHost = true;
            if (options.readTrace)
                run.trace = std::move(trace).value();
        }
    }
    if (options.readTrace && !run.trace) {
        auto trace = drive.readTrace();
        if (!trace)
            return trace.error();
        run.trace = std::move(trace).value();
    }
    return run;
}

namespace {

std::optional<double> recordedMotionTimeS(const TestRun& run)
{
    if (run.trace)
        if (const auto* v = run.trace->metadata.find(model::meta::kMotionTimeS))
            return v->number();
    return std::nullopt;
}

} // namespace

double motionTimeS(const TestRun& run)
{
    return recordedMotionTimeS(run).value_or(0.0);
}

double motionTimeS(const TestRun& run, const Result<TestPlan>& plan)
{
    return recordedMotionTimeS(run).value_or(plan ? plan->motionTimeS : 0.0);
}

} // namespace axistune::device

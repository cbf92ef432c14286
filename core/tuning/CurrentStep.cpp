// SPDX-License-Identifier: GPL-3.0-or-later
// Evaluation of a measured current step against the predictions of the current-loop design
// (spec/current-loop-and-multisweep-frf.md §2.8: 10–90 % rise time; §2.6: overshoot of the step).
#include "core/tuning/CurrentStep.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace axistune::tuning {

namespace {

double crossing(const std::vector<double>& t, const std::vector<double>& y, double level)
{
    for (std::size_t i = 1; i < y.size() && i < t.size(); ++i)
        if (y[i - 1] < level && y[i] >= level)
            return t[i - 1] + (level - y[i - 1]) / (y[i] - y[i - 1]) * (t[i] - t[i - 1]);
    return std::numeric_limits<double>::quiet_NaN();
}

} // namespace

Result<MeasuredCurrentStep> currentStepFromCapture(const model::Capture& cap)
{
    for (const char* name : {"t_s", "current_cmd_A", "current_A"})
        if (!cap.channel(name))
            return makeError(ErrorCode::BadInput, std::string("current step: the trace has no channel ") + name);
    const auto& t = cap.channel("t_s")->data;
    const auto& cmd = cap.channel("current_cmd_A")->data;
    const auto& i = cap.channel("current_A")->data;
    if (t.size() != cmd.size() || t.size() != i.size())
        return makeError(ErrorCode::BadInput,
                         "current step: the channels t_s, current_cmd_A and current_A differ in length");
    double peak = 0.0;
    for (double c : cmd)
        peak = std::max(peak, std::isfinite(c) ? std::abs(c) : 0.0);
    if (!(peak > 0.0))
        return makeError(ErrorCode::BadInput, "current step: the current command never leaves 0");
    std::size_t k0 = 0;
    while (k0 < cmd.size() && !(std::abs(cmd[k0]) >= 0.5 * peak))
        ++k0;
    if (cmd.size() - k0 < 3 || t.size() < 2)
        return makeError(ErrorCode::BadInput, "current step: fewer than 3 samples after the step");
    MeasuredCurrentStep m;
    m.amplitudeA = cmd[k0];
    m.stepTimeS = t[k0];
    m.periodS = t[1] - t[0];
    for (std::size_t k = k0; k < t.size(); ++k) {
        m.tS.push_back(t[k] - t[k0]);
        m.normalised.push_back(i[k] / m.amplitudeA);
    }
    return m;
}

StepFigures stepFigures(const std::vector<double>& t, const std::vector<double>& y)
{
    StepFigures f;
    f.riseTimeS = crossing(t, y, 0.9) - crossing(t, y, 0.1);
    double top = -std::numeric_limits<double>::infinity();
    for (double v : y)
        top = std::max(top, v);
    f.overshoot = y.empty() ? 0.0 : std::max(0.0, top - 1.0);
    return f;
}

StepDifference compareSteps(const std::vector<double>& a, const std::vector<double>& b)
{
    StepDifference d;
    d.samples = std::min(a.size(), b.size());
    double sum = 0.0;
    for (std::size_t k = 0; k < d.samples; ++k) {
        const double e = a[k] - b[k];
        d.maxAbs = std::max(d.maxAbs, std::abs(e));
        sum += e * e;
    }
    d.rms = d.samples > 0 ? std::sqrt(sum / static_cast<double>(d.samples)) : 0.0;
    return d;
}

} // namespace axistune::tuning

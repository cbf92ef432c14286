// SPDX-License-Identifier: GPL-3.0-or-later
// Reversal (quadrant-glitch) compensation tuned from circle tests, docs/ballbar.md "Reversal
// compensation". The starting point is the integrator rule: a velocity-command pulse a·exp(−t/τ) adds
// K_i·a·τ/R of torque to the velocity integrator (R the screw lead in m/rad), so a = ΔT·R/(K_i·τ) gives
// it the friction reversal ΔT at once; which τ (and how far from the rule a) leaves the smallest spike
// depends on the loops and is found on the model by simulated circles.
#include "core/tuning/ReversalCompensation.h"

#include "core/model/Constants.h"
#include "core/model/Number.h"
#include "core/sim/AxisParameters.h"

#include <algorithm>
#include <cmath>

namespace axistune::tuning {
namespace {

using model::kPi;
constexpr double kMaxAmplitude = 0.05; ///< reversal.amplitude upper limit [m/s] (parameter catalogue)

std::string um(double m)
{
    return model::formatFixed(m * 1e6, 2);
}

/// A circle of the model and the spikes the diagnostics read from it.
struct SimulatedCircle {
    io::BallBarTrace trace;
    std::array<AxisSpikes, 2> spikes;
};

Result<SimulatedCircle> simulateCircle(const sim::MachineDefinition& model, const sim::CircleTestOptions& circle,
                                       const BallBarOptions& opt)
{
    auto r = sim::runCircleTest(model, circle);
    if (!r)
        return r.error();
    auto spikes = reversalSpikes(r->ballbar, opt);
    if (!spikes)
        return spikes.error();
    return SimulatedCircle{std::move(r->ballbar), *spikes};
}

struct Candidate {
    double a = 0.0, tau = 0.01, cost = 0.0;
};

class Search {
public:
    Search(const sim::MachineDefinition& model, const sim::CircleTestOptions& circle, const ReversalCompOptions& opt)
        : m_model(model), m_circle(circle), m_opt(opt)
    {
        m_circle.dataArcDeg = opt.searchDataArcDeg;
        m_circle.leadArcDeg = opt.searchLeadArcDeg;
        m_circle.dataStartDeg = 45.0;
    }

    /// Both axes at once (their pulses do not interact: each acts at its own reversals). Cost per axis:
    /// worst |spike| plus how far the step moves from the uncompensated one (a pulse must not fake lost motion).
    Result<std::array<double, 2>> cost(const std::array<Candidate, 2>& c)
    {
        auto spikes = run(c);
        if (!spikes)
            return spikes.error();
        if (!m_base) {
            m_base = true;
            m_baseStep = {(*spikes)[0].stepM, (*spikes)[1].stepM};
        }
        std::array<double, 2> out{};
        for (int k = 0; k < 2; ++k)
            out[k] = (*spikes)[k].worstM + std::abs((*spikes)[k].stepM - m_baseStep[k]);
        ++m_evaluations;
        return out;
    }

    int evaluations() const { return m_evaluations; }

private:
    Result<std::array<AxisSpikes, 2>> run(const std::array<Candidate, 2>& c)
    {
        sim::MachineDefinition m = m_model;
        const std::string names[2] = {m_circle.axisX, m_circle.axisY};
        for (int k = 0; k < 2; ++k) {
            for (auto& a : m.axes) {
                if (a.name != names[k])
                    continue;
                a.values["reversal.amplitude"] = c[k].a;
                a.values["reversal.time_constant"] = c[k].tau;
            }
        }
        auto r = simulateCircle(m, m_circle, m_opt.ballbar);
        if (!r)
            return r.error();
        return r->spikes;
    }

    const sim::MachineDefinition& m_model;
    sim::CircleTestOptions m_circle;
    ReversalCompOptions m_opt;
    bool m_base = false;
    std::array<double, 2> m_baseStep{};
    int m_evaluations = 0;
};

sim::MachineDefinition withPulses(sim::MachineDefinition m, const std::array<ReversalCompAxis, 2>& axes)
{
    for (auto& a : m.axes) {
        for (const auto& c : axes) {
            if (a.name != c.axis)
                continue;
            a.values["reversal.amplitude"] = c.amplitudeMPerS;
            a.values["reversal.time_constant"] = c.timeConstantS;
        }
    }
    return m;
}

/// Coordinate search from the integrator rule: τ over a grid (a from the rule), then a around the rule at
/// the best τ, then τ once more at the best a. Both axes advance together; an axis without a spike keeps 0.
Result<std::array<Candidate, 2>> searchPulses(Search& s, const std::array<double, 2>& ruleProduct,
                                              const std::array<bool, 2>& active)
{
    std::array<Candidate, 2> best{};
    for (int k = 0; k < 2; ++k)
        best[k] = {0.0, 0.01, std::numeric_limits<double>::infinity()};
    auto consider = [&](const std::array<Candidate, 2>& c) -> Status {
        auto cost = s.cost(c);
        if (!cost)
            return cost.error();
        for (int k = 0; k < 2; ++k) {
            if ((*cost)[k] < best[k].cost) {
                best[k] = c[k];
                best[k].cost = (*cost)[k];
            }
        }
        return Status::success();
    };
    auto pulse = [&](int k, double a, double tau) {
        return active[k] ? Candidate{std::clamp(a, 0.0, kMaxAmplitude), std::clamp(tau, 1e-4, 0.5)}
                         : Candidate{0.0, 0.01};
    };
    if (auto st = consider({Candidate{0.0, 0.01}, Candidate{0.0, 0.01}}); !st) // uncompensated: the reference
        return st.error();
    for (double tau : {0.002, 0.004, 0.008, 0.016, 0.032}) {
        if (auto st = consider({pulse(0, ruleProduct[0] / tau, tau), pulse(1, ruleProduct[1] / tau, tau)}); !st)
            return st.error();
    }
    const std::array<Candidate, 2> atTau = best;
    for (double f : {0.5, 0.75, 1.25, 1.5}) {
        if (auto st = consider({pulse(0, atTau[0].a * f, atTau[0].tau), pulse(1, atTau[1].a * f, atTau[1].tau)}); !st)
            return st.error();
    }
    const std::array<Candidate, 2> atA = best;
    for (double f : {0.7, 1.4}) {
        if (auto st = consider({pulse(0, atA[0].a, atA[0].tau * f), pulse(1, atA[1].a, atA[1].tau * f)}); !st)
            return st.error();
    }
    return best;
}

} // namespace

Result<std::array<AxisSpikes, 2>> reversalSpikes(const io::BallBarTrace& trace, const BallBarOptions& opt)
{
    std::array<AxisSpikes, 2> out;
    for (int axis = 0; axis < 2; ++axis) {
        int n = 0;
        for (double rev : axis == 0 ? std::array<double, 2>{0.0, kPi} : std::array<double, 2>{0.5 * kPi, 1.5 * kPi}) {
            auto ev = fitReversal(trace, axis, rev, opt);
            if (!ev)
                continue; // not covered by this trace
            const double h = ev->spike ? ev->spikeHeightM : 0.0;
            out[axis].heightsM.push_back(h);
            out[axis].worstM = std::max(out[axis].worstM, std::abs(h));
            out[axis].stepM += ev->stepM;
            ++n;
        }
        if (n == 0)
            return makeError(ErrorCode::BadInput, trace.source + ": no reversal of axis " + std::to_string(axis + 1) +
                                                      " is covered by the trace");
        out[axis].stepM /= n;
    }
    return out;
}

Result<ReversalCompResult> tuneReversalCompensation(const sim::MachineDefinition& model,
                                                    const sim::CircleTestOptions& circle,
                                                    const io::BallBarTrace& measured, double dTxNm, double dTyNm,
                                                    const ReversalCompOptions& opt)
{
    const std::string names[2] = {circle.axisX, circle.axisY};
    for (const auto& n : names) {
        const auto* a = model.axis(n);
        if (!a || a->kind != sim::AxisKind::Linear)
            return makeError(ErrorCode::BadInput,
                             "reversal compensation: the model '" + model.name + "' has no linear axis '" + n + "'");
    }
    auto meas = reversalSpikes(measured, opt.ballbar);
    if (!meas)
        return meas.error();
    ReversalCompResult res;
    std::array<bool, 2> active{};
    const double dT[2] = {dTxNm, dTyNm};
    for (int k = 0; k < 2; ++k) {
        res.axes[k].axis = names[k];
        res.axes[k].measuredSpikeM = (*meas)[k].worstM;
        res.axes[k].dTNm = dT[k];
        active[k] = (*meas)[k].worstM > 0.0 && std::isfinite(dT[k]) && dT[k] > 0.0;
    }
    if (!active[0] && !active[1])
        return makeError(ErrorCode::BadInput,
                         measured.source +
                             ": reversal compensation refused: the measured circle shows no reversal "
                             "spike above the detection rule on " +
                             names[0] + " or " + names[1] + " (nothing to compensate)");
    // The model as the drive is now: it must show the measured spikes, or its prediction means nothing.
    auto base = simulateCircle(model, circle, opt.ballbar);
    if (!base)
        return base.error();
    res.modelUncompensated = base->trace;
    for (int k = 0; k < 2; ++k) {
        res.axes[k].modelSpikeM = base->spikes[k].worstM;
        if (!active[k])
            continue;
        const double rel = std::abs(res.axes[k].modelSpikeM - res.axes[k].measuredSpikeM) / res.axes[k].measuredSpikeM;
        if (rel > kModelSpikeTolerance)
            return makeError(ErrorCode::BadInput, "reversal compensation refused: the model '" + model.name +
                                                      "' gives a " + names[k] + " reversal spike of " +
                                                      um(res.axes[k].modelSpikeM) + " um where the circle measured " +
                                                      um(res.axes[k].measuredSpikeM) + " um (more than " +
                                                      std::to_string(static_cast<int>(kModelSpikeTolerance * 100)) +
                                                      " % apart): its prediction cannot be trusted");
    }
    std::array<double, 2> rule{};
    for (int k = 0; k < 2; ++k) {
        const auto& v = model.axis(names[k])->values;
        const double ki = v.at("velocity.ki"), lead = v.at("plant.screw_lead");
        rule[k] = ki > 0.0 && active[k] ? dT[k] * lead / ki : 0.0;
        if (active[k] && !(rule[k] > 0.0))
            return makeError(ErrorCode::BadInput, "reversal compensation refused: axis " + names[k] +
                                                      " has no velocity integral gain (velocity.ki = 0)");
    }
    Search search(model, circle, opt);
    auto best = searchPulses(search, rule, active);
    if (!best)
        return best.error();
    for (int k = 0; k < 2; ++k) {
        res.axes[k].amplitudeMPerS = (*best)[k].a;
        res.axes[k].timeConstantS = (*best)[k].tau;
        res.axes[k].evaluations = search.evaluations();
    }
    auto predicted = simulateCircle(withPulses(model, res.axes), circle, opt.ballbar);
    if (!predicted)
        return predicted.error();
    res.predicted = predicted->trace;
    for (int k = 0; k < 2; ++k) {
        auto& a = res.axes[k];
        a.predictedSpikeM = predicted->spikes[k].worstM;
        a.predictedReduction = a.modelSpikeM > 0.0 ? 1.0 - a.predictedSpikeM / a.modelSpikeM : 0.0;
    }
    return res;
}

} // namespace axistune::tuning

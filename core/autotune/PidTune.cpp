// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/autotune/PidTune.h"

#include "core/device/hal/AxisNotch.h"
#include "core/model/Number.h"

#include <algorithm>
#include <cmath>

namespace axistune::autotune {

const std::vector<std::string>& pidGainKeys()
{
    static const std::vector<std::string> keys{"Pgain", "Igain", "Dgain", "FF1", "FF2"};
    return keys;
}

Status checkPidTuneRequest(const PidTuneRequest& r, const PidTuneNames& names)
{
    if (r.axis.empty())
        return makeError(ErrorCode::BadInput, "no " + names.axis + " given");
    if (!(r.amplitude >= 0.0) || !(r.amplitudePct >= 0.0) || !std::isfinite(r.amplitude) ||
        !std::isfinite(r.amplitudePct))
        return makeError(ErrorCode::BadInput, names.excitation + " must be a positive number");
    if (!(r.phaseMarginDeg >= 30.0 && r.phaseMarginDeg <= 80.0))
        return makeError(ErrorCode::BadInput, names.phaseMargin + " must lie in 30..80 deg");
    if (!(r.gainMarginDb >= 3.0 && r.gainMarginDb <= 20.0))
        return makeError(ErrorCode::BadInput, names.gainMargin + " must lie in 3..20 dB");
    if (!(r.fminHz > 0.0) || (r.fmaxHz > 0.0 && !(r.fmaxHz > r.fminHz)))
        return makeError(ErrorCode::BadInput, "the band must have 0 < " + names.fmin + " < " + names.fmax);
    return Status::success();
}

namespace {

Result<device::FrfMeasurement> measureOpenLoop(device::Drive& drive, const PidTuneRequest& o, double fmaxHz,
                                               const device::RunOptions& run)
{
    device::TestRequest r;
    r.axis = o.axis;
    auto& f = r.test.emplace<device::FrfTest>();
    f.method = device::FrfMethod::Multisine;
    f.quantity = device::FrfQuantity::OpenLoop;
    f.fminHz = o.fminHz;
    f.fmaxHz = fmaxHz;
    f.amplitudePeak = o.amplitude;
    f.amplitudePct = o.amplitudePct > 0.0 ? o.amplitudePct : 5.0;
    f.multisinePeriods = o.periods;
    if (auto plan = drive.planTest(r); !plan)
        return plan.error();
    device::RunOptions ro = run;
    ro.readTrace = false;
    auto done = device::runTest(drive, r, ro);
    if (!done)
        return done.error();
    if (!done->frf)
        return makeError(ErrorCode::Device, "the drive returned no frequency response");
    return std::move(*done->frf);
}

void validLines(const dsp::FrequencyResponse& f, std::vector<double>& freq, std::vector<std::complex<double>>& h)
{
    for (std::size_t i = 0; i < f.size(); ++i)
        if (f.valid[i]) {
            freq.push_back(f.freqHz[i]);
            h.push_back(f.h[i]);
        }
}

std::string fmt(double x, int digits)
{
    return model::formatNumber(x, digits);
}

std::optional<tuning::BiquadNotch> asBiquad(const std::optional<device::hal::AxisNotch>& n)
{
    if (!n)
        return std::nullopt;
    return tuning::BiquadNotch{n->f0Hz, n->q};
}

std::optional<device::hal::AxisNotch> asAxisNotch(const std::optional<tuning::BiquadNotch>& n)
{
    if (!n)
        return std::nullopt;
    return device::hal::AxisNotch{n->f0Hz, n->q};
}

bool sameNotch(const std::optional<tuning::BiquadNotch>& a, const std::optional<tuning::BiquadNotch>& b)
{
    return a.has_value() == b.has_value() && (!a || (a->f0Hz == b->f0Hz && a->q == b->q));
}

std::string notchText(const tuning::BiquadNotch& n)
{
    return fmt(n.f0Hz, 5) + " Hz, Q " + fmt(n.q, 3);
}

/// The lines (indices into `freqHz`) where the notch takes less than 60 dB out (|N| ≥ 1e-3), with N there: at the
/// notch's zero a loop gain of ~0 says nothing of the plant or the margins (and the design refuses a zero).
struct NotchedLines {
    std::vector<std::size_t> index;
    std::vector<std::complex<double>> n;
};
NotchedLines linesOutsideZero(const std::vector<double>& freqHz, const tuning::BiquadNotch& notch, double periodS)
{
    NotchedLines out;
    for (std::size_t k = 0; k < freqHz.size(); ++k) {
        const auto n = tuning::biquadNotchResponse(notch, periodS, freqHz[k]);
        if (std::abs(n) >= 1e-3) {
            out.index.push_back(k);
            out.n.push_back(n);
        }
    }
    return out;
}

} // namespace

bool PidTuneProposal::notchChanges() const
{
    return !sameNotch(notch, runningNotch);
}

Result<PidLoopMeasurement> measurePidLoop(device::Drive& drive, const PidTuneRequest& request,
                                          const device::RunOptions& run)
{
    if (auto st = checkPidTuneRequest(request); !st)
        return st.error();
    auto caps = drive.capabilities(request.axis);
    if (!caps)
        return caps.error();
    if (std::find(caps->frfQuantities.begin(), caps->frfQuantities.end(), device::FrfQuantity::OpenLoop) ==
        caps->frfQuantities.end())
        return makeError(ErrorCode::BadInput, "axis " + request.axis +
                                                  ": the drive does not measure the open position loop; this tuning "
                                                  "is for a PID the NC closes (hal:, linuxcnc:)");
    PidLoopMeasurement m;
    m.servoRateHz = caps->traceRateHz;
    m.fmaxHz = request.fmaxHz > 0.0 ? request.fmaxHz : 0.45 * m.servoRateHz;
    auto before = drive.readParameters(request.axis, pidGainKeys());
    if (!before)
        return before.error();
    m.runningValues = *before;
    m.running = {before->at("Pgain"), before->at("Igain"), before->at("Dgain"), before->at("FF1"), before->at("FF2")};
    auto notch = device::hal::readAxisNotch(drive, request.axis);
    if (!notch)
        return notch.error();
    m.runningNotch = asBiquad(*notch);
    auto measured = measureOpenLoop(drive, request, m.fmaxHz, run);
    if (!measured)
        return measured.error();
    validLines(measured->frf, m.freqHz, m.loop);
    const double T = 1.0 / m.servoRateHz;
    if (m.runningNotch) {
        // The notch runs between the pid and the drive input: L = C·N·P.
        const auto kept = linesOutsideZero(m.freqHz, *m.runningNotch, T);
        std::vector<double> f;
        std::vector<std::complex<double>> l, withoutNotch;
        for (std::size_t i = 0; i < kept.index.size(); ++i) {
            f.push_back(m.freqHz[kept.index[i]]);
            l.push_back(m.loop[kept.index[i]]);
            withoutNotch.push_back(m.loop[kept.index[i]] / kept.n[i]);
        }
        auto plant = tuning::effectivePlant(f, withoutNotch, m.running, T);
        if (!plant)
            return plant.error();
        m.plant = std::move(plant).value();
        m.freqHz = std::move(f);
        m.loop = std::move(l);
    } else {
        auto plant = tuning::effectivePlant(m.freqHz, m.loop, m.running, T);
        if (!plant)
            return plant.error();
        m.plant = std::move(plant).value();
    }
    m.motionTimeS = measured->motionTimeS;
    m.frf = std::move(measured).value();
    return m;
}

std::vector<std::complex<double>> predictedPidLoop(const PidLoopMeasurement& m, const tuning::PositionPid& gains,
                                                   const std::optional<tuning::BiquadNotch>& notch)
{
    const double T = 1.0 / m.servoRateHz;
    std::vector<std::complex<double>> l(m.plant.size());
    for (std::size_t k = 0; k < l.size(); ++k) {
        l[k] = tuning::pidResponse(gains, T, m.freqHz[k]) * m.plant[k];
        if (notch)
            l[k] *= tuning::biquadNotchResponse(*notch, T, m.freqHz[k]);
    }
    return l;
}

namespace {

// GainsAndNotch: a notch at the plant's strongest resonance above the crossover, when it lets the crossover rise by
// 10 % or more (LinuxCNC's biquad: 0.5 ≤ Q ≤ 2; the Q with the highest crossover is taken).
Status proposeGains(const PidLoopMeasurement& m, const PidTuneRequest& o, const tuning::PositionPidOptions& po,
                    PidTuneProposal& p)
{
    const double T = 1.0 / m.servoRateHz;
    auto design = tuning::designPositionPid(m.freqHz, m.plant, T, po);
    if (!design)
        return design.error();
    if (o.notch) {
        p.resonanceHz = tuning::plantResonanceHz(m.freqHz, m.plant, po.input, 1.5 * design->crossoverHz);
        if (!p.resonanceHz) {
            p.notchRule = "no resonance stands 6 dB above the plant's median above 1.5 × the crossover: no notch";
        } else {
            double bestCrossover = design->crossoverHz;
            for (const double q : {2.0, 1.4, 1.0, 0.7, 0.5}) {
                const tuning::BiquadNotch candidate{*p.resonanceHz, q};
                // The notch's zero sits on the resonance's line: it is left out of the design.
                const auto kept = linesOutsideZero(m.freqHz, candidate, T);
                std::vector<double> freq;
                std::vector<std::complex<double>> notched;
                for (std::size_t i = 0; i < kept.index.size(); ++i) {
                    freq.push_back(m.freqHz[kept.index[i]]);
                    notched.push_back(m.plant[kept.index[i]] * kept.n[i]);
                }
                auto d = tuning::designPositionPid(freq, notched, T, po);
                if (d && d->crossoverHz >= 1.1 * bestCrossover) {
                    bestCrossover = d->crossoverHz;
                    p.notch = candidate;
                    design = std::move(d);
                }
            }
            p.notchRule = p.notch ? "notch at the resonance " + fmt(*p.resonanceHz, 5) + " Hz (peak of |P|·ω²" +
                                        std::string(po.input == tuning::DriveInput::Torque ? "" : "/ω") + "), Q " +
                                        fmt(p.notch->q, 3) + ": the Q of 0.5–2 that lets the crossover rise most"
                                  : "a notch at the resonance " + fmt(*p.resonanceHz, 5) +
                                        " Hz would not raise the crossover by 10 %: no notch";
        }
    } else {
        p.notchRule = "no notch (asked)";
    }
    if (m.runningNotch && p.notch)
        p.notchRule += "; it replaces the running notch (" + notchText(*m.runningNotch) + ")";
    else if (m.runningNotch)
        p.notchRule += "; the running notch (" + notchText(*m.runningNotch) +
                       ") is removed: the gains are designed for the plant without it";
    p.gains = design->gains;
    p.rules = design->rules;
    p.predicted = design->predicted;
    return Status::success();
}

// The margins of C·N·P over the measured lines but those at the notch's zero (as the gains' design leaves them out).
tuning::PositionLoopMargins notchedMargins(const PidLoopMeasurement& m, const tuning::PositionPid& gains,
                                           const tuning::BiquadNotch& notch)
{
    const auto kept = linesOutsideZero(m.freqHz, notch, 1.0 / m.servoRateHz);
    const auto l = predictedPidLoop(m, gains, notch);
    std::vector<double> f;
    std::vector<std::complex<double>> lk;
    for (const std::size_t k : kept.index) {
        f.push_back(m.freqHz[k]);
        lk.push_back(l[k]);
    }
    return tuning::positionLoopMargins(f, lk);
}

// NotchOnly: the running gains stay; a notch at the plant's strongest resonance above the running crossover when it
// raises the loop's gain margin by 1 dB or more while the phase margin stays at the one asked (or, when the running
// loop has less, falls by at most 3°): of Q 0.5–2, the one with the largest gain margin. Over a running notch the
// candidates are judged on the plant without it; when none is better by 1 dB the running notch stays.
void proposeNotchOnly(const PidLoopMeasurement& m, const tuning::PositionPidOptions& po, PidTuneProposal& p)
{
    const double pmFloor = std::min(po.phaseMarginDeg, p.runningMargins.phaseMarginDeg - 3.0);
    p.gains = m.running;
    p.predicted = p.runningMargins;
    p.notch = m.runningNotch;
    const std::string stays = m.runningNotch ? "no new notch; the running notch (" + notchText(*m.runningNotch) +
                                                   ") stays"
                                             : std::string("no notch");
    const double above = p.runningMargins.crossoverHz > 0.0 ? 1.5 * p.runningMargins.crossoverHz : m.freqHz.front();
    p.resonanceHz = tuning::plantResonanceHz(m.freqHz, m.plant, po.input, above);
    if (!p.resonanceHz) {
        p.notchRule = "no resonance stands 6 dB above the plant's median above 1.5 × the running crossover (" +
                      fmt(p.runningMargins.crossoverHz, 4) + " Hz): " + stays;
        return;
    }
    std::optional<tuning::PositionLoopMargins> best;
    std::optional<tuning::BiquadNotch> bestNotch;
    for (const double q : {2.0, 1.4, 1.0, 0.7, 0.5}) {
        const tuning::BiquadNotch candidate{*p.resonanceHz, q};
        const auto margins = notchedMargins(m, m.running, candidate);
        if (!(margins.phaseMarginDeg >= pmFloor))
            continue;
        if (!best || margins.gainMarginDb > best->gainMarginDb) {
            best = margins;
            bestNotch = candidate;
        }
    }
    const std::string at = "the resonance " + fmt(*p.resonanceHz, 5) + " Hz (peak of |P|·ω²" +
                           std::string(po.input == tuning::DriveInput::Torque ? "" : "/ω") + ")";
    if (!best || !(best->gainMarginDb >= p.runningMargins.gainMarginDb + 1.0)) {
        p.notchRule = "a notch at " + at + " would not raise the running loop's gain margin by 1 dB with the phase " +
                      "margin at least " + fmt(pmFloor, 3) + "° (the one asked, or 3° below the running loop's when " +
                      "that is less): " + stays;
        return;
    }
    p.notch = bestNotch;
    p.predicted = *best;
    p.notchRule = "notch at " + at + ", Q " + fmt(p.notch->q, 3) + ": of Q 0.5–2, the largest gain margin (" +
                  fmt(best->gainMarginDb, 3) + " dB, running " + fmt(p.runningMargins.gainMarginDb, 3) +
                  " dB) with the phase margin at least " + fmt(pmFloor, 3) +
                  "° (the one asked, or 3° below the running " + "loop's when that is less); the gains are not changed" +
                  (m.runningNotch ? "; it replaces the running notch (" + notchText(*m.runningNotch) + ")" : "");
}

} // namespace

Result<PidTuneProposal> proposePidTune(const PidLoopMeasurement& m, const PidTuneRequest& o)
{
    if (m.freqHz.size() < 5)
        return makeError(ErrorCode::OutOfRange, "only " + std::to_string(m.freqHz.size()) +
                                                    " valid lines were measured: too few to tune from");
    PidTuneProposal p;
    tuning::PositionPidOptions po;
    po.phaseMarginDeg = o.phaseMarginDeg;
    po.gainMarginDb = o.gainMarginDb;
    if (!o.driveInput) {
        auto input = tuning::driveInputFromSlope(m.freqHz, m.plant);
        if (!input)
            return makeError(
                input.error().code,
                input.error().detail +
                    "; choose the drive input: torque or velocity (pid-tune --drive-input, the wizard's Drive input)");
        po.input = *input;
        p.inputRule = "read from the slope of the measured plant over its lowest decade";
    } else {
        po.input = *o.driveInput;
        p.inputRule = "given by the user";
    }
    p.input = po.input;
    p.runningMargins = tuning::positionLoopMargins(m.freqHz, m.loop);
    p.runningNotch = m.runningNotch;
    if (o.scope == PidTuneScope::NotchOnly) {
        proposeNotchOnly(m, po, p);
    } else if (auto st = proposeGains(m, o, po, p); !st) {
        return st.error();
    }
    p.predictedLoop = predictedPidLoop(m, p.gains, p.notch);
    return p;
}

Result<PidTuneApplied> applyPidTune(device::Drive& drive, const PidTuneRequest& o, const PidLoopMeasurement& m,
                                    const PidTuneProposal& p, const device::RunOptions& run)
{
    PidTuneApplied a;
    auto before = drive.readParameters(o.axis, pidGainKeys());
    if (!before)
        return before.error();
    a.before = *before;
    auto notchNow = device::hal::readAxisNotch(drive, o.axis);
    if (!notchNow)
        return notchNow.error();
    a.notchBefore = asBiquad(*notchNow);
    if (!sameNotch(a.notchBefore, m.runningNotch))
        return makeError(ErrorCode::BadInput,
                         "AxisTune's notch after " + o.axis + " is no longer the one the measurement ran with (" +
                             (m.runningNotch ? notchText(*m.runningNotch) : std::string("none")) + ", now " +
                             (a.notchBefore ? notchText(*a.notchBefore) : std::string("none")) +
                             "): measure again; nothing was changed");
    const bool notchChanges = !sameNotch(p.notch, a.notchBefore);
    if (notchChanges)
        if (auto st = device::hal::restoreAxisNotch(drive, o.axis, asAxisNotch(p.notch)); !st)
            return st.error();
    auto restore = [&] {
        if (!a.written.empty())
            (void)drive.writeParameters(o.axis, a.before);
        if (notchChanges)
            (void)device::hal::restoreAxisNotch(drive, o.axis, asAxisNotch(a.notchBefore));
    };
    if (o.scope == PidTuneScope::GainsAndNotch) {
        const model::ParameterValues gains{{"Pgain", p.gains.p},
                                           {"Igain", p.gains.i},
                                           {"Dgain", p.gains.d},
                                           {"FF1", p.gains.ff1},
                                           {"FF2", p.gains.ff2}};
        if (auto st = drive.writeParameters(o.axis, gains); !st) {
            restore();
            return st.error();
        }
        a.written = gains;
    }
    PidTuneRequest again = o;
    again.fmaxHz = m.fmaxHz;
    auto after = measureOpenLoop(drive, again, m.fmaxHz, run);
    if (!after) {
        a.refusal = "the verifying measurement failed: " + after.error().detail;
    } else {
        std::vector<double> fa;
        std::vector<std::complex<double>> la;
        validLines(after->frf, fa, la);
        a.measured = tuning::positionLoopMargins(fa, la);
        a.measuredOk = true;
        a.motionTimeS = after->motionTimeS;
        a.frf = std::move(after).value();
        const double pm = o.scope == PidTuneScope::NotchOnly ? std::min(o.phaseMarginDeg, p.predicted.phaseMarginDeg)
                                                             : o.phaseMarginDeg;
        const double gm =
            o.scope == PidTuneScope::NotchOnly ? std::min(o.gainMarginDb, p.predicted.gainMarginDb) : o.gainMarginDb;
        if (!(a.measured.phaseMarginDeg >= pm - 3.0) || !(a.measured.gainMarginDb >= gm - 1.0))
            a.refusal = "the measured loop misses the margins asked (phase margin " +
                        fmt(a.measured.phaseMarginDeg, 4) + " deg, gain margin " + fmt(a.measured.gainMarginDb, 4) +
                        " dB)";
    }
    if (!a.refusal.empty()) {
        // Put back what ran before: nothing stays on a loop that could not be verified.
        restore();
        a.refusal += "; the gains from before were restored";
        if (notchChanges)
            a.refusal += a.notchBefore ? " and the notch from before (" + notchText(*a.notchBefore) + ") put back"
                                       : " and the notch removed";
        return a;
    }
    a.applied = true;
    return a;
}

bool PidTuneNotchUndo::changes() const
{
    return !sameNotch(before, applied);
}

Status checkPidTuneNotchUndo(device::Drive& drive, const PidTuneNotchUndo& undo, bool force)
{
    if (!undo.changes() || force)
        return Status::success();
    auto now = device::hal::readAxisNotch(drive, undo.axis);
    if (!now)
        return now.error();
    auto close = [](double a, double b) { return std::abs(a - b) <= 1e-5 * std::abs(b); };
    const bool same = now->has_value() == undo.applied.has_value() &&
                      (!undo.applied || (close((*now)->f0Hz, undo.applied->f0Hz) && close((*now)->q, undo.applied->q)));
    if (!same)
        return makeError(ErrorCode::Safety,
                         "AxisTune's notch after " + undo.axis + " is " +
                             (*now ? notchText(*asBiquad(*now)) : std::string("not there")) + ", not the one the tune "
                             "applied (" + (undo.applied ? notchText(*undo.applied) : std::string("none")) +
                             "): it was changed since; putting the one from before back would undo that change");
    return Status::success();
}

Result<PidTuneNotchUndone> undoPidTuneNotch(device::Drive& drive, const PidTuneNotchUndo& undo)
{
    PidTuneNotchUndone done;
    if (!undo.changes())
        return done;
    // What HAL holds now, read before the write: a forced undo overwrites a later change, and the journal says which.
    auto held = device::hal::readAxisNotch(drive, undo.axis);
    if (!held)
        return held.error();
    done.held = asBiquad(*held);
    if (auto st = device::hal::restoreAxisNotch(drive, undo.axis, asAxisNotch(undo.before)); !st)
        return st.error();
    done.changed = true;
    done.restored = undo.before;
    return done;
}

} // namespace axistune::autotune

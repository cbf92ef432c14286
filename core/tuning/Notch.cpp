// SPDX-License-Identifier: GPL-3.0-or-later
// Notch placement per resonance and predicted loop with the notches, spec/current-loop-and-multisweep-frf.md
// §3.8 (notch realisation: Tustin pre-warped at f0, bandwidth-warp correction x/(sin x cos x)) and
// §4.4 (Wizard D: centre = peak, width from the −3 dB width, predicted FRF = measured loop × filter).
// Depth/width rule: Notch.h and docs/notch.md.
#include "core/tuning/Notch.h"

#include "core/model/MetadataKeys.h"
#include "core/model/Units.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace axistune::tuning {

namespace {

std::string num(double v) { return model::formatNumber(v, 6); }

}  // namespace

double notchWidthParameter(double centerHz, double digitalWidthHz, double execRateHz)
{
    // Digital −3 dB edges of the pre-warped notch: tan(ω±h/2) = tan x·(√(1+ζ²) ± ζ), x = π f0 h. Their
    // product is tan²x and their difference 2ζ tan x, so tan(π W h) = ζ·sin 2x exactly; for small
    // angles this is the spec's W·x/(sin x cos x).
    const double h = 1.0 / execRateHz;
    const double zeta = std::tan(std::numbers::pi * digitalWidthHz * h) / std::sin(2.0 * std::numbers::pi * centerHz * h);
    return 2.0 * centerHz * zeta;
}

Status checkExistingNotch(const dsp::NotchSpec& n, double execRateHz, const std::string& what)
{
    if (!std::isfinite(n.centerHz) || !std::isfinite(n.widthHz) || !std::isfinite(n.depth))
        return makeError(ErrorCode::BadInput, what + ": centre, width and depth must be finite numbers");
    auto b = dsp::designNotch(n, 1.0 / execRateHz);
    if (!b)
        return makeError(b.error().code, what + ": " + b.error().detail);
    return Status::success();
}

Result<NotchProposal> proposeNotches(const std::vector<Resonance>& resonances, const std::vector<dsp::NotchSpec>& existing,
                                     const NotchOptions& o)
{
    if (!(o.execRateHz > 0.0) || !std::isfinite(o.execRateHz))
        return makeError(ErrorCode::BadInput, "execution rate must be > 0 Hz, got " + num(o.execRateHz));
    if (o.slotCount < 0 || o.maxNotches < 0)
        return makeError(ErrorCode::BadInput, "slot count and maximum number of notches must be >= 0");
    if (!std::isfinite(o.targetOpenLoopDb))
        return makeError(ErrorCode::BadInput, "target open-loop gain must be finite");
    const int used = static_cast<int>(existing.size());
    if (used > o.slotCount)
        return makeError(ErrorCode::BadInput, std::to_string(used) + " existing notches but the drive has only "
                                                  + std::to_string(o.slotCount) + " slots");
    for (std::size_t k = 0; k < existing.size(); ++k)
        if (auto st = checkExistingNotch(existing[k], o.execRateHz, "existing notch " + std::to_string(k + 1)); !st)
            return st.error();

    NotchProposal p;
    p.slotsFree = o.slotCount - used;
    const int limit = std::min(p.slotsFree, o.maxNotches);
    const double nyquist = 0.5 * o.execRateHz;
    const double target = std::pow(10.0, o.targetOpenLoopDb / 20.0);

    std::vector<const Resonance*> order;
    for (const auto& r : resonances) {
        if (!(r.freqHz < nyquist)) {
            p.skipped.push_back({r.freqHz, "at or above the execution Nyquist frequency " + num(nyquist) + " Hz"});
            continue;
        }
        order.push_back(&r);
    }
    std::stable_sort(order.begin(), order.end(),
                     [](const Resonance* a, const Resonance* b) { return a->levelDb > b->levelDb; });
    int slot = used;
    for (const Resonance* r : order) {
        if (static_cast<int>(p.notches.size()) >= limit) {
            p.skipped.push_back({r->freqHz, p.notches.size() == static_cast<std::size_t>(p.slotsFree)
                                                ? "no free notch slot"
                                                : "more resonances than --max allows"});
            continue;
        }
        const double f0 = r->freqHz;
        const double gainAtPeak = std::pow(10.0, r->levelDb / 20.0);
        const double depth = std::min(std::pow(10.0, -r->peakDb / 20.0), target / gainAtPeak);
        const double maxWidth = std::min(f0, 2.0 * (nyquist - f0));
        const double width = std::clamp(r->widthHz / depth, std::min(r->widthHz, maxWidth), maxWidth);
        ProposedNotch n;
        n.spec = {f0, notchWidthParameter(f0, width, o.execRateHz), depth};
        n.digitalWidthHz = width;
        n.resonanceHz = f0;
        if (auto b = dsp::designNotch(n.spec, 1.0 / o.execRateHz); !b) {
            p.skipped.push_back({f0, "not realisable: " + b.error().detail});
            continue;
        }
        n.slot = ++slot;
        p.notches.push_back(n);
    }
    return p;
}

dsp::FrequencyResponse openLoopOf(const dsp::FrequencyResponse& measured, const LoopForm& form)
{
    return form.open ? measured : dsp::openLoopFromClosedLoop(measured, form.closed);
}

dsp::FrequencyResponse measuredFormOf(const dsp::FrequencyResponse& l, const LoopForm& form)
{
    if (form.open)
        return l;
    dsp::FrequencyResponse m;
    m.metadata = l.metadata;
    m.metadata.erase(model::meta::kLoop);
    for (std::size_t i = 0; i < l.size(); ++i) {
        const std::complex<double> v = l.h[i];
        const std::complex<double> den = 1.0 + v;
        const bool ok = (i >= l.valid.size() || l.valid[i]) && std::abs(den) > 1e-12 * std::max(1.0, std::abs(v));
        std::complex<double> out;
        switch (form.closed) {
        case dsp::LoopMeasurement::Complementary: out = v / den; break;
        case dsp::LoopMeasurement::NegComplementary: out = -v / den; break;
        case dsp::LoopMeasurement::Sensitivity: out = 1.0 / den; break;
        }
        const double coh = i < l.coherence.size() ? l.coherence[i] : std::nan("");
        m.push(l.freqHz[i], ok ? out : std::complex<double>(0.0, 0.0), coh, ok);
    }
    return m;
}

Result<NotchPrediction> predictWithNotches(const dsp::FrequencyResponse& measured, const LoopForm& form,
                                           const std::vector<dsp::NotchSpec>& notches, double execRateHz)
{
    if (!(execRateHz > 0.0) || !std::isfinite(execRateHz))
        return makeError(ErrorCode::BadInput, "execution rate must be > 0 Hz, got " + num(execRateHz));
    const double h = 1.0 / execRateHz;
    dsp::FilterCascade cascade;
    for (std::size_t k = 0; k < notches.size(); ++k) {
        auto b = dsp::designNotch(notches[k], h);
        if (!b)
            return makeError(b.error().code, "notch " + std::to_string(k + 1) + ": " + b.error().detail);
        cascade.add(*b);
    }
    NotchPrediction p;
    p.openLoopBefore = openLoopOf(measured, form);
    p.openLoopAfter = p.openLoopBefore;
    p.openLoopAfter.metadata.set("notches", static_cast<double>(notches.size()));
    for (std::size_t i = 0; i < p.openLoopAfter.size(); ++i)
        p.openLoopAfter.h[i] *= cascade.response(p.openLoopAfter.freqHz[i], h);
    p.measuredAfter = measuredFormOf(p.openLoopAfter, form);
    p.before = dsp::loopMargins(p.openLoopBefore);
    p.after = dsp::loopMargins(p.openLoopAfter);
    return p;
}

std::vector<ProposedNotch> allocateNotchSlots(const NotchProposal& proposal,
                                              const std::map<int, dsp::NotchSpec>& existing, int slotCount)
{
    std::vector<int> freeSlots;
    for (int s = 1; s <= slotCount; ++s)
        if (!existing.count(s))
            freeSlots.push_back(s);
    const int k = static_cast<int>(existing.size());
    std::vector<ProposedNotch> out;
    for (auto n : proposal.notches) {
        const int idx = n.slot - k - 1;
        if (idx < 0 || idx >= static_cast<int>(freeSlots.size()))
            continue;
        n.slot = freeSlots[static_cast<std::size_t>(idx)];
        out.push_back(n);
    }
    std::sort(out.begin(), out.end(), [](const ProposedNotch& a, const ProposedNotch& b) { return a.slot < b.slot; });
    return out;
}

Result<NotchAnalysis> analyseNotches(const dsp::FrequencyResponse& measured, const LoopForm& form,
                                     const ResonanceOptions& resonanceOptions, const NotchOptions& notchOptions,
                                     const std::map<int, dsp::NotchSpec>& existing)
{
    NotchAnalysis a;
    auto res = findResonances(openLoopOf(measured, form), resonanceOptions);
    if (!res)
        return res.error();
    a.resonances = std::move(res).value();
    std::vector<dsp::NotchSpec> packed;
    for (const auto& [slot, n] : existing)
        packed.push_back(n);
    auto prop = proposeNotches(a.resonances, packed, notchOptions);
    if (!prop)
        return prop.error();
    a.proposal = std::move(prop).value();
    a.notches = allocateNotchSlots(a.proposal, existing, notchOptions.slotCount);
    std::vector<dsp::NotchSpec> added;
    for (const auto& n : a.notches)
        added.push_back(n.spec);
    auto pred = predictWithNotches(measured, form, added, notchOptions.execRateHz);
    if (!pred)
        return pred.error();
    a.prediction = std::move(pred).value();
    return a;
}

}  // namespace axistune::tuning

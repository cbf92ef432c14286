// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Notch-filter tuning on a measured velocity-loop FRF (spec/current-loop-and-multisweep-frf.md §3.8,
// §4.4 "Wizard D"): a notch per resonance within the execution rate's limits, the predicted FRF with
// the notches and the margins before and after. See docs/notch.md for the rules.
//
// Filter semantics: those of the drive (dsp::designNotch, as the simulated drive runs its
// filter.notchN.center/width/depth): N(s) = (s²+2dζω0 s+ω0²)/(s²+2ζω0 s+ω0²), ζ = width/(2 f0),
// Tustin pre-warped at f0, run at the execution rate (the current loop). The proposed width
// parameter is chosen so that the DIGITAL full-depth −3 dB width W equals the intended width:
// width_param = 2 f0 · tan(π W/f_exec) / sin(2π f0/f_exec), exact (the spec §3.8 correction
// W·x/(sin x cos x), x = π f0/f_exec, is its small-angle form and leaves 597.6 Hz for 600 Hz at 3.3 kHz).
//
// Proposal per resonance (f_r, height H dB, −3 dB width w, open-loop gain |L_r|):
//   depth  d = min(10^(−H/20), 10^(target/20) / |L_r|)  (flattens the peak to its baseline and brings
//          the open-loop gain at the resonance to the target or below);
//   width  w_d = clamp(w / d, w, min(f0, 2 (f_N − f0)))  digital −3 dB width: with w/d the notch
//          zeros lie on the mode's poles (ζ_notch·d = ζ_mode), so the peak drops by d without side lobes;
//   centre f_r; a resonance at or above the execution Nyquist frequency f_N is never notched.
// Slots: the drive has `slotCount` notches; the existing ones occupy slots 1..k and are never
// changed or removed. At most min(maxNotches, slotCount − k) notches are proposed, the resonances
// with the highest open-loop gain first.

#include "core/dsp/DigitalFilter.h"
#include "core/dsp/FrequencyResponse.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/model/Result.h"
#include "core/tuning/Resonance.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace axistune::tuning {

/// What the measured FRF is: the open loop L itself, or one of the closed-loop forms of LoopAnalysis.h.
struct LoopForm {
    bool open = false;
    dsp::LoopMeasurement closed = dsp::LoopMeasurement::Complementary;  ///< used when !open
};

struct NotchOptions {
    double execRateHz = 16000.0;   ///< rate the notches run at (current loop)
    int slotCount = 4;             ///< notch slots of the drive (filter.notch1..4)
    int maxNotches = 4;            ///< upper bound on proposed notches
    double targetOpenLoopDb = -20.0;  ///< open-loop gain wanted at each notched resonance
};

struct ProposedNotch {
    dsp::NotchSpec spec;           ///< drive parameters (centre, width parameter, depth)
    double digitalWidthHz = 0.0;   ///< realised digital full-depth −3 dB width
    double resonanceHz = 0.0;
    int slot = 0;                  ///< 1-based drive slot
};

struct SkippedResonance {
    double freqHz = 0.0;
    std::string reason;
};

struct NotchProposal {
    std::vector<ProposedNotch> notches;   ///< increasing slot
    std::vector<SkippedResonance> skipped;
    int slotsFree = 0;
};

/// Checks an existing notch for execution at `execRateHz` (same rules as the drive). `what` names it in errors.
Status checkExistingNotch(const dsp::NotchSpec& n, double execRateHz, const std::string& what);

/// Proposes notches for `resonances` (found on the open loop, so levelDb is |L_r|).
Result<NotchProposal> proposeNotches(const std::vector<Resonance>& resonances, const std::vector<dsp::NotchSpec>& existing,
                                     const NotchOptions& options);

/// The drive slots of a proposal: proposeNotches numbers the added notches k+1, k+2, … after the k existing ones;
/// here they go to the drive's free slots (1..slotCount not in `existing`, increasing), and a notch beyond the
/// free slots is left out. Sorted by slot.
std::vector<ProposedNotch> allocateNotchSlots(const NotchProposal& proposal,
                                              const std::map<int, dsp::NotchSpec>& existing, int slotCount);

/// Drive width parameter whose digital −3 dB width is exactly `digitalWidthHz` (< execRateHz/2).
double notchWidthParameter(double centerHz, double digitalWidthHz, double execRateHz);

/// Open loop from a measurement of the given form (a copy when open).
dsp::FrequencyResponse openLoopOf(const dsp::FrequencyResponse& measured, const LoopForm& form);
/// The measured form of an open loop L (inverse of openLoopOf); invalid points stay invalid.
dsp::FrequencyResponse measuredFormOf(const dsp::FrequencyResponse& openLoop, const LoopForm& form);

struct NotchPrediction {
    dsp::FrequencyResponse openLoopBefore;
    dsp::FrequencyResponse openLoopAfter;   ///< L · Π N_k(e^{jωh})
    dsp::FrequencyResponse measuredAfter;   ///< predicted FRF in the measured form
    dsp::LoopMargins before;
    dsp::LoopMargins after;
};

/// The measured FRF with `notches` added in the torque-command path (run at execRateHz).
Result<NotchPrediction> predictWithNotches(const dsp::FrequencyResponse& measured, const LoopForm& form,
                                           const std::vector<dsp::NotchSpec>& notches, double execRateHz);

/// The whole notch analysis of one measured FRF (the notch wizard and `axistune-cli notch`): resonances on the open
/// loop, the proposal, the notches on the drive's free slots, the prediction with them.
struct NotchAnalysis {
    std::vector<Resonance> resonances;
    NotchProposal proposal;             ///< as proposeNotches numbers it (after the existing ones)
    std::vector<ProposedNotch> notches; ///< on the drive's slots (allocateNotchSlots), increasing slot
    NotchPrediction prediction;         ///< the measured FRF with the added notches
};
/// Errors: those of findResonances, proposeNotches (an existing notch the rate cannot run) and predictWithNotches.
Result<NotchAnalysis> analyseNotches(const dsp::FrequencyResponse& measured, const LoopForm& form,
                                     const ResonanceOptions& resonanceOptions, const NotchOptions& notchOptions,
                                     const std::map<int, dsp::NotchSpec>& existing);

}  // namespace axistune::tuning

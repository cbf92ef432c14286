// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Tap (impact-hammer) testing: the FRF of a structure from hammer force and response records
// (docs/machining.md "Tap test"; method: Ewins, Modal Testing §3.9 "Transient excitation",
// Schmitz & Smith, Machining Dynamics §2.6):
//   1. hits: the force crosses the trigger level upwards (default 10 % of the record's largest |force|);
//      crossings later than the double-hit window after a hit are separate hits, earlier ones are a
//      double hit (the hammer bounced): refused with its times, or that hit dropped with a note;
//   2. blocks: from the trigger minus the pre-trigger, all of one length (the record's end or the next
//      hit, whichever comes first over all hits, or the length asked for);
//   3. force window: the force is kept from the block start to the trigger plus the force window
//      (default: twice the time the pulse takes to fall back below 5 % of its peak) and zeroed after;
//   4. exponential window exp(−t/τ) on force and response (optional): the FRF of the windowed records is
//      H(s + σ) with σ = 1/τ, i.e. every pole moves left by σ. The decay is written to the FRF
//      (metadata exp_window_decay_1_s) and removed from fitted modes (machining::removeExponentialWindow);
//   5. H1 over the hits: H = Σ conj(F)·X / Σ |F|², coherence = |Σ conj(F)·X|² / (Σ|F|²·Σ|X|²) (defined
//      from two hits on; one hit gives no coherence, NaN, never a meaningless 1);
//   6. conversion between accelerance, mobility and receptance by (jω)^(n_out − n_in), DC excluded;
//   7. a point is valid where the averaged force spectrum is within forceRangeDb of its level at the
//      lowest frequencies (above that the hammer does not excite the structure).

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Result.h"

#include <string>
#include <vector>

namespace axistune::dsp {

/// Order of the time derivative of displacement: displacement 0, velocity 1, acceleration 2.
enum class MotionQuantity { Displacement = 0, Velocity = 1, Acceleration = 2 };
enum class DoubleHitPolicy { Refuse, Drop };

struct ImpactRecord {
    std::string name;             ///< for messages (file name)
    std::vector<double> forceN;   ///< hammer force [N]
    std::vector<double> response; ///< response in SI (m, m/s or m/s² by ImpactOptions::response)
};

struct ImpactOptions {
    double fsHz = 0.0;
    MotionQuantity response = MotionQuantity::Acceleration;
    MotionQuantity output = MotionQuantity::Displacement; ///< receptance (m/N), mobility, accelerance
    double triggerLevelN = 0.0;                           ///< 0: 10 % of the record's largest |force|
    double preTriggerS = -1.0;                            ///< < 0: 1 ms or what the record has before the first hit
    double forceWindowS = 0.0;                            ///< 0: automatic (see above)
    double expTauS = 0.0;                                 ///< 0: no exponential window
    double lengthS = 0.0;                                 ///< 0: automatic block length
    double doubleHitWindowS = 0.05; ///< a second crossing closer than this after a hit is a double hit
    DoubleHitPolicy doubleHit = DoubleHitPolicy::Refuse;
    double forceRangeDb = 40.0; ///< valid where the force spectrum is within this of its low-frequency level
    /// Points below are invalid. < 0: automatic, 50 Hz when acceleration becomes receptance, 20 Hz for one
    /// integration (a piezo accelerometer does not measure near DC and 1/ω² magnifies its noise), else 0.
    double minFrequencyHz = -1.0;
};

struct ImpactHit {
    std::string record;
    double triggerS = 0.0; ///< time of the trigger crossing in its record
    double peakForceN = 0.0;
    double pulseS = 0.0;  ///< trigger to the force back below 5 % of the peak
    bool dropped = false; ///< a double hit dropped by DoubleHitPolicy::Drop
    std::string note;
};

struct ImpactResult {
    FrequencyResponse frf;       ///< metadata: units, hits, block, windows, decay, band
    std::vector<ImpactHit> hits; ///< all hits found, dropped ones flagged
    std::size_t used = 0;        ///< hits averaged
    double blockS = 0.0, preTriggerS = 0.0, forceWindowS = 0.0;
    double expDecayPerS = 0.0;      ///< σ = 1/τ added by the exponential window (0 without)
    double forceBandHz = 0.0;       ///< first frequency where the force spectrum leaves forceRangeDb
    double residualResponse = 0.0;  ///< |response| at the block end / its peak, worst hit (leakage check)
    std::vector<std::string> notes; ///< messages for the user (dropped hits, leakage)
};

/// SI unit token of an FRF of `output` per newton: m/N, m/s/N, m/s2/N.
std::string impactUnits(MotionQuantity output);

/// The averaged FRF of all hits of all records. Errors name the record and time: no hit, a double hit
/// (policy Refuse), a pre-trigger or length that the records do not have, non-finite samples.
Result<ImpactResult> impactFrf(const std::vector<ImpactRecord>& records, const ImpactOptions& options);

} // namespace axistune::dsp

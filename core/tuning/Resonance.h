// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Resonance detection on a measured loop frequency response (spec/current-loop-and-multisweep-frf.md
// §4.3 step 7: "resonance candidates with frequency, peak height and −3 dB width"). See docs/notch.md.
//
// Rule (on the magnitude in dB against log10 f, usable points only):
//   usable     valid, finite, non-zero, f > 0, coherence NaN (undefined) or ≥ minCoherence;
//   weight     γ²/(1−γ²) (inverse variance of the magnitude estimate; 1 where coherence is undefined);
//   baseline   at every usable point, a robust straight line (Tukey bisquare IRLS, coherence-weighted)
//              through the points within ±halfWindowOctaves; peaks and anti-resonances are its outliers;
//   noise      1.4826 · median |second difference| / √6 of the dB values in the window (the
//              point-to-point scatter, free of the smooth trend and of peaks several points wide);
//   candidate  a local maximum of the excess over the baseline with excess ≥ minHeightDb and
//              ≥ noiseFactor · noise;
//   peak       vertex of the parabola through the excess at the maximum and its two neighbours
//              (in log f), height = excess at the vertex [dB above the baseline];
//   width      between the −3 dB crossings of the excess (linear interpolation in log f), walked from
//              the maximum over contiguous usable points; with only one crossing found, twice that
//              half; with none, the candidate is not a resonance (a shoulder or a trend);
//   merging    candidates inside the −3 dB band of a higher one are dropped.

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Result.h"

#include <cstddef>
#include <vector>

namespace axistune::tuning {

struct ResonanceOptions {
    double halfWindowOctaves = 0.5;  ///< baseline window: f·2^(±halfWindowOctaves)
    double minHeightDb = 6.0;        ///< smallest height above the baseline
    double noiseFactor = 4.0;        ///< height must also exceed this many local noise scales
    double minCoherence = 0.5;       ///< points below are not used (where coherence is defined)
    double fminHz = 0.0;             ///< search band
    double fmaxHz = 1e300;
};

struct Resonance {
    double freqHz = 0.0;       ///< peak frequency (parabolic vertex)
    double peakDb = 0.0;       ///< height above the local baseline [dB]
    double widthHz = 0.0;      ///< full width at peakDb − 3 dB [Hz]
    double levelDb = 0.0;      ///< magnitude of the analysed response at the peak [dB]
    double baselineDb = 0.0;   ///< baseline at the peak [dB]
    double noiseDb = 0.0;      ///< local noise scale of the baseline fit [dB]
    bool widthOneSided = false;  ///< only one −3 dB crossing was found (width = twice that half)
    std::size_t index = 0;     ///< index of the highest point in the response
};

/// Resonances of `frf` (usually the open loop), sorted by increasing frequency. Errors (BadInput):
/// fewer than 5 usable points, invalid options.
Result<std::vector<Resonance>> findResonances(const dsp::FrequencyResponse& frf, const ResonanceOptions& options = {});

}  // namespace axistune::tuning

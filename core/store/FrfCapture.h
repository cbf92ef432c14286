// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A frequency response stored in a session (docs/storage.md): a capture whose metadata says
// content=frf, with the channels f_Hz, re, im, mag_dB, phase_deg, coherence (NaN: not defined) and
// valid (1/0), and the FRF's own metadata. The CLI (--db) and the GUI store FRFs this way, and the
// session review reads them back with frfFromCapture.

#include "core/dsp/FrequencyResponse.h"
#include "core/model/Capture.h"
#include "core/model/Result.h"

namespace axistune::store {

model::Capture frfAsCapture(const dsp::FrequencyResponse& frf);
/// True when a stored capture holds an FRF (metadata content=frf).
bool isFrfCapture(const model::Capture& capture);
/// The FRF back from frfAsCapture's layout; errors name the missing channel or the length mismatch.
Result<dsp::FrequencyResponse> frfFromCapture(const model::Capture& capture);

}  // namespace axistune::store

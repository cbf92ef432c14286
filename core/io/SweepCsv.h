// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Sine-stream CSV (DESIGN.md "File formats"):
//   # fs_Hz=4000
//   # amplitude=0.5
//   freq_Hz,phase_offset_deg,sample,excitation,response
// one row per traced sample. Consecutive rows with the same frequency and phase offset form one
// block (one sweep at one frequency); `sample` is the index k counted from the start of the
// measurement window (t = k/fs, negative while settling) and increases by one within a block.
// A frequency with three offsets (0, +120, -120) is demodulated by the multi-sweep method, with one
// offset by the conventional method (core/dsp/SineDemodulation.h). fs_Hz is required, amplitude
// optional (informational; the FRF divides by the demodulated excitation).

#include "core/dsp/SineDemodulation.h"
#include "core/model/Result.h"

#include <istream>
#include <ostream>
#include <string>

namespace axistune::io {

inline constexpr const char* kSweepCsvHeader = "freq_Hz,phase_offset_deg,sample,excitation,response";

Result<dsp::SweepRecording> readSweepCsv(std::istream& in, const std::string& sourceName);
Result<dsp::SweepRecording> readSweepCsvFile(const std::string& path);

/// Writes fs_Hz, amplitude and the other metadata, the header and every block's rows.
Status writeSweepCsv(std::ostream& out, const dsp::SweepRecording& recording);
Status writeSweepCsvFile(const std::string& path, const dsp::SweepRecording& recording);

}  // namespace axistune::io

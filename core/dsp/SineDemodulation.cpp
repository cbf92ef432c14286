// SPDX-License-Identifier: GPL-3.0-or-later
// Conventional and three-phase multi-sweep sine-stream demodulation,
// spec/current-loop-and-multisweep-frf.md §3.3 (Fourier coefficients), §3.5 (multi-sweep, patent
// JP 5813151) and §3.6 (alias-free ranges fs/2 and fs). Phase = atan2(a, b) (the thesis' (3.11)
// and (3.28) print the inverse ratio; the spec's correction is followed).
#include "core/dsp/SineDemodulation.h"

#include "core/model/Constants.h"
#include "core/model/MetadataKeys.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace axistune::dsp {

namespace {

using model::kRadPerDeg;

// Σ y[i]·cos(ω k + ψ) and Σ y[i]·sin(ω k + ψ) with k = first + i, the angle reduced in cycles first
// so that long windows keep full accuracy.
void correlate(const SweepSamples& s, double cyclesPerSample, double& sc, double& ss)
{
    const double psi = s.phaseOffsetDeg * kRadPerDeg;
    for (std::size_t i = 0; i < s.y.size(); ++i) {
        const double k = static_cast<double>(s.firstSample + static_cast<std::int64_t>(i));
        const double c = std::fmod(cyclesPerSample * k, 1.0);
        const double th = 2.0 * std::numbers::pi * c + psi;
        sc += s.y[i] * std::cos(th);
        ss += s.y[i] * std::sin(th);
    }
}

bool sameAngle(double aDeg, double bDeg)
{
    const double d = std::remainder(aDeg - bDeg, 360.0);
    return std::abs(d) < 1e-6;
}

}  // namespace

Result<Demodulated> demodulate(std::span<const SweepSamples> sweeps, double freqHz, double fsHz)
{
    if (!(fsHz > 0.0))
        return makeError(ErrorCode::BadInput, "demodulation: sampling frequency must be positive");
    if (!(freqHz > 0.0) || !std::isfinite(freqHz))
        return makeError(ErrorCode::BadInput, "demodulation: frequency must be positive");
    if (sweeps.size() != 1 && sweeps.size() != 3) {
        return makeError(ErrorCode::BadInput, "demodulation at " + std::to_string(freqHz) + " Hz: "
                                                  + std::to_string(sweeps.size())
                                                  + " phase offsets; expected 1 (conventional) or 3 (multi-sweep)");
    }
    for (const auto& s : sweeps) {
        if (s.y.empty())
            return makeError(ErrorCode::BadInput, "demodulation at " + std::to_string(freqHz) + " Hz: empty window");
        if (s.firstSample != sweeps[0].firstSample || s.y.size() != sweeps[0].y.size()) {
            return makeError(ErrorCode::BadInput, "demodulation at " + std::to_string(freqHz)
                                                      + " Hz: the sweeps cover different sample windows");
        }
    }
    Demodulated d;
    d.multiSweep = sweeps.size() == 3;
    if (d.multiSweep) {
        for (double want : {0.0, 120.0, -120.0}) {
            const bool found = std::any_of(sweeps.begin(), sweeps.end(),
                                           [&](const SweepSamples& s) { return sameAngle(s.phaseOffsetDeg, want); });
            if (!found) {
                return makeError(ErrorCode::BadInput, "demodulation at " + std::to_string(freqHz)
                                                          + " Hz: multi-sweep needs phase offsets 0, +120 and -120 deg");
            }
        }
    }
    double sc = 0.0, ss = 0.0;
    for (const auto& s : sweeps)
        correlate(s, freqHz / fsHz, sc, ss);
    const double norm = 2.0 / (static_cast<double>(sweeps.size()) * static_cast<double>(sweeps[0].y.size()));
    d.a = norm * sc;
    d.b = norm * ss;
    d.valid = d.multiSweep ? freqHz < fsHz : freqHz < 0.5 * fsHz;
    return d;
}

std::array<double, 2> parkTransform(double u, double v, double w, double theta)
{
    // Sᵀ[u v w] with S = sqrt(2/3)[cos 0, cos 2π/3, cos 4π/3; sin 0, sin 2π/3, sin 4π/3]ᵀ
    const double k = std::sqrt(2.0 / 3.0);
    const double c1 = std::cos(2.0 * std::numbers::pi / 3.0), c2 = std::cos(4.0 * std::numbers::pi / 3.0);
    const double s1 = std::sin(2.0 * std::numbers::pi / 3.0), s2 = std::sin(4.0 * std::numbers::pi / 3.0);
    const double alpha = k * (u + c1 * v + c2 * w);
    const double beta = k * (s1 * v + s2 * w);
    // R(θ)ᵀ = [cos θ, sin θ; -sin θ, cos θ]
    return {std::cos(theta) * alpha + std::sin(theta) * beta, -std::sin(theta) * alpha + std::cos(theta) * beta};
}

Result<FrequencyResponse> sineStreamFrf(const SweepRecording& rec)
{
    if (!(rec.fsHz > 0.0))
        return makeError(ErrorCode::BadInput, "sine stream: fs_Hz must be positive");
    // Group blocks by frequency (exact value as written in the file).
    std::map<double, std::vector<const SweepBlock*>> byFreq;
    for (const auto& b : rec.blocks)
        byFreq[b.freqHz].push_back(&b);
    if (byFreq.empty())
        return makeError(ErrorCode::BadInput, "sine stream: no data");
    FrequencyResponse frf;
    bool anyMulti = false, anyConventional = false;
    for (const auto& [f, blocks] : byFreq) {
        const std::string at = "sine stream at " + std::to_string(f) + " Hz";
        std::vector<SweepSamples> ys, xs;
        for (const SweepBlock* b : blocks) {
            auto first = std::find_if(b->sample.begin(), b->sample.end(), [](std::int64_t k) { return k >= 0; });
            const auto i0 = static_cast<std::size_t>(first - b->sample.begin());
            for (std::size_t i = i0 + 1; i < b->sample.size(); ++i) {
                if (b->sample[i] != b->sample[i - 1] + 1)
                    return makeError(ErrorCode::BadInput, at + ": sample indices must increase by one");
            }
            if (i0 == b->sample.size())
                return makeError(ErrorCode::BadInput, at + ": no samples with index >= 0 (measurement window)");
            const std::size_t m = b->sample.size() - i0;
            ys.push_back({b->phaseOffsetDeg, b->sample[i0], std::span<const double>(b->response).subspan(i0, m)});
            xs.push_back({b->phaseOffsetDeg, b->sample[i0], std::span<const double>(b->excitation).subspan(i0, m)});
        }
        auto dy = demodulate(ys, f, rec.fsHz);
        if (!dy)
            return dy.error();
        auto dx = demodulate(xs, f, rec.fsHz);
        if (!dx)
            return dx.error();
        if (dx->amplitude() == 0.0)
            return makeError(ErrorCode::BadInput, at + ": the excitation is zero");
        (dy->multiSweep ? anyMulti : anyConventional) = true;
        frf.push(f, dy->phasor() / dx->phasor(), std::nan(""), dy->valid);
    }
    frf.metadata.set(model::meta::kMethod, anyMulti && anyConventional ? "sine-stream-mixed"
                                           : anyMulti                  ? "multisweep"
                                                                       : "conventional");
    frf.metadata.set(model::meta::kFsHz, rec.fsHz);
    return frf;
}

}  // namespace axistune::dsp

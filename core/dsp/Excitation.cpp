// SPDX-License-Identifier: GPL-3.0-or-later
// Excitation signals: stepped sine stream (spec/current-loop-and-multisweep-frf.md §3.3, §3.5,
// §4.3), maximal-length PRBS (Fibonacci LFSR with primitive feedback polynomials, tap table after
// Xilinx XAPP052) and linear/exponential chirps (phase as the integral of the instantaneous frequency).
#include "core/dsp/Excitation.h"

#include "core/model/Constants.h"

#include <cmath>
#include <numbers>
#include <string>

namespace axistune::dsp {

namespace {

Status checkAmplitude(double amplitude, double limit)
{
    if (!(amplitude > 0.0) || !std::isfinite(amplitude))
        return makeError(ErrorCode::OutOfRange, "excitation amplitude must be positive");
    if (!(amplitude <= limit)) {
        return makeError(ErrorCode::OutOfRange, "excitation amplitude " + std::to_string(amplitude)
                                                    + " exceeds its limit " + std::to_string(limit));
    }
    return {};
}

}  // namespace

Result<std::vector<SineStreamSegment>> planSineStream(const SineStreamOptions& o)
{
    if (auto s = checkAmplitude(o.amplitude, o.amplitudeLimit); !s)
        return s.error();
    if (!(o.fsHz > 0.0))
        return makeError(ErrorCode::BadInput, "sine stream: sampling frequency must be positive");
    if (o.freqHz.empty())
        return makeError(ErrorCode::BadInput, "sine stream: no frequencies");
    if (o.periods == 0)
        return makeError(ErrorCode::OutOfRange, "sine stream: at least one period per frequency");
    if (o.settleTimeS < 0.0 || o.settlePeriods < 0.0 || o.minMeasureTimeS < 0.0)
        return makeError(ErrorCode::OutOfRange, "sine stream: settle and measure times must not be negative");
    if (o.phaseOffsetsDeg.empty())
        return makeError(ErrorCode::BadInput, "sine stream: no phase offset");
    std::vector<SineStreamSegment> plan;
    for (double f : o.freqHz) {
        if (!(f > 0.0) || !(f < o.fsHz)) {
            return makeError(ErrorCode::OutOfRange, "sine stream: frequency " + std::to_string(f)
                                                        + " Hz outside (0, fs = " + std::to_string(o.fsHz) + " Hz)");
        }
        const double settleS = std::max(o.settleTimeS, o.settlePeriods / f);
        auto periods = static_cast<std::size_t>(std::max<double>(static_cast<double>(o.periods),
                                                                 std::ceil(o.minMeasureTimeS * f - 1e-9)));
        const auto measure = std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(periods * o.fsHz / f)));
        for (double psi : o.phaseOffsetsDeg) {
            SineStreamSegment seg;
            seg.freqHz = f;
            seg.phaseOffsetDeg = psi;
            seg.settleSamples = static_cast<std::size_t>(std::ceil(settleS * o.fsHz - 1e-9));
            seg.measureSamples = measure;
            seg.periods = periods;
            plan.push_back(seg);
        }
    }
    return plan;
}

double sineStreamValue(const SineStreamSegment& s, double amplitude, std::int64_t k, double fsHz)
{
    // Phase reduced modulo one period in integer arithmetic would need rational f/fs; fmod of the
    // product keeps the argument small enough for full double accuracy at practical lengths.
    const double cycles = std::fmod(s.freqHz * static_cast<double>(k) / fsHz, 1.0);
    return amplitude * std::sin(model::kTwoPi * cycles + s.phaseOffsetDeg * model::kRadPerDeg);
}

std::size_t sineStreamLength(const std::vector<SineStreamSegment>& plan)
{
    std::size_t n = 0;
    for (const auto& s : plan)
        n += s.settleSamples + s.measureSamples;
    return n;
}

Result<std::vector<double>> makePrbs(const PrbsOptions& o)
{
    if (auto s = checkAmplitude(o.amplitude, o.amplitudeLimit); !s)
        return s.error();
    // Taps (1-based bit positions) of primitive polynomials, XAPP052 table.
    static const unsigned kTaps[25][4] = {
        {0}, {0}, {2, 1}, {3, 2}, {4, 3}, {5, 3}, {6, 5}, {7, 6}, {8, 6, 5, 4}, {9, 5}, {10, 7}, {11, 9},
        {12, 6, 4, 1}, {13, 4, 3, 1}, {14, 5, 3, 1}, {15, 14}, {16, 15, 13, 4}, {17, 14}, {18, 11}, {19, 6, 2, 1},
        {20, 17}, {21, 19}, {22, 21}, {23, 18}, {24, 23, 22, 17}};
    if (o.order < 2 || o.order > 24)
        return makeError(ErrorCode::OutOfRange, "PRBS order must lie in 2..24");
    if (o.holdSamples == 0 || o.periods == 0)
        return makeError(ErrorCode::OutOfRange, "PRBS: hold samples and periods must be at least 1");
    const std::size_t bits = (std::size_t{1} << o.order) - 1;
    std::vector<double> seq;
    seq.reserve(bits);
    std::uint32_t reg = (1u << o.order) - 1;
    for (std::size_t i = 0; i < bits; ++i) {
        const unsigned out = reg & 1u;
        seq.push_back(out ? o.amplitude : -o.amplitude);
        // XNOR-free Fibonacci form on the right-shifting register: bit (n - tap) holds tap position.
        unsigned fb = 0;
        for (unsigned t : kTaps[o.order]) {
            if (t != 0)
                fb ^= (reg >> (o.order - t)) & 1u;
        }
        reg = (reg >> 1) | (fb << (o.order - 1));
    }
    std::vector<double> out;
    out.reserve(bits * o.holdSamples * o.periods);
    for (std::size_t p = 0; p < o.periods; ++p) {
        for (double v : seq)
            out.insert(out.end(), o.holdSamples, v);
    }
    return out;
}

Result<std::vector<double>> makeChirp(const ChirpOptions& o)
{
    if (auto s = checkAmplitude(o.amplitude, o.amplitudeLimit); !s)
        return s.error();
    if (!(o.fsHz > 0.0) || !(o.durationS > 0.0))
        return makeError(ErrorCode::OutOfRange, "chirp: sampling frequency and duration must be positive");
    const double nyq = 0.5 * o.fsHz;
    if (!(o.f0Hz >= 0.0) || !(o.f1Hz >= 0.0) || o.f0Hz >= nyq || o.f1Hz >= nyq) {
        return makeError(ErrorCode::OutOfRange, "chirp: frequencies must lie in [0, fs/2 = " + std::to_string(nyq) + " Hz)");
    }
    if (o.kind == ChirpKind::Exponential && (!(o.f0Hz > 0.0) || !(o.f1Hz > 0.0) || o.f0Hz == o.f1Hz))
        return makeError(ErrorCode::OutOfRange, "exponential chirp: f0 and f1 must be positive and different");
    const auto n = static_cast<std::size_t>(std::llround(o.durationS * o.fsHz));
    std::vector<double> out(n);
    const double T = o.durationS;
    const double twoPi = 2.0 * std::numbers::pi;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = static_cast<double>(k) / o.fsHz;
        double cycles = 0.0;
        if (o.kind == ChirpKind::Linear) {
            cycles = o.f0Hz * t + 0.5 * (o.f1Hz - o.f0Hz) * t * t / T;
        } else {
            const double lnk = std::log(o.f1Hz / o.f0Hz);
            cycles = o.f0Hz * T / lnk * std::expm1(lnk * t / T);
        }
        out[k] = o.amplitude * std::sin(twoPi * (cycles - std::floor(cycles)));
    }
    return out;
}

}  // namespace axistune::dsp

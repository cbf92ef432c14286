// SPDX-License-Identifier: GPL-3.0-or-later
// Tap testing: trigger, force and exponential windows, double hits, H1 over hits, unit conversion
// (core/dsp/ImpactTest.h; Ewins, Modal Testing §3.9; Schmitz & Smith, Machining Dynamics §2.6).
#include "core/dsp/ImpactTest.h"

#include "core/dsp/Fft.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Units.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

namespace axistune::dsp {

namespace {

std::string num(double v, int digits = 4)
{
    return model::formatNumber(v, digits);
}

struct Crossing {
    std::size_t record = 0;
    std::size_t index = 0; // first sample at or above the level
};

// Upward crossings of `level` with hysteresis (the force must fall below level/2 before the next one).
std::vector<std::size_t> crossings(const std::vector<double>& f, double level)
{
    std::vector<std::size_t> out;
    bool armed = true;
    for (std::size_t i = 0; i < f.size(); ++i) {
        if (armed && f[i] >= level) {
            out.push_back(i);
            armed = false;
        } else if (!armed && f[i] < 0.5 * level) {
            armed = true;
        }
    }
    return out;
}

} // namespace

std::string impactUnits(MotionQuantity output)
{
    switch (output) {
    case MotionQuantity::Displacement:
        return "m/N";
    case MotionQuantity::Velocity:
        return "m/s/N";
    case MotionQuantity::Acceleration:
        return "m/s2/N";
    }
    return "m/N";
}

Result<ImpactResult> impactFrf(const std::vector<ImpactRecord>& records, const ImpactOptions& o)
{
    if (!(o.fsHz > 0.0) || !std::isfinite(o.fsHz))
        return makeError(ErrorCode::BadInput, "sampling frequency must be positive");
    if (records.empty())
        return makeError(ErrorCode::BadInput, "no impact record");
    if (o.expTauS < 0.0 || o.forceWindowS < 0.0 || o.lengthS < 0.0 || o.triggerLevelN < 0.0 ||
        !(o.doubleHitWindowS > 0.0))
        return makeError(ErrorCode::OutOfRange, "trigger level, windows and length must not be negative");
    const double dt = 1.0 / o.fsHz;
    ImpactResult res;

    // 1. hits per record
    struct Hit {
        std::size_t record, trigger, pulseEnd;
        double peak;
        bool dropped;
    };
    std::vector<Hit> hits;
    for (std::size_t r = 0; r < records.size(); ++r) {
        const auto& rec = records[r];
        if (rec.forceN.size() != rec.response.size())
            return makeError(ErrorCode::BadInput, rec.name + ": force and response have different lengths");
        for (std::size_t i = 0; i < rec.forceN.size(); ++i) {
            if (!std::isfinite(rec.forceN[i]) || !std::isfinite(rec.response[i]))
                return makeError(ErrorCode::BadInput,
                                 rec.name + ": sample " + std::to_string(i + 1) + " is not finite");
        }
        double fmax = 0.0;
        for (double v : rec.forceN)
            fmax = std::max(fmax, std::abs(v));
        if (!(fmax > 0.0))
            return makeError(ErrorCode::BadInput, rec.name + ": the force is zero everywhere, no hit");
        const double level = o.triggerLevelN > 0.0 ? o.triggerLevelN : 0.1 * fmax;
        const auto cr = crossings(rec.forceN, level);
        if (cr.empty())
            return makeError(ErrorCode::BadInput, rec.name + ": the force never reaches the trigger level " +
                                                      num(level) + " N (largest " + num(fmax) + " N)");
        const auto window = static_cast<std::size_t>(std::llround(o.doubleHitWindowS * o.fsHz));
        for (std::size_t k = 0; k < cr.size(); ++k) {
            Hit h{r, cr[k], cr[k], 0.0, false};
            std::size_t end = k + 1 < cr.size() ? cr[k + 1] : rec.forceN.size();
            for (std::size_t i = cr[k]; i < end && rec.forceN[i] >= 0.05 * h.peak; ++i) {
                h.peak = std::max(h.peak, rec.forceN[i]);
                h.pulseEnd = i + 1;
            }
            ImpactHit info{rec.name, static_cast<double>(cr[k]) * dt,
                           h.peak,   static_cast<double>(h.pulseEnd - cr[k]) * dt,
                           false,    {}};
            // a rebound: further crossings inside the double-hit window belong to this hit
            std::size_t j = k + 1;
            while (j < cr.size() && cr[j] - cr[k] < window)
                ++j;
            if (j > k + 1) {
                const std::string what = rec.name + ": double hit at " + num(static_cast<double>(cr[k]) * dt, 6) +
                                         " s: the force crosses " + num(level) + " N again at " +
                                         num(static_cast<double>(cr[k + 1]) * dt, 6) +
                                         " s, within the double-hit window of " + num(o.doubleHitWindowS) + " s";
                if (o.doubleHit == DoubleHitPolicy::Refuse)
                    return makeError(ErrorCode::BadInput, what + "; repeat the hit or drop it (--double-hit drop)");
                h.dropped = true;
                info.dropped = true;
                info.note = what + "; dropped";
                res.notes.push_back(info.note);
            }
            hits.push_back(h);
            res.hits.push_back(info);
            k = j - 1;
        }
    }
    std::size_t used = 0;
    for (const auto& h : hits)
        used += h.dropped ? 0 : 1;
    if (used == 0)
        return makeError(ErrorCode::BadInput, "every hit was a double hit and was dropped; no FRF");

    // 2. pre-trigger and block length common to all hits
    std::size_t preAvail = std::numeric_limits<std::size_t>::max();
    for (const auto& h : hits)
        preAvail = h.dropped ? preAvail : std::min(preAvail, h.trigger);
    std::size_t pre = 0;
    if (o.preTriggerS >= 0.0) {
        pre = static_cast<std::size_t>(std::llround(o.preTriggerS * o.fsHz));
        if (pre > preAvail)
            return makeError(ErrorCode::OutOfRange, "pre-trigger " + num(o.preTriggerS) + " s: a hit has only " +
                                                        num(static_cast<double>(preAvail) * dt) +
                                                        " s of record before its trigger");
    } else {
        pre = std::min(preAvail, static_cast<std::size_t>(std::llround(1e-3 * o.fsHz)));
    }
    std::size_t block = std::numeric_limits<std::size_t>::max();
    for (std::size_t k = 0; k < hits.size(); ++k) {
        const auto& h = hits[k];
        if (h.dropped)
            continue;
        const std::size_t start = h.trigger - pre;
        std::size_t end = records[h.record].forceN.size();
        if (k + 1 < hits.size() && hits[k + 1].record == h.record)
            end = hits[k + 1].trigger - std::min(pre, hits[k + 1].trigger);
        block = std::min(block, end - start);
    }
    if (o.lengthS > 0.0) {
        const auto want = static_cast<std::size_t>(std::llround(o.lengthS * o.fsHz));
        if (want > block)
            return makeError(ErrorCode::OutOfRange, "block length " + num(o.lengthS) + " s: the hits leave only " +
                                                        num(static_cast<double>(block) * dt) + " s");
        block = want;
    }
    if (block < 16)
        return makeError(ErrorCode::BadInput, "the hits are only " + std::to_string(block) + " samples apart; no FRF");

    // 3.–5. windows, FFT, sums over hits
    const double sigma = o.expTauS > 0.0 ? 1.0 / o.expTauS : 0.0;
    RealFft fft(block);
    const std::size_t bins = fft.bins();
    std::vector<std::complex<double>> sxy(bins);
    std::vector<double> sxx(bins, 0.0), syy(bins, 0.0);
    double forceWindowS = 0.0;
    for (const auto& h : hits) {
        if (h.dropped)
            continue;
        const auto& rec = records[h.record];
        const std::size_t start = h.trigger - pre;
        const std::size_t pulse = h.pulseEnd - h.trigger;
        const std::size_t keep = o.forceWindowS > 0.0 ? static_cast<std::size_t>(std::llround(o.forceWindowS * o.fsHz))
                                                      : std::max<std::size_t>(2 * pulse, 5);
        const std::size_t forceEnd = std::min(block, pre + keep); // samples of the block that keep the force
        forceWindowS = std::max(forceWindowS, static_cast<double>(forceEnd - pre) * dt);
        double peakResp = 0.0, endResp = 0.0;
        const std::size_t tail = std::max<std::size_t>(block / 50, 1);
        for (std::size_t i = 0; i < block; ++i) {
            const double a = std::abs(rec.response[start + i]);
            peakResp = std::max(peakResp, a);
            if (i + tail >= block)
                endResp = std::max(endResp, a);
        }
        if (peakResp > 0.0)
            res.residualResponse = std::max(res.residualResponse, endResp / peakResp);
        auto in = fft.input();
        for (std::size_t i = 0; i < block; ++i)
            in[i] = (i < forceEnd ? rec.forceN[start + i] : 0.0) * std::exp(-sigma * static_cast<double>(i) * dt);
        fft.execute();
        std::vector<std::complex<double>> F(fft.output().begin(), fft.output().end());
        for (std::size_t i = 0; i < block; ++i)
            in[i] = rec.response[start + i] * std::exp(-sigma * static_cast<double>(i) * dt);
        fft.execute();
        const auto X = fft.output();
        for (std::size_t k = 0; k < bins; ++k) {
            sxy[k] += std::conj(F[k]) * X[k];
            sxx[k] += std::norm(F[k]);
            syy[k] += std::norm(X[k]);
        }
        ++res.used;
    }

    // 6.–7. H1, coherence, conversion, force band
    const int order = static_cast<int>(o.output) - static_cast<int>(o.response);
    const double df = o.fsHz / static_cast<double>(block);
    const std::size_t lowBins = std::max<std::size_t>(1, std::min<std::size_t>(bins - 1, 5));
    double ref = 0.0;
    for (std::size_t k = 1; k <= lowBins; ++k)
        ref += sxx[k] / static_cast<double>(lowBins);
    const double floor = ref * std::pow(10.0, -o.forceRangeDb / 10.0);
    const double fmin = o.minFrequencyHz >= 0.0 ? o.minFrequencyHz : order <= -2 ? 50.0 : order == -1 ? 20.0 : 0.0;
    res.forceBandHz = static_cast<double>(bins - 1) * df;
    bool bandSet = false;
    for (std::size_t k = 1; k < bins; ++k) {
        const double f = static_cast<double>(k) * df;
        const bool ok = sxx[k] >= floor && sxx[k] > 0.0;
        if (!ok && !bandSet) {
            res.forceBandHz = f;
            bandSet = true;
        }
        std::complex<double> h = sxx[k] > 0.0 ? sxy[k] / sxx[k] : std::complex<double>(0.0, 0.0);
        const std::complex<double> jw(0.0, 2.0 * std::numbers::pi * f);
        h *= std::pow(jw, order);
        const double coh =
            res.used >= 2 && sxx[k] > 0.0 && syy[k] > 0.0 ? std::norm(sxy[k]) / (sxx[k] * syy[k]) : std::nan("");
        res.frf.push(f, h, coh, ok && f >= fmin);
    }
    res.blockS = static_cast<double>(block) * dt;
    res.preTriggerS = static_cast<double>(pre) * dt;
    res.forceWindowS = forceWindowS;
    res.expDecayPerS = sigma;
    if (res.residualResponse > 0.02 && sigma == 0.0) {
        res.notes.push_back("the response at the end of the block is still " + num(100.0 * res.residualResponse, 3) +
                            " % of its peak: leakage; use an exponential window (--exp-tau) or a longer record");
    }
    auto& md = res.frf.metadata;
    md.set(model::meta::kMethod, "impact-h1");
    md.set(model::meta::kUnits, impactUnits(o.output));
    md.set("hits", static_cast<double>(res.used));
    md.set("hits_dropped", static_cast<double>(hits.size() - res.used));
    md.set(model::meta::kFsHz, o.fsHz);
    md.set("block_s", res.blockS);
    md.set("pre_trigger_s", res.preTriggerS);
    md.set("force_window_s", res.forceWindowS);
    md.set("exp_window_tau_s", o.expTauS);
    md.set(model::meta::kExpWindowDecay, sigma);
    md.set("force_band_Hz", res.forceBandHz);
    md.set("force_range_dB", o.forceRangeDb);
    md.set("fmin_Hz", fmin);
    return res;
}

} // namespace axistune::dsp

// SPDX-License-Identifier: GPL-3.0-or-later
// Gain/phase margins and peak sensitivity on measured open-loop data (classical Nyquist/Bode
// margins, e.g. Skogestad & Postlethwaite, "Multivariable Feedback Control", §2.4); open loop from
// the closed-loop velocity FRF of spec/current-loop-and-multisweep-frf.md §3.2 (3.1).
#include "core/dsp/LoopAnalysis.h"

#include "core/model/MetadataKeys.h"

#include <cmath>

namespace axistune::dsp {

FrequencyResponse openLoopFromClosedLoop(const FrequencyResponse& m, LoopMeasurement kind)
{
    FrequencyResponse l;
    l.metadata = m.metadata;
    l.metadata.set(model::meta::kLoop, "open-loop");
    for (std::size_t i = 0; i < m.size(); ++i) {
        const std::complex<double> v = m.h[i];
        std::complex<double> den;
        std::complex<double> num;
        switch (kind) {
        case LoopMeasurement::Complementary: num = v; den = 1.0 - v; break;
        case LoopMeasurement::NegComplementary: num = -v; den = 1.0 + v; break;
        case LoopMeasurement::Sensitivity: num = 1.0 - v; den = v; break;
        }
        const bool ok = m.valid[i] && std::abs(den) > 1e-12 * std::max(1.0, std::abs(num));
        l.push(m.freqHz[i], ok ? num / den : std::complex<double>(0.0, 0.0), m.coherence[i], ok);
    }
    return l;
}

namespace {

struct Pt {
    double logF, logMag, phaseDeg, f;
    std::complex<double> h;
};

double lerp(double a, double b, double t) { return a + (b - a) * t; }

}  // namespace

LoopMargins loopMargins(const FrequencyResponse& L)
{
    LoopMargins r;
    // Runs of consecutive valid points with f > 0 and L ≠ 0; phase unwrapped within a run.
    std::vector<std::vector<Pt>> runs(1);
    for (std::size_t i = 0; i < L.size(); ++i) {
        const bool ok = L.valid[i] && L.freqHz[i] > 0.0 && std::abs(L.h[i]) > 0.0;
        if (!ok) {
            if (!runs.back().empty())
                runs.emplace_back();
            continue;
        }
        runs.back().push_back({std::log10(L.freqHz[i]), std::log10(std::abs(L.h[i])), phaseDeg(L.h[i]), L.freqHz[i], L.h[i]});
        const double s = std::abs(1.0 / (1.0 + L.h[i]));
        if (s > r.peakSensitivity) {
            r.peakSensitivity = s;
            r.peakSensitivityFreqHz = L.freqHz[i];
        }
    }
    r.peakSensitivityDb = r.peakSensitivity > 0.0 ? 20.0 * std::log10(r.peakSensitivity) : -LoopMargins::kInf;
    for (auto& run : runs) {
        std::vector<double> ph;
        for (const auto& p : run)
            ph.push_back(p.phaseDeg);
        ph = unwrapDeg(ph);
        for (std::size_t i = 0; i < run.size(); ++i)
            run[i].phaseDeg = ph[i];
        for (std::size_t i = 1; i < run.size(); ++i) {
            const Pt& a = run[i - 1];
            const Pt& b = run[i];
            // gain crossover: log|L| changes sign (a point exactly at 0 dB counts once, as the left end)
            if ((a.logMag >= 0.0 && b.logMag < 0.0) || (a.logMag <= 0.0 && b.logMag > 0.0)) {
                const double t = a.logMag / (a.logMag - b.logMag);
                const double phase = lerp(a.phaseDeg, b.phaseDeg, t);
                const double pm = std::remainder(phase + 180.0, 360.0);
                r.gainCrossovers.push_back({std::pow(10.0, lerp(a.logF, b.logF, t)), 0.0, pm == -180.0 ? 180.0 : pm});
            }
            // phase crossover: the unwrapped phase passes −180 + 360k
            const double ka = std::floor((a.phaseDeg + 180.0) / 360.0);
            const double kb = std::floor((b.phaseDeg + 180.0) / 360.0);
            if (ka != kb) {
                const double level = -180.0 + 360.0 * std::max(ka, kb);
                const double t = (level - a.phaseDeg) / (b.phaseDeg - a.phaseDeg);
                const double logMag = lerp(a.logMag, b.logMag, t);
                r.phaseCrossovers.push_back({std::pow(10.0, lerp(a.logF, b.logF, t)), -20.0 * logMag, 0.0});
            }
        }
    }
    for (const auto& c : r.gainCrossovers) {
        if (std::abs(c.marginDeg) < std::abs(r.phaseMarginDeg)) {
            r.phaseMarginDeg = c.marginDeg;
            r.phaseMarginFreqHz = c.freqHz;
        }
    }
    for (const auto& c : r.phaseCrossovers) {
        if (std::abs(c.marginDb) < std::abs(r.gainMarginDb)) {
            r.gainMarginDb = c.marginDb;
            r.gainMarginFreqHz = c.freqHz;
        }
    }
    return r;
}

}  // namespace axistune::dsp

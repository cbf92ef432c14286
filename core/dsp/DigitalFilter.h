// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Digital filters of the torque-command path: second-order notch and low-pass, designed by the
// Tustin transform with pre-warping at the characteristic frequency, and their cascade.
//
// Notch convention (documented in docs/algorithms.md):
//   N(s) = (s^2 + 2·d·ζ·ω0·s + ω0^2) / (s^2 + 2·ζ·ω0·s + ω0^2),  ζ = width / (2·f0)
// f0 the centre, d the depth (gain at the centre, 0 = full notch, 1 = no notch) and width the full
// -3 dB bandwidth of the full-depth prototype. Pre-warping at f0 makes the discrete gain at the
// centre exactly d. A notch whose centre is at or above the Nyquist frequency of its execution
// rate is refused.

#include "core/model/Result.h"

#include <complex>
#include <vector>

namespace axistune::dsp {

struct NotchSpec {
    double centerHz = 0.0;
    double widthHz = 0.0;
    double depth = 0.0;  ///< linear gain at the centre, 0..1
};

/// Direct-form-II-transposed biquad: y = (b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2) x.
class Biquad {
public:
    Biquad() = default;
    Biquad(double b0, double b1, double b2, double a1, double a2) : m_b0(b0), m_b1(b1), m_b2(b2), m_a1(a1), m_a2(a2) {}

    double process(double x)
    {
        const double y = m_b0 * x + m_s1;
        m_s1 = m_b1 * x - m_a1 * y + m_s2;
        m_s2 = m_b2 * x - m_a2 * y;
        return y;
    }
    void reset() { m_s1 = m_s2 = 0.0; }
    /// Frequency response at f [Hz] for a sample period h [s].
    std::complex<double> response(double fHz, double periodS) const;

    double b0() const { return m_b0; }
    double b1() const { return m_b1; }
    double b2() const { return m_b2; }
    double a1() const { return m_a1; }
    double a2() const { return m_a2; }

private:
    double m_b0 = 1.0, m_b1 = 0.0, m_b2 = 0.0, m_a1 = 0.0, m_a2 = 0.0;
    double m_s1 = 0.0, m_s2 = 0.0;
};

/// Notch designed for execution period h. Errors: centre ≥ Nyquist, width ≤ 0, depth outside [0, 1].
Result<Biquad> designNotch(const NotchSpec& spec, double periodS);
/// First-order low-pass with cutoff fc (Tustin, pre-warped at fc), stored as a biquad with b2 = a2 = 0.
Result<Biquad> designLowPass(double cutoffHz, double periodS);

/// A cascade of biquads run at one rate.
class FilterCascade {
public:
    void add(const Biquad& b) { m_stages.push_back(b); }
    void clear() { m_stages.clear(); }
    double process(double x)
    {
        for (auto& s : m_stages)
            x = s.process(x);
        return x;
    }
    void reset()
    {
        for (auto& s : m_stages)
            s.reset();
    }
    std::complex<double> response(double fHz, double periodS) const;
    const std::vector<Biquad>& stages() const { return m_stages; }

private:
    std::vector<Biquad> m_stages;
};

}  // namespace axistune::dsp

namespace axistune::dsp {

/// Notch whose digital full-depth -3 dB width equals spec.widthHz (not only the analogue
/// prototype's). Centre-only pre-warping shrinks the digital width by (sin x·cos x)/x with
/// x = π·f0·h (spec/current-loop-and-multisweep-frf.md §3.8: 3.3 kHz/600 Hz at 16 kHz would give
/// 444.7 Hz); this designs the prototype with width·x/(sin x·cos x) instead. Same errors as designNotch.
Result<Biquad> designNotchDigitalWidth(const NotchSpec& spec, double periodS);

}  // namespace axistune::dsp

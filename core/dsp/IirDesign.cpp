// SPDX-License-Identifier: GPL-3.0-or-later
// Butterworth / Chebyshev I low-pass in second-order sections (analog prototype, pre-warped bilinear
// transform) and forward-backward filtering with odd extension and steady-state initial conditions
// (Gustafsson's zero-phase filtering as implemented by scipy.signal.sosfiltfilt); docs/identification.md.
#include "core/dsp/IirDesign.h"

#include <cmath>
#include <complex>
#include <numbers>
#include <string>

namespace axistune::dsp {
namespace {

using cd = std::complex<double>;

Status checkArgs(int order, double wn)
{
    if (order < 2 || order > 16 || order % 2 != 0)
        return makeError(ErrorCode::OutOfRange, "filter order " + std::to_string(order) + " is not even in 2..16");
    if (!(wn > 0.0 && wn < 1.0))
        return makeError(ErrorCode::OutOfRange, "filter cutoff must lie strictly between 0 and the Nyquist frequency");
    return Status::success();
}

// The analog prototype poles (upper half plane, one per conjugate pair) → sections, unity DC each.
Sos sectionsFromPoles(const std::vector<cd>& upperPoles, double wn)
{
    // Bilinear transform with the design rate fs = 2 (the cutoff is a fraction of Nyquist):
    // pre-warped analog cutoff 2·fs·tan(π·wn/2), z = (2·fs + s)/(2·fs − s).
    const double fs2 = 4.0;
    const double warped = fs2 * std::tan(std::numbers::pi * wn / 2.0);
    Sos sos;
    for (const cd& p0 : upperPoles) {
        const cd s = p0 * warped;
        const cd z = (fs2 + s) / (fs2 - s);
        SosSection sec;
        sec.a = {-2.0 * z.real(), std::norm(z)};
        const double g = (1.0 + sec.a[0] + sec.a[1]) / 4.0; // zeros at −1: numerator (1 + z⁻¹)²
        sec.b = {g, 2.0 * g, g};
        sos.push_back(sec);
    }
    return sos;
}

// Steady state of one direct-form-II-transposed section for a unit input.
std::array<double, 2> unitSteadyState(const SosSection& s)
{
    const double gain = (s.b[0] + s.b[1] + s.b[2]) / (1.0 + s.a[0] + s.a[1]);
    const double z2 = s.b[2] - s.a[1] * gain;
    const double z1 = s.b[1] - s.a[0] * gain + z2;
    return {z1, z2};
}

void runSections(const Sos& sos, std::vector<double>& x, double initialLevel)
{
    double level = initialLevel; // the steady-state input of each section for a constant signal
    for (const auto& s : sos) {
        auto z = unitSteadyState(s);
        double z1 = z[0] * level, z2 = z[1] * level;
        for (double& v : x) {
            const double y = s.b[0] * v + z1;
            z1 = s.b[1] * v - s.a[0] * y + z2;
            z2 = s.b[2] * v - s.a[1] * y;
            v = y;
        }
        level *= (s.b[0] + s.b[1] + s.b[2]) / (1.0 + s.a[0] + s.a[1]);
    }
}

} // namespace

Result<Sos> butterworthLowPass(int order, double wn)
{
    if (auto st = checkArgs(order, wn); !st)
        return st.error();
    std::vector<cd> poles;
    for (int k = 0; k < order / 2; ++k) {
        const double th = std::numbers::pi * (2.0 * k + order + 1) / (2.0 * order);
        poles.push_back(std::polar(1.0, th));
    }
    return sectionsFromPoles(poles, wn);
}

Result<Sos> chebyshev1LowPass(int order, double rippleDb, double wn)
{
    if (auto st = checkArgs(order, wn); !st)
        return st.error();
    if (!(rippleDb > 0.0 && rippleDb < 10.0))
        return makeError(ErrorCode::OutOfRange, "Chebyshev ripple must lie in (0, 10) dB");
    const double eps = std::sqrt(std::pow(10.0, rippleDb / 10.0) - 1.0);
    const double mu = std::asinh(1.0 / eps) / order;
    std::vector<cd> poles;
    for (int k = 0; k < order / 2; ++k) {
        const double th = std::numbers::pi * (2.0 * k + 1) / (2.0 * order);
        poles.emplace_back(-std::sinh(mu) * std::sin(th), std::cosh(mu) * std::cos(th));
    }
    Sos sos = sectionsFromPoles(poles, wn);
    const double dc = std::pow(10.0, -rippleDb / 20.0); // even order: DC sits at the ripple's bottom
    for (double& b : sos.front().b)
        b *= dc;
    return sos;
}

Result<std::vector<double>> filtfiltSos(const Sos& sos, const std::vector<double>& x)
{
    const std::size_t pad = 3 * (2 * sos.size() + 1);
    if (x.size() <= pad) {
        return makeError(ErrorCode::BadInput, "zero-phase filter needs more than " + std::to_string(pad) +
                                                  " samples, got " + std::to_string(x.size()));
    }
    const std::size_t n = x.size();
    std::vector<double> ext;
    ext.reserve(n + 2 * pad);
    for (std::size_t i = pad; i >= 1; --i)
        ext.push_back(2.0 * x.front() - x[i]);
    ext.insert(ext.end(), x.begin(), x.end());
    for (std::size_t i = 1; i <= pad; ++i)
        ext.push_back(2.0 * x.back() - x[n - 1 - i]);
    runSections(sos, ext, ext.front());
    std::vector<double> rev(ext.rbegin(), ext.rend());
    runSections(sos, rev, rev.front());
    std::vector<double> y(n);
    for (std::size_t i = 0; i < n; ++i)
        y[i] = rev[rev.size() - 1 - (pad + i)];
    return y;
}

} // namespace axistune::dsp

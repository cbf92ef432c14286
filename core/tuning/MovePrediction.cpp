// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/tuning/MovePrediction.h"

#include "core/dsp/Fft.h"
#include "core/model/Number.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace axistune::tuning {
namespace {

using cd = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// P_eff at any frequency from the measured lines (see the header).
class PlantInterpolator {
public:
    PlantInterpolator(const std::vector<double>& f, const std::vector<cd>& p, DriveInput input)
        : m_f(f), m_logMag(f.size()), m_phase(f.size()), m_order(input == DriveInput::Torque ? 2.0 : 1.0)
    {
        for (std::size_t i = 0; i < f.size(); ++i) {
            m_logMag[i] = std::log(std::abs(p[i]));
            const double ph = std::arg(p[i]);
            if (i == 0) {
                m_phase[i] = ph;
            } else {
                double d = ph - std::remainder(m_phase[i - 1], kTwoPi);
                d = std::remainder(d, kTwoPi);
                m_phase[i] = m_phase[i - 1] + d;
            }
        }
    }
    bool inside(double fHz) const { return fHz >= m_f.front() && fHz <= m_f.back(); }
    cd at(double fHz) const
    {
        if (fHz <= m_f.front())
            return std::polar(std::exp(m_logMag.front()) * std::pow(m_f.front() / fHz, m_order), m_phase.front());
        if (fHz >= m_f.back())
            return std::polar(std::exp(m_logMag.back()) * std::pow(m_f.back() / fHz, m_order), m_phase.back());
        const auto it = std::upper_bound(m_f.begin(), m_f.end(), fHz);
        const std::size_t hi = static_cast<std::size_t>(it - m_f.begin());
        const std::size_t lo = hi - 1;
        // Linear in log f: a rigid body (a power of f) is interpolated exactly between widely spaced low lines.
        const double w = std::log(fHz / m_f[lo]) / std::log(m_f[hi] / m_f[lo]);
        return std::polar(std::exp((1.0 - w) * m_logMag[lo] + w * m_logMag[hi]),
                          (1.0 - w) * m_phase[lo] + w * m_phase[hi]);
    }

private:
    const std::vector<double>& m_f;
    std::vector<double> m_logMag;
    std::vector<double> m_phase;
    double m_order;
};

std::size_t nextFftSize(std::size_t n)
{
    std::size_t p = 1;
    while (p < n)
        p <<= 1;
    return p;
}

} // namespace

Result<MovePrediction> predictMove(const std::vector<double>& freqHz, const std::vector<std::complex<double>>& plant,
                                   const PositionPid& pid, double periodS, std::span<const double> command,
                                   const MovePredictionOptions& options)
{
    if (freqHz.size() < 3 || plant.size() != freqHz.size())
        return makeError(ErrorCode::BadInput, "a move prediction needs at least 3 measured lines of the plant");
    for (std::size_t i = 0; i < freqHz.size(); ++i) {
        if (!(freqHz[i] > 0.0) || !std::isfinite(freqHz[i]) || !std::isfinite(plant[i].real()) ||
            !std::isfinite(plant[i].imag()) || plant[i] == cd(0.0))
            return makeError(ErrorCode::BadInput,
                             "plant line " + std::to_string(i) + " is not a finite, non-zero value");
        if (i > 0 && !(freqHz[i] > freqHz[i - 1]))
            return makeError(ErrorCode::BadInput, "plant lines must ascend in frequency");
    }
    if (!(periodS > 0.0) || !std::isfinite(periodS))
        return makeError(ErrorCode::BadInput, "servo period must be positive");
    if (command.size() < 2)
        return makeError(ErrorCode::BadInput, "the move's command has fewer than 2 samples");
    double span = 0.0;
    for (double x : command) {
        if (!std::isfinite(x))
            return makeError(ErrorCode::BadInput, "the move's command holds a value that is not a finite number");
        span = std::max(span, std::abs(x - command.front()));
    }
    if (std::abs(command.back() - command.front()) > 1e-9 * std::max(span, 1e-300))
        return makeError(ErrorCode::BadInput, "the move must end where it starts (out and back)");
    if (!(options.restAfterS >= 0.0) || !std::isfinite(options.restAfterS))
        return makeError(ErrorCode::BadInput, "rest after the move must not be negative");

    const std::size_t rest = static_cast<std::size_t>(std::ceil(options.restAfterS / periodS));
    const std::size_t n = nextFftSize(command.size() + rest);
    dsp::RealFft fwd(n);
    std::fill(fwd.input().begin(), fwd.input().end(), 0.0);
    for (std::size_t i = 0; i < command.size(); ++i)
        fwd.input()[i] = command[i] - command.front();
    fwd.execute();

    const double order = options.input == DriveInput::Torque ? 2.0 : 1.0;
    auto solve = [&]() {
        const PlantInterpolator p(freqHz, plant, options.input);
        dsp::InverseRealFft errInv(n);
        dsp::InverseRealFft outInv(n);
        errInv.input()[0] = 0.0; // DC: the loop holds any constant command without error (integrator, or a plant with
        outInv.input()[0] = 0.0; // a pole at 0)
        double inside = 0.0, outside = 0.0;
        for (std::size_t k = 1; k < fwd.bins(); ++k) {
            const cd r = fwd.output()[k];
            const double f = static_cast<double>(k) / (static_cast<double>(n) * periodS);
            const cd zInv = std::polar(1.0, -kTwoPi * f * periodS);
            const cd diff = (1.0 - zInv) / periodS;
            const cd cD = pid.d * diff;
            const cd cPi = pidResponse(pid, periodS, f) - cD;
            const cd c = cPi + cD;
            const cd cr = options.errorPreviousTarget ? cPi * zInv + cD : c;
            const cd ff = pid.ff1 * diff + pid.ff2 * diff * diff;
            const cd notch = options.notch ? biquadNotchResponse(*options.notch, periodS, f) : cd(1.0);
            const cd pn = p.at(f) * notch;
            const cd y = pn * (cr + ff) * r / (1.0 + pn * c);
            const cd e = (options.errorPreviousTarget ? zInv * r : r) - y;
            errInv.input()[k] = e;
            outInv.input()[k] = (cr + ff) * r - c * y;
            (p.inside(f) ? inside : outside) += std::norm(e);
        }
        errInv.execute();
        outInv.execute();
        MovePrediction out;
        out.extrapolatedShare = inside + outside > 0.0 ? outside / (inside + outside) : 0.0;
        out.error.resize(command.size());
        out.output.resize(command.size());
        const double scale = 1.0 / static_cast<double>(n);
        for (std::size_t i = 0; i < command.size(); ++i) {
            out.error[i] = errInv.output()[i] * scale;
            out.output[i] = outInv.output()[i] * scale;
            out.peakError = std::max(out.peakError, std::abs(out.error[i]));
            out.peakOutput = std::max(out.peakOutput, std::abs(out.output[i]));
        }
        return out;
    };
    MovePrediction out = solve();
    // The slope of |P| over the lowest decade of lines (least squares in log-log): the extrapolation below the band
    // continues it as the rigid body, which holds when the measured plant is one there.
    double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
    for (std::size_t i = 0; i < freqHz.size() && freqHz[i] <= 10.0 * freqHz.front(); ++i, ++m) {
        const double x = std::log10(freqHz[i]), y = std::log10(std::abs(plant[i]));
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    out.lowDecadeOrder = m >= 3 && m * sxx - sx * sx > 0.0 ? -(m * sxy - sx * sy) / (m * sxx - sx * sx) : NAN;
    if (out.extrapolatedShare > options.maxExtrapolatedShare &&
        !(std::abs(out.lowDecadeOrder - order) <= options.maxOrderDeviation))
        return makeError(ErrorCode::OutOfRange,
                         model::formatNumber(100.0 * out.extrapolatedShare, 3) +
                             " % of the predicted following error lies below the measured lines (" +
                             model::formatNumber(freqHz.front(), 4) + " to " + model::formatNumber(freqHz.back(), 4) +
                             " Hz), where the plant is extrapolated as a rigid body (|P| ∝ f^-" +
                             model::formatNumber(order, 1) + "), but over its lowest measured decade it falls as f^-" +
                             model::formatNumber(out.lowDecadeOrder, 3) +
                             ": measure down to a lower --fmin before trusting it");
    return out;
}

} // namespace axistune::tuning

// SPDX-License-Identifier: GPL-3.0-or-later
// Chatter avoidance by spindle-speed control (ChatterAvoidance.h; spec/chatter-stability-and-spindle-speed.md
// §3.0–§3.4). The stable-pocket rule is SpindleSpeed's pocketAdvice; the frequency estimate is
// ChatterFrequencyEstimator; the filters are the Butterworth designs of CuttingForceObserver and
// VibrationModeChatter.
#include "core/machining/ChatterAvoidance.h"

#include "core/machining/CuttingForceObserver.h"
#include "core/machining/SpindleSpeed.h"
#include "core/machining/VibrationModeChatter.h"
#include "core/model/Constants.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace axistune::machining {

namespace {
std::string str(double v)
{
    return std::to_string(v);
}
} // namespace

Result<double> multiModeCost(int rho, const std::vector<double>& freqsHz, const std::vector<double>& weights)
{
    if (freqsHz.empty())
        return makeError(ErrorCode::BadInput, "J_chat: no chatter frequency");
    if (freqsHz.size() != weights.size())
        return makeError(ErrorCode::BadInput, "J_chat: " + std::to_string(freqsHz.size()) + " frequencies but " +
                                                  std::to_string(weights.size()) + " weights");
    if (rho < 1)
        return makeError(ErrorCode::OutOfRange, "J_chat: lobe number must be >= 1 (got " + std::to_string(rho) + ")");
    for (std::size_t j = 0; j < freqsHz.size(); ++j) {
        if (!(freqsHz[j] > 0.0) || !std::isfinite(freqsHz[j]))
            return makeError(ErrorCode::OutOfRange, "J_chat: chatter frequency " + std::to_string(j + 1) +
                                                        " must be > 0 Hz (got " + str(freqsHz[j]) + ")");
        if (!(weights[j] >= 0.0) || !std::isfinite(weights[j]))
            return makeError(ErrorCode::OutOfRange, "J_chat: weight " + std::to_string(j + 1) + " must be >= 0");
        if (j > 0 && weights[j] > weights[j - 1])
            return makeError(ErrorCode::OutOfRange, "J_chat: weights must not increase (w_j >= w_j+1)");
    }
    double j = 0.0; // r_1 = ρ exactly: the first term is zero by definition (ρ f_1/f_1 could leave one ulp)
    for (std::size_t i = 1; i < freqsHz.size(); ++i) {
        const double r = rho * freqsHz[i] / freqsHz[0];
        const double d = r - std::floor(r + 0.5);
        j += weights[i] * d * d;
    }
    return j;
}

Result<MultiModeChoice> multiModeLobeSearch(const std::vector<double>& freqsHz, const std::vector<double>& weights,
                                            double rpm, int teeth, int searchBelow, int searchAbove)
{
    if (searchBelow < 0 || searchAbove < 0 || searchBelow > 100 || searchAbove > 100)
        return makeError(ErrorCode::OutOfRange, "J_chat search widths must be in [0, 100]");
    if (auto c = multiModeCost(1, freqsHz, weights); !c)
        return c.error();
    auto pocket = pocketAdvice(freqsHz[0], rpm, teeth);
    if (!pocket)
        return pocket.error();
    MultiModeChoice out;
    out.rhoNew = pocket->lobe;
    double best = 0.0;
    int bestRho = 0;
    for (int rho = std::max(1, out.rhoNew - searchBelow); rho <= out.rhoNew + searchAbove; ++rho) {
        const double j = multiModeCost(rho, freqsHz, weights).value();
        out.candidates.push_back({rho, j, 60.0 * freqsHz[0] / (rho * teeth)});
        const int d = rho - out.rhoNew, dBest = bestRho - out.rhoNew;
        if (bestRho == 0 || j < best || (j == best && d * d < dBest * dBest)) {
            best = j;
            bestRho = rho;
        }
    }
    out.rhoProp = bestRho;
    out.cost = best;
    out.rpm = 60.0 * freqsHz[0] / (bestRho * teeth);
    return out;
}

Result<EscDesign> escDesign(double pcRadS)
{
    if (!(pcRadS > 0.0) || !std::isfinite(pcRadS))
        return makeError(ErrorCode::OutOfRange, "ESC pole p_c must be > 0 rad/s (got " + str(pcRadS) + ")");
    return EscDesign{pcRadS / 3.0, 8.0 * pcRadS / 3.0, std::sqrt(3.0) * pcRadS};
}

// ---- DOB ----------------------------------------------------------------------------------------------

Result<StageDob> StageDob::create(const StageDobOptions& opt, double ts)
{
    if (!(ts > 0.0) || !std::isfinite(ts))
        return makeError(ErrorCode::OutOfRange, "DOB sample period must be > 0 s");
    if (!(opt.massKg > 0.0) || !std::isfinite(opt.massKg))
        return makeError(ErrorCode::OutOfRange, "DOB stage mass M_tn must be > 0 kg (got " + str(opt.massKg) + ")");
    if (!(opt.viscousNsPerM >= 0.0) || !std::isfinite(opt.viscousNsPerM))
        return makeError(ErrorCode::OutOfRange, "DOB stage viscosity D_tn must be >= 0 N s/m");
    StageDob d;
    d.m_opt = opt;
    d.m_ts = ts;
    auto q = butterworth2LowPass(opt.qCutoffHz, ts);
    if (!q)
        return makeError(q.error().code, "DOB Q cut-off: " + q.error().detail);
    auto sq = butterworth2Derivative(opt.qCutoffHz, ts);
    if (!sq)
        return makeError(sq.error().code, "DOB Q cut-off: " + sq.error().detail);
    d.m_qF = d.m_qV = *q;
    d.m_sqV = *sq;
    auto hp = butterworthHighPass(2, opt.bandLowHz, ts);
    if (!hp)
        return makeError(hp.error().code, "DOB G_F high-pass: " + hp.error().detail);
    d.m_gf = *hp;
    if (opt.bandHighHz > 0.0) {
        if (!(opt.bandHighHz > opt.bandLowHz))
            return makeError(ErrorCode::OutOfRange, "DOB G_F band: the upper corner must exceed the lower one");
        auto lp = butterworthLowPass(2, opt.bandHighHz, ts);
        if (!lp)
            return makeError(lp.error().code, "DOB G_F low-pass: " + lp.error().detail);
        for (const auto& b : lp->stages())
            d.m_gf.add(b);
    }
    return d;
}

void StageDob::reset()
{
    m_first = true;
    m_lastPos = 0.0;
    m_qF.reset();
    m_qV.reset();
    m_sqV.reset();
    m_gf.reset();
}

double StageDob::step(double positionM, double thrustN)
{
    // v_t by backward difference of the encoder; F̂ = G_F(Q F_t − M sQ v − D Q v)   (1-25)
    const double v = m_first ? 0.0 : (positionM - m_lastPos) / m_ts;
    m_first = false;
    m_lastPos = positionM;
    const double inner =
        m_qF.process(thrustN) - m_opt.massKg * m_sqV.process(v) - m_opt.viscousNsPerM * m_qV.process(v);
    return m_gf.process(inner);
}

// ---- adaptive avoidance ---------------------------------------------------------------------------------

Result<dsp::FilterCascade> bandPassSections(int sections, double f1, double f2, double ts)
{
    if (sections < 1 || sections > 8)
        return makeError(ErrorCode::OutOfRange,
                         "band-pass: sections must be in [1, 8] (got " + std::to_string(sections) + ")");
    if (!(ts > 0.0) || !std::isfinite(ts))
        return makeError(ErrorCode::OutOfRange, "band-pass: sample period must be > 0 s");
    if (!(f1 > 0.0) || !(f2 > f1) || !(f2 < 0.5 / ts) || !std::isfinite(f2))
        return makeError(ErrorCode::OutOfRange,
                         "band-pass: need 0 < " + str(f1) + " < " + str(f2) + " < Nyquist " + str(0.5 / ts) + " Hz");
    // H(s') = B s'/(s'² + B s' + W0²) with s' = (1 − z⁻¹)/(1 + z⁻¹), W1,2 = tan(π f1,2 t_s), B = W2 − W1,
    // W0² = W1 W2: the digital −3 dB edges are exactly f1 and f2.
    const double w1 = std::tan(std::numbers::pi * f1 * ts), w2 = std::tan(std::numbers::pi * f2 * ts);
    const double b = w2 - w1, w0 = w1 * w2;
    const double a0 = 1.0 + b + w0;
    dsp::FilterCascade c;
    for (int i = 0; i < sections; ++i)
        c.add(dsp::Biquad(b / a0, 0.0, -b / a0, 2.0 * (w0 - 1.0) / a0, (1.0 - b + w0) / a0));
    return c;
}

AdaptiveOptions adaptiveTable4Dob()
{
    return AdaptiveOptions{};
}

AdaptiveOptions adaptiveTable3Accelerometer()
{
    AdaptiveOptions o;
    o.samplePeriodS = 125e-6;
    o.kalman = {2, 1e-16, 0.3, 1e-4};
    o.thresholdPower = 121.0;
    o.highPassHz = 100.0;
    o.lowPassHz = 0.0;
    return o;
}

AdaptiveOptions multiModeTable5Accelerometer()
{
    AdaptiveOptions o;
    o.samplePeriodS = 200e-6;
    o.kalman = {4, 1e-16, 1.0, 1e-4};
    o.thresholdPower = 1e4;
    o.highPassHz = 100.0;
    o.lowPassHz = 0.0;
    o.multiMode = true;
    o.weights = {1.0, 0.5};
    return o;
}

Result<AdaptiveAvoidance> AdaptiveAvoidance::create(const AdaptiveOptions& o, int teeth)
{
    if (!(o.samplePeriodS > 0.0) || o.samplePeriodS > 0.01)
        return makeError(ErrorCode::OutOfRange,
                         "sample period t_s must be in (0, 0.01] s (got " + str(o.samplePeriodS) + ")");
    if (o.kalman.order < 2 || o.kalman.order % 2 != 0 || o.kalman.order > 20)
        return makeError(ErrorCode::OutOfRange,
                         "AR order N_d must be even, 2..20 (got " + std::to_string(o.kalman.order) + ")");
    if (!(o.kalman.rv >= 0.0) || !(o.kalman.rw > 0.0) || !(o.kalman.p0 > 0.0) || !std::isfinite(o.kalman.rv) ||
        !std::isfinite(o.kalman.rw) || !std::isfinite(o.kalman.p0))
        return makeError(ErrorCode::OutOfRange, "Kalman R_v must be >= 0, R_w and P[0] > 0");
    if (!(o.thresholdPower > 0.0) || !std::isfinite(o.thresholdPower))
        return makeError(ErrorCode::OutOfRange, "threshold sigma_th must be > 0");
    if (!(o.holdS > 0.0) || o.holdS > 100.0)
        return makeError(ErrorCode::OutOfRange, "hold time must be in (0, 100] s");
    if (o.maxSteps < 1 || o.maxSteps > 1000)
        return makeError(ErrorCode::OutOfRange, "step limit must be in [1, 1000]");
    if (teeth < 1 || teeth > 100)
        return makeError(ErrorCode::OutOfRange, "teeth must be in [1, 100]");
    if (o.multiMode) {
        if (o.weights.size() != static_cast<std::size_t>(o.kalman.order / 2))
            return makeError(ErrorCode::BadInput, "multi-mode: one weight per chatter frequency is needed (N_d/2 = " +
                                                      std::to_string(o.kalman.order / 2) + ", got " +
                                                      std::to_string(o.weights.size()) + ")");
        std::vector<double> ones(o.weights.size(), 1000.0);
        if (auto c = multiModeCost(1, ones, o.weights); !c)
            return c.error();
        if (o.searchBelow < 0 || o.searchAbove < 0 || o.searchBelow > 100 || o.searchAbove > 100)
            return makeError(ErrorCode::OutOfRange, "search widths must be in [0, 100]");
        if (!(o.costTarget >= 0.0))
            return makeError(ErrorCode::OutOfRange, "cost target must be >= 0");
    }
    AdaptiveAvoidance a;
    a.m_opt = o;
    a.m_teeth = teeth;
    const double nyq = 0.5 / o.samplePeriodS;
    if (o.highPassHz > 0.0) {
        auto hp = butterworthHighPass(4, o.highPassHz, o.samplePeriodS);
        if (!hp)
            return makeError(hp.error().code, "pre-filter high-pass: " + hp.error().detail);
        for (const auto& b : hp->stages())
            a.m_pre.add(b);
    }
    if (o.lowPassHz > 0.0 && o.lowPassHz < nyq) {
        auto lp = butterworthLowPass(4, o.lowPassHz, o.samplePeriodS);
        if (!lp)
            return makeError(lp.error().code, "pre-filter low-pass: " + lp.error().detail);
        for (const auto& b : lp->stages())
            a.m_pre.add(b);
    }
    if (o.modeBandCentreHz != 0.0 || o.modeBandWidthHz != 0.0) {
        if (!(o.modeBandCentreHz > 0.0) || !(o.modeBandWidthHz > 0.0) ||
            !(o.modeBandWidthHz < 2.0 * o.modeBandCentreHz))
            return makeError(ErrorCode::OutOfRange, "tool-mode band: need centre > 0 and 0 < width < 2 centre (got " +
                                                        str(o.modeBandCentreHz) + ", " + str(o.modeBandWidthHz) +
                                                        " Hz)");
        auto bp = bandPassSections(o.modeBandSections, o.modeBandCentreHz - 0.5 * o.modeBandWidthHz,
                                   o.modeBandCentreHz + 0.5 * o.modeBandWidthHz, o.samplePeriodS);
        if (!bp)
            return makeError(bp.error().code, "tool-mode " + bp.error().detail);
        for (const auto& s : bp->stages())
            a.m_pre.add(s);
    }
    a.m_kf = ChatterFrequencyEstimator(o.kalman, o.samplePeriodS);
    return a;
}

double AdaptiveAvoidance::step(double timeS, double signal, double rpmActual)
{
    if (m_cmd == 0.0)
        m_cmd = rpmActual;
    m_au = m_pre.process(std::isfinite(signal) ? signal : 0.0);
    m_kf.step(m_au);
    const auto f = m_kf.frequenciesHz();
    m_fChat = f.empty() ? 0.0 : f[0];
    m_fChat2 = f.size() > 1 ? f[1] : 0.0;
    const double p = m_au * m_au;
    if (!triggered()) {
        if (p > m_opt.thresholdPower) {
            m_triggerTimeS = timeS;
            adapt(timeS, rpmActual);
        }
        return m_cmd;
    }
    if (timeS - m_lastStepS >= 0.5 * m_opt.holdS)
        m_windowMax = std::max(m_windowMax, p);
    if (timeS - m_lastStepS >= m_opt.holdS) {
        if (m_windowMax > m_opt.thresholdPower && static_cast<int>(m_steps.size()) < m_opt.maxSteps)
            adapt(timeS, rpmActual);
        else
            m_lastStepS = timeS; // next window
        m_windowMax = 0.0;
    }
    return m_cmd;
}

void AdaptiveAvoidance::adapt(double timeS, double rpmActual)
{
    m_lastStepS = timeS;
    auto f = m_kf.frequenciesHz();
    if (f.empty())
        return;
    AvoidanceStep s;
    s.timeS = timeS;
    s.fromRpm = rpmActual;
    if (m_opt.multiMode) {
        f.resize(m_opt.weights.size());
        auto c = multiModeLobeSearch(f, m_opt.weights, rpmActual, m_teeth, m_opt.searchBelow, m_opt.searchAbove);
        if (!c)
            return; // no usable estimate yet (e.g. a real pole): try again after the hold
        s.rhoNew = c->rhoNew;
        s.rho = c->rhoProp;
        s.cost = c->cost;
        s.costMet = c->cost <= m_opt.costTarget;
        s.toRpm = c->rpm;
    } else {
        auto p = pocketAdvice(f[0], rpmActual, m_teeth);
        if (!p)
            return;
        s.rhoNew = s.rho = p->lobe;
        s.toRpm = p->rpm;
        s.costMet = true;
    }
    s.chatterHz = f;
    m_cost = s.cost;
    m_cmd = s.toRpm;
    m_steps.push_back(std::move(s));
}

// ---- ESC --------------------------------------------------------------------------------------------------

Result<EscController> EscController::create(const EscOptions& o, double initialRpm)
{
    auto d = escDesign(o.pcRadS);
    if (!d)
        return d.error();
    if (!(o.samplePeriodS > 0.0) || o.samplePeriodS > 0.01)
        return makeError(ErrorCode::OutOfRange, "ESC sample period must be in (0, 0.01] s");
    if (!(o.ditherRadS > 0.0) || !std::isfinite(o.ditherRadS))
        return makeError(ErrorCode::OutOfRange, "ESC dither a_c must be > 0 rad/s (got " + str(o.ditherRadS) + ")");
    if (!(o.curvature > 0.0) || !std::isfinite(o.curvature))
        return makeError(ErrorCode::OutOfRange, "ESC curvature f'' must be > 0 (got " + str(o.curvature) + ")");
    if (!(o.startS >= 0.0) || !std::isfinite(o.startS))
        return makeError(ErrorCode::OutOfRange, "ESC start time must be >= 0 s");
    if (!(o.minRpm > 0.0) || !(o.maxRpm > o.minRpm) || !std::isfinite(o.maxRpm))
        return makeError(ErrorCode::OutOfRange,
                         "ESC speed bounds: need 0 < min < max rpm (got " + str(o.minRpm) + ", " + str(o.maxRpm) + ")");
    const double ac = o.ditherRadS / model::kRadPerSPerRpm; // dither in rpm
    if (o.minRpm + ac > initialRpm || o.maxRpm - ac < initialRpm)
        return makeError(ErrorCode::OutOfRange, "ESC: the initial speed ± the dither must lie inside the speed bounds");
    if (d->omegaPRadS >= std::numbers::pi / o.samplePeriodS)
        return makeError(ErrorCode::OutOfRange,
                         "ESC dither frequency sqrt(3) p_c is at or above the Nyquist frequency");
    EscController c;
    c.m_opt = o;
    c.m_design = *d;
    c.m_w0 = initialRpm * model::kRadPerSPerRpm;
    c.m_kInt = 2.0 * d->kcPerS / (o.ditherRadS * o.curvature);
    c.m_cmd = initialRpm;
    const double k = 2.0 / o.samplePeriodS;
    c.m_hpA = k / (k + d->hcRadS); // Tustin s/(s + h_c): y = A (x − x₋) + B y₋
    c.m_hpB = (k - d->hcRadS) / (k + d->hcRadS);
    return c;
}

double EscController::meanRpm() const
{
    return (m_w0 + m_theta) / model::kRadPerSPerRpm;
}

double EscController::step(double timeS, double y)
{
    if (timeS < m_opt.startS || !std::isfinite(y)) {
        m_prevY = std::isfinite(y) ? y : m_prevY;
        return m_cmd;
    }
    if (!m_started) {
        m_started = true;
        m_prevY = y;
        m_prevHp = 0.0;
    }
    const double tRel = timeS - m_opt.startS;
    const double s = std::sin(m_design.omegaPRadS * tRel);
    m_hp = m_hpA * (y - m_prevY) + m_hpB * m_prevHp;
    m_prevY = y;
    m_prevHp = m_hp;
    // ξ = sin(ω_p t) · HPF[y]; θ̂' = −k_int ξ   (6-8), (6-9)
    double theta = m_theta - m_kInt * s * m_hp * m_opt.samplePeriodS;
    const double lo = m_opt.minRpm * model::kRadPerSPerRpm + m_opt.ditherRadS - m_w0;
    const double hi = m_opt.maxRpm * model::kRadPerSPerRpm - m_opt.ditherRadS - m_w0;
    if (theta < lo || theta > hi) {
        ++m_boundHits;
        theta = std::clamp(theta, lo, hi); // the designed speed bound (anti-windup), counted
    }
    m_theta = theta;
    m_cmd = (m_w0 + m_theta + m_opt.ditherRadS * s) / model::kRadPerSPerRpm;
    return m_cmd;
}

} // namespace axistune::machining

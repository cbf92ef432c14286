// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// In-process chatter avoidance by spindle-speed control (spec/chatter-stability-and-spindle-speed.md §3.0–§3.4):
//  - the multi-resonance lobe cost J_chat(ρ) and its search (§3.3, eqs. (5-3)–(5-6));
//  - the extremum-seeking design (6-24) from the pole p_c;
//  - the feed-stage disturbance observer F̂_x = G_F(Q F_t − Q(M_tn s + D_tn) v_t) (§3.0.3, eq. (1-25));
//  - the adaptive avoider (Methods 2 and 3): Kalman chatter-frequency estimate on a pre-filtered signal, trigger
//    on a_u² (or F̂_u²) > σ_th, jump to the stable-pocket speed (1-21)/(1-22) or to the lobe of least J_chat,
//    repeated after a hold time while the vibration stays above the threshold, up to a step limit;
//  - the extremum-seeking controller (Method 4): dither a_c sin(ω_p t), high-pass s/(s + h_c), demodulation,
//    integrator, speed bounds.
// All controllers are sample-by-sample at their own period t_s and never allocate in step().

#include "core/dsp/DigitalFilter.h"
#include "core/machining/ChatterFrequencyEstimator.h"
#include "core/model/Result.h"

#include <cstdint>
#include <vector>

namespace axistune::machining {

// ---- §3.3 multi-resonance cost --------------------------------------------------------------------------

/// J_chat(ρ) = Σ_j w_j (r_j − round(r_j))², r_j = ρ f_j / f_1 (eqs. (5-3), (5-4)); f_1 is the dominant
/// chatter frequency (freqsHz[0]). J ≡ 0 for one frequency. Errors: sizes differ, empty, f ≤ 0, w < 0,
/// weights not non-increasing, ρ < 1.
Result<double> multiModeCost(int rho, const std::vector<double>& freqsHz, const std::vector<double>& weights);

struct LobeCandidateCost {
    int rho = 0;
    double cost = 0.0;
    double rpm = 0.0; ///< 60 f_1/(ρ N_t), eq. (5-5)
};

struct MultiModeChoice {
    int rhoNew = 0; ///< round half up of f_1/f_TPE (1-21)
    int rhoProp = 0; ///< argmin J over [ρ_new − n_below, ρ_new + n_above] ∩ ℕ, tie → least (ρ − ρ_new)² (5-6)
    double cost = 0.0;
    double rpm = 0.0;
    std::vector<LobeCandidateCost> candidates;
};

/// The search of eq. (5-6) at the actual speed rpm with N_t teeth. Errors as multiModeCost, plus rpm ≤ 0,
/// teeth < 1, widths < 0, f_1 below half the tooth-passing frequency (no lobe number).
Result<MultiModeChoice> multiModeLobeSearch(const std::vector<double>& freqsHz, const std::vector<double>& weights,
                                            double rpm, int teeth, int searchBelow, int searchAbove);

// ---- §3.4 ESC design -------------------------------------------------------------------------------------

struct EscDesign {
    double hcRadS = 0.0;     ///< high-pass corner h_c = p_c/3
    double kcPerS = 0.0;     ///< averaged loop gain k_c = 8 p_c/3
    double omegaPRadS = 0.0; ///< dither frequency ω_p = √3 p_c
};
/// Eq. (6-24): triple pole of (6-22) at −p_c. Errors: p_c not finite or ≤ 0.
Result<EscDesign> escDesign(double pcRadS);

// ---- §3.0.3 feed-stage disturbance observer ---------------------------------------------------------------

struct StageDobOptions {
    double massKg = 273.0;      ///< M_tn (Table 1(b))
    double viscousNsPerM = 1e4; ///< D_tn (Table 1(b))
    double qCutoffHz = 2000.0;  ///< DOB low-pass Q (Ch.4: 2000 Hz)
    double bandLowHz = 1000.0;  ///< G_F high-pass corner (2nd order)
    double bandHighHz = 2000.0; ///< G_F low-pass corner (2nd order); 0 = high-pass only (Ch.6)
};

/// Runs at the encoder/current sample period t_s. Input: linear-encoder position [m] and the thrust command
/// F_t [N] (torque command / lead per radian). Output F̂ [N] (the force on the table, sign of F_t).
class StageDob {
public:
    StageDob() = default;
    /// Errors: mass ≤ 0, viscous < 0, a corner ≥ Nyquist or ≤ 0, band high ≤ band low.
    static Result<StageDob> create(const StageDobOptions& opt, double samplePeriodS);
    double step(double positionM, double thrustN);
    void reset();

private:
    StageDobOptions m_opt;
    double m_ts = 0.0, m_lastPos = 0.0;
    bool m_first = true;
    dsp::Biquad m_qF, m_sqV, m_qV;
    dsp::FilterCascade m_gf;
};

// ---- Methods 2/3: adaptive avoidance ---------------------------------------------------------------------

enum class AvoidanceSensor { Accelerometer, Dob };

struct AdaptiveOptions {
    double samplePeriodS = 250e-6;             ///< t_s (Table 4(a))
    KalmanAROptions kalman{2, 1e-6, 0.3, 1e3}; ///< N_d, R_v, R_w, P[0] (Table 4(a))
    double thresholdPower = 1e4;               ///< σ_th on the filtered signal squared (Table 4(a): 10000 N²)
    double highPassHz = 1000.0;                ///< pre-filter: high-pass corner (4th order); Ch.4 BPF 1000–2000 Hz
    double lowPassHz = 2000.0;                 ///< pre-filter: low-pass corner (4th order); 0 or ≥ Nyquist: none
    /// Tool-mode band (not in Table 4; docs/chatter-avoidance.md "DOB path"): after the pre-filter, a band-pass
    /// of `modeBandSections` identical 2nd-order sections with −3 dB edges (per section) at centre ± width/2.
    /// Centre = the tool's mode f_n, width = the tooth-passing frequency, so that of the comb f_c + k f_TPE that
    /// the force carries, one line reaches the N_d = 2 estimator. 0 = off.
    double modeBandCentreHz = 0.0;
    double modeBandWidthHz = 0.0;
    int modeBandSections = 3;
    double holdS = 0.1;     ///< time between adaptation steps (the speed settles, the estimate re-tracks)
    int maxSteps = 5;       ///< step limit
    bool multiMode = false; ///< Method 3: J_chat search instead of the nearest pocket
    std::vector<double> weights{1.0, 0.5}; ///< w_j (non-increasing), one per N_d/2
    int searchBelow = 1, searchAbove = 1;  ///< n̲, n̄ (the thesis uses 1, 1)
    double costTarget = 0.01;              ///< J_chat accepted ("cost met") at or below this
};

/// `sections` identical 2nd-order band-pass sections (bilinear, edges pre-warped), each with unit gain at the
/// centre √(f1 f2) and −3 dB at f1 and f2. Errors: sections < 1 or > 8, not 0 < f1 < f2 < Nyquist.
Result<dsp::FilterCascade> bandPassSections(int sections, double f1Hz, double f2Hz, double periodS);

/// Table 4 (DOB, Ch.4) defaults for Method 2; Table 3 (accelerometer, Ch.3) with a 100 Hz high-pass; Table 5
/// (accelerometer, two modes, Ch.5) for Method 3.
AdaptiveOptions adaptiveTable4Dob();
AdaptiveOptions adaptiveTable3Accelerometer();
AdaptiveOptions multiModeTable5Accelerometer();

struct AvoidanceStep {
    double timeS = 0.0;
    double fromRpm = 0.0, toRpm = 0.0;
    std::vector<double> chatterHz;
    int rhoNew = 0, rho = 0;
    double cost = 0.0;
    bool costMet = false;
};

class AdaptiveAvoidance {
public:
    AdaptiveAvoidance() = default;
    /// Errors name the option: t_s, N_d (even, 2..20, = 2·weights for multi-mode), σ_th, filter corners, hold,
    /// step limit, weights, search widths.
    static Result<AdaptiveAvoidance> create(const AdaptiveOptions& opt, int teeth);
    /// One sample of the sensor signal at time t with the actual spindle speed; returns the speed command [rpm].
    double step(double timeS, double signal, double rpmActual);
    double filtered() const { return m_au; }
    double chatterHz() const { return m_fChat; } ///< dominant estimate (0 before the first estimate)
    double secondChatterHz() const { return m_fChat2; }
    double cost() const { return m_cost; }
    bool triggered() const { return m_triggerTimeS >= 0.0; }
    double triggerTimeS() const { return m_triggerTimeS; }
    const std::vector<AvoidanceStep>& steps() const { return m_steps; }
    double commandRpm() const { return m_cmd; }

private:
    void adapt(double timeS, double rpmActual);
    AdaptiveOptions m_opt;
    int m_teeth = 0;
    dsp::FilterCascade m_pre;
    ChatterFrequencyEstimator m_kf{KalmanAROptions{}, 1e-3};
    double m_au = 0.0, m_fChat = 0.0, m_fChat2 = 0.0, m_cost = 0.0, m_cmd = 0.0;
    double m_triggerTimeS = -1.0, m_lastStepS = 0.0, m_windowMax = 0.0;
    std::vector<AvoidanceStep> m_steps;
};

// ---- Method 4: extremum-seeking control ------------------------------------------------------------------

struct EscOptions {
    double samplePeriodS = 200e-6;                      ///< t_s (Table 6)
    double pcRadS = 8.0 * 2.0 * 3.14159265358979323846; ///< p_c (Table 6)
    double ditherRadS = 1.0;                            ///< a_c [rad/s of spindle speed] (Fig. 42: 1 and 4)
    double curvature = 1e5;                             ///< assumed f''(θ*) (simulation value, §5.4)
    double startS = 5.0;                                ///< t_prop (Table 6)
    double minRpm = 0.0, maxRpm = 0.0;                  ///< bounds of the speed command (both required, min < max)
};

class EscController {
public:
    EscController() = default;
    /// Errors: t_s, p_c, a_c, f'' ≤ 0 or not finite; bounds not min < max; dither wider than the bounds;
    /// ω_p at or above Nyquist.
    static Result<EscController> create(const EscOptions& opt, double initialRpm);
    /// One sample of the cost y (a_y² or F̂_x²) at time t; returns the speed command [rpm].
    double step(double timeS, double cost);
    const EscDesign& design() const { return m_design; }
    double integratorGain() const { return m_kInt; } ///< k_int = 2 k_c/(a_c f'') so that the averaged gain is k_c
    double meanRpm() const;                          ///< ω₀ + θ̂ in rpm (without the dither)
    double commandRpm() const { return m_cmd; }
    double filteredCost() const { return m_hp; }
    std::uint64_t boundHits() const { return m_boundHits; } ///< samples the integrator was held at a bound

private:
    EscOptions m_opt;
    EscDesign m_design;
    double m_w0 = 0.0, m_theta = 0.0, m_kInt = 0.0, m_cmd = 0.0, m_hp = 0.0;
    double m_hpA = 0.0, m_hpB = 0.0, m_prevY = 0.0, m_prevHp = 0.0;
    bool m_started = false;
    std::uint64_t m_boundHits = 0;
};

} // namespace axistune::machining

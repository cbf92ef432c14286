// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// AxisTune's LinuxCNC test machine for the tests (scripts/hal-testbed, docs/linuxcnc.md): the fixture that starts a
// HAL session under the machine-wide lock, and halcmd helpers.

#include "core/device/hal/HalCmd.h"
#include "core/device/hal/HalText.h"
#include "core/dsp/FrequencyResponse.h"
#include "core/model/Number.h"

#include <Eigen/Dense>
#include <chrono>
#include <cmath>
#include <complex>
#include <gtest/gtest.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/linuxcnc/HalMachineLock.h"

namespace axistune::testing {

using device::hal::HalSessionOptions;
using device::hal::parseSignals;
using device::hal::runHalcmd;

inline const std::string kScript = std::string(AXISTUNE_SOURCE_DIR) + "/scripts/hal-testbed";

inline HalSessionOptions halOptions()
{
    HalSessionOptions o;
    o.halcmd = {kScript, "halcmd"};
    o.timeout = std::chrono::seconds(30);
    return o;
}

inline Status runScript(const std::vector<std::string>& args)
{
    HalSessionOptions o;
    o.halcmd = {kScript};
    o.timeout = std::chrono::seconds(180);
    auto r = runHalcmd(o, args);
    if (!r)
        return r.error();
    return {};
}

/// `halcmd -s show sig` without the live values: names, types, writers and readers.
inline std::string netsOf(const std::string& showSig)
{
    auto sigs = parseSignals(showSig);
    EXPECT_TRUE(sigs) << (sigs ? "" : sigs.error().detail);
    std::string out;
    if (sigs)
        for (const auto& s : *sigs) {
            out += s.type + " " + s.name + " <== " + s.writer + " ==>";
            for (const auto& r : s.readers)
                out += " " + r;
            out += "\n";
        }
    return out;
}

inline std::string halText(const std::vector<std::string>& args)
{
    auto r = runHalcmd(halOptions(), args);
    EXPECT_TRUE(r) << (r ? "" : r.error().detail);
    return r ? *r : std::string{};
}

inline double getp(const std::string& name)
{
    const std::string t = halText({"getp", name});
    const auto v = model::parseNumber(t.substr(0, t.find_first_of(" \n")));
    EXPECT_TRUE(v.has_value()) << name << ": '" << t << "'";
    return v.value_or(std::nan(""));
}

class HalTestbed : public ::testing::Test {
protected:
    /// Starts the test machine (its torque-mode INI, or `ini`) with the servo period `periodNs`.
    void startBed(long periodNs, const std::string& ini = {})
    {
        if (!m_lock)
            m_lock = std::make_unique<axistune::testing::HalMachineLock>();
        ASSERT_TRUE(m_lock->held()) << "cannot open /tmp/axistune-hal-machine.lock";
        std::vector<std::string> args{"start", "--period", std::to_string(periodNs)};
        if (!ini.empty())
            args.insert(args.end(), {"--ini", ini});
        auto st = runScript(args);
        ASSERT_TRUE(st) << st.error().detail;
        m_started = true;
    }
    void TearDown() override
    {
        if (m_started)
            (void)runScript({"stop"});
        m_lock.reset();
    }
    bool m_started = false;
    std::unique_ptr<axistune::testing::HalMachineLock> m_lock; ///< held from the start to after the stop
};

/// The lines that differ between two texts of the same number of lines, as (before, after); a text with more lines
/// than the other adds ("", line) or (line, "") pairs.
inline std::vector<std::pair<std::string, std::string>> changedLines(const std::string& before,
                                                                     const std::string& after)
{
    std::istringstream a(before), b(after);
    std::vector<std::pair<std::string, std::string>> changed;
    std::string la, lb;
    for (;;) {
        const bool ha = static_cast<bool>(std::getline(a, la)), hb = static_cast<bool>(std::getline(b, lb));
        if (!ha && !hb)
            return changed;
        if (!ha || !hb || la != lb)
            changed.emplace_back(ha ? la : "", hb ? lb : "");
    }
}

/// The plant's exact discrete-time response from drive input to recorded feedback, from the component's own
/// update equations (linuxcnc/axistune_plant.comp, friction and quantization off): per substep h
///   ω_m ← ω_m + h (u − k(θ_m−θ_l) − c(ω_m−ω_l) − b_m ω_m)/J_m,  ω_l ← ω_l + h (k(θ_m−θ_l) + c(ω_m−ω_l) − b_l ω_l)/J_l,
///   θ_m ← θ_m + h ω_m,  θ_l ← θ_l + h ω_l   (the new velocities, from the old state)
/// so one servo period is x ← A x + B u with A = A₁ⁿ, B = Σ A₁ⁱ B₁. The sampler runs after the plant in the same
/// period, so it records y[k] = C x[k+1] with u[k]: H(z) = z C (zI − A)⁻¹ B.
struct Plant {
    double jm, jl, k, c, bm, bl, lead;
    int substeps;
    double kv = 0.0; ///< velocity-mode drive gain; then u is velocity_cmd [mm/s] and the torque kv(u·2π/lead − ωm)
};

inline Plant readPlant()
{
    return {getp("plant.x.jm"), getp("plant.x.jl"), getp("plant.x.k"),    getp("plant.x.c"),
            getp("plant.x.bm"), getp("plant.x.bl"), getp("plant.x.lead"), static_cast<int>(getp("plant.x.substeps")),
            getp("plant.x.kv")};
}

/// One servo period of the plant, x ← A x + B u, position y = C x (C picks the motor angle times lead/2π).
struct PlantStateSpace {
    Eigen::Matrix4d A;
    Eigen::Vector4d B;
    Eigen::RowVector4d C;
};

inline PlantStateSpace plantStateSpace(const Plant& p, double periodS)
{
    const double h = periodS / p.substeps;
    Eigen::Matrix4d V = Eigen::Matrix4d::Identity(); // velocity update, state (θm, ωm, θl, ωl)
    V.row(1) += h * Eigen::RowVector4d(-p.k / p.jm, -(p.c + p.bm + p.kv) / p.jm, p.k / p.jm, p.c / p.jm);
    V.row(3) += h * Eigen::RowVector4d(p.k / p.jl, p.c / p.jl, -p.k / p.jl, -(p.c + p.bl) / p.jl);
    Eigen::Matrix4d P = Eigen::Matrix4d::Identity(); // position update with the new velocities
    P(0, 1) = h;
    P(2, 3) = h;
    const Eigen::Matrix4d A1 = P * V;
    // The drive input's gain into the motor's acceleration: 1/Jm for a torque; kv·(2π/lead)/Jm for a velocity command.
    const double inputGain = p.kv > 0.0 ? p.kv * 2.0 * M_PI / p.lead : 1.0;
    const Eigen::Vector4d B1 = P * Eigen::Vector4d(0.0, h * inputGain / p.jm, 0.0, 0.0);
    PlantStateSpace s{Eigen::Matrix4d::Identity(), Eigen::Vector4d::Zero(),
                      Eigen::RowVector4d(p.lead / (2.0 * M_PI), 0.0, 0.0, 0.0)};
    for (int i = 0; i < p.substeps; ++i) {
        s.B += s.A * B1;
        s.A = A1 * s.A;
    }
    return s;
}

inline std::complex<double> exactResponse(const Plant& p, double periodS, double fHz)
{
    const PlantStateSpace s = plantStateSpace(p, periodS);
    const std::complex<double> z = std::polar(1.0, 2.0 * M_PI * fHz * periodS);
    const Eigen::Matrix4cd M = z * Eigen::Matrix4cd::Identity() - s.A.cast<std::complex<double>>();
    const Eigen::Vector4cd x = M.partialPivLu().solve(s.B.cast<std::complex<double>>());
    return z * (s.C.cast<std::complex<double>>() * x)(0);
}

/// The plant's resonance at the servo period `periodS`: the peak of the exact response's |H|·ω² on a 0.01 Hz grid,
/// 30 to 200 Hz.
inline double exactResonanceHz(const Plant& p, double periodS)
{
    double fr = 0.0, hi = -1.0;
    for (double f = 30.0; f <= 200.0; f += 0.01) {
        const double v = std::abs(exactResponse(p, periodS, f)) * std::pow(2.0 * M_PI * f, 2);
        if (v > hi)
            hi = v, fr = f;
    }
    return fr;
}

/// The largest departure of a measured plant FRF (every line valid) from the plant's exact response at the servo
/// period `periodS`: |20 log10 |ratio|| [dB] and |arg ratio| [deg]. An invalid line fails the calling test.
struct ExactDeparture {
    double dB = 0.0, deg = 0.0;
};
inline ExactDeparture departureFromExact(const dsp::FrequencyResponse& frf, const Plant& plant, double periodS)
{
    ExactDeparture w;
    for (std::size_t i = 0; i < frf.size(); ++i) {
        EXPECT_TRUE(frf.valid[i]) << frf.freqHz[i] << " Hz";
        const std::complex<double> ratio = frf.h[i] / exactResponse(plant, periodS, frf.freqHz[i]);
        w.dB = std::max(w.dB, std::abs(20.0 * std::log10(std::abs(ratio))));
        w.deg = std::max(w.deg, std::abs(std::arg(ratio)) * 180.0 / M_PI);
    }
    return w;
}

/// pid-tune's result after --apply: the measured margins meet issue 17's (PM ≥ 45°, GM ≥ 6 dB) and lie within
/// 3° / 1 dB of the prediction.
inline void expectVerifiedMargins(const nlohmann::json& result)
{
    const auto& predicted = result.at("proposed").at("predicted");
    const auto& measured = result.at("verified").at("measured");
    EXPECT_GE(measured.at("phase_margin_deg").get<double>(), 45.0);
    EXPECT_GE(measured.at("gain_margin_dB").get<double>(), 6.0);
    EXPECT_NEAR(measured.at("phase_margin_deg").get<double>(), predicted.at("phase_margin_deg").get<double>(), 3.0);
    EXPECT_NEAR(measured.at("gain_margin_dB").get<double>(), predicted.at("gain_margin_dB").get<double>(), 1.0);
}

} // namespace axistune::testing

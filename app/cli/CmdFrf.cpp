// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli frf: frequency response from a capture (Welch H1/H2 + coherence) or from a
// sine-stream recording (conventional or three-phase multi-sweep demodulation); docs/frequency-response.md.
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/dsp/InjectionHold.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/dsp/SineDemodulation.h"
#include "core/dsp/Welch.h"
#include "core/io/CaptureCsv.h"
#include "core/io/FrfCsv.h"
#include "core/io/SweepCsv.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>

namespace axistune::cli {

namespace {

struct FrfOptions {
    std::string inPath;
    std::string sweepPath;
    std::string inputCol;
    std::string outputCol;
    std::string timeCol;
    double fsHz = 0.0;
    std::size_t nperseg = 1024;
    std::optional<std::size_t> noverlap;
    std::string estimator = "h1";
    std::string window = "hann";
    std::string outPath;
    std::string margins;  // "", open, complementary, neg-complementary, sensitivity
};

// fs from --fs, the fs_Hz metadata or a uniform time column (checked to 1e-6 of the step).
Result<double> samplingFrequency(const model::Capture& cap, const FrfOptions& o)
{
    const std::string src = o.inPath;
    const std::string timeName = o.timeCol.empty() ? "t_s" : o.timeCol;
    const model::Channel* t = cap.channel(timeName);
    if (!o.timeCol.empty() && t == nullptr)
        return makeError(ErrorCode::NotFound, src + ": no time column '" + o.timeCol + "'");
    std::optional<double> fromTime;
    if (t != nullptr && t->data.size() >= 2) {
        const auto& d = t->data;
        const double dt = (d.back() - d.front()) / static_cast<double>(d.size() - 1);
        if (!(dt > 0.0))
            return makeError(ErrorCode::BadInput, src + ", column '" + timeName + "': time does not increase");
        const double step0 = d[1] - d[0];
        for (std::size_t i = 1; i < d.size(); ++i) {
            const double step = d[i] - d[i - 1];
            if (std::abs(step - step0) > 1e-6 * std::abs(step0) + 1e-12 * std::abs(d[i])) {
                return makeError(ErrorCode::BadInput, src + ", column '" + timeName
                                                          + "': not uniformly sampled: the step between data rows "
                                                          + std::to_string(i) + " and " + std::to_string(i + 1) + " is "
                                                          + io::detail::formatDouble(step) + " s, the first step is "
                                                          + io::detail::formatDouble(step0) + " s");
            }
        }
        fromTime = 1.0 / dt;
    }
    if (o.fsHz > 0.0)
        return o.fsHz;
    if (auto it = cap.metadata.find("fs_Hz"); it != cap.metadata.end()) {
        double fs = 0.0;
        if (!io::detail::parseDouble(it->second, fs) || !(fs > 0.0) || !std::isfinite(fs))
            return makeError(ErrorCode::BadInput, src + ": metadata fs_Hz is not a positive number ('" + it->second + "')");
        if (fromTime && std::abs(*fromTime - fs) > 1e-6 * fs) {
            return makeError(ErrorCode::BadInput, src + ": metadata fs_Hz=" + it->second + " disagrees with column '"
                                                      + timeName + "' (" + std::to_string(*fromTime) + " Hz)");
        }
        return fs;
    }
    if (fromTime)
        return *fromTime;
    return makeError(ErrorCode::BadInput, src + ": no sampling frequency: give --fs, a '# fs_Hz=' line or a time column 't_s'");
}

Result<dsp::FrequencyResponse> frfFromCapture(const FrfOptions& o)
{
    if (o.inputCol.empty() || o.outputCol.empty())
        return makeError(ErrorCode::BadInput, "--in needs --input COL and --output COL");
    auto cap = io::readCaptureCsvFile(o.inPath);
    if (!cap)
        return cap.error();
    const auto* x = cap->channel(o.inputCol);
    const auto* y = cap->channel(o.outputCol);
    for (const auto& [name, ch] : {std::pair{o.inputCol, x}, std::pair{o.outputCol, y}}) {
        if (ch == nullptr)
            return makeError(ErrorCode::NotFound, o.inPath + ": no column '" + name + "'");
    }
    auto fs = samplingFrequency(cap.value(), o);
    if (!fs)
        return fs.error();
    dsp::WelchOptions w;
    w.nperseg = o.nperseg;
    w.noverlap = o.noverlap;
    w.window = o.window == "boxcar" ? dsp::WelchWindow::Rectangular : dsp::WelchWindow::Hann;
    const auto est = o.estimator == "h2" ? dsp::FrfEstimator::H2 : dsp::FrfEstimator::H1;
    auto frf = dsp::welchFrf(x->data, y->data, *fs, w, est);
    if (!frf)
        return makeError(frf.error().code, o.inPath + ": " + frf.error().detail);
    auto& md = frf.value().metadata;
    md["input"] = o.inputCol;
    md["output"] = o.outputCol;
    md["fs_Hz"] = io::detail::formatDouble(*fs);
    md["window"] = o.window;
    return frf;
}

nlohmann::json frfJson(const dsp::FrequencyResponse& f)
{
    nlohmann::json j;
    j["metadata"] = f.metadata;
    auto col = [&](auto get) {
        nlohmann::json a = nlohmann::json::array();
        for (std::size_t i = 0; i < f.size(); ++i) {
            const double v = get(i);
            a.push_back(std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr));
        }
        return a;
    };
    j["f_Hz"] = col([&](std::size_t i) { return f.freqHz[i]; });
    j["re"] = col([&](std::size_t i) { return f.h[i].real(); });
    j["im"] = col([&](std::size_t i) { return f.h[i].imag(); });
    j["mag_dB"] = col([&](std::size_t i) { return dsp::magnitudeDb(f.h[i]); });
    j["phase_deg"] = col([&](std::size_t i) { return dsp::phaseDeg(f.h[i]); });
    j["coherence"] = col([&](std::size_t i) { return f.coherence[i]; });
    j["valid"] = nlohmann::json::array();
    for (bool v : f.valid)
        j["valid"].push_back(v ? 1 : 0);
    return j;
}

nlohmann::json marginsJson(const dsp::FrequencyResponse& frf, const std::string& kind)
{
    const dsp::FrequencyResponse open = kind == "open" ? frf
                                        : dsp::openLoopFromClosedLoop(frf, kind == "complementary" ? dsp::LoopMeasurement::Complementary
                                                                           : kind == "sensitivity" ? dsp::LoopMeasurement::Sensitivity
                                                                                                   : dsp::LoopMeasurement::NegComplementary);
    const auto m = dsp::loopMargins(open);
    auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
    nlohmann::json j{{"measurement", kind},
                     {"phase_margin_deg", num(m.phaseMarginDeg)},
                     {"phase_margin_freq_Hz", m.gainCrossovers.empty() ? nlohmann::json(nullptr) : num(m.phaseMarginFreqHz)},
                     {"gain_margin_dB", num(m.gainMarginDb)},
                     {"gain_margin_freq_Hz", m.phaseCrossovers.empty() ? nlohmann::json(nullptr) : num(m.gainMarginFreqHz)},
                     {"peak_sensitivity", num(m.peakSensitivity)},
                     {"peak_sensitivity_dB", num(m.peakSensitivityDb)},
                     {"peak_sensitivity_freq_Hz", num(m.peakSensitivityFreqHz)}};
    j["gain_crossovers_Hz"] = nlohmann::json::array();
    for (const auto& c : m.gainCrossovers)
        j["gain_crossovers_Hz"].push_back(c.freqHz);
    j["phase_crossovers_Hz"] = nlohmann::json::array();
    for (const auto& c : m.phaseCrossovers)
        j["phase_crossovers_Hz"].push_back(c.freqHz);
    return j;
}

int runFrf(const FrfOptions& o)
{
    const std::string cmd = "frf";
    if (o.inPath.empty() == o.sweepPath.empty())
        return reportError(cmd, makeError(ErrorCode::BadInput, "give exactly one of --in capture.csv or --sweep sweep.csv"));
    Result<dsp::FrequencyResponse> frf = makeError(ErrorCode::Internal, "");
    if (!o.sweepPath.empty()) {
        auto rec = io::readSweepCsvFile(o.sweepPath);
        if (!rec)
            return reportError(cmd, rec.error());
        frf = dsp::sineStreamFrf(rec.value());
        if (!frf)
            return reportError(cmd, makeError(frf.error().code, o.sweepPath + ": " + frf.error().detail));
        // A drive's sweep (capture --sweep-out) names its injection hold: the same correction as the drive's FRF.
        const auto& md = rec->metadata;
        if (md.count("injection_hold_period_s") && md.count("injection_hold_ticks")) {
            char* e1 = nullptr;
            char* e2 = nullptr;
            const double h = std::strtod(md.at("injection_hold_period_s").c_str(), &e1);
            const long n = std::strtol(md.at("injection_hold_ticks").c_str(), &e2, 10);
            Status st = (*e1 || *e2) ? Status(makeError(ErrorCode::BadInput, "not a number"))
                                     : dsp::correctInjectionHold(frf.value(), h, static_cast<int>(n));
            if (!st)
                return reportError(cmd, makeError(ErrorCode::BadInput, o.sweepPath + ": metadata injection_hold_period_s / "
                                                                       "injection_hold_ticks: " + st.error().detail));
        }
    } else {
        frf = frfFromCapture(o);
        if (!frf)
            return reportError(cmd, frf.error());
    }
    if (o.outPath.empty()) {
        auto j = frfJson(frf.value());
        if (!o.margins.empty())
            j["margins"] = marginsJson(frf.value(), o.margins);
        return writeJsonResult(cmd, j, "", -1);
    }
    if (auto st = io::writeFrfCsvFile(o.outPath, frf.value()); !st)
        return reportError(cmd, st.error());
    std::size_t valid = 0;
    for (bool v : frf->valid)
        valid += v ? 1 : 0;
    nlohmann::json summary{{"out", o.outPath}, {"points", frf->size()}, {"valid_points", valid}, {"metadata", frf->metadata}};
    if (!o.margins.empty())
        summary["margins"] = marginsJson(frf.value(), o.margins);
    return writeJsonResult(cmd, summary, "", -1);
}

const CliRegistrar kRegistrar{CliCommand{
    "frf",
    "Frequency response from a capture (Welch H1/H2 + coherence) or a sine-stream CSV (multi-sweep/conventional)",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<FrfOptions>();
        sub.add_option("--in", o->inPath, "capture CSV (time series)");
        sub.add_option("--sweep", o->sweepPath, "sine-stream CSV: freq_Hz,phase_offset_deg,sample,excitation,response");
        sub.add_option("--input", o->inputCol, "excitation column of the capture (e.g. torque_cmd_Nm)");
        sub.add_option("--output", o->outputCol, "response column of the capture (e.g. motor_vel_rad_s)");
        sub.add_option("--time", o->timeCol, "time column [s] (default t_s if present; must be uniform)");
        sub.add_option("--fs", o->fsHz, "sampling frequency [Hz] (default: '# fs_Hz=' metadata or the time column)");
        sub.add_option("--nperseg", o->nperseg, "Welch segment length (default 1024)")->check(CLI::PositiveNumber);
        sub.add_option("--noverlap", o->noverlap, "Welch segment overlap (default nperseg/2)")->check(CLI::NonNegativeNumber);
        sub.add_option("--estimator", o->estimator, "h1 (Pxy/Pxx, default) or h2 (Pyy/Pyx)")
            ->check(CLI::IsMember({"h1", "h2"}));
        sub.add_option("--window", o->window, "hann (periodic, default) or boxcar")->check(CLI::IsMember({"hann", "boxcar"}));
        sub.add_option("--out", o->outPath, "write the FRF CSV (f_Hz,re,im,mag_dB,phase_deg,coherence,valid) here; "
                                            "without it the FRF is printed as JSON");
        sub.add_option("--margins", o->margins,
                       "add gain/phase margins and peak sensitivity to the JSON; the FRF is: open (L), complementary "
                       "(L/(1+L), disturbance injected into the torque command), neg-complementary (-L/(1+L)) or "
                       "sensitivity (1/(1+L))")
            ->check(CLI::IsMember({"open", "complementary", "neg-complementary", "sensitivity"}));
        return recordSessions(sub, [o] { return runFrf(*o); });
    }}};

}  // namespace

}  // namespace axistune::cli

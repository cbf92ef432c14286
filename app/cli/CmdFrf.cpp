// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli frf: frequency response from a capture (Welch H1/H2 + coherence) or from a
// sine-stream recording (conventional or three-phase multi-sweep demodulation); docs/frequency-response.md.
#include "app/cli/CliCommand.h"
#include "app/cli/ImportOptions.h"
#include "app/cli/SessionRecorder.h"
#include "core/dsp/ImpactTest.h"
#include "core/dsp/InjectionHold.h"
#include "core/dsp/LoopAnalysis.h"
#include "core/dsp/LoopMarginsJson.h"
#include "core/dsp/SineDemodulation.h"
#include "core/dsp/Welch.h"
#include "core/io/CaptureCsv.h"
#include "core/io/FrfCsv.h"
#include "core/io/SampleTime.h"
#include "core/io/SweepCsv.h"
#include "core/model/MetadataJson.h"
#include "core/model/MetadataKeys.h"
#include "core/model/Number.h"
#include "core/model/ResultJson.h"
#include "core/model/Units.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

namespace axistune::cli {

namespace {

struct FrfOptions {
    std::vector<std::string> inPaths;
    std::string inPath;  // the first of inPaths
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
    ImportCliOptions import;
    // tap test (--impact)
    bool impact = false;
    std::string forceCol, responseCol;
    std::string responseType = "accel";
    std::string quantity = "receptance";
    double triggerN = 0.0;
    double preTriggerS = -1.0;
    double forceWindowS = 0.0;
    double expTauS = 0.0;
    double lengthS = 0.0;
    std::string doubleHit = "refuse";
    double doubleHitWindowS = 0.05;
    double forceRangeDb = 40.0;
    double fminHz = -1.0;
};

// fs from --fs (overrides everything), the fs_Hz metadata or a time column that is uniform within
// io::kTimeJitterTolerance of its interval (core/io/SampleTime.h).
Result<double> samplingFrequency(const model::Capture& cap, const FrfOptions& o, const std::string& src)
{
    if (o.fsHz > 0.0)
        return o.fsHz;
    const std::string timeName = o.timeCol.empty() ? "t_s" : o.timeCol;
    const model::Channel* t = cap.channel(timeName);
    if (!o.timeCol.empty() && t == nullptr)
        return makeError(ErrorCode::NotFound, src + ": no time column '" + o.timeCol + "'");
    std::optional<double> fromTime;
    if (t != nullptr) {
        std::size_t first = 0;
        // The file line of the first row, for messages only: a value that is not a whole number >= 0 names none.
        if (const auto line = cap.metadata.integer(model::meta::kFirstDataLine); line && *line >= 0)
            first = static_cast<std::size_t>(*line);
        auto timing = io::sampleTiming(t->data, src + ", column '" + timeName + "'", first);
        if (!timing)
            return timing.error();
        fromTime = timing->fsHz;
    }
    if (const auto* v = cap.metadata.find(model::meta::kFsHz)) {
        const double fs = v->number().value_or(0.0);
        if (!(fs > 0.0) || !std::isfinite(fs))
            return makeError(ErrorCode::BadInput,
                             src + ": metadata fs_Hz is not a positive number ('" + v->text() + "')");
        if (fromTime && std::abs(*fromTime - fs) > io::kTimeJitterTolerance * fs) {
            return makeError(ErrorCode::BadInput, src + ": metadata fs_Hz=" + v->text() + " disagrees with column '" +
                                                      timeName + "' (" + model::formatNumber(*fromTime, 10) + " Hz)");
        }
        return fs;
    }
    if (fromTime)
        return *fromTime;
    return makeError(ErrorCode::BadInput, src + ": no sampling frequency: give --fs, a '# fs_Hz=' line or a time column 't_s' (or --time)");
}

Result<dsp::FrequencyResponse> frfFromCapture(const FrfOptions& o)
{
    if (o.inputCol.empty() || o.outputCol.empty())
        return makeError(ErrorCode::BadInput, "--in needs --input COL and --output COL");
    if (o.inPaths.size() != 1)
        return makeError(ErrorCode::BadInput, "several --in files are only for --impact");
    auto cap = readTimeSeries(o.inPath, o.import);
    if (!cap)
        return cap.error();
    const auto* x = cap->channel(o.inputCol);
    const auto* y = cap->channel(o.outputCol);
    for (const auto& [name, ch] : {std::pair{o.inputCol, x}, std::pair{o.outputCol, y}}) {
        if (ch == nullptr)
            return makeError(ErrorCode::NotFound, o.inPath + ": no column '" + name + "'");
    }
    auto fs = samplingFrequency(cap.value(), o, o.inPath);
    if (!fs)
        return fs.error();
    dsp::WelchOptions w;
    w.nperseg = o.nperseg;
    w.noverlap = o.noverlap;
    w.window = o.window == "boxcar" ? dsp::WelchWindow::Rectangular : dsp::WelchWindow::Hann;
    const auto est = o.estimator == "h2" ? dsp::FrfEstimator::H2 : dsp::FrfEstimator::H1;
    // A hammer pulse (crest factor far above a noise or multisine excitation's 2–5) in Welch segments
    // gives a wrong magnitude and a meaningless coherence (issue 19): say so, the result stays as asked.
    double peak = 0.0, power = 0.0;
    for (double v : x->data) {
        peak = std::max(peak, std::abs(v));
        power += v * v;
    }
    if (power > 0.0 && peak / std::sqrt(power / static_cast<double>(x->data.size())) > 20.0)
        std::cerr << "axistune-cli frf: note: column '" << o.inputCol
                  << "' looks like a hammer impact (crest factor above 20); use --impact for tap tests\n";
    auto frf = dsp::welchFrf(x->data, y->data, *fs, w, est);
    if (!frf)
        return makeError(frf.error().code, o.inPath + ": " + frf.error().detail);
    auto& md = frf.value().metadata;
    md.set(model::meta::kInput, o.inputCol);
    md.set(model::meta::kOutput, o.outputCol);
    md.set(model::meta::kFsHz, *fs);
    md.set("window", o.window);
    return frf;
}

dsp::MotionQuantity motionQuantity(const std::string& s)
{
    if (s == "displacement" || s == "receptance")
        return dsp::MotionQuantity::Displacement;
    if (s == "velocity" || s == "mobility")
        return dsp::MotionQuantity::Velocity;
    return dsp::MotionQuantity::Acceleration;
}

// Tap test: every --in file is one record (one or several hits) with the same columns and rate.
Result<dsp::ImpactResult> frfFromImpact(const FrfOptions& o)
{
    if (o.forceCol.empty() || o.responseCol.empty())
        return makeError(ErrorCode::BadInput, "--impact needs --force COL and --response COL");
    std::vector<dsp::ImpactRecord> records;
    std::optional<double> fs;
    for (const auto& path : o.inPaths) {
        auto cap = readTimeSeries(path, o.import);
        if (!cap)
            return cap.error();
        const auto* f = cap->channel(o.forceCol);
        const auto* x = cap->channel(o.responseCol);
        for (const auto& [name, ch] : {std::pair{o.forceCol, f}, std::pair{o.responseCol, x}}) {
            if (ch == nullptr)
                return makeError(ErrorCode::NotFound, path + ": no column '" + name + "'");
        }
        auto rate = samplingFrequency(cap.value(), o, path);
        if (!rate)
            return rate.error();
        if (fs && std::abs(*fs - *rate) > 1e-6 * *fs)
            return makeError(ErrorCode::BadInput, path + ": sampled at " + model::formatNumber(*rate, 10) + " Hz, the first record at "
                                                      + model::formatNumber(*fs, 10) + " Hz");
        fs = *rate;
        records.push_back({path, f->data, x->data});
    }
    dsp::ImpactOptions io;
    io.fsHz = *fs;
    io.response = motionQuantity(o.responseType);
    io.output = motionQuantity(o.quantity);
    io.triggerLevelN = o.triggerN;
    io.preTriggerS = o.preTriggerS;
    io.forceWindowS = o.forceWindowS;
    io.expTauS = o.expTauS;
    io.lengthS = o.lengthS;
    io.doubleHit = o.doubleHit == "drop" ? dsp::DoubleHitPolicy::Drop : dsp::DoubleHitPolicy::Refuse;
    io.doubleHitWindowS = o.doubleHitWindowS;
    io.forceRangeDb = o.forceRangeDb;
    io.minFrequencyHz = o.fminHz;
    auto res = dsp::impactFrf(records, io);
    if (!res)
        return res.error();
    auto& md = res.value().frf.metadata;
    md.set(model::meta::kInput, o.forceCol);
    md.set(model::meta::kOutput, o.responseCol);
    md.set("response_type", o.responseType);
    md.set(model::meta::kQuantity, o.quantity);
    return res;
}

nlohmann::json impactSummary(const dsp::ImpactResult& r)
{
    nlohmann::json hits = nlohmann::json::array();
    for (const auto& h : r.hits)
        hits.push_back({{"record", h.record}, {"trigger_s", h.triggerS}, {"peak_force_N", h.peakForceN}, {"pulse_s", h.pulseS},
                        {"dropped", h.dropped}});
    // the largest |H| among the valid points: what a service engineer looks at first
    double peak = 0.0, peakHz = 0.0;
    for (std::size_t i = 0; i < r.frf.size(); ++i) {
        if (r.frf.valid[i] && std::abs(r.frf.h[i]) > peak) {
            peak = std::abs(r.frf.h[i]);
            peakHz = r.frf.freqHz[i];
        }
    }
    return {{"hits", hits},
            {"hits_used", r.used},
            {"block_s", r.blockS},
            {"pre_trigger_s", r.preTriggerS},
            {"force_window_s", r.forceWindowS},
            {"exp_window_decay_1_s", r.expDecayPerS},
            {"force_band_Hz", r.forceBandHz},
            {"residual_response", r.residualResponse},
            {"peak", {{"f_Hz", peakHz}, {"magnitude", peak}, {"units", *r.frf.metadata.text(model::meta::kUnits)}}},
            {"notes", r.notes}};
}

nlohmann::json frfJson(const dsp::FrequencyResponse& f)
{
    nlohmann::json j;
    j["metadata"] = f.metadata;
    // A column with a value that is not finite is left out and named in "undefined" (docs/formats.md
    // "Undefined values"); f, re and im are finite in every FRF the estimators accept.
    const std::size_t n = f.size();
    std::vector<double> re(n), im(n), mag(n), phase(n);
    for (std::size_t i = 0; i < n; ++i) {
        re[i] = f.h[i].real();
        im[i] = f.h[i].imag();
        mag[i] = dsp::magnitudeDb(f.h[i]);
        phase[i] = dsp::phaseDeg(f.h[i]);
    }
    const char* notFinite = "not a finite number";
    model::putNumbers(j, "f_Hz", f.freqHz, notFinite);
    model::putNumbers(j, "re", re, notFinite);
    model::putNumbers(j, "im", im, notFinite);
    model::putNumbers(j, "mag_dB", mag, "|H| = 0 has no level in dB; use re and im");
    model::putNumbers(j, "phase_deg", phase, "|H| = 0 has no phase; use re and im");
    model::putNumbers(j, "coherence", f.coherence,
                      "coherence not estimated (a sine sweep has none) or not defined (no input power)");
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
    // Undefined margins are left out and named with the reason (docs/formats.md "Undefined values").
    nlohmann::json j{{"measurement", kind}};
    const double inf = std::numeric_limits<double>::infinity();
    model::putNumber(j, "phase_margin_deg", m.phaseMarginDeg, dsp::kNoGainCrossover);
    model::putNumber(j, "phase_margin_freq_Hz", m.gainCrossovers.empty() ? inf : m.phaseMarginFreqHz,
                     dsp::kNoGainCrossover);
    model::putNumber(j, "gain_margin_dB", m.gainMarginDb, dsp::kNoPhaseCrossover);
    model::putNumber(j, "gain_margin_freq_Hz", m.phaseCrossovers.empty() ? inf : m.gainMarginFreqHz,
                     dsp::kNoPhaseCrossover);
    model::putNumber(j, "peak_sensitivity", m.peakSensitivity, dsp::kNoValidPoint);
    model::putNumber(j, "peak_sensitivity_dB", m.peakSensitivityDb, dsp::kNoValidPoint);
    model::putNumber(j, "peak_sensitivity_freq_Hz", m.peakSensitivityFreqHz, dsp::kNoValidPoint);
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
    if (o.inPaths.empty() == o.sweepPath.empty())
        return reportError(cmd, makeError(ErrorCode::BadInput, "give exactly one of --in capture.csv or --sweep sweep.csv"));
    Result<dsp::FrequencyResponse> frf = makeError(ErrorCode::Internal, "");
    std::optional<nlohmann::json> impact;
    if (o.impact) {
        if (!o.sweepPath.empty())
            return reportError(cmd, makeError(ErrorCode::BadInput, "--impact reads --in records, not --sweep"));
        auto r = frfFromImpact(o);
        if (!r)
            return reportError(cmd, r.error());
        for (const auto& n : r->notes)
            std::cerr << "axistune-cli frf: note: " << n << '\n';
        impact = impactSummary(*r);
        frf = std::move(r.value().frf);
    } else if (!o.sweepPath.empty()) {
        auto rec = io::readSweepCsvFile(o.sweepPath);
        if (!rec)
            return reportError(cmd, rec.error());
        frf = dsp::sineStreamFrf(rec.value());
        if (!frf)
            return reportError(cmd, makeError(frf.error().code, o.sweepPath + ": " + frf.error().detail));
        // A drive's sweep (capture --sweep-out) names its injection hold: the same correction as the drive's FRF.
        const auto& md = rec->metadata;
        if (md.contains(model::meta::kInjectionHoldPeriodS) && md.contains(model::meta::kInjectionHoldTicks)) {
            const auto h = md.number(model::meta::kInjectionHoldPeriodS);
            const auto n = md.integer(model::meta::kInjectionHoldTicks);
            Status st = !h                       ? Status(h.error())
                        : !n                     ? Status(n.error())
                        : *n < 1 || *n > 1000000 ? Status(makeError(ErrorCode::BadInput, "tick count out of range"))
                                                 : dsp::correctInjectionHold(frf.value(), *h, static_cast<int>(*n));
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
        if (impact)
            j["impact"] = *impact;
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
    if (impact)
        summary["impact"] = *impact;
    if (!o.margins.empty())
        summary["margins"] = marginsJson(frf.value(), o.margins);
    return writeJsonResult(cmd, summary, "", -1);
}

const CliRegistrar kRegistrar{CliCommand{
    "frf",
    "Frequency response from a capture (Welch H1/H2 + coherence) or a sine-stream CSV (multi-sweep/conventional)",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<FrfOptions>();
        sub.add_option("--in", o->inPaths, "time series: capture CSV, a delimited table, a halscope log or UFF58 time records "
                                           "(--impact: repeat for several records)");
        sub.add_option("--sweep", o->sweepPath, "sine-stream CSV: freq_Hz,phase_offset_deg,sample,excitation,response");
        sub.add_option("--input", o->inputCol, "excitation column of the capture (e.g. torque_cmd_Nm)");
        sub.add_option("--output", o->outputCol, "response column of the capture (e.g. motor_vel_rad_s)");
        sub.add_option("--time", o->timeCol, "time column [s] (default t_s if present; uniform within 1 % of the interval)");
        sub.add_option("--fs", o->fsHz, "sampling frequency [Hz]; overrides the '# fs_Hz=' metadata and the time column");
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
        addImportOptions(sub, o->import);
        sub.add_flag("--impact", o->impact, "tap test: FRF from hammer force and response records (docs/machining.md \"Tap test\")");
        sub.add_option("--force", o->forceCol, "--impact: hammer force column [N]");
        sub.add_option("--response", o->responseCol, "--impact: response column (SI: m, m/s or m/s^2; --unit converts)");
        sub.add_option("--response-type", o->responseType, "--impact: accel (default), velocity or displacement")
            ->check(CLI::IsMember({"accel", "velocity", "displacement"}));
        sub.add_option("--quantity", o->quantity, "--impact: receptance (m/N, default), mobility (m/s/N) or accelerance (m/s2/N)")
            ->check(CLI::IsMember({"receptance", "mobility", "accelerance"}));
        sub.add_option("--trigger", o->triggerN, "--impact: trigger level [N] (default 10 % of the largest force of each record)")
            ->check(CLI::NonNegativeNumber);
        sub.add_option("--pre-trigger", o->preTriggerS, "--impact: time kept before the trigger [s] (default 1 ms or what the record has)")
            ->check(CLI::NonNegativeNumber);
        sub.add_option("--force-window", o->forceWindowS, "--impact: force kept after the trigger [s] (default twice the pulse)")
            ->check(CLI::NonNegativeNumber);
        sub.add_option("--exp-tau", o->expTauS, "--impact: exponential window time constant [s] on force and response "
                                                "(default none); its decay is written to the FRF and removed from fitted modes")
            ->check(CLI::NonNegativeNumber);
        sub.add_option("--length", o->lengthS, "--impact: block length from the pre-trigger [s] (default: to the record end or the next hit)")
            ->check(CLI::NonNegativeNumber);
        sub.add_option("--double-hit", o->doubleHit, "--impact: refuse (default) or drop a hit whose force crosses the trigger again")
            ->check(CLI::IsMember({"refuse", "drop"}));
        sub.add_option("--double-hit-window", o->doubleHitWindowS, "--impact: crossings closer than this [s] are one double hit, "
                                                                    "later ones separate hits (default 0.05)")
            ->check(CLI::PositiveNumber);
        sub.add_option("--force-range-db", o->forceRangeDb, "--impact: points are valid where the force spectrum is within this "
                                                            "of its low-frequency level (default 40 dB)")
            ->check(CLI::PositiveNumber);
        sub.add_option("--fmin", o->fminHz, "--impact: points below this [Hz] are invalid (default 50 Hz for acceleration to "
                                            "receptance, 20 Hz for one integration, else 0)")
            ->check(CLI::NonNegativeNumber);
        return recordSessions(sub, [o] {
            if (!o->inPaths.empty())
                o->inPath = o->inPaths.front();
            return runFrf(*o);
        });
    }}};

}  // namespace

}  // namespace axistune::cli

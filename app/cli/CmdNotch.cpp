// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-cli notch: resonances of a measured velocity-loop FRF, a notch per resonance within the
// execution rate's limits and the free drive slots, predicted FRF and margins (docs/notch.md).
#include "app/cli/CliCommand.h"
#include "app/cli/SessionRecorder.h"
#include "core/dsp/LoopMarginsJson.h"
#include "core/io/FrfCsv.h"
#include "core/model/InputLimits.h"
#include "core/tuning/Notch.h"
#include "core/tuning/Resonance.h"
#include "core/tuning/VelocityLoopDesign.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

namespace axistune::cli {

namespace {

struct NotchCliOptions {
    std::string frfPath;
    std::string existingPath;
    std::string loop = "complementary";
    std::string outFrf;
    int maxNotches = -1;  ///< -1: all free slots
    tuning::NotchOptions notch;
    tuning::ResonanceOptions res;
};

Result<std::vector<dsp::NotchSpec>> readExisting(const std::string& path)
{
    auto parsed = model::readJsonFile(path);
    if (!parsed)
        return parsed.error();
    const nlohmann::json& j = *parsed;
    if (!j.is_array())
        return makeError(ErrorCode::BadInput, path + ": expected a JSON list of {center_Hz, width_Hz, depth}");
    std::vector<dsp::NotchSpec> out;
    for (std::size_t k = 0; k < j.size(); ++k) {
        const auto& e = j[k];
        const std::string where = path + ": element " + std::to_string(k);
        if (!e.is_object())
            return makeError(ErrorCode::BadInput, where + ": expected an object");
        dsp::NotchSpec n;
        for (const auto& [key, dst] : {std::pair<const char*, double*>{"center_Hz", &n.centerHz},
                                       {"width_Hz", &n.widthHz}, {"depth", &n.depth}}) {
            if (!e.contains(key))
                return makeError(ErrorCode::BadInput, where + ": missing field '" + key + "'");
            if (!e[key].is_number())
                return makeError(ErrorCode::BadInput, where + ", field '" + key + "': not a number");
            *dst = e[key].get<double>();
        }
        out.push_back(n);
    }
    return out;
}

int runNotch(NotchCliOptions o)
{
    const std::string cmd = "notch";
    // One parser of loop measurements (core/tuning/VelocityLoopDesign.h); a plant is not a loop form.
    const auto kind = tuning::parseLoopMeasurement(o.loop);
    const auto parsedForm = kind ? tuning::loopFormOf(*kind) : Result<tuning::LoopForm>(kind.error());
    const tuning::LoopForm form = parsedForm ? *parsedForm : tuning::LoopForm{};
    if (!parsedForm)
        return reportError(cmd, makeError(ErrorCode::BadInput, "--loop must be open, complementary, neg-complementary or "
                                                               "sensitivity (got '" + o.loop + "')"));
    if (!(o.notch.execRateHz > 0.0) || !std::isfinite(o.notch.execRateHz))
        return reportError(cmd, makeError(ErrorCode::BadInput, "--exec-rate-hz must be > 0"));
    if (o.maxNotches < -1)
        return reportError(cmd, makeError(ErrorCode::BadInput, "--max must be >= 0"));
    o.notch.maxNotches = o.maxNotches < 0 ? o.notch.slotCount : o.maxNotches;

    std::vector<dsp::NotchSpec> existing;
    if (!o.existingPath.empty()) {
        auto e = readExisting(o.existingPath);
        if (!e)
            return reportError(cmd, e.error());
        existing = *e;
        for (std::size_t k = 0; k < existing.size(); ++k)
            if (auto st = tuning::checkExistingNotch(existing[k], o.notch.execRateHz,
                                                     o.existingPath + ": element " + std::to_string(k));
                !st)
                return reportError(cmd, st.error());
    }
    auto frf = io::readFrfCsvFile(o.frfPath);
    if (!frf)
        return reportError(cmd, frf.error());
    // The existing notches occupy slots 1..k; the analysis is the notch wizard's (tuning::analyseNotches).
    std::map<int, dsp::NotchSpec> existingSlots;
    for (std::size_t k = 0; k < existing.size(); ++k)
        existingSlots[static_cast<int>(k) + 1] = existing[k];
    auto analysis = tuning::analyseNotches(*frf, form, o.res, o.notch, existingSlots);
    if (!analysis)
        return reportError(cmd, Error{analysis.error().code, o.frfPath + ": " + analysis.error().detail});
    const auto* res = &analysis->resonances;
    const auto* proposal = &analysis->proposal;
    const auto* pred = &analysis->prediction;
    std::vector<dsp::NotchSpec> added;
    for (const auto& n : analysis->notches)
        added.push_back(n.spec);
    if (!o.outFrf.empty()) {
        auto out = pred->measuredAfter;
        out.metadata.set("predicted_with_notches", static_cast<double>(added.size()));
        if (auto st = io::writeFrfCsvFile(o.outFrf, out); !st)
            return reportError(cmd, st.error());
    }

    nlohmann::json j;
    j["frf"] = o.frfPath;
    j["loop"] = o.loop;
    j["exec_rate_Hz"] = o.notch.execRateHz;
    j["nyquist_Hz"] = 0.5 * o.notch.execRateHz;
    j["slots_total"] = o.notch.slotCount;
    j["slots_free"] = proposal->slotsFree;
    j["target_open_loop_dB"] = o.notch.targetOpenLoopDb;
    j["resonances"] = nlohmann::json::array();
    for (const auto& r : *res)
        j["resonances"].push_back({{"f_Hz", r.freqHz},
                                   {"peak_dB", r.peakDb},
                                   {"width_Hz", r.widthHz},
                                   {"open_loop_dB", r.levelDb},
                                   {"noise_dB", r.noiseDb},
                                   {"width_one_sided", r.widthOneSided}});
    j["existing"] = nlohmann::json::array();
    for (std::size_t k = 0; k < existing.size(); ++k)
        j["existing"].push_back({{"slot", k + 1},
                                 {"center_Hz", existing[k].centerHz},
                                 {"width_Hz", existing[k].widthHz},
                                 {"depth", existing[k].depth}});
    j["notches"] = nlohmann::json::array();
    for (const auto& n : analysis->notches)
        j["notches"].push_back({{"slot", n.slot},
                                {"center_Hz", n.spec.centerHz},
                                {"width_Hz", n.spec.widthHz},
                                {"depth", n.spec.depth},
                                {"digital_width_Hz", n.digitalWidthHz},
                                {"parameters", {{"filter.notch" + std::to_string(n.slot) + ".center", n.spec.centerHz},
                                                {"filter.notch" + std::to_string(n.slot) + ".width", n.spec.widthHz},
                                                {"filter.notch" + std::to_string(n.slot) + ".depth", n.spec.depth}}}});
    j["skipped"] = nlohmann::json::array();
    for (const auto& s : proposal->skipped)
        j["skipped"].push_back({{"f_Hz", s.freqHz}, {"reason", s.reason}});
    j["margins_before"] = dsp::loopMarginsJson(pred->before);
    j["margins_after"] = dsp::loopMarginsJson(pred->after);
    if (!o.outFrf.empty())
        j["predicted_frf"] = o.outFrf;
    return writeJsonResult(cmd, j, "");
}

const CliRegistrar kRegistrar{CliCommand{
    "notch",
    "Resonances of a velocity-loop FRF, proposed notch filters, predicted FRF and margins before/after",
    [](CLI::App& sub) -> std::function<int()> {
        auto o = std::make_shared<NotchCliOptions>();
        sub.add_option("--frf", o->frfPath, "measured FRF CSV (f_Hz,re,im,... or f_Hz,mag_dB,phase_deg,...)")->required();
        sub.add_option("--exec-rate-hz", o->notch.execRateHz, "rate the notches run at (current loop), default 16000");
        sub.add_option("--existing", o->existingPath, "JSON list of existing notches {center_Hz, width_Hz, depth}");
        sub.add_option("--max", o->maxNotches, "propose at most N notches (default: all free slots)");
        sub.add_option("--slots", o->notch.slotCount, "notch slots of the drive (default 4)");
        sub.add_option("--target-db", o->notch.targetOpenLoopDb, "open-loop gain wanted at a resonance [dB], default -20");
        sub.add_option("--loop", o->loop, "what the FRF is: complementary (T = L/(1+L), default), neg-complementary, "
                                          "sensitivity or open");
        sub.add_option("--min-height-db", o->res.minHeightDb, "smallest peak height above the baseline [dB], default 6");
        sub.add_option("--noise-factor", o->res.noiseFactor, "peak height must exceed this many local noise scales, default 4");
        sub.add_option("--min-coherence", o->res.minCoherence, "ignore points with a lower coherence, default 0.5");
        sub.add_option("--fmin", o->res.fminHz, "search resonances above this frequency [Hz]");
        sub.add_option("--fmax", o->res.fmaxHz, "search resonances below this frequency [Hz]");
        sub.add_option("--out-frf", o->outFrf, "write the predicted FRF (measured form, with the notches) to this CSV");
        return recordSessions(sub, [o] { return runNotch(*o); });
    }}};

}  // namespace

}  // namespace axistune::cli

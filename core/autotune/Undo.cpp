// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/autotune/Undo.h"

#include "core/autotune/AutoTuneRun.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace axistune::autotune {

using detail::num;
using detail::readsBackAs;

Result<AppliedTune> appliedTuneFromJson(const nlohmann::json& j)
{
    if (!j.is_object())
        return makeError(ErrorCode::BadInput, "the result is not a JSON object");
    const auto outcome = j.find("outcome");
    if (outcome == j.end() || !outcome->is_string())
        return makeError(ErrorCode::BadInput, "the result has no 'outcome'");
    if (*outcome != "applied")
        return makeError(ErrorCode::BadInput, "outcome is '" + outcome->get<std::string>() +
                                                  "': only an applied run can be undone (a refused or dry run "
                                                  "restored its parameters itself)");
    const auto axis = j.find("axis");
    if (axis == j.end() || !axis->is_string() || axis->get<std::string>().empty())
        return makeError(ErrorCode::BadInput, "the result has no 'axis'");
    const auto fin = j.find("final");
    if (fin == j.end() || !fin->is_object() || !fin->contains("parameters") || !(*fin)["parameters"].is_object())
        return makeError(ErrorCode::BadInput, "the result has no 'final.parameters'");
    const auto steps = j.find("steps");
    const nlohmann::json* apply = nullptr;
    if (steps != j.end() && steps->is_array())
        for (const auto& s : *steps)
            if (s.is_object() && s.value("name", std::string()) == "apply")
                apply = &s;
    if (!apply || !apply->contains("measured") || !(*apply)["measured"].is_object())
        return makeError(ErrorCode::BadInput, "the result has no 'apply' step with 'measured'");
    AppliedTune t;
    t.axis = axis->get<std::string>();
    for (const auto& [k, v] : (*fin)["parameters"].items()) {
        if (!v.is_number() || !std::isfinite(v.get<double>()))
            return makeError(ErrorCode::BadInput, "final.parameters." + k + " is not a finite number");
        const auto& m = (*apply)["measured"];
        const auto b = m.find("before." + k);
        if (b == m.end() || !b->is_number() || !std::isfinite(b->get<double>()))
            return makeError(ErrorCode::BadInput, "steps[apply].measured.before." + k + " is missing or not a number");
        t.applied[k] = v.get<double>();
        t.before[k] = b->get<double>();
    }
    if (t.applied.empty())
        return makeError(ErrorCode::BadInput, "final.parameters is empty: the run applied nothing");
    return t;
}

std::vector<ChangedParameter> changedSinceApplied(const model::ParameterValues& now, const AppliedTune& tune)
{
    std::vector<ChangedParameter> out;
    for (const auto& [k, v] : tune.applied) {
        const auto it = now.find(k);
        if (it == now.end())
            out.push_back({k, v, std::nullopt});
        else if (!readsBackAs(it->second, v))
            out.push_back({k, v, it->second});
    }
    return out;
}

Error changedRefusal(const AppliedTune& tune, const std::vector<ChangedParameter>& changed)
{
    const auto& c = changed.front();
    if (!c.now)
        return makeError(ErrorCode::NotFound, "axis " + tune.axis + " has no parameter " + c.key);
    return makeError(ErrorCode::Safety, c.key + " is " + num(*c.now, 7) + ", not the " + num(c.applied, 7) +
                                            " the run applied: it was changed since, and undoing would "
                                            "overwrite that (nothing written)");
}

Result<std::vector<UndoneParameter>> undoTune(device::Drive& drive, const AppliedTune& tune, bool force)
{
    std::vector<std::string> keys;
    for (const auto& [k, v] : tune.applied)
        keys.push_back(k);
    auto now = drive.readParameters(tune.axis, keys);
    if (!now)
        return now.error();
    if (!force)
        if (const auto changed = changedSinceApplied(*now, tune); !changed.empty())
            return changedRefusal(tune, changed);
    model::ParameterValues back;
    for (const auto& k : keys)
        back[k] = tune.before.at(k);
    if (auto st = drive.writeParameters(tune.axis, back); !st)
        return st.error();
    auto read = drive.readParameters(tune.axis, keys);
    if (!read)
        return read.error();
    std::vector<UndoneParameter> out;
    for (const auto& k : keys) {
        const auto it = read->find(k);
        if (it == read->end() || !readsBackAs(it->second, back[k]))
            return makeError(ErrorCode::Device, k + " reads back " +
                                                    (it == read->end() ? std::string("nothing") : num(it->second, 7)) +
                                                    " after the undo, written " + num(back[k], 7));
        out.push_back({k, now->count(k) ? now->at(k) : tune.applied.at(k), it->second});
    }
    return out;
}

} // namespace axistune::autotune

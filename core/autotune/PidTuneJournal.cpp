// SPDX-License-Identifier: GPL-3.0-or-later
// The journal of a position-PID tune and of its undo (core/autotune/PidTune.h PidTuneWrite): what the NC PID page
// saves with its session and what pid-tune's result JSON lists (docs/storage.md "Journal").
#include "core/autotune/PidTune.h"
#include "core/device/hal/HalAxis.h"

#include <nlohmann/json.hpp>

namespace axistune::autotune {
namespace {

// HAL's names of AxisTune's notch (docs/linuxcnc.md "Notches"): the component and its parameters f0 and Q.
const std::string kNotch = device::hal::kNotchComponent;
const std::string kNotchF0 = kNotch + ".f0";
const std::string kNotchQ = kNotch + ".Q";

} // namespace

std::vector<PidTuneWrite> pidTuneNotchWrites(const std::optional<tuning::BiquadNotch>& from,
                                             const std::optional<tuning::BiquadNotch>& to)
{
    if (!from && !to)
        return {};
    if (!from)
        return {{kNotch, 0.0, 1.0}, {kNotchF0, std::nullopt, to->f0Hz}, {kNotchQ, std::nullopt, to->q}};
    if (!to)
        return {{kNotch, 1.0, 0.0}};
    if (from->f0Hz == to->f0Hz && from->q == to->q)
        return {};
    return {{kNotchF0, from->f0Hz, to->f0Hz}, {kNotchQ, from->q, to->q}};
}

std::vector<PidTuneWrite> pidTuneAppliedWrites(const PidTuneApplied& applied, const PidTuneProposal& proposal)
{
    if (!applied.applied)
        return {};
    std::vector<PidTuneWrite> out;
    for (const auto& [k, v] : applied.written) {
        const auto before = applied.before.find(k);
        out.push_back({k, before != applied.before.end() ? std::optional<double>(before->second) : std::nullopt, v});
    }
    for (auto& w : pidTuneNotchWrites(applied.notchBefore, proposal.notch))
        out.push_back(std::move(w));
    return out;
}

std::vector<PidTuneWrite> pidTuneUndoWrites(const std::vector<UndoneParameter>& gains, const PidTuneNotchUndone& notch)
{
    std::vector<PidTuneWrite> out;
    for (const auto& u : gains)
        out.push_back({u.key, u.applied, u.restored});
    if (notch.changed)
        for (auto& w : pidTuneNotchWrites(notch.held, notch.restored))
            out.push_back(std::move(w));
    return out;
}

nlohmann::json pidTuneWritesJson(const std::vector<PidTuneWrite>& writes)
{
    nlohmann::json out = nlohmann::json::array();
    for (const auto& w : writes) {
        nlohmann::json e{{"key", w.key}};
        if (w.from) // absent, not null: nothing before (result files hold numbers only)
            e["old"] = *w.from;
        e["new"] = w.to;
        out.push_back(std::move(e));
    }
    return out;
}

} // namespace axistune::autotune

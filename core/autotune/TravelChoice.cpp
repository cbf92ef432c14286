// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/autotune/TravelChoice.h"

#include "core/autotune/AmplitudeMap.h"
#include "core/device/MoveTo.h"
#include "core/model/Number.h"

#include <cmath>

namespace axistune::autotune {

double defaultTimeBudgetS(int positions)
{
    return kDefaultBudgetPerPositionS * static_cast<double>(positions < 1 ? 1 : positions);
}

double positionsInset(bool linear, double positionGainPerS)
{
    if (!(positionGainPerS > 0.0) || !std::isfinite(positionGainPerS))
        return std::nan("");
    return (linear ? device::kMoveToSpeedLinear : device::kMoveToSpeedRotary) / positionGainPerS;
}

Result<std::vector<double>> positionsOverTravel(double window, double inset, int n)
{
    if (n < 2)
        return makeError(ErrorCode::BadInput, "positions over the travel: need at least 2");
    if (!(inset >= 0.0) || !std::isfinite(inset) || !(window > inset))
        return makeError(ErrorCode::BadInput, "the travel window +-" + model::formatNumber(window, 4) +
                                                  " leaves no room inside the inset " + model::formatNumber(inset, 4) +
                                                  " (the move's servo lag v/K_p) from its ends");
    const double w = window - inset;
    std::vector<double> xs;
    for (int i = 0; i < n; ++i)
        xs.push_back(-w + 2.0 * w * static_cast<double>(i) / static_cast<double>(n - 1));
    return xs;
}

Result<TravelChoice> travelChoice(device::Drive& drive, const std::string& axis)
{
    auto caps = drive.capabilities(axis);
    if (!caps)
        return caps.error();
    TravelChoice c;
    if (auto st = device::checkCanMoveTo(drive, axis); !st) {
        if (st.error().code != ErrorCode::BadInput)
            return st.error();
        c.refusal = st.error().detail;
    }
    if (auto w = device::travelWindow(drive, axis))
        c.window = *w;
    if (caps->scope) {
        if (auto sc = drive.scopeCapabilities(axis)) {
            for (const auto& ch : sc->channels)
                if (ch.name.rfind("position_cmd_", 0) == 0 && (ch.unit == "m" || ch.unit == "rad")) {
                    c.units = ch.unit;
                    break;
                }
        }
    }
    const std::vector<std::string> kpKey{"position.kp"};
    if (auto kp = drive.readParameters(axis, kpKey); kp && kp->count("position.kp"))
        c.inset = positionsInset(c.units != "rad", kp->at("position.kp"));
    else
        c.inset = std::nan("");
    return c;
}

Status checkChoices(const Options& o, const ChoiceNames& n)
{
    auto bad = [](const std::string& what) { return makeError(ErrorCode::BadInput, what); };
    if (o.positions < 1)
        return bad(n.positions + ": must be >= 1 (got " + model::formatNumber(o.positions, 10) + ")");
    if (!(o.timeBudgetS > 0.0) || !std::isfinite(o.timeBudgetS))
        return bad(n.timeBudget + ": must be > 0 s");
    if (!(o.minBandwidthHz >= 0.0) || !std::isfinite(o.minBandwidthHz))
        return bad(n.minBandwidth + ": must be >= 0 Hz (0: the style's)");
    if (!o.amplitudeMapPct.empty()) {
        if (o.positions > 1)
            return bad(n.amplitudes + ": it is for one position; over the travel the plain adaptive FRF is measured "
                                      "at each position");
        if (auto st = checkAmplitudeList(o.amplitudeMapPct); !st)
            return bad(n.amplitudes + ": " + st.error().detail);
    }
    if (o.motor && o.positions > 1)
        return bad(n.motor + ": they are for one position; over the travel the current loop is kept (tune it at "
                             "one position first)");
    return {};
}

Result<std::vector<double>> parseAmplitudeList(std::string_view text)
{
    std::vector<double> out;
    std::size_t i = 0;
    auto sep = [](char c) { return c == ',' || c == ' ' || c == '\t'; };
    while (i < text.size()) {
        while (i < text.size() && sep(text[i]))
            ++i;
        std::size_t j = i;
        while (j < text.size() && !sep(text[j]))
            ++j;
        if (j > i) {
            const auto item = text.substr(i, j - i);
            const auto v = model::parseNumber(item);
            if (!v)
                return makeError(ErrorCode::BadInput, "amplitude map: '" + std::string(item) + "' is not a number");
            out.push_back(*v);
        }
        i = j;
    }
    return out;
}

} // namespace axistune::autotune

// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/hal/HalText.h"

#include "core/model/Number.h"

#include <sstream>

namespace axistune::device::hal {
namespace {

template <typename F> Status forEachLine(std::string_view text, F&& f)
{
    std::size_t lineNo = 0;
    while (!text.empty()) {
        const std::size_t nl = text.find('\n');
        const std::string_view line = text.substr(0, nl);
        ++lineNo;
        const auto w = splitWords(line);
        if (!w.empty()) {
            if (auto st = f(w, lineNo); !st)
                return st;
        }
        if (nl == std::string_view::npos)
            break;
        text.remove_prefix(nl + 1);
    }
    return {};
}

bool isArrow(const std::string& w)
{
    return w == "==>" || w == "<==" || w == "<=>";
}

Status badLine(const char* what, std::size_t lineNo, const std::vector<std::string>& w)
{
    std::string joined;
    for (const auto& s : w)
        joined += (joined.empty() ? "" : " ") + s;
    return makeError(ErrorCode::Device, std::string("halcmd show ") + what + ", line " + std::to_string(lineNo) +
                                            ": cannot read '" + joined + "'");
}

} // namespace

Result<std::vector<HalPin>> parsePins(std::string_view text)
{
    std::vector<HalPin> pins;
    auto st = forEachLine(text, [&](const std::vector<std::string>& w, std::size_t lineNo) -> Status {
        if (w.size() != 5 && w.size() != 7)
            return badLine("pin", lineNo, w);
        if (w.size() == 7 && !isArrow(w[5]))
            return badLine("pin", lineNo, w);
        HalPin p{w[0], w[1], w[2], w[3], w[4], w.size() == 7 ? w[6] : std::string{}};
        pins.push_back(std::move(p));
        return {};
    });
    if (!st)
        return st.error();
    return pins;
}

Result<std::vector<HalSignal>> parseSignals(std::string_view text)
{
    std::vector<HalSignal> sigs;
    auto st = forEachLine(text, [&](const std::vector<std::string>& w, std::size_t lineNo) -> Status {
        if (w.size() < 3 || (w.size() - 3) % 2 != 0)
            return badLine("sig", lineNo, w);
        HalSignal s{w[0], w[1], w[2], {}, {}};
        for (std::size_t i = 3; i + 1 < w.size(); i += 2) {
            if (w[i] == "<==")
                s.writer = w[i + 1];
            else if (w[i] == "==>" || w[i] == "<=>")
                s.readers.push_back(w[i + 1]);
            else
                return badLine("sig", lineNo, w);
        }
        sigs.push_back(std::move(s));
        return {};
    });
    if (!st)
        return st.error();
    return sigs;
}

Result<std::vector<HalThread>> parseThreads(std::string_view text)
{
    std::vector<HalThread> threads;
    auto st = forEachLine(text, [&](const std::vector<std::string>& w, std::size_t lineNo) -> Status {
        if (w.size() < 5)
            return badLine("thread", lineNo, w);
        auto period = model::parseInteger(w[0]);
        if (!period || *period <= 0)
            return badLine("thread", lineNo, w);
        HalThread t;
        t.periodNs = *period;
        t.name = w[2];
        t.functions.assign(w.begin() + 5, w.end());
        threads.push_back(std::move(t));
        return {};
    });
    if (!st)
        return st.error();
    return threads;
}

std::vector<std::string> splitWords(std::string_view line)
{
    std::vector<std::string> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
            ++i;
        std::size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r')
            ++j;
        if (j > i)
            out.emplace_back(line.substr(i, j - i));
        i = j;
    }
    return out;
}

const HalPin* findPin(const std::vector<HalPin>& pins, std::string_view name)
{
    for (const auto& p : pins)
        if (p.name == name)
            return &p;
    return nullptr;
}

const HalSignal* findSignal(const std::vector<HalSignal>& halSignals, std::string_view name)
{
    for (const auto& s : halSignals)
        if (s.name == name)
            return &s;
    return nullptr;
}

} // namespace axistune::device::hal

// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/hal/HalScope.h"

#include "core/device/hal/HalText.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <string_view>
#include <unistd.h>

namespace axistune::device::hal {
namespace {

constexpr std::uint64_t kHostRingValues = 8u << 20;    ///< channels × rows the host ring holds in roll mode
constexpr std::uint64_t kHostCaptureValues = 4u << 20; ///< channels × rows of one triggered capture
constexpr const char* kScopeInstance = "sampler.1";    ///< HalSampler.h

struct ChannelPin {
    const char* name;
    const char* pin; ///< suffix of the pid's pin
    const char* unit;
    const char* description;
};
const ChannelPin kPidChannels[] = {
    {"command", "command", "position unit", "position command the pid follows (<pid>.command)"},
    {"feedback", "feedback", "position unit", "position feedback (<pid>.feedback)"},
    {"output", "output", "output unit", "PID output, the drive input (<pid>.output)"},
    {"following_error", "error", "position unit", "following error the pid computes (<pid>.error)"},
};

/// The sampler pin type letter of a HAL pin type ('f', 'b', 's', 'u'), 0 for none (a port).
char typeLetter(const std::string& halType)
{
    return halType == "float" ? 'f' : halType == "bit" ? 'b' : halType == "s32" ? 's' : halType == "u32" ? 'u' : 0;
}

/// A pin the scope can sample without changing anything: a float, bit, s32 or u32 pin that is an output (a net of
/// the scope's own carries it when it is on none) or an input on a net; not AxisTune's own components' pins.
bool samplable(const HalPin& p)
{
    if (!typeLetter(p.type) || p.name.rfind("sampler.", 0) == 0 || p.name.rfind("streamer.", 0) == 0 ||
        p.name.rfind("axistune", 0) == 0)
        return false;
    return p.dir == "OUT" || !p.signal.empty();
}

const char* unitOf(const std::string& halType)
{
    return halType == "float" ? "HAL units" : halType == "bit" ? "HAL bit" : "HAL count";
}

} // namespace

ScopeCapabilities halScopeCapabilities(const HalAxis& axis, const std::vector<HalPin>& pins)
{
    ScopeCapabilities c;
    for (const auto& ch : kPidChannels)
        c.channels.push_back({ch.name, std::string("HAL ") + ch.unit, ch.description});
    auto pidChannel = [&](const std::string& pin) {
        for (const auto& ch : kPidChannels)
            if (pin == axis.pid + "." + ch.pin)
                return true;
        return false;
    };
    for (const auto& p : pins)
        if (samplable(p) && !pidChannel(p.name)) // the pid's own under their channel names above
            c.channels.push_back(
                {p.name, unitOf(p.type),
                 "HAL " + p.type + " pin (" + p.dir + (p.signal.empty() ? "" : ", net " + p.signal) + ")"});
    c.fastestRateHz = axis.periodNs > 0 ? 1e9 / static_cast<double>(axis.periodNs) : 0.0;
    c.maxChannels = static_cast<int>(std::string_view(kScopeSamplerTypes).size());
    c.maxDivider = 1; // the sampler takes every period; no divider in LinuxCNC 2.9's sampler
    c.maxValues = kHostCaptureValues;
    c.ringValues = kHostRingValues;
    return c;
}

Result<std::unique_ptr<HalScope>> HalScope::start(const HalSessionOptions& options, const HalAxis& axis,
                                                  const ScopeCapabilities& caps, const ScopeSetup& setup)
{
    auto text = runHalcmd(options, {"-s", "show", "pin"});
    if (!text)
        return text.error();
    auto ps = parsePins(*text);
    if (!ps)
        return ps.error();
    std::unique_ptr<HalScope> s(new HalScope);
    s->m_options = options;
    s->m_axis = axis;
    // Each channel takes the next free pin of its type of sampler.1; m_pick maps the sampler's row to the channels.
    const std::string types = kScopeSamplerTypes;
    std::string used(types.size(), 0);
    std::vector<std::vector<std::string>> links;
    std::map<std::string, std::string> ownNets; ///< an output pin on no net → the net of the scope's own made for it
    for (std::size_t i = 0; i < setup.channels.size(); ++i) {
        const std::string& name = caps.channels[setup.channels[i]].name;
        std::string pin = name;
        for (const auto& c : kPidChannels)
            if (name == c.name)
                pin = axis.pid + "." + c.pin;
        const HalPin* p = findPin(*ps, pin);
        if (!p)
            return makeError(ErrorCode::NotFound, "HAL has no pin " + pin);
        const char letter = typeLetter(p->type);
        std::size_t slot = types.size();
        for (std::size_t k = 0; k < types.size() && slot == types.size(); ++k)
            if (types[k] == letter && !used[k])
                slot = k;
        if (slot == types.size()) {
            const auto count = std::count(types.begin(), types.end(), letter);
            return makeError(ErrorCode::BadInput, letter ? "the hal: scope samples at most " + std::to_string(count) +
                                                               " " + p->type + " pins at once (channel " + pin + ")"
                                                         : "scope channel " + pin + " is a " + p->type +
                                                               " pin, which the sampler cannot take");
        }
        used[slot] = 1;
        s->m_pick.push_back(slot);
        const std::string samplerPin = std::string(kScopeInstance) + ".pin." + std::to_string(slot);
        if (!p->signal.empty()) {
            links.push_back({"linksp", p->signal, samplerPin});
        } else if (auto own = ownNets.find(pin); own != ownNets.end()) {
            links.push_back({"linksp", own->second, samplerPin}); // the same pin twice
        } else if (p->dir == "OUT") {
            // An output on no net: a net of AxisTune's own carries it to the sampler (removed afterwards).
            const std::string net = "axistune-scope-" + std::to_string(slot);
            ownNets[pin] = net;
            links.push_back({"net", net, pin, samplerPin});
        } else {
            return makeError(ErrorCode::BadInput, pin + " is not linked to a net: sampling it would change its value");
        }
    }
    // The sampler, loaded once for the scope and the tests (HalSampler.h): a test may run meanwhile.
    auto module = HalSamplerModule::acquire(options, axis.periodNs);
    if (!module)
        return module.error();
    s->m_sampler = std::move(module).value();
    auto client = HalClient::open("axistune-scope-" + std::to_string(::getpid()));
    if (!client) {
        (void)s->stop();
        return client.error();
    }
    s->m_client = std::move(client).value();
    auto stream = HalStream::attach(*s->m_client, HalStream::Direction::FromHal, kSamplerKey + 1, types);
    if (!stream) {
        (void)s->stop();
        return stream.error();
    }
    s->m_stream = std::move(stream).value();
    // Rows an earlier scope left in the FIFO (the module stayed loaded for a test) are not this capture's.
    {
        std::vector<double> stale;
        std::uint32_t n = 0;
        while (s->m_stream->read(stale, n)) {
        }
    }
    // Pins linked first, then the function on the thread: every row holds the linked pins.
    struct Step {
        std::vector<std::string> doArgs;
        std::vector<std::string> undoArgs;
    };
    std::vector<Step> steps;
    for (auto& l : links) {
        std::vector<std::string> undo =
            l.front() == "net" ? std::vector<std::string>{"delsig", l[1]} : std::vector<std::string>{"unlinkp", l[2]};
        steps.push_back({std::move(l), std::move(undo)});
    }
    steps.push_back({{"addf", kScopeInstance, axis.thread}, {"delf", kScopeInstance, axis.thread}});
    for (auto& st : steps) {
        auto r = runHalcmd(options, st.doArgs);
        if (!r) {
            (void)s->stop();
            return makeError(ErrorCode::Device,
                             "inserting the scope's sampler failed (nothing left changed): " + r.error().detail);
        }
        s->m_undo.push_back(std::move(st.undoArgs));
    }
    const std::uint64_t ringRows = kHostRingValues / std::max<std::size_t>(setup.channels.size(), 1);
    s->m_recorder.arm(setup, ringRows);
    s->m_thread = std::thread([p = s.get()] { p->read(); });
    return s;
}

void HalScope::read()
{
    std::vector<double> row, picked(m_pick.size());
    std::uint32_t raw = 0, lastRaw = 0;
    std::uint64_t sample = 0;
    bool first = true;
    auto lastRow = std::chrono::steady_clock::now();
    while (!m_stop.load()) {
        bool any = false;
        while (m_stream->read(row, raw)) {
            // The sampler numbers rows with a 32-bit counter: unwrapped here to the 64-bit sample number.
            sample = first ? raw : sample + static_cast<std::uint32_t>(raw - lastRaw);
            first = false;
            lastRaw = raw;
            std::lock_guard lock(m_mutex);
            for (std::size_t k = 0; k < m_pick.size(); ++k)
                picked[k] = row[m_pick[k]];
            m_recorder.push(sample, picked);
            any = true;
        }
        const auto now = std::chrono::steady_clock::now();
        if (any) {
            lastRow = now;
        } else if (now - lastRow > std::chrono::seconds(3)) {
            std::lock_guard lock(m_mutex);
            m_failure = "the HAL sampler delivered no row for 3 s: the HAL session stopped or " + m_axis.thread +
                        " no longer runs";
            return;
        }
        if (!any)
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
}

void HalScope::stopReading()
{
    m_stop = true;
    if (m_thread.joinable())
        m_thread.join();
    std::lock_guard lock(m_mutex);
    m_recorder.stop();
}

Status HalScope::stop()
{
    stopReading();
    m_stream.reset();
    Status first;
    while (!m_undo.empty()) {
        auto args = std::move(m_undo.back());
        m_undo.pop_back();
        auto r = runHalcmd(m_options, args);
        if (!r && first)
            first = r.error();
    }
    m_client.reset();
    // Unloads the sampler unless a test still holds it (two periods after sampler.1 left the thread).
    m_sampler.reset();
    std::lock_guard lock(m_mutex);
    m_recorder.stop();
    return first;
}

HalScope::~HalScope()
{
    (void)stop();
}

ScopeStatus HalScope::status() const
{
    std::lock_guard lock(m_mutex);
    return m_recorder.status();
}

ScopeRows HalScope::rows(std::uint64_t from, std::size_t maxRows) const
{
    std::lock_guard lock(m_mutex);
    return m_recorder.rows(from, maxRows);
}

Result<ScopeCapture> HalScope::capture() const
{
    std::lock_guard lock(m_mutex);
    return m_recorder.capture();
}

std::string HalScope::failure() const
{
    std::lock_guard lock(m_mutex);
    return m_failure;
}

} // namespace axistune::device::hal

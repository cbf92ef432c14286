// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/hal/HalScope.h"

#include "core/device/hal/HalText.h"

#include <chrono>
#include <unistd.h>

namespace axistune::device::hal {
namespace {

constexpr int kSamplerDepth = 65536;                   ///< sampler FIFO rows (65 ms at 1 kHz … 16 ms at 4 kHz)
constexpr std::uint64_t kHostRingValues = 8u << 20;    ///< channels × rows the host ring holds in roll mode
constexpr std::uint64_t kHostCaptureValues = 4u << 20; ///< channels × rows of one triggered capture

struct ChannelPin {
    const char* name;
    const char* pin; ///< suffix of the pid's pin
    bool output;     ///< an OUT pin: a net may be made for it; an IN pin must already be on one
    const char* unit;
    const char* description;
};
const ChannelPin kChannels[] = {
    {"command", "command", false, "position unit", "position command the pid follows (<pid>.command)"},
    {"feedback", "feedback", false, "position unit", "position feedback (<pid>.feedback)"},
    {"output", "output", true, "output unit", "PID output, the drive input (<pid>.output)"},
    {"following_error", "error", true, "position unit", "following error the pid computes (<pid>.error)"},
};

} // namespace

ScopeCapabilities halScopeCapabilities(const HalAxis& axis)
{
    ScopeCapabilities c;
    for (const auto& ch : kChannels)
        c.channels.push_back({ch.name, std::string("HAL ") + ch.unit, ch.description});
    c.fastestRateHz = axis.periodNs > 0 ? 1e9 / static_cast<double>(axis.periodNs) : 0.0;
    c.maxChannels = static_cast<int>(c.channels.size());
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
    if (findPin(*ps, "sampler.0.pin.0"))
        return makeError(ErrorCode::Busy, "LinuxCNC's sampler is loaded already (a test of AxisTune, or another "
                                          "program): the scope needs it; stop the test first");
    std::unique_ptr<HalScope> s(new HalScope);
    s->m_options = options;
    s->m_axis = axis;
    std::string cfg;
    std::vector<std::vector<std::string>> links;
    for (std::size_t i = 0; i < setup.channels.size(); ++i) {
        const std::string& name = caps.channels[setup.channels[i]].name;
        const ChannelPin* ch = nullptr;
        for (const auto& c : kChannels)
            if (name == c.name)
                ch = &c;
        if (!ch)
            return makeError(ErrorCode::BadInput, "scope channel '" + name + "' is not a hal: channel");
        const std::string pin = axis.pid + "." + ch->pin;
        const HalPin* p = findPin(*ps, pin);
        if (!p)
            return makeError(ErrorCode::NotFound, "HAL has no pin " + pin);
        const std::string samplerPin = "sampler.0.pin." + std::to_string(i);
        cfg += 'f';
        if (!p->signal.empty()) {
            links.push_back({"linksp", p->signal, samplerPin});
        } else if (ch->output) {
            // An output on no net: a net of AxisTune's own carries it to the sampler (removed afterwards).
            links.push_back({"net", "axistune-scope-" + std::to_string(i), pin, samplerPin});
        } else {
            return makeError(ErrorCode::BadInput, pin + " is not linked to a net: sampling it would change its value");
        }
    }
    struct Step {
        std::vector<std::string> doArgs;
        std::vector<std::string> undoArgs;
    };
    std::vector<Step> steps = {
        {{"loadrt", "sampler", "depth=" + std::to_string(kSamplerDepth), "cfg=" + cfg}, {"unloadrt", "sampler"}},
        {{"addf", "sampler.0", axis.thread}, {"delf", "sampler.0", axis.thread}},
    };
    for (auto& l : links) {
        std::vector<std::string> undo =
            l.front() == "net" ? std::vector<std::string>{"delsig", l[1]} : std::vector<std::string>{"unlinkp", l[2]};
        steps.push_back({std::move(l), std::move(undo)});
    }
    for (auto& st : steps) {
        auto r = runHalcmd(options, st.doArgs);
        if (!r) {
            (void)s->stop();
            return makeError(ErrorCode::Device,
                             "inserting the scope's sampler failed (nothing left changed): " + r.error().detail);
        }
        s->m_undo.push_back(std::move(st.undoArgs));
    }
    auto client = HalClient::open("axistune-scope-" + std::to_string(::getpid()));
    if (!client) {
        (void)s->stop();
        return client.error();
    }
    s->m_client = std::move(client).value();
    auto stream = HalStream::attach(*s->m_client, HalStream::Direction::FromHal, kSamplerKey, cfg);
    if (!stream) {
        (void)s->stop();
        return stream.error();
    }
    s->m_stream = std::move(stream).value();
    const std::uint64_t ringRows = kHostRingValues / std::max<std::size_t>(setup.channels.size(), 1);
    s->m_recorder.arm(setup, ringRows);
    s->m_thread = std::thread([p = s.get()] { p->read(); });
    return s;
}

void HalScope::read()
{
    std::vector<double> row;
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
            m_recorder.push(sample, row);
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

Status HalScope::stop()
{
    m_stop = true;
    if (m_thread.joinable())
        m_thread.join();
    m_stream.reset();
    Status first;
    bool waited = false;
    while (!m_undo.empty()) {
        auto args = std::move(m_undo.back());
        m_undo.pop_back();
        if (args.front() == "unloadrt" && !waited) {
            // The sampler's function may still run this period: unloading frees its FIFO (HalInjection::remove).
            std::this_thread::sleep_for(
                std::max(std::chrono::nanoseconds(2 * m_axis.periodNs), std::chrono::nanoseconds(20'000'000)));
            waited = true;
        }
        auto r = runHalcmd(m_options, args);
        if (!r && first)
            first = r.error();
    }
    m_client.reset();
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

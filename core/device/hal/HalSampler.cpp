// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/device/hal/HalSampler.h"

#include "core/device/hal/HalText.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>

namespace axistune::device::hal {
namespace {

std::mutex g_mutex;
std::weak_ptr<HalSamplerModule> g_module; ///< guarded by g_mutex

} // namespace

Result<std::shared_ptr<HalSamplerModule>> HalSamplerModule::acquire(const HalSessionOptions& options,
                                                                    std::int64_t periodNs)
{
    std::lock_guard lock(g_mutex);
    if (auto m = g_module.lock()) {
        m->m_periodNs = std::max(m->m_periodNs, periodNs);
        return m;
    }
    auto text = runHalcmd(options, {"-s", "show", "pin", "sampler."});
    if (!text)
        return text.error();
    auto pins = parsePins(*text);
    if (!pins)
        return pins.error();
    if (!pins->empty())
        return makeError(ErrorCode::Busy, "LinuxCNC's sampler is loaded by another program (" + pins->front().name +
                                              " exists): AxisTune's tests and scope need it; unload it first");
    std::string cfg = std::string(kTestSamplerTypes) + "," + std::string(kScopeSamplerTypes);
    auto r =
        runHalcmd(options, {"loadrt", "sampler",
                            "depth=" + std::to_string(kTestSamplerDepth) + "," + std::to_string(kScopeSamplerDepth),
                            "cfg=" + cfg});
    if (!r)
        return makeError(ErrorCode::Device, "loading LinuxCNC's sampler failed: " + r.error().detail);
    std::shared_ptr<HalSamplerModule> m(new HalSamplerModule);
    m->m_options = options;
    m->m_periodNs = periodNs;
    g_module = m;
    return m;
}

bool HalSamplerModule::heldByThisProcess()
{
    std::lock_guard lock(g_mutex);
    return !g_module.expired();
}

HalSamplerModule::~HalSamplerModule()
{
    // Runs when the last holder let go (g_module has expired): its function may still run this period, and
    // unloading frees the FIFO it writes (LinuxCNC's sampler then crashes the servo thread). Wait two periods. An
    // acquire meanwhile waits for the unload, then loads again.
    std::lock_guard lock(g_mutex);
    std::this_thread::sleep_for(
        std::max(std::chrono::nanoseconds(2 * m_periodNs), std::chrono::nanoseconds(20'000'000)));
    (void)runHalcmd(m_options, {"unloadrt", "sampler"});
}

} // namespace axistune::device::hal

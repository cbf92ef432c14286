// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// LinuxCNC's `sampler` as AxisTune loads it (docs/linuxcnc.md "Scope"). LinuxCNC loads a component once per HAL
// session, with all its instances; AxisTune's tests record through one sampler instance and its scope through
// another, and each may start while the other runs. So the component is loaded once with both instances:
//   sampler.0: "fffff" (kTestSamplerTypes), a test's record (HalInjection);
//   sampler.1: kScopeSamplerTypes (12 float, 4 bit, 2 s32, 2 u32 pins), the scope (HalScope), of which a scope
//              links as many of each type as it samples.
// Each user adds its instance's function to the thread and links its pins, and takes them off again; the module is
// unloaded by the last holder, two servo periods after its functions left the threads.

#include "core/device/hal/HalCmd.h"
#include "core/model/Result.h"

#include <cstdint>
#include <memory>

namespace axistune::device::hal {

inline constexpr const char* kTestSamplerTypes = "fffff";
inline constexpr int kTestSamplerDepth = 16384;                           ///< rows of sampler.0's FIFO
inline constexpr const char* kScopeSamplerTypes = "ffffffffffffbbbbssuu"; ///< pins of sampler.1 (20 of HAL's 21)
inline constexpr int kScopeSamplerDepth = 32768; ///< rows of sampler.1's FIFO (33 ms at 1 kHz … 8 ms at 4 kHz)

class HalSamplerModule {
public:
    /// The module this process loaded, or a new load. Refused when a sampler is loaded that this process did not
    /// load (another program's, or one an AxisTune left behind when it died: removeLeftoverInjection takes that).
    /// `periodNs` is the period of the thread the holder will add its function to (the unload waits two of the
    /// longest).
    static Result<std::shared_ptr<HalSamplerModule>> acquire(const HalSessionOptions& options, std::int64_t periodNs);
    /// Whether this process holds the loaded sampler now.
    static bool heldByThisProcess();
    ~HalSamplerModule();
    HalSamplerModule(const HalSamplerModule&) = delete;
    HalSamplerModule& operator=(const HalSamplerModule&) = delete;

private:
    HalSamplerModule() = default;
    HalSessionOptions m_options;
    std::int64_t m_periodNs = 0;
};

} // namespace axistune::device::hal

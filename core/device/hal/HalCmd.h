// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// halcmd as a child process (no shell): how the HAL backend loads components, links nets and sets pins.

#include "core/model/Result.h"

#include <chrono>
#include <span>
#include <string>
#include <vector>

namespace axistune::device::hal {

struct HalSessionOptions {
    /// The halcmd command line prefix. "halcmd" for a HAL session of the same user; the test machine run as
    /// root uses {"scripts/hal-testbed", "halcmd"} so that modules are loaded by the HAL session's user.
    std::vector<std::string> halcmd{"halcmd"};
    std::chrono::milliseconds timeout{10000}; ///< per halcmd call
};

/// Runs halcmd with `args`; returns what it printed on stdout. A non-zero exit, a timeout or a failure to start
/// is a Device error naming the command and quoting halcmd's own message.
Result<std::string> runHalcmd(const HalSessionOptions& options, std::span<const std::string> args);
Result<std::string> runHalcmd(const HalSessionOptions& options, std::initializer_list<std::string> args);

} // namespace axistune::device::hal

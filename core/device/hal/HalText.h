// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Readers of `halcmd -s show pin|sig|thread` (LinuxCNC 2.9, script mode): what the HAL backend needs to
// find a PID's nets and the servo thread, and to check that a test left the HAL as it found it.

#include "core/model/Result.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace axistune::device::hal {

struct HalPin {
    std::string owner; ///< component
    std::string type;  ///< float, bit, s32, u32, port
    std::string dir;   ///< IN, OUT, IO
    std::string value; ///< as halcmd prints it
    std::string name;
    std::string signal; ///< the net it is linked to; empty when unlinked
};

struct HalSignal {
    std::string type;
    std::string value;
    std::string name;
    std::string writer;               ///< the OUT pin driving it; empty when none
    std::vector<std::string> readers; ///< IN pins
};

struct HalThread {
    std::int64_t periodNs = 0;
    std::string name;
    std::vector<std::string> functions; ///< in execution order
};

/// The blank-separated words of one line (blanks: space, tab, carriage return), as halcmd and HAL files split them.
std::vector<std::string> splitWords(std::string_view line);

/// `halcmd -s show pin`: one pin per line "owner type dir value name [==>|<==|<=> signal]".
Result<std::vector<HalPin>> parsePins(std::string_view text);
/// `halcmd -s show sig`: "type value name [<== writer] [==> reader]...".
Result<std::vector<HalSignal>> parseSignals(std::string_view text);
/// `halcmd -s show thread`: "period fp name tmax maxtime function...".
Result<std::vector<HalThread>> parseThreads(std::string_view text);

const HalPin* findPin(const std::vector<HalPin>& pins, std::string_view name);
const HalSignal* findSignal(const std::vector<HalSignal>& halSignals, std::string_view name);

} // namespace axistune::device::hal

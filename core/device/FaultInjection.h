// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Named failure modes of axistune-simdrive for tests (STYLE.md: a mock link with named failure
// modes): "drop-after:N", "delay:MS", "illegal-address", "drive-fault:S". See docs/modbus.md.

#include "core/model/Result.h"

#include <string>
#include <vector>

namespace axistune::device {

struct FaultInjection {
    int dropAfterRequests = 0;    ///< > 0: close each connection when its N-th request arrives
    int delayMs = 0;              ///< > 0: answer every request this late (past the client's timeout)
    bool illegalAddress = false;  ///< parameter registers answer ILLEGAL DATA ADDRESS
    double driveFaultAfterS = -1; ///< >= 0: the drive faults this long (machine time) into a test

    bool any() const { return dropAfterRequests > 0 || delayMs > 0 || illegalAddress || driveFaultAfterS >= 0; }
};

/// Parses one mode into `f`; the error names the mode and the accepted forms.
Status addFaultMode(FaultInjection& f, const std::string& mode);
Result<FaultInjection> parseFaultModes(const std::vector<std::string>& modes);
/// A one-line description of the active modes for the log, e.g. "drop-after:5, delay:1500".
std::string describeFaults(const FaultInjection& f);

} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
// The drive conformance suite (tests/conformance/DriveConformance.h) on hal:, against the repository's LinuxCNC
// test machine (scripts/hal-testbed, started for each rule). Here because the HAL tests run one at a time
// (RESOURCE_LOCK linuxcnc_hal, tests/CMakeLists.txt).
#include "tests/conformance/DriveConformance.h"

namespace axistune::device {
namespace {

INSTANTIATE_TEST_SUITE_P(Backends, DriveConformance, ::testing::Values("hal", "linuxcnc"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

} // namespace
} // namespace axistune::device

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// AxisTune's LinuxCNC test machine for the tests (scripts/hal-testbed, docs/linuxcnc.md): the fixture that starts a
// HAL session under the machine-wide lock, and halcmd helpers.

#include "core/device/hal/HalCmd.h"
#include "core/device/hal/HalText.h"
#include "core/model/Number.h"

#include <chrono>
#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>

#include "tests/linuxcnc/HalMachineLock.h"

namespace axistune::testing {

using device::hal::HalSessionOptions;
using device::hal::parseSignals;
using device::hal::runHalcmd;

inline const std::string kScript = std::string(AXISTUNE_SOURCE_DIR) + "/scripts/hal-testbed";

inline HalSessionOptions halOptions()
{
    HalSessionOptions o;
    o.halcmd = {kScript, "halcmd"};
    o.timeout = std::chrono::seconds(30);
    return o;
}

inline Status runScript(const std::vector<std::string>& args)
{
    HalSessionOptions o;
    o.halcmd = {kScript};
    o.timeout = std::chrono::seconds(180);
    auto r = runHalcmd(o, args);
    if (!r)
        return r.error();
    return {};
}

/// `halcmd -s show sig` without the live values: names, types, writers and readers.
inline std::string netsOf(const std::string& showSig)
{
    auto sigs = parseSignals(showSig);
    EXPECT_TRUE(sigs) << (sigs ? "" : sigs.error().detail);
    std::string out;
    if (sigs)
        for (const auto& s : *sigs) {
            out += s.type + " " + s.name + " <== " + s.writer + " ==>";
            for (const auto& r : s.readers)
                out += " " + r;
            out += "\n";
        }
    return out;
}

inline std::string halText(const std::vector<std::string>& args)
{
    auto r = runHalcmd(halOptions(), args);
    EXPECT_TRUE(r) << (r ? "" : r.error().detail);
    return r ? *r : std::string{};
}

inline double getp(const std::string& name)
{
    const std::string t = halText({"getp", name});
    const auto v = model::parseNumber(t.substr(0, t.find_first_of(" \n")));
    EXPECT_TRUE(v.has_value()) << name << ": '" << t << "'";
    return v.value_or(std::nan(""));
}

class HalTestbed : public ::testing::Test {
protected:
    void startBed(long periodNs)
    {
        if (!m_lock)
            m_lock = std::make_unique<axistune::testing::HalMachineLock>();
        ASSERT_TRUE(m_lock->held()) << "cannot open /tmp/axistune-hal-machine.lock";
        auto st = runScript({"start", "--period", std::to_string(periodNs)});
        ASSERT_TRUE(st) << st.error().detail;
        m_started = true;
    }
    void TearDown() override
    {
        if (m_started)
            (void)runScript({"stop"});
        m_lock.reset();
    }
    bool m_started = false;
    std::unique_ptr<axistune::testing::HalMachineLock> m_lock; ///< held from the start to after the stop
};

} // namespace axistune::testing

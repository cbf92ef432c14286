// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The committed register map read as plain JSON (not through core's loader) and mbpoll, the
// independent Modbus client from Debian, for the end-to-end Modbus tests.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/NumberText.h"
#include "tests/app/cli/CliRunner.h"

namespace axistune::testing {

inline nlohmann::json registerMap()
{
    return nlohmann::json::parse(
        readFileText(std::string(AXISTUNE_TEST_DATA_DIR) + "/../../resources/drives/axistune-sim.json"));
}

inline int parameterAddress(const std::string& key)
{
    const auto map = registerMap();
    for (const auto& p : map["parameters"]) {
        if (p["key"] == key)
            return p["address"].get<int>();
    }
    return -1;
}

/// Runs mbpoll once (1 s timeout) and returns its stdout and stderr.
inline std::string mbpoll(int port, const std::string& args)
{
    const std::string cmd = "mbpoll -m tcp -0 -1 -o 1 -p " + std::to_string(port) + " " + args + " 2>&1";
    std::string out;
    if (FILE* f = popen(cmd.c_str(), "r")) {
        char buf[512];
        while (fgets(buf, sizeof buf, f))
            out += buf;
        pclose(f);
    }
    return out;
}

/// The value mbpoll printed for reference `address` ("[1020]: \t0.8").
inline double mbpollValue(const std::string& out, int address)
{
    const std::string tag = "[" + std::to_string(address) + "]:";
    const auto at = out.find(tag);
    return at == std::string::npos ? std::nan("") : axistune::testutil::stod(out.c_str() + at + tag.size());
}

} // namespace axistune::testing

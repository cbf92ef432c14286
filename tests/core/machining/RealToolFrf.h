// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reads one FRF of ../shared/data/real/tooltip_frf_H11_H15.csv (impact-hammer receptances of a real tool
// holder, m/N, 0–5000 Hz at 1 Hz; see the data's README) for the tests of the tool-mode fit.
#include "core/dsp/FrequencyResponse.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace axistune::testing {

inline const std::string kRealToolFrfCsv = std::string(AXISTUNE_REAL_DATA_DIR) + "/tooltip_frf_H11_H15.csv";

/// Column pair j = 1..5 (H1j); empty on a read error.
inline dsp::FrequencyResponse readRealToolFrf(int j)
{
    dsp::FrequencyResponse frf;
    std::ifstream in(kRealToolFrfCsv);
    std::string line;
    bool header = false;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#')
            continue;
        if (!header) {
            header = true;
            continue;
        }
        std::vector<double> v;
        const char* p = line.data();
        const char* end = line.data() + line.size();
        while (p < end) {
            double d = 0.0;
            auto [q, ec] = std::from_chars(p, end, d);
            if (ec != std::errc())
                return {};
            v.push_back(d);
            p = q < end && *q == ',' ? q + 1 : q;
        }
        if (v.size() != 11)
            return {};
        frf.push(v[0], {v[static_cast<std::size_t>(2 * j - 1)], v[static_cast<std::size_t>(2 * j)]}, std::nan(""),
                 true);
    }
    return frf;
}

} // namespace axistune::testing

// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Helpers for the store tests: temporary folders and deterministic captures.

#include "core/model/Capture.h"
#include "core/model/Metadata.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace axistune::store::testutil {

/// A new folder under the system's temporary folder, removed with its contents when the test process exits (the
/// kill test's stores are about 100 MB each; forked children leave with _exit and remove nothing).
inline std::filesystem::path tempDir(const std::string& tag)
{
    static struct Reaper {
        std::vector<std::filesystem::path> dirs;
        ~Reaper()
        {
            for (const auto& d : dirs) {
                std::error_code ec;
                std::filesystem::remove_all(d, ec);
            }
        }
    } reaper;
    std::string tmpl = (std::filesystem::temp_directory_path() / ("axistune-store-" + tag + "-XXXXXX")).string();
    char* d = mkdtemp(tmpl.data());
    if (!d)
        return std::filesystem::temp_directory_path();
    reaper.dirs.emplace_back(d);
    return reaper.dirs.back();
}

/// Channel k, sample i: sin(0.001*i*(k+1)) + k — every value differs, so a swapped or shifted
/// channel is caught.
inline model::Capture makeCapture(std::size_t channels, std::size_t samples, double seed = 0.0)
{
    model::Capture c;
    c.metadata.set("fs_Hz", 4000.0);
    c.metadata.set("seed", seed);
    for (std::size_t k = 0; k < channels; ++k) {
        model::Channel ch;
        ch.name = "ch" + std::to_string(k) + "_Nm";
        ch.data.resize(samples);
        for (std::size_t i = 0; i < samples; ++i)
            ch.data[i] = std::sin(0.001 * static_cast<double>(i) * static_cast<double>(k + 1) + seed) + static_cast<double>(k);
        c.channels.push_back(std::move(ch));
    }
    return c;
}

}  // namespace axistune::store::testutil

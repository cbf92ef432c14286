// SPDX-License-Identifier: GPL-3.0-or-later
// axistune-fuzz-replay TARGET PATH...: feeds every regular file under each PATH (files or folders,
// recursively) to the fuzz target TARGET, as libFuzzer would. A crash, a sanitizer report or a contract
// violation (tests/fuzz/FuzzTarget.h) aborts; otherwise it prints how many inputs it replayed.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

#include "tests/fuzz/FuzzTarget.h"

namespace axistune::fuzz {
std::map<std::string, TargetFn>& registry()
{
    static std::map<std::string, TargetFn> r;
    return r;
}
} // namespace axistune::fuzz

int main(int argc, char** argv)
{
    namespace fs = std::filesystem;
    using axistune::fuzz::registry;
    if (argc < 2) {
        std::cerr << "usage: axistune-fuzz-replay TARGET PATH...\ntargets:";
        for (const auto& [name, fn] : registry())
            std::cerr << ' ' << name;
        std::cerr << '\n';
        return 2;
    }
    const auto it = registry().find(argv[1]);
    if (it == registry().end()) {
        std::cerr << "axistune-fuzz-replay: no target '" << argv[1] << "'\n";
        return 2;
    }
    std::vector<fs::path> files;
    for (int i = 2; i < argc; ++i) {
        const fs::path p(argv[i]);
        if (fs::is_directory(p)) {
            for (const auto& e : fs::recursive_directory_iterator(p))
                if (e.is_regular_file())
                    files.push_back(e.path());
        } else if (fs::is_regular_file(p)) {
            files.push_back(p);
        } else {
            std::cerr << "axistune-fuzz-replay: " << p << " is neither a file nor a folder\n";
            return 2;
        }
    }
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
        std::ifstream in(f, std::ios::binary);
        std::ostringstream ss;
        ss << in.rdbuf();
        std::cerr << "replay " << f.string() << '\n';
        it->second(ss.str());
    }
    std::cout << argv[1] << ": " << files.size() << " inputs replayed, no crash, every contract held\n";
    return files.empty() ? 1 : 0;
}

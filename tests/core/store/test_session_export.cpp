// SPDX-License-Identifier: GPL-3.0-or-later
// The session summary JSON (core/store/SessionExport.h): capture metadata keep numbers as JSON numbers, and a journal
// entry without an old value says why instead of writing null (docs/formats.md "Undefined values").
#include "core/store/SessionExport.h"
#include "core/store/SessionRecord.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace axistune;

TEST(SessionExport, MetadataNumbersStayNumbersAndAMissingOldValueSaysWhy)
{
    store::SessionRecord rec;
    rec.info.kind = "frf";
    model::Capture cap;
    cap.metadata.set("fs_Hz", 4000.0);
    cap.metadata.set("x", 0.1);
    cap.metadata.set("test", "step");
    cap.channels.push_back({"t_s", {0.0, 0.00025}});
    rec.captures.push_back({"trace", cap});
    store::JournalEntry first;
    first.axis = "X";
    first.key = "velocity.kp";
    first.newValue = 2.0;
    store::JournalEntry second = first;
    second.oldValue = 2.0;
    second.newValue = 2.5;
    rec.journal = {first, second};

    const auto j = store::sessionSummaryJson(rec);
    const auto& meta = j.at("captures").at(0).at("metadata");
    EXPECT_EQ(meta.dump(), R"({"fs_Hz":4000,"test":"step","x":0.1})");
    const auto& journal = j.at("journal");
    ASSERT_EQ(journal.size(), 2u);
    EXPECT_FALSE(journal[0].contains("old"));
    EXPECT_EQ(journal[0].at("undefined").at("old"), "not recorded (not read before this write, or none before it)");
    EXPECT_EQ(journal[1].at("old").get<double>(), 2.0);
    EXPECT_FALSE(journal[1].contains("undefined"));
}

// SPDX-License-Identifier: GPL-3.0-or-later
// The typed metadata keys (core/model/MetadataKeys.h, issue 16 item 6): a key's kind decides what can be set and
// read (checked at compile time with requires-expressions), whole numbers beyond 2^53 keep their digits, every
// catalogue name is spelled once, and no metadata call in core/, app/ or widgets/ spells a catalogue key as a
// literal (the sources are read from AXISTUNE_SOURCE_DIR).
#include "core/model/MetadataKeys.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace axistune::model {
namespace {

// What the kinds allow: a number key takes numbers, a whole-number key integers only (a double would be cut
// silently), a text key texts; a text key is not read as a number, a number key not as a whole number.
template <class K, class V>
concept Settable = requires(Metadata m, K k, V v) { m.set(k, v); };
template <class K>
concept ReadsNumber = requires(const Metadata m, K k) { m.number(k); };
template <class K>
concept ReadsInteger = requires(const Metadata m, K k) { m.integer(k); };

static_assert(Settable<NumberKey, double> && Settable<NumberKey, int>);
static_assert(Settable<IntegerKey, std::uint64_t> && Settable<IntegerKey, int>);
static_assert(Settable<TextKey, const char*> && Settable<TextKey, std::string>);
static_assert(!Settable<NumberKey, std::string> && !Settable<NumberKey, const char*>);
static_assert(!Settable<IntegerKey, double> && !Settable<IntegerKey, bool> && !Settable<IntegerKey, std::string>);
static_assert(!Settable<TextKey, double> && !Settable<TextKey, MetadataValue>);
static_assert(ReadsNumber<NumberKey> && !ReadsNumber<TextKey> && !ReadsNumber<IntegerKey>);
static_assert(ReadsInteger<IntegerKey> && !ReadsInteger<NumberKey> && !ReadsInteger<TextKey>);

TEST(MetadataKeys, TypedKeysSetAndReadTheirKind)
{
    Metadata md;
    md.set(meta::kFsHz, 4000.0);
    md.set(meta::kTest, "step");
    md.set(meta::kNperseg, std::size_t{1024});
    ASSERT_TRUE(md.find(meta::kFsHz)->isNumber());
    EXPECT_EQ(md.number(meta::kFsHz).value(), 4000.0);
    EXPECT_EQ(md.text(meta::kFsHz), "4000"); // the written form, for messages
    EXPECT_EQ(md.text(meta::kTest), "step");
    EXPECT_FALSE(md.find(meta::kTest)->isNumber());
    EXPECT_EQ(md.integer(meta::kNperseg).value(), 1024);
    // The same entries as the names give: a typed key is its name.
    EXPECT_EQ(md.number("fs_Hz").value(), 4000.0);
    EXPECT_EQ(md.textOr("test", ""), "step");
    // A text that spells a number stays text (a file written from it reads back as the same text).
    md.set(meta::kAxis, "4000");
    EXPECT_FALSE(md.find(meta::kAxis)->isNumber());
    // Missing and bad values name the key.
    EXPECT_FALSE(md.contains(meta::kMotionTimeS));
    const auto missing = md.number(meta::kMotionTimeS);
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().detail, "metadata 'motion_time_s' is missing");
    md.setFromText("fs_Hz", "4,0");
    const auto bad = md.number(meta::kFsHz);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().detail, "metadata 'fs_Hz' is not a number ('4,0')");
    EXPECT_TRUE(md.erase(meta::kFsHz));
    EXPECT_FALSE(md.erase(meta::kFsHz));
}

TEST(MetadataKeys, WholeNumbersBeyondTwoToTheFiftyThirdKeepTheirDigits)
{
    Metadata md;
    const std::uint64_t exact = std::uint64_t{1} << 53, beyond = (std::uint64_t{1} << 60) + 1;
    md.set(meta::kSeed, exact);
    EXPECT_TRUE(md.find(meta::kSeed)->isNumber());
    EXPECT_EQ(md.text(meta::kSeed), "9007199254740992");
    md.set(meta::kSeed, beyond); // 1152921504606846977: as a double it would be ...976
    EXPECT_FALSE(md.find(meta::kSeed)->isNumber());
    EXPECT_EQ(md.text(meta::kSeed), "1152921504606846977");
    EXPECT_EQ(md.integer(meta::kSeed).value(), 1152921504606846977LL);
    md.set(meta::kFirstDataLine, -3);
    EXPECT_EQ(md.integer(meta::kFirstDataLine).value(), -3);
}

std::string readAll(const std::filesystem::path& p)
{
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> catalogueNames()
{
    const auto text = readAll(std::filesystem::path(AXISTUNE_SOURCE_DIR) / "core/model/MetadataKeys.h");
    const std::regex key(R"re(inline constexpr (NumberKey|IntegerKey|TextKey) k\w+\{"([^"]+)"\})re");
    std::vector<std::string> names;
    for (std::sregex_iterator it(text.begin(), text.end(), key), end; it != end; ++it)
        names.push_back((*it)[2]);
    return names;
}

TEST(MetadataKeys, EveryCatalogueNameIsSpelledOnce)
{
    const auto names = catalogueNames();
    ASSERT_GE(names.size(), 40u); // the header was read
    EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
    // Spot checks against the formats the keys are documented in (docs/formats.md).
    for (const char* expected : {"fs_Hz", "motion_time_s", "test", "method", "axis", "measurement", "seed"})
        EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
}

TEST(MetadataKeys, NoMetadataCallSpellsACatalogueKeyAsALiteral)
{
    std::string alternatives;
    for (const auto& n : catalogueNames())
        alternatives += (alternatives.empty() ? "" : "|") + n;
    // md.set("fs_Hz", …), cap.metadata.number("fs_Hz"), m_trace->metadata.find("machine"), …
    const std::regex literal(
        R"re((\bmd|metadata)(\.|->)(set|number|optionalNumber|integer|text|textOr|contains|find|erase)\("()re" +
        alternatives + R"re()")re");
    // The pattern finds what it is for, and not a JSON key or a typed call.
    ASSERT_TRUE(std::regex_search(std::string(R"(    cap.metadata.set("fs_Hz", 1.0 / t);)"), literal));
    ASSERT_TRUE(std::regex_search(std::string(R"(if (const auto* v = md.find("machine")))"), literal));
    ASSERT_TRUE(std::regex_search(std::string(R"(m_trace->metadata.number("motion_time_s"))"), literal));
    ASSERT_FALSE(std::regex_search(std::string(R"(j.set("fs_Hz", 1.0);)"), literal));
    ASSERT_FALSE(std::regex_search(std::string(R"(md.set(model::meta::kFsHz, 1.0);)"), literal));
    ASSERT_FALSE(std::regex_search(std::string(R"(md.set("fs_Hz_raw", 1.0);)"), literal));
    std::vector<std::string> found;
    std::size_t files = 0;
    for (const char* dir : {"core", "app", "widgets"}) {
        for (const auto& e :
             std::filesystem::recursive_directory_iterator(std::filesystem::path(AXISTUNE_SOURCE_DIR) / dir)) {
            const auto ext = e.path().extension();
            if (!e.is_regular_file() || (ext != ".cpp" && ext != ".h"))
                continue;
            ++files;
            std::istringstream in(readAll(e.path()));
            std::string line;
            for (int n = 1; std::getline(in, line); ++n)
                if (std::regex_search(line, literal))
                    found.push_back(e.path().lexically_relative(AXISTUNE_SOURCE_DIR).string() + ":" +
                                    std::to_string(n) + ": " + line);
        }
    }
    EXPECT_GT(files, 300u); // the tree was read
    std::string list;
    for (const auto& f : found)
        list += f + "\n";
    EXPECT_TRUE(found.empty()) << "use the constants of core/model/MetadataKeys.h:\n" << list;
}

} // namespace
} // namespace axistune::model

// SPDX-License-Identifier: GPL-3.0-or-later
// What the wizard's choice page asks of core before a tune (core/autotune/TravelChoice.h; docs/tuning.md "The
// wizard"): the travel window and unit of a linear axis the drive can position (sim:long-axis X: +-0.75 m, the
// preset's travel, docs/simulator.md "Long axis"), the refusal of a rotary preset axis without a travel window
// (checkCanMoveTo's reason), the choices that cannot run together, the amplitude list's text, the default budget.
#include "core/autotune/AmplitudeMap.h"
#include "core/autotune/TravelChoice.h"
#include "core/device/MoveTo.h"

#include <gtest/gtest.h>

using namespace axistune;

TEST(TravelChoice, LongAxisHasItsTravelWindowInMetres)
{
    auto d = device::connect({"sim:long-axis", 1});
    ASSERT_TRUE(d.ok());
    auto t = autotune::travelChoice(**d, "X");
    ASSERT_TRUE(t.ok()) << t.error().detail;
    EXPECT_TRUE(t->refusal.empty()) << t->refusal;
    EXPECT_EQ(t->window, 0.75); // the preset's stated window, passed through unchanged
    EXPECT_EQ(t->units, "m");
}

TEST(TravelChoice, RotaryPresetAxisIsRefusedWithTheSequencesReason)
{
    auto d = device::connect({"sim:dd-table", 1});
    ASSERT_TRUE(d.ok());
    auto t = autotune::travelChoice(**d, "C");
    ASSERT_TRUE(t.ok()) << t.error().detail;
    const auto why = device::checkCanMoveTo(**d, "C");
    ASSERT_FALSE(why.ok());
    EXPECT_EQ(t->refusal, why.error().detail);
    EXPECT_FALSE(autotune::travelChoice(**d, "Q").ok()); // an axis the drive does not have
}

TEST(TravelChoice, ChoicesThatCannotRunTogetherAreRefused)
{
    autotune::Options o;
    o.axis = "X";
    EXPECT_TRUE(autotune::checkChoices(o).ok());
    o.amplitudeMapPct = {5.0, 10.0, 20.0};
    EXPECT_TRUE(autotune::checkChoices(o).ok());
    o.positions = 3;
    auto st = autotune::checkChoices(o);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::BadInput);
    EXPECT_NE(st.error().detail.find("one position"), std::string::npos);
    o.positions = 1;
    o.amplitudeMapPct = {5.0, 10.0};
    st = autotune::checkChoices(o);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().detail.find(autotune::checkAmplitudeList(o.amplitudeMapPct).error().detail),
              std::string::npos);
    o.amplitudeMapPct.clear();
    o.positions = 0;
    EXPECT_FALSE(autotune::checkChoices(o).ok());
    o.positions = 2;
    o.timeBudgetS = 0.0;
    EXPECT_FALSE(autotune::checkChoices(o).ok());
    o.timeBudgetS = 10.0;
    o.minBandwidthHz = -1.0;
    EXPECT_FALSE(autotune::checkChoices(o).ok());
    o.minBandwidthHz = 0.0;
    o.motor = tuning::MotorData{};
    EXPECT_FALSE(autotune::checkChoices(o).ok());
}

TEST(TravelChoice, AmplitudeListText)
{
    auto a = autotune::parseAmplitudeList(" 5, 10 ,20\t40 ");
    ASSERT_TRUE(a.ok());
    EXPECT_EQ(*a, (std::vector<double>{5.0, 10.0, 20.0, 40.0}));
    EXPECT_TRUE(autotune::parseAmplitudeList("")->empty());
    EXPECT_TRUE(autotune::parseAmplitudeList(" , ")->empty());
    auto bad = autotune::parseAmplitudeList("5, ten, 20");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().detail.find("'ten'"), std::string::npos);
    EXPECT_FALSE(autotune::parseAmplitudeList("5, 1e400").ok()); // not finite
    EXPECT_EQ(autotune::defaultTimeBudgetS(1), 30.0);
    EXPECT_EQ(autotune::defaultTimeBudgetS(3), 90.0);
}

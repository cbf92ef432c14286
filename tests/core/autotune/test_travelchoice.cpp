// SPDX-License-Identifier: GPL-3.0-or-later
// What the wizard's choice page asks of core before a tune (core/autotune/TravelChoice.h; docs/tuning.md "The
// wizard"): the travel window and unit of a linear axis the drive can position (sim:long-axis X: +-0.75 m, the
// preset's travel, docs/simulator.md "Long axis"), the refusal of a rotary preset axis without a travel window
// (checkCanMoveTo's reason), the choices that cannot run together, the amplitude list's text, the default budget.
#include "core/autotune/AmplitudeMap.h"
#include "core/autotune/TravelChoice.h"
#include "core/device/MoveTo.h"

#include <cmath>
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
    // The positions' inset: the jog speed 0.5 m/s over the preset's position gain 30 1/s
    // (resources/machines/long-axis.json), by hand 1/60 m.
    EXPECT_NEAR(t->inset, 0.5 / 30.0, 1e-15);
}

TEST(TravelChoice, PositionsStayInsideTheWindowByTheMovesServoLag)
{
    // v/K_p: 0.5 m/s (linear) or 2 rad/s (rotary) over K_p, by hand.
    EXPECT_DOUBLE_EQ(autotune::positionsInset(true, 30.0), 0.5 / 30.0);
    EXPECT_DOUBLE_EQ(autotune::positionsInset(false, 40.0), 2.0 / 40.0);
    EXPECT_TRUE(std::isnan(autotune::positionsInset(true, 0.0)));
    EXPECT_TRUE(std::isnan(autotune::positionsInset(true, std::nan(""))));
    // Evenly over -(W - inset) ... +(W - inset): W = 0.75, inset 0.05 → -0.7, -0.35, 0, 0.35, 0.7.
    auto xs = autotune::positionsOverTravel(0.75, 0.05, 5);
    ASSERT_TRUE(xs.ok());
    const double want[] = {-0.7, -0.35, 0.0, 0.35, 0.7};
    ASSERT_EQ(xs->size(), 5u);
    for (std::size_t i = 0; i < 5; ++i)
        EXPECT_NEAR((*xs)[i], want[i], 1e-15);
    // No room: refused naming the window and the inset; a NaN inset (no position gain) is refused too.
    auto none = autotune::positionsOverTravel(0.01, 0.0167, 3);
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().code, ErrorCode::BadInput);
    EXPECT_NE(none.error().detail.find("0.01"), std::string::npos) << none.error().detail;
    EXPECT_NE(none.error().detail.find("0.0167"), std::string::npos) << none.error().detail;
    EXPECT_FALSE(autotune::positionsOverTravel(0.75, std::nan(""), 3).ok());
    EXPECT_FALSE(autotune::positionsOverTravel(0.75, 0.01, 1).ok());
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

// SPDX-License-Identifier: GPL-3.0-or-later
// The FRF step's refusals (core/autotune/AutoTuneSequence.h frfRefusal) on counts written by hand: "strong
// non-linearity" above 20 % of the lines flagged non-linear, "coherence too low" below 60 % valid, the first before
// the second. No preset variant reaches 20 % non-linear lines in the adaptive FRF's best try (docs/tuning.md "Strong
// non-linearity"), so the rule is tested here on its own.
#include "core/autotune/AutoTuneSequence.h"

#include <gtest/gtest.h>

using axistune::autotune::detail::FrfFigures;
using axistune::autotune::detail::frfRefusal;

namespace {

FrfFigures figures(std::size_t lines, std::size_t valid, std::size_t nonlinear)
{
    FrfFigures f;
    f.lines = lines;
    f.valid = valid;
    f.nonlinear = nonlinear;
    return f;
}

bool starts(const std::optional<std::string>& why, const std::string& head)
{
    return why && why->rfind(head, 0) == 0;
}

} // namespace

TEST(FrfRefusal, MoreThanAFifthNonLinearIsStrongNonLinearity)
{
    // 388 lines: 20 % is 77.6. 77 non-linear passes, 78 is refused, naming the counts.
    EXPECT_FALSE(frfRefusal(figures(388, 300, 77)));
    const auto why = frfRefusal(figures(388, 300, 78));
    ASSERT_TRUE(starts(why, "strong non-linearity: 78 of 388 FRF lines")) << why.value_or("(none)");
    EXPECT_NE(why->find("more than 20 %"), std::string::npos) << *why;
}

TEST(FrfRefusal, FewerThanSixtyPercentValidIsCoherenceTooLow)
{
    // 60 % of 388 is 232.8: 233 valid passes, 232 is refused.
    EXPECT_FALSE(frfRefusal(figures(388, 233, 0)));
    const auto why = frfRefusal(figures(388, 232, 0));
    ASSERT_TRUE(starts(why, "coherence too low: only 232 of 388 FRF lines are valid")) << why.value_or("(none)");
    EXPECT_NE(why->find("at least 60 %"), std::string::npos) << *why;
}

TEST(FrfRefusal, NonLinearityIsNamedBeforeLowCoherenceAndAnEmptyFrfIsRefused)
{
    // Both rules broken: the non-linearity is the reason (the lines it flags are also invalid).
    EXPECT_TRUE(starts(frfRefusal(figures(388, 100, 200)), "strong non-linearity"));
    // No lines: nothing is valid.
    EXPECT_TRUE(starts(frfRefusal(figures(0, 0, 0)), "coherence too low"));
}

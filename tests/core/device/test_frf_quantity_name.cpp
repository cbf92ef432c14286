// SPDX-License-Identifier: GPL-3.0-or-later
// The one spelling of the FRF quantities (core/device/FrfQuantityName.h): the `quantity` metadata of FRF files and
// sessions and the CLI's --quantity use these texts (docs/cli.md, docs/linuxcnc.md), so they are pinned here; the
// inverse takes back exactly them. The NC PID page once wrote "open_loop" beside hal:'s "open-loop".
#include "core/device/FrfQuantityName.h"

#include <gtest/gtest.h>

namespace axistune::device {
namespace {

TEST(FrfQuantityName, OneSpellingEachAndItsInverse)
{
    EXPECT_EQ(frfQuantityMetadataName(FrfQuantity::Default), "default");
    EXPECT_EQ(frfQuantityMetadataName(FrfQuantity::Plant), "plant");
    EXPECT_EQ(frfQuantityMetadataName(FrfQuantity::OpenLoop), "open-loop");
    for (const auto q : {FrfQuantity::Default, FrfQuantity::Plant, FrfQuantity::OpenLoop})
        EXPECT_EQ(frfQuantityFromMetadataName(frfQuantityMetadataName(q)), q);
    for (const char* other : {"open_loop", "Plant", "", "open loop", "plant "})
        EXPECT_FALSE(frfQuantityFromMetadataName(other).has_value()) << other;
}

} // namespace
} // namespace axistune::device

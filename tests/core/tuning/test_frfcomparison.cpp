// SPDX-License-Identifier: GPL-3.0-or-later
// tuning::compareMagnitudes / peakMagnitudeDb against hand-computed values.
#include "core/tuning/FrfComparison.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace axistune;

namespace {
dsp::FrequencyResponse fromDb(const std::vector<double>& f, const std::vector<double>& db, const std::vector<bool>& valid = {})
{
    dsp::FrequencyResponse r;
    for (std::size_t i = 0; i < f.size(); ++i)
        r.push(f[i], std::polar(std::pow(10.0, db[i] / 20.0), 0.3), std::nan(""), valid.empty() ? true : valid[i]);
    return r;
}
}  // namespace

TEST(FrfComparison, InterpolatesInLogFrequencyAndFindsTheLargestDeviation)
{
    // Reference: 0 dB at 100 Hz, -20 dB at 1000 Hz -> at 316.23 Hz (half way in log f) -10 dB.
    const auto ref = fromDb({100, 1000}, {0, -20});
    const auto meas = fromDb({100, std::sqrt(1e5), 1000}, {0.5, -10.0 + 2.0, -20.25});
    const auto d = tuning::compareMagnitudes(ref, meas, -50.0);
    ASSERT_EQ(d.points, 3u);
    EXPECT_NEAR(d.maxAbsDb, 2.0, 1e-9);
    EXPECT_NEAR(d.maxAtHz, std::sqrt(1e5), 1e-9);
    EXPECT_NEAR(d.rmsDb, std::sqrt((0.25 + 4.0 + 0.0625) / 3.0), 1e-9);
    EXPECT_DOUBLE_EQ(d.fminHz, 100.0);
    EXPECT_DOUBLE_EQ(d.fmaxHz, 1000.0);
}

TEST(FrfComparison, InvalidOutsideAndBelowTheFloorAreNotCompared)
{
    // The reference's invalid middle point is bridged (interpolation between 100 and 1000 Hz);
    // the measurement's invalid point, a point outside the reference's range and a point where both
    // are below the floor are skipped.
    const auto ref = fromDb({100, 300, 1000, 2000}, {0, 40, -20, -80}, {true, false, true, true});
    const auto meas = fromDb({50, 200, 500, 1900, 3000}, {0, 7, 99, -79, 0}, {true, true, false, true, true});
    const auto d = tuning::compareMagnitudes(ref, meas, -50.0);
    ASSERT_EQ(d.points, 1u);
    const double refAt200 = -20.0 * std::log10(2.0);  // 0 dB + (-20 dB/decade)·log10(2)
    EXPECT_NEAR(d.maxAbsDb, 7.0 - refAt200, 1e-9);
    EXPECT_TRUE(std::isnan(tuning::compareMagnitudes(ref, fromDb({5000}, {0}), -50.0).maxAbsDb));
}

TEST(FrfComparison, PeakWithinTheRelativeBand)
{
    const auto r = fromDb({90, 95, 100, 104, 111}, {1, 3, 9, 12, 30}, {true, true, true, true, true});
    EXPECT_NEAR(tuning::peakMagnitudeDb(r, 100.0, 0.05), 12.0, 1e-9);   // 95..105 Hz
    EXPECT_NEAR(tuning::peakMagnitudeDb(r, 100.0, 0.011), 9.0, 1e-9);   // 98.9..101.1 Hz
    EXPECT_TRUE(std::isnan(tuning::peakMagnitudeDb(r, 200.0, 0.05)));
}

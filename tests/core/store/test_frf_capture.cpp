// SPDX-License-Identifier: GPL-3.0-or-later
// A frequency response survives the session layout (content=frf capture) unchanged.
#include "core/store/FrfCapture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

using namespace axistune;

TEST(FrfCapture, RoundTripKeepsEveryPointCoherenceValidityAndMetadata)
{
    dsp::FrequencyResponse frf;
    frf.metadata.set("method", "multisweep");
    for (int i = 0; i < 50; ++i) {
        const double f = 10.0 * std::pow(1.1, i);
        const std::complex<double> s(0.0, 2.0 * std::numbers::pi * f);
        const std::complex<double> h = 1.0 / (1.0 + s / 200.0);  // first-order low-pass
        frf.push(f, h, i % 2 ? std::nan("") : 0.5, i < 40);
    }
    const auto cap = store::frfAsCapture(frf);
    EXPECT_TRUE(store::isFrfCapture(cap));
    // The stored magnitude column is the analytic |h| in dB.
    const double f10 = frf.freqHz[10];
    const double w = 2.0 * std::numbers::pi * f10 / 200.0;
    EXPECT_NEAR(cap.channel("mag_dB")->data[10], -10.0 * std::log10(1.0 + w * w), 1e-12);
    auto back = store::frfFromCapture(cap);
    ASSERT_TRUE(back) << back.error().detail;
    ASSERT_EQ(back->size(), frf.size());
    for (std::size_t i = 0; i < frf.size(); ++i) {
        EXPECT_EQ(back->freqHz[i], frf.freqHz[i]);
        EXPECT_EQ(back->h[i], frf.h[i]);
        EXPECT_EQ(back->valid[i], frf.valid[i]);
        EXPECT_EQ(std::isnan(back->coherence[i]), std::isnan(frf.coherence[i]));
    }
    EXPECT_EQ(back->metadata.text("method"), "multisweep");
    EXPECT_FALSE(back->metadata.contains("content"));
}

TEST(FrfCapture, MissingOrUnequalChannelsAreNamedErrors)
{
    model::Capture c;
    c.metadata.set("content", "frf");
    c.channels = {{"f_Hz", {1.0, 2.0}}, {"re", {1.0, 2.0}}};
    auto r = store::frfFromCapture(c);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().detail.find("'im'"), std::string::npos);
    c.channels.push_back({"im", {1.0}});
    r = store::frfFromCapture(c);
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().detail.find("different lengths"), std::string::npos);
}

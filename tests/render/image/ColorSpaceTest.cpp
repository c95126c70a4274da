#include "render/image/ColorSpace.hpp"

#include <gtest/gtest.h>

namespace speculum::render {
namespace {

TEST(ColorSpace, KnownValues) {
    EXPECT_FLOAT_EQ(linearToSrgb(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(linearToSrgb(1.0f), 1.0f);
    // Linear segment near black.
    EXPECT_FLOAT_EQ(linearToSrgb(0.001f), 0.01292f);
    EXPECT_FLOAT_EQ(srgbToLinear(0.04f), 0.04f / 12.92f);
    // Mid grey: 18% reflectance is about 46% encoded; 0.5 encoded is about 21.4% linear.
    EXPECT_NEAR(linearToSrgb(0.18f), 0.4613f, 1e-4f);
    EXPECT_NEAR(srgbToLinear(0.5f), 0.21404f, 1e-5f);
}

TEST(ColorSpace, ContinuousAtTheSegmentJoin) {
    EXPECT_NEAR(linearToSrgb(0.0031308f), linearToSrgb(0.0031309f), 2e-6f); // slope 12.92
    EXPECT_NEAR(srgbToLinear(0.04045f), srgbToLinear(0.040451f), 1e-6f);
}

TEST(ColorSpace, RoundTripIsIdentity) {
    for (int i = 0; i <= 1000; ++i) {
        const float x = i / 1000.0f;
        EXPECT_NEAR(srgbToLinear(linearToSrgb(x)), x, 2e-6f) << x;
        EXPECT_NEAR(linearToSrgb(srgbToLinear(x)), x, 2e-6f) << x;
    }
}

TEST(ColorSpace, EveryEightBitCodeSurvivesARoundTrip) {
    for (int code = 0; code < 256; ++code) {
        EXPECT_EQ(linearToSrgb8(srgb8ToLinear(static_cast<std::uint8_t>(code))), code);
    }
}

TEST(ColorSpace, QuantisationClampsAndRounds) {
    EXPECT_EQ(toUnorm8(-0.5f), 0);
    EXPECT_EQ(toUnorm8(2.0f), 255);
    EXPECT_EQ(toUnorm8(0.5f / 255.0f + 1e-4f), 1);
    EXPECT_EQ(toUnorm8(0.5f / 255.0f - 1e-4f), 0);
    EXPECT_EQ(linearToSrgb8(7.0f), 255);
    EXPECT_EQ(linearToSrgb8(std::numeric_limits<float>::quiet_NaN()), 0);
}

} // namespace
} // namespace speculum::render

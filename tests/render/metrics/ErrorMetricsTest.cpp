// Error metrics on images whose errors are known by construction.
#include "render/metrics/ErrorMetrics.hpp"

#include "render/image/ColorSpace.hpp"
#include "render/imageio/TextureLoader.hpp"
#include "render/reference/IdBuffer.hpp"
#include "support/TestPaths.hpp"

#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace speculum::test {
namespace {

using namespace render::metrics;

render::Image uniform(int w, int h, float value) {
    render::Image image;
    image.width = w;
    image.height = h;
    image.rgba.assign(static_cast<std::size_t>(w) * h * 4, value);
    for (std::size_t i = 3; i < image.rgba.size(); i += 4)
        image.rgba[i] = 1.0f;
    return image;
}

TEST(ErrorMetrics, RmseAndPsnrOfAUniformOffset) {
    const auto a = uniform(4, 3, 0.5f), b = uniform(4, 3, 0.6f);
    auto linear = compare(a, b, nullptr, Encoding::Linear);
    ASSERT_TRUE(linear.ok());
    EXPECT_NEAR(linear->rmse, 0.1, 1e-6);
    EXPECT_NEAR(linear->psnr, 20.0, 1e-4);
    EXPECT_EQ(linear->pixels, 12u);
    auto srgb = compare(a, b);
    ASSERT_TRUE(srgb.ok());
    const double d = render::linearToSrgb(0.6f) - render::linearToSrgb(0.5f);
    EXPECT_NEAR(srgb->rmse, d, 1e-6);
    EXPECT_NEAR(srgb->psnr, -20.0 * std::log10(d), 1e-4);
}

TEST(ErrorMetrics, ErrorInOnePixelOfFourAndMasks) {
    auto a = uniform(2, 2, 0.0f);
    const auto b = uniform(2, 2, 0.0f);
    a.rgba[(1 * 2 + 1) * 4 + 0] = 0.6f; // pixel (1,1), red only
    auto all = compare(a, b, nullptr, Encoding::Linear);
    ASSERT_TRUE(all.ok());
    EXPECT_NEAR(all->rmse, std::sqrt(0.36 / 12.0), 1e-6);
    EXPECT_NEAR(all->maxError, std::sqrt(0.36 / 3.0), 1e-6);
    const std::vector<std::uint8_t> onlyBad = {0, 0, 0, 1}, onlyGood = {1, 1, 1, 0};
    auto bad = compare(a, b, &onlyBad, Encoding::Linear);
    EXPECT_NEAR(bad->rmse, std::sqrt(0.36 / 3.0), 1e-6);
    EXPECT_EQ(bad->pixels, 1u);
    auto good = compare(a, b, &onlyGood, Encoding::Linear);
    EXPECT_EQ(good->rmse, 0.0);
    EXPECT_EQ(good->psnr, kMaxPsnr);
    const std::vector<std::uint8_t> none(4, 0);
    auto empty = compare(a, b, &none);
    EXPECT_EQ(empty->pixels, 0u);
    EXPECT_EQ(empty->psnr, kMaxPsnr);
}

TEST(ErrorMetrics, MismatchesAreErrorsAndNaNCountsAsZero) {
    EXPECT_FALSE(compare(uniform(2, 2, 0), uniform(2, 3, 0)).ok());
    const std::vector<std::uint8_t> shortMask(3, 1);
    EXPECT_FALSE(compare(uniform(2, 2, 0), uniform(2, 2, 0), &shortMask).ok());
    EXPECT_FALSE(absoluteDifference(uniform(1, 2, 0), uniform(2, 1, 0)).ok());
    auto a = uniform(1, 1, 0.0f);
    a.rgba[0] = std::nanf("");
    auto s = compare(a, uniform(1, 1, 0.0f));
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->rmse, 0.0);
}

TEST(ErrorMetrics, DifferenceImageAndColourMap) {
    auto a = uniform(3, 1, 0.0f);
    const auto b = uniform(3, 1, 0.0f);
    a.rgba[4 + 1] = 0.1f; // pixel 1: small error in green
    a.rgba[8 + 0] = 1.0f; // pixel 2: full error
    auto diff = absoluteDifference(a, b, Encoding::Linear);
    ASSERT_TRUE(diff.ok());
    EXPECT_FLOAT_EQ(diff->rgba[4 + 1], 0.1f);
    EXPECT_FLOAT_EQ(diff->rgba[3], 1.0f);
    const render::Image map = errorColorMap(*diff);
    EXPECT_EQ(map.at(0, 0), glm::vec4(0, 0, 0, 1)); // no error: black
    const glm::dvec3 top = errorRamp(1.0);
    EXPECT_NEAR(map.at(2, 0).r, top.r, 1e-6); // beyond full scale: the top colour
    EXPECT_NEAR(map.at(2, 0).b, top.b, 1e-6);
    // Brightness rises along the ramp.
    double previous = -1.0;
    for (int i = 0; i <= 20; ++i) {
        const glm::dvec3 c = errorRamp(i / 20.0);
        const double luminance = glm::dot(c, glm::dvec3(0.2126, 0.7152, 0.0722));
        EXPECT_GT(luminance, previous) << i;
        previous = luminance;
    }
}

TEST(ErrorMetrics, ErrorMapIsWrittenAsAnImage) {
    auto a = uniform(8, 8, 0.2f);
    const auto b = uniform(8, 8, 0.25f);
    auto diff = absoluteDifference(a, b);
    ASSERT_TRUE(diff.ok());
    const std::string path = speculum::testDataPath("error_map_test.png");
    std::filesystem::remove(path);
    ASSERT_TRUE(writeErrorMap(path, *diff).ok());
    auto loaded = render::loadTexture(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_EQ(loaded->width, 8);
    EXPECT_EQ(loaded->height, 8);
}

TEST(ErrorMetrics, AnglesBetweenDirections) {
    EXPECT_NEAR(angleBetween({1, 0, 0}, {0, 2, 0}), M_PI / 2, 1e-12);
    EXPECT_NEAR(angleBetween({1, 0, 0}, {-3, 0, 0}), M_PI, 1e-12);
    EXPECT_NEAR(angleBetween({1, 0, 0}, {1, 1e-9, 0}), 1e-9, 1e-15); // acos would give 0 here
    EXPECT_EQ(angleBetween({0, 0, 0}, {1, 0, 0}), 0.0);
    auto stats = angularError({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{1, 0, 0}, {1, 1, 0}, {0, 0, 1}});
    ASSERT_TRUE(stats.ok());
    EXPECT_NEAR(stats->maxDegrees, 45.0, 1e-9);
    EXPECT_NEAR(stats->meanDegrees, 15.0, 1e-9);
    EXPECT_NEAR(stats->rmsDegrees, std::sqrt(45.0 * 45.0 / 3.0), 1e-9);
    EXPECT_FALSE(angularError({{1, 0, 0}}, {}).ok());
}

TEST(ErrorMetrics, MasksFromIdBuffers) {
    using render::reference::HitKind;
    render::reference::IdBuffer ids;
    ids.width = 3;
    ids.height = 1;
    ids.ids = {{HitKind::Mirror, 0}, {HitKind::Reflector, 0}, {HitKind::MirrorBack, 1}};
    EXPECT_EQ(render::reference::mirrorMask(ids), (std::vector<std::uint8_t>{1, 0, 0}));
    EXPECT_EQ(render::reference::reflectorMask(ids), (std::vector<std::uint8_t>{0, 1, 0}));
}

} // namespace
} // namespace speculum::test

#include "tools/marble/Marble.hpp"

#include "render/imageio/TextureLoader.hpp"
#include "support/TestPaths.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <gtest/gtest.h>
#include <string>

namespace speculum::render {
namespace {

// The seed the committed texture was made with (see tools/make_marble.cpp).
constexpr std::uint32_t kCommittedSeed = 7;

// Rec. 709 weights on the encoded bytes: a perceptual brightness, good enough for a histogram.
double brightness(const TextureImage& image, int x, int y) {
    const std::uint8_t* p = &image.rgba8[(static_cast<std::size_t>(y) * image.width + x) * 4];
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

TEST(Marble, SameSeedGivesTheSameImage) {
    const TextureImage a = generateMarble(128, 42);
    const TextureImage b = generateMarble(128, 42);
    EXPECT_EQ(a.rgba8, b.rgba8);
}

TEST(Marble, DifferentSeedsGiveDifferentImages) {
    EXPECT_NE(generateMarble(64, 1).rgba8, generateMarble(64, 2).rgba8);
}

TEST(Marble, IsOpaqueRgbaOfTheRequestedSize) {
    const TextureImage marble = generateMarble(96, 3);
    ASSERT_EQ(marble.width, 96);
    ASSERT_EQ(marble.height, 96);
    ASSERT_EQ(marble.rgba8.size(), 96u * 96u * 4u);
    for (std::size_t i = 3; i < marble.rgba8.size(); i += 4) {
        ASSERT_EQ(marble.rgba8[i], 255);
    }
}

TEST(Marble, IsMostlyWhiteWithSomeDarkVeins) {
    for (std::uint32_t seed : {1u, 7u, 1234567u}) {
        const TextureImage marble = generateMarble(256, seed);
        int bright = 0;
        int veins = 0;
        double sum = 0.0;
        double darkest = 255.0;
        double maxChroma = 0.0;
        for (int y = 0; y < marble.height; ++y) {
            for (int x = 0; x < marble.width; ++x) {
                const double b = brightness(marble, x, y);
                sum += b;
                bright += b > 200.0;
                veins += b < 190.0;
                darkest = std::min(darkest, b);
                const std::uint8_t* p = &marble.rgba8[(static_cast<std::size_t>(y) * marble.width + x) * 4];
                maxChroma =
                    std::max(maxChroma, double(std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]})));
            }
        }
        const double pixels = marble.width * marble.height;
        EXPECT_GT(sum / pixels, 200.0) << "seed " << seed << ": marble should be light overall";
        EXPECT_GT(bright / pixels, 0.8) << "seed " << seed;
        EXPECT_GT(veins / pixels, 0.01) << "seed " << seed << ": there should be visible veins";
        EXPECT_LT(veins / pixels, 0.15) << "seed " << seed << ": veins should not dominate";
        EXPECT_LT(darkest, 140.0) << "seed " << seed << ": vein cores should be clearly grey";
        EXPECT_LT(maxChroma, 16.0) << "seed " << seed << ": white and grey stone, not coloured";
    }
}

TEST(Marble, TilesSeamlessly) {
    // Across the wrap-around edge the image changes no more than between neighbouring interior columns.
    const TextureImage marble = generateMarble(256, 7);
    auto columnStep = [&](int x0, int x1) {
        double sum = 0.0;
        for (int y = 0; y < marble.height; ++y) {
            sum += std::abs(brightness(marble, x0, y) - brightness(marble, x1, y));
        }
        return sum / marble.height;
    };
    auto rowStep = [&](int y0, int y1) {
        double sum = 0.0;
        for (int x = 0; x < marble.width; ++x) {
            sum += std::abs(brightness(marble, x, y0) - brightness(marble, x, y1));
        }
        return sum / marble.width;
    };
    double interiorColumns = 0.0;
    double interiorRows = 0.0;
    for (int i = 1; i < 255; ++i) {
        interiorColumns += columnStep(i, i + 1);
        interiorRows += rowStep(i, i + 1);
    }
    interiorColumns /= 254.0;
    interiorRows /= 254.0;
    EXPECT_LT(columnStep(255, 0), 2.0 * interiorColumns + 0.5);
    EXPECT_LT(rowStep(255, 0), 2.0 * interiorRows + 0.5);
}

TEST(Marble, CommittedTextureMatchesTheGenerator) {
    const std::string path = speculum::testSourcePath("resources/scenes/textures/marble.png");
    const base::Result<TextureImage> committed = loadTexture(path);
    ASSERT_TRUE(committed.ok()) << committed.error();
    const TextureImage generated = generateMarble(512, kCommittedSeed);
    ASSERT_EQ(committed->width, 512);
    ASSERT_EQ(committed->height, 512);
    // The file holds the generator's row 0 at its top (writeImage writes rows top first); the loader
    // returns the file's bottom row first (TextureImage), so the rows compare turned over.
    std::size_t differing = 0;
    const std::size_t row = 512u * 4u;
    for (std::size_t i = 0; i < generated.rgba8.size(); ++i) {
        const std::size_t y = i / row, rest = i % row;
        differing += committed->rgba8[(511 - y) * row + rest] != generated.rgba8[i];
    }
    EXPECT_EQ(differing, 0u) << "regenerate with: speculum-make-marble " << path << " --size 512 --seed "
                             << kCommittedSeed;
}

} // namespace
} // namespace speculum::render

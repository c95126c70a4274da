// Stills in tiles: a still larger than a tile renders tile by tile, each tile a window of the whole
// image's view, and gives the pixels of the untiled still; progress counts tiles × samples and cancel
// stops between them; sizes beyond the GPU's limits render; absurd sizes are refused before any work.
#include "scene/evaluate/Snapshot.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/GlTest.hpp"
#include "support/TestPaths.hpp"

#include <algorithm>
#include <cmath>

namespace speculum::test {
namespace {

using namespace render;

// The demo room with two facing stencil mirrors and a texture mirror, and its ball made the curved
// reflector: nested mirror views of both techniques and an environment map in one frame. The texture
// mirror's blur is off (see the blur test below).
FrameInput mirrorsAndReflector() {
    scene::Scene scene;
    std::vector<std::string> warnings;
    EXPECT_TRUE(
        scene::openProject(
            scene, QString::fromStdString(speculum::testSourcePath("resources/scenes/mirrors.speculum.json")),
            warnings)
            .ok());
    scene::MeshLibrary meshes;
    std::vector<scene::Warning> snapshotWarnings;
    FrameInput input = scene::snapshot(scene, 0.25, meshes, snapshotWarnings);
    for (Mirror& mirror : input.mirrors)
        mirror.roughness = 0.0;
    const auto ball = std::find_if(input.items.begin(), input.items.end(),
                                   [](const DrawItem& item) { return item.name == "Ball"; });
    EXPECT_NE(ball, input.items.end());
    Reflector reflector;
    reflector.name = ball->name;
    reflector.world = ball->world;
    reflector.mesh = ball->mesh;
    reflector.material = ball->material;
    reflector.map = ReflectorMap::DualParaboloid;
    reflector.resolution = 128;
    reflector.reflectivity = 0.8;
    input.reflectors = {reflector};
    input.items.erase(ball);
    return input;
}

struct Difference {
    double maximum = 0.0;
    double mean = 0.0;
    std::size_t over = 0; // channel values differing by more than the threshold
};

Difference compare(const Image& a, const Image& b, double threshold) {
    Difference d;
    EXPECT_EQ(a.rgba.size(), b.rgba.size());
    for (std::size_t i = 0; i < std::min(a.rgba.size(), b.rgba.size()); ++i) {
        const double diff = std::abs(double(a.rgba[i]) - double(b.rgba[i]));
        d.maximum = std::max(d.maximum, diff);
        d.mean += diff;
        d.over += diff > threshold ? 1 : 0;
    }
    d.mean /= double(std::max<std::size_t>(a.rgba.size(), 1));
    return d;
}

bool ran(const FrameReport& report, PassKind kind) {
    return report.countRan(kind) > 0;
}

TEST_F(GlTest, StillInSmallTilesMatchesTheUntiledStill) {
    const FrameInput input = mirrorsAndReflector();
    for (int ssaa : {1, 2}) {
        SCOPED_TRACE("ssaa " + std::to_string(ssaa));
        // An odd size that no tile divides: edge tiles reach past the image.
        auto whole = renderStill(renderer(), input, {301, 173, ssaa});
        auto tiled = renderStill(renderer(), input, {301, 173, ssaa, 64});
        ASSERT_TRUE(whole.ok()) << whole.error();
        ASSERT_TRUE(tiled.ok()) << tiled.error();
        EXPECT_EQ(whole->tiles, 1);
        EXPECT_EQ(tiled->tiles, 5 * 3);
        ASSERT_EQ(tiled->image.width, 301);
        ASSERT_EQ(tiled->image.height, 173);
        // The scene does what it is meant to test: nested mirror views and the environment map (rendered
        // by the first still, reused after).
        EXPECT_TRUE(ran(whole->firstSample, PassKind::Mirror));
        EXPECT_GE(whole->firstSample.plan.views.size(), 3u);
        if (ssaa == 1) {
            EXPECT_TRUE(ran(whole->firstSample, PassKind::Envmap));
        }

        // Same sample positions, same plan, same depth: the only difference left is float rounding of
        // vertex positions in the tile's clip space. It can move a triangle edge across a sample that lies
        // within a rounding error of it, so a few channel values may differ fully; nearly all must agree
        // to half-float precision (the linear buffer's, 2⁻¹¹ relative).
        const Difference d = compare(whole->image, tiled->image, 2e-3);
        const std::size_t values = whole->image.rgba.size();
        std::printf("[ tiles    ] ssaa %d: %zu of %zu values differ by more than 2e-3, max %.4f, mean %.2e\n",
                    ssaa, d.over, values, d.maximum, d.mean);
        EXPECT_LE(d.over, values / 2000) << "more than 0.05% of the values differ";
        EXPECT_LT(d.mean, 1e-4);
    }
}

// The texture technique's blur reads a mip level of the mirror's reflection texture, which a tile holds
// only its own part of: near tile borders a blurred reflection cannot see past the tile. It stays close,
// not equal.
TEST_F(GlTest, BlurredTextureMirrorInTilesStaysClose) {
    FrameInput input = mirrorsAndReflector();
    for (Mirror& mirror : input.mirrors)
        if (mirror.technique == MirrorTechnique::Texture)
            mirror.roughness = 0.15;
    auto whole = renderStill(renderer(), input, {301, 173, 1});
    auto tiled = renderStill(renderer(), input, {301, 173, 1, 64});
    ASSERT_TRUE(whole.ok() && tiled.ok());
    const Difference d = compare(whole->image, tiled->image, 2e-3);
    EXPECT_LT(d.mean, 5e-3);
}

TEST_F(GlTest, TiledStillReportsProgressPerTileAndSampleAndCancels) {
    const FrameInput input = mirrorsAndReflector();
    std::vector<std::pair<double, std::string>> calls;
    auto still =
        renderStill(renderer(), input, {130, 70, 2, 64}, [&](double fraction, const std::string& stage) {
            calls.emplace_back(fraction, stage);
            return true;
        });
    ASSERT_TRUE(still.ok()) << still.error();
    ASSERT_EQ(still->tiles, 3 * 2);
    ASSERT_EQ(calls.size(), 3u * 2u * 4u + 1u); // before every sample of every tile, and when done
    EXPECT_EQ(calls.front().second, "tile 1/6, sample 1/4");
    EXPECT_EQ(calls[5].second, "tile 2/6, sample 2/4");
    EXPECT_EQ(calls.back().first, 1.0);
    for (std::size_t i = 1; i < calls.size(); ++i)
        EXPECT_GT(calls[i].first, calls[i - 1].first);

    int seen = 0;
    auto cancelled = renderStill(renderer(), input, {130, 70, 2, 64},
                                 [&](double, const std::string&) { return ++seen < 6; });
    ASSERT_FALSE(cancelled.ok());
    EXPECT_NE(cancelled.error().find("cancelled"), std::string::npos);
    EXPECT_EQ(seen, 6) << "stops at the first refusal";
}

TEST_F(GlTest, StillWiderThanTheGpuLimitRendersInTiles) {
    const int limit = maxStillSize();
    ASSERT_GT(limit, 0);
    FrameInput input = mirrorsAndReflector();
    input.camera.fovY = 2.0; // the panorama stays a recognisable picture, not a smear
    auto still = renderStill(renderer(), input, {limit + 16, 8, 1});
    ASSERT_TRUE(still.ok()) << still.error();
    EXPECT_EQ(still->image.width, limit + 16);
    EXPECT_GT(still->tiles, 1);
    // Every column was written (the buffer starts zeroed; a rendered pixel has alpha 1).
    for (int x = 0; x < still->image.width; ++x)
        ASSERT_EQ(still->image.at(x, 4).a, 1.0f) << "column " << x;
}

TEST_F(GlTest, AbsurdStillSizeIsRefusedBeforeAnyAllocation) {
    auto still = renderStill(renderer(), mirrorsAndReflector(), {1000000, 1000000, 1});
    ASSERT_FALSE(still.ok());
    EXPECT_NE(still.error().find("1000000x1000000"), std::string::npos) << still.error();
    EXPECT_NE(still.error().find("GiB"), std::string::npos) << still.error();
}

} // namespace
} // namespace speculum::test

// Tiles of an image, without GL: a tile's projection puts every point on the tile's pixel that the
// image's projection puts it on, at the same depth; restricting a plan to a tile keeps the image's
// decisions and drops only the mirror views that have no pixel in the tile.
#include "render/math/Mirror.hpp"
#include "render/math/Projection.hpp"
#include "render/plan/Planner.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace speculum::render {
namespace {

// Window coordinates (pixels, y up) and depth of a clip-space point on a width × height target.
glm::dvec3 window(const glm::dvec4& clip, int width, int height) {
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    return {(ndc.x + 1.0) * 0.5 * width, (ndc.y + 1.0) * 0.5 * height, ndc.z};
}

TEST(TileProjection, PutsPointsOnTheSamePixelsOfTheTileAtTheSameDepth) {
    const glm::dmat4 image =
        math::jitter(math::perspective(60.0, 301.0 / 173.0, 0.1, 50.0), 0.25, -0.25, 301, 173);
    // A tile reaching past the image's top-right corner and one starting left of and below it.
    for (const glm::ivec4& tile : {glm::ivec4(248, 116, 62, 58), glm::ivec4(-10, -6, 64, 40)}) {
        const glm::dmat4 cropped = math::tileProjection(image, tile.x, tile.y, tile.z, tile.w, 301, 173);
        for (const glm::dvec4& p : {glm::dvec4(0.3, -0.2, -2.0, 1.0), glm::dvec4(-4.0, 1.5, -9.0, 1.0),
                                    glm::dvec4(0.01, 0.02, -0.5, 1.0)}) {
            const glm::dvec3 a = window(image * p, 301, 173);
            const glm::dvec3 b = window(cropped * p, tile.z, tile.w);
            EXPECT_NEAR(b.x, a.x - tile.x, 1e-9);
            EXPECT_NEAR(b.y, a.y - tile.y, 1e-9);
            EXPECT_DOUBLE_EQ(b.z, a.z);
        }
    }
    EXPECT_EQ(math::tileProjection(image, 0, 0, 301, 173, 301, 173), image) << "the whole image: unchanged";
}

// Two mirrors side by side, camera at the origin looking down −Z: one on the left half, one on the right.
FrameInput twoMirrors() {
    FrameInput input;
    input.camera.position = {0, 0, 0};
    input.camera.target = {0, 0, -1};
    input.camera.far = 100.0;
    for (double x : {-1.5, 1.5}) {
        Mirror m;
        m.name = x < 0 ? "Left" : "Right";
        m.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(x, 0, -4)), glm::radians(90.0),
                              glm::dvec3(1, 0, 0));
        input.mirrors.push_back(m);
    }
    return input;
}

int passesFor(const FramePlan& plan, const std::string& target) {
    return static_cast<int>(std::count_if(plan.passes.begin(), plan.passes.end(),
                                          [&](const PlannedPass& p) { return p.target == target; }));
}

TEST(TilePlan, KeepsTheImagesDecisionsAndDropsViewsOutsideTheTile) {
    const FrameInput input = twoMirrors();
    const PlanViewport image{640, 360};
    const FramePlan whole = planFrame(input, {}, image);
    ASSERT_EQ(whole.views.size(), 2u);
    const math::PixelRect left = whole.views[0].rect;
    ASSERT_LT(left.x1, 320) << "the left mirror lies in the left half";

    FramePlan tile = whole;
    restrictToTile(tile, {0, 100, 320, 300}, image);
    ASSERT_EQ(tile.views.size(), 2u) << "view indices stay valid";
    EXPECT_EQ(passesFor(tile, "Left"), passesFor(whole, "Left"));
    EXPECT_EQ(passesFor(tile, "Right"), 0) << "no pixel of the right mirror in the left tile";
    EXPECT_EQ(tile.skipped.size(), whole.skipped.size()) << "nothing new is reported skipped";
    // The left mirror's pixels, clipped to the tile and counted from its corner.
    EXPECT_EQ(tile.views[0].rect.x0, left.x0);
    EXPECT_EQ(tile.views[0].rect.y0, std::max(left.y0, 100) - 100);
    EXPECT_EQ(tile.views[0].rect.y1, std::min(left.y1, 300) - 100);
    EXPECT_EQ(tile.views[0].pixelArea, whole.views[0].pixelArea);
    EXPECT_EQ(tile.views[0].projection,
              math::tileProjection(whole.views[0].projection, 0, 100, 320, 200, 640, 360));
}

} // namespace
} // namespace speculum::render

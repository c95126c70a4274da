// Which mirrors get passes, without any GL: each skip has its reason.
#include "PlanScenes.hpp"
#include "render/math/Mirror.hpp"
#include "render/plan/Planner.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace speculum::render {
namespace {

constexpr PlanViewport kViewport{640, 360};

using test::cameraAtOrigin;
using test::wall;

std::string skipReason(const FramePlan& plan, const std::string& target) {
    for (const auto& s : plan.skipped)
        if (s.target == target)
            return s.reason;
    return {};
}

int passesFor(const FramePlan& plan, const std::string& target) {
    int n = 0;
    for (const auto& p : plan.passes)
        n += p.target == target;
    return n;
}

TEST(MirrorPlanner, AVisibleMirrorGetsMaskMirrorAndSurfacePassesInOrder) {
    FrameInput input = cameraAtOrigin();
    input.mirrors = {wall("Wall", -3.0)};
    const FramePlan plan = planFrame(input, {}, kViewport);
    std::vector<PassKind> kinds;
    for (const auto& p : plan.passes)
        kinds.push_back(p.kind);
    EXPECT_EQ(kinds, (std::vector{PassKind::Main, PassKind::MirrorMask, PassKind::Mirror,
                                  PassKind::MirrorSurface, PassKind::Composite}));
    ASSERT_EQ(plan.views.size(), 1u);
    EXPECT_EQ(plan.views[0].depth, 1);
    EXPECT_EQ(plan.views[0].stencilLevel, 1);
    EXPECT_NEAR(plan.views[0].eye.z, -6.0, 1e-12);
    EXPECT_TRUE(skipReason(plan, "Wall").empty());
}

TEST(MirrorPlanner, SkipsWithReasons) {
    struct Case {
        const char* what;
        Mirror mirror;
        const char* reason;
    };
    const std::vector<Case> cases = {
        {"behind the camera", wall("M", 3.0, false), "outside the view"},
        {"facing away", wall("M", -3.0, false), "behind the mirror"},
        {"camera on its plane",
         [] {
             Mirror m = wall("M", -3.0);
             m.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -3)), glm::radians(90.0),
                                   glm::dvec3(0, 0, 1)); // the plane x = 0 contains the camera
             return m;
         }(),
         "on the mirror's plane"},
        {"far away and tiny", wall("M", -90.0, true, 0.05), "less than one pixel"},
        {"collapsed",
         [] {
             Mirror m = wall("M", -3.0);
             m.world = glm::scale(m.world, glm::dvec3(0, 1, 1));
             return m;
         }(),
         "zero area"},
    };
    for (const Case& c : cases) {
        FrameInput input = cameraAtOrigin();
        input.mirrors = {c.mirror};
        const FramePlan plan = planFrame(input, {}, kViewport);
        EXPECT_TRUE(plan.views.empty()) << c.what;
        EXPECT_EQ(passesFor(plan, "M"), 0) << c.what;
        EXPECT_NE(skipReason(plan, "M").find(c.reason), std::string::npos)
            << c.what << ": " << skipReason(plan, "M");
    }
}

TEST(MirrorPlanner, NearlyEdgeOnMirrorIsSkippedOrFiniteNeverNan) {
    for (double angle : {89.0, 89.99, 89.9999, 90.0}) {
        FrameInput input = cameraAtOrigin();
        Mirror m = wall("M", -3.0);
        // Tilt the mirror about X until its plane contains the view direction.
        m.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0, -0.5, -3)),
                              glm::radians(90.0 - angle), glm::dvec3(1, 0, 0));
        input.mirrors = {m};
        const FramePlan plan = planFrame(input, {}, kViewport);
        for (const auto& v : plan.views)
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) {
                    ASSERT_TRUE(std::isfinite(v.projection[c][r])) << angle;
                }
        if (plan.views.empty()) {
            EXPECT_FALSE(skipReason(plan, "M").empty()) << angle;
        }
    }
}

TEST(MirrorPlanner, FacingMirrorsNestToTheDepthLimitAndSayWhereItStopped) {
    FrameInput input = cameraAtOrigin();
    input.camera.position = {0.3, 0.2, -1.0};
    input.camera.target = {0, 0, -3};
    input.mirrors = {wall("Front", -3.0, true, 4.0), wall("Back", 1.0, false, 4.0)};
    input.settings.mirrorDepth = 5;
    const FramePlan plan = planFrame(input, {}, kViewport);
    int deepest = 0;
    for (const auto& v : plan.views) {
        deepest = std::max(deepest, v.depth);
        EXPECT_EQ(v.stencilLevel, v.depth);
        if (v.parent >= 0) {
            const auto& parent = plan.views[static_cast<std::size_t>(v.parent)];
            EXPECT_NE(parent.mirror, v.mirror) << "a mirror never sees itself";
            EXPECT_GE(v.rect.x0, parent.rect.x0);
            EXPECT_LE(v.rect.x1, parent.rect.x1) << "each level within its parent's pixels";
            EXPECT_LE(v.pixelArea, parent.pixelArea + 1e-6);
        }
    }
    EXPECT_EQ(deepest, 5);
    bool limit = false;
    for (const auto& s : plan.skipped)
        limit |= s.reason.find("depth limit (5)") != std::string::npos;
    EXPECT_TRUE(limit);
    input.settings.mirrorDepth = 0;
    EXPECT_TRUE(planFrame(input, {}, kViewport).views.empty());
}

TEST(MirrorPlanner, TextureMirrorsRenderIntoTheirOwnTextureAndNestFromAFreshStencil) {
    FrameInput input = cameraAtOrigin();
    input.camera.position = {0.3, 0.2, -1.0};
    input.camera.target = {0, 0, -3};
    Mirror front = wall("Front", -3.0, true, 4.0);
    front.technique = MirrorTechnique::Texture;
    input.mirrors = {front, wall("Back", 1.0, false, 4.0)};
    input.settings.mirrorDepth = 3;
    const FramePlan plan = planFrame(input, {}, kViewport);
    ASSERT_GE(plan.views.size(), 3u);
    const MirrorView& first = plan.views[0];
    EXPECT_TRUE(first.ownTarget);
    EXPECT_EQ(first.textureSlot, 0);
    EXPECT_EQ(first.stencilLevel, 0);
    const MirrorView& second = plan.views[1];
    EXPECT_EQ(second.parent, 0);
    EXPECT_FALSE(second.ownTarget);
    EXPECT_EQ(second.textureSlot, 0) << "drawn inside the first mirror's texture";
    EXPECT_EQ(second.stencilLevel, 1);
    const MirrorView& third = plan.views[2];
    EXPECT_TRUE(third.ownTarget);
    EXPECT_EQ(third.textureSlot, 1) << "a texture view inside a texture view needs another texture";
}

TEST(MirrorPlanner, MirrorOnlyVisibleThroughAnotherIsCulledOutsideItsReflectedView) {
    FrameInput input = cameraAtOrigin();
    // A small mirror off to the side behind the camera: not in the view, and not in the reflected view of
    // the wall in front either (the wall reflects what is behind the camera near the view axis only).
    Mirror side = wall("Side", 2.0, false, 0.2);
    side.world = glm::translate(glm::dmat4(1.0), glm::dvec3(40, 0, 0)) * side.world;
    input.mirrors = {wall("Wall", -3.0), side};
    const FramePlan plan = planFrame(input, {}, kViewport);
    ASSERT_EQ(plan.views.size(), 1u);
    EXPECT_NE(skipReason(plan, "Side").find("outside"), std::string::npos) << skipReason(plan, "Side");
}

} // namespace
} // namespace speculum::render

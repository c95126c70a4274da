// Which mirrors get passes, without any GL: each skip has its reason code.
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

// The target's skip; nullptr when the plan has none for it.
const SkippedEffect* skipOf(const FramePlan& plan, const std::string& target) {
    for (const auto& s : plan.skipped)
        if (s.target == target)
            return &s;
    return nullptr;
}

int passesFor(const FramePlan& plan, const std::string& target) {
    int n = 0;
    for (const auto& p : plan.passes)
        n += p.target == target;
    return n;
}

// An 8-bit output that can hold the camera's buffer itself (an sRGB target with depth and stencil) takes the
// passes directly: the composite is not planned, and the plan says why. A blend that needs radiance above 1
// (a stencil mirror whose weight varies over it: Fresnel) keeps the half-float buffer and its composite; one
// with a constant weight is drawn pre-weighted, and nested ones multiply their weights.
TEST(MirrorPlanner, AnOutputThatHoldsTheCameraBufferNeedsNoComposite) {
    FrameInput input = cameraAtOrigin();
    input.mirrors = {wall("Wall", -3.0)};
    input.mirrors[0].technique = MirrorTechnique::Stencil;
    input.mirrors[0].reflectivity = 1.0;
    PlanViewport direct{640, 360};
    direct.eightBitOutput = true;
    direct.outputTakesCameraBuffer = true;
    const FramePlan plan = planFrame(input, {}, direct);
    EXPECT_EQ(plan.cameraBuffer, CameraBuffer::Srgb8);
    EXPECT_TRUE(plan.cameraBufferIsOutput);
    for (const auto& p : plan.passes) {
        EXPECT_NE(p.kind, PassKind::Composite);
        EXPECT_NE(p.writes.target, PassTarget::Output)
            << toString(p.kind) << ": the camera's buffer is the output";
    }
    ASSERT_NE(skipOf(plan, "output"), nullptr);
    EXPECT_EQ(skipOf(plan, "output")->code, PlanReason::CompositeNotNeeded);
    EXPECT_EQ(plan.passes.front().code, PlanReason::MainIntoOutput);

    input.mirrors[0].reflectivity = 0.5;
    const FramePlan weighted = planFrame(input, {}, direct);
    EXPECT_TRUE(weighted.preWeighted) << "a constant weight: the reflection is drawn pre-weighted";
    EXPECT_TRUE(weighted.cameraBufferIsOutput);
    ASSERT_EQ(weighted.views.size(), 1u);
    EXPECT_EQ(weighted.views[0].weight, glm::dvec3(0.5));

    input.mirrors[0].fresnel = true; // a weight that varies over the mirror
    const FramePlan blended = planFrame(input, {}, direct);
    EXPECT_EQ(blended.cameraBuffer, CameraBuffer::HalfFloat);
    EXPECT_FALSE(blended.cameraBufferIsOutput);
    EXPECT_FALSE(blended.preWeighted);
    EXPECT_EQ(blended.views[0].weight, glm::dvec3(1.0));
    EXPECT_EQ(blended.passes.back().code, PlanReason::CompositeFresnelBlend);
    EXPECT_EQ(blended.passes.back().details.node, "Wall");
    EXPECT_EQ(blended.passes.back().kind, PassKind::Composite);
    EXPECT_EQ(skipOf(blended, "output"), nullptr);
}

TEST(MirrorPlanner, NestedStencilMirrorsMultiplyTheirWeights) {
    FrameInput input = cameraAtOrigin();
    input.settings.mirrorDepth = 3;
    input.mirrors = {wall("Front", -3.0), wall("Back", 3.0, false)};
    for (Mirror& m : input.mirrors)
        m.technique = MirrorTechnique::Stencil;
    input.mirrors[0].reflectivity = 1.0; // a perfect mirror adds no surface of its own
    input.mirrors[0].tint = {1.0, 0.5, 0.25};
    input.mirrors[1].reflectivity = 0.5;
    input.mirrors[1].tint = {0.8, 0.9, 1.0};
    PlanViewport eightBit{640, 360};
    eightBit.eightBitOutput = true;
    const FramePlan plan = planFrame(input, {}, eightBit);
    EXPECT_TRUE(plan.preWeighted);
    EXPECT_EQ(plan.cameraBuffer, CameraBuffer::Srgb8);
    ASSERT_GE(plan.views.size(), 2u);
    for (const MirrorView& view : plan.views) {
        glm::dvec3 expected(1.0);
        for (int v = static_cast<int>(&view - plan.views.data()); v >= 0;
             v = plan.views[static_cast<std::size_t>(v)].parent) {
            const Mirror& m =
                input.mirrors[static_cast<std::size_t>(plan.views[static_cast<std::size_t>(v)].mirror)];
            expected *= m.reflectivity * m.tint;
        }
        EXPECT_LT(glm::length(view.weight - expected), 1e-12) << "view at depth " << view.depth;
    }

    // Two that both add their surfaces: 8 bits would round a pixel seen through both twice.
    input.mirrors[0].reflectivity = 0.8;
    const FramePlan both = planFrame(input, {}, eightBit);
    EXPECT_FALSE(both.preWeighted);
    EXPECT_EQ(both.cameraBuffer, CameraBuffer::HalfFloat);
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
    EXPECT_EQ(skipOf(plan, "Wall"), nullptr);
}

TEST(MirrorPlanner, SkipsWithReasons) {
    struct Case {
        const char* what;
        Mirror mirror;
        PlanReason code;
    };
    const std::vector<Case> cases = {
        {"behind the camera", wall("M", 3.0, false), PlanReason::MirrorOutsideView},
        {"facing away", wall("M", -3.0, false), PlanReason::MirrorBehind},
        {"camera on its plane",
         [] {
             Mirror m = wall("M", -3.0);
             m.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -3)), glm::radians(90.0),
                                   glm::dvec3(0, 0, 1)); // the plane x = 0 contains the camera
             return m;
         }(),
         PlanReason::MirrorEdgeOn},
        {"far away and tiny", wall("M", -90.0, true, 0.05), PlanReason::MirrorBelowPixel},
        {"collapsed",
         [] {
             Mirror m = wall("M", -3.0);
             m.world = glm::scale(m.world, glm::dvec3(0, 1, 1));
             return m;
         }(),
         PlanReason::MirrorNoPlane},
    };
    for (const Case& c : cases) {
        FrameInput input = cameraAtOrigin();
        input.mirrors = {c.mirror};
        const FramePlan plan = planFrame(input, {}, kViewport);
        EXPECT_TRUE(plan.views.empty()) << c.what;
        EXPECT_EQ(passesFor(plan, "M"), 0) << c.what;
        ASSERT_NE(skipOf(plan, "M"), nullptr) << c.what;
        EXPECT_EQ(skipOf(plan, "M")->code, c.code) << c.what << ": " << skipOf(plan, "M")->reason();
    }
}

TEST(MirrorPlanner, ASkipSaysWhyAndWhereTheMirrorIsSeen) {
    FrameInput input = cameraAtOrigin();
    input.mirrors = {wall("M", -3.0, false)};
    const FramePlan plan = planFrame(input, {}, kViewport);
    ASSERT_NE(skipOf(plan, "M"), nullptr);
    EXPECT_EQ(skipOf(plan, "M")->reason(),
              "no reflection: the camera is behind the mirror (it sees its back) (seen "
              "directly)");
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
            EXPECT_NE(skipOf(plan, "M"), nullptr) << angle;
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
        limit |= s.code == PlanReason::MirrorDepthLimit && s.details.limit == 5;
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

// Simulate only what is needed, for glossy too: a slightly rough mirror seen inside another mirror takes
// the convolved chain instead of the footprint's taps (its error is bounded up to roughness 0.3), and says
// so; seen directly and large, or rougher, it keeps the taps the settings ask for.
TEST(MirrorPlanner, ARoughMirrorSeenInsideAnotherTakesTheCheaperChainAndSaysWhy) {
    FrameInput input = cameraAtOrigin();
    input.camera.position = {0.3, 0.2, -1.0};
    input.camera.target = {0, 0, -3};
    Mirror front = wall("Front", -3.0, true, 4.0);
    front.roughness = 0.2;
    input.mirrors = {front, wall("Back", 1.0, false, 4.0)};
    input.settings.mirrorDepth = 3;
    input.settings.glossyFilter = GlossyFilter::Footprint;
    auto frontViews = [](const FramePlan& plan) {
        std::vector<const MirrorView*> out;
        for (const MirrorView& v : plan.views)
            if (v.mirror == 0)
                out.push_back(&v);
        return out;
    };
    const FramePlan plan = planFrame(input, {}, kViewport);
    const std::vector<const MirrorView*> views = frontViews(plan);
    ASSERT_GE(views.size(), 2u);
    EXPECT_EQ(views[0]->depth, 1);
    EXPECT_GT(views[0]->pixelArea, 4096.0);
    EXPECT_EQ(views[0]->glossyFilter, GlossyFilter::Footprint) << "seen directly, large: the taps";
    EXPECT_EQ(views[1]->depth, 3);
    EXPECT_EQ(views[1]->glossyFilter, GlossyFilter::Chain) << "seen inside another mirror: the chain";
    bool said = false, convolves = false;
    for (const PlannedPass& pass : plan.passes) {
        if (pass.kind != PassKind::MirrorSurface ||
            plan.views[std::size_t(pass.view)].glossyFilter != GlossyFilter::Chain)
            continue;
        said |=
            pass.reason().find("instead of 16 taps a pixel: seen inside another mirror") != std::string::npos;
        convolves |= pass.writes.convolveMips;
    }
    EXPECT_TRUE(said);
    EXPECT_TRUE(convolves) << "the chain is built as Gaussian levels";
    // Rougher than the chain's error is known for: the taps everywhere.
    input.mirrors[0].roughness = 0.6;
    const FramePlan rougher = planFrame(input, {}, kViewport); // the views point into it: keep it alive
    for (const MirrorView* v : frontViews(rougher))
        EXPECT_EQ(v->glossyFilter, GlossyFilter::Footprint);
    // The cheap filter asked for is kept as it is.
    input.mirrors[0].roughness = 0.2;
    input.settings.glossyFilter = GlossyFilter::Mip;
    const FramePlan cheap = planFrame(input, {}, kViewport);
    for (const MirrorView* v : frontViews(cheap))
        EXPECT_EQ(v->glossyFilter, GlossyFilter::Mip);
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
    bool outsideWall = false, outsideView = false;
    for (const SkippedEffect& s : plan.skipped) {
        if (s.target != "Side")
            continue;
        outsideWall |=
            s.code == PlanReason::MirrorOutsideParent && s.details.seenIn == std::vector<std::string>{"Wall"};
        outsideView |= s.code == PlanReason::MirrorOutsideView && s.details.seenIn.empty();
    }
    EXPECT_TRUE(outsideWall) << "outside the wall's reflected view";
    EXPECT_TRUE(outsideView) << "outside the camera's view";
}

} // namespace
} // namespace speculum::render

namespace speculum::render {
namespace {

// A screen-space mirror seen directly traces the camera's image: its passes come after every other
// mirror's, after one depth pyramid, with the buffer kept in half float; seen inside another mirror it is
// drawn as a texture mirror, and says so. Without one, nothing of it is planned.
TEST(MirrorPlanner, AScreenSpaceMirrorTracesAfterEveryOtherMirrorOnlyWhereTheCameraSeesIt) {
    using test::passOf;
    FrameInput input = cameraAtOrigin();
    input.camera.position = {0.3, 0.2, -1.0};
    input.camera.target = {0, 0, -3};
    input.mirrors = {wall("Front", -3.0, true, 4.0), wall("Back", 1.0, false, 4.0)};
    input.settings.mirrorDepth = 2;
    PlanViewport eightBit = kViewport;
    eightBit.eightBitOutput = true;
    eightBit.outputTakesCameraBuffer = true;
    EXPECT_EQ(passOf(planFrame(input, {}, eightBit), PassKind::ScreenDepth), nullptr);

    input.mirrors[0].technique = MirrorTechnique::ScreenSpace;
    const FramePlan plan = planFrame(input, {}, eightBit);
    std::size_t depthPass = plan.passes.size(), lastOther = 0, trace = 0;
    int pyramids = 0;
    for (std::size_t i = 0; i < plan.passes.size(); ++i) {
        const PlannedPass& pass = plan.passes[i];
        if (pass.kind == PassKind::ScreenDepth) {
            depthPass = std::min(depthPass, i);
            ++pyramids;
            EXPECT_NE(pass.reason().find("Front"), std::string::npos) << pass.reason();
        }
        if (pass.code == PlanReason::MirrorScreenTrace)
            trace = i;
        if (pass.view >= 0 && !plan.views[static_cast<std::size_t>(pass.view)].screenSpace)
            lastOther = i;
    }
    EXPECT_EQ(pyramids, 1);
    EXPECT_LT(lastOther, depthPass) << "every other mirror is in the image before the trace";
    EXPECT_LT(depthPass, trace);
    EXPECT_EQ(plan.cameraBuffer, CameraBuffer::HalfFloat) << "the trace reads linear radiance";
    const PlannedPass* composite = passOf(plan, PassKind::Composite);
    ASSERT_NE(composite, nullptr);
    EXPECT_EQ(composite->code, PlanReason::CompositeScreenSpace);
    int traced = 0;
    for (std::size_t v = 0; v < plan.views.size(); ++v) {
        if (!plan.views[v].screenSpace)
            continue;
        ++traced;
        EXPECT_EQ(plan.views[v].depth, 1);
        for (const MirrorView& inside : plan.views)
            EXPECT_NE(inside.parent, int(v)) << "nothing is planned inside a traced mirror";
    }
    EXPECT_EQ(traced, 1);

    // The back mirror, behind the camera, is seen only inside the front one: drawn as a texture mirror,
    // which its pass says, and nothing is traced.
    input.mirrors[0].technique = MirrorTechnique::Stencil;
    input.mirrors[1].technique = MirrorTechnique::ScreenSpace;
    const FramePlan nested = planFrame(input, {}, eightBit);
    EXPECT_EQ(passOf(nested, PassKind::ScreenDepth), nullptr);
    bool said = false;
    for (const PlannedPass& pass : nested.passes)
        if (pass.kind == PassKind::Mirror && pass.target == "Back") {
            EXPECT_TRUE(nested.views[static_cast<std::size_t>(pass.view)].ownTarget);
            said |= pass.reason().find("screen space asked") != std::string::npos;
        }
    EXPECT_TRUE(said);
}

} // namespace
} // namespace speculum::render

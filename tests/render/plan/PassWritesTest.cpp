// How each planned pass writes (PassWrites) and each shadowed light's one frustum (ShadowPlan), decided by
// the planner without GL: the renderer only carries them out. Links the core library only.
#include "PlanScenes.hpp"
#include "render/frame/SceneLimits.hpp"
#include "render/math/ShadowFrustum.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <vector>

namespace speculum::render {
namespace {

constexpr PlanViewport kViewport{640, 360};

using test::cameraAtOrigin;
using test::wall;

// Two mirrors facing each other, the camera between them looking at the front one: the back one is seen
// in it (depth 2), the front one in that (depth 3), and so on to mirrorDepth.
FrameInput facingMirrors(int depth, MirrorTechnique front = MirrorTechnique::Stencil, double blur = 0.0) {
    FrameInput input = cameraAtOrigin();
    input.camera.position = {0.3, 0.2, -1.0};
    input.camera.target = {0, 0, -3};
    Mirror f = wall("Front", -3.0, true, 4.0);
    f.technique = front;
    f.roughness = blur;
    input.mirrors = {f, wall("Back", 1.0, false, 4.0)};
    input.settings.mirrorDepth = depth;
    return input;
}

FrameInput litScene() {
    FrameInput input;
    auto box = std::make_shared<const MeshData>(makeBox());
    auto plane = std::make_shared<const MeshData>(makePlane(1));
    input.items.push_back({"Box", glm::translate(glm::dmat4(1.0), glm::dvec3(0, 1, 0)), box, {}, true});
    input.items.push_back({"Floor", glm::scale(glm::dmat4(1.0), glm::dvec3(5, 1, 5)), plane, {}, true});
    Light lamp;
    lamp.name = "Lamp";
    lamp.position = {0, 4, 0};
    lamp.shadows = ShadowParams{};
    lamp.shadows->pcf = 3;
    input.lights.push_back(lamp);
    Light off; // lights without shadows: no ShadowPlan
    off.name = "Fill";
    off.position = {2, 3, 1};
    input.lights.push_back(off);
    Light spot;
    spot.name = "Spot";
    spot.type = LightType::Spot;
    spot.position = {3, 5, 2};
    spot.direction = {-0.5, -1, -0.3};
    spot.spotAngle = 30.0;
    spot.shadows = ShadowParams{};
    spot.shadows->mapSize = 8; // below the smallest map: drawn at kMinShadowMapSize
    input.lights.push_back(spot);
    return input;
}

// One expected pass: its kind and target, and how it writes. `scissored`: the scissor is the pass's view's
// pixel rectangle (every mirror pass); otherwise none.
struct Row {
    PassKind kind;
    std::string target;
    PassTarget writesTo;
    int slot = -1;
    bool clear = false;
    bool clearWhole = false;
    bool scissored = false;
    int stencilEqual = -1;
    bool clockwise = false;
    bool mipmaps = false;
    int readSlot = -1;
};

std::string describe(const PlannedPass& pass) {
    return std::string(toString(pass.kind)) + " " + pass.target + " → " +
           std::string(toString(pass.writes.target));
}

void expectWrites(const FramePlan& plan, const std::vector<Row>& rows) {
    ASSERT_EQ(plan.passes.size(), rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const PlannedPass& pass = plan.passes[i];
        const PassWrites& w = pass.writes;
        const Row& row = rows[i];
        SCOPED_TRACE("pass " + std::to_string(i) + ": " + describe(pass));
        EXPECT_EQ(pass.kind, row.kind);
        EXPECT_EQ(pass.target, row.target);
        EXPECT_EQ(w.target, row.writesTo);
        EXPECT_EQ(w.slot, row.slot);
        EXPECT_EQ(w.clear, row.clear);
        EXPECT_EQ(w.clearWhole, row.clearWhole);
        ASSERT_EQ(w.scissor.has_value(), row.scissored);
        if (row.scissored) {
            const math::PixelRect& rect = plan.views[static_cast<std::size_t>(pass.view)].rect;
            EXPECT_FALSE(rect.empty());
            EXPECT_EQ(w.scissor->x0, rect.x0);
            EXPECT_EQ(w.scissor->y0, rect.y0);
            EXPECT_EQ(w.scissor->x1, rect.x1);
            EXPECT_EQ(w.scissor->y1, rect.y1);
        }
        EXPECT_EQ(w.stencilEqual, row.stencilEqual);
        EXPECT_EQ(w.clockwise, row.clockwise);
        EXPECT_EQ(w.mipmaps, row.mipmaps);
        EXPECT_EQ(w.readSlot, row.readSlot);
    }
}

const Row kMain{PassKind::Main, "", PassTarget::Linear, -1, true};
const Row kComposite{PassKind::Composite, "", PassTarget::Output};

TEST(PassWrites, PlainSceneDrawsIntoTheLinearBufferAndResolvesIntoTheOutput) {
    const FramePlan plan = planFrame(litScene(), {}, kViewport);
    expectWrites(plan, {{PassKind::Shadow, "Lamp", PassTarget::OwnMap},
                        {PassKind::Shadow, "Spot", PassTarget::OwnMap},
                        kMain,
                        kComposite});
}

TEST(PassWrites, StencilMirrorSeenDirectlyDrawsThroughItsStencilLevelWithFlippedWinding) {
    FrameInput input = cameraAtOrigin();
    input.mirrors = {wall("Wall", -3.0)};
    const FramePlan plan = planFrame(input, {}, kViewport);
    ASSERT_EQ(plan.views.size(), 1u);
    expectWrites(plan,
                 {kMain,
                  {PassKind::MirrorMask, "Wall", PassTarget::Linear, -1, false, false, true},
                  {PassKind::Mirror, "Wall", PassTarget::Linear, -1, false, false, true, 1, true},
                  {PassKind::MirrorSurface, "Wall", PassTarget::Linear, -1, false, false, true, -1, false},
                  kComposite});
}

TEST(PassWrites, StencilMirrorInAStencilMirrorWindsBackAndItsSurfaceIsDrawnReflected) {
    const FramePlan plan = planFrame(facingMirrors(2), {}, kViewport);
    ASSERT_EQ(plan.views.size(), 2u);
    ASSERT_EQ(plan.views[1].parent, 0);
    expectWrites(plan,
                 {kMain,
                  {PassKind::MirrorMask, "Front", PassTarget::Linear, -1, false, false, true},
                  {PassKind::Mirror, "Front", PassTarget::Linear, -1, false, false, true, 1, true},
                  // Marked in the Front mirror's (reflected) view: its winding.
                  {PassKind::MirrorMask, "Back", PassTarget::Linear, -1, false, false, true, -1, true},
                  {PassKind::Mirror, "Back", PassTarget::Linear, -1, false, false, true, 2, false},
                  {PassKind::MirrorSurface, "Back", PassTarget::Linear, -1, false, false, true, -1, true},
                  {PassKind::MirrorSurface, "Front", PassTarget::Linear, -1, false, false, true, -1, false},
                  kComposite});
}

TEST(PassWrites, BlurredTextureMirrorClearsItsWholeTextureAndBuildsMipmapsBeforeItsSurfaceReadsIt) {
    const FramePlan plan = planFrame(facingMirrors(2, MirrorTechnique::Texture, 0.5), {}, kViewport);
    ASSERT_EQ(plan.views.size(), 2u);
    // The stencil mirror seen in it nests inside the texture, from a fresh stencil space.
    expectWrites(
        plan,
        {kMain,
         {PassKind::MirrorMask, "Front", PassTarget::Linear, -1, false, false, true},
         {PassKind::Mirror, "Front", PassTarget::Reflection, 0, true, true, true, -1, true},
         {PassKind::MirrorMask, "Back", PassTarget::Reflection, 0, false, false, true, -1, true},
         {PassKind::Mirror, "Back", PassTarget::Reflection, 0, false, false, true, 1, false},
         {PassKind::MirrorSurface, "Back", PassTarget::Reflection, 0, false, false, true, -1, true},
         {PassKind::MirrorSurface, "Front", PassTarget::Linear, -1, false, false, true, -1, false, true, 0},
         kComposite});
}

// Cleared whole too (a scissored clear costs a quad drawn through it on llvmpipe), drawn in its pixels.
TEST(PassWrites, SharpTextureMirrorClearsItsWholeTextureDrawsInItsPixelsAndNeedsNoMipmaps) {
    const FramePlan plan = planFrame(facingMirrors(1, MirrorTechnique::Texture), {}, kViewport);
    expectWrites(plan, {kMain,
                        {PassKind::MirrorMask, "Front", PassTarget::Linear, -1, false, false, true},
                        {PassKind::Mirror, "Front", PassTarget::Reflection, 0, true, true, true, -1, true},
                        {PassKind::MirrorSurface, "Front", PassTarget::Linear, -1, false, false, true, -1,
                         false, false, 0},
                        kComposite});
}

TEST(PassWrites, TileMovesAndClipsEveryScissorLikeItsViewsPixels) {
    const FrameInput input = facingMirrors(2);
    const FramePlan whole = planFrame(input, {}, kViewport);
    ASSERT_EQ(whole.views.size(), 2u);
    const math::PixelRect front = whole.views[0].rect;
    const math::PixelRect back = whole.views[1].rect;
    // A tile starting inside the front mirror's pixels and ending halfway up them: clips its left, bottom
    // and top edges, and moves what is left to the tile's corner.
    const int midY = (front.y0 + front.y1) / 2;
    const math::PixelRect tile{front.x0 + 2, front.y0 + 3, front.x1 + 10, midY};
    ASSERT_LT(front.x0 + 2, back.x1) << "the back mirror's view keeps pixels in the tile";
    FramePlan tiled = whole;
    restrictToTile(tiled, tile, kViewport);
    ASSERT_EQ(tiled.passes.size(), whole.passes.size());
    for (std::size_t i = 0; i < tiled.passes.size(); ++i) {
        const PlannedPass& pass = tiled.passes[i];
        SCOPED_TRACE(describe(pass));
        ASSERT_EQ(pass.writes.scissor.has_value(), pass.view >= 0);
        if (pass.view < 0)
            continue;
        const math::PixelRect& rect = tiled.views[static_cast<std::size_t>(pass.view)].rect;
        EXPECT_EQ(pass.writes.scissor->x0, rect.x0);
        EXPECT_EQ(pass.writes.scissor->y0, rect.y0);
        EXPECT_EQ(pass.writes.scissor->x1, rect.x1);
        EXPECT_EQ(pass.writes.scissor->y1, rect.y1);
        if (pass.view == 0) { // by hand: clipped to the tile, counted from its corner
            EXPECT_EQ(pass.writes.scissor->x0, 0);
            EXPECT_EQ(pass.writes.scissor->y0, 0);
            EXPECT_EQ(pass.writes.scissor->x1, front.x1 - tile.x0);
            EXPECT_EQ(pass.writes.scissor->y1, midY - tile.y0);
        }
    }

    // A tile without any mirror pixel drops the mirror passes; the others keep no scissor.
    FramePlan corner = whole;
    restrictToTile(corner, {0, 0, 8, 8}, kViewport);
    ASSERT_LT(front.x0, 600);
    for (const PlannedPass& pass : corner.passes) {
        EXPECT_LT(pass.view, 0) << describe(pass);
        EXPECT_FALSE(pass.writes.scissor.has_value()) << describe(pass);
    }
}

TEST(PassWrites, EnvironmentMapMirrorPassesDrawIntoTheMapThroughTheirStencilLevel) {
    FrameInput input;
    input.camera.position = {0.0, 0.0, 6.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.far = 50.0;
    Mirror facing = wall("Facing", 0.0);
    facing.world = glm::translate(glm::dmat4(1.0), glm::dvec3(-3, 0, 0)) *
                   glm::rotate(glm::dmat4(1.0), glm::radians(-90.0), glm::dvec3(0, 0, 1)); // +Y → +X
    input.mirrors = {facing};
    Reflector ball;
    ball.name = "Ball";
    ball.mesh = std::make_shared<const MeshData>(makeSphere(16));
    ball.resolution = 64;
    ball.mirrorDepth = 1;
    input.reflectors = {ball};
    const FramePlan plan = planFrame(input, {}, kViewport);
    ASSERT_FALSE(plan.envmaps.empty());
    int mirrorPasses = 0;
    for (const PlannedPass& pass : plan.envmaps[0].passes) {
        SCOPED_TRACE(describe(pass));
        const MirrorView& view = plan.envmaps[0].views[static_cast<std::size_t>(pass.view)];
        EXPECT_EQ(pass.writes.target, PassTarget::OwnMap);
        EXPECT_FALSE(pass.writes.scissor.has_value());
        EXPECT_FALSE(pass.writes.clear);
        if (pass.kind == PassKind::Mirror) {
            ++mirrorPasses;
            EXPECT_EQ(pass.writes.stencilEqual, view.stencilLevel);
            EXPECT_EQ(pass.writes.clockwise, view.depth % 2 == 1);
        } else if (pass.kind == PassKind::MirrorMask) {
            EXPECT_EQ(pass.writes.stencilEqual, 0) << "marks the face's own pixels";
            EXPECT_FALSE(pass.writes.clockwise) << "depth 1: drawn in the face's own view";
        } else {
            EXPECT_EQ(pass.writes.stencilEqual, 1) << "steps the mirror's pixels back";
            EXPECT_FALSE(pass.writes.clockwise) << "depth 1: drawn in the face's own view";
        }
    }
    EXPECT_GT(mirrorPasses, 0);
}

// Two mirrors facing each other across the reflector, three deep: in each face every view's passes nest
// (mask, reflection, the views inside it, surface), each drawing through the stencil level of the view it
// is drawn in, with the winding of that view's reflections.
TEST(PassWrites, EnvironmentMapNestedMirrorsNestTheirStencilLevelsAndWindingsFaceByFace) {
    FrameInput input = facingMirrors(3);
    input.camera.position = {0.0, 0.0, 0.0};
    input.camera.target = {0.0, 0.0, -3.0};
    Reflector ball;
    ball.name = "Ball";
    ball.mesh = std::make_shared<const MeshData>(makeSphere(16));
    ball.world = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -1.0)) *
                 glm::scale(glm::dmat4(1.0), glm::dvec3(0.3));
    ball.resolution = 64;
    ball.mirrorDepth = 3;
    input.reflectors = {ball};
    const FramePlan plan = planFrame(input, {}, kViewport);
    ASSERT_FALSE(plan.envmaps.empty());
    const EnvmapPlan& map = plan.envmaps[0];
    std::vector<int> open; // views whose surface is still to come, innermost last
    int face = -1;
    int deepest = 0;
    for (const PlannedPass& pass : map.passes) {
        SCOPED_TRACE(describe(pass) + " (view " + std::to_string(pass.view) + ")");
        ASSERT_GE(pass.view, 0);
        const MirrorView& view = map.views[static_cast<std::size_t>(pass.view)];
        if (view.face != face) {
            EXPECT_TRUE(open.empty()) << "a face's passes end with its last surface";
            EXPECT_GT(view.face, face) << "faces in order";
            face = view.face;
        }
        const int parentLevel =
            view.parent >= 0 ? map.views[static_cast<std::size_t>(view.parent)].stencilLevel : 0;
        const bool parentOdd =
            view.parent >= 0 && map.views[static_cast<std::size_t>(view.parent)].depth % 2 == 1;
        EXPECT_EQ(view.stencilLevel, view.depth);
        EXPECT_EQ(pass.writes.target, PassTarget::OwnMap);
        EXPECT_FALSE(pass.writes.scissor.has_value());
        EXPECT_FALSE(pass.writes.clear);
        EXPECT_FALSE(pass.writes.mipmaps);
        EXPECT_EQ(pass.writes.readSlot, -1);
        switch (pass.kind) {
        case PassKind::MirrorMask:
            EXPECT_EQ(view.parent, open.empty() ? -1 : open.back()) << "drawn in the innermost open view";
            EXPECT_EQ(pass.writes.stencilEqual, parentLevel);
            EXPECT_EQ(pass.writes.clockwise, parentOdd);
            open.push_back(pass.view);
            break;
        case PassKind::Mirror:
            ASSERT_FALSE(open.empty());
            EXPECT_EQ(open.back(), pass.view) << "right after its mask";
            EXPECT_EQ(pass.writes.stencilEqual, parentLevel + 1);
            EXPECT_EQ(pass.writes.clockwise, view.depth % 2 == 1);
            deepest = std::max(deepest, view.depth);
            break;
        case PassKind::MirrorSurface:
            ASSERT_FALSE(open.empty());
            EXPECT_EQ(open.back(), pass.view) << "after the views inside it";
            EXPECT_EQ(pass.writes.stencilEqual, view.stencilLevel);
            EXPECT_EQ(pass.writes.clockwise, parentOdd);
            open.pop_back();
            break;
        default:
            ADD_FAILURE() << "only mirror passes draw inside the map";
        }
    }
    EXPECT_TRUE(open.empty());
    EXPECT_EQ(deepest, 3);
}

TEST(PassWrites, TargetsHaveNames) {
    EXPECT_EQ(toString(PassTarget::OwnMap), "own-map");
    EXPECT_EQ(toString(PassTarget::Linear), "linear");
    EXPECT_EQ(toString(PassTarget::Reflection), "reflection");
    EXPECT_EQ(toString(PassTarget::Output), "output");
}

void expectSameFrustum(const math::ShadowFrustum& a, const math::ShadowFrustum& b) {
    EXPECT_EQ(a.cube, b.cube);
    EXPECT_EQ(a.perspective, b.perspective);
    EXPECT_EQ(a.viewProjection, b.viewProjection);
    EXPECT_EQ(a.near, b.near);
    EXPECT_EQ(a.far, b.far);
    EXPECT_EQ(a.texelSize, b.texelSize);
    EXPECT_EQ(a.faceMask, b.faceMask);
}

TEST(ShadowPlan, EachShadowedLightHasItsOneFrustumAndSignatureInSlotOrder) {
    const FrameInput input = litScene();
    const FramePlan plan = planFrame(input, {}, kViewport);
    ASSERT_EQ(plan.shadowedLights, (std::vector<int>{0, 2}));
    ASSERT_EQ(plan.shadows.size(), plan.shadowedLights.size());
    // The scene as drawn: the spot's map at the smallest size, which its signature is of.
    const FrameInput drawn = plannedInput(input, plan).value_or(input);
    for (std::size_t k = 0; k < plan.shadows.size(); ++k) {
        const ShadowPlan& shadow = plan.shadows[k];
        const Light& light = input.lights[static_cast<std::size_t>(shadow.light)];
        SCOPED_TRACE(light.name);
        EXPECT_EQ(shadow.light, plan.shadowedLights[k]);
        EXPECT_EQ(shadow.mapSize, std::max(light.shadows->mapSize, kMinShadowMapSize));
        EXPECT_EQ(shadow.pcf, light.shadows->pcf);
        const auto frustum = math::shadowFrustum(input, light, shadow.mapSize);
        ASSERT_TRUE(frustum);
        expectSameFrustum(shadow.frustum, *frustum);
        EXPECT_EQ(shadow.signature, shadowSignature(drawn, shadow.light));
        EXPECT_EQ(shadow.signature, shadowSignature(drawn, shadow.light, shadow.frustum));
        EXPECT_TRUE(shadow.render);
        EXPECT_EQ(plan.shadowOf(shadow.light), &shadow);
    }
    EXPECT_EQ(plan.shadows[1].mapSize, kMinShadowMapSize)
        << "the spot's 8² map is drawn at the smallest size";
    EXPECT_TRUE(plan.shadows[0].frustum.cube);
    EXPECT_EQ(plan.shadowOf(1), nullptr) << "a light without shadows samples no map";
    EXPECT_EQ(plan.shadowOf(7), nullptr);
    // Each rendered map's pass carries the same signature.
    for (const PlannedPass& pass : plan.passes)
        if (pass.kind == PassKind::Shadow) {
            ASSERT_NE(plan.shadowOf(pass.lightIndex), nullptr);
            EXPECT_EQ(pass.signature, plan.shadowOf(pass.lightIndex)->signature);
        }
}

TEST(ShadowPlan, AReusedMapIsPlannedButNotRendered) {
    const FrameInput input = litScene();
    const FrameInput drawn = plannedInput(input, planFrame(input, {}, kViewport)).value_or(input);
    PlannerState state;
    state.shadowSignatures[2] = shadowSignature(drawn, 2);
    state.shadowSignatures[0] = shadowSignature(drawn, 0) + 1; // an old map of something else
    const FramePlan plan = planFrame(input, state, kViewport);
    ASSERT_NE(plan.shadowOf(0), nullptr);
    ASSERT_NE(plan.shadowOf(2), nullptr);
    EXPECT_TRUE(plan.shadowOf(0)->render);
    EXPECT_FALSE(plan.shadowOf(2)->render) << "unchanged: the old map is sampled";
    int shadowPasses = 0;
    for (const PlannedPass& pass : plan.passes)
        if (pass.kind == PassKind::Shadow) {
            ++shadowPasses;
            EXPECT_EQ(pass.lightIndex, 0);
        }
    EXPECT_EQ(shadowPasses, 1);
}

} // namespace
} // namespace speculum::render

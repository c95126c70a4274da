// An interactive preview (RenderOptions::preview), planned without GL: the planner leaves out levels of
// mirror nesting, holds the environment map and, while a handle is dragged, draws the shadow maps smaller,
// exactly as a scene edited that way would be planned, and lists each effect among the skips.
#include "PlanScenes.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/plan/Planner.hpp"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace speculum::render {
namespace {

constexpr PlanViewport kViewport{640, 360};

// Two facing mirrors in front of and behind a camera at the origin, nested 4 levels deep, a chrome ball and
// a box between them, and a light with a 1024² shadow map.
FrameInput mirrorsScene() {
    FrameInput input = test::cameraAtOrigin();
    input.settings.mirrorDepth = 4;
    input.mirrors.push_back(test::wall("Front", -3.0, true, 4.0));
    input.mirrors.push_back(test::wall("Back", 3.0, false, 4.0));
    static const auto box = std::make_shared<const MeshData>(makeBox());
    static const auto sphere = std::make_shared<const MeshData>(makeSphere(16));
    input.items.push_back(
        {"Box", glm::translate(glm::dmat4(1.0), glm::dvec3(0.8, -0.5, -1.5)), box, {}, true});
    Light light;
    light.name = "Lamp";
    light.position = {0, 2, -1};
    light.shadows = ShadowParams{1024, 3};
    input.lights.push_back(light);
    Reflector ball;
    ball.name = "Ball";
    ball.mesh = sphere;
    ball.world = glm::translate(glm::dmat4(1.0), glm::dvec3(-0.6, 0.0, -1.8)) *
                 glm::scale(glm::dmat4(1.0), glm::dvec3(0.4));
    input.reflectors = {ball};
    return input;
}

PlanOptions preview(double scale, int mirrorDepthCut, bool redrawsShadows) {
    PlanOptions options;
    options.preview = {scale, mirrorDepthCut, redrawsShadows};
    return options;
}

// What the renderer records once the frame's maps are drawn.
PlannerState afterDrawing(const FrameInput& input, const FramePlan& plan) {
    PlannerState state;
    for (const ShadowPlan& shadow : plan.shadows)
        state.shadowSignatures[shadow.light] = shadow.signature;
    state.mapOf(0).signature = envmapSignature(input, 0);
    state.mapOf(0).reflector = input.reflectors[0].name;
    state.mapOf(0).settings = envmapSettingsKey(input.reflectors[0]);
    return state;
}

std::vector<std::string> previewReasons(const FramePlan& plan) {
    std::vector<std::string> reasons;
    for (const SkippedEffect& s : plan.skipped)
        if (isPreview(s.code))
            reasons.push_back(s.target + ": " + s.reason());
    return reasons;
}

// The passes as kind, target and view, without reasons: what the frame draws.
std::vector<std::string> drawn(const FramePlan& plan) {
    std::vector<std::string> passes;
    for (const PlannedPass& p : plan.passes)
        passes.push_back(std::string(toString(p.kind)) + " " + p.target + " " + std::to_string(p.view));
    return passes;
}

TEST(PlannerPreview, NavigatingNestsFewerMirrorsHoldsTheMapAndKeepsTheShadows) {
    FrameInput input = mirrorsScene();
    const FramePlan rest = planFrame(input, {}, kViewport);
    const PlannerState state = afterDrawing(input, rest);
    input.items[0].world[3].x += 0.1; // something the map sees moves: at rest it is drawn again
    const FramePlan moved = planFrame(input, state, kViewport);
    ASSERT_TRUE(std::any_of(moved.passes.begin(), moved.passes.end(),
                            [](const PlannedPass& p) { return p.kind == PassKind::Envmap; }));

    const FramePlan plan = planFrame(input, state, kViewport, preview(0.25, 2, false));
    EXPECT_EQ(plan.mirrorDepth, 2);
    for (const MirrorView& view : plan.views)
        EXPECT_LE(view.depth, 2);
    EXPECT_TRUE(std::none_of(plan.passes.begin(), plan.passes.end(),
                             [](const PlannedPass& p) { return p.kind == PassKind::Envmap; }));
    EXPECT_EQ(plan.shadowOf(0)->mapSize, 1024) << "navigating changes no shadow";
    EXPECT_EQ(previewReasons(plan),
              (std::vector<std::string>{
                  "Ball: preview: environment map held while the view moves (update \"on-change\" applies "
                  "again at rest)",
                  "output: preview: drawn at 25% of the output's width and height and scaled up to it",
                  ": preview: mirrors nest 2 levels deep, not 4 (settings.mirrorDepth)"}));

    // The very frame the scene edited that way plans (the editor's viewport edited it before).
    FrameInput edited = input;
    edited.settings.mirrorDepth = 2;
    edited.reflectors[0].update = ReflectorUpdate::Once;
    EXPECT_EQ(drawn(plan), drawn(planFrame(edited, state, kViewport)));
}

TEST(PlannerPreview, AHandleDragDrawsShadowMapsSmaller) {
    FrameInput input = mirrorsScene();
    const FramePlan plan = planFrame(input, {}, kViewport, preview(0.25, 0, true));
    ASSERT_NE(plan.shadowOf(0), nullptr);
    EXPECT_EQ(plan.shadowOf(0)->mapSize, 256) << "a power of two less per halving of the scale";
    EXPECT_EQ(plan.passes[0].details.mapSize, 256) << plan.passes[0].reason();
    const std::vector<std::string> reasons = previewReasons(plan);
    EXPECT_NE(std::find(reasons.begin(), reasons.end(),
                        "Lamp: preview: shadow map drawn at 256², not 1024², while a handle is dragged"),
              reasons.end())
        << ::testing::PrintToString(reasons);
    EXPECT_EQ(plannedInput(input, plan)->lights[0].shadows->mapSize, 256);
    // Never under 256², nor larger than the light's own.
    EXPECT_EQ(planFrame(input, {}, kViewport, preview(0.125, 0, true)).shadowOf(0)->mapSize, 256);
    input.lights[0].shadows->mapSize = 128;
    EXPECT_EQ(planFrame(input, {}, kViewport, preview(0.125, 0, true)).shadowOf(0)->mapSize, 128);
    input.lights[0].shadows->mapSize = 4096;
    EXPECT_EQ(planFrame(input, {}, kViewport, preview(0.5, 0, true)).shadowOf(0)->mapSize, 2048);
}

TEST(PlannerPreview, AMapNotDrawnYetIsDrawnAndMirrorsKeepOneLevel) {
    const FrameInput input = mirrorsScene();
    const FramePlan plan = planFrame(input, {}, kViewport, preview(0.5, 16, false));
    EXPECT_TRUE(std::any_of(plan.passes.begin(), plan.passes.end(), [](const PlannedPass& p) {
        return p.kind == PassKind::Envmap;
    })) << "a preview holds the map there is, not none";
    EXPECT_EQ(plan.mirrorDepth, 1) << "never less than one level";
}

TEST(PlannerPreview, AFrameAtRestGivesUpNothing) {
    const FrameInput input = mirrorsScene();
    const FramePlan rest = planFrame(input, {}, kViewport);
    const FramePlan none = planFrame(input, {}, kViewport, preview(1.0, 0, true));
    EXPECT_FALSE(none.preview.active());
    EXPECT_TRUE(previewReasons(none).empty());
    EXPECT_EQ(drawn(none), drawn(rest));
    EXPECT_EQ(none.mirrorDepth, 4);
    EXPECT_EQ(none.shadowOf(0)->mapSize, 1024);
    EXPECT_FALSE(plannedInput(input, none));
}

} // namespace
} // namespace speculum::render

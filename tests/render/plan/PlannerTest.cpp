// The planner decides passes without any GL: which run, which are skipped, and why.
#include "render/plan/Planner.hpp"

#include "render/gl/Program.hpp"
#include "render/math/Projection.hpp"
#include "render/math/ShadowFrustum.hpp"
#include "render/mesh/Primitives.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace speculum::render {
namespace {

FrameInput sceneWithLight(bool shadows) {
    FrameInput input;
    auto box = std::make_shared<const MeshData>(makeBox());
    auto plane = std::make_shared<const MeshData>(makePlane(1));
    input.items.push_back({"Box", glm::translate(glm::dmat4(1.0), glm::dvec3(0, 1, 0)), box, {}, true});
    input.items.push_back({"Floor", glm::scale(glm::dmat4(1.0), glm::dvec3(5, 1, 5)), plane, {}, true});
    Light light;
    light.name = "Lamp";
    light.position = {0, 4, 0};
    if (shadows)
        light.shadows = ShadowParams{};
    input.lights.push_back(light);
    return input;
}

std::vector<PassKind> kinds(const FramePlan& plan) {
    std::vector<PassKind> k;
    for (const auto& p : plan.passes)
        k.push_back(p.kind);
    return k;
}

const SkippedEffect* skipFor(const FramePlan& plan, const std::string& target) {
    for (const auto& s : plan.skipped)
        if (s.target == target)
            return &s;
    return nullptr;
}

TEST(Planner, ShadowPassThenMainThenCompositeWithReasons) {
    const FramePlan plan = planFrame(sceneWithLight(true), {});
    ASSERT_EQ(kinds(plan), (std::vector{PassKind::Shadow, PassKind::Main, PassKind::Composite}));
    EXPECT_EQ(plan.passes[0].target, "Lamp");
    EXPECT_EQ(plan.passes[0].code, PlanReason::ShadowFirstMap);
    EXPECT_EQ(plan.passes[0].details.casters, 2u);
    for (const auto& p : plan.passes)
        EXPECT_FALSE(p.reason().empty());
    EXPECT_EQ(plan.shadowedLights, std::vector<int>{0});
}

TEST(Planner, NoShadowCastingLightMeansNoShadowPass) {
    const FramePlan plan = planFrame(sceneWithLight(false), {});
    EXPECT_EQ(kinds(plan), (std::vector{PassKind::Main, PassKind::Composite}));
    const SkippedEffect* skip = skipFor(plan, "Lamp");
    ASSERT_NE(skip, nullptr);
    EXPECT_EQ(skip->code, PlanReason::ShadowsOff);
}

TEST(Planner, NoCastersMeansNoShadowPass) {
    FrameInput input = sceneWithLight(true);
    for (auto& item : input.items)
        item.castsShadows = false;
    const FramePlan plan = planFrame(input, {});
    EXPECT_EQ(kinds(plan), (std::vector{PassKind::Main, PassKind::Composite}));
    ASSERT_NE(skipFor(plan, "Lamp"), nullptr);
    EXPECT_EQ(skipFor(plan, "Lamp")->code, PlanReason::NoShadowCasters);
}

TEST(Planner, UnchangedLightAndCastersReuseTheMapAndAnyChangeRendersIt) {
    FrameInput input = sceneWithLight(true);
    PlannerState state;
    state.shadowSignatures[0] = shadowSignature(input, 0);
    FramePlan plan = planFrame(input, state);
    EXPECT_EQ(kinds(plan), (std::vector{PassKind::Main, PassKind::Composite}));
    ASSERT_NE(skipFor(plan, "Lamp"), nullptr);
    EXPECT_EQ(skipFor(plan, "Lamp")->code, PlanReason::ShadowMapReused);
    EXPECT_EQ(plan.shadowedLights, std::vector<int>{0}) << "a reused map is still sampled";

    FrameInput movedLight = input;
    movedLight.lights[0].position.x += 0.01;
    EXPECT_EQ(planFrame(movedLight, state).passes.front().kind, PassKind::Shadow);
    FrameInput movedCaster = input;
    movedCaster.items[0].world = glm::translate(movedCaster.items[0].world, glm::dvec3(0, 0.01, 0));
    EXPECT_EQ(planFrame(movedCaster, state).passes.front().kind, PassKind::Shadow);
    FrameInput biggerMap = input;
    biggerMap.lights[0].shadows->mapSize = 2048;
    EXPECT_EQ(planFrame(biggerMap, state).passes.front().kind, PassKind::Shadow);
    FrameInput softer = input;
    softer.lights[0].shadows->pcf = 7; // a lookup setting: the map itself is unchanged
    EXPECT_EQ(planFrame(softer, state).passes.front().kind, PassKind::Main);
}

TEST(Planner, AtMostFourLightsGetShadowMaps) {
    FrameInput input = sceneWithLight(true);
    for (int i = 0; i < 5; ++i) {
        Light extra = input.lights[0];
        extra.name = "Extra " + std::to_string(i);
        input.lights.push_back(extra);
    }
    const FramePlan plan = planFrame(input, {});
    EXPECT_EQ(plan.shadowedLights.size(), std::size_t(kMaxShadowedLights));
    ASSERT_NE(skipFor(plan, "Extra 4"), nullptr);
}

TEST(ShadowFrustum, PointLightCubeFacesHoldOnlyWhereCastersAre) {
    FrameInput input = sceneWithLight(true);
    input.items.resize(1); // only the box, straight below the lamp
    input.items[0].world = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 0));
    input.items[0].world = glm::scale(input.items[0].world, glm::dvec3(0.2));
    const auto frustum = math::shadowFrustum(input, input.lights[0], 512);
    ASSERT_TRUE(frustum);
    EXPECT_TRUE(frustum->cube);
    EXPECT_EQ(frustum->faceMask, 1u << 3) << "only the −Y face looks at the box";
    EXPECT_GT(frustum->far, 4.0);
    EXPECT_GT(frustum->near, 0.0);
}

TEST(ShadowFrustum, DirectionalMapContainsEveryPointOfTheScene) {
    FrameInput input = sceneWithLight(true);
    input.lights[0].type = LightType::Directional;
    input.lights[0].direction = glm::normalize(glm::dvec3(0.3, -1, 0.4));
    const auto frustum = math::shadowFrustum(input, input.lights[0], 1024);
    ASSERT_TRUE(frustum);
    EXPECT_FALSE(frustum->perspective);
    for (const auto& corner : math::sceneBounds(input).corners()) {
        const glm::dvec4 clip = frustum->viewProjection[0] * glm::dvec4(corner, 1.0);
        for (int a = 0; a < 3; ++a) {
            EXPECT_LE(std::abs(clip[a] / clip.w), 1.0 + 1e-9);
        }
    }
}

TEST(ShaderLog, CompileErrorsNameTheShaderFileAndLine) {
    std::vector<std::string> files;
    auto text = gl::preprocessShader("mesh.frag", "", files);
    ASSERT_TRUE(text.ok()) << text.error();
    ASSERT_GE(files.size(), 3u); // mesh.frag includes material.glsl, which includes lighting.glsl
    EXPECT_EQ(files[0], "mesh.frag");
    EXPECT_EQ(files[1], "material.glsl");
    EXPECT_EQ(files[2], "lighting.glsl");
    EXPECT_EQ(gl::mapShaderLog("0:12(3): error: `foo' undeclared", files),
              "shaders/mesh.frag:12:3: error: `foo' undeclared\n");
    EXPECT_EQ(gl::mapShaderLog("2(40) : error C1008: undefined variable", files),
              "shaders/lighting.glsl:40: error C1008: undefined variable\n");
}

} // namespace
} // namespace speculum::render

// Map sizes the GPU cannot hold, planned without GL: planFrame brings each shadow map and the reflector's
// resolution within its own limit (cube maps, 2D maps, the tennis-ball map's 3n height) and below the sizes
// of its kind that failed to allocate in earlier frames, says what it did in the plan's warnings, and the
// scene the executors draw (plannedInput) has the sizes planned.
#include "PlanScenes.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/plan/Planner.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace speculum::render {
namespace {

using test::passOf;
using test::skipCode;
using test::skipReason;

constexpr GpuLimits kLimits{4096, 2048, 8192, 16384};

Light shadowed(LightType type, int mapSize, const std::string& name) {
    Light light;
    light.name = name;
    light.type = type;
    light.position = {0.0, 4.0, 0.0};
    light.direction = {0.0, -1.0, 0.0};
    light.shadows = render::ShadowParams{mapSize, 3};
    return light;
}

Reflector reflector(ReflectorMap map, ReflectorFill fill, int resolution) {
    static const auto sphere = std::make_shared<const MeshData>(makeSphere(16));
    Reflector r;
    r.name = "Ball";
    r.mesh = sphere;
    r.world = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0.5, 0));
    r.map = map;
    r.fill = fill;
    r.resolution = resolution;
    return r;
}

// A box on a floor, both casting shadows, seen from +Z: every light gets a map.
FrameInput scene(std::vector<Light> lights) {
    FrameInput input;
    input.camera.position = {0.0, 2.0, 6.0};
    input.camera.target = {0.0, 0.5, 0.0};
    static const auto box = std::make_shared<const MeshData>(makeBox());
    static const auto plane = std::make_shared<const MeshData>(makePlane(1));
    input.items.push_back({"Box", glm::translate(glm::dmat4(1.0), glm::dvec3(1.5, 0.5, 0)), box, {}, true});
    input.items.push_back({"Floor", glm::scale(glm::dmat4(1.0), glm::dvec3(5, 1, 5)), plane, {}, true});
    input.lights = std::move(lights);
    return input;
}

PlanOptions within(const GpuLimits& gpu) {
    PlanOptions options;
    options.maps.gpu = gpu;
    return options;
}

TEST(GpuLimits, SizesThatFitChangeNothing) {
    FrameInput input =
        scene({shadowed(LightType::Point, 2048, "Lamp"), shadowed(LightType::Spot, 4096, "Spot")});
    input.reflectors = {reflector(ReflectorMap::TennisBall, ReflectorFill::Direct, 1365)};
    const FramePlan plan = planFrame(input, {}, {320, 180}, within(kLimits));
    EXPECT_TRUE(plan.warnings.empty()) << ::testing::PrintToString(plan.warnings);
    EXPECT_EQ(plan.shadowOf(0)->mapSize, 2048);
    EXPECT_EQ(plan.shadowOf(1)->mapSize, 4096);
    EXPECT_EQ(plan.reflectorResolution(0), 1365);
    EXPECT_FALSE(plannedInput(input, plan)) << "the scene is drawn as it is";
}

TEST(GpuLimits, ShadowMapsAreFittedToTheirOwnKindOfTexture) {
    FrameInput input =
        scene({shadowed(LightType::Point, 100000, "Lamp"), shadowed(LightType::Spot, 100000, "Spot"),
               shadowed(LightType::Directional, 100000, "Sun"), shadowed(LightType::Spot, 4, "Tiny")});
    input.lights.push_back(shadowed(LightType::Point, 100000, "Unshadowed"));
    input.lights.back().shadows.reset(); // no map: nothing to fit
    const FramePlan plan = planFrame(input, {}, {320, 180}, within(kLimits));
    ASSERT_EQ(plan.shadows.size(), 4u);
    EXPECT_EQ(plan.shadowOf(0)->mapSize, 2048); // a cube map
    EXPECT_EQ(plan.shadowOf(1)->mapSize, 4096); // 2D maps
    EXPECT_EQ(plan.shadowOf(2)->mapSize, 4096);
    EXPECT_EQ(plan.shadowOf(3)->mapSize, kMinShadowMapSize);
    ASSERT_EQ(plan.warnings.size(), 4u);
    EXPECT_NE(plan.warnings[0].find("light \"Lamp\""), std::string::npos) << plan.warnings[0];
    EXPECT_NE(plan.warnings[0].find("100000"), std::string::npos) << plan.warnings[0];
    EXPECT_NE(plan.warnings[0].find("2048"), std::string::npos) << plan.warnings[0];
    EXPECT_NE(plan.warnings[3].find("Tiny"), std::string::npos) << plan.warnings[3];
    // The shadow pass says the size it draws, and the executors draw the scene with it.
    EXPECT_EQ(passOf(plan, PassKind::Shadow)->details.mapSize, 2048)
        << passOf(plan, PassKind::Shadow)->reason();
    const auto drawn = plannedInput(input, plan);
    ASSERT_TRUE(drawn);
    EXPECT_EQ(drawn->lights[0].shadows->mapSize, 2048);
    EXPECT_EQ(drawn->lights[3].shadows->mapSize, kMinShadowMapSize);
    EXPECT_EQ(drawn->lights[4].shadows, std::nullopt);
    EXPECT_EQ(input.lights[0].shadows->mapSize, 100000) << "the input is left as it was";
}

TEST(GpuLimits, ReflectorResolutionFitsEveryTextureItsMapNeeds) {
    struct Case {
        ReflectorMap map;
        ReflectorFill fill;
        int expected;
    };
    for (const Case& c : {Case{ReflectorMap::Cube, ReflectorFill::Resampled, 2048},
                          Case{ReflectorMap::DualParaboloid, ReflectorFill::Direct, 4096},
                          Case{ReflectorMap::DualParaboloid, ReflectorFill::Resampled, 2048}, // its cube
                          Case{ReflectorMap::TennisBall, ReflectorFill::Direct, 4096 / 3},
                          Case{ReflectorMap::Octahedral, ReflectorFill::Direct, 2048}}) { // always resampled
        FrameInput input = scene({});
        input.reflectors = {reflector(c.map, c.fill, 100000)};
        const FramePlan plan = planFrame(input, {}, {320, 180}, within(kLimits));
        EXPECT_EQ(plan.reflectorResolution(0), c.expected);
        ASSERT_EQ(plan.warnings.size(), 1u);
        EXPECT_NE(plan.warnings[0].find("reflector \"Ball\": resolution 100000"), std::string::npos)
            << plan.warnings[0];
        EXPECT_NE(plan.warnings[0].find(std::to_string(c.expected)), std::string::npos) << plan.warnings[0];
        ASSERT_NE(passOf(plan, PassKind::Envmap), nullptr);
        EXPECT_EQ(passOf(plan, PassKind::Envmap)->details.resolution, c.expected)
            << passOf(plan, PassKind::Envmap)->reason();
        ASSERT_FALSE(plan.envmaps.empty());
        EXPECT_EQ(plan.envmaps[0].settingsKey,
                  envmapSettingsKey(plannedInput(input, plan)->reflectors.at(0)));
    }
    FrameInput tiny = scene({});
    tiny.reflectors = {reflector(ReflectorMap::Cube, ReflectorFill::Direct, 0)};
    EXPECT_EQ(planFrame(tiny, {}, {320, 180}, within(kLimits)).reflectorResolution(0), kMinEnvmapResolution);
}

// What allocation learnt in earlier frames: a map of a kind that failed at a size is planned below it, by
// halving from the size asked for (as the allocation's own fallback halves), with the warning the
// allocation gave when it failed.
TEST(GpuLimits, SizesThatFailedToAllocateArePlannedBelow) {
    FrameInput input =
        scene({shadowed(LightType::Point, 8192, "Lamp"), shadowed(LightType::Spot, 8192, "Spot")});
    input.reflectors = {reflector(ReflectorMap::Cube, ReflectorFill::Resampled, 4096)};
    PlanOptions options;
    options.maps.failed[MapKind::ShadowCube] = {1024, "did not fit in GPU memory"};
    options.maps.failed[MapKind::EnvmapCube] = {2048, "did not fit in GPU memory"};
    const FramePlan plan = planFrame(input, {}, {320, 180}, options);
    EXPECT_EQ(plan.shadowOf(0)->mapSize, 512);
    EXPECT_EQ(plan.shadowOf(1)->mapSize, 8192) << "2D maps are another kind";
    EXPECT_EQ(plan.reflectorResolution(0), 1024);
    EXPECT_EQ(plan.warnings,
              (std::vector<std::string>{
                  "light 'Lamp': the 8192² cube shadow map did not fit in GPU memory; using 512²",
                  "reflector 'Ball': the 4096 cube environment map did not fit in GPU memory; "
                  "using 1024"}));
    EXPECT_EQ(passOf(plan, PassKind::Shadow)->details.mapSize, 512);
    EXPECT_NE(passOf(plan, PassKind::Envmap)->reason().find("1024×1024"), std::string::npos);
    ASSERT_FALSE(plan.envmaps.empty());
    EXPECT_EQ(plan.envmaps[0].faces.front().width, 1024);
    const auto drawn = plannedInput(input, plan);
    ASSERT_TRUE(drawn);
    EXPECT_EQ(drawn->lights[0].shadows->mapSize, 512);
    EXPECT_EQ(drawn->reflectors[0].resolution, 1024);
    // Its signature is the one of a map asked for at that size: the map is reused as such.
    FrameInput asked = input;
    asked.lights[0].shadows->mapSize = 512;
    EXPECT_EQ(plan.shadowOf(0)->signature, shadowSignature(asked, 0));
}

TEST(GpuLimits, AKindOfMapOfWhichNoneFitsIsLeftOutWithAWarning) {
    FrameInput input =
        scene({shadowed(LightType::Point, 1024, "Lamp"), shadowed(LightType::Spot, 1024, "Spot")});
    input.reflectors = {reflector(ReflectorMap::DualParaboloid, ReflectorFill::Direct, 256)};
    PlanOptions options;
    options.maps.failed[MapKind::ShadowCube] = {kMinShadowMapSize, "did not fit in GPU memory"};
    options.maps.failed[MapKind::EnvmapParaboloid] = {kMinEnvmapResolution, "did not fit in GPU memory"};
    const FramePlan plan = planFrame(input, {}, {320, 180}, options);
    EXPECT_EQ(plan.shadowOf(0), nullptr);
    EXPECT_EQ(plan.shadowedLights, std::vector<int>{1}) << "the spot light keeps its map";
    EXPECT_EQ(skipCode(plan, "Lamp"), PlanReason::ShadowMapDoesNotFit) << skipReason(plan, "Lamp");
    EXPECT_EQ(plan.reflectorResolution(0), 0);
    EXPECT_EQ(passOf(plan, PassKind::Envmap), nullptr);
    EXPECT_EQ(skipCode(plan, "Ball"), PlanReason::EnvmapDoesNotFit) << skipReason(plan, "Ball");
    ASSERT_EQ(plan.warnings.size(), 2u);
    EXPECT_NE(plan.warnings[0].find("nor did any down to 16²; the light casts no shadows"), std::string::npos)
        << plan.warnings[0];
    EXPECT_NE(plan.warnings[1].find("nor did any down to 8; the reflector is drawn without it"),
              std::string::npos)
        << plan.warnings[1];
}

TEST(GpuLimits, BelowFailureHalvesFromTheSizeAskedFor) {
    const FailedAllocation at4096{4096, "did not fit"};
    EXPECT_EQ(belowFailure(8192, 16, at4096), 2048);
    EXPECT_EQ(belowFailure(3000, 16, at4096), 3000);
    EXPECT_EQ(belowFailure(4, 16, {}), 16);
    EXPECT_EQ(belowFailure(64, 16, FailedAllocation{16, "did not fit"}), 0);
}

} // namespace
} // namespace speculum::render

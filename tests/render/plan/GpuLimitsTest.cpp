// Map sizes the GPU cannot hold, without GL: fitToGpuLimits brings each within its own limit (cube maps,
// 2D maps, the tennis-ball map's 3n height) and says what it did.
#include "render/plan/GpuLimits.hpp"

#include <gtest/gtest.h>

namespace speculum::render {
namespace {

constexpr GpuLimits kLimits{4096, 2048, 8192, 16384};

Light shadowed(LightType type, int mapSize, const std::string& name) {
    Light light;
    light.name = name;
    light.type = type;
    light.shadows = render::ShadowParams{mapSize, 3};
    return light;
}

Reflector reflector(ReflectorMap map, ReflectorFill fill, int resolution) {
    Reflector r;
    r.name = "Ball";
    r.map = map;
    r.fill = fill;
    r.resolution = resolution;
    return r;
}

TEST(GpuLimits, SizesThatFitChangeNothing) {
    FrameInput input;
    input.lights = {shadowed(LightType::Point, 2048, "Lamp"), shadowed(LightType::Spot, 4096, "Spot")};
    input.reflector = reflector(ReflectorMap::TennisBall, ReflectorFill::Direct, 1365);
    std::vector<std::string> warnings;
    EXPECT_FALSE(fitToGpuLimits(input, kLimits, warnings));
    EXPECT_TRUE(warnings.empty());
}

TEST(GpuLimits, ShadowMapsAreFittedToTheirOwnKindOfTexture) {
    FrameInput input;
    input.lights = {shadowed(LightType::Point, 100000, "Lamp"), shadowed(LightType::Spot, 100000, "Spot"),
                    shadowed(LightType::Directional, 100000, "Sun"), shadowed(LightType::Spot, 4, "Tiny")};
    input.lights.push_back(shadowed(LightType::Point, 100000, "Unshadowed"));
    input.lights.back().shadows.reset(); // no map: nothing to fit
    std::vector<std::string> warnings;
    const auto fitted = fitToGpuLimits(input, kLimits, warnings);
    ASSERT_TRUE(fitted);
    EXPECT_EQ(fitted->lights[0].shadows->mapSize, 2048); // a cube map
    EXPECT_EQ(fitted->lights[1].shadows->mapSize, 4096); // 2D maps
    EXPECT_EQ(fitted->lights[2].shadows->mapSize, 4096);
    EXPECT_EQ(fitted->lights[3].shadows->mapSize, kMinShadowMapSize);
    EXPECT_EQ(fitted->lights[4].shadows->mapSize, 100000);
    ASSERT_EQ(warnings.size(), 4u);
    EXPECT_NE(warnings[0].find("light \"Lamp\""), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("100000"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("2048"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[3].find("Tiny"), std::string::npos) << warnings[3];
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
                          Case{ReflectorMap::TennisBall, ReflectorFill::Direct, 4096 / 3}}) {
        FrameInput input;
        input.reflector = reflector(c.map, c.fill, 100000);
        std::vector<std::string> warnings;
        const auto fitted = fitToGpuLimits(input, kLimits, warnings);
        ASSERT_TRUE(fitted);
        EXPECT_EQ(fitted->reflector->resolution, c.expected);
        ASSERT_EQ(warnings.size(), 1u);
        EXPECT_NE(warnings[0].find("reflector \"Ball\": resolution 100000"), std::string::npos)
            << warnings[0];
        EXPECT_NE(warnings[0].find(std::to_string(c.expected)), std::string::npos) << warnings[0];
    }
    FrameInput tiny;
    tiny.reflector = reflector(ReflectorMap::Cube, ReflectorFill::Direct, 0);
    std::vector<std::string> warnings;
    EXPECT_EQ(fitToGpuLimits(tiny, kLimits, warnings)->reflector->resolution, kMinEnvmapResolution);
}

} // namespace
} // namespace speculum::render

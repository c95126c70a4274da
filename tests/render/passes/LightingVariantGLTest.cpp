// The lit shaders built for a frame's lights (passes/LightingVariant) and for each material's features
// (passes::setMaterial) draw the image the general shaders draw from uniforms alone: every kind of light,
// with and without shadow maps, textured and untextured materials, vertex colours, masks, normal maps and
// emission textures, in the main view, in mirrors of both techniques and in the curved reflector's
// environment map.
#include "render/mesh/Primitives.hpp"
#include "render/mesh/Teapot.hpp"
#include "render/passes/LightingVariant.hpp"
#include "render/plan/Planner.hpp"
#include "support/GlTest.hpp"
#include "support/MaterialScenes.hpp"
#include "support/TestPaths.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kWidth = 200, kHeight = 150;

Light light(const std::string& name, LightType type, glm::dvec3 position, bool shadows, int pcf) {
    Light l;
    l.name = name;
    l.type = type;
    l.position = position;
    l.direction = glm::normalize(glm::dvec3(0.0) - position);
    l.spotAngle = 40.0;
    l.intensity = 0.6;
    if (shadows)
        l.shadows = render::ShadowParams{512, pcf};
    return l;
}

// A textured teapot and a plain box on a marble floor before a wall with two mirrors, a chrome ball beside
// them, under `lights`.
FrameInput litScene(std::vector<Light> lights) {
    FrameInput input;
    input.settings.ambient = 0.15;
    input.camera.position = {0.5, 1.6, 4.0};
    input.camera.target = {0.0, 0.3, 0.0};
    input.camera.far = 30.0;
    static const auto plane = std::make_shared<const MeshData>(makePlane(1));
    static const auto box = std::make_shared<const MeshData>(makeBox());
    static const auto teapot = std::make_shared<const MeshData>(makeTeapot(6));
    DrawItem floor{"Floor", glm::scale(glm::dmat4(1.0), glm::dvec3(4.0, 1.0, 4.0)), plane, {}, true};
    // Textured and untextured materials alternate in the draw order: each switch of shader variant must
    // carry the view's uniforms along.
    floor.material.texture.path = speculum::testSourcePath("resources/scenes/textures/marble.png");
    DrawItem wall{"Wall",
                  glm::scale(glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 2, -2)),
                                         glm::radians(90.0), glm::dvec3(1, 0, 0)),
                             glm::dvec3(4.0, 1.0, 2.0)),
                  plane,
                  {},
                  true};
    wall.material.color = {0.6, 0.65, 0.75};
    DrawItem pot{"Teapot",
                 glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(-0.6, 0.0, 0.3)), glm::dvec3(0.35)),
                 teapot,
                 {},
                 true};
    pot.material.color = {0.8, 0.3, 0.2};
    pot.material.texture.path = floor.material.texture.path;
    pot.material.specular = 0.6;
    DrawItem cube{"Box",
                  glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.7, 0.3, 0.6)), glm::dvec3(0.3)),
                  box,
                  {},
                  true};
    cube.material.color = {0.2, 0.6, 0.3};
    input.items = {floor, wall, pot, cube};

    auto mirror = [](const std::string& name, double x, MirrorTechnique technique) {
        Mirror m;
        m.name = name;
        m.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(x, 1.2, -1.99)), glm::radians(90.0),
                              glm::dvec3(1, 0, 0));
        m.size = {1.2, 1.4};
        m.reflectivity = 0.7; // its own lit surface shows under the reflection
        m.technique = technique;
        return m;
    };
    input.mirrors = {mirror("Stencil mirror", -1.0, MirrorTechnique::Stencil),
                     mirror("Texture mirror", 1.0, MirrorTechnique::Texture)};
    input.mirrors[1].roughness = 0.2;

    Reflector ball;
    ball.name = "Ball";
    ball.mesh = std::make_shared<const MeshData>(makeSphere(48));
    ball.world = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.4, 1.2)), glm::dvec3(0.4));
    ball.reflectivity = 0.8;
    ball.map = ReflectorMap::DualParaboloid;
    ball.resolution = 128;
    input.reflectors = {ball};

    input.lights = std::move(lights);
    return input;
}

class LightingVariants : public GlTest {
protected:
    // Largest difference of any channel between the two renders, with the frame's warnings checked.
    double largestDifference(const FrameInput& input) {
        StillSettings settings{kWidth, kHeight, 1};
        settings.lightingVariants = false;
        auto general = renderStill(renderer(), input, settings);
        settings.lightingVariants = true;
        auto variant = renderStill(renderer(), input, settings);
        EXPECT_TRUE(general.ok() && variant.ok());
        if (!general.ok() || !variant.ok())
            return 1e9;
        for (const std::string& warning : variant->firstSample.warnings)
            ADD_FAILURE() << warning;
        variantReport = variant->firstSample;
        double largest = 0.0;
        for (std::size_t i = 0; i < general->image.rgba.size(); ++i)
            largest = std::max(largest, double(std::abs(general->image.rgba[i] - variant->image.rgba[i])));
        return largest;
    }

    // Mean of the red, green and blue channels over the image: the scene must actually be lit.
    double meanBrightness(const FrameInput& input) {
        const Image image = renderImage(input, kWidth, kHeight);
        double sum = 0.0;
        for (std::size_t i = 0; i < image.rgba.size(); i += 4)
            sum += image.rgba[i] + image.rgba[i + 1] + image.rgba[i + 2];
        return sum / (3.0 * kWidth * kHeight);
    }

    FrameReport variantReport; // the last largestDifference's frame drawn with the variant
};

TEST_F(LightingVariants, EveryKindOfLightWithAndWithoutShadowsDrawsTheSameImage) {
    const FrameInput input = litScene({light("Point", LightType::Point, {1.5, 3.0, 1.5}, true, 5),
                                       light("Spot", LightType::Spot, {-2.0, 3.5, 2.0}, true, 3),
                                       light("Sun", LightType::Directional, {2.0, 4.0, 3.0}, true, 1),
                                       light("Fill", LightType::Point, {-1.5, 1.0, 3.0}, false, 1)});
    EXPECT_LT(largestDifference(input), 2e-3);
    // Three maps, in three slots of two kinds, and the variant names them.
    EXPECT_EQ(variantReport.plan.shadowedLights.size(), 3u);
    const std::string variant = passes::lightingVariant(input, variantReport.plan.shadowedLights);
    EXPECT_NE(variant.find("#define LIGHT_COUNT 4"), std::string::npos) << variant;
    EXPECT_NE(variant.find("#define LIGHT_TYPE_1 2"), std::string::npos) << variant << "the spot";
    EXPECT_NE(variant.find("#define LIGHT_TYPE_2 1"), std::string::npos) << variant << "the sun";

    EXPECT_NE(variant.find("#define LIGHT_CUBE_0 1"), std::string::npos) << variant;
    EXPECT_NE(variant.find("#define LIGHT_CUBE_1 0"), std::string::npos) << variant;
    EXPECT_NE(variant.find("#define LIGHT_SLOT_3 -1"), std::string::npos) << variant;
}

TEST_F(LightingVariants, NoLightsAndMoreShadowedLightsThanSlotsDrawTheSameImage) {
    EXPECT_LT(largestDifference(litScene({})), 2e-3);
    std::vector<Light> many;
    for (int i = 0; i < kMaxShadowedLights + 2; ++i)
        many.push_back(light("Lamp " + std::to_string(i), i % 2 ? LightType::Spot : LightType::Point,
                             {std::cos(i * 1.1) * 2.5, 2.5 + 0.2 * i, std::sin(i * 1.1) * 2.5}, true, 3));
    EXPECT_LT(largestDifference(litScene(many)), 2e-3);
}

TEST_F(LightingVariants, ModelMaterialFeaturesDrawTheSameImageInEveryVariant) {
    // Vertex colours, alpha masks, normal maps, emission textures, wrap modes and tinted highlights,
    // each compiled out where a material does not use it, in the main view, the mirrors and the
    // reflector's map, against the general shader that reads them all from uniforms.
    FrameInput input = litScene({light("Point", LightType::Point, {1.5, 3.0, 1.5}, true, 3),
                                 light("Sun", LightType::Directional, {2.0, 4.0, 3.0}, true, 1)});
    const FrameInput features = materials::featureScene(materials::freshFolder());
    for (DrawItem item : features.items) {
        if (item.name == "Floor")
            continue;
        item.world = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, 0.3)) * item.world;
        input.items.push_back(item);
    }
    EXPECT_LT(largestDifference(input), 2e-3);
}

TEST_F(LightingVariants, EachLightAddsItsLightInTheVariant) {
    // The variant must not drop a light: each one brightens the image it draws.
    const Light a = light("A", LightType::Point, {1.5, 3.0, 1.5}, true, 3);
    const Light b = light("B", LightType::Spot, {-2.0, 3.5, 2.0}, true, 3);
    const double none = meanBrightness(litScene({}));
    const double one = meanBrightness(litScene({a}));
    const double two = meanBrightness(litScene({a, b}));
    EXPECT_GT(one, none + 0.01);
    EXPECT_GT(two, one + 0.01);
}

// A shadow lookup whose kernel cannot reach the box of what the map holds answers "lit" without reading
// the map (RenderOptions::boundShadowLookups). Only the teapot and the box cast here, so most of the
// floor, the wall and the mirrors' reflections take the shortcut, and the shadows' edges (PCF 1, 3 and 5,
// every kind of map) lie right at its border: the image must be exactly the one every lookup filters.
TEST_F(LightingVariants, ShadowLookupsBoundedByWhatTheMapHoldsDrawTheSameImageAsEveryLookupFiltered) {
    const std::vector<std::vector<Light>> rigs = {
        {light("Point", LightType::Point, {1.5, 3.0, 1.5}, true, 5)},
        {light("Point", LightType::Point, {-0.4, 1.2, 1.0}, true, 1)},
        {light("Spot", LightType::Spot, {-2.0, 3.5, 2.0}, true, 3)},
        {light("Sun", LightType::Directional, {2.0, 4.0, 3.0}, true, 5)},
        {light("Point", LightType::Point, {1.5, 3.0, 1.5}, true, 3),
         light("Spot", LightType::Spot, {-2.0, 3.5, 2.0}, true, 5),
         light("Sun", LightType::Directional, {2.0, 4.0, 3.0}, true, 1)}};
    for (const std::vector<Light>& lights : rigs) {
        SCOPED_TRACE(lights.front().name + " PCF " + std::to_string(lights.front().shadows->pcf) + ", " +
                     std::to_string(lights.size()) + " light(s)");
        FrameInput input = litScene(lights);
        for (DrawItem& item : input.items)
            item.castsShadows = item.name == "Teapot" || item.name == "Box";
        StillSettings settings{kWidth, kHeight, 1};
        settings.boundShadowLookups = false;
        auto filtered = renderStill(renderer(), input, settings);
        settings.boundShadowLookups = true;
        auto bounded = renderStill(renderer(), input, settings);
        for (Light& l : input.lights)
            l.shadows.reset();
        auto unshadowed = renderStill(renderer(), input, settings);
        ASSERT_TRUE(filtered.ok() && bounded.ok() && unshadowed.ok());
        double largest = 0.0, shadowed = 0.0;
        for (std::size_t i = 0; i < filtered->image.rgba.size(); ++i) {
            largest = std::max(largest, double(std::abs(filtered->image.rgba[i] - bounded->image.rgba[i])));
            shadowed =
                std::max(shadowed, double(std::abs(filtered->image.rgba[i] - unshadowed->image.rgba[i])));
        }
        EXPECT_EQ(largest, 0.0);
        EXPECT_GT(shadowed, 0.1) << "the casters must shadow something, or the test shows nothing";
    }
}

} // namespace
} // namespace speculum::test

// Whole frames: precision far from the origin, textures (and their failure), no NaN, resizing.
#include "render/mesh/Primitives.hpp"
#include "render/mesh/Teapot.hpp"
#include "support/GlTest.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::test {
namespace {

using namespace render;

FrameInput teapotScene(const glm::dvec3& offset) {
    FrameInput input;
    input.settings.background = {0.1, 0.1, 0.12};
    input.camera.position = offset + glm::dvec3(0.0, 0.0, 1.0);
    input.camera.target = offset + glm::dvec3(0.0, 0.0, -3.0);
    input.camera.fovY = 65.0;
    auto teapot = std::make_shared<const MeshData>(makeTeapot(6));
    auto plane = std::make_shared<const MeshData>(makePlane(1));
    DrawItem pot{
        "Teapot",
        glm::scale(glm::translate(glm::dmat4(1.0), offset + glm::dvec3(0.0, -1.0, -3.0)), glm::dvec3(0.25)),
        teapot,
        {},
        true};
    pot.material.specular = 0.5;
    DrawItem table{"Table",
                   glm::scale(glm::translate(glm::dmat4(1.0), offset + glm::dvec3(0.0, -1.0, -3.0)),
                              glm::dvec3(2.0, 1.0, 2.0)),
                   plane,
                   {},
                   true};
    Light light;
    light.name = "Light";
    light.position = offset + glm::dvec3(0.0, 2.0, -2.0);
    light.shadows = render::ShadowParams{512, 3};
    input.items = {pot, table};
    input.lights = {light};
    return input;
}

double meanAbsDifference(const Image& a, const Image& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i)
        sum += std::abs(double(a.rgba[i]) - double(b.rgba[i]));
    return sum / double(a.rgba.size());
}

TEST_F(GlTest, TeapotFrameHasNoNanAndShowsTheTeapotAboveTheTable) {
    const Image image = renderImage(teapotScene({}), 320, 180);
    ASSERT_EQ(image.width, 320);
    for (float v : image.rgba)
        ASSERT_TRUE(std::isfinite(v));
    // The teapot stands on the table in the middle of the view; the top rows show the background.
    const glm::vec4 background = image.at(160, 5);
    EXPECT_NEAR(background.r, 0.1f, 0.01f);
    const glm::vec4 teapot = image.at(160, 110);
    EXPECT_GT(std::abs(teapot.g - background.g), 0.05f);
}

TEST_F(GlTest, SceneFarFromTheOriginRendersLikeTheSameSceneAtTheOrigin) {
    // Camera-relative rendering from double-precision transforms: 1e5 units away, floats alone would
    // quantise positions to about 0.008 units and shake the image apart.
    const Image near = renderImage(teapotScene({}), 320, 180);
    const Image far = renderImage(teapotScene({1e5, 0.0, -1e5}), 320, 180);
    ASSERT_EQ(near.rgba.size(), far.rgba.size());
    EXPECT_LT(meanAbsDifference(near, far), 0.002);
}

TEST_F(GlTest, MissingTextureShowsACheckerAndWarns) {
    FrameInput input = teapotScene({});
    input.items[1].material.texture.path = "/nonexistent/marble.png";
    renderImage(input, 64, 36);
    ASSERT_EQ(lastReport().warnings.size(), 1u);
    EXPECT_NE(lastReport().warnings[0].find("/nonexistent/marble.png"), std::string::npos);
}

TEST_F(GlTest, ResizingTheTargetBetweenFramesKeepsWorking) {
    const FrameInput input = teapotScene({});
    for (int size : {64, 300, 17, 128})
        EXPECT_EQ(renderImage(input, size, size / 2 + 1).width, size);
}

TEST_F(GlTest, SupersamplingAveragesSubPixelSamples) {
    const FrameInput input = teapotScene({});
    const Image one = renderImage(input, 160, 90, 1);
    const Image four = renderImage(input, 160, 90, 4);
    // Same picture, smoother edges: close on average, not identical.
    EXPECT_LT(meanAbsDifference(one, four), 0.02);
    EXPECT_GT(meanAbsDifference(one, four), 0.0);
}

} // namespace
} // namespace speculum::test

#include "scene/evaluate/Snapshot.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/TestPaths.hpp"

namespace speculum::test {
namespace {

// A frame of an unchanged scene looks the same as the one before it, whatever the renderer reused
// (shadow maps, environment maps) between them.
TEST_F(GlTest, ConsecutiveFramesOfAnUnchangedDemoSceneAreIdentical) {
    for (const char* name : {"teapot.speculum.json", "mirrors.speculum.json", "chrome.speculum.json"}) {
        scene::Scene scene;
        std::vector<std::string> warnings;
        ASSERT_TRUE(
            scene::openProject(
                scene, QString::fromStdString(speculum::testSourcePath("resources/scenes/")) + name, warnings)
                .ok());
        scene::MeshLibrary meshes;
        std::vector<scene::Warning> snapshotWarnings;
        const render::FrameInput input = scene::snapshot(scene, 0.25, meshes, snapshotWarnings);
        const render::Image first = renderImage(input, 160, 90);
        const render::Image second = renderImage(input, 160, 90);
        const render::Image third = renderImage(input, 160, 90);
        double worst12 = 0.0, worst23 = 0.0;
        for (std::size_t i = 0; i < first.rgba.size(); ++i) {
            worst12 = std::max(worst12, double(std::abs(first.rgba[i] - second.rgba[i])));
            worst23 = std::max(worst23, double(std::abs(second.rgba[i] - third.rgba[i])));
        }
        EXPECT_EQ(worst12, 0.0) << name << ": first and second frame";
        EXPECT_EQ(worst23, 0.0) << name << ": second and third frame";
    }
}

// A redrawn shadow map clears only the texels its casters covered and cover now: a caster that moved (within
// a face, or onto another face of a point light's cube) leaves no shadow behind, for every kind of light.
// The frame matches a fresh renderer's, which has never drawn the old position.
TEST_F(GlTest, AShadowCasterThatMovedLeavesNoShadowBehind) {
    for (const LightType type : {LightType::Point, LightType::Spot, LightType::Directional}) {
        FrameInput before = teapotScene(glm::dvec3(0.0));
        before.items[1].castsShadows = false; // the teapot alone: its texels are a small part of the map
        Light& light = before.lights[0];
        light.type = type;
        light.direction = glm::normalize(glm::dvec3(0.2, -1.0, -0.3));
        light.spotAngle = 60.0;
        FrameInput after = before;
        // The teapot moves across the table, and (point light) from under the light to its side.
        after.items[0].world =
            glm::scale(glm::translate(glm::dmat4(1.0), {1.3, -0.5, -3.6}), glm::dvec3(0.25));
        (void)renderImage(before, 160, 90);
        const Image moved = renderImage(after, 160, 90);
        auto fresh = Renderer::create();
        ASSERT_TRUE(fresh.ok()) << fresh.error();
        auto still = renderStill(**fresh, after, {160, 90, 1});
        ASSERT_TRUE(still.ok()) << still.error();
        const Image& expected = (*still).image;
        double worst = 0.0;
        for (std::size_t i = 0; i < moved.rgba.size(); ++i)
            worst = std::max(worst, double(std::abs(moved.rgba[i] - expected.rgba[i])));
        EXPECT_EQ(worst, 0.0) << "light type " << int(type);
    }
}

} // namespace
} // namespace speculum::test

// The tracer never produces NaN, whatever the input, and its threading, progress and cancel behave.
#include "render/reference/Tracer.hpp"
#include "support/SceneBuilder.hpp"

#include <atomic>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace speculum::test {
namespace {

using render::FrameInput;
using render::reference::Tracer;
using render::reference::TraceSettings;

FrameInput brokenScene() {
    FrameInput input;
    input.camera.position = {0, 0.5, 2};
    input.camera.target = {0, 0, 0};
    input.settings.mirrorDepth = 8;

    auto mesh = std::make_shared<render::MeshData>();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    mesh->positions = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0},         {0.5, 0.5, 0},
                       {2, 2, 0},  {3, 3, 0}, {float(nan), 0, 0}};
    mesh->normals = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    mesh->uvs = {{0, 0}, {1, 0}, {0, 1}, {float(nan), 0}, {0, 0}, {0, 0}, {0, 0}};
    mesh->indices = {0, 1, 2,   // zero normals: falls back to the face normal
                     3, 3, 3,   // a point
                     3, 4, 5,   // collinear
                     0, 1, 6,   // a NaN vertex
                     0, 1, 99}; // out of range
    render::Material m;
    m.specular = 1.0;
    m.shininess = 0.0; // pow(x, 0) and a clamped shininess
    input.items.push_back(item("Broken", mesh, glm::dmat4(1.0), m));
    input.items.push_back(item("Collapsed", boxMesh(), placed({0, 0, -1}, {1, 0, 1}), m)); // zero-height box
    input.items.push_back(item("Missing", nullptr, glm::dmat4(1.0), m));
    input.items.push_back(item("Textured", planeMesh(), placed({0, -0.5, 0}, {3, 1, 3}), m));
    input.items.back().material.texture.path = "/no/such/texture.png";

    render::Mirror flat = mirror({0, 0, -2}, {0, 0, 1}, {0, 0}); // zero size: no plane
    input.mirrors.push_back(flat);
    input.mirrors.push_back(mirror({0, -0.4, 0}, {0, 1, 0}, {4, 4}));
    input.mirrors.back().fresnel = true;
    input.mirrors.back().reflectivity = 2.0; // out of range: clamped

    render::Light onSurface; // exactly on the textured floor
    onSurface.position = {0, -0.5, 0};
    onSurface.shadows = render::ShadowParams{};
    render::Light noDirection;
    noDirection.type = render::LightType::Directional;
    noDirection.direction = {0, 0, 0};
    noDirection.shadows = render::ShadowParams{16, 9};
    render::Light sharpSpot;
    sharpSpot.type = render::LightType::Spot;
    sharpSpot.position = {0, 2, 0};
    sharpSpot.spotBlend = 0.0;
    sharpSpot.shadows = render::ShadowParams{1, 3};
    input.lights = {onSurface, noDirection, sharpSpot};

    render::Reflector reflector;
    reflector.mesh = mesh;
    reflector.world = placed({0.5, 0, -0.5}, {1, 1, 0}); // flattened to zero depth
    input.reflectors = {reflector};
    return input;
}

bool allFinite(const render::Image& image) {
    for (float v : image.rgba)
        if (!std::isfinite(v))
            return false;
    return true;
}

TEST(ReferenceTracerRobustness, DegenerateInputGivesNoNaNAndWarnings) {
    auto tracer = Tracer::create(brokenScene());
    ASSERT_TRUE(tracer.ok()) << tracer.error();
    bool droppedWarning = false, textureWarning = false;
    for (const std::string& w : tracer->warnings()) {
        droppedWarning |= w.find("invalid triangles") != std::string::npos;
        textureWarning |= w.find("/no/such/texture.png") != std::string::npos;
    }
    EXPECT_TRUE(droppedWarning);
    EXPECT_TRUE(textureWarning);
    for (auto shadows : {render::reference::ShadowMode::Hard, render::reference::ShadowMode::PcfFootprint}) {
        TraceSettings settings;
        settings.width = 64;
        settings.height = 48;
        settings.ssaa = 2;
        settings.shadows = shadows;
        auto result = tracer->render(settings);
        ASSERT_TRUE(result.ok()) << result.error();
        EXPECT_TRUE(allFinite(result->image));
    }
}

TEST(ReferenceTracerRobustness, CameraLookingAlongItsUpVectorStillRenders) {
    FrameInput input = brokenScene();
    input.camera.position = {0, 5, 0};
    input.camera.target = {0, 0, 0};
    input.camera.up = {0, 1, 0};
    auto tracer = Tracer::create(input);
    ASSERT_TRUE(tracer.ok());
    TraceSettings settings;
    settings.width = 16;
    settings.height = 16;
    auto result = tracer->render(settings);
    ASSERT_TRUE(result.ok());
    EXPECT_TRUE(allFinite(result->image));
}

TEST(ReferenceTracerRobustness, EmptySceneIsBackground) {
    FrameInput input;
    input.settings.background = {0.25, 0.5, 0.75};
    auto tracer = Tracer::create(input);
    ASSERT_TRUE(tracer.ok());
    TraceSettings settings;
    settings.width = 8;
    settings.height = 4;
    auto result = tracer->render(settings);
    ASSERT_TRUE(result.ok());
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            EXPECT_EQ(result->image.at(x, y), glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
            EXPECT_EQ(result->ids.at(x, y).kind, render::reference::HitKind::Background);
        }
}

TEST(ReferenceTracerRobustness, BadSizeIsAnError) {
    auto tracer = Tracer::create(FrameInput{});
    ASSERT_TRUE(tracer.ok());
    TraceSettings settings;
    settings.width = 0;
    auto result = tracer->render(settings);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().find("0x720"), std::string::npos) << result.error();
}

TEST(ReferenceTracerRobustness, ThreadCountDoesNotChangeTheImage) {
    auto tracer = Tracer::create(brokenScene());
    ASSERT_TRUE(tracer.ok());
    TraceSettings settings;
    settings.width = 40;
    settings.height = 30;
    settings.threads = 1;
    auto one = tracer->render(settings);
    settings.threads = 5;
    auto five = tracer->render(settings);
    ASSERT_TRUE(one.ok() && five.ok());
    EXPECT_EQ(one->image.rgba, five->image.rgba);
    EXPECT_EQ(one->ids.ids, five->ids.ids);
}

TEST(ReferenceTracerRobustness, ProgressRisesToOneAndCancelStops) {
    FrameInput input = brokenScene();
    auto tracer = Tracer::create(input);
    ASSERT_TRUE(tracer.ok());
    TraceSettings settings;
    settings.width = 320;
    settings.height = 240;
    settings.ssaa = 3;
    std::vector<double> seen;
    auto done = tracer->render(settings, [&](double f) {
        seen.push_back(f);
        return true;
    });
    ASSERT_TRUE(done.ok());
    ASSERT_FALSE(seen.empty());
    EXPECT_EQ(seen.back(), 1.0);
    for (std::size_t i = 1; i < seen.size(); ++i)
        EXPECT_GE(seen[i], seen[i - 1]);

    int calls = 0;
    auto cancelled = tracer->render(settings, [&](double) { return ++calls < 1; });
    ASSERT_FALSE(cancelled.ok());
    EXPECT_EQ(cancelled.error(), "render cancelled");
}

} // namespace
} // namespace speculum::test

// The exact tracer held to the same pictures as the rasterizer (tests/gl/test_materials.cpp): textures
// upright and un-mirrored on the built-in plane and box, wrap modes, vertex colours, alpha masks on
// primary, mirror and shadow rays, normal maps, emission textures, 16-bit textures.
#include "render/image/ColorSpace.hpp"
#include "render/imageio/ImageWriter.hpp"
#include "render/imageio/TextureLoader.hpp"
#include "render/reference/Tracer.hpp"
#include "support/MaterialScenes.hpp"
#include "support/SceneBuilder.hpp"

#include <cstdlib>
#include <gtest/gtest.h>

namespace speculum::test {
namespace {

using namespace materials;
using render::FrameInput;
using render::reference::Tracer;
using render::reference::TraceResult;
using render::reference::TraceSettings;

TraceResult traced(const FrameInput& input, int width, int height) {
    auto tracer = Tracer::create(input);
    EXPECT_TRUE(tracer.ok()) << (tracer.ok() ? "" : tracer.error());
    TraceSettings settings;
    settings.width = width;
    settings.height = height;
    auto result = tracer->render(settings);
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error());
    if (const char* folder = std::getenv("SPECULUM_TEST_DUMP")) {
        const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
        EXPECT_TRUE(
            render::writeImage(std::string(folder) + "/" + info->name() + "_reference.png", result->image)
                .ok());
    }
    return std::move(*result);
}

TEST(MaterialTracing, TextureOnThePlaneSeenFromAboveIsUprightAndUnmirrored) {
    const std::string texture = writeQuadrantTexture(freshFolder());
    const TraceResult r = traced(orientationScene(View::PlaneFromAbove, showTexture(texture)), 96, 96);
    expectUprightQuadrants(r.image, "plane from above");
}

TEST(MaterialTracing, TextureOnTheBoxTopAndFrontIsUprightAndUnmirrored) {
    const std::string texture = writeQuadrantTexture(freshFolder());
    expectUprightQuadrants(traced(orientationScene(View::BoxFromAbove, showTexture(texture)), 96, 96).image,
                           "box top face from above");
    expectUprightQuadrants(traced(orientationScene(View::BoxFromFront, showTexture(texture)), 96, 96).image,
                           "box +Z face from the front");
}

TEST(MaterialTracing, EmbeddedImagesShowLikeTheirFiles) {
    // A model's embedded texture arrives decoded (TextureSource::image): it must land like the same file.
    const std::string path = writeQuadrantTexture(freshFolder());
    auto image = render::loadTexture(path);
    ASSERT_TRUE(image.ok()) << image.error();
    render::Material m = showTexture("");
    m.texture.path = "/abs/model.glb#*0";
    m.texture.image = std::make_shared<const render::TextureImage>(std::move(*image));
    expectUprightQuadrants(traced(orientationScene(View::PlaneFromAbove, m), 96, 96).image, "embedded image");
}

TEST(MaterialTracing, WrapModesRepeatClampAndMirrorTheTexture) {
    const std::string texture = writeQuadrantTexture(freshFolder());
    for (render::TextureWrap wrap :
         {render::TextureWrap::ClampToEdge, render::TextureWrap::Repeat, render::TextureWrap::MirroredRepeat})
        expectWrapSamples(traced(wrapScene(texture, wrap), 128, 128).image, wrap, "tracer");
}

TEST(MaterialTracing, VertexColoursMultiplyTheBaseColour) {
    FrameInput input = orientationScene(View::PlaneFromAbove, showTexture(""));
    input.items[0].mesh = planeWith(true, false);
    const render::Image image = traced(input, 96, 96).image;
    const glm::vec4 bottomLeft = image.at(30, 66), bottomRight = image.at(66, 66), topLeft = image.at(30, 30);
    EXPECT_GT(bottomLeft.r, 2.0f * std::max(bottomLeft.g, bottomLeft.b)) << "red corner";
    EXPECT_GT(bottomRight.g, 2.0f * std::max(bottomRight.r, bottomRight.b)) << "green corner";
    EXPECT_GT(topLeft.b, 2.0f * std::max(topLeft.r, topLeft.g)) << "blue corner";
}

TEST(MaterialTracing, AlphaMaskedSurfacesLetCameraRaysThrough) {
    render::Material m = showTexture(writeStripeMask(freshFolder()));
    m.alphaMode = render::AlphaMode::Mask;
    FrameInput input = orientationScene(View::PlaneFromAbove, m);
    // A green floor under the masked plane: what the holes show.
    input.items.push_back(item("Floor", planeMesh(), placed({0, -0.5, 0}, {3, 1, 3}), emissive({0, 1, 0})));
    const TraceResult r = traced(input, 128, 128);
    int cut = 0, kept = 0;
    for (int x = 40; x < 88; ++x) {
        const glm::vec4 p = r.image.at(x, 64);
        cut += p.g > 0.9f && p.r < 0.1f;
        kept += p.r > 0.7f;
    }
    EXPECT_GT(cut, 15) << "no holes: the mask was ignored";
    EXPECT_GT(kept, 15) << "no surface left";
}

TEST(MaterialTracing, AlphaMaskedSurfacesLetMirrorRaysThrough) {
    // A mirror on the ground facing up, the masked plane above it facing down, the camera above both
    // looking down: the mirror shows the plane's underside, whose holes show what is above it (a red
    // ceiling behind the camera is not seen directly, only through the holes in the reflection).
    render::Material m = showTexture(writeStripeMask(freshFolder()));
    m.alphaMode = render::AlphaMode::Mask;
    FrameInput input;
    input.settings.background = glm::dvec3(0.0);
    input.settings.ambient = 1.0;
    input.camera.position = {0, 1.5, 0};
    input.camera.target = {0, 0, 0};
    input.camera.up = {0, 0, -1};
    input.camera.fovY = 40.0;
    input.camera.far = 20.0;
    input.mirrors.push_back(mirror({0, 0, 0}, {0, 1, 0}, {8, 8}));
    input.mirrors[0].reflectivity = 1.0;
    // The masked plane between camera and mirror, seen through only in its holes.
    input.items.push_back(item("Masked", planeMesh(), placed({0, 0.5, 0}, {3, 1, 3}), m));
    input.items.push_back(item("Ceiling", planeMesh(), placed({0, 3.0, 0}, {6, 1, 6}), emissive({1, 0, 0})));
    const TraceResult r = traced(input, 96, 96);
    // Through a hole, the mirror; in the mirror, the plane again from below, and through its holes the
    // ceiling: some pixels are the ceiling's red (possible only through two masked hits), others the
    // plane's own colour.
    int ceiling = 0;
    for (int x = 0; x < 96; ++x) {
        const glm::vec4 p = r.image.at(x, 48);
        ceiling += p.r > 0.9f && p.g < 0.1f && p.b < 0.1f;
    }
    EXPECT_GT(ceiling, 5);
}

TEST(MaterialTracing, AlphaMaskCutsTheShadowToo) {
    const std::string stripes = writeStripeMask(freshFolder());
    const double opaque =
        litShare(traced(maskedShadowScene(stripes, render::AlphaMode::Opaque), 96, 96).image);
    const double masked = litShare(traced(maskedShadowScene(stripes, render::AlphaMode::Mask), 96, 96).image);
    EXPECT_LT(opaque, 0.3);
    EXPECT_GT(masked, 0.45);
    EXPECT_LT(masked, 0.8);
}

TEST(MaterialTracing, NormalMapBendsTheLightingOnlyWithTangents) {
    const std::string bands = writeBandNormalMap(freshFolder());
    // The plane from above, lit by a directional light from the +X side: bands leaning towards +X catch
    // more light than those leaning away.
    render::Material m;
    m.color = glm::dvec3(1.0);
    m.ambient = 0.0;
    m.normalTexture.path = bands;
    FrameInput input = orientationScene(View::PlaneFromAbove, m);
    render::Light sun;
    sun.type = render::LightType::Directional;
    sun.direction = glm::normalize(glm::dvec3(-1.0, -1.0, 0.0));
    input.lights.push_back(sun);
    input.items[0].mesh = planeWith(false, true);
    const render::Image bumpy = traced(input, 128, 128).image;
    float lo = 1e9f, hi = 0.0f;
    for (int x = 40; x < 88; ++x) {
        lo = std::min(lo, bumpy.at(x, 64).g);
        hi = std::max(hi, bumpy.at(x, 64).g);
    }
    // cos(45° - 35°) against cos(45° + 35°): 0.98 against 0.17.
    EXPECT_GT(hi, 0.9f);
    EXPECT_LT(lo, 0.3f);
    // Without tangents the map cannot apply: the plane is evenly lit at cos 45°.
    input.items[0].mesh = planeWith(false, false);
    const render::Image flatLit = traced(input, 128, 128).image;
    EXPECT_NEAR(flatLit.at(50, 64).g, 0.7071f, 0.01f);
    EXPECT_NEAR(flatLit.at(70, 64).g, 0.7071f, 0.01f);
}

TEST(MaterialTracing, EmissionTextureAndSpecularColour) {
    const std::string texture = writeQuadrantTexture(freshFolder());
    render::Material m;
    m.color = glm::dvec3(0.0);
    m.ambient = 0.0;
    m.emission = glm::dvec3(0.5);
    m.emissionTexture.path = texture;
    FrameInput input = orientationScene(View::PlaneFromAbove, m);
    const render::Image image = traced(input, 96, 96).image;
    // emission · texture: the quadrants at half strength, upright.
    const glm::vec4 topRight = image.at(60, 36);
    EXPECT_NEAR(topRight.g, 0.5f, 0.01f);
    EXPECT_NEAR(topRight.r, 0.0f, 0.01f);
    // A highlight straight up from a light above the camera takes the specular colour.
    render::Material shiny;
    shiny.color = glm::dvec3(0.0);
    shiny.ambient = 0.0;
    shiny.specular = 1.0;
    shiny.shininess = 2.0;
    shiny.specularColor = glm::dvec3(1.0, 0.5, 0.0);
    FrameInput lit = orientationScene(View::PlaneFromAbove, shiny);
    render::Light sun;
    sun.type = render::LightType::Directional;
    sun.direction = {0, -1, 0};
    lit.lights.push_back(sun);
    const glm::vec4 centre = traced(lit, 32, 32).image.at(16, 16);
    EXPECT_GT(centre.r, 0.9f);
    EXPECT_NEAR(centre.g, 0.5f * centre.r, 0.01f);
    EXPECT_LT(centre.b, 0.01f);
}

TEST(MaterialTracing, SixteenBitTexturesKeepTheirPrecision) {
    const std::filesystem::path path = freshFolder() / "deep.png";
    const std::uint16_t code = 33024;
    {
        auto out = OIIO::ImageOutput::create(path.string());
        ASSERT_TRUE(out);
        OIIO::ImageSpec spec(4, 4, 3, OIIO::TypeDesc::UINT16);
        ASSERT_TRUE(out->open(path.string(), spec));
        std::vector<std::uint16_t> pixels(4 * 4 * 3, code);
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT16, pixels.data()));
        ASSERT_TRUE(out->close());
    }
    const render::Image image =
        traced(orientationScene(View::PlaneFromAbove, showTexture(path.string())), 32, 32).image;
    EXPECT_NEAR(image.at(16, 16).g, render::srgbToLinear(code / 65535.0f), 1e-4f);
}

} // namespace
} // namespace speculum::test

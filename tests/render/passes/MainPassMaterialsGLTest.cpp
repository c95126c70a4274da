// Textures and the model-file material features in the rasterizer: which way up a texture shows on the
// built-in plane and box, wrap modes, vertex colours, alpha masks on surfaces and in shadows, and 16-bit
// textures kept beyond 8 bits. tests/render/reference/test_material_tracing.cpp holds the tracer to the
// same pictures.
#include "render/gl/Program.hpp"
#include "render/image/ColorSpace.hpp"
#include "render/imageio/ImageWriter.hpp"
#include "render/imageio/TextureLoader.hpp"
#include "support/BombPng.hpp"
#include "support/GlTest.hpp"
#include "support/MaterialScenes.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>

namespace speculum::test {
namespace {

using namespace materials;
using render::FrameInput;

class Materials : public GlTest {
protected:
    // With SPECULUM_TEST_DUMP set to a folder, a rendered image is written there to be looked at.
    void dump(const std::string& name, const render::Image& image) {
        if (const char* folder = std::getenv("SPECULUM_TEST_DUMP")) {
            EXPECT_TRUE(render::writeImage(std::string(folder) + "/" + name + ".png", image).ok());
        }
    }
};

TEST_F(Materials, TextureOnThePlaneSeenFromAboveIsUprightAndUnmirrored) {
    const std::string texture = writeQuadrantTexture(freshFolder());
    const render::Image image =
        renderImage(orientationScene(View::PlaneFromAbove, showTexture(texture)), 96, 96);
    dump("orientation_plane_raster", image);
    expectUprightQuadrants(image, "plane from above");
}

// The editor draws through this path: a texture that promises 2 GiB of texels in 69 bytes must cost a
// warning naming it and the checker, never the memory it promises or an exception out of the frame.
TEST_F(Materials, ADecompressionBombTextureIsAWarningNamingItAndTheFrameIsDrawn) {
    const std::string bomb = (freshFolder() / "bomb.png").string();
    writeBombPng(bomb);
    const auto start = std::chrono::steady_clock::now();
    const render::Image image =
        renderImage(orientationScene(View::PlaneFromAbove, showTexture(bomb)), 32, 32);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0)
        << "refused from its header and first bytes";
    EXPECT_EQ(image.width, 32) << "the frame is drawn";
    const std::vector<std::string>& warnings = lastReport().warnings;
    const bool named = std::any_of(warnings.begin(), warnings.end(), [&](const std::string& w) {
        return w.find(bomb) != std::string::npos && w.find("16384×16384") != std::string::npos;
    });
    EXPECT_TRUE(named) << "a warning names the file and its declared size; got " << warnings.size()
                       << " warnings";
}

TEST_F(Materials, TextureOnTheBoxTopAndFrontIsUprightAndUnmirrored) {
    const std::string texture = writeQuadrantTexture(freshFolder());
    const render::Image top = renderImage(orientationScene(View::BoxFromAbove, showTexture(texture)), 96, 96);
    dump("orientation_box_top_raster", top);
    expectUprightQuadrants(top, "box top face from above");
    const render::Image front =
        renderImage(orientationScene(View::BoxFromFront, showTexture(texture)), 96, 96);
    dump("orientation_box_front_raster", front);
    expectUprightQuadrants(front, "box +Z face from the front");
}

TEST_F(Materials, WrapModesRepeatClampAndMirrorTheTexture) {
    const std::string texture = writeQuadrantTexture(freshFolder());
    // One renderer, one texture, three materials: the wrap belongs to the material, not to the image.
    for (render::TextureWrap wrap : {render::TextureWrap::ClampToEdge, render::TextureWrap::Repeat,
                                     render::TextureWrap::MirroredRepeat}) {
        const render::Image image = renderImage(wrapScene(texture, wrap), 128, 128);
        expectWrapSamples(image, wrap, "rasterizer");
    }
}

TEST_F(Materials, VertexColoursMultiplyTheBaseColour) {
    render::Material white = showTexture("");
    FrameInput input = orientationScene(View::PlaneFromAbove, white);
    input.items[0].mesh = planeWith(true, false);
    const render::Image image = renderImage(input, 96, 96);
    // Corners (u, v): red (0, 0) bottom left on screen, green (1, 0) bottom right, blue (0, 1) top left.
    const glm::vec4 bottomLeft = image.at(30, 66), bottomRight = image.at(66, 66), topLeft = image.at(30, 30);
    EXPECT_GT(bottomLeft.r, 2.0f * std::max(bottomLeft.g, bottomLeft.b)) << "red corner";
    EXPECT_GT(bottomRight.g, 2.0f * std::max(bottomRight.r, bottomRight.b)) << "green corner";
    EXPECT_GT(topLeft.b, 2.0f * std::max(topLeft.r, topLeft.g)) << "blue corner";
    // The same plane without colours is white: the colours come from the vertices.
    input.items[0].mesh = planeWith(false, false);
    const render::Image plain = renderImage(input, 96, 96);
    EXPECT_NEAR(plain.at(30, 66).g, 1.0f, 0.02f);
}

TEST_F(Materials, AlphaMaskCutsTheSurface) {
    const std::filesystem::path folder = freshFolder();
    render::Material m = showTexture(writeStripeMask(folder));
    m.alphaMode = render::AlphaMode::Mask;
    FrameInput input = orientationScene(View::PlaneFromAbove, m);
    input.settings.background = glm::dvec3(0.0, 0.0, 1.0);
    const render::Image image = renderImage(input, 128, 128);
    dump("alpha_mask_raster", image);
    // Stripes 4 texels wide across 16: along the middle row the plane shows opaque, cut, opaque, cut.
    const int y = 64;
    int cut = 0, kept = 0;
    for (int x = 40; x < 88; ++x) {
        const glm::vec4 p = image.at(x, y);
        cut += p.b > 0.9f && p.r < 0.1f;  // the blue background through the holes
        kept += p.r > 0.7f && p.b < 0.5f; // the stripes' own colour
    }
    EXPECT_GT(cut, 15) << "no holes: the mask was ignored";
    EXPECT_GT(kept, 15) << "no surface left";
    // Opaque, the same texture covers the background everywhere (its colour stays where alpha is 0).
    input.items[0].material.alphaMode = render::AlphaMode::Opaque;
    const render::Image opaque = renderImage(input, 128, 128);
    for (int x = 40; x < 88; ++x)
        ASSERT_LT(opaque.at(x, y).b, 0.6f) << x;
}

TEST_F(Materials, AlphaMaskCutsTheShadowToo) {
    const std::string stripes = writeStripeMask(freshFolder());
    const render::Image opaque = renderImage(maskedShadowScene(stripes, render::AlphaMode::Opaque), 96, 96);
    const render::Image masked = renderImage(maskedShadowScene(stripes, render::AlphaMode::Mask), 96, 96);
    const render::Image blend = renderImage(maskedShadowScene(stripes, render::AlphaMode::Blend), 96, 96);
    dump("masked_shadow_raster", masked);
    // The view is three quarters in the quad's shadow: opaque, a quarter is lit; masked, half the
    // shadow falls through the stripes.
    EXPECT_LT(litShare(opaque), 0.3);
    EXPECT_GT(litShare(masked), 0.45);
    EXPECT_LT(litShare(masked), 0.8);
    EXPECT_NEAR(litShare(blend), litShare(masked), 0.02) << "Blend is drawn as Mask at 0.5";
}

TEST_F(Materials, SixteenBitTexturesKeepTheirPrecision) {
    const std::filesystem::path path = freshFolder() / "deep.png";
    // 33024/65535 lies between the 8-bit codes 128 and 129: rounded to 8 bits it would come out at 128.
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
        renderImage(orientationScene(View::PlaneFromAbove, showTexture(path.string())), 32, 32);
    const float exact = render::srgbToLinear(code / 65535.0f);
    const float eightBit = render::srgb8ToLinear(128);
    ASSERT_GT(exact - eightBit, 1.5e-3f);
    EXPECT_NEAR(image.at(16, 16).g, exact, 4e-4f) << "8-bit rounding would give " << eightBit;
}

TEST_F(Materials, NormalMapBendsTheLightingOnlyWithTangents) {
    // As in the tracer's test: bands leaning towards the light catch cos 10°, the others cos 80°.
    render::Material m;
    m.color = glm::dvec3(1.0);
    m.ambient = 0.0;
    m.normalTexture.path = writeBandNormalMap(freshFolder());
    FrameInput input = orientationScene(View::PlaneFromAbove, m);
    render::Light sun;
    sun.type = render::LightType::Directional;
    sun.direction = glm::normalize(glm::dvec3(-1.0, -1.0, 0.0));
    input.lights.push_back(sun);
    input.items[0].mesh = planeWith(false, true);
    const render::Image bumpy = renderImage(input, 128, 128);
    dump("normal_map_raster", bumpy);
    float lo = 1e9f, hi = 0.0f;
    for (int x = 40; x < 88; ++x) {
        lo = std::min(lo, bumpy.at(x, 64).g);
        hi = std::max(hi, bumpy.at(x, 64).g);
    }
    EXPECT_GT(hi, 0.9f);
    EXPECT_LT(lo, 0.3f);
    input.items[0].mesh = planeWith(false, false);
    const render::Image flatLit = renderImage(input, 128, 128);
    EXPECT_NEAR(flatLit.at(50, 64).g, 0.7071f, 0.01f);
    EXPECT_NEAR(flatLit.at(70, 64).g, 0.7071f, 0.01f);
}

TEST_F(Materials, EmissionTextureEmbeddedImageAndSpecularColour) {
    // The emission texture given as a decoded image, as a model's embedded texture arrives.
    auto decoded = render::loadTexture(writeQuadrantTexture(freshFolder()));
    ASSERT_TRUE(decoded.ok()) << decoded.error();
    render::Material m;
    m.color = glm::dvec3(0.0);
    m.ambient = 0.0;
    m.emission = glm::dvec3(0.5);
    m.emissionTexture.path = "/abs/model.glb#*1";
    m.emissionTexture.image = std::make_shared<const render::TextureImage>(std::move(*decoded));
    const render::Image image = renderImage(orientationScene(View::PlaneFromAbove, m), 96, 96);
    const glm::vec4 topRight = image.at(60, 36);
    EXPECT_NEAR(topRight.g, 0.5f, 0.01f);
    EXPECT_NEAR(topRight.r, 0.0f, 0.01f);
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
    const glm::vec4 centre = renderImage(lit, 32, 32).at(16, 16);
    EXPECT_GT(centre.r, 0.9f);
    EXPECT_NEAR(centre.g, 0.5f * centre.r, 0.01f);
    EXPECT_LT(centre.b, 0.01f);
}

TEST_F(Materials, EveryMaterialDrawVariantBuilds) {
    // A draw variant that fails to build falls back silently to the general shader (gl::Program::useWith),
    // which would make the variant comparisons (test_lighting_variants) compare the general shader with
    // itself: every combination must build for each lit fragment shader.
    const char* features[] = {"MATERIAL_TEXTURE", "MATERIAL_EMISSION_TEXTURE", "MATERIAL_NORMAL_TEXTURE",
                              "MATERIAL_ALPHA_MASK", "MATERIAL_VERTEX_COLOR"};
    const std::string lights = "#define LIGHT_COUNT 1\n#define LIGHT_SLOT_0 0\n#define LIGHT_CUBE_0 0\n";
    for (int combination = 0; combination < 32; ++combination) {
        std::string defines = lights;
        for (int f = 0; f < 5; ++f)
            if (combination & (1 << f))
                defines += std::string("#define ") + features[f] + " 0\n";
        for (const char* fragment : {"mesh.frag", "mirror.frag", "reflector.frag"}) {
            if (std::string(fragment) != "mesh.frag" && combination != 0 && combination != 31)
                continue;
            auto program = render::gl::Program::build("mesh.vert", fragment, defines);
            EXPECT_TRUE(program.ok()) << fragment << " with\n"
                                      << defines << (program.ok() ? "" : program.error());
        }
    }
    auto masked = render::gl::Program::build("shadow.vert", "shadow.frag", "#define SHADOW_MASK 1\n");
    EXPECT_TRUE(masked.ok()) << (masked.ok() ? "" : masked.error());
}

} // namespace
} // namespace speculum::test

#pragma once

// Scenes shared by the rasterizer's and the tracer's texture and material tests (tests/gl and
// tests/render/reference), so both renderers are held to the same pictures.
#include "render/frame/FrameInput.hpp"
#include "render/image/Image.hpp"
#include "render/mesh/Primitives.hpp"
#include "support/TestPaths.hpp"

#include <OpenImageIO/imageio.h>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>

namespace speculum::test::materials {

// A fresh, empty folder per test under the build's test-data folder.
inline std::filesystem::path freshFolder() {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path folder = std::filesystem::path(speculum::testDataPath()) / "materials" /
                                         (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

// The four quadrant colours of the test image, as a person sees the file in an image viewer.
enum Quadrant { TopLeft, TopRight, BottomLeft, BottomRight };
inline const std::array<glm::dvec3, 4> kQuadrantColours = {
    glm::dvec3(1, 0, 0), // top left: red
    glm::dvec3(0, 1, 0), // top right: green
    glm::dvec3(0, 0, 1), // bottom left: blue
    glm::dvec3(1, 1, 0), // bottom right: yellow
};
inline const char* const kQuadrantNames[4] = {"red (top left)", "green (top right)", "blue (bottom left)",
                                              "yellow (bottom right)"};

// Writes an RGBA image through OpenImageIO, `rgba` in file order (row 0 = the top row, as viewers show).
inline void writeRgba8(const std::filesystem::path& path, int width, int height,
                       const std::vector<std::uint8_t>& rgba) {
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out) << OIIO::geterror();
    OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
    spec.alpha_channel = 3;
    spec.attribute("oiio:UnassociatedAlpha", 1);
    ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, rgba.data())) << out->geterror();
    ASSERT_TRUE(out->close()) << out->geterror();
}

// A 32×32 PNG in four solid quadrants (kQuadrantColours), written by OpenImageIO, not by the loader under
// test. Returns its path.
inline std::string writeQuadrantTexture(const std::filesystem::path& folder) {
    const int size = 32;
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(size) * size * 4);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const int q = (y < size / 2 ? 0 : 2) + (x < size / 2 ? 0 : 1);
            std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * size + x) * 4];
            for (int c = 0; c < 3; ++c)
                p[c] = kQuadrantColours[q][c] > 0.5 ? 255 : 0;
            p[3] = 255;
        }
    const std::filesystem::path path = folder / "quadrants.png";
    writeRgba8(path, size, size, rgba);
    return path.string();
}

// Shows its texture as is: base 1 lit by ambient 1 alone (no lights), so a pixel is the texel's colour.
inline render::Material showTexture(const std::string& texture) {
    render::Material m;
    m.color = glm::dvec3(1.0);
    m.ambient = 1.0;
    m.diffuse = 0.0;
    m.specular = 0.0;
    m.texture.path = texture;
    return m;
}

// What the orientation views look at.
enum class View {
    PlaneFromAbove, // the built-in plane, camera above it with -Z up the screen
    BoxFromAbove,   // the built-in box's top face, the same way
    BoxFromFront,   // the box's +Z face, camera in front with +Y up
};

inline render::FrameInput orientationScene(View view, const render::Material& material) {
    render::FrameInput input;
    input.settings.background = glm::dvec3(0.0);
    input.settings.ambient = 1.0;
    render::DrawItem item;
    item.name = "Textured";
    item.material = material;
    item.castsShadows = false;
    item.mesh = std::make_shared<const render::MeshData>(view == View::PlaneFromAbove ? render::makePlane(1)
                                                                                      : render::makeBox());
    input.items.push_back(item);
    render::Camera& camera = input.camera;
    camera.fovY = 60.0;
    camera.near = 0.1;
    camera.far = 20.0;
    switch (view) {
    case View::PlaneFromAbove:
        camera.position = {0, 3, 0};
        camera.target = {0, 0, 0};
        camera.up = {0, 0, -1};
        break;
    case View::BoxFromAbove:
        camera.position = {0, 4, 0};
        camera.target = {0, 0, 0};
        camera.up = {0, 0, -1};
        break;
    case View::BoxFromFront:
        camera.position = {0, 0, 4};
        camera.target = {0, 0, 0};
        camera.up = {0, 1, 0};
        break;
    }
    return input;
}

// The quadrant colour nearest to a pixel (-1 when the pixel is nearer black: background).
inline int nearestQuadrant(const glm::vec4& pixel) {
    const glm::dvec3 c(pixel);
    int best = -1;
    double bestDistance = glm::length(c);
    for (int q = 0; q < 4; ++q) {
        const double d = glm::length(c - kQuadrantColours[q]);
        if (d < bestDistance) {
            bestDistance = d;
            best = q;
        }
    }
    return best;
}

// Checks that each quadrant of the textured face lands in the same quadrant of the screen, i.e. the image
// shows upright and un-mirrored. The face covers the middle of the square image in every view; samples are
// taken at a quarter of the face's width from its centre.
inline void expectUprightQuadrants(const render::Image& image, const char* what) {
    ASSERT_GT(image.width, 0);
    const double offset = 0.12; // of the image size: inside the face, well inside its quadrants
    const struct {
        double x, y;
        Quadrant expected;
    } samples[] = {{0.5 - offset, 0.5 - offset, TopLeft},
                   {0.5 + offset, 0.5 - offset, TopRight},
                   {0.5 - offset, 0.5 + offset, BottomLeft},
                   {0.5 + offset, 0.5 + offset, BottomRight}};
    for (const auto& s : samples) {
        const int x = static_cast<int>(s.x * image.width), y = static_cast<int>(s.y * image.height);
        const int got = nearestQuadrant(image.at(x, y));
        EXPECT_EQ(got, s.expected) << what << ": screen pixel (" << x << ", " << y << ") shows "
                                   << (got < 0 ? "background" : kQuadrantNames[got]) << ", expected "
                                   << kQuadrantNames[s.expected];
    }
}

// A 16×16 RGBA PNG of vertical stripes 4 texels wide, alternately opaque white and fully transparent
// (colour kept): an alpha cut-out.
inline std::string writeStripeMask(const std::filesystem::path& folder) {
    const int size = 16;
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(size) * size * 4);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * size + x) * 4];
            const bool opaque = (x / 4) % 2 == 0;
            p[0] = 230;
            p[1] = opaque ? 200 : 30;
            p[2] = 120;
            p[3] = opaque ? 255 : 0;
        }
    const std::filesystem::path path = folder / "stripes.png";
    writeRgba8(path, size, size, rgba);
    return path.string();
}

// A 16×16 tangent-space normal map (data, 8-bit): vertical bands whose normals lean ±35° towards ±u, so a
// light from one side brightens every other band.
inline std::string writeBandNormalMap(const std::filesystem::path& folder) {
    const int size = 16;
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(size) * size * 4);
    const double lean = glm::radians(35.0);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double sx = ((x / 4) % 2 == 0 ? 1.0 : -1.0) * std::sin(lean);
            const glm::dvec3 n(sx, 0.0, std::cos(lean));
            std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * size + x) * 4];
            for (int c = 0; c < 3; ++c)
                p[c] = static_cast<std::uint8_t>(std::lround((n[c] * 0.5 + 0.5) * 255.0));
            p[3] = 255;
        }
    const std::filesystem::path path = folder / "bands_normal.png";
    writeRgba8(path, size, size, rgba);
    return path.string();
}

// The built-in plane with tangents along +u (+X) and `uvScale` applied to its uvs, optionally coloured
// per vertex (the four corners red, green, blue, white).
inline render::MeshHandle planeWith(bool colours, bool tangents, glm::vec2 uvScale = glm::vec2(1.0f),
                                    glm::vec2 uvOffset = glm::vec2(0.0f), int tessellation = 1) {
    render::MeshData mesh = render::makePlane(tessellation);
    for (glm::vec2& uv : mesh.uvs)
        uv = uv * uvScale + uvOffset;
    if (tangents)
        mesh.tangents.assign(mesh.positions.size(), glm::vec4(1, 0, 0, 1));
    if (colours) {
        for (const glm::vec3& p : mesh.positions) {
            const float u = (p.x + 1.0f) * 0.5f, v = (1.0f - p.z) * 0.5f;
            // Bilinear between red (u0 v0), green (u1 v0), blue (u0 v1) and white (u1 v1), alpha 1.
            const glm::vec3 c = glm::mix(glm::mix(glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), u),
                                         glm::mix(glm::vec3(0, 0, 1), glm::vec3(1, 1, 1), u), v);
            mesh.colors.emplace_back(c, 1.0f);
        }
    }
    return std::make_shared<const render::MeshData>(std::move(mesh));
}

// Every new material feature in one small lit, shadowed scene: a textured floor (mirrored-repeat uvs), a
// vertex-coloured box, an alpha-masked upright quad casting striped shadows, a normal-mapped panel and an
// emission-textured cube with clamped uvs. Both renderers draw it; the agreement tests compare them.
inline render::FrameInput featureScene(const std::filesystem::path& folder) {
    const std::string quadrants = writeQuadrantTexture(folder);
    const std::string stripes = writeStripeMask(folder);
    const std::string bands = writeBandNormalMap(folder);
    render::FrameInput input;
    input.settings.background = glm::dvec3(0.05, 0.06, 0.08);
    input.settings.ambient = 0.25;
    input.camera.position = {0.0, 2.6, 4.2};
    input.camera.target = {0.0, 0.3, 0.0};
    input.camera.fovY = 55.0;
    input.camera.near = 0.1;
    input.camera.far = 30.0;

    auto add = [&](std::string name, render::MeshHandle mesh, glm::dmat4 world, render::Material m) {
        render::DrawItem d;
        d.name = std::move(name);
        d.mesh = std::move(mesh);
        d.world = world;
        d.material = m;
        input.items.push_back(d);
    };
    render::Material floor;
    floor.color = glm::dvec3(0.9);
    floor.texture.path = quadrants;
    floor.wrap[0] = render::TextureWrap::MirroredRepeat;
    floor.wrap[1] = render::TextureWrap::MirroredRepeat;
    add("Floor", planeWith(false, false, glm::vec2(3.0f), glm::vec2(-1.0f)),
        glm::scale(glm::dmat4(1.0), glm::dvec3(3.0, 1.0, 3.0)), floor);

    render::Material tinted;
    tinted.color = glm::dvec3(1.0);
    tinted.specular = 0.3;
    tinted.specularColor = glm::dvec3(1.0, 0.6, 0.2);
    render::MeshData box = render::makeBox();
    for (const glm::vec3& p : box.positions)
        box.colors.emplace_back(glm::vec3(0.5f) + 0.5f * p * glm::vec3(0.9f, 0.6f, 0.9f), 1.0f);
    add("Coloured box", std::make_shared<const render::MeshData>(std::move(box)),
        glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(-1.4, 0.45, 0.3)), glm::dvec3(0.45)), tinted);

    render::Material masked;
    masked.color = glm::dvec3(1.0);
    masked.texture.path = stripes;
    masked.alphaMode = render::AlphaMode::Mask;
    masked.alphaCutoff = 0.5;
    add("Masked quad", planeWith(false, false, glm::vec2(2.0f, 1.0f)),
        glm::scale(glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0.2, 0.8, -0.6)),
                               glm::radians(90.0), glm::dvec3(1, 0, 0)),
                   glm::dvec3(0.9, 1.0, 0.7)),
        masked);

    render::Material bumpy;
    bumpy.color = glm::dvec3(0.7, 0.75, 0.9);
    bumpy.specular = 0.4;
    bumpy.shininess = 24.0;
    bumpy.normalTexture.path = bands;
    bumpy.normalScale = 0.8;
    add("Normal-mapped panel", planeWith(false, true, glm::vec2(2.0f, 2.0f)),
        glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(1.3, 0.02, 1.0)), glm::dvec3(0.8, 1.0, 0.8)),
        bumpy);

    render::Material glowing;
    glowing.color = glm::dvec3(0.2);
    glowing.emission = glm::dvec3(0.9);
    glowing.emissionTexture.path = quadrants;
    glowing.wrap[0] = render::TextureWrap::ClampToEdge;
    glowing.wrap[1] = render::TextureWrap::ClampToEdge;
    render::MeshData cube = render::makeBox();
    for (glm::vec2& uv : cube.uvs)
        uv = uv * 1.6f - glm::vec2(0.3f);
    add("Glowing cube", std::make_shared<const render::MeshData>(std::move(cube)),
        glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(1.5, 0.4, -1.2)), glm::dvec3(0.4)), glowing);

    render::Light light;
    light.type = render::LightType::Spot;
    light.position = {-1.5, 4.0, 2.5};
    light.direction = glm::normalize(glm::dvec3(1.5, -4.0, -2.5));
    light.spotAngle = 60.0;
    light.spotBlend = 0.2;
    light.intensity = 1.2;
    light.shadows = render::ShadowParams{};
    light.shadows->mapSize = 2048;
    light.shadows->pcf = 1;
    input.lights.push_back(light);
    return input;
}

// The plane seen from above (orientationScene's first view) with uvs running over [-1, 2] on both axes,
// so its edges show how the texture wraps.
inline render::FrameInput wrapScene(const std::string& texture, render::TextureWrap wrap) {
    render::Material m = showTexture(texture);
    m.wrap = {wrap, wrap};
    render::FrameInput input = orientationScene(View::PlaneFromAbove, m);
    input.items[0].mesh = planeWith(false, false, glm::vec2(3.0f), glm::vec2(-1.0f));
    return input;
}

// In wrapScene, the screen points where u = -0.7 and u = -0.2 (both at v = 0.25): ClampToEdge shows
// the left edge's colour (blue, blue), Repeat u + 1 (blue at 0.3, yellow at 0.8), MirroredRepeat -u
// (yellow at 0.7, blue at 0.2).
inline void expectWrapSamples(const render::Image& image, render::TextureWrap wrap, const char* what) {
    // The camera 3 above the plane with a 60° field of view sees ±tan(30°)·3 around the centre.
    const double halfView = 3.0 * std::tan(glm::radians(30.0));
    auto screenX = [&](double u) { return 0.5 + ((u + 1.0) / 3.0 * 2.0 - 1.0) / (2.0 * halfView); };
    const double z = 1.0 - 2.0 * (0.25 + 1.0) / 3.0; // v = 0.25
    const int y = static_cast<int>((0.5 + z / (2.0 * halfView)) * image.height);
    const int expected[3][2] = {
        {BottomLeft, BottomLeft}, {BottomLeft, BottomRight}, {BottomRight, BottomLeft}};
    const int row = wrap == render::TextureWrap::ClampToEdge ? 0
                    : wrap == render::TextureWrap::Repeat    ? 1
                                                             : 2;
    const double us[2] = {-0.7, -0.2};
    for (int i = 0; i < 2; ++i) {
        const int x = static_cast<int>(screenX(us[i]) * image.width);
        const int got = nearestQuadrant(image.at(x, y));
        EXPECT_EQ(got, expected[row][i])
            << what << ": at u = " << us[i] << " (pixel " << x << ", " << y << ") the plane shows "
            << (got < 0 ? "background" : kQuadrantNames[got]) << ", expected "
            << kQuadrantNames[expected[row][i]];
    }
}

// A white floor lit by a directional light 45° from the vertical, and a horizontal quad 1 above it,
// textured with the stripe mask 4 times across, whose shadow falls beside it at x in [0, 2]. The camera
// looks straight down at part of that shadow, where the quad itself is out of view.
inline render::FrameInput maskedShadowScene(const std::string& stripes, render::AlphaMode mode) {
    render::FrameInput input;
    input.settings.background = glm::dvec3(0.0);
    input.settings.ambient = 0.2;
    render::DrawItem floor;
    floor.name = "Floor";
    floor.mesh = std::make_shared<const render::MeshData>(render::makePlane(1));
    floor.world = glm::scale(glm::dmat4(1.0), glm::dvec3(4.0, 1.0, 4.0));
    floor.material.color = glm::dvec3(1.0);
    floor.material.ambient = 1.0;
    floor.material.diffuse = 1.0;
    input.items.push_back(floor);
    render::DrawItem quad;
    quad.name = "Masked quad";
    quad.mesh = planeWith(false, false, glm::vec2(4.0f, 1.0f));
    quad.world = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 1.0, 0.0));
    quad.material.color = glm::dvec3(0.8, 0.2, 0.2);
    quad.material.texture.path = stripes;
    quad.material.alphaMode = mode;
    input.items.push_back(quad);
    render::Light sun;
    sun.type = render::LightType::Directional;
    sun.direction = glm::normalize(glm::dvec3(1.0, -1.0, 0.0));
    sun.shadows = render::ShadowParams{};
    sun.shadows->mapSize = 2048;
    sun.shadows->pcf = 1;
    input.lights.push_back(sun);
    input.camera.position = {1.7, 4.0, 0.0};
    input.camera.target = {1.7, 0.0, 0.0};
    input.camera.up = {0, 0, -1};
    input.camera.fovY = 16.0;
    input.camera.near = 0.5;
    input.camera.far = 10.0;
    return input;
}

// The share of pixels brighter than half the lit floor's value (0.2 ambient + cos 45° ≈ 0.91).
inline double litShare(const render::Image& image) {
    std::size_t lit = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            lit += image.at(x, y).g > 0.45f;
    return double(lit) / double(std::max(1, image.width * image.height));
}

} // namespace speculum::test::materials

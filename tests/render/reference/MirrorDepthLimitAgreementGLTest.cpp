// The end of a mirror corridor, where the depth limit stops the reflections: both renderers end the paths
// there, so the last mirror shows only its surface's share, surface·(1 − R), and adds no reflection. A
// corridor of perfect mirrors ends in black, never in a lit wall, and the rasterizer agrees with the tracer
// pixel for pixel at every depth, Fresnel included.
#include "render/imageio/ImageWriter.hpp"
#include "render/mesh/Primitives.hpp"
#include "render/reference/Tracer.hpp"
#include "support/GlTest.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kWidth = 96;
constexpr int kHeight = 64;

Material lit(glm::dvec3 colour) {
    Material m;
    m.color = colour;
    m.ambient = 1.0;
    m.diffuse = 1.0;
    m.specular = 0.3;
    m.shininess = 16.0;
    return m;
}

// Two facing mirrors 4 apart (z = −2 facing +Z, z = +2 facing −Z), a lit red box between them, a lamp,
// and the camera between them looking slightly off the corridor's axis so that every level shows.
FrameInput corridor(double reflectivity, bool fresnel) {
    FrameInput input;
    input.settings.background = {0.0, 0.0, 0.0};
    input.settings.ambient = 0.3;
    input.camera.position = {0.5, 0.3, 1.2};
    input.camera.target = {0.0, 0.0, -2.0};
    input.camera.fovY = 50.0;
    input.camera.far = 200.0;
    Light lamp;
    lamp.type = LightType::Point;
    lamp.position = {0.0, 1.5, 0.0};
    lamp.intensity = 1.0;
    input.lights.push_back(lamp);
    static const auto box = std::make_shared<const MeshData>(makeBox());
    input.items.push_back({"Red",
                           glm::scale(glm::translate(glm::dmat4(1.0), {-0.4, -0.3, -0.5}), glm::dvec3(0.25)),
                           box, lit({0.9, 0.1, 0.1}), true});
    for (double side : {-1.0, 1.0}) {
        Mirror mirror;
        mirror.name = side < 0 ? "Back" : "Front";
        // The rectangle's local +Y is its normal: turned onto +Z for the back mirror, onto −Z for the front.
        mirror.world = glm::rotate(glm::translate(glm::dmat4(1.0), {0.0, 0.0, 2.0 * side}),
                                   glm::radians(-90.0 * side), glm::dvec3(1, 0, 0));
        mirror.size = {6.0, 6.0};
        mirror.reflectivity = reflectivity;
        mirror.fresnel = fresnel;
        // A mirror without a material of its own shows the default one's grey: what used to read as light.
        input.mirrors.push_back(mirror);
    }
    return input;
}

reference::TraceResult trace(const FrameInput& input) {
    auto tracer = reference::Tracer::create(input);
    EXPECT_TRUE(tracer.ok()) << (tracer.ok() ? "" : tracer.error());
    reference::TraceSettings settings;
    settings.width = kWidth;
    settings.height = kHeight;
    settings.threads = 2;
    settings.shadows = reference::ShadowMode::Hard;
    auto result = tracer->render(settings);
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error());
    return result.ok() ? std::move(*result) : reference::TraceResult{};
}

void dump(const std::string& name, const Image& raster, const Image& traced) {
    const char* folder = std::getenv("SPECULUM_TEST_DUMP");
    if (!folder)
        return;
    EXPECT_TRUE(writeImage(std::string(folder) + "/" + name + "_raster.png", raster).ok());
    EXPECT_TRUE(writeImage(std::string(folder) + "/" + name + "_reference.png", traced).ok());
}

bool agrees(const glm::vec4& a, const glm::vec4& b) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(a[c] - b[c]) > 0.03f * std::max(std::abs(a[c]), std::abs(b[c])) + 0.01f)
            return false;
    return true;
}

bool black(const glm::vec4& c) {
    return c.r < 0.005f && c.g < 0.005f && c.b < 0.005f;
}

struct Compared {
    int mirrorPixels = 0; // pixels whose first hit is a mirror's front
    int agreeing = 0;     // of those, where both renderers agree
    int blackInBoth = 0;  // of those, black in both
};

class MirrorDepthLimit : public GlTest {
protected:
    // Both renderers' images of `input`, compared on the pixels whose first hit is a mirror's front.
    Compared compare(const FrameInput& input, const std::string& name) {
        const Image raster = renderImage(input, kWidth, kHeight);
        const reference::TraceResult traced = trace(input);
        dump(name, raster, traced.image);
        Compared c;
        if (raster.width != kWidth || traced.image.width != kWidth)
            return c;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                if (traced.ids.at(x, y).kind != reference::HitKind::Mirror)
                    continue;
                const glm::vec4 a = raster.at(x, y), b = traced.image.at(x, y);
                ++c.mirrorPixels;
                c.agreeing += agrees(a, b);
                c.blackInBoth += black(a) && black(b);
            }
        std::printf("[ measured ] %s: %d of %d mirror pixels agree, %d black in both\n", name.c_str(),
                    c.agreeing, c.mirrorPixels, c.blackInBoth);
        return c;
    }
};

TEST_F(MirrorDepthLimit, PerfectMirrorsEndTheCorridorInBlackAtEveryDepth) {
    for (int depth = 0; depth <= 3; ++depth) {
        FrameInput input = corridor(1.0, false);
        input.settings.mirrorDepth = depth;
        const std::string name = "corridor_perfect_depth" + std::to_string(depth);
        SCOPED_TRACE(name);
        const Compared c = compare(input, name);
        ASSERT_GT(c.mirrorPixels, kWidth * kHeight / 2) << "the mirrors fill the view";
        EXPECT_GE(c.agreeing, int(0.98 * c.mirrorPixels));
        // The innermost image of the corridor is where the paths end: dark in both, not the surface's grey.
        EXPECT_GT(c.blackInBoth, 50);
        if (depth == 0) { // no reflection at all: every mirror pixel is black
            EXPECT_EQ(c.blackInBoth, c.mirrorPixels);
        }
    }
}

TEST_F(MirrorDepthLimit, PartlySilveredMirrorsShowTheirSurfaceShareAtTheLimitInBothRenderers) {
    for (bool fresnel : {false, true})
        for (int depth : {0, 1, 3}) {
            FrameInput input = corridor(0.6, fresnel);
            input.settings.mirrorDepth = depth;
            if (fresnel) // and a tinted surface of their own
                for (Mirror& mirror : input.mirrors) {
                    mirror.material = lit({0.2, 0.5, 0.9});
                    mirror.hasMaterial = true;
                }
            const std::string name =
                std::string("corridor_0.6") + (fresnel ? "_fresnel" : "") + "_depth" + std::to_string(depth);
            SCOPED_TRACE(name);
            const Compared c = compare(input, name);
            ASSERT_GT(c.mirrorPixels, kWidth * kHeight / 2);
            EXPECT_GE(c.agreeing, int(0.98 * c.mirrorPixels));
            EXPECT_EQ(c.blackInBoth, 0) << "the surface's share still shows";
        }
}

} // namespace
} // namespace speculum::test

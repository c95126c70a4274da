// The reference tracer against the formulas it claims to implement: Blinn-Phong at a known point, shadow
// rays, mirror blending and recursion depth, and the camera's pixel grid.
#include "render/reference/Tracer.hpp"

#include "support/SceneBuilder.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace speculum::test {
namespace {

using render::FrameInput;
using render::reference::HitKind;
using render::reference::Tracer;
using render::reference::TraceResult;
using render::reference::TraceSettings;

TraceResult trace(const FrameInput& input, int width, int height, int ssaa = 1,
                  render::reference::ShadowMode shadows = render::reference::ShadowMode::Hard) {
    auto tracer = Tracer::create(input);
    EXPECT_TRUE(tracer.ok()) << (tracer.ok() ? "" : tracer.error());
    TraceSettings settings;
    settings.width = width;
    settings.height = height;
    settings.ssaa = ssaa;
    settings.shadows = shadows;
    auto result = tracer->render(settings);
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error());
    return std::move(*result);
}

void expectColour(const glm::vec4& actual, glm::dvec3 expected, double tolerance = 1e-5) {
    EXPECT_NEAR(actual.r, expected.r, tolerance);
    EXPECT_NEAR(actual.g, expected.g, tolerance);
    EXPECT_NEAR(actual.b, expected.b, tolerance);
}

// Camera one unit above a large floor plane at y = 0, looking straight down; with an odd image size the
// centre pixel's ray hits the origin exactly.
FrameInput floorSeenFromAbove() {
    FrameInput input;
    input.camera.position = {0.0, 1.0, 0.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.up = {0.0, 0.0, -1.0};
    input.camera.fovY = 60.0;
    render::Material m;
    m.color = {0.6, 0.5, 0.4};
    m.ambient = 0.7;
    m.diffuse = 0.9;
    m.specular = 0.3;
    m.shininess = 20.0;
    m.emission = {0.01, 0.02, 0.03};
    input.items.push_back(item("Floor", planeMesh(), placed({0, 0, 0}, {5, 1, 5}), m));
    input.settings.ambient = 0.2;
    render::Light light;
    light.position = {0.5, 2.0, 0.3};
    light.color = {1.0, 0.9, 0.8};
    light.intensity = 1.5;
    input.lights.push_back(light);
    return input;
}

TEST(ReferenceTracer, LitPlaneMatchesBlinnPhongAtTheCentrePixel) {
    const FrameInput input = floorSeenFromAbove();
    const TraceResult result = trace(input, 51, 51);
    const render::Material& m = input.items[0].material;
    const render::Light& light = input.lights[0];
    const glm::dvec3 n(0, 1, 0), p(0, 0, 0);
    const glm::dvec3 toLight = glm::normalize(light.position - p);
    const glm::dvec3 viewDir = glm::normalize(input.camera.position - p);
    const glm::dvec3 h = glm::normalize(toLight + viewDir);
    const glm::dvec3 radiance = light.color * light.intensity;
    const glm::dvec3 expected =
        m.emission +
        m.color * (m.ambient * input.settings.ambient + m.diffuse * glm::dot(n, toLight) * radiance) +
        m.specular * std::pow(glm::dot(n, h), m.shininess) * radiance;
    expectColour(result.image.at(25, 25), expected);
    EXPECT_EQ(result.ids.at(25, 25).kind, HitKind::Object);
    EXPECT_EQ(result.ids.at(25, 25).index, 0);
    EXPECT_EQ(result.image.at(25, 25).a, 1.0f);
}

TEST(ReferenceTracer, SpotConeFadesWithTheShadersSmoothstep) {
    FrameInput input = floorSeenFromAbove();
    render::Light& light = input.lights[0];
    light.type = render::LightType::Spot;
    light.position = {0.0, 2.0, 0.0};
    light.direction = {0.0, -1.0, 0.0};
    light.spotAngle = 20.0;
    light.spotBlend = 0.5; // full inside 10°, none outside 20°
    const TraceResult result = trace(input, 51, 51);
    const render::Material& m = input.items[0].material;
    // Pixel (0, 25)'s ray meets the floor at x = −tan 30° · 50/51, seen from the light ≈ 15.8° off axis:
    // in the blend band, so the cone factor is the smoothstep's, about one half.
    const glm::dvec3 p(-std::tan(glm::radians(30.0)) * 50.0 / 51.0, 0.0, 0.0);
    const glm::dvec3 toLight = glm::normalize(light.position - p);
    const double outer = std::cos(glm::radians(20.0)), inner = std::cos(glm::radians(10.0));
    const double t = std::clamp((glm::dot(-toLight, light.direction) - outer) / (inner - outer), 0.0, 1.0);
    const double cone = t * t * (3 - 2 * t);
    ASSERT_GT(cone, 0.2);
    ASSERT_LT(cone, 0.8);
    const glm::dvec3 n(0, 1, 0);
    const glm::dvec3 h = glm::normalize(toLight + glm::normalize(input.camera.position - p));
    const glm::dvec3 radiance = light.color * light.intensity;
    const glm::dvec3 expected =
        m.emission +
        m.color * (m.ambient * input.settings.ambient + m.diffuse * glm::dot(n, toLight) * radiance * cone) +
        m.specular * std::pow(glm::dot(n, h), m.shininess) * radiance * cone;
    expectColour(result.image.at(0, 25), expected);
}

TEST(ReferenceTracer, ShadowRaysDarkenOnlyBehindCasters) {
    FrameInput input = floorSeenFromAbove();
    input.lights[0].position = {2.0, 2.0, 0.0};
    input.lights[0].shadows = render::ShadowParams{};
    // A small box on the segment from the origin to the light, out of the camera's view of the centre.
    input.items.push_back(
        item("Blocker", boxMesh(), placed({1.0, 1.0, 0.0}, glm::dvec3(0.1)), emissive({0, 0, 0})));
    const render::Material& m = input.items[0].material;
    const glm::dvec3 ambientOnly = m.emission + m.color * m.ambient * input.settings.ambient;

    expectColour(trace(input, 51, 51).image.at(25, 25), ambientOnly);
    expectColour(trace(input, 51, 51, 1, render::reference::ShadowMode::PcfFootprint).image.at(25, 25),
                 ambientOnly);

    FrameInput noCasting = input;
    noCasting.items[1].castsShadows = false;
    EXPECT_GT(trace(noCasting, 51, 51).image.at(25, 25).r, ambientOnly.r + 0.1);

    FrameInput shadowsOff = input; // a light without a shadow map lights through everything, as in GL
    shadowsOff.lights[0].shadows.reset();
    EXPECT_GT(trace(shadowsOff, 51, 51).image.at(25, 25).r, ambientOnly.r + 0.1);
}

TEST(ReferenceTracer, PcfFootprintSoftensTheShadowEdge) {
    FrameInput input = floorSeenFromAbove();
    input.lights[0].position = {0.0, 3.0, 0.0};
    input.lights[0].shadows = render::ShadowParams{64, 7}; // coarse map, wide kernel: a wide penumbra
    // A thin wall whose shadow edge runs along x = 0 on the floor.
    input.items.push_back(
        item("Wall", boxMesh(), placed({-1.0, 1.5, 0.0}, {1.0, 0.01, 2.0}), emissive({0, 0, 0})));
    const TraceResult hard = trace(input, 101, 101);
    const TraceResult soft = trace(input, 101, 101, 1, render::reference::ShadowMode::PcfFootprint);
    auto partial = [](const TraceResult& r) {
        // Pixels along the row through the centre strictly between the shadow's and the light's values.
        const float dark = r.image.at(10, 50).r, lit = r.image.at(90, 50).r;
        int count = 0;
        for (int x = 0; x < 101; ++x) {
            const float v = r.image.at(x, 50).r;
            if (v > dark + 0.02f * (lit - dark) && v < lit - 0.02f * (lit - dark))
                ++count;
        }
        return count;
    };
    EXPECT_LT(hard.image.at(10, 50).r, hard.image.at(90, 50).r - 0.1f);
    EXPECT_GT(partial(soft), partial(hard) + 2);
}

// Camera at the origin looking down −Z; an emissive box straight ahead above a floor mirror at y = −1.
FrameInput boxAboveFloorMirror() {
    FrameInput input;
    input.camera.position = {0.0, 0.0, 0.0};
    input.camera.target = {0.0, 0.0, -1.0};
    input.camera.fovY = 90.0;
    input.camera.far = 100.0;
    input.settings.background = {0.0, 0.0, 0.0};
    input.items.push_back(
        item("Box", boxMesh(), placed({0, 0, -3}, glm::dvec3(0.3)), emissive({1.0, 0.5, 0.25})));
    render::Mirror floor = mirror({0, -1, 0}, {0, 1, 0}, {20, 20});
    floor.reflectivity = 0.8;
    floor.tint = {0.5, 1.0, 1.0};
    floor.hasMaterial = true;
    floor.material = emissive({0.0, 0.0, 0.1});
    input.mirrors.push_back(floor);
    return input;
}

// The pixel (in a size×size image, fovY 90°) through which the camera sees the point p.
glm::ivec2 pixelOf(glm::dvec3 p, int size) {
    const double ndcX = p.x / -p.z, ndcY = p.y / -p.z;
    return {int((ndcX + 1.0) * 0.5 * size), int((1.0 - ndcY) * 0.5 * size)};
}

TEST(ReferenceTracer, MirrorShowsTheObjectAtTheMirroredPixelBlendedLikeMirrorFrag) {
    const FrameInput input = boxAboveFloorMirror();
    const int size = 101;
    const TraceResult result = trace(input, size, size);
    const glm::ivec2 direct = pixelOf({0, 0, -3}, size);
    const glm::ivec2 mirrored = pixelOf({0, -2, -3}, size); // the box's image, reflected in y = −1
    expectColour(result.image.at(direct.x, direct.y), {1.0, 0.5, 0.25});
    EXPECT_EQ(result.ids.at(direct.x, direct.y).kind, HitKind::Object);
    // surface·(1−R) + R·tint·reflection
    const double r = 0.8;
    const glm::dvec3 expected =
        glm::dvec3(0, 0, 0.1) * (1 - r) + r * glm::dvec3(0.5, 1, 1) * glm::dvec3(1, 0.5, 0.25);
    expectColour(result.image.at(mirrored.x, mirrored.y), expected);
    EXPECT_EQ(result.ids.at(mirrored.x, mirrored.y).kind, HitKind::Mirror);
    EXPECT_EQ(result.ids.at(mirrored.x, mirrored.y).index, 0);
    // Where the mirror reflects only the background.
    const glm::ivec2 empty = pixelOf({1.5, -2, -3}, size);
    expectColour(result.image.at(empty.x, empty.y), glm::dvec3(0, 0, 0.1) * (1 - r));
}

TEST(ReferenceTracer, FresnelRaisesReflectivityAtGrazingAngles) {
    FrameInput input = boxAboveFloorMirror();
    input.mirrors[0].fresnel = true;
    input.mirrors[0].reflectivity = 0.2;
    input.mirrors[0].tint = {1, 1, 1};
    input.settings.background = {1, 1, 1};
    const int size = 101;
    const TraceResult result = trace(input, size, size);
    // Two mirror pixels that reflect the white background: the grazing one is brighter.
    auto at = [&](glm::dvec3 p) {
        const glm::ivec2 px = pixelOf(p, size);
        return result.image.at(px.x, px.y);
    };
    const glm::vec4 steep = at({0.75, -1, -1.5}), grazing = at({0.75, -1, -20});
    // Schlick's R for the ray through the centre of the steep pixel (fovY 90°: ndc = view direction).
    const glm::ivec2 px = pixelOf({0.75, -1, -1.5}, size);
    const glm::dvec3 dir(2.0 * (px.x + 0.5) / size - 1.0, 1.0 - 2.0 * (px.y + 0.5) / size, -1.0);
    const double cSteep = -dir.y / glm::length(dir);
    const double rSteep = 0.2 + 0.8 * std::pow(1 - cSteep, 5.0);
    expectColour(steep, glm::dvec3(0, 0, 0.1) * (1 - rSteep) + glm::dvec3(rSteep), 1e-5);
    EXPECT_GT(grazing.r, steep.r + 0.1f);
}

TEST(ReferenceTracer, MirrorDepthLimitEndsThePathWithTheSurfaceShareAlone) {
    // Floor (blue) and ceiling (green) half-silvered mirrors facing each other; a steep ray bounces
    // between them.
    FrameInput input;
    input.camera.position = {0, 0, 0};
    input.camera.target = {0, 0, -1};
    input.camera.fovY = 90.0;
    input.camera.far = 1000.0;
    input.settings.background = {0, 0, 0};
    render::Mirror floor = mirror({0, -1, 0}, {0, 1, 0}, {200, 200});
    floor.hasMaterial = true;
    floor.material = emissive({0, 0, 1});
    floor.reflectivity = 0.5;
    render::Mirror ceiling = mirror({0, 1, 0}, {0, -1, 0}, {200, 200});
    ceiling.hasMaterial = true;
    ceiling.material = emissive({0, 1, 0});
    ceiling.reflectivity = 0.5;
    input.mirrors = {floor, ceiling};
    const int size = 101;
    const glm::ivec2 px = pixelOf({0, -1, -1.5}, size);
    const glm::dvec3 blue(0, 0, 1), green(0, 1, 0);
    for (int depth = 0; depth <= 5; ++depth) {
        input.settings.mirrorDepth = depth;
        const TraceResult result = trace(input, size, size);
        // The ray meets the floor at level 1, the ceiling at 2, the floor at 3, …; the k-th mirror adds
        // its surface's share, 0.5^k of its colour, up to the first mirror beyond the limit, which reflects
        // nothing: what lies behind it is not followed.
        glm::dvec3 expected(0.0);
        for (int k = 1; k <= depth + 1; ++k)
            expected += std::pow(0.5, k) * (k % 2 == 1 ? blue : green);
        SCOPED_TRACE("mirrorDepth " + std::to_string(depth));
        expectColour(result.image.at(px.x, px.y), expected);
    }
    // Perfect mirrors keep nothing of their surfaces: the end of the corridor is dark at every depth, not
    // a lit wall.
    input.mirrors[0].reflectivity = 1.0;
    input.mirrors[1].reflectivity = 1.0;
    for (int depth = 0; depth <= 5; ++depth) {
        input.settings.mirrorDepth = depth;
        SCOPED_TRACE("perfect mirrors, mirrorDepth " + std::to_string(depth));
        expectColour(trace(input, size, size).image.at(px.x, px.y), {0, 0, 0});
    }
}

TEST(ReferenceTracer, BackOfAMirrorShowsItsMaterial) {
    FrameInput input = boxAboveFloorMirror();
    input.mirrors[0] = mirror({0, -1, 0}, {0, -1, 0}, {20, 20}); // now facing down, away from the camera
    input.mirrors[0].material = emissive({0.3, 0.2, 0.1});
    const TraceResult result = trace(input, 101, 101);
    const glm::ivec2 px = pixelOf({0, -2, -3}, 101);
    expectColour(result.image.at(px.x, px.y), {0.3, 0.2, 0.1});
    EXPECT_EQ(result.ids.at(px.x, px.y).kind, HitKind::MirrorBack);
}

TEST(ReferenceTracer, FarPlaneClipsMirroredPathsByTheirUnfoldedLength) {
    FrameInput input = boxAboveFloorMirror();
    input.mirrors[0].reflectivity = 1.0;
    input.mirrors[0].tint = {1, 1, 1};
    const glm::ivec2 mirrored = pixelOf({0, -2, -3}, 101);
    input.camera.far = 3.5; // the box is at view depth ~2.7 directly, its image at ~2.7 too (depth 3 − 0.3)
    expectColour(trace(input, 101, 101).image.at(mirrored.x, mirrored.y), {1.0, 0.5, 0.25});
    input.camera.far = 2.0; // the mirror point (depth 1.5) is in range, the reflected box is not
    expectColour(trace(input, 101, 101).image.at(mirrored.x, mirrored.y), {0, 0, 0});
}

TEST(ReferenceTracer, ReflectorReflectsAboutItsSurfaceNormal) {
    // A flat "reflector" (a plane mesh) behaves like a mirror of its reflectivity without tint.
    FrameInput input = boxAboveFloorMirror();
    input.mirrors.clear();
    render::Reflector reflector;
    reflector.mesh = planeMesh();
    reflector.world = placed({0, -1, 0}, {10, 1, 10});
    reflector.reflectivity = 0.75;
    reflector.material = emissive({0.2, 0.0, 0.0});
    input.reflectors = {reflector};
    const TraceResult result = trace(input, 101, 101);
    const glm::ivec2 mirrored = pixelOf({0, -2, -3}, 101);
    expectColour(result.image.at(mirrored.x, mirrored.y),
                 glm::dvec3(0.2, 0, 0) * 0.25 + 0.75 * glm::dvec3(1.0, 0.5, 0.25));
    EXPECT_EQ(result.ids.at(mirrored.x, mirrored.y).kind, HitKind::Reflector);
}

TEST(ReferenceTracer, ReflectorShowsPlanarMirrorsToItsOwnMirrorDepth) {
    // A flat reflector floor sees a half-silvered green mirror ahead; that mirror reflects only the dim red
    // sky.
    FrameInput input = boxAboveFloorMirror();
    input.items.clear();
    input.settings.mirrorDepth = 5; // the camera's own limit does not apply inside the reflector's map
    input.settings.background = {0.2, 0, 0};
    render::Mirror ahead = mirror({0, 0, -5}, {0, 0, 1}, {20, 20});
    ahead.hasMaterial = true;
    ahead.material = emissive({0, 1, 0});
    ahead.reflectivity = 0.5;
    input.mirrors = {ahead};
    render::Reflector reflector;
    reflector.mesh = planeMesh();
    reflector.world = placed({0, -1, 0}, {10, 1, 10});
    reflector.material = emissive({0, 0, 0});
    input.reflectors = {reflector};
    const glm::ivec2 px = pixelOf({0, -1, -2}, 101);
    // At depth 0 the mirror shows its surface's share alone; at depth 1 the sky behind it too.
    input.reflectors[0].mirrorDepth = 0;
    expectColour(trace(input, 101, 101).image.at(px.x, px.y), {0, 0.5, 0});
    input.reflectors[0].mirrorDepth = 1;
    expectColour(trace(input, 101, 101).image.at(px.x, px.y), {0.1, 0.5, 0});
    // Fresnel: at this angle (cos ≈ 0.45) Schlick's R rises from 0.3 to 0.3 + 0.7·0.55^5.
    input.reflectors[0].mirrorDepth = 0;
    input.reflectors[0].reflectivity = 0.3;
    input.reflectors[0].fresnel = true;
    const glm::dvec3 dir(2.0 * (px.x + 0.5) / 101 - 1.0, 1.0 - 2.0 * (px.y + 0.5) / 101, -1.0);
    const double c = -dir.y / glm::length(dir);
    const double r = 0.3 + 0.7 * std::pow(1.0 - c, 5.0);
    expectColour(trace(input, 101, 101).image.at(px.x, px.y), glm::dvec3(0, 0.5 * r, 0));
}

TEST(ReferenceTracer, SupersamplingAveragesTheOrderedGrid) {
    // A vertical edge between two emissive halves through the middle of a pixel column: with 2×2 samples
    // the pixel straddling it is the mean of both colours.
    FrameInput input;
    input.camera.position = {0, 0, 0};
    input.camera.target = {0, 0, -1};
    input.camera.fovY = 90.0;
    input.settings.background = {0, 0, 0};
    // Plane facing +Z at z = −1 covering x ≥ 0 only (its left edge at x = 0 → ndc 0).
    glm::dmat4 world = glm::rotate(placed({1.0, 0.0, -1.0}), glm::radians(90.0), glm::dvec3(1, 0, 0));
    input.items.push_back(item("Half", planeMesh(), world, emissive({1, 1, 1})));
    const TraceResult one = trace(input, 10, 10, 1);
    const TraceResult four = trace(input, 10, 10, 2);
    EXPECT_EQ(four.samples, 4);
    // Column 5 starts at ndc 0: fully white; column 4 ends at 0: black, in both.
    EXPECT_NEAR(four.image.at(5, 5).r, 1.0f, 1e-6);
    EXPECT_NEAR(four.image.at(4, 5).r, 0.0f, 1e-6);
    // An image 2× wider has its edge inside pixels 9/10 exactly at ndc 0: still no partial pixel. Use an
    // odd width instead so the edge splits the centre pixel in half.
    const TraceResult odd = trace(input, 11, 11, 2);
    EXPECT_NEAR(odd.image.at(5, 5).r, 0.5f, 1e-6);
    EXPECT_EQ(one.image.at(5, 5).r, 1.0f);
}

} // namespace
} // namespace speculum::test

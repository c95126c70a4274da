// Shadows seen in rendered pixels: a square caster above a ground plane, lit by each kind of light, with
// the exact shadow computed analytically and compared pixel by pixel.
#include "render/mesh/Primitives.hpp"
#include "render/plan/Planner.hpp"
#include "support/GlTest.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kSize = 256;
constexpr double kCasterHeight = 1.0;
constexpr double kCasterHalf = 0.5;
constexpr double kGroundHalf = 3.0;
constexpr double kInShadow = 0.2; // ground in shadow: ambient only, 0.8 · 0.2 = 0.16
constexpr double kLit = 0.4;      // lit ground: 0.16 + 0.8 · n·l with n·l > 0.5 here

FrameInput shadowScene(const Light& light) {
    FrameInput input;
    input.settings.ambient = 0.2;
    input.settings.background = {0.0, 0.0, 0.0};
    input.camera.position = {0.0, 6.0, 0.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.up = {0.0, 0.0, -1.0};
    input.camera.fovY = 60.0;
    input.camera.near = 0.1;
    input.camera.far = 20.0;
    auto plane = std::make_shared<const MeshData>(makePlane(1));
    DrawItem ground{
        "Ground", glm::scale(glm::dmat4(1.0), glm::dvec3(kGroundHalf, 1.0, kGroundHalf)), plane, {}, true};
    ground.material.color = {0.8, 0.8, 0.8};
    DrawItem caster{"Caster",
                    glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, kCasterHeight, 0.0)),
                               glm::dvec3(kCasterHalf, 1.0, kCasterHalf)),
                    plane,
                    {},
                    true};
    input.items = {ground, caster};
    input.lights = {light};
    return input;
}

Light pointLight(int pcf) {
    Light light;
    light.name = "Lamp";
    light.type = LightType::Point;
    light.position = {2.0, 3.0, 0.0};
    light.shadows = render::ShadowParams{1024, pcf};
    return light;
}

// The ray through the centre of pixel (x, y), row 0 at the top.
struct Ray {
    glm::dvec3 origin;
    glm::dvec3 direction;
};

Ray pixelRay(const Camera& camera, int x, int y) {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double t = std::tan(glm::radians(camera.fovY) * 0.5);
    const double nx = ((x + 0.5) / kSize * 2.0 - 1.0) * t;
    const double ny = (1.0 - (y + 0.5) / kSize * 2.0) * t;
    return {camera.position, glm::normalize(forward + right * nx + up * ny)};
}

// Where the ray meets the horizontal plane y = h, if in front of the camera.
std::optional<glm::dvec3> hitHeight(const Ray& ray, double h) {
    if (std::abs(ray.direction.y) < 1e-12)
        return std::nullopt;
    const double t = (h - ray.origin.y) / ray.direction.y;
    if (t <= 0)
        return std::nullopt;
    return ray.origin + ray.direction * t;
}

// The exact shadow of the caster square on the ground, an axis-aligned rectangle in XZ.
struct Rect {
    glm::dvec2 min, max;
    bool contains(const glm::dvec2& p) const {
        return p.x > min.x && p.x < max.x && p.y > min.y && p.y < max.y;
    }
    // Distance to the rectangle's outline, inside or outside.
    double edgeDistance(const glm::dvec2& p) const {
        const double dx = std::max({min.x - p.x, 0.0, p.x - max.x});
        const double dy = std::max({min.y - p.y, 0.0, p.y - max.y});
        if (!contains(p))
            return std::hypot(dx, dy);
        return std::min({p.x - min.x, max.x - p.x, p.y - min.y, max.y - p.y});
    }
};

Rect exactShadow(const Light& light) {
    auto project = [&](glm::dvec3 corner) {
        if (light.type == LightType::Directional) {
            const glm::dvec3 d = glm::normalize(light.direction);
            const double t = -corner.y / d.y;
            corner += d * t;
        } else {
            const double t = light.position.y / (light.position.y - corner.y);
            corner = light.position + (corner - light.position) * t;
        }
        return glm::dvec2(corner.x, corner.z);
    };
    const glm::dvec2 a = project({-kCasterHalf, kCasterHeight, -kCasterHalf});
    const glm::dvec2 b = project({kCasterHalf, kCasterHeight, kCasterHalf});
    return {glm::min(a, b), glm::max(a, b)};
}

struct ShadowCensus {
    int shadowed = 0, lit = 0, between = 0;
    int wrongInside = 0, wrongOutside = 0, betweenAwayFromEdge = 0;
};

// Classifies every pixel that shows the ground (not the caster, not near the ground's border).
ShadowCensus census(const Image& image, const FrameInput& input, double margin) {
    const Rect shadow = exactShadow(input.lights[0]);
    ShadowCensus c;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const Ray ray = pixelRay(input.camera, x, y);
            const auto onCaster = hitHeight(ray, kCasterHeight);
            if (onCaster && std::abs(onCaster->x) < kCasterHalf + 0.05 &&
                std::abs(onCaster->z) < kCasterHalf + 0.05)
                continue;
            const auto p = hitHeight(ray, 0.0);
            if (!p || std::abs(p->x) > kGroundHalf - 0.1 || std::abs(p->z) > kGroundHalf - 0.1)
                continue;
            const double v = image.at(x, y).g;
            EXPECT_TRUE(std::isfinite(v));
            const glm::dvec2 q{p->x, p->z};
            const double edge = shadow.edgeDistance(q);
            const bool inside = shadow.contains(q);
            if (v < kInShadow)
                ++c.shadowed;
            else if (v > kLit)
                ++c.lit;
            else
                ++c.between;
            if (edge < margin)
                continue;
            if (inside && v >= kInShadow)
                ++c.wrongInside;
            if (!inside && v <= kLit)
                ++c.wrongOutside;
            if (v >= kInShadow && v <= kLit)
                ++c.betweenAwayFromEdge;
        }
    return c;
}

// World width of the band around the exact outline where filtering may blend: the PCF kernel and the
// normal offset measured on the ground, plus two pixels of the image.
double edgeMargin(int pcf) {
    const double texel = 2.0 * 4.0 / 1024.0 * 1.5; // a cube-face texel at ~4 units, magnified onto the ground
    const double pixel = 2.0 * 6.0 * std::tan(glm::radians(30.0)) / kSize;
    return (pcf + 3) * texel + 2.0 * pixel;
}

TEST_F(GlTest, PointLightShadowIsWhereGeometrySaysAndPcfBlendsOnlyAtEdges) {
    const FrameInput input = shadowScene(pointLight(5));
    const Image image = renderImage(input, kSize, kSize);
    ASSERT_EQ(image.width, kSize);
    const ShadowCensus c = census(image, input, edgeMargin(5));
    EXPECT_GT(c.shadowed, 1000) << "the shadow must be visible";
    EXPECT_GT(c.lit, 10000) << "the ground around it must be lit";
    EXPECT_EQ(c.wrongInside, 0) << "light inside the exact shadow (leak)";
    EXPECT_EQ(c.wrongOutside, 0) << "shadow outside the exact shadow (acne or misplaced shadow)";
    EXPECT_EQ(c.betweenAwayFromEdge, 0) << "PCF blending away from the shadow's outline";
    EXPECT_GT(c.between, 20) << "a 5×5 PCF kernel must soften the outline";
}

TEST_F(GlTest, PcfOfOneGivesHardShadowsAndWiderKernelsSofterOnes) {
    const FrameInput hardInput = shadowScene(pointLight(1));
    const ShadowCensus hard = census(renderImage(hardInput, kSize, kSize), hardInput, edgeMargin(1));
    EXPECT_EQ(hard.wrongInside + hard.wrongOutside, 0);
    const FrameInput softInput = shadowScene(pointLight(9));
    const ShadowCensus soft = census(renderImage(softInput, kSize, kSize), softInput, edgeMargin(9));
    EXPECT_EQ(soft.wrongInside + soft.wrongOutside + soft.betweenAwayFromEdge, 0);
    EXPECT_LT(hard.between * 3, soft.between) << "hard " << hard.between << " vs soft " << soft.between;
}

TEST_F(GlTest, DirectionalLightShadowCoversTheExactShadowWithoutLeaks) {
    Light sun;
    sun.name = "Sun";
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::dvec3(1.2, -1.0, 0.3));
    sun.shadows = render::ShadowParams{1024, 3};
    const FrameInput input = shadowScene(sun);
    const ShadowCensus c = census(renderImage(input, kSize, kSize), input, edgeMargin(3) + 0.03);
    EXPECT_GT(c.shadowed, 1000);
    EXPECT_GT(c.lit, 10000);
    EXPECT_EQ(c.wrongInside, 0);
    EXPECT_EQ(c.wrongOutside, 0);
    EXPECT_EQ(c.betweenAwayFromEdge, 0);
}

TEST_F(GlTest, SpotLightCastsTheShadowInsideItsCone) {
    Light spot = pointLight(3);
    spot.type = LightType::Spot;
    spot.direction = glm::normalize(glm::dvec3(-2.7, -3.0, 0.0)); // from (2, 3, 0) towards the shadow
    spot.spotAngle = 50.0;
    const FrameInput input = shadowScene(spot);
    const Image image = renderImage(input, kSize, kSize);
    const Rect shadow = exactShadow(spot);
    int checkedDark = 0, checkedLit = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const auto p = hitHeight(pixelRay(input.camera, x, y), 0.0);
            const auto c = hitHeight(pixelRay(input.camera, x, y), kCasterHeight);
            if (!p || (std::abs(c->x) < 0.55 && std::abs(c->z) < 0.55))
                continue;
            const glm::dvec2 q{p->x, p->z};
            const double r = glm::length(q);
            if (shadow.contains(q) && shadow.edgeDistance(q) > 0.1) {
                EXPECT_LT(image.at(x, y).g, kInShadow) << x << "," << y;
                ++checkedDark;
            } else if (!shadow.contains(q) && shadow.edgeDistance(q) > 0.1 && r < 1.2) {
                EXPECT_GT(image.at(x, y).g, kLit) << x << "," << y;
                ++checkedLit;
            }
        }
    EXPECT_GT(checkedDark, 100);
    EXPECT_GT(checkedLit, 100);
}

TEST_F(GlTest, UnchangedLightAndCastersReuseTheShadowMapWithIdenticalPixels) {
    const FrameInput input = shadowScene(pointLight(3));
    const Image first = renderImage(input, 128, 128);
    ASSERT_FALSE(lastReport().ran.empty());
    EXPECT_EQ(lastReport().planned(lastReport().ran.front()).kind, PassKind::Shadow);
    const Image second = renderImage(input, 128, 128);
    bool reused = false;
    EXPECT_EQ(lastReport().countRan(PassKind::Shadow), 0u);
    for (const auto& skip : lastReport().skipped)
        reused |= skip.target == "Lamp" && skip.code == PlanReason::ShadowMapReused;
    EXPECT_TRUE(reused);
    EXPECT_EQ(first.rgba, second.rgba);

    FrameInput moved = input;
    moved.items[1].world = glm::translate(moved.items[1].world, glm::dvec3(0.1, 0.0, 0.0));
    renderImage(moved, 128, 128);
    ASSERT_FALSE(lastReport().ran.empty());
    EXPECT_EQ(lastReport().planned(lastReport().ran.front()).kind, PassKind::Shadow)
        << "a moved caster must re-render the map";
}

} // namespace
} // namespace speculum::test

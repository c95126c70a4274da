// Planar mirrors seen in rendered pixels, for both techniques: the reflection is where geometry says,
// never outside the mirror, never of what is behind it, and the back of a mirror reflects nothing.
#include "render/mesh/Primitives.hpp"
#include "render/plan/Planner.hpp"
#include "support/GlTest.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace speculum::test {
namespace {

using namespace render;

constexpr int kWidth = 320;
constexpr int kHeight = 240;

Material emissive(glm::dvec3 color) {
    Material m;
    m.color = {0.0, 0.0, 0.0};
    m.ambient = 0.0;
    m.diffuse = 0.0;
    m.emission = color;
    return m;
}

DrawItem cube(const std::string& name, glm::dvec3 centre, double half, glm::dvec3 color) {
    static const auto box = std::make_shared<const MeshData>(makeBox());
    return {name, glm::scale(glm::translate(glm::dmat4(1.0), centre), glm::dvec3(half)), box, emissive(color),
            false};
}

// A 4 × 3 mirror in the plane z = −2 facing +Z, seen from (0, 0, 4).
FrameInput mirrorScene(MirrorTechnique technique) {
    FrameInput input;
    input.settings.background = {0.0, 0.0, 0.0};
    input.settings.ambient = 0.0;
    input.camera.position = {0.0, 0.0, 4.0};
    input.camera.target = {0.0, 0.0, 0.0};
    input.camera.fovY = 60.0;
    input.camera.far = 30.0;
    Mirror mirror;
    mirror.name = "Mirror";
    mirror.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -2)), glm::radians(90.0),
                               glm::dvec3(1, 0, 0));
    mirror.size = {4.0, 3.0};
    mirror.reflectivity = 1.0;
    mirror.technique = technique;
    mirror.material = emissive({0.2, 0.2, 0.2}); // seen only where the mirror does not reflect
    mirror.hasMaterial = true;
    input.mirrors.push_back(mirror);
    return input;
}

struct Ray {
    glm::dvec3 origin, direction;
};

Ray pixelRay(const Camera& camera, int x, int y) {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double t = std::tan(glm::radians(camera.fovY) * 0.5);
    const double aspect = double(kWidth) / kHeight;
    const double nx = ((x + 0.5) / kWidth * 2.0 - 1.0) * t * aspect;
    const double ny = (1.0 - (y + 0.5) / kHeight * 2.0) * t;
    return {camera.position, glm::normalize(forward + right * nx + up * ny)};
}

bool hitsMirror(const Ray& ray) {
    if (std::abs(ray.direction.z) < 1e-12)
        return false;
    const double t = (-2.0 - ray.origin.z) / ray.direction.z;
    const glm::dvec3 p = ray.origin + t * ray.direction;
    return t > 0 && std::abs(p.x) <= 2.0 && std::abs(p.y) <= 1.5;
}

bool hitsBox(const Ray& ray, glm::dvec3 centre, double half) {
    double t0 = 0.0, t1 = 1e30;
    for (int a = 0; a < 3; ++a) {
        const double inv = 1.0 / ray.direction[a];
        double ta = (centre[a] - half - ray.origin[a]) * inv, tb = (centre[a] + half - ray.origin[a]) * inv;
        if (ta > tb)
            std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t0 <= t1;
}

// True if any of the 3×3 pixels around (x, y) satisfies f: one pixel of tolerance for rasterization.
template <typename F>
bool near(int x, int y, F f) {
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if (f(x + dx, y + dy))
                return true;
    return false;
}

bool isRed(const glm::vec4& c) {
    return c.r > 0.5f && c.g < 0.2f && c.b < 0.2f;
}
bool isGreen(const glm::vec4& c) {
    return c.g > 0.5f && c.r < 0.2f && c.b < 0.2f;
}

// Screen position of a world point.
glm::dvec2 project(const Camera& camera, glm::dvec3 p) {
    const glm::dmat4 vp =
        glm::perspective(glm::radians(camera.fovY), double(kWidth) / kHeight, camera.near, camera.far) *
        glm::lookAt(camera.position, camera.target, camera.up);
    const glm::dvec4 c = vp * glm::dvec4(p, 1.0);
    return {(c.x / c.w * 0.5 + 0.5) * kWidth, (0.5 - c.y / c.w * 0.5) * kHeight};
}

class Mirrors : public GlTest, public ::testing::WithParamInterface<MirrorTechnique> {};

TEST_P(Mirrors, ReflectionAppearsAtTheMirroredPosition) {
    FrameInput input = mirrorScene(GetParam());
    input.items.push_back(cube("Red", {1.0, 0.3, 0.0}, 0.3, {1, 0, 0}));
    const Image image = renderImage(input, kWidth, kHeight);
    // The reflection of the cube's centre: through z = −2, at (1, 0.3, −4).
    const glm::dvec2 at = project(input.camera, {1.0, 0.3, -4.0});
    EXPECT_TRUE(isRed(image.at(int(at.x), int(at.y)))) << at.x << "," << at.y;
    // The reflection is mirrored, not translated: its left-right order is kept, so a point left of the
    // reflected centre shows black, not red, once past the reflected cube's extent.
    const glm::dvec2 beside = project(input.camera, {0.0, 0.3, -4.0});
    EXPECT_FALSE(isRed(image.at(int(beside.x), int(beside.y))));
    ASSERT_FALSE(lastReport().plan.views.empty());
}

TEST_P(Mirrors, NothingOfTheReflectionAppearsOutsideTheMirror) {
    FrameInput input = mirrorScene(GetParam());
    // Its reflection straddles the mirror's right edge.
    const glm::dvec3 centre{2.4, 0.0, 0.0};
    input.items.push_back(cube("Red", centre, 0.3, {1, 0, 0}));
    const Image image = renderImage(input, kWidth, kHeight);
    int reflected = 0, stray = 0;
    for (int y = 1; y < kHeight - 1; ++y)
        for (int x = 1; x < kWidth - 1; ++x) {
            if (!isRed(image.at(x, y)))
                continue;
            const bool inMirror =
                near(x, y, [&](int px, int py) { return hitsMirror(pixelRay(input.camera, px, py)); });
            const bool onCube = near(
                x, y, [&](int px, int py) { return hitsBox(pixelRay(input.camera, px, py), centre, 0.3); });
            if (inMirror && !onCube)
                ++reflected;
            if (!inMirror && !onCube)
                ++stray;
        }
    EXPECT_GT(reflected, 20) << "the part of the reflection inside the mirror shows";
    EXPECT_EQ(stray, 0) << "red pixels outside both the mirror and the cube";
}

TEST_P(Mirrors, ObjectsBehindTheMirrorAreNeverReflected) {
    FrameInput input = mirrorScene(GetParam());
    input.items.push_back(cube("Hidden", {0.5, 0.0, -3.0}, 0.4, {0, 1, 0}));
    const Image image = renderImage(input, kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            ASSERT_FALSE(isGreen(image.at(x, y))) << "green at " << x << "," << y;
}

TEST_P(Mirrors, ObjectPushedThroughTheMirrorShowsOnlyItsPartInFront) {
    FrameInput input = mirrorScene(GetParam());
    // A bar from z = −2.6 to z = −1.4: half in front of the mirror (z > −2), half behind.
    static const auto box = std::make_shared<const MeshData>(makeBox());
    DrawItem bar{
        "Bar",
        glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(-1.0, -0.5, -2.0)), glm::dvec3(0.2, 0.2, 0.6)),
        box, emissive({1, 0, 0}), false};
    input.items.push_back(bar);
    const Image image = renderImage(input, kWidth, kHeight);
    // Its reflection can only be the front half reflected: z from −2.6 (image of −1.4) to −2.
    const glm::dvec2 deep = project(input.camera, {-1.0, -0.5, -2.5});
    EXPECT_TRUE(isRed(image.at(int(deep.x), int(deep.y)))) << "reflection of the front half";
    // Without the oblique near plane, the back half would reflect to z in (−2, −1.4): in front of the mirror,
    // where the stencil still lets the mirror's pixels through. The mirror's pixels beside the real bar must
    // not be red; check along a ray that sees the mirror just outside the real bar.
    int redInMirrorOutsideBar = 0, redExpected = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const Ray ray = pixelRay(input.camera, x, y);
            if (!hitsMirror(ray) || !isRed(image.at(x, y)))
                continue;
            // Where does this ray's reflection go? Reflect it at the mirror and test the front half.
            const double t = (-2.0 - ray.origin.z) / ray.direction.z;
            const glm::dvec3 hit = ray.origin + t * ray.direction;
            const Ray bounced{hit, {ray.direction.x, ray.direction.y, -ray.direction.z}};
            const bool seesFrontHalf = near(x, y, [&](int px, int py) {
                const Ray r = pixelRay(input.camera, px, py);
                const double tt = (-2.0 - r.origin.z) / r.direction.z;
                const Ray b{r.origin + tt * r.direction, {r.direction.x, r.direction.y, -r.direction.z}};
                return hitsBox(b, {-1.0, -0.5, -1.7}, 0.3) || hitsBox(r, {-1.0, -0.5, -1.7}, 0.3);
            });
            (void)bounced;
            if (seesFrontHalf)
                ++redExpected;
            else
                ++redInMirrorOutsideBar;
        }
    EXPECT_GT(redExpected, 10);
    EXPECT_EQ(redInMirrorOutsideBar, 0);
}

TEST_P(Mirrors, TheBackOfAMirrorReflectsNothing) {
    FrameInput input = mirrorScene(GetParam());
    input.items.push_back(cube("Red", {1.0, 0.0, 0.0}, 0.3, {1, 0, 0}));
    // The camera behind the mirror, looking at its back; the red cube is on the other side.
    input.camera.position = {0.3, 0.2, -6.0};
    input.camera.target = {0.0, 0.0, -2.0};
    const Image image = renderImage(input, kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            ASSERT_FALSE(isRed(image.at(x, y))) << x << "," << y;
    EXPECT_TRUE(lastReport().plan.views.empty());
    bool reason = false;
    for (const auto& s : lastReport().skipped)
        reason |= s.target == "Mirror" && s.code == PlanReason::MirrorBehind;
    EXPECT_TRUE(reason);
    // The mirror's back shows its own material.
    const glm::vec4 centre = image.at(kWidth / 2, kHeight / 2);
    EXPECT_NEAR(centre.r, 0.2f, 0.02f);
}

TEST_P(Mirrors, CameraOnTheMirrorPlaneAndJustAboveItGiveFiniteImages) {
    for (double height : {0.0, 1e-4}) {
        FrameInput input = mirrorScene(GetParam());
        input.items.push_back(cube("Red", {1.0, 0.0, 0.0}, 0.3, {1, 0, 0}));
        input.camera.position = {0.0, 0.0, -2.0 + height};
        input.camera.target = {1.0, 0.0, -2.0 + height};
        const Image image = renderImage(input, 64, 48);
        ASSERT_EQ(image.width, 64);
        for (float v : image.rgba)
            ASSERT_TRUE(std::isfinite(v)) << height;
    }
}

TEST_P(Mirrors, TwoFacingMirrorsNestToTheDepthLimitWithFiniteViews) {
    FrameInput input = mirrorScene(GetParam());
    input.settings.mirrorDepth = 8;
    Mirror front = input.mirrors[0];
    front.name = "Front";
    // Facing the first mirror from z = +2, seen from behind... no: both face the gap between them; the
    // camera sits between them looking slightly off-axis so every nesting level is visible.
    front.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 2)), glm::radians(-90.0),
                              glm::dvec3(1, 0, 0));
    input.mirrors.push_back(front);
    input.camera.position = {0.4, 0.2, 1.0};
    input.camera.target = {0.0, 0.0, -2.0};
    input.items.push_back(cube("Red", {0.0, 0.0, 0.0}, 0.2, {1, 0, 0}));
    const Image image = renderImage(input, kWidth, kHeight);
    for (float v : image.rgba)
        ASSERT_TRUE(std::isfinite(v));
    int deepest = 0;
    for (const MirrorView& view : lastReport().plan.views) {
        deepest = std::max(deepest, view.depth);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                ASSERT_TRUE(std::isfinite(view.projection[c][r]));
    }
    EXPECT_EQ(deepest, 8) << "the corridor reaches the depth limit";
    // The nested images of the red cube: more red blobs than the cube itself.
    int red = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            red += isRed(image.at(x, y));
    EXPECT_GT(red, 200);
}

INSTANTIATE_TEST_SUITE_P(Techniques, Mirrors,
                         ::testing::Values(MirrorTechnique::Stencil, MirrorTechnique::Texture),
                         [](const auto& info) {
                             return info.param == MirrorTechnique::Stencil ? std::string("Stencil")
                                                                           : std::string("Texture");
                         });

} // namespace
} // namespace speculum::test

namespace speculum::test {
namespace {

using namespace render;

// A lit sphere: with a negative scale its triangles wind the other way, which must not turn its lighting
// inside out, directly or in a mirror.
TEST_F(GlTest, NegativeScaleObjectsAreLitTheSameDirectlyAndInMirrors) {
    auto renderSphere = [&](double sx, bool throughMirror) {
        FrameInput input;
        input.settings.background = {0, 0, 0};
        input.settings.ambient = 0.0;
        input.camera.position = {0, 0, 4};
        input.camera.target = {0, 0, 0};
        input.camera.fovY = 40.0;
        auto sphere = std::make_shared<const MeshData>(makeSphere(48));
        DrawItem ball{"Ball", glm::scale(glm::dmat4(1.0), glm::dvec3(sx, 1.0, 1.0)), sphere, {}, false};
        Light light;
        light.type = LightType::Directional;
        light.direction = glm::normalize(glm::dvec3(-1, -0.5, -1));
        input.lights = {light};
        if (throughMirror) {
            // Look at the ball's reflection in a mirror behind the camera-facing side: the ball moves to
            // the mirror's other side and the camera looks at the mirror.
            Mirror mirror;
            mirror.name = "Mirror";
            mirror.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, -2)),
                                       glm::radians(90.0), glm::dvec3(1, 0, 0));
            mirror.size = {8, 8};
            input.mirrors = {mirror};
            ball.world = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 2)) * ball.world;
            input.camera.position = {0, 0, 6};
            input.camera.fovY = 20.0;
            // Light the side that faces the mirror.
            input.lights[0].direction = glm::normalize(glm::dvec3(-1, -0.5, 1));
        }
        input.items = {ball};
        return renderImage(input, 96, 96);
    };
    for (bool mirror : {false, true}) {
        const Image positive = renderSphere(1.0, mirror);
        const Image negative = renderSphere(-1.0, mirror);
        ASSERT_EQ(positive.rgba.size(), negative.rgba.size());
        double difference = 0.0, brightness = 0.0;
        for (std::size_t i = 0; i < positive.rgba.size(); ++i) {
            difference = std::max(difference, double(std::abs(positive.rgba[i] - negative.rgba[i])));
            brightness = std::max(brightness, double(positive.rgba[i]));
        }
        EXPECT_GT(brightness, 0.5) << "the lit side is visible (mirror: " << mirror << ")";
        EXPECT_LT(difference, 0.05) << "mirror: " << mirror;
    }
}

TEST_F(GlTest, MirrorPartlyOffScreenReflectsOnlyItsVisiblePart) {
    FrameInput input;
    input.settings.background = {0, 0, 0};
    input.camera.position = {0, 0, 4};
    input.camera.target = {0, 0, 0};
    input.camera.fovY = 60.0;
    Mirror mirror;
    mirror.name = "Mirror";
    // Centred far to the right: only its left part is on screen.
    mirror.world = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(4, 0, -2)), glm::radians(90.0),
                               glm::dvec3(1, 0, 0));
    mirror.size = {6, 3};
    input.mirrors = {mirror};
    auto box = std::make_shared<const MeshData>(makeBox());
    Material red;
    red.color = {0, 0, 0};
    red.ambient = red.diffuse = 0.0;
    red.emission = {1, 0, 0};
    input.items = {{"Red", glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(2, 0, 0)), glm::dvec3(0.3)),
                    box, red, false}};
    const Image image = renderImage(input, 160, 120);
    ASSERT_EQ(lastReport().plan.views.size(), 1u);
    const math::PixelRect rect = lastReport().plan.views[0].rect;
    EXPECT_EQ(rect.x1, 160) << "clamped to the screen";
    EXPECT_GT(rect.x0, 60);
    int redPixels = 0;
    for (float v : image.rgba)
        ASSERT_TRUE(std::isfinite(v));
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x)
            redPixels += image.at(x, y).r > 0.5f;
    EXPECT_GT(redPixels, 20);
}

// A perfect stencil mirror skips shading its own surface and only tints the reflection: its image must
// be the one a lit mirror gives as its reflectivity approaches 1 (here 0.9999, off by 1e-4 of the surface).
TEST_F(GlTest, PerfectMirrorLooksLikeAMirrorOfReflectivityJustUnderOne) {
    FrameInput input = mirrorScene(MirrorTechnique::Stencil);
    input.settings.ambient = 0.3;
    input.mirrors[0].tint = {1.0, 0.5, 0.25};
    input.mirrors[0].hasMaterial = false; // a plain grey lit surface under the reflection
    Light light;
    light.name = "Light";
    light.position = {0, 3, 2};
    light.shadows = render::ShadowParams{512, 3};
    input.lights = {light};
    input.items.push_back(cube("Red", {1.0, 0.3, 0.0}, 0.3, {1, 0, 0}));
    input.items.push_back(cube("Green", {-1.0, -0.3, 0.5}, 0.3, {0, 1, 0}));
    const Image perfect = renderImage(input, kWidth, kHeight);
    input.mirrors[0].reflectivity = 0.9999;
    const Image lit = renderImage(input, kWidth, kHeight);
    float largest = 0.0f;
    int tinted = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec4 a = perfect.at(x, y), b = lit.at(x, y);
            largest = std::max({largest, std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
            tinted += a.r > 0.5f && a.g < 0.2f; // the red cube's reflection, tint applied
        }
    EXPECT_LT(largest, 2.0f / 255.0f);
    EXPECT_GT(tinted, 20);
}

} // namespace
} // namespace speculum::test

// Mirror math in double precision: reflection matrices, Lengyel's oblique near plane, and the hard
// cases (camera on, just above and behind the plane; edge-on; far from the origin; bad normals).
#include "render/math/Mirror.hpp"

#include "render/math/Projection.hpp"
#include "render/plan/Planner.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <random>

namespace speculum::render::math {
namespace {

bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r]))
                return false;
    return true;
}

Plane tiltedPlane() {
    const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, 1.0, -0.2));
    return {n, -glm::dot(n, glm::dvec3(1.0, -1.0, -3.0))};
}

TEST(ReflectionMatrix, IsAnInvolutionWithDeterminantMinusOneThatFixesThePlane) {
    const Plane plane = tiltedPlane();
    auto r = reflectionMatrix(plane);
    ASSERT_TRUE(r.ok()) << r.error();
    const glm::dmat4 rr = *r * *r;
    for (int c = 0; c < 4; ++c)
        for (int row = 0; row < 4; ++row)
            EXPECT_NEAR(rr[c][row], c == row ? 1.0 : 0.0, 1e-12);
    EXPECT_NEAR(glm::determinant(*r), -1.0, 1e-12);
    // A point on the plane stays; a point above lands as far below.
    const glm::dvec3 onPlane = glm::dvec3(1.0, -1.0, -3.0);
    EXPECT_NEAR(glm::length(glm::dvec3(*r * glm::dvec4(onPlane, 1.0)) - onPlane), 0.0, 1e-12);
    const glm::dvec3 above = onPlane + 0.7 * plane.normal;
    EXPECT_NEAR(plane.distance(glm::dvec3(*r * glm::dvec4(above, 1.0))), -0.7, 1e-12);
}

TEST(ReflectionMatrix, ZeroAndNonUnitNormalsAreClearErrors) {
    auto zero = reflectionMatrix({{0, 0, 0}, 1.0});
    ASSERT_FALSE(zero.ok());
    EXPECT_NE(zero.error().find("zero"), std::string::npos);
    auto long_ = reflectionMatrix({{0, 2, 0}, 1.0});
    ASSERT_FALSE(long_.ok());
    EXPECT_NE(long_.error().find("unit"), std::string::npos);
    auto nan = reflectionMatrix({{0, NAN, 0}, 1.0});
    EXPECT_FALSE(nan.ok());
}

TEST(MirrorPlane, FollowsLocalYThroughScalesAndRejectsCollapsedRectangles) {
    glm::dmat4 world = glm::translate(glm::dmat4(1.0), glm::dvec3(0, -1, -3));
    auto plane = mirrorPlane(world);
    ASSERT_TRUE(plane.ok());
    EXPECT_NEAR(plane->normal.y, 1.0, 1e-15);
    EXPECT_NEAR(plane->distance({0, 0, 0}), 1.0, 1e-15);
    // Negative scales (mirroring node transforms) keep the reflective side where local +Y goes.
    auto flippedX = mirrorPlane(glm::scale(world, glm::dvec3(-2, 1, 1)));
    ASSERT_TRUE(flippedX.ok());
    EXPECT_NEAR(flippedX->normal.y, 1.0, 1e-15);
    auto flippedY = mirrorPlane(glm::scale(world, glm::dvec3(1, -1, 1)));
    ASSERT_TRUE(flippedY.ok());
    EXPECT_NEAR(flippedY->normal.y, -1.0, 1e-15);
    // A zero Y scale still has a plane; a zero X or Z scale has no area.
    EXPECT_TRUE(mirrorPlane(glm::scale(world, glm::dvec3(1, 0, 1))).ok());
    auto collapsed = mirrorPlane(glm::scale(world, glm::dvec3(0, 1, 1)));
    ASSERT_FALSE(collapsed.ok());
    EXPECT_NE(collapsed.error().find("zero area"), std::string::npos);
}

struct ObliqueCase {
    glm::dmat4 projection = perspective(65.0, 16.0 / 9.0, 0.1, 10.0);
    glm::dmat4 view = glm::lookAt(glm::dvec3(0, 0.5, 1), glm::dvec3(0, -1, -3), glm::dvec3(0, 1, 0));
    Plane mirror{{0, 1, 0}, 1.0}; // y = −1, reflective side up
    // The plane as the reflected pass clips: keep what lies on the reflective side, in view space of the
    // reflected geometry (the reflection maps the kept side behind the mirror).
    glm::dvec4 clipInView(const glm::dmat4& reflection) const {
        return transformPlane(transformPlane(glm::dvec4(mirror.normal, mirror.d), reflection), view);
    }
};

TEST(ObliqueProjection, PointsOnTheMirrorLandOnTheNearPlaneAndTheFarContentStays) {
    ObliqueCase c;
    auto r = reflectionMatrix(c.mirror);
    ASSERT_TRUE(r.ok());
    auto oblique = obliqueProjection(c.projection, c.clipInView(*r));
    ASSERT_TRUE(oblique.ok()) << oblique.error();
    EXPECT_TRUE(finite(*oblique));
    // Mirror plane points, seen through the reflected view, map to z_ndc = −1.
    for (double x : {-1.5, 0.0, 1.7})
        for (double z : {-4.5, -3.0, -1.2}) {
            const glm::dvec4 clip = *oblique * c.view * *r * glm::dvec4(x, -1.0, z, 1.0);
            EXPECT_NEAR(clip.z / clip.w, -1.0, 1e-9) << x << "," << z;
        }
    // Whatever the original frustum held beyond the plane is still inside the new one (far plane included).
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const glm::dmat4 inverse = glm::inverse(c.projection);
    const glm::dvec4 clipPlane = c.clipInView(*r);
    int kept = 0;
    for (int i = 0; i < 20000; ++i) {
        glm::dvec4 p = inverse * glm::dvec4(u(rng), u(rng), u(rng) * 0.999, 1.0);
        p /= p.w;
        if (glm::dot(clipPlane, p) < 1e-9)
            continue; // in front of the mirror: the oblique near plane clips it, as it must
        ++kept;
        const glm::dvec4 clip = *oblique * p;
        EXPECT_LE(std::abs(clip.z), clip.w * (1.0 + 1e-9));
        EXPECT_LE(std::abs(clip.x), clip.w * (1.0 + 1e-9));
    }
    EXPECT_GT(kept, 200);
    // Points on the far plane of the original frustum, beyond the mirror, are not clipped.
    const glm::dvec4 farCentre = inverse * glm::dvec4(0.0, -0.9, 1.0, 1.0);
    const glm::dvec4 clip = *oblique * (farCentre / farCentre.w);
    EXPECT_LE(clip.z, clip.w * (1.0 + 1e-9));
}

TEST(ObliqueProjection, CameraOnOrBehindThePlaneGetsAnErrorNotANan) {
    const glm::dmat4 projection = perspective(65.0, 1.0, 0.1, 10.0);
    // View space: camera at the origin. Plane through the camera.
    auto on = obliqueProjection(projection, {0, 1, 0, 0});
    ASSERT_FALSE(on.ok());
    EXPECT_NE(on.error().find("on the mirror plane"), std::string::npos);
    auto behind = obliqueProjection(projection, {0, 1, 0, 0.5});
    ASSERT_FALSE(behind.ok());
    EXPECT_NE(behind.error().find("behind"), std::string::npos);
    // 1e-4 above the plane is fine and finite.
    auto above = obliqueProjection(projection, {0, 1, 0, -1e-4});
    ASSERT_TRUE(above.ok()) << above.error();
    EXPECT_TRUE(finite(*above));
}

TEST(ObliqueProjection, PlaneThroughTheFarCornerIsReportedEdgeOn) {
    const glm::dmat4 projection = perspective(90.0, 1.0, 0.1, 10.0);
    // The far corner in view space is (10, 10, −10) for a 90° square frustum; a plane through it whose
    // normal keeps the camera on its negative side.
    const glm::dvec3 corner(10.0, 10.0, -10.0);
    const glm::dvec3 n = glm::normalize(glm::dvec3(1.0, 1.0, 0.5));
    auto result = obliqueProjection(projection, glm::dvec4(n, -glm::dot(n, corner)));
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().find("edge-on"), std::string::npos);
    // Nearly parallel to the view direction but not through the corner: still a finite matrix.
    const glm::dvec3 grazing = glm::normalize(glm::dvec3(0.0, 1.0, 1e-7));
    auto nearly = obliqueProjection(projection, glm::dvec4(grazing, -0.5));
    ASSERT_TRUE(nearly.ok()) << nearly.error();
    EXPECT_TRUE(finite(*nearly));
}

TEST(ObliqueProjection, MirrorFarFromTheOriginIsAsPreciseAsNearIt) {
    // Camera-relative: the planner builds the same view-space plane whatever the absolute position.
    for (double offset : {0.0, 1e5}) {
        FrameInput input;
        input.camera.position = {offset, 0.0, 1.0};
        input.camera.target = {offset, -1.0, -3.0};
        Mirror mirror;
        mirror.name = "Far mirror";
        mirror.world = glm::translate(glm::dmat4(1.0), glm::dvec3(offset, -1.0, -3.0));
        mirror.size = {4.0, 4.0};
        input.mirrors.push_back(mirror);
        const FramePlan plan = planFrame(input, {}, {640, 360});
        ASSERT_EQ(plan.views.size(), 1u) << offset;
        const MirrorView& v = plan.views[0];
        EXPECT_TRUE(finite(v.projection));
        // The virtual eye lies as far below the mirror plane (y = −1) as the camera (y = 0) is above it.
        EXPECT_NEAR(v.eye.y, -2.0, 1e-9) << offset;
        EXPECT_NEAR(v.eye.x, offset, 1e-9);
        EXPECT_GT(v.pixelArea, 1000.0);
    }
}

TEST(ScreenCoverage, ClipsToTheViewAndToTheParentsPixels) {
    const glm::dmat4 vp = perspective(90.0, 1.0, 0.1, 100.0) *
                          glm::lookAt(glm::dvec3(0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0));
    // A square filling the middle half of a 100×100 view.
    const std::vector<glm::dvec3> square = {
        {-0.5, -0.5, -1}, {0.5, -0.5, -1}, {0.5, 0.5, -1}, {-0.5, 0.5, -1}};
    const ScreenCoverage full = screenCoverage(square, vp, 100, 100, {0, 0, 100, 100});
    EXPECT_NEAR(full.pixelArea, 2500.0, 1e-6);
    // The pixel rectangle is conservative: it contains every covered pixel.
    EXPECT_GE(full.rect.x0, 24);
    EXPECT_LE(full.rect.x0, 25);
    EXPECT_GE(full.rect.x1, 75);
    EXPECT_LE(full.rect.x1, 76);
    const ScreenCoverage clipped = screenCoverage(square, vp, 100, 100, {0, 0, 50, 100});
    EXPECT_NEAR(clipped.pixelArea, 1250.0, 1e-6);
    // Partly behind the camera: clipped at the near plane, never inverted.
    const std::vector<glm::dvec3> crossing = {{-1, -1, 1}, {1, -1, 1}, {1, -1, -5}, {-1, -1, -5}};
    const ScreenCoverage floor = screenCoverage(crossing, vp, 100, 100, {0, 0, 100, 100});
    EXPECT_GT(floor.pixelArea, 100.0);
    EXPECT_LE(floor.rect.y1, 50);
}

} // namespace
} // namespace speculum::render::math

namespace speculum::render::math {
namespace {

// A mirror 1e12 wide seen from 6 m: only the part in view is drawn, it lies within the rectangle and
// covers the whole frustum's cross-section; a small mirror is drawn whole (its texture coordinates kept).
TEST(VisibleMirrorRectangle, NarrowsAHugeMirrorToThePartInView) {
    const glm::dmat4 view = glm::lookAt(glm::dvec3(0.5, 0.3, 6.0), glm::dvec3(0.0), glm::dvec3(0, 1, 0));
    const glm::dmat4 projection = glm::perspective(glm::radians(65.0), 4.0 / 3.0, 0.1, 100.0);
    // The unit square of local XZ turned to face +Z, 1e12 across.
    const glm::dmat4 rectangle = glm::scale(
        glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(1, 0, 0)), glm::dvec3(5e11, 1.0, 5e11));
    const glm::dmat4 part = visibleMirrorRectangle(rectangle, projection * view * rectangle);
    ASSERT_TRUE(finite(part));
    // Its corners: within a few hundred metres (far is 100), so float rounding is millimetres.
    for (const glm::dvec2& c : {glm::dvec2(-1, -1), glm::dvec2(1, 1)}) {
        const glm::dvec3 p(part * glm::dvec4(c.x, 0.0, c.y, 1.0));
        EXPECT_LT(glm::length(p), 1e3);
        EXPECT_NEAR(p.z, 0.0, 1e-6); // still in the mirror's plane
    }
    // Every point of the frustum on the plane z = 0 lies inside the part: the view's four corner rays.
    const glm::dmat4 inverse = glm::inverse(projection * view);
    const glm::dmat4 toLocal = glm::inverse(part);
    for (const glm::dvec2& ndc :
         {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)}) {
        glm::dvec4 a = inverse * glm::dvec4(ndc, -1.0, 1.0), b = inverse * glm::dvec4(ndc, 1.0, 1.0);
        const glm::dvec3 pa = glm::dvec3(a) / a.w, pb = glm::dvec3(b) / b.w;
        const glm::dvec3 onPlane = pa + (pb - pa) * (-pa.z / (pb.z - pa.z));
        const glm::dvec4 local = toLocal * glm::dvec4(onPlane, 1.0);
        EXPECT_LE(std::abs(local.x), 1.0) << ndc.x << "," << ndc.y;
        EXPECT_LE(std::abs(local.z), 1.0) << ndc.x << "," << ndc.y;
    }
    const glm::dmat4 small = glm::scale(glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(1, 0, 0)),
                                        glm::dvec3(2.0, 1.0, 2.0));
    EXPECT_EQ(visibleMirrorRectangle(small, projection * view * small), small);
}

} // namespace
} // namespace speculum::render::math

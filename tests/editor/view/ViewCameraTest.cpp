// The viewport's own camera, without a viewport: orbit, pan, zoom and framing keep the geometry a user
// expects (distance, direction, far plane) and never flip over a pole.
#include "editor/view/ViewCamera.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

namespace {

TEST(ViewCamera, OrbitKeepsDistanceZoomScalesItPanMovesBoth) {
    speculum::render::Camera scene;
    scene.position = {0.0, 0.0, 1.0};
    scene.target = {0.0, 0.0, -3.0};
    speculum::view::ViewCamera view;
    view.reset(scene);

    view.orbit(90.0, 0.0);
    EXPECT_NEAR(glm::length(view.camera().position - view.camera().target), 4.0, 1e-9);
    EXPECT_NEAR(view.camera().position.y, 0.0, 1e-9);
    EXPECT_NEAR(std::abs(view.camera().position.x), 4.0, 1e-9); // a quarter turn around the target
    view.orbit(0.0, 500.0);                                     // far past the pole: clamped, never flips
    const glm::dvec3 offset = glm::normalize(view.camera().position - view.camera().target);
    EXPECT_LT(std::abs(offset.y), 1.0);
    EXPECT_GT(std::abs(offset.y), 0.99);

    view.reset(scene);
    view.zoom(0.5);
    EXPECT_NEAR(glm::length(view.camera().position - view.camera().target), 2.0, 1e-9);
    view.zoom(10.0);
    EXPECT_NEAR(glm::length(view.camera().position - view.camera().target), 20.0, 1e-9);
    EXPECT_GE(view.camera().far, scene.far + 16.0 - 1e-9); // the scene stays inside the far plane

    view.reset(scene);
    view.pan(0.25, 0.0);
    EXPECT_GT(view.camera().position.x, 0.0);
    EXPECT_DOUBLE_EQ(view.camera().position.x, view.camera().target.x);
    EXPECT_NEAR(view.camera().target.z, -3.0, 1e-12);
}

TEST(ViewCamera, FrameFillsTheViewWithTheSphereFromTheSameDirection) {
    speculum::render::Camera scene;
    scene.position = {0.0, 0.0, 1.0};
    scene.target = {0.0, 0.0, -3.0};
    scene.fovY = 60.0;
    speculum::view::ViewCamera view;
    view.reset(scene);

    const glm::dvec3 center{10.0, 0.0, -3.0};
    view.frame(center, 2.0, 2.0); // wider than high: the vertical field of view decides
    const speculum::render::Camera& framed = view.camera();
    EXPECT_NEAR(glm::length(framed.target - center), 0.0, 1e-9);
    const glm::dvec3 direction = glm::normalize(framed.position - framed.target);
    EXPECT_NEAR(glm::dot(direction, glm::dvec3(0.0, 0.0, 1.0)), 1.0, 1e-9) << "looks from where it looked";
    // The sphere fills the height of the view with a tenth to spare: distance = 1.1 radius / sin(fovY / 2).
    EXPECT_NEAR(glm::length(framed.position - framed.target), 1.1 * 2.0 / std::sin(glm::radians(30.0)), 1e-6);
    EXPECT_GT(framed.far, glm::length(framed.position - framed.target) + 2.0) << "the far plane keeps it";
}

// The orbit follows the rule of three.js OrbitControls (and Blender's turntable): the scene
// follows the mouse. rotateUp(2π·Δy/h) with Δy = now − before and phi -= angle: dragging down shrinks the
// angle from +Y, so the camera rises; rotateLeft likewise: dragging right moves the camera to its left.
speculum::render::Camera sideCamera() {
    speculum::render::Camera scene;
    scene.position = {0.0, 0.0, 1.0}; // 4 units in front of the target, level with it
    scene.target = {0.0, 0.0, -3.0};
    return scene;
}

double angleFromUpDegrees(const speculum::render::Camera& c) {
    const glm::dvec3 offset = glm::normalize(c.position - c.target);
    return glm::degrees(std::acos(offset.y));
}

TEST(ViewCamera, DraggingDownRaisesTheCameraAsInThreeJsAndBlender) {
    speculum::view::ViewCamera view;
    view.reset(sideCamera());
    ASSERT_FALSE(view.invertedVertical()) << "the default is Blender's direction";

    view.orbitByDrag(0.0, 50.0, 500.0); // a tenth of the height down: 18° up towards the pole
    EXPECT_NEAR(angleFromUpDegrees(view.camera()), 90.0 - 18.0, 1e-9);
    EXPECT_GT(view.camera().position.y, 0.0) << "looks more from above";
    EXPECT_NEAR(glm::length(view.camera().position - view.camera().target), 4.0, 1e-9);

    view.reset(sideCamera());
    view.orbitByDrag(0.0, -50.0, 500.0); // up: the camera goes below the target
    EXPECT_NEAR(angleFromUpDegrees(view.camera()), 90.0 + 18.0, 1e-9);

    view.reset(sideCamera());
    view.orbitByDrag(50.0, 0.0, 500.0); // right: the camera moves to its left (−X from +Z)
    EXPECT_LT(view.camera().position.x, 0.0);
    EXPECT_NEAR(view.camera().position.y, 0.0, 1e-12);
}

TEST(ViewCamera, InvertedVerticalOrbitTurnsTheOtherWayAndSurvivesReset) {
    speculum::view::ViewCamera view;
    view.setInvertedVertical(true);
    view.reset(sideCamera()); // a preference, not part of the camera
    ASSERT_TRUE(view.invertedVertical());
    view.orbitByDrag(0.0, 50.0, 500.0);
    EXPECT_NEAR(angleFromUpDegrees(view.camera()), 90.0 + 18.0, 1e-9) << "down lowers the camera";
    view.orbitByDrag(30.0, 0.0, 500.0);
    EXPECT_LT(view.camera().position.x, 0.0) << "horizontal is not inverted";
}

TEST(ViewCamera, PitchStopsTwoDegreesShortOfEitherPole) {
    speculum::view::ViewCamera view;
    view.reset(sideCamera());
    view.orbit(0.0, 87.0); // 3° from the top
    EXPECT_NEAR(angleFromUpDegrees(view.camera()), 3.0, 1e-9);
    view.orbit(0.0, 5.0); // would pass the pole: stops at 2°
    EXPECT_NEAR(angleFromUpDegrees(view.camera()), 2.0, 1e-9);
    EXPECT_GT(view.camera().position.z, view.camera().target.z) << "still on the same side: no flip";
    view.orbit(0.0, -500.0);
    EXPECT_NEAR(angleFromUpDegrees(view.camera()), 178.0, 1e-9);
    EXPECT_GT(view.camera().position.z, view.camera().target.z);
}

TEST(ViewCamera, PlaceRestoresASavedViewAndKeepsItInsideTheFarPlane) {
    speculum::view::ViewCamera view;
    view.reset(sideCamera());
    view.place({0.0, 30.0, 20.0}, {1.0, 0.0, -3.0});
    EXPECT_EQ(view.camera().position, glm::dvec3(0.0, 30.0, 20.0));
    EXPECT_EQ(view.camera().target, glm::dvec3(1.0, 0.0, -3.0));
    EXPECT_EQ(view.camera().up, sideCamera().up);
    EXPECT_EQ(view.camera().fovY, sideCamera().fovY);
    EXPECT_GE(view.camera().far, glm::length(view.camera().position - view.camera().target));
    view.place({1.0, 0.0, -3.0}, {1.0, 0.0, -3.0}); // no direction: ignored
    EXPECT_EQ(view.camera().position, glm::dvec3(0.0, 30.0, 20.0));
}

} // namespace

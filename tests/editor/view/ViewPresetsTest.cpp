// Blender's numpad views in speculum's Y-up world, and the view camera taking them. Front looks
// along −Z, Right along −X, Top straight down with +X to the right and −Z up on screen; the opposite
// sides (Ctrl+numpad) look the other way; the distance to the target, the field of view and the depth
// range stay as they were, and orbiting on from a preset turns the usual way.
#include "editor/view/ViewPresets.hpp"

#include "editor/view/ViewCamera.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace {

using speculum::render::Camera;
using speculum::view::presetDirection;
using speculum::view::presetName;
using speculum::view::presetView;
using speculum::view::ViewCamera;
using speculum::view::ViewPreset;

constexpr ViewPreset kAll[] = {ViewPreset::Front, ViewPreset::Back, ViewPreset::Right,
                               ViewPreset::Left,  ViewPreset::Top,  ViewPreset::Bottom};

Camera obliqueCamera() {
    Camera c;
    c.position = {3.0, 2.0, 5.0};
    c.target = {1.0, 0.5, -1.0};
    c.fovY = 50.0;
    c.near = 0.05;
    c.far = 40.0;
    return c;
}

// The screen's right and up vectors of a camera, in world space.
glm::dvec3 screenRight(const Camera& c) {
    return glm::normalize(glm::cross(c.target - c.position, c.up));
}
glm::dvec3 screenUp(const Camera& c) {
    return glm::normalize(glm::cross(screenRight(c), c.target - c.position));
}

TEST(ViewPresets, EachLooksAtTheSameTargetFromItsSideAtTheSameDistance) {
    const Camera current = obliqueCamera();
    const double distance = glm::length(current.position - current.target);
    for (ViewPreset preset : kAll) {
        SCOPED_TRACE(std::string(presetName(preset)));
        const Camera view = presetView(current, preset);
        EXPECT_EQ(view.target, current.target);
        EXPECT_NEAR(glm::length(view.position - view.target), distance, 1e-9);
        const glm::dvec3 looking = glm::normalize(view.target - view.position);
        // Top and Bottom stop 2° short of the pole, as the orbit does.
        const double tolerance = preset == ViewPreset::Top || preset == ViewPreset::Bottom ? 0.0007 : 1e-12;
        EXPECT_NEAR(glm::dot(looking, presetDirection(preset)), 1.0, tolerance);
        EXPECT_EQ(view.up, glm::dvec3(0.0, 1.0, 0.0));
        EXPECT_EQ(view.fovY, current.fovY);
        EXPECT_EQ(view.near, current.near);
        EXPECT_EQ(view.far, current.far);
    }
}

TEST(ViewPresets, DirectionsAreBlendersInAYUpWorld) {
    EXPECT_EQ(presetDirection(ViewPreset::Front), glm::dvec3(0.0, 0.0, -1.0));
    EXPECT_EQ(presetDirection(ViewPreset::Right), glm::dvec3(-1.0, 0.0, 0.0));
    EXPECT_EQ(presetDirection(ViewPreset::Top), glm::dvec3(0.0, -1.0, 0.0));
    for (auto [a, b] : {std::pair{ViewPreset::Front, ViewPreset::Back},
                        {ViewPreset::Right, ViewPreset::Left},
                        {ViewPreset::Top, ViewPreset::Bottom}}) {
        EXPECT_EQ(presetDirection(a), -presetDirection(b)) << presetName(a) << " and " << presetName(b);
    }
}

TEST(ViewPresets, OnScreenXIsToTheRightAndTopShowsMinusZUp) {
    const Camera current = obliqueCamera();
    EXPECT_NEAR(glm::dot(screenRight(presetView(current, ViewPreset::Front)), {1.0, 0.0, 0.0}), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(screenUp(presetView(current, ViewPreset::Front)), {0.0, 1.0, 0.0}), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(screenRight(presetView(current, ViewPreset::Right)), {0.0, 0.0, -1.0}), 1.0, 1e-12);
    const Camera top = presetView(current, ViewPreset::Top);
    EXPECT_NEAR(glm::dot(screenRight(top), {1.0, 0.0, 0.0}), 1.0, 1e-9);
    EXPECT_GT(glm::dot(screenUp(top), {0.0, 0.0, -1.0}), 0.999);
}

TEST(ViewPresets, TheViewCameraTakesAPresetAndOrbitsOnFromItWithoutAJump) {
    ViewCamera view;
    view.reset(obliqueCamera());
    const Camera top = presetView(view.camera(), ViewPreset::Top);
    view.place(top.position, top.target, top.up);
    EXPECT_EQ(view.camera().position, top.position);
    EXPECT_EQ(view.camera().up, top.up);
    EXPECT_EQ(view.camera().fovY, obliqueCamera().fovY) << "the view's own field of view";

    // A small downward drag from the top view: the camera is already at the 2° limit, so it stays.
    const glm::dvec3 before = view.camera().position;
    view.orbitByDrag(0.0, 10.0, 600.0);
    EXPECT_NEAR(glm::length(view.camera().position - before), 0.0, 1e-9);
    // Upward, it leaves the pole at once (no dead zone to catch up with first).
    view.orbitByDrag(0.0, -10.0, 600.0);
    EXPECT_GT(glm::length(view.camera().position - before), 1e-3);
}

TEST(ViewPresets, APlacedUpAlongTheViewIsIgnored) {
    Camera tilted = obliqueCamera();
    tilted.up = {0.0, 0.0, 1.0};
    ViewCamera view;
    view.reset(tilted);
    const glm::dvec3 up = view.camera().up;
    view.place({0.0, 5.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}); // looking straight down along −up
    EXPECT_EQ(view.camera().position, glm::dvec3(0.0, 5.0, 0.0));
    EXPECT_EQ(view.camera().up, up);
    view.place({0.0, 0.0, 5.0}, {0.0, 0.0, 0.0}, {0.0, std::nan(""), 0.0});
    EXPECT_EQ(view.camera().up, up);
}

} // namespace

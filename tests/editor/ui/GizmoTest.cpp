// How a handle drag of the current node carries over to the other selected nodes: the same world
// displacement in each one's parent space, the same angles, the same factors.
#include "editor/ui/Gizmo.hpp"

#include "scene/model/NodeMath.hpp"
#include "scene/model/SceneData.hpp"

#include <gtest/gtest.h>

namespace {

using namespace speculum;

TEST(FollowDrag, MovesByTheSameWorldDisplacementInEachParentsSpace) {
    speculum::scene::NodeData leadStart, leadNow, other;
    leadStart.transform.translate = {1, 1, 1};
    leadNow.transform.translate = {2, 3, 1}; // under a parent scaled by 2: a world move of (2, 4, 0)
    const glm::dmat4 leadParent = speculum::scene::localMatrix({7, 0, 0}, {0, 0, 0}, {2, 2, 2});
    other.transform.translate = {5, 0, 0};
    other.material = speculum::scene::MaterialComponent{};
    // Under a parent turned 90° about Z: world +X is the parent's -Y, world +Y its +X.
    const glm::dmat4 otherParent = speculum::scene::localMatrix({0, 0, -3}, {0, 0, 90}, {1, 1, 1});
    const speculum::scene::NodeData out =
        ui::followDrag(ui::HandleMode::Move, leadStart, leadNow, leadParent, other, otherParent);
    EXPECT_NEAR(out.transform.translate.x, 5.0 + 4.0, 1e-12);
    EXPECT_NEAR(out.transform.translate.y, 0.0 - 2.0, 1e-12);
    EXPECT_NEAR(out.transform.translate.z, 0.0, 1e-12);
    EXPECT_EQ(out.transform.rotate, other.transform.rotate);
    EXPECT_EQ(out.material, other.material) << "only the transform changes";

    // A parent scaled to zero cannot take a world displacement: the node stays.
    const glm::dmat4 flat = speculum::scene::localMatrix({0, 0, 0}, {0, 0, 0}, {0, 0, 0});
    EXPECT_EQ(ui::followDrag(ui::HandleMode::Move, leadStart, leadNow, leadParent, other, flat), other);
}

TEST(FollowDrag, RotatesByTheSameAnglesAndScalesByTheSameFactors) {
    speculum::scene::NodeData leadStart, leadNow, other;
    leadStart.transform.rotate = {10, 0, 0};
    leadNow.transform.rotate = {10, 0, 30};
    other.transform.rotate = {0, 45, 5};
    const glm::dmat4 identity(1.0);
    EXPECT_EQ(ui::followDrag(ui::HandleMode::Rotate, leadStart, leadNow, identity, other, identity)
                  .transform.rotate,
              glm::dvec3(0, 45, 35));

    leadStart.transform.scale = {0.5, 0, 1};
    leadNow.transform.scale = {1, 3, 1}; // y started at zero: no factor to carry over
    other.transform.scale = {2, 4, 6};
    EXPECT_EQ(
        ui::followDrag(ui::HandleMode::Scale, leadStart, leadNow, identity, other, identity).transform.scale,
        glm::dvec3(4, 4, 6));

    EXPECT_EQ(ui::followDrag(ui::HandleMode::Select, leadStart, leadNow, identity, other, identity), other);
}

} // namespace

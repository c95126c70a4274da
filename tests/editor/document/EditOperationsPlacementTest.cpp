// Where new things land, on the document File ▸ New opens: Add ▸ … puts a node on the
// floor at the view's focus and beside what is already there; the first mirror faces the view (or lies
// flat under a view from above) instead of lying edge-on; Duplicate moves the copy beside its original.
#include "editor/document/EditOperations.hpp"
#include "editor/document/NewScene.hpp"
#include "editor/document/NodeFactory.hpp"
#include "scene/evaluate/PickScene.hpp"
#include "scene/evaluate/Picking.hpp"
#include "scene/import/MeshLibrary.hpp"
#include "scene/model/NodeMath.hpp"
#include "scene/model/Scene.hpp"

#include <QUndoStack>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace speculum::document {
namespace {

class Placement : public ::testing::Test {
protected:
    void SetUp() override { scene.reset(newSceneData()); }

    // Adds what placeNewNode gives, seen from the new scene's camera unless told otherwise.
    scene::NodeId add(NewNodeKind kind, glm::dvec3 viewPosition = glm::dvec3(0.0),
                      glm::dvec3 focus = glm::dvec3(0.0)) {
        NewNodePlacement placement;
        placement.focus = focus == glm::dvec3(0.0) ? scene.camera().target : focus;
        placement.viewPosition = viewPosition == glm::dvec3(0.0) ? scene.camera().position : viewPosition;
        auto added = addNodeTree(scene, undo, placeNewNode(scene, meshes, kind, placement));
        EXPECT_TRUE(added) << added.error();
        return added ? *added : scene::kNoNode;
    }

    glm::dmat4 world(scene::NodeId id) { return scene::worldMatrices(scene, 0.0).at(id); }

    render::math::Box box(scene::NodeId id) {
        render::math::Box b;
        const scene::NodeData& d = scene.findNode(id)->data();
        std::vector<scene::Warning> ignored;
        if (d.mesh) {
            auto mesh = meshes.get(*d.mesh, ignored);
            EXPECT_TRUE(mesh && *mesh);
            b.add(render::math::worldBounds(scene::meshBounds(*mesh), world(id)));
        }
        if (d.mirror) {
            const glm::dvec2 h = d.mirror->size * 0.5;
            b.add(glm::dvec3(world(id) * glm::dvec4(-h.x, 0.0, -h.y, 1.0)));
            b.add(glm::dvec3(world(id) * glm::dvec4(h.x, 0.0, h.y, 1.0)));
        }
        return b;
    }

    static bool overlap(const render::math::Box& a, const render::math::Box& b) {
        for (int i = 0; i < 3; ++i) {
            if (!(a.min[i] < b.max[i] - 1e-9 && b.min[i] < a.max[i] - 1e-9)) {
                return false;
            }
        }
        return true;
    }

    glm::dvec3 mirrorNormal(scene::NodeId id) {
        return glm::normalize(glm::dvec3(world(id) * glm::dvec4(0.0, 1.0, 0.0, 0.0)));
    }

    scene::Scene scene;
    QUndoStack undo;
    scene::MeshLibrary meshes;
};

TEST_F(Placement, TheNewSceneIsAFloorASunAndARaisedCameraLookingDownAtIt) {
    const scene::SceneData data = scene.toData();
    ASSERT_EQ(data.nodes.size(), 2u);
    EXPECT_TRUE(data.nodes[0].data.mesh);
    ASSERT_TRUE(data.nodes[1].data.light);
    EXPECT_TRUE(data.nodes[1].data.light->shadows) << "the sun casts shadows";
    EXPECT_GT(data.camera.position.y, 1.0);
    const glm::dvec3 look = glm::normalize(data.camera.target - data.camera.position);
    EXPECT_LT(look.y, -0.1) << "looking down at the floor, not along it";
    const render::math::Box floor = box(scene.topLevelNodes()[0]->id());
    EXPECT_NEAR(floor.max.y, 0.0, 1e-12);
    EXPECT_NEAR(floor.max.x - floor.min.x, 10.0, 1e-9);
}

TEST_F(Placement, TheFirstMirrorStandsOnTheFloorFacingTheView) {
    const scene::NodeId mirror = add(NewNodeKind::Mirror);
    const glm::dvec3 centre(world(mirror)[3]);
    const glm::dvec3 toView = glm::normalize(scene.camera().position - centre);
    EXPECT_GT(glm::dot(mirrorNormal(mirror), toView), 0.5) << "facing the view";
    EXPECT_NEAR(glm::dot(mirrorNormal(mirror), glm::dvec3(0.0, 1.0, 0.0)), 0.0, 1e-9) << "standing upright";
    const render::math::Box b = box(mirror);
    EXPECT_GE(b.min.y, -1e-9) << "not through the floor";
    EXPECT_LT(b.min.y, 0.05) << "on it";
}

TEST_F(Placement, UnderAViewFromAboveAMirrorLiesFlatJustAboveTheFloor) {
    const glm::dvec3 focus(0.5, 0.0, 0.5);
    const scene::NodeId mirror = add(NewNodeKind::Mirror, focus + glm::dvec3(0.1, 6.0, 0.0), focus);
    EXPECT_GT(mirrorNormal(mirror).y, 0.999) << "facing up at the view";
    const render::math::Box b = box(mirror);
    EXPECT_GT(b.min.y, 0.0) << "a hair above the floor, so the two do not fight for depth";
    EXPECT_LE(b.min.y, 0.01 + 1e-12) << "a centimetre at most";
}

TEST_F(Placement, NewObjectsLandOnTheFloorBesideEachOther) {
    const scene::NodeId a = add(NewNodeKind::Teapot);
    const scene::NodeId b = add(NewNodeKind::Teapot);
    const scene::NodeId c = add(NewNodeKind::Box);
    EXPECT_NEAR(box(a).min.y, 0.0, 1e-9);
    EXPECT_NEAR(box(b).min.y, 0.0, 1e-9);
    EXPECT_NEAR(box(c).min.y, 0.0, 1e-9);
    EXPECT_FALSE(overlap(box(a), box(b)));
    EXPECT_FALSE(overlap(box(a), box(c)));
    EXPECT_FALSE(overlap(box(b), box(c)));
    const glm::dvec3 focus = scene.camera().target;
    EXPECT_NEAR(box(a).center().x, focus.x, 1e-9) << "the first one where the view looks";
    EXPECT_NEAR(box(a).center().z, focus.z, 1e-9);
}

TEST_F(Placement, ALightGoesAboveTheFocus) {
    const scene::NodeId light = add(NewNodeKind::PointLight);
    const glm::dvec3 at(world(light)[3]);
    EXPECT_NEAR(at.x, scene.camera().target.x, 1e-9);
    EXPECT_NEAR(at.z, scene.camera().target.z, 1e-9);
    EXPECT_GT(at.y, 1.0);
}

TEST_F(Placement, ADuplicateStepsAsideAlongXAndCopiesDoNotLandInEachOther) {
    const scene::NodeId teapot = add(NewNodeKind::Teapot);
    undo.clear();
    auto first = duplicateNodes(scene, undo, {teapot}, teapot, &meshes, 0.0);
    ASSERT_TRUE(first) << first.error();
    const scene::NodeId copy = first->copies.at(0);
    EXPECT_EQ(undo.count(), 1);
    EXPECT_FALSE(overlap(box(copy), box(teapot)));
    EXPECT_GT(box(copy).min.x, box(teapot).max.x) << "along +X";
    EXPECT_NEAR(box(copy).min.y, box(teapot).min.y, 1e-9);
    EXPECT_NEAR(box(copy).center().z, box(teapot).center().z, 1e-9);

    auto second = duplicateNodes(scene, undo, {teapot}, teapot, &meshes, 0.0);
    ASSERT_TRUE(second) << second.error();
    const scene::NodeId again = second->copies.at(0);
    EXPECT_FALSE(overlap(box(again), box(copy))) << "past the first copy, not onto it";
    EXPECT_FALSE(overlap(box(again), box(teapot)));

    undo.undo();
    undo.undo();
    EXPECT_EQ(scene.findNode(copy), nullptr);
    EXPECT_EQ(scene.findNode(again), nullptr);
}

} // namespace
} // namespace speculum::document

namespace speculum::document {
namespace {

// A new chrome sphere inside a scene gets the parallax proxy the bench's "parallax on" would give it (a box
// around everything else); one that nothing surrounds gets none.
TEST_F(Placement, ANewReflectorInsideTheSceneStartsWithParallaxOn) {
    // On the new scene's floor alone nothing stands above the sphere: no proxy.
    const scene::NodeId alone = add(NewNodeKind::ReflectorSphere);
    EXPECT_FALSE(scene.findNode(alone)->data().reflector->parallax);
    undo.undo();
    // A tall box at the floor's corner closes the space above it.
    scene::NodeTree tall = makeNode(NewNodeKind::Box, {4.0, 4.0, -4.0});
    tall.data.transform.scale = {0.5, 4.0, 0.5};
    auto tower = addNodeTree(scene, undo, tall);
    ASSERT_TRUE(tower) << tower.error();
    const scene::NodeId ball = add(NewNodeKind::ReflectorSphere);
    const auto& proxy = scene.findNode(ball)->data().reflector->parallax;
    ASSERT_TRUE(proxy);
    EXPECT_EQ(proxy->shape, render::ParallaxShape::Box);
    const render::math::Box own = box(ball);
    render::math::Box around = box(*tower);
    around.add(box(scene.topLevelNodes().front()->id())); // the floor
    EXPECT_LT(glm::length(own.center() + proxy->min - around.min), 1e-6);
    EXPECT_LT(glm::length(own.center() + proxy->max - around.max), 1e-6);
}

} // namespace
} // namespace speculum::document

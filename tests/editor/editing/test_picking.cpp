// Click-to-select on the CPU: the nearest surface wins, clicking a reflection selects the reflected object,
// mirrors seen from behind or at the depth limit select the mirror, and the editor's pick scene follows the
// document (node ids, parents' transforms, animations).
#include "editor/document/Commands.hpp"
#include "editor/document/NodeFactory.hpp"
#include "editor/document/PickScene.hpp"
#include "editor/document/Picking.hpp"
#include "editor/document/ProjectFile.hpp"
#include "render/mesh/Primitives.hpp"

#include <QUndoStack>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace {

using namespace speculum;
using namespace speculum::document;

render::MeshHandle sphere() {
    static const render::MeshHandle mesh = std::make_shared<render::MeshData>(render::makeSphere(24));
    return mesh;
}

glm::dmat4 at(const glm::dvec3& p, double scale = 1.0) {
    return glm::scale(glm::translate(glm::dmat4(1.0), p), glm::dvec3(scale));
}

TEST(Picking, NearestSurfaceWinsAndMissesAreEmpty) {
    PickScene scene;
    scene.meshes.push_back({1, sphere(), at({0, 0, -5})});
    scene.meshes.push_back({2, sphere(), at({0, 0, -10}, 3.0)});
    const auto hit = pick(scene, Ray{{0, 0, 0}, {0, 0, -1}});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->id, 1u);
    EXPECT_NEAR(hit->distance, 4.0, 0.01);
    EXPECT_EQ(hit->reflections, 0);

    const auto side = pick(scene, Ray{{2.0, 0, 0}, {0, 0, -1}}); // past the small sphere, into the big one
    ASSERT_TRUE(side);
    EXPECT_EQ(side->id, 2u);
    EXPECT_FALSE(pick(scene, Ray{{0, 0, 0}, {0, 0, 1}})) << "nothing behind the camera";
    EXPECT_FALSE(pick(scene, Ray{{0, 0, 0}, {0, 1, 0}}));
}

TEST(Picking, ClickingAReflectionSelectsTheReflectedObject) {
    // A floor mirror at y = -1 facing up; a sphere above it and in front of the camera, out of direct view.
    PickScene scene;
    scene.mirrors.push_back({10, at({0, -1, -5}), {10.0, 10.0}});
    scene.meshes.push_back({1, sphere(), at({0, 1, -8}, 0.5)});
    // Aim at the floor where the sphere's reflection is: the sphere's mirror image sits at y = -3.
    const glm::dvec3 image(0, -3, -8);
    const Ray ray{{0, 0, 0}, image};
    const auto direct = pick(PickScene{scene.meshes, {}, 3}, ray);
    EXPECT_FALSE(direct) << "without the mirror the ray goes below the sphere";
    const auto hit = pick(scene, ray);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->id, 1u) << "the reflected sphere, not the mirror";
    EXPECT_EQ(hit->reflections, 1);
    EXPECT_EQ(hit->firstMirror, 10u);
    EXPECT_NEAR(glm::length(hit->point - glm::dvec3(0, 1, -8)), 0.5, 0.01) << "a point on the sphere";
    EXPECT_LT(hit->point.y, 1.0) << "on its underside, the side the mirror sees";

    // Where the reflection shows nothing, the click selects the mirror itself.
    const auto empty = pick(scene, Ray{{0, 0, 0}, {3, -1, -5}});
    ASSERT_TRUE(empty);
    EXPECT_EQ(empty->id, 10u);

    // With no reflections allowed, the mirror.
    scene.mirrorDepth = 0;
    const auto flat = pick(scene, ray);
    ASSERT_TRUE(flat);
    EXPECT_EQ(flat->id, 10u);
}

TEST(Picking, MirrorSeenFromBehindIsOpaque) {
    PickScene scene;
    // The reflective side (+Y) turned to -Z: away from a camera at the origin looking down -Z.
    const glm::dmat4 facingAway = glm::rotate(at({0, 0, -5}), glm::radians(-90.0), glm::dvec3(1, 0, 0));
    scene.mirrors.push_back({10, facingAway, {4.0, 4.0}});
    scene.meshes.push_back({1, sphere(), at({0, 0, 3})}); // behind the camera: only a reflection shows it
    const auto hit = pick(scene, Ray{{0, 0, 0}, {0, 0, -1}});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->id, 10u);
    EXPECT_EQ(hit->reflections, 0);
    // Turned towards the camera, the same ray is reflected back to the sphere behind the camera.
    scene.mirrors.front().world = glm::rotate(at({0, 0, -5}), glm::radians(90.0), glm::dvec3(1, 0, 0));
    const auto back = pick(scene, Ray{{0, 0, 0}, {0, 0, -1}});
    ASSERT_TRUE(back);
    EXPECT_EQ(back->id, 1u);
}

TEST(Picking, TwoFacingMirrorsStopAtTheDepthLimit) {
    PickScene scene;
    // Two parallel mirrors facing each other along X; a ray bouncing between them forever.
    scene.mirrors.push_back(
        {10, glm::rotate(at({-2, 0, 0}), glm::radians(-90.0), glm::dvec3(0, 0, 1)), {4, 4}});
    scene.mirrors.push_back(
        {11, glm::rotate(at({2, 0, 0}), glm::radians(90.0), glm::dvec3(0, 0, 1)), {4, 4}});
    scene.mirrorDepth = 3;
    const auto hit = pick(scene, Ray{{0, 0, 0}, {1, 0, 0.01}});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->reflections, 3);
    EXPECT_TRUE(hit->id == 10u || hit->id == 11u);
}

TEST(Picking, CameraRayGoesThroughTheImageCorners) {
    render::Camera camera;
    camera.position = {0, 0, 0};
    camera.target = {0, 0, -1};
    camera.fovY = 90.0;
    const Ray centre = cameraRay(camera, 2.0, 0.0, 0.0);
    EXPECT_NEAR(glm::length(glm::normalize(centre.direction) - glm::dvec3(0, 0, -1)), 0.0, 1e-12);
    const Ray top = cameraRay(camera, 2.0, 0.0, 1.0);
    EXPECT_NEAR(glm::degrees(std::atan2(top.direction.y, -top.direction.z)), 45.0, 1e-9);
    const Ray right = cameraRay(camera, 2.0, 1.0, 0.0);
    EXPECT_NEAR(right.direction.x / -right.direction.z, 2.0, 1e-9);
}

TEST(PickScene, FollowsTheDocument) {
    Scene scene;
    QUndoStack stack;
    NodeTree parent = makeNode(NewNodeKind::Empty, {0, 0, -5});
    NodeTree child = makeNode(NewNodeKind::Sphere, {1, 0, 0});
    child.data.transform.scale = glm::dvec3(0.5);
    parent.children.push_back(child);
    auto* add = new AddNodeCommand(scene, parent);
    stack.push(add);
    auto* mirror = new AddNodeCommand(scene, makeNode(NewNodeKind::Mirror, {0, -2, -5}));
    stack.push(mirror);
    const NodeId sphereId = scene.findNode(add->nodeId())->child(0)->id();

    MeshLibrary meshes;
    const PickScene picks = buildPickScene(scene, 0.0, meshes);
    ASSERT_EQ(picks.meshes.size(), 1u);
    ASSERT_EQ(picks.mirrors.size(), 1u);
    EXPECT_EQ(picks.meshes.front().id, sphereId);
    EXPECT_EQ(picks.mirrors.front().id, mirror->nodeId());
    // The sphere's world centre is parent translate + child translate.
    const auto hit = pick(picks, Ray{{1, 0, 0}, {0, 0, -1}});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->id, sphereId);
    EXPECT_NEAR(hit->point.z, -4.5, 0.01);
    EXPECT_EQ(glm::dvec3(parentWorldMatrix(scene, sphereId, 0.0)[3]), glm::dvec3(0, 0, -5));
}

} // namespace

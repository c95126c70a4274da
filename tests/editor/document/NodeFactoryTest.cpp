// The Add menu's nodes: each kind has the component that makes it what its name says, names are made
// unique, and a second curved reflector is refused. Imports are placed on the ground beside what is there.
#include "editor/document/NodeFactory.hpp"

#include "editor/document/Commands.hpp"
#include "scene/project/ProjectFile.hpp"

#include <QDir>
#include <QUndoStack>
#include <gtest/gtest.h>

namespace {

using namespace speculum::document;
using namespace speculum::scene;

TEST(NodeFactory, EachKindHasItsComponentAndLoads) {
    speculum::scene::SceneData scene;
    const NewNodeKind kinds[] = {NewNodeKind::Empty,
                                 NewNodeKind::Teapot,
                                 NewNodeKind::Sphere,
                                 NewNodeKind::Box,
                                 NewNodeKind::Plane,
                                 NewNodeKind::Mirror,
                                 NewNodeKind::ReflectorSphere,
                                 NewNodeKind::PointLight,
                                 NewNodeKind::DirectionalLight,
                                 NewNodeKind::SpotLight};
    for (NewNodeKind kind : kinds) {
        speculum::scene::NodeTree t = makeNode(kind, {1.0, 2.0, 3.0});
        EXPECT_EQ(QString::fromStdString(t.data.name), displayName(kind));
        scene.nodes.push_back(t);
    }
    EXPECT_TRUE(scene.nodes[5].data.mirror);
    EXPECT_FALSE(scene.nodes[5].data.mesh) << "a mirror is its rectangle";
    EXPECT_TRUE(scene.nodes[6].data.reflector && scene.nodes[6].data.mesh);
    EXPECT_EQ(scene.nodes[6].data.mesh->builtin, speculum::scene::BuiltinMesh::Sphere);
    EXPECT_EQ(scene.nodes[9].data.light->type, speculum::scene::LightType::Spot);
    EXPECT_EQ(scene.nodes[1].data.transform.translate, glm::dvec3(1.0, 2.0, 3.0));
    EXPECT_GT(scene.nodes[7].data.transform.translate.y, 3.0) << "lights go above the point";

    std::vector<std::string> warnings;
    auto loaded = speculum::scene::parseProject(speculum::scene::serializeProject(scene, QDir::temp()),
                                                QDir::temp(), warnings);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_TRUE(*loaded == scene);
}

TEST(NodeFactory, NamesBecomeUniqueAndOneReflectorPerScene) {
    speculum::scene::Scene scene;
    QUndoStack stack;
    EXPECT_EQ(uniqueName(scene, "Mirror"), "Mirror");
    stack.push(new AddNodeCommand(scene, makeNode(NewNodeKind::Mirror)));
    EXPECT_EQ(uniqueName(scene, "Mirror"), "Mirror 2");
    speculum::scene::NodeTree second = makeNode(NewNodeKind::Mirror);
    second.data.name = uniqueName(scene, second.data.name);
    stack.push(new AddNodeCommand(scene, second));
    EXPECT_EQ(uniqueName(scene, "Mirror"), "Mirror 3");

    auto* sphere = new AddNodeCommand(scene, makeNode(NewNodeKind::ReflectorSphere));
    stack.push(sphere);
    // A second reflector is a reflector too: each has a map of its own.
    const speculum::scene::NodeTree copy = duplicateTree(scene, sphere->nodeId());
    EXPECT_TRUE(copy.data.reflector);
    EXPECT_EQ(copy.data.name, "Chrome sphere 2");
}

speculum::render::math::Box box(glm::dvec3 lo, glm::dvec3 hi) {
    speculum::render::math::Box b;
    b.add(lo);
    b.add(hi);
    return b;
}

TEST(NodeFactory, ImportsStandOnTheGroundAtTheFocusBesideWhatIsThere) {
    const auto model = box({-1, 2, -1}, {1, 4, 1}); // 2 × 2 × 2, floating 2 above the ground
    // Nothing there: bottom on y = 0, centred on the focus in x and z (the focus's height does not matter).
    EXPECT_EQ(placeOnGround(model, {5, 3, -2}, {}), glm::dvec3(5, -2, -2));
    // A floor (top at y = 0) and a floor mirror do not push it away.
    const auto floor = box({-10, -0.1, -10}, {10, 0, 10});
    const auto floorMirror = box({-3, 0, -3}, {3, 0, 3});
    EXPECT_EQ(placeOnGround(model, {0, 0, 0}, {floor, floorMirror}), glm::dvec3(0, -2, 0));
    // A teapot at the focus, and a crate right of it: the model goes past both along +X, with a gap.
    const auto teapot = box({-0.5, 0, -0.5}, {0.5, 1, 0.5});
    const auto crate = box({1.5, 0, -0.2}, {3.0, 0.5, 0.2});
    const glm::dvec3 at = placeOnGround(model, {0, 0, 0}, {floor, teapot, crate});
    EXPECT_GT(at.x - 1.0, 3.0) << "its left side is past the crate";
    EXPECT_LT(at.x - 1.0, 3.5) << "but not far past it";
    EXPECT_EQ(at.y, -2.0);
    EXPECT_EQ(at.z, 0.0);
    // Something beside the path (further back in z) or hanging high above does not count.
    const auto behind = box({-0.5, 0, 5}, {0.5, 1, 6});
    const auto lamp = box({-0.2, 3, -0.2}, {0.2, 3.5, 0.2});
    EXPECT_EQ(placeOnGround(model, {0, 0, 0}, {behind, lamp}), glm::dvec3(0, -2, 0));

    // A table top under the focus is the ground there (the teapot on it is in the way); one beside the
    // focus, or above it, is not.
    const auto table = box({-2, 0.65, -1}, {2, 0.7, 1});
    const auto onTable = box({-0.3, 0.7, -0.3}, {0.3, 1.0, 0.3});
    const glm::dvec3 up = placeOnGround(model, {0, 0.9, 0}, {floor, table, onTable});
    EXPECT_DOUBLE_EQ(up.y, 0.7 - 2.0) << "its bottom on the table top";
    EXPECT_GT(up.x - 1.0, 0.3) << "beside the teapot on the table";
    EXPECT_EQ(placeOnGround(model, {5, 0.9, 0}, {floor, table}).y, -2.0) << "not under the focus";
    EXPECT_EQ(placeOnGround(model, {0, 0.3, 0}, {floor, table}).y, -2.0) << "above the focus";
}

TEST(NodeFactory, OccupiedBoxesCoverMeshesAndMirrorsInWorldSpace) {
    speculum::scene::Scene scene;
    QUndoStack stack;
    speculum::scene::NodeTree parent = makeNode(NewNodeKind::Empty, {2, 0, 0});
    parent.children.push_back(makeNode(NewNodeKind::Box, {0, 0.5, 0}));
    stack.push(new AddNodeCommand(scene, parent));
    stack.push(new AddNodeCommand(scene, makeNode(NewNodeKind::Mirror, {-3, 1, 0})));
    stack.push(new AddNodeCommand(scene, makeNode(NewNodeKind::PointLight, {0, 3, 0})));
    speculum::scene::MeshLibrary meshes;
    const auto boxes = occupiedBoxes(scene, 0.0, meshes);
    ASSERT_EQ(boxes.size(), 2u) << "the box and the mirror; a light takes no room";
    const auto b = boxes[0];
    EXPECT_NEAR(b.center().x, 2.0, 1e-6) << "the parent's translation counts";
    EXPECT_NEAR(b.center().y, 0.5, 1e-6);
    EXPECT_NEAR(boxes[1].center().x, -3.0, 1e-6);
    EXPECT_NEAR(boxes[1].max.y, 1.0, 1e-6);

    speculum::scene::NodeData node;
    node.transform.translate = {1, 2, 3};
    node.transform.scale = {2, 2, 4};
    scaleAboutParentOrigin(node, 0.5);
    EXPECT_EQ(node.transform.translate, glm::dvec3(0.5, 1, 1.5));
    EXPECT_EQ(node.transform.scale, glm::dvec3(1, 1, 2));
}

} // namespace

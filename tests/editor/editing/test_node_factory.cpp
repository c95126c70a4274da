// The Add menu's nodes: each kind has the component that makes it what its name says, names are made
// unique, and a second curved reflector is refused.
#include "editor/document/Commands.hpp"
#include "editor/document/NodeFactory.hpp"
#include "editor/document/ProjectFile.hpp"

#include <QDir>
#include <QUndoStack>
#include <gtest/gtest.h>

namespace {

using namespace speculum::document;

TEST(NodeFactory, EachKindHasItsComponentAndLoads) {
    SceneData scene;
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
        NodeTree t = makeNode(kind, {1.0, 2.0, 3.0});
        EXPECT_EQ(QString::fromStdString(t.data.name), displayName(kind));
        scene.nodes.push_back(t);
    }
    EXPECT_TRUE(scene.nodes[5].data.mirror);
    EXPECT_FALSE(scene.nodes[5].data.mesh) << "a mirror is its rectangle";
    EXPECT_TRUE(scene.nodes[6].data.reflector && scene.nodes[6].data.mesh);
    EXPECT_EQ(scene.nodes[6].data.mesh->builtin, BuiltinMesh::Sphere);
    EXPECT_EQ(scene.nodes[9].data.light->type, LightType::Spot);
    EXPECT_EQ(scene.nodes[1].data.transform.translate, glm::dvec3(1.0, 2.0, 3.0));
    EXPECT_GT(scene.nodes[7].data.transform.translate.y, 3.0) << "lights go above the point";

    std::vector<std::string> warnings;
    auto loaded = parseProject(serializeProject(scene, QDir::temp()), QDir::temp(), warnings);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_TRUE(*loaded == scene);
}

TEST(NodeFactory, NamesBecomeUniqueAndOneReflectorPerScene) {
    Scene scene;
    QUndoStack stack;
    EXPECT_EQ(uniqueName(scene, "Mirror"), "Mirror");
    stack.push(new AddNodeCommand(scene, makeNode(NewNodeKind::Mirror)));
    EXPECT_EQ(uniqueName(scene, "Mirror"), "Mirror 2");
    NodeTree second = makeNode(NewNodeKind::Mirror);
    second.data.name = uniqueName(scene, second.data.name);
    stack.push(new AddNodeCommand(scene, second));
    EXPECT_EQ(uniqueName(scene, "Mirror"), "Mirror 3");

    EXPECT_TRUE(canAdd(scene, makeNode(NewNodeKind::ReflectorSphere)).ok());
    stack.push(new AddNodeCommand(scene, makeNode(NewNodeKind::ReflectorSphere)));
    const auto refused = canAdd(scene, makeNode(NewNodeKind::ReflectorTeapot));
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().find("Chrome sphere"), std::string::npos) << refused.error();
    EXPECT_TRUE(canAdd(scene, makeNode(NewNodeKind::Teapot)).ok());

    bool dropped = false;
    const NodeTree copy = duplicateTree(scene, reflectorNode(scene), &dropped);
    EXPECT_TRUE(dropped);
    EXPECT_FALSE(copy.data.reflector);
    EXPECT_EQ(copy.data.name, "Chrome sphere 2");
    EXPECT_TRUE(canAdd(scene, copy).ok());
}

} // namespace

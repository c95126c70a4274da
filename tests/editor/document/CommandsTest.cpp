#include "editor/document/Commands.hpp"

#include "ThreeNodeScene.hpp"

#include <QUndoStack>
#include <gtest/gtest.h>

namespace speculum::document {
namespace {

using test::named;

// Scene: A, B (with children B1, B2), C.
class CommandsTest : public ::testing::Test {
protected:
    void SetUp() override {
        scene.reset(test::threeNodeScene());
        original = scene.toData();
        QObject::connect(&scene, &scene::Scene::changed, [this] { ++changes; });
    }

    scene::NodeId idOf(const std::string& name) const { return test::nodeIdByName(scene, name); }

    std::vector<std::string> topLevelNames() const {
        std::vector<std::string> names;
        for (const auto& node : scene.topLevelNodes()) {
            names.push_back(node->name());
        }
        return names;
    }

    scene::Scene scene;
    QUndoStack stack;
    scene::SceneData original;
    int changes = 0;
};

TEST_F(CommandsTest, SetNodeDataUndoesAndRedoes) {
    const scene::NodeId a = idOf("A");
    scene::NodeData data = scene.findNode(a)->data();
    data.transform.translate = {1, 2, 3};
    data.material = scene::MaterialComponent{};
    scene::NodeId signalled = scene::kNoNode;
    QObject::connect(&scene, &scene::Scene::nodeChanged, [&](scene::NodeId id) { signalled = id; });
    stack.push(new SetNodeDataCommand(scene, a, data));
    EXPECT_EQ(signalled, a);
    EXPECT_EQ(scene.findNode(a)->data(), data);
    stack.undo();
    EXPECT_EQ(scene.toData(), original);
    stack.redo();
    EXPECT_EQ(scene.findNode(a)->data(), data);
    EXPECT_GT(changes, 0);
}

TEST_F(CommandsTest, ASliderDragIsOneUndoStep) {
    const scene::NodeId a = idOf("A");
    for (int i = 1; i <= 10; ++i) {
        scene::NodeData data = scene.findNode(a)->data();
        data.transform.rotate.y = i * 10.0;
        stack.push(new SetNodeDataCommand(scene, a, data, "Rotate", "transform.rotate#1"));
    }
    EXPECT_EQ(stack.count(), 1);
    EXPECT_EQ(scene.findNode(a)->data().transform.rotate.y, 100.0);
    stack.undo();
    EXPECT_EQ(scene.toData(), original);
    stack.redo();
    EXPECT_EQ(scene.findNode(a)->data().transform.rotate.y, 100.0);

    // Another key, another node, or no key: separate steps.
    scene::NodeData data = scene.findNode(a)->data();
    data.transform.scale.x = 2;
    stack.push(new SetNodeDataCommand(scene, a, data, "Scale", "transform.scale#2"));
    scene::NodeData c = scene.findNode(idOf("C"))->data();
    c.transform.scale.x = 3;
    stack.push(new SetNodeDataCommand(scene, idOf("C"), c, "Scale", "transform.scale#2"));
    // Without a key each edit is a step of its own (an edit that changes nothing is none: exact undo).
    c.transform.scale.x = 4;
    stack.push(new SetNodeDataCommand(scene, idOf("C"), c));
    c.transform.scale.x = 5;
    stack.push(new SetNodeDataCommand(scene, idOf("C"), c));
    stack.push(new SetNodeDataCommand(scene, idOf("C"), c));
    EXPECT_EQ(stack.count(), 5);
    while (stack.canUndo()) {
        stack.undo();
    }
    EXPECT_EQ(scene.toData(), original);
}

TEST_F(CommandsTest, SetNodesDataChangesSeveralNodesAsOneStep) {
    const scene::NodeId a = idOf("A"), b1 = idOf("B1"), c = idOf("C");
    auto moved = [&](scene::NodeId id, double x) {
        scene::NodeData data = scene.findNode(id)->data();
        data.transform.translate.x = x;
        return SetNodesDataCommand::Change{id, data};
    };
    stack.push(new SetNodesDataCommand(scene, {moved(a, 1), moved(b1, 2), moved(c, 3)}, "Move 3 nodes"));
    EXPECT_EQ(stack.count(), 1);
    EXPECT_EQ(stack.undoText().toStdString(), "Move 3 nodes");
    EXPECT_EQ(scene.findNode(a)->data().transform.translate.x, 1.0);
    EXPECT_EQ(scene.findNode(b1)->data().transform.translate.x, 2.0);
    EXPECT_EQ(scene.findNode(c)->data().transform.translate.x, 3.0);
    const scene::SceneData after = scene.toData();
    stack.undo();
    EXPECT_EQ(scene.toData(), original) << "undo restores every node";
    stack.redo();
    EXPECT_EQ(scene.toData(), after) << "redo applies every node again";

    // Without a text it names what it edits.
    stack.push(new SetNodesDataCommand(scene, {moved(a, 4)}));
    EXPECT_EQ(stack.undoText().toStdString(), "Edit \u201cA\u201d");
    stack.push(new SetNodesDataCommand(scene, {moved(a, 5), moved(c, 6)}));
    EXPECT_EQ(stack.undoText().toStdString(), "Edit 2 nodes");
    EXPECT_EQ(stack.count(), 3) << "no merge key: no merging";
}

TEST_F(CommandsTest, AHandleDragOverSeveralNodesIsOneUndoStep) {
    const scene::NodeId a = idOf("A"), c = idOf("C");
    auto turned = [&](scene::NodeId id, double degrees) {
        scene::NodeData data = scene.findNode(id)->data();
        data.transform.rotate.z = degrees;
        return SetNodesDataCommand::Change{id, data};
    };
    for (int i = 1; i <= 10; ++i) {
        stack.push(new SetNodesDataCommand(scene, {turned(a, i * 10.0), turned(c, i * 20.0)},
                                           "Rotate 2 nodes", "handle#1"));
    }
    EXPECT_EQ(stack.count(), 1);
    EXPECT_EQ(stack.undoText().toStdString(), "Rotate 2 nodes");
    EXPECT_EQ(scene.findNode(a)->data().transform.rotate.z, 100.0);
    EXPECT_EQ(scene.findNode(c)->data().transform.rotate.z, 200.0);
    stack.undo();
    EXPECT_EQ(scene.toData(), original) << "one undo takes the whole drag back";
    stack.redo();
    EXPECT_EQ(scene.findNode(a)->data().transform.rotate.z, 100.0);
    EXPECT_EQ(scene.findNode(c)->data().transform.rotate.z, 200.0);

    // Another drag (key), other nodes, the same nodes in another order, or a single-node command: separate
    // steps.
    stack.push(new SetNodesDataCommand(scene, {turned(a, 1), turned(c, 2)}, "Rotate 2 nodes", "handle#2"));
    stack.push(new SetNodesDataCommand(scene, {turned(a, 3)}, "Rotate", "handle#2"));
    stack.push(new SetNodesDataCommand(scene, {turned(c, 4), turned(a, 5)}, "Rotate", "handle#2"));
    stack.push(new SetNodeDataCommand(scene, a, turned(a, 6).data, "Rotate", "handle#2"));
    EXPECT_EQ(stack.count(), 5);
    while (stack.canUndo()) {
        stack.undo();
    }
    EXPECT_EQ(scene.toData(), original);
}

TEST_F(CommandsTest, RenameUndoesAndRedoes) {
    const scene::NodeId b = idOf("B");
    stack.push(new RenameNodeCommand(scene, b, "Bee"));
    EXPECT_EQ(scene.findNode(b)->name(), "Bee");
    EXPECT_NE(stack.text(0).indexOf("Bee"), -1);
    stack.undo();
    EXPECT_EQ(scene.findNode(b)->name(), "B");
    EXPECT_EQ(scene.toData(), original);
    stack.redo();
    EXPECT_EQ(scene.findNode(b)->name(), "Bee");
}

TEST_F(CommandsTest, AddKeepsItsIdOverUndoRedo) {
    const scene::NodeId b = idOf("B");
    std::vector<std::tuple<scene::NodeId, scene::NodeId, int>> added;
    QObject::connect(
        &scene, &scene::Scene::nodeAdded,
        [&](scene::NodeId id, scene::NodeId parent, int index) { added.emplace_back(id, parent, index); });
    auto* command = new AddNodeCommand(scene, named("New", {named("New child")}), b, 1);
    stack.push(command);
    const scene::NodeId id = command->nodeId();
    ASSERT_NE(id, scene::kNoNode);
    ASSERT_EQ(scene.findNode(b)->childCount(), 3);
    EXPECT_EQ(scene.findNode(b)->child(1)->id(), id);
    EXPECT_EQ(scene.findNode(id)->child(0)->name(), "New child");
    ASSERT_EQ(added.size(), 1u);
    EXPECT_EQ(added[0], std::make_tuple(id, b, 1));
    const scene::NodeId childId = scene.findNode(id)->child(0)->id();

    stack.undo();
    EXPECT_EQ(scene.findNode(id), nullptr);
    EXPECT_EQ(scene.findNode(childId), nullptr);
    EXPECT_EQ(scene.toData(), original);
    stack.redo();
    EXPECT_EQ(scene.findNode(b)->child(1)->id(), id);
    EXPECT_EQ(scene.findNode(childId)->parent()->id(), id);

    // Appending at the top level.
    auto* top = new AddNodeCommand(scene, named("Last"));
    stack.push(top);
    EXPECT_EQ(topLevelNames(), (std::vector<std::string>{"A", "B", "C", "Last"}));
}

TEST_F(CommandsTest, RemoveRestoresTheSameNodesAtTheSamePlace) {
    const scene::NodeId b = idOf("B");
    const scene::NodeId b2 = idOf("B2");
    int aboutToRemove = 0;
    auto connection = QObject::connect(
        &scene, &scene::Scene::nodeAboutToBeRemoved, [&](scene::NodeId id, scene::NodeId parent, int index) {
            ++aboutToRemove;
            EXPECT_EQ(id, b);
            EXPECT_EQ(parent, scene::kNoNode);
            EXPECT_EQ(index, 1);
            EXPECT_NE(scene.findNode(id), nullptr) << "still there when views are told it is about to go";
        });
    stack.push(new RemoveNodeCommand(scene, b));
    QObject::disconnect(connection);
    EXPECT_EQ(aboutToRemove, 1);
    EXPECT_EQ(topLevelNames(), (std::vector<std::string>{"A", "C"}));
    EXPECT_EQ(scene.findNode(b2), nullptr);
    stack.undo();
    EXPECT_EQ(scene.toData(), original);
    EXPECT_EQ(scene.indexOf(b), 1);
    EXPECT_EQ(scene.findNode(b2)->parent()->id(), b);

    // A later command that refers to a removed-then-restored child still works.
    stack.push(new RemoveNodeCommand(scene, b2));
    stack.push(new RemoveNodeCommand(scene, b));
    stack.undo();
    stack.undo();
    EXPECT_EQ(scene.toData(), original);
    stack.redo();
    stack.redo();
    EXPECT_EQ(topLevelNames(), (std::vector<std::string>{"A", "C"}));
    stack.undo();
    EXPECT_EQ(scene.findNode(b)->childCount(), 1);
    EXPECT_EQ(scene.findNode(b)->child(0)->name(), "B1");
}

TEST_F(CommandsTest, MoveReparentsAndUndoes) {
    const scene::NodeId c = idOf("C");
    const scene::NodeId b = idOf("B");
    stack.push(new MoveNodeCommand(scene, c, b, 0));
    EXPECT_EQ(scene.parentOf(c), b);
    EXPECT_EQ(scene.indexOf(c), 0);
    EXPECT_EQ(topLevelNames(), (std::vector<std::string>{"A", "B"}));
    EXPECT_TRUE(scene.isAncestor(b, c));
    stack.undo();
    EXPECT_EQ(scene.toData(), original);
    EXPECT_EQ(scene.parentOf(c), scene::kNoNode);
    stack.redo();
    EXPECT_EQ(scene.findNode(b)->child(0)->id(), c);
}

TEST_F(CommandsTest, SettingsAndCameraUndoAndMerge) {
    int settingsSignals = 0;
    int cameraSignals = 0;
    QObject::connect(&scene, &scene::Scene::settingsChanged, [&] { ++settingsSignals; });
    QObject::connect(&scene, &scene::Scene::cameraChanged, [&] { ++cameraSignals; });

    scene::SceneSettings settings = scene.settings();
    for (double ambient : {0.3, 0.4, 0.5}) {
        settings.ambient = ambient;
        stack.push(new SetSettingsCommand(scene, settings, true));
    }
    EXPECT_EQ(stack.count(), 1);
    EXPECT_EQ(scene.settings().ambient, 0.5);
    settings.mirrorDepth = 7;
    stack.push(new SetSettingsCommand(scene, settings));
    EXPECT_EQ(stack.count(), 2);

    scene::CameraData camera = scene.camera();
    for (double x : {1.0, 2.0}) {
        camera.position.x = x;
        stack.push(new SetCameraCommand(scene, camera, true));
    }
    EXPECT_EQ(stack.count(), 3);
    EXPECT_EQ(scene.camera().position.x, 2.0);
    camera.fovY = 30;
    stack.push(new SetCameraCommand(scene, camera));
    EXPECT_EQ(stack.count(), 4);
    EXPECT_GE(settingsSignals, 4);
    EXPECT_GE(cameraSignals, 3);

    stack.undo();
    EXPECT_EQ(scene.camera().fovY, 65.0);
    stack.undo();
    EXPECT_EQ(scene.camera(), original.camera);
    stack.undo();
    EXPECT_EQ(scene.settings().mirrorDepth, original.settings.mirrorDepth);
    EXPECT_EQ(scene.settings().ambient, 0.5);
    stack.undo();
    EXPECT_EQ(scene.toData(), original);
    while (stack.canRedo()) {
        stack.redo();
    }
    EXPECT_EQ(scene.settings().mirrorDepth, 7);
    EXPECT_EQ(scene.camera().fovY, 30.0);
}

TEST_F(CommandsTest, ResetGivesFreshIdsAndSignals) {
    std::vector<scene::NodeId> before;
    scene.forEachNode([&](const scene::Node& node) { before.push_back(node.id()); });
    int resets = 0;
    QObject::connect(&scene, &scene::Scene::sceneReset, [&] { ++resets; });
    scene.reset(original);
    EXPECT_EQ(resets, 1);
    EXPECT_EQ(scene.toData(), original);
    for (scene::NodeId id : before) {
        EXPECT_EQ(scene.findNode(id), nullptr) << "ids are never reused";
    }
}

} // namespace
} // namespace speculum::document

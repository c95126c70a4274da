// Exact undo: a command whose net effect is nothing is never left on the undo stack. For every command
// kind, a push that changes nothing keeps the stack (count, index, redo steps, clean state) as it was; a
// merge chain that comes back to where it started leaves no step; a real edit still undoes and redoes.
#include "ThreeNodeScene.hpp"
#include "UndoStackState.hpp"
#include "editor/document/Commands.hpp"
#include "editor/document/EditTransaction.hpp"

#include <QSignalSpy>
#include <QUndoStack>
#include <functional>
#include <gtest/gtest.h>

namespace speculum::document {
namespace {

using test::named;

class ExactUndo : public ::testing::Test {
protected:
    void SetUp() override { scene.reset(test::threeNodeScene()); }

    scene::NodeId idOf(const std::string& name) const { return test::nodeIdByName(scene, name); }

    scene::NodeData dataOf(const std::string& name) const { return scene.findNode(idOf(name))->data(); }

    // Two real steps, saved after the second, then one undone: the stack has a redo step and its clean
    // state lies in it, the case QUndoStack::push would lose.
    void makeHistory() {
        scene::NodeData c = dataOf("C");
        c.transform.translate.x = 5.0;
        stack.push(new SetNodeDataCommand(scene, idOf("C"), c));
        c.transform.translate.y = 6.0;
        stack.push(new SetNodeDataCommand(scene, idOf("C"), c));
        stack.setClean();
        stack.undo();
        ASSERT_EQ(stack.count(), 2);
        ASSERT_EQ(stack.index(), 1);
        ASSERT_EQ(stack.cleanIndex(), 2);
    }

    using StackState = test::UndoStackState;
    StackState state() const { return test::undoStackState(stack); }

    scene::Scene scene;
    QUndoStack stack;
};

// One factory per command kind, each making a command that changes nothing in the scene as it is.
struct NoOpCase {
    const char* name;
    std::function<QUndoCommand*(scene::Scene&, const std::function<scene::NodeId(const std::string&)>&)> make;
};

std::vector<NoOpCase> noOpCases() {
    return {
        {"set node data to its own value",
         [](scene::Scene& s, const auto& id) {
             return new SetNodeDataCommand(s, id("A"), s.findNode(id("A"))->data(), {}, QStringLiteral("k"));
         }},
        {"set several nodes' data to their own values",
         [](scene::Scene& s, const auto& id) {
             return new SetNodesDataCommand(
                 s, {{id("A"), s.findNode(id("A"))->data()}, {id("B1"), s.findNode(id("B1"))->data()}});
         }},
        {"rename to the same name",
         [](scene::Scene& s, const auto& id) { return new RenameNodeCommand(s, id("B"), "B"); }},
        {"move to the same place",
         [](scene::Scene& s, const auto& id) { return new MoveNodeCommand(s, id("B2"), id("B"), 1); }},
        {"move to the end where it is",
         [](scene::Scene& s, const auto& id) { return new MoveNodeCommand(s, id("C"), scene::kNoNode, -1); }},
        {"move past the end where it is",
         [](scene::Scene& s, const auto& id) { return new MoveNodeCommand(s, id("B2"), id("B"), 99); }},
        {"settings to their own value",
         [](scene::Scene& s, const auto&) { return new SetSettingsCommand(s, s.settings(), true); }},
        {"camera to its own value",
         [](scene::Scene& s, const auto&) { return new SetCameraCommand(s, s.camera(), true); }},
    };
}

TEST_F(ExactUndo, ANoOpCommandOfEveryKindIsObsoleteFromTheStart) {
    for (const NoOpCase& c : noOpCases()) {
        std::unique_ptr<QUndoCommand> command(
            c.make(scene, [this](const std::string& n) { return idOf(n); }));
        EXPECT_TRUE(command->isObsolete()) << c.name;
    }
}

TEST_F(ExactUndo, ANoOpPushKeepsTheRedoStepsAndTheCleanState) {
    makeHistory();
    const StackState before = state();
    const scene::SceneData sceneBefore = scene.toData();
    for (const NoOpCase& c : noOpCases()) {
        QSignalSpy cleanChanged(&stack, &QUndoStack::cleanChanged);
        QSignalSpy indexChanged(&stack, &QUndoStack::indexChanged);
        EXPECT_FALSE(pushEdit(stack, c.make(scene, [this](const std::string& n) { return idOf(n); })))
            << c.name;
        EXPECT_EQ(state(), before) << c.name;
        EXPECT_TRUE(stack.canRedo()) << c.name << ": the redo step is kept";
        EXPECT_EQ(cleanChanged.count(), 0) << c.name;
        EXPECT_EQ(indexChanged.count(), 0) << c.name;
        EXPECT_EQ(scene.toData(), sceneBefore) << c.name;
    }
    stack.redo();
    EXPECT_TRUE(stack.isClean()) << "the saved state is still reachable";
}

TEST_F(ExactUndo, ANoOpPushedStraightOnACleanStackLeavesItClean) {
    // Even a caller that bypasses pushEdit() gets no step: QUndoStack drops obsolete commands.
    scene::NodeData a = dataOf("A");
    a.transform.translate.z = 1.0;
    stack.push(new SetNodeDataCommand(scene, idOf("A"), a));
    stack.setClean();
    for (const NoOpCase& c : noOpCases()) {
        stack.push(c.make(scene, [this](const std::string& n) { return idOf(n); }));
        EXPECT_EQ(stack.count(), 1) << c.name;
        EXPECT_TRUE(stack.isClean()) << c.name;
    }
}

TEST_F(ExactUndo, ANoOpInATransactionLeavesNoStep) {
    makeHistory();
    const StackState before = state();
    {
        EditTransaction edit(stack, QStringLiteral("Nothing"));
        for (const NoOpCase& c : noOpCases()) {
            edit.push(c.make(scene, [this](const std::string& n) { return idOf(n); }));
        }
        EXPECT_TRUE(edit.empty());
        edit.commit();
    }
    EXPECT_EQ(state(), before);
}

// Mergeable commands: from the start value through others and back, as a drag or a slider does.
struct MergeCase {
    const char* name;
    // Pushes the edit that sets the scene to step k (0 = the start value) under one merge key.
    std::function<void(scene::Scene&, QUndoStack&, scene::NodeId a, scene::NodeId b, int step)> push;
};

std::vector<MergeCase> mergeCases() {
    auto translated = [](const scene::NodeData& start, int step) {
        scene::NodeData d = start;
        d.transform.translate.x += 0.25 * step;
        return d;
    };
    return {
        {"node data (slider)",
         [translated](scene::Scene& s, QUndoStack& u, scene::NodeId a, scene::NodeId, int step) {
             static scene::NodeData start;
             if (step == 1) {
                 start = s.findNode(a)->data();
             }
             pushEdit(u,
                      new SetNodeDataCommand(s, a, translated(start, step), {}, QStringLiteral("slider#1")));
         }},
        {"several nodes (handle drag)",
         [translated](scene::Scene& s, QUndoStack& u, scene::NodeId a, scene::NodeId b, int step) {
             static scene::NodeData startA, startB;
             if (step == 1) {
                 startA = s.findNode(a)->data();
                 startB = s.findNode(b)->data();
             }
             pushEdit(
                 u, new SetNodesDataCommand(s, {{a, translated(startA, step)}, {b, translated(startB, step)}},
                                            {}, QStringLiteral("handle#1")));
         }},
        {"settings",
         [](scene::Scene& s, QUndoStack& u, scene::NodeId, scene::NodeId, int step) {
             static scene::SceneSettings start;
             if (step == 1) {
                 start = s.settings();
             }
             scene::SceneSettings v = start;
             v.ambient = start.ambient + 0.125 * step;
             auto* command = new SetSettingsCommand(s, v, true);
             command->setMergeKey(QStringLiteral("settings.ambient#1"));
             pushEdit(u, command);
         }},
        {"camera",
         [](scene::Scene& s, QUndoStack& u, scene::NodeId, scene::NodeId, int step) {
             static scene::CameraData start;
             if (step == 1) {
                 start = s.camera();
             }
             scene::CameraData v = start;
             v.position.x = start.position.x + 0.5 * step;
             auto* command = new SetCameraCommand(s, v, true);
             command->setMergeKey(QStringLiteral("navigate#1"));
             pushEdit(u, command);
         }},
    };
}

TEST_F(ExactUndo, AMergeChainBackToTheStartDisappears) {
    for (const MergeCase& c : mergeCases()) {
        stack.clear();
        // A saved step first, so the chain starts above the clean state.
        scene::NodeData b = dataOf("B");
        b.transform.rotate.y += 10.0;
        stack.push(new SetNodeDataCommand(scene, idOf("B"), b));
        stack.setClean();
        const scene::SceneData start = scene.toData();
        QSignalSpy cleanChanged(&stack, &QUndoStack::cleanChanged);

        for (int step : {1, 2, 3, 2}) {
            c.push(scene, stack, idOf("A"), idOf("C"), step);
        }
        EXPECT_EQ(stack.count(), 2) << c.name << ": the chain is one step";
        EXPECT_FALSE(stack.isClean()) << c.name;
        c.push(scene, stack, idOf("A"), idOf("C"), 0); // back where it began (Esc, or dragged back)
        EXPECT_EQ(scene.toData(), start) << c.name;
        EXPECT_EQ(stack.count(), 1) << c.name << ": no step left";
        EXPECT_EQ(stack.index(), 1) << c.name;
        EXPECT_TRUE(stack.isClean()) << c.name << ": the document is not modified";
        EXPECT_EQ(cleanChanged.count(), 2) << c.name << ": modified, then clean again";
        EXPECT_EQ(stack.undoText(), stack.command(0)->text()) << c.name;
    }
}

TEST_F(ExactUndo, AMergeChainEndingElsewhereIsOneStepThatUndoesAndRedoes) {
    for (const MergeCase& c : mergeCases()) {
        stack.clear();
        const scene::SceneData start = scene.toData();
        for (int step : {1, 2, 0, 3}) { // passing the start on the way does not end the step
            c.push(scene, stack, idOf("A"), idOf("C"), step);
        }
        const scene::SceneData end = scene.toData();
        ASSERT_NE(end, start) << c.name;
        EXPECT_EQ(stack.count(), 1) << c.name;
        stack.undo();
        EXPECT_EQ(scene.toData(), start) << c.name;
        EXPECT_TRUE(stack.isClean()) << c.name;
        stack.redo();
        EXPECT_EQ(scene.toData(), end) << c.name;
        stack.undo();
    }
}

TEST_F(ExactUndo, RealEditsOfEveryKindStillUndoAndRedo) {
    const scene::SceneData start = scene.toData();
    scene::NodeData a = dataOf("A");
    a.material = scene::MaterialComponent{};
    EXPECT_TRUE(pushEdit(stack, new SetNodeDataCommand(scene, idOf("A"), a)));
    scene::NodeData b1 = dataOf("B1");
    b1.transform.scale = {2, 2, 2};
    EXPECT_TRUE(pushEdit(stack, new SetNodesDataCommand(scene, {{idOf("B1"), b1}})));
    EXPECT_TRUE(pushEdit(stack, new RenameNodeCommand(scene, idOf("C"), "D")));
    EXPECT_TRUE(pushEdit(stack, new MoveNodeCommand(scene, idOf("B2"), idOf("B"), 0)));
    EXPECT_TRUE(pushEdit(stack, new MoveNodeCommand(scene, idOf("A"), scene::kNoNode, -1)));
    scene::SceneSettings settings = scene.settings();
    settings.mirrorDepth += 1;
    EXPECT_TRUE(pushEdit(stack, new SetSettingsCommand(scene, settings)));
    scene::CameraData camera = scene.camera();
    camera.fovY += 5.0;
    EXPECT_TRUE(pushEdit(stack, new SetCameraCommand(scene, camera)));
    EXPECT_TRUE(pushEdit(stack, new AddNodeCommand(scene, named("E"))));
    EXPECT_TRUE(pushEdit(stack, new RemoveNodeCommand(scene, idOf("B1"))));
    EXPECT_EQ(stack.count(), 9);
    const scene::SceneData end = scene.toData();
    ASSERT_NE(end, start);
    while (stack.canUndo()) {
        stack.undo();
    }
    EXPECT_EQ(scene.toData(), start);
    while (stack.canRedo()) {
        stack.redo();
    }
    EXPECT_EQ(scene.toData(), end);
    EXPECT_EQ(stack.count(), 9);
}

} // namespace
} // namespace speculum::document

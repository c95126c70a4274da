// Exact undo for a sweep's settings, applied the way the Accuracy panel does (AccuracyPanel::applyRecord:
// applySweepSettings, then pushEdit when there is a command): a record the document already has leaves the
// stack exactly as it was (no step, the redo steps and the clean state kept), and a real one is one step.
#include "ThreeNodeScene.hpp"
#include "UndoStackState.hpp"
#include "editor/document/Commands.hpp"
#include "editor/document/SweepResults.hpp"

#include <QSignalSpy>
#include <QUndoStack>
#include <gtest/gtest.h>
#include <string>

namespace speculum::document {
namespace {

class SweepUndo : public ::testing::Test {
protected:
    void SetUp() override { scene.reset(test::threeNodeScene()); }

    // Two real steps, saved after the second, then one undone: a redo step holding the clean state.
    void makeHistory() {
        const scene::NodeId id = test::nodeIdByName(scene, "C");
        scene::NodeData c = scene.findNode(id)->data();
        c.transform.translate.x = 5.0;
        ASSERT_TRUE(pushEdit(stack, new SetNodeDataCommand(scene, id, c)));
        c.transform.translate.y = 6.0;
        ASSERT_TRUE(pushEdit(stack, new SetNodeDataCommand(scene, id, c)));
        stack.setClean();
        stack.undo();
        ASSERT_EQ(stack.index(), 1);
        ASSERT_EQ(stack.cleanIndex(), 2);
    }

    // What the panel does with a record; whether it left a step.
    bool apply(const accuracy::Settings& settings) {
        SweepApplication application = applySweepSettings(scene, settings, QStringLiteral("Apply"));
        return application.command && pushEdit(stack, application.command.release());
    }

    using StackState = test::UndoStackState;
    StackState state() const { return test::undoStackState(stack); }

    scene::Scene scene;
    QUndoStack stack;
};

TEST_F(SweepUndo, ARecordTheDocumentAlreadyHasLeavesTheStackAsItWas) {
    makeHistory();
    const StackState before = state();
    const scene::SceneData sceneBefore = scene.toData();
    QSignalSpy cleanChanged(&stack, &QUndoStack::cleanChanged);
    QSignalSpy indexChanged(&stack, &QUndoStack::indexChanged);

    // The scene's own mirror depth, and a setting this scene cannot take (it has no shadowed light).
    EXPECT_FALSE(apply({{"mirrorDepth", std::to_string(scene.settings().mirrorDepth)}, {"pcf", "3"}}));

    EXPECT_EQ(state(), before);
    EXPECT_TRUE(stack.canRedo()) << "the redo step is kept";
    EXPECT_EQ(cleanChanged.count(), 0);
    EXPECT_EQ(indexChanged.count(), 0);
    EXPECT_EQ(scene.toData(), sceneBefore);
    stack.redo();
    EXPECT_TRUE(stack.isClean()) << "the saved state is still reachable";
}

TEST_F(SweepUndo, ARecordThatChangesSomethingIsOneStepBackToTheCleanState) {
    stack.setClean();
    const scene::SceneData before = scene.toData();
    const int depth = scene.settings().mirrorDepth == 3 ? 2 : 3;
    EXPECT_TRUE(apply({{"mirrorDepth", std::to_string(depth)}}));
    EXPECT_EQ(stack.count(), 1);
    EXPECT_FALSE(stack.isClean());
    EXPECT_EQ(scene.settings().mirrorDepth, depth);
    stack.undo();
    EXPECT_TRUE(stack.isClean());
    EXPECT_EQ(scene.toData(), before);
}

} // namespace
} // namespace speculum::document

// EditTransaction on its own: what it pushes is one step with its label, all or nothing; a transaction
// that ends without commit() (an early return, an exception) leaves the stack and the scene as they were.
#include "editor/document/EditTransaction.hpp"

#include "OperationsTestSupport.hpp"

#include <stdexcept>

namespace speculum::document {
namespace {

using test::named;
using test::OperationsTest;

class EditTransactionTest : public OperationsTest {};

TEST_F(EditTransactionTest, CommitLeavesOneStepWithTheLabelAndUndoRestoresExactly) {
    {
        EditTransaction edit(undo, QStringLiteral("Tidy up"));
        edit.push(new RemoveNodeCommand(scene, idOf("A")));
        edit.push(new RenameNodeCommand(scene, idOf("C"), "See"));
        EXPECT_EQ(edit.size(), 2);
        EXPECT_EQ(undo.count(), 0) << "nothing reaches the stack before commit()";
        EXPECT_EQ(topLevelNames(), (std::vector<std::string>{"B", "See"})) << "but the commands have run";
        edit.commit();
    }
    EXPECT_EQ(topLevelNames(), (std::vector<std::string>{"B", "See"}));
    ASSERT_EQ(undo.count(), 1);
    EXPECT_EQ(undo.undoText(), QStringLiteral("Tidy up"));
    EXPECT_FALSE(undo.isClean());
    undo.undo();
    EXPECT_EQ(scene.toData(), original);
    EXPECT_TRUE(undo.isClean());
    undo.redo();
    EXPECT_EQ(topLevelNames(), (std::vector<std::string>{"B", "See"}));
}

TEST_F(EditTransactionTest, WithoutALabelOneCommandReadsLikeThatCommand) {
    EditTransaction edit(undo);
    edit.push(new RemoveNodeCommand(scene, idOf("A")));
    edit.commit();
    EXPECT_EQ(undo.undoText().toStdString(), "Delete \u201cA\u201d");
}

TEST_F(EditTransactionTest, CommitWithNothingPushedLeavesNoStep) {
    EditTransaction edit(undo, QStringLiteral("Nothing"));
    edit.commit();
    EXPECT_EQ(undo.count(), 0);
    EXPECT_TRUE(undo.isClean());
    EXPECT_EQ(scene.toData(), original);
}

TEST_F(EditTransactionTest, ReturningEarlyUndoesWhatRanAndKeepsTheRedoHistory) {
    // A step to redo, so that a rollback which touched the stack would lose it.
    undo.push(new RenameNodeCommand(scene, idOf("A"), "Eh"));
    undo.undo();
    ASSERT_TRUE(undo.canRedo());
    const int changesBefore = changes;
    auto giveUp = [&] {
        EditTransaction edit(undo, QStringLiteral("Half done"));
        edit.push(new RemoveNodeCommand(scene, idOf("B")));
        edit.push(new MoveNodeCommand(scene, idOf("C"), idOf("A"), 0));
        return false; // no commit()
    };
    EXPECT_FALSE(giveUp());
    EXPECT_GT(changes, changesBefore) << "the commands did run";
    EXPECT_EQ(scene.toData(), original);
    EXPECT_EQ(undo.count(), 1);
    EXPECT_EQ(undo.index(), 0);
    EXPECT_TRUE(undo.canRedo()) << "the redo history is kept";
    EXPECT_EQ(undo.redoText().toStdString(), "Rename \u201cA\u201d to \u201cEh\u201d");
    EXPECT_TRUE(undo.isClean());
}

TEST_F(EditTransactionTest, AnExceptionUndoesWhatRan) {
    undo.push(new RenameNodeCommand(scene, idOf("A"), "Eh"));
    const scene::SceneData before = scene.toData();
    undo.setClean();
    try {
        EditTransaction edit(undo, QStringLiteral("Throws"));
        edit.push(new RemoveNodeCommand(scene, idOf("B1")));
        edit.push(new RemoveNodeCommand(scene, idOf("B")));
        throw std::runtime_error("out of here");
    } catch (const std::runtime_error&) {
    }
    EXPECT_EQ(scene.toData(), before);
    EXPECT_EQ(undo.count(), 1);
    EXPECT_EQ(undo.undoText().toStdString(), "Rename \u201cA\u201d to \u201cEh\u201d");
    EXPECT_TRUE(undo.isClean());
}

TEST_F(EditTransactionTest, MergeableCommandsMergeInsideTheTransaction) {
    const scene::NodeId a = idOf("A");
    scene::NodeData first = scene.findNode(a)->data();
    first.transform.translate = {1, 0, 0};
    scene::NodeData second = first;
    second.transform.translate = {2, 0, 0};
    EditTransaction edit(undo, QStringLiteral("Drag"));
    edit.push(new SetNodeDataCommand(scene, a, first, {}, QStringLiteral("drag#1")));
    edit.push(new SetNodeDataCommand(scene, a, second, {}, QStringLiteral("drag#1")));
    EXPECT_EQ(edit.size(), 1);
    edit.commit();
    EXPECT_EQ(scene.findNode(a)->data().transform.translate, glm::dvec3(2, 0, 0));
    undo.undo();
    EXPECT_EQ(scene.toData(), original);
}

} // namespace
} // namespace speculum::document

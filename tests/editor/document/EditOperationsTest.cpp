// The editing operations of the document layer, each on a Scene with its undo stack: what it does, that it
// is one undo step with the label the Undo menu shows, that undo gives back exactly the scene before it,
// and that a refused operation (or one that would change nothing) leaves no step and no change.
#include "editor/document/EditOperations.hpp"

#include "OperationsTestSupport.hpp"
#include "editor/document/NodeFactory.hpp"
#include "render/frame/SceneLimits.hpp"

namespace speculum::document {
namespace {

using test::named;
using test::OperationsTest;
using Names = std::vector<std::string>;

class EditOperationsTest : public OperationsTest {
protected:
    void expectNoStepAndNoChange() {
        EXPECT_EQ(undo.count(), 0);
        EXPECT_TRUE(undo.isClean());
        EXPECT_EQ(scene.toData(), original);
    }
};

TEST_F(EditOperationsTest, AddNodeTreeAddsAtTheTopLevelWithAUniqueName) {
    auto added = addNodeTree(scene, undo, named("A"));
    ASSERT_TRUE(added) << added.error();
    EXPECT_EQ(scene.findNode(*added)->name(), "A 2");
    EXPECT_EQ(topLevelNames(), (Names{"A", "B", "C", "A 2"}));
    expectOneStepThatUndoesExactly("Add \u201cA 2\u201d", original);
}

TEST_F(EditOperationsTest, AddNodeTreeTakesASecondReflectorAsOneUndoableStep) {
    ASSERT_TRUE(addNodeTree(scene, undo, makeNode(NewNodeKind::ReflectorSphere)));
    const scene::SceneData withOne = scene.toData();
    undo.clear();
    auto second = addNodeTree(scene, undo, makeNode(NewNodeKind::ReflectorTeapot));
    ASSERT_TRUE(second) << second.error();
    EXPECT_TRUE(scene.findNode(*second)->data().reflector.has_value());
    EXPECT_EQ(undo.count(), 1);
    undo.undo();
    EXPECT_EQ(scene.toData(), withOne);
}

TEST_F(EditOperationsTest, DeleteOneNodeOrSeveralIsOneStep) {
    ASSERT_TRUE(deleteNodes(scene, undo, {idOf("B")}));
    EXPECT_EQ(topLevelNames(), (Names{"A", "C"}));
    EXPECT_EQ(idOf("B1"), scene::kNoNode) << "the subtree goes with it";
    expectOneStepThatUndoesExactly("Delete \u201cB\u201d", original);

    undo.undo();
    undo.clear();
    ASSERT_TRUE(deleteNodes(scene, undo, {idOf("C"), idOf("A")}));
    EXPECT_EQ(topLevelNames(), (Names{"B"}));
    expectOneStepThatUndoesExactly("Delete 2 nodes", original);
}

TEST_F(EditOperationsTest, DeleteOfNothingIsRefused) {
    EXPECT_FALSE(deleteNodes(scene, undo, {}));
    EXPECT_FALSE(deleteNodes(scene, undo, {scene::NodeId(987654)}));
    expectNoStepAndNoChange();
}

TEST_F(EditOperationsTest, DuplicatePutsEachCopyAfterItsOriginalWithAUniqueName) {
    auto one = duplicateNodes(scene, undo, {idOf("B")}, idOf("B2"));
    ASSERT_TRUE(one) << one.error();
    ASSERT_EQ(one->copies.size(), 1u);
    EXPECT_EQ(topLevelNames(), (Names{"A", "B", "B 2", "C"}));
    EXPECT_EQ(namesUnder(one->copies.front()).size(), 2u) << "with its subtree";
    EXPECT_EQ(one->currentCopy, one->copies.front()) << "the current node lies under it";
    expectOneStepThatUndoesExactly("Duplicate \u201cB\u201d", original);

    undo.undo();
    undo.clear();
    auto two = duplicateNodes(scene, undo, {idOf("A"), idOf("B1")}, idOf("A"));
    ASSERT_TRUE(two) << two.error();
    ASSERT_EQ(two->copies.size(), 2u);
    EXPECT_EQ(topLevelNames(), (Names{"A", "A 2", "B", "C"}));
    EXPECT_EQ(namesUnder(idOf("B")), (Names{"B1", "B1 2", "B2"})) << "under the same parent";
    EXPECT_EQ(two->currentCopy, idOf("A 2"));
    expectOneStepThatUndoesExactly("Duplicate 2 nodes", original);
}

TEST_F(EditOperationsTest, DuplicateOfAReflectorIsASecondReflector) {
    auto reflector = addNodeTree(scene, undo, makeNode(NewNodeKind::ReflectorSphere));
    ASSERT_TRUE(reflector);
    const scene::SceneData before = scene.toData();
    undo.clear();
    auto copy = duplicateNodes(scene, undo, {*reflector});
    ASSERT_TRUE(copy);
    EXPECT_TRUE(scene.findNode(copy->copies.front())->data().reflector.has_value());
    EXPECT_TRUE(scene.findNode(*reflector)->data().reflector.has_value());
    expectOneStepThatUndoesExactly("Duplicate \u201c" + scene.findNode(*reflector)->name() + "\u201d",
                                   before);
}

TEST_F(EditOperationsTest, RenameTrimsAndRefusesEmptyOrUnchangedNames) {
    ASSERT_TRUE(renameNode(scene, undo, idOf("A"), "  Apple "));
    EXPECT_EQ(topLevelNames(), (Names{"Apple", "B", "C"}));
    expectOneStepThatUndoesExactly("Rename \u201cA\u201d to \u201cApple\u201d", original);

    undo.undo();
    undo.clear();
    EXPECT_FALSE(renameNode(scene, undo, idOf("A"), "   "));
    EXPECT_FALSE(renameNode(scene, undo, idOf("A"), "A"));
    EXPECT_FALSE(renameNode(scene, undo, scene::NodeId(987654), "X"));
    expectNoStepAndNoChange();
}

TEST_F(EditOperationsTest, MoveOneNodeUnderAnother) {
    ASSERT_TRUE(moveNodes(scene, undo, {idOf("C")}, idOf("B"), 1));
    EXPECT_EQ(topLevelNames(), (Names{"A", "B"}));
    EXPECT_EQ(namesUnder(idOf("B")), (Names{"B1", "C", "B2"}));
    expectOneStepThatUndoesExactly("Move \u201cC\u201d", original);
}

TEST_F(EditOperationsTest, MoveSeveralKeepsTreeOrderAndTakesChildrenWithTheirParent) {
    // Listed out of order, with B1 under B: B and C move, B1 goes with B.
    ASSERT_TRUE(moveNodes(scene, undo, {idOf("C"), idOf("B1"), idOf("B")}, scene::kNoNode, 0));
    EXPECT_EQ(topLevelNames(), (Names{"B", "C", "A"}));
    EXPECT_EQ(namesUnder(idOf("B")), (Names{"B1", "B2"}));
    expectOneStepThatUndoesExactly("Move 2 nodes", original);
}

TEST_F(EditOperationsTest, MoveIntoItsOwnSubtreeOrToWhereItIsIsRefused) {
    EXPECT_FALSE(moveNodes(scene, undo, {idOf("B")}, idOf("B1"), 0));
    EXPECT_FALSE(moveNodes(scene, undo, {idOf("A"), idOf("B")}, idOf("B2"), -1));
    EXPECT_FALSE(moveNodes(scene, undo, {idOf("A")}, scene::kNoNode, 0)) << "already first";
    EXPECT_FALSE(moveNodes(scene, undo, {idOf("B1"), idOf("B2")}, idOf("B"), 0)) << "already in that order";
    EXPECT_FALSE(moveNodes(scene, undo, {}, scene::kNoNode, 0));
    expectNoStepAndNoChange();
}

TEST_F(EditOperationsTest, OutermostInTreeOrder) {
    EXPECT_EQ(outermostInTreeOrder(scene, {idOf("C"), idOf("B2"), idOf("B"), idOf("A"), idOf("C"), 987654}),
              (std::vector<scene::NodeId>{idOf("A"), idOf("B"), idOf("C")}));
}

TEST_F(EditOperationsTest, SetCameraFromViewTakesTheViewAndKeepsTheDepthRange) {
    render::Camera view;
    view.position = {5, 6, 7};
    view.target = {1, 2, 3};
    view.up = {0, 0, 1};
    view.far = 1e12;
    ASSERT_TRUE(setCameraFromView(scene, undo, view));
    EXPECT_EQ(scene.camera().position, view.position);
    EXPECT_EQ(scene.camera().target, view.target);
    EXPECT_EQ(scene.camera().up, view.up);
    EXPECT_EQ(scene.camera().fovY, original.camera.fovY) << "the lens stays the scene's";
    EXPECT_LE(scene.camera().far, scene.camera().near * render::kMaxFarNearRatio);
    expectOneStepThatUndoesExactly("Set scene camera from view", original);

    // The same view again changes nothing: no second step.
    ASSERT_TRUE(setCameraFromView(scene, undo, view));
    EXPECT_EQ(undo.count(), 1);
}

} // namespace
} // namespace speculum::document

namespace speculum::document {
namespace {

// Hide and show: one undo step each; a hidden node and what is under it are in no picture and cannot be
// clicked; the file keeps it.
TEST_F(EditOperationsTest, HiddenNodesLeaveEveryPictureAndComeBackWithShowAll) {
    ASSERT_TRUE(setNodesHidden(scene, undo, {idOf("B")}, true));
    EXPECT_TRUE(scene.isHidden(idOf("B")));
    EXPECT_TRUE(scene.isHidden(idOf("B1"))) << "under a hidden node";
    EXPECT_FALSE(scene.isHidden(idOf("A")));
    expectOneStepThatUndoesExactly("Hide \u201cB\u201d", original);
    EXPECT_FALSE(setNodesHidden(scene, undo, {idOf("B")}, true)) << "already hidden: no step";
    EXPECT_EQ(undo.count(), 1);
    ASSERT_TRUE(setNodesHidden(scene, undo, {idOf("A"), idOf("C")}, true));
    EXPECT_EQ(undo.undoText().toStdString(), "Hide 2 nodes");
    ASSERT_TRUE(showAllNodes(scene, undo));
    EXPECT_EQ(undo.undoText().toStdString(), "Show 3 nodes");
    EXPECT_EQ(scene.toData(), original);
    EXPECT_FALSE(showAllNodes(scene, undo)) << "nothing hidden: no step";
}

} // namespace
} // namespace speculum::document

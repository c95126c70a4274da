// The shared Selection on its own: several nodes with a current one, Ctrl+click toggling, the camera
// selected alone, nodes that leave the scene let go of, the roots an action on the selection acts on; and
// how a handle drag of the current node carries over to the other selected nodes.
#include "editor/document/Commands.hpp"
#include "editor/document/NodeFactory.hpp"
#include "editor/document/NodeMath.hpp"
#include "editor/document/Scene.hpp"
#include "editor/ui/Gizmo.hpp"
#include "editor/ui/Selection.hpp"

#include <QCoreApplication>
#include <QSignalSpy>
#include <QUndoStack>
#include <gtest/gtest.h>

namespace {

using namespace speculum;
using document::NodeId;
using Ids = std::vector<NodeId>;

class SelectionTest : public ::testing::Test {
protected:
    NodeId add(document::NewNodeKind kind) {
        auto* command = new document::AddNodeCommand(m_scene, document::makeNode(kind));
        m_undo.push(command);
        return command->nodeId();
    }

    document::Scene m_scene;
    QUndoStack m_undo;
    ui::Selection m_selection{m_scene};
};

TEST_F(SelectionTest, HoldsSeveralNodesInTheOrderPickedWithTheLastOneCurrent) {
    const NodeId a = add(document::NewNodeKind::Sphere);
    const NodeId b = add(document::NewNodeKind::Box);
    const NodeId c = add(document::NewNodeKind::Mirror);
    QSignalSpy changed(&m_selection, &ui::Selection::changed);

    m_selection.selectNode(a);
    EXPECT_EQ(m_selection.nodes(), Ids{a});
    EXPECT_EQ(m_selection.node(), a);
    m_selection.toggleNode(c);
    m_selection.toggleNode(b);
    EXPECT_EQ(m_selection.nodes(), (Ids{a, c, b}));
    EXPECT_EQ(m_selection.node(), b);
    EXPECT_EQ(m_selection.selectedNode(), m_scene.findNode(b));
    EXPECT_TRUE(m_selection.contains(c));
    EXPECT_EQ(changed.count(), 3);

    // Toggling the current node off makes the one picked before it current.
    m_selection.toggleNode(b);
    EXPECT_EQ(m_selection.nodes(), (Ids{a, c}));
    EXPECT_EQ(m_selection.node(), c);
    EXPECT_FALSE(m_selection.contains(b));

    // selectNode selects only that one; selecting the same again is no change.
    m_selection.selectNode(b);
    EXPECT_EQ(m_selection.nodes(), Ids{b});
    const int before = changed.count();
    m_selection.selectNode(b);
    EXPECT_EQ(changed.count(), before);

    // setNodes: unknown ids and repeats are skipped, `current` goes last.
    m_selection.setNodes({a, 9999, b, a, c}, b);
    EXPECT_EQ(m_selection.nodes(), (Ids{a, c, b}));
    m_selection.setNodes({a, c}, 9999);
    EXPECT_EQ(m_selection.node(), c) << "without a current among them, the last one is";
    m_selection.selectNode(document::kNoNode);
    EXPECT_TRUE(m_selection.isEmpty());
}

TEST_F(SelectionTest, TheCameraIsSelectedAlone) {
    const NodeId a = add(document::NewNodeKind::Sphere);
    const NodeId b = add(document::NewNodeKind::Box);
    m_selection.setNodes({a, b});
    m_selection.selectCamera();
    EXPECT_TRUE(m_selection.isCamera());
    EXPECT_TRUE(m_selection.nodes().empty());
    EXPECT_EQ(m_selection.node(), document::kNoNode);
    m_selection.toggleNode(a);
    EXPECT_FALSE(m_selection.isCamera());
    EXPECT_EQ(m_selection.nodes(), Ids{a});
    m_selection.clear();
    EXPECT_TRUE(m_selection.isEmpty());
}

TEST_F(SelectionTest, NodesThatLeaveTheSceneAreDropped) {
    const NodeId a = add(document::NewNodeKind::Sphere);
    const NodeId b = add(document::NewNodeKind::Box);
    const NodeId c = add(document::NewNodeKind::Mirror);
    m_selection.setNodes({a, b, c}, b);
    m_undo.push(new document::RemoveNodeCommand(m_scene, b));
    QCoreApplication::processEvents(); // queued: a node only moving is not deselected
    EXPECT_EQ(m_selection.nodes(), (Ids{a, c}));
    EXPECT_EQ(m_selection.node(), c);
    m_undo.undo();
    m_undo.undo(); // the mirror's Add: it goes too
    QCoreApplication::processEvents();
    EXPECT_EQ(m_selection.nodes(), Ids{a});
}

TEST_F(SelectionTest, RootsSkipNodesUnderASelectedAncestor) {
    const NodeId a = add(document::NewNodeKind::Sphere);
    const NodeId b = add(document::NewNodeKind::Box);
    const NodeId c = add(document::NewNodeKind::Mirror);
    m_undo.push(new document::MoveNodeCommand(m_scene, b, a, 0)); // b under a
    m_selection.setNodes({b, a, c}, b);
    EXPECT_EQ(m_selection.roots(), (Ids{a, c})) << "b goes with a";
    m_selection.setNodes({b, c}, c);
    EXPECT_EQ(m_selection.roots(), (Ids{b, c})) << "an unselected parent does not count";
}

TEST(FollowDrag, MovesByTheSameWorldDisplacementInEachParentsSpace) {
    document::NodeData leadStart, leadNow, other;
    leadStart.transform.translate = {1, 1, 1};
    leadNow.transform.translate = {2, 3, 1}; // under a parent scaled by 2: a world move of (2, 4, 0)
    const glm::dmat4 leadParent = document::localMatrix({7, 0, 0}, {0, 0, 0}, {2, 2, 2});
    other.transform.translate = {5, 0, 0};
    other.material = document::MaterialComponent{};
    // Under a parent turned 90° about Z: world +X is the parent's -Y, world +Y its +X.
    const glm::dmat4 otherParent = document::localMatrix({0, 0, -3}, {0, 0, 90}, {1, 1, 1});
    const document::NodeData out =
        ui::followDrag(ui::HandleMode::Move, leadStart, leadNow, leadParent, other, otherParent);
    EXPECT_NEAR(out.transform.translate.x, 5.0 + 4.0, 1e-12);
    EXPECT_NEAR(out.transform.translate.y, 0.0 - 2.0, 1e-12);
    EXPECT_NEAR(out.transform.translate.z, 0.0, 1e-12);
    EXPECT_EQ(out.transform.rotate, other.transform.rotate);
    EXPECT_EQ(out.material, other.material) << "only the transform changes";

    // A parent scaled to zero cannot take a world displacement: the node stays.
    const glm::dmat4 flat = document::localMatrix({0, 0, 0}, {0, 0, 0}, {0, 0, 0});
    EXPECT_EQ(ui::followDrag(ui::HandleMode::Move, leadStart, leadNow, leadParent, other, flat), other);
}

TEST(FollowDrag, RotatesByTheSameAnglesAndScalesByTheSameFactors) {
    document::NodeData leadStart, leadNow, other;
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

// The shared Selection on its own: several nodes with a current one, Ctrl+click toggling, the camera
// selected alone, nodes that leave the scene let go of, the roots an action on the selection acts on.
#include "editor/view/Selection.hpp"

#include "editor/document/Commands.hpp"
#include "editor/document/NodeFactory.hpp"
#include "scene/model/Scene.hpp"

#include <QCoreApplication>
#include <QSignalSpy>
#include <QUndoStack>
#include <gtest/gtest.h>

namespace {

using namespace speculum;
using speculum::scene::NodeId;
using Ids = std::vector<NodeId>;

class SelectionTest : public ::testing::Test {
protected:
    NodeId add(document::NewNodeKind kind) {
        auto* command = new document::AddNodeCommand(m_scene, document::makeNode(kind));
        m_undo.push(command);
        return command->nodeId();
    }

    speculum::scene::Scene m_scene;
    QUndoStack m_undo;
    view::Selection m_selection{m_scene};
};

TEST_F(SelectionTest, HoldsSeveralNodesInTheOrderPickedWithTheLastOneCurrent) {
    const NodeId a = add(document::NewNodeKind::Sphere);
    const NodeId b = add(document::NewNodeKind::Box);
    const NodeId c = add(document::NewNodeKind::Mirror);
    QSignalSpy changed(&m_selection, &view::Selection::changed);

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
    m_selection.selectNode(speculum::scene::kNoNode);
    EXPECT_TRUE(m_selection.isEmpty());
}

TEST_F(SelectionTest, TheCameraIsSelectedAlone) {
    const NodeId a = add(document::NewNodeKind::Sphere);
    const NodeId b = add(document::NewNodeKind::Box);
    m_selection.setNodes({a, b});
    m_selection.selectCamera();
    EXPECT_TRUE(m_selection.isCamera());
    EXPECT_TRUE(m_selection.nodes().empty());
    EXPECT_EQ(m_selection.node(), speculum::scene::kNoNode);
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

} // namespace

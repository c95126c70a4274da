// Copy and paste of nodes: the copy is a small project file with absolute paths; pasting adds its subtrees
// where they were, with unique names, as one undo step; a second reflector is dropped; text that is no
// speculum scene is refused without a step.
#include "editor/document/NodeClipboard.hpp"

#include "OperationsTestSupport.hpp"
#include "editor/document/EditOperations.hpp"
#include "editor/document/NodeFactory.hpp"

#include <QString>

namespace speculum::document {
namespace {

using test::named;
using test::OperationsTest;
using Names = std::vector<std::string>;

class NodeClipboardTest : public OperationsTest {};

TEST_F(NodeClipboardTest, PastingACopyAddsTheSubtreesWithUniqueNamesAsOneStep) {
    const QByteArray copied = copyNodes(scene, {idOf("B"), idOf("B1"), idOf("C")});
    EXPECT_TRUE(copied.contains("\"format\": \"speculum-scene\"")) << "a project file, readable as text";
    auto pasted = pasteNodes(scene, undo, copied);
    ASSERT_TRUE(pasted) << pasted.error();
    ASSERT_EQ(pasted->nodes.size(), 2u) << "B1 goes with B";
    EXPECT_EQ(topLevelNames(), (Names{"A", "B", "C", "B 2", "C 2"}));
    EXPECT_EQ(namesUnder(pasted->nodes.front()), (Names{"B1", "B2"}));
    expectOneStepThatUndoesExactly("Paste 2 nodes", original);
}

TEST_F(NodeClipboardTest, APastedNodeKeepsItsTransformAndItsModelPath) {
    scene::NodeTree model = named("Duck");
    model.data.transform.translate = {1.5, 0.25, -2.0};
    model.data.mesh = scene::MeshComponent::fromFile("/usr/share/assimp/models/OBJ/box.obj");
    ASSERT_TRUE(addNodeTree(scene, undo, model));
    const QByteArray copied = copyNodes(scene, {idOf("Duck")});
    // Into another document, as another editor would paste it.
    scene::Scene other;
    QUndoStack otherUndo;
    other.setProjectPath(QStringLiteral("/tmp/elsewhere/other.speculum.json"));
    auto pasted = pasteNodes(other, otherUndo, copied);
    ASSERT_TRUE(pasted) << pasted.error();
    const scene::NodeData& data = other.findNode(pasted->nodes.front())->data();
    EXPECT_EQ(data.name, "Duck");
    EXPECT_EQ(data.transform.translate, glm::dvec3(1.5, 0.25, -2.0));
    ASSERT_TRUE(data.mesh);
    EXPECT_EQ(data.mesh->file, "/usr/share/assimp/models/OBJ/box.obj") << "absolute wherever it is pasted";
    EXPECT_EQ(otherUndo.undoText().toStdString(), "Paste \u201cDuck\u201d");
}

TEST_F(NodeClipboardTest, APastedReflectorStaysOneBesideTheFirst) {
    auto reflector = addNodeTree(scene, undo, makeNode(NewNodeKind::ReflectorSphere));
    ASSERT_TRUE(reflector);
    const QByteArray copied = copyNodes(scene, {*reflector});
    auto pasted = pasteNodes(scene, undo, copied);
    ASSERT_TRUE(pasted) << pasted.error();
    EXPECT_TRUE(scene.findNode(pasted->nodes.front())->data().reflector);
    EXPECT_TRUE(scene.findNode(*reflector)->data().reflector) << "each keeps its reflector";
}

TEST_F(NodeClipboardTest, TextThatHoldsNoNodesIsRefusedWithoutAStep) {
    for (const QByteArray& text :
         {QByteArray("hello"), QByteArray("{\"format\": \"speculum-scene\", \"version\": 1}"),
          QByteArray()}) {
        auto pasted = pasteNodes(scene, undo, text);
        ASSERT_FALSE(pasted) << text.toStdString();
        EXPECT_NE(pasted.error().find("clipboard"), std::string::npos) << pasted.error();
    }
    EXPECT_EQ(undo.count(), 0);
    EXPECT_EQ(scene.toData(), original);
}

} // namespace
} // namespace speculum::document

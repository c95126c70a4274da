// As a Blender or Godot user tries them: the editing shortcuts work from the
// scene tree (not only from the viewport) without stealing keys from text fields; a new document starts
// with a floor, a sun and a camera raised above them; the first mirror added faces the view instead of
// lying edge-on; new objects do not land inside each other and a duplicate steps aside.
#include "editor/document/NewScene.hpp"
#include "editor/document/NodeFactory.hpp"
#include "editor/ui/SceneTreePanel.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "scene/evaluate/PickScene.hpp"
#include "scene/evaluate/Picking.hpp"
#include "scene/model/NodeMath.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QAction>
#include <QDir>
#include <QLineEdit>
#include <QTest>
#include <QTreeView>
#include <QUndoStack>
#include <QWindow>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace speculum::ui {
namespace {

using test::waitFor;
using test::waitForFrames;

class EditorInput : public ::testing::Test {
protected:
    void SetUp() override {
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1280, 800);
        m_window->show();
        ASSERT_TRUE(
            waitFor([&] { return m_window->windowHandle() && m_window->windowHandle()->isExposed(); }));
        m_window->activateWindow();
        m_window->clock().setPlaying(false);
    }
    void TearDown() override {
        if (m_window) {
            m_window->undoStack().setClean();
            m_window.reset();
        }
    }

    QTreeView& tree() { return m_window->sceneTree().view(); }
    scene::Scene& scene() { return m_window->scene(); }

    // Keyboard focus in the scene tree, as after a click on a row.
    void focusTree() {
        tree().setFocus(Qt::OtherFocusReason);
        ASSERT_TRUE(waitFor([&] { return tree().hasFocus(); }));
    }

    // The world box of what `id` draws (its mesh and mirror, children included).
    render::math::Box box(scene::NodeId id) {
        render::math::Box b;
        const auto worlds = scene::worldMatrices(scene(), 0.0);
        std::vector<scene::Warning> ignored;
        scene().forEachNode([&](const scene::Node& n) {
            if (!scene().isAncestor(id, n.id())) {
                return;
            }
            const glm::dmat4& world = worlds.at(n.id());
            if (n.data().mesh) {
                if (auto mesh = m_window->viewport().meshes().get(*n.data().mesh, ignored); mesh && *mesh) {
                    b.add(render::math::worldBounds(scene::meshBounds(*mesh), world));
                }
            }
            if (n.data().mirror) {
                const glm::dvec2 h = n.data().mirror->size * 0.5;
                b.add(glm::dvec3(world * glm::dvec4(-h.x, 0.0, -h.y, 1.0)));
                b.add(glm::dvec3(world * glm::dvec4(h.x, 0.0, h.y, 1.0)));
            }
        });
        return b;
    }

    static bool overlap(const render::math::Box& a, const render::math::Box& b) {
        for (int i = 0; i < 3; ++i) {
            if (!(a.min[i] < b.max[i] - 1e-9 && b.min[i] < a.max[i] - 1e-9)) {
                return false;
            }
        }
        return true;
    }

    std::unique_ptr<MainWindow> m_window;
};

TEST_F(EditorInput, ANewSceneHasAFloorASunAndACameraAboveThem) {
    const scene::SceneData data = scene().toData();
    EXPECT_TRUE(data == document::newSceneData());
    ASSERT_EQ(data.nodes.size(), 2u);
    EXPECT_EQ(data.nodes[0].data.name, "Floor");
    EXPECT_EQ(data.nodes[1].data.name, "Sun");
    ASSERT_TRUE(data.nodes[1].data.light);
    EXPECT_GT(data.camera.position.y, 1.0) << "raised: the floor is seen from above, not edge-on";
    EXPECT_LT(data.camera.target.y, data.camera.position.y) << "looking down at the floor";
    EXPECT_FALSE(m_window->isWindowModified()) << "nothing to save yet";
    EXPECT_EQ(m_window->undoStack().count(), 0);
    ASSERT_TRUE(waitForFrames(*m_window));
    EXPECT_TRUE(m_window->viewport().rendererError().isEmpty());
}

TEST_F(EditorInput, TheFirstMirrorFacesTheViewAndStandsOnTheFloor) {
    ASSERT_TRUE(m_window->addNode(document::NewNodeKind::Mirror).ok());
    const scene::NodeId id = m_window->selection().node();
    const scene::Node* mirror = scene().findNode(id);
    ASSERT_TRUE(mirror && mirror->data().mirror);
    const glm::dmat4 world = scene::worldMatrices(scene(), 0.0).at(id);
    const glm::dvec3 normal = glm::normalize(glm::dvec3(world * glm::dvec4(0.0, 1.0, 0.0, 0.0)));
    const glm::dvec3 centre(world[3]);
    const glm::dvec3 toView = glm::normalize(m_window->viewport().viewCamera().position - centre);
    EXPECT_GT(glm::dot(normal, toView), 0.5) << "facing the view, never edge-on";
    const auto b = box(id);
    EXPECT_GE(b.min.y, -1e-6) << "on the floor, not through it";
    EXPECT_LT(b.min.y, 0.05) << "standing on it, not floating";
}

TEST_F(EditorInput, NewObjectsDoNotLandInsideEachOtherAndADuplicateStepsAside) {
    ASSERT_TRUE(m_window->addNode(document::NewNodeKind::Teapot).ok());
    const scene::NodeId first = m_window->selection().node();
    ASSERT_TRUE(m_window->addNode(document::NewNodeKind::Teapot).ok());
    const scene::NodeId second = m_window->selection().node();
    EXPECT_FALSE(overlap(box(first), box(second))) << "the second teapot lands beside the first";
    EXPECT_NEAR(box(second).min.y, 0.0, 1e-6) << "on the floor";

    ASSERT_TRUE(m_window->duplicateSelected().ok());
    const scene::NodeId copy = m_window->selection().node();
    ASSERT_NE(copy, second);
    EXPECT_FALSE(overlap(box(copy), box(second))) << "the duplicate steps aside from its original";
    EXPECT_FALSE(overlap(box(copy), box(first)));
    EXPECT_NEAR(box(copy).min.y, box(second).min.y, 1e-9) << "at the same height";
}

TEST_F(EditorInput, DeleteDuplicateAndHandleKeysWorkFromTheSceneTree) {
    ASSERT_TRUE(m_window->addNode(document::NewNodeKind::Teapot).ok());
    const scene::NodeId teapot = m_window->selection().node();
    focusTree();
    const std::size_t nodes = scene().topLevelNodes().size();

    QTest::keyClick(&tree(), Qt::Key_D, Qt::ControlModifier);
    EXPECT_EQ(scene().topLevelNodes().size(), nodes + 1) << "Ctrl+D from the tree duplicates";
    EXPECT_EQ(m_window->undoStack().undoText().toStdString(), "Duplicate \u201cTeapot\u201d");

    QTest::keyClick(&tree(), Qt::Key_E);
    EXPECT_EQ(m_window->viewport().handleMode(), HandleMode::Rotate) << "E from the tree: rotate handles";
    QTest::keyClick(&tree(), Qt::Key_W);
    EXPECT_EQ(m_window->viewport().handleMode(), HandleMode::Move);

    const int steps = m_window->undoStack().count();
    QTest::keyClick(&tree(), Qt::Key_Delete);
    EXPECT_EQ(scene().topLevelNodes().size(), nodes) << "Delete from the tree deletes";
    EXPECT_EQ(m_window->undoStack().count(), steps + 1) << "in one undo step";
    EXPECT_TRUE(scene().findNode(teapot)) << "the copy went, the original stays";
    m_window->undoStack().undo();
    EXPECT_EQ(scene().topLevelNodes().size(), nodes + 1);
}

TEST_F(EditorInput, ATextFieldKeepsItsKeys) {
    ASSERT_TRUE(m_window->addNode(document::NewNodeKind::Teapot).ok());
    const std::size_t nodes = scene().topLevelNodes().size();
    const int steps = m_window->undoStack().count();
    // The tree's own rename editor, as F2 or a double click opens it.
    const QModelIndex current = tree().currentIndex();
    ASSERT_TRUE(current.isValid());
    tree().edit(current);
    QLineEdit* editor = nullptr;
    ASSERT_TRUE(waitFor([&] {
        editor = qobject_cast<QLineEdit*>(QApplication::focusWidget());
        return editor != nullptr;
    }));
    editor->selectAll();
    QTest::keyClicks(editor, QStringLiteral("qwer"));
    EXPECT_EQ(editor->text(), QStringLiteral("qwer")) << "letters type, they do not switch handles";
    EXPECT_EQ(m_window->viewport().handleMode(), HandleMode::Move);
    QTest::keyClick(editor, Qt::Key_Home);
    QTest::keyClick(editor, Qt::Key_Delete);
    EXPECT_EQ(editor->text(), QStringLiteral("wer")) << "Delete deletes a character, not the node";
    QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
    EXPECT_EQ(editor->selectedText(), QStringLiteral("wer")) << "Ctrl+A selects the text";
    EXPECT_EQ(scene().topLevelNodes().size(), nodes);
    EXPECT_EQ(m_window->undoStack().count(), steps) << "nothing edited until the rename is committed";
    QTest::keyClick(editor, Qt::Key_Escape);
}

// Pictures of a new document with its first mirror and of each demo, for people to look at
// (SPECULUM_SHOTS_DIR set).
TEST_F(EditorInput, ScreenshotsOfANewSceneAndTheDemos) {
    const QString shots = qEnvironmentVariable("SPECULUM_SHOTS_DIR");
    if (shots.isEmpty()) {
        GTEST_SKIP() << "set SPECULUM_SHOTS_DIR to write the screenshots";
    }
    auto shoot = [&](const QString& name) {
        ASSERT_TRUE(waitFor([&] { return !m_window->viewport().isInteracting(); }));
        ASSERT_TRUE(waitForFrames(*m_window, 2));
        EXPECT_TRUE(m_window->grab().save(QDir(shots).filePath(name)));
    };
    ASSERT_TRUE(m_window->addNode(document::NewNodeKind::Mirror).ok());
    ASSERT_TRUE(m_window->addNode(document::NewNodeKind::Teapot).ok());
    shoot(QStringLiteral("new-scene-first-mirror.png"));
    for (const char* demo : {"teapot", "mirrors", "chrome", "models"}) {
        const QString path =
            QString::fromStdString(speculum::testSourcePath("resources/scenes/%1.speculum.json")).arg(demo);
        ASSERT_TRUE(m_window->openProjectFile(path).ok()) << demo;
        shoot(QStringLiteral("demo-%1.png").arg(QString::fromLatin1(demo)));
    }
}

} // namespace
} // namespace speculum::ui

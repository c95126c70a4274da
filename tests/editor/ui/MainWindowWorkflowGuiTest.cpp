// The editor as a user drives it: building a scene from the Add menu and the inspector, undoing it all and
// redoing it, saving and reopening; the scene tree's rename, reparent, delete and duplicate; refused
// inspector values; click-to-select (also through a mirror) and handle drags; multiple selection in the tree
// and the viewport, with Delete, Duplicate, handle drags and a drag in the tree as one undo step; crash
// recovery.
#include "editor/document/Commands.hpp"
#include "editor/document/NewScene.hpp"
#include "editor/ui/Gizmo.hpp"
#include "editor/ui/Inspector.hpp"
#include "editor/ui/PropertyEditors.hpp"
#include "editor/ui/SceneTreeModel.hpp"
#include "editor/ui/SceneTreePanel.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "scene/evaluate/PickScene.hpp"
#include "scene/model/Scene.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QAction>
#include <QClipboard>
#include <QDir>
#include <QDoubleSpinBox>
#include <QDropEvent>
#include <QFile>
#include <QGuiApplication>
#include <QLabel>
#include <QMenu>
#include <QMimeData>
#include <QSlider>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTreeView>
#include <QUndoStack>
#include <QUndoView>
#include <QUrl>
#include <QWindow>
#include <algorithm>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <optional>
#include <tuple>

namespace {

using namespace speculum;
using namespace speculum::ui::test;
using speculum::scene::NodeId;
using ui::MainWindow;

const QString kTeapotProject =
    QString::fromStdString(speculum::testSourcePath("resources/scenes/teapot.speculum.json"));

class EditorWorkflow : public ::testing::Test {
protected:
    void SetUp() override {
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1600, 900);
        m_window->show();
        ASSERT_TRUE(
            waitFor([&] { return m_window->windowHandle() && m_window->windowHandle()->isExposed(); }));
        m_window->clock().setPlaying(false);
        m_window->clock().setTime(0.0);
    }

    void TearDown() override {
        if (m_window) {
            m_window->undoStack().setClean();
            m_window->newProject(); // nothing modified: no prompt on close
            m_window.reset();
        }
    }

    void openTeapot() {
        auto status = m_window->openProjectFile(kTeapotProject);
        ASSERT_TRUE(status.ok()) << status.error();
        ASSERT_TRUE(waitForFrames(*m_window));
        ASSERT_TRUE(m_window->viewport().rendererError().isEmpty());
    }

    void trigger(const char* name) {
        QAction* a = m_window->action(QString::fromLatin1(name));
        ASSERT_NE(a, nullptr) << name;
        ASSERT_TRUE(a->isEnabled()) << name;
        a->trigger();
    }

    // A spin box of the inspector: "<key>" for numbers, "<key>.x" etc. for vectors and colours.
    QDoubleSpinBox* spin(const QString& key, const QString& part = {}) {
        ui::PropertyEditor* editor = m_window->inspector().editor(key);
        if (!editor) {
            ADD_FAILURE() << "no editor for " << key.toStdString();
            return nullptr;
        }
        auto* box = editor->findChild<QDoubleSpinBox*>(part.isEmpty() ? key : key + QLatin1Char('.') + part);
        EXPECT_NE(box, nullptr) << key.toStdString() << " " << part.toStdString();
        return box;
    }

    void setVector(const QString& key, const glm::dvec3& v) {
        const char* parts[] = {"x", "y", "z"};
        for (int i = 0; i < 3; ++i) {
            if (QDoubleSpinBox* s = spin(key, QString::fromLatin1(parts[i]))) {
                s->setValue(v[i]);
            }
        }
    }

    const speculum::scene::Node* selected() { return m_window->selection().selectedNode(); }

    std::optional<NodeId> nodeNamed(const std::string& name) {
        std::optional<NodeId> found;
        m_window->scene().forEachNode([&](const speculum::scene::Node& node) {
            if (node.name() == name && !found) {
                found = node.id();
            }
        });
        return found;
    }

    // Widget position (logical pixels) of a world point in the viewport's current view.
    QPoint onScreen(const glm::dvec3& world) {
        ui::ScreenProjection projection(m_window->viewport().viewCamera(),
                                        QSizeF(m_window->viewport().width(), m_window->viewport().height()));
        const auto p = projection.project(world);
        EXPECT_TRUE(p.has_value());
        return p ? p->toPoint() : QPoint();
    }

    QTreeView* treeView() { return m_window->sceneTree().findChild<QTreeView*>(QStringLiteral("sceneTree")); }

    // Clicks a row of the scene tree as a user does (with Ctrl or Shift for a multiple selection).
    void clickRow(const QModelIndex& index, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
        QTreeView* view = treeView();
        ASSERT_TRUE(index.isValid());
        view->scrollTo(index);
        QTest::mouseClick(view->viewport(), Qt::LeftButton, modifiers, view->visualRect(index).center());
    }

    // The node ids the tree shows selected, in tree order.
    std::vector<NodeId> treeSelection() {
        std::vector<NodeId> ids;
        QModelIndexList rows = treeView()->selectionModel()->selectedIndexes();
        std::sort(rows.begin(), rows.end());
        for (const QModelIndex& index : rows) {
            ids.push_back(m_window->sceneTreeModel().nodeId(index));
        }
        return ids;
    }

    // Every node with its parent and its index there, in tree order.
    std::vector<std::tuple<NodeId, NodeId, int>> layout() {
        std::vector<std::tuple<NodeId, NodeId, int>> nodes;
        const speculum::scene::Scene& scene = m_window->scene();
        scene.forEachNode([&](const speculum::scene::Node& node) {
            nodes.emplace_back(node.id(), scene.parentOf(node.id()), scene.indexOf(node.id()));
        });
        return nodes;
    }

    std::unique_ptr<MainWindow> m_window;
};

using Ids = std::vector<NodeId>;
using Layout = std::vector<std::tuple<NodeId, NodeId, int>>;

TEST_F(EditorWorkflow, BuildASceneThroughMenusAndInspectorUndoAllRedoAllSaveAndReopen) {
    m_window->newProject();
    QUndoStack& undo = m_window->undoStack();
    // A new document holds its floor and sun (document::newSceneData); what is built comes after them.
    const speculum::scene::SceneData fresh = m_window->scene().toData();
    EXPECT_TRUE(fresh == document::newSceneData());
    ASSERT_EQ(fresh.nodes.size(), 2u);
    EXPECT_EQ(fresh.nodes[0].data.name, "Floor");
    EXPECT_EQ(fresh.nodes[1].data.name, "Sun");

    trigger("addTeapot");
    ASSERT_TRUE(selected());
    EXPECT_EQ(selected()->name(), "Teapot");
    setVector(QStringLiteral("transform.translate"), {0.0, -1.0, -3.0});

    trigger("addMirror");
    EXPECT_EQ(selected()->name(), "Mirror");
    setVector(QStringLiteral("transform.translate"), {0.0, -1.0, -3.0});
    spin(QStringLiteral("mirror.size"), QStringLiteral("x"))->setValue(4.0);
    spin(QStringLiteral("mirror.size"), QStringLiteral("y"))->setValue(4.0);
    spin(QStringLiteral("mirror.reflectivity"))->setValue(0.6);

    trigger("addMirror");
    EXPECT_EQ(selected()->name(), "Mirror 2");
    setVector(QStringLiteral("transform.translate"), {0.0, 0.0, -5.0});
    spin(QStringLiteral("transform.rotate"), QStringLiteral("x"))->setValue(90.0); // a back wall facing +Z

    trigger("addReflectorSphere");
    EXPECT_EQ(selected()->name(), "Chrome sphere");
    setVector(QStringLiteral("transform.translate"), {1.0, -0.6, -3.0});

    trigger("addPointLight");
    EXPECT_EQ(selected()->name(), "Point light");
    setVector(QStringLiteral("transform.translate"), {0.0, 2.0, -2.0});
    EXPECT_EQ(undo.undoText().toStdString(), "Change Translate of \u201cPoint light\u201d");
    EXPECT_TRUE(m_window->action(QStringLiteral("actionUndo"))->text().contains(undo.undoText()));

    // Scene tree shows them all (camera row first), with the kinds' names.
    ui::SceneTreeModel& tree = m_window->sceneTreeModel();
    ASSERT_EQ(tree.rowCount(), 8);
    EXPECT_EQ(tree.index(1, 0).data().toString(), QStringLiteral("Floor"));
    EXPECT_EQ(tree.index(3, 0).data().toString(), QStringLiteral("Teapot"));
    EXPECT_EQ(tree.index(7, 0).data().toString(), QStringLiteral("Point light"));

    const speculum::scene::SceneData built = m_window->scene().toData();
    ASSERT_EQ(built.nodes.size(), 7u);
    EXPECT_EQ(built.nodes[3].data.mirror->size, glm::dvec2(4.0, 4.0));
    EXPECT_DOUBLE_EQ(built.nodes[3].data.mirror->reflectivity, 0.6);
    EXPECT_DOUBLE_EQ(built.nodes[4].data.transform.rotate.x, 90.0);
    EXPECT_TRUE(built.nodes[5].data.reflector);
    EXPECT_TRUE(built.nodes[6].data.light);
    EXPECT_TRUE(m_window->isWindowModified());

    // Undo everything: the new scene again; redo everything: the same scene.
    const int steps = undo.count();
    EXPECT_GE(steps, 10);
    while (undo.canUndo()) {
        undo.undo();
    }
    EXPECT_TRUE(m_window->scene().toData() == fresh);
    EXPECT_EQ(tree.rowCount(), 3);
    EXPECT_FALSE(m_window->isWindowModified());
    while (undo.canRedo()) {
        undo.redo();
    }
    EXPECT_TRUE(m_window->scene().toData() == built);
    EXPECT_EQ(tree.rowCount(), 8);
    ASSERT_TRUE(waitForFrames(*m_window));

    // Save, start afresh, reopen: the same scene, seen from where the editor looked when it was saved
    // (the file's editorView), while the scene camera stays what `speculum render` draws.
    m_window->viewport().placeView({3.0, 4.0, 5.0}, {0.0, 0.5, -3.0});
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("built.speculum.json"));
    ASSERT_TRUE(m_window->saveProjectFile(path).ok());
    EXPECT_FALSE(m_window->isWindowModified());
    EXPECT_EQ(m_window->recentFiles().value(0), path);
    speculum::scene::SceneData saved = built;
    saved.editorView = speculum::scene::EditorView{{3.0, 4.0, 5.0}, {0.0, 0.5, -3.0}};
    m_window->newProject();
    EXPECT_TRUE(m_window->scene().toData() == fresh);
    EXPECT_NE(m_window->viewport().viewCamera().position, glm::dvec3(3.0, 4.0, 5.0));
    ASSERT_TRUE(m_window->openProjectFile(path).ok());
    EXPECT_TRUE(m_window->scene().toData() == saved);
    EXPECT_TRUE(m_window->scene().camera() == built.camera) << "the scene camera is not the editor view";
    const auto [position, target] = m_window->viewport().viewPositionTarget();
    EXPECT_LT(glm::length(position - glm::dvec3(3.0, 4.0, 5.0)), 1e-9) << "reopened where it was saved";
    EXPECT_LT(glm::length(target - glm::dvec3(0.0, 0.5, -3.0)), 1e-9);
    EXPECT_EQ(m_window->windowHandle()->title(), QStringLiteral("built.speculum.json — speculum"));
}

TEST_F(EditorWorkflow, ASliderDragIsOneUndoStepAndInvalidValuesAreRefusedVisibly) {
    m_window->newProject();
    trigger("addMirror");
    const NodeId mirror = selected()->id();
    QUndoStack& undo = m_window->undoStack();
    const int before = undo.count();

    auto* slider = m_window->inspector()
                       .editor(QStringLiteral("mirror.reflectivity"))
                       ->findChild<QSlider*>(QStringLiteral("mirror.reflectivity.slider"));
    ASSERT_NE(slider, nullptr);
    slider->setSliderDown(true); // press
    for (int v : {100, 200, 300, 400}) {
        slider->setValue(v);
    }
    slider->setSliderDown(false);
    EXPECT_EQ(undo.count(), before + 1) << "one drag, one step";
    EXPECT_NEAR(m_window->scene().findNode(mirror)->data().mirror->reflectivity, 0.4, 1e-9);
    EXPECT_EQ(undo.undoText().toStdString(), "Change Reflectivity of \u201cMirror\u201d");

    // A second drag is a second step.
    slider->setSliderDown(true);
    slider->setValue(500);
    slider->setSliderDown(false);
    EXPECT_EQ(undo.count(), before + 2);

    // Out of range: refused with a message, nothing changes, nothing is clamped.
    spin(QStringLiteral("mirror.reflectivity"))->setValue(2.0);
    const QString error = m_window->inspector().errorText();
    EXPECT_TRUE(error.contains(QStringLiteral("Reflectivity must be in 0..1, got 2"))) << error.toStdString();
    EXPECT_TRUE(m_window->inspector().findChild<QLabel*>(QStringLiteral("inspectorError"))->isVisible());
    EXPECT_NEAR(m_window->scene().findNode(mirror)->data().mirror->reflectivity, 0.5, 1e-9);
    EXPECT_EQ(undo.count(), before + 2);
    spin(QStringLiteral("mirror.size"), QStringLiteral("x"))->setValue(-1.0);
    EXPECT_TRUE(m_window->inspector().errorText().contains(QStringLiteral("greater than 0")));
    EXPECT_EQ(m_window->scene().findNode(mirror)->data().mirror->size.x, 2.0);

    // A valid value clears the message.
    spin(QStringLiteral("mirror.reflectivity"))->setValue(0.75);
    EXPECT_TRUE(m_window->inspector().errorText().isEmpty());
    EXPECT_NEAR(m_window->scene().findNode(mirror)->data().mirror->reflectivity, 0.75, 1e-9);

    // The inspector follows undo.
    undo.undo();
    EXPECT_NEAR(spin(QStringLiteral("mirror.reflectivity"))->value(), 0.5, 1e-9);
}

TEST_F(EditorWorkflow, SceneTreeRenamesReparentsDeletesAndDuplicatesUndoably) {
    openTeapot();
    ui::SceneTreeModel& tree = m_window->sceneTreeModel();
    QUndoStack& undo = m_window->undoStack();
    const NodeId teapot = *nodeNamed("Teapot");
    const NodeId light = *nodeNamed("Light");

    // Rename in place.
    ASSERT_TRUE(tree.setData(tree.indexOf(teapot), QStringLiteral("Pot")));
    EXPECT_EQ(m_window->scene().findNode(teapot)->name(), "Pot");
    EXPECT_EQ(undo.undoText().toStdString(), "Rename \u201cTeapot\u201d to \u201cPot\u201d");
    EXPECT_FALSE(tree.setData(tree.indexOf(teapot), QString())) << "an empty name is refused";
    undo.undo();
    EXPECT_EQ(tree.indexOf(teapot).data().toString(), QStringLiteral("Teapot"));

    // Drag the light onto the teapot: it becomes its child.
    std::unique_ptr<QMimeData> mime(tree.mimeData({tree.indexOf(light)}));
    ASSERT_TRUE(tree.canDropMimeData(mime.get(), Qt::MoveAction, -1, 0, tree.indexOf(teapot)));
    tree.dropMimeData(mime.get(), Qt::MoveAction, -1, 0, tree.indexOf(teapot));
    EXPECT_EQ(m_window->scene().parentOf(light), teapot);
    EXPECT_EQ(tree.indexOf(light).parent(), tree.indexOf(teapot));
    EXPECT_EQ(undo.undoText().toStdString(), "Move \u201cLight\u201d");
    // Not into its own subtree.
    std::unique_ptr<QMimeData> up(tree.mimeData({tree.indexOf(teapot)}));
    EXPECT_FALSE(tree.canDropMimeData(up.get(), Qt::MoveAction, -1, 0, tree.indexOf(light)));
    undo.undo();
    EXPECT_EQ(m_window->scene().parentOf(light), speculum::scene::kNoNode);
    EXPECT_EQ(tree.rowCount(), 4);

    // Delete and duplicate through the Edit menu.
    m_window->selection().selectNode(light);
    trigger("actionDelete");
    QCoreApplication::processEvents(); // the selection lets go of removed nodes once the command is done
    EXPECT_FALSE(m_window->scene().findNode(light));
    EXPECT_EQ(tree.rowCount(), 3);
    EXPECT_TRUE(m_window->selection().isEmpty());
    undo.undo();
    EXPECT_TRUE(m_window->scene().findNode(light)) << "the same node comes back";
    EXPECT_TRUE(tree.indexOf(light).isValid());

    m_window->selection().selectNode(teapot);
    trigger("actionDuplicate");
    ASSERT_TRUE(selected());
    EXPECT_EQ(selected()->name(), "Teapot 2");
    EXPECT_EQ(m_window->scene().indexOf(selected()->id()), m_window->scene().indexOf(teapot) + 1);
    EXPECT_EQ(undo.undoText().toStdString(), "Duplicate \u201cTeapot\u201d");
    EXPECT_EQ(tree.rowCount(), 5);

    // The tree's selection follows the shared selection.
    auto* view = m_window->sceneTree().findChild<QTreeView*>(QStringLiteral("sceneTree"));
    ASSERT_NE(view, nullptr);
    EXPECT_EQ(tree.nodeId(view->currentIndex()), selected()->id());
}

TEST_F(EditorWorkflow, ClickSelectsThroughMirrorsAndHandlesMoveWithOneUndoStep) {
    openTeapot();
    ui::Viewport& viewport = m_window->viewport();
    const NodeId teapot = *nodeNamed("Teapot");
    const NodeId table = *nodeNamed("Table");
    ASSERT_TRUE(m_window->scene().findNode(table)->data().mirror) << "the demo's table is a mirror";

    // The teapot's body.
    const glm::dvec3 body(0.0, -1.0 + 1.0 * 0.25, -3.0);
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, onScreen(body));
    EXPECT_EQ(m_window->selection().node(), teapot);

    // Its reflection in the table (the mirror image of the body below the table plane y = -1).
    const glm::dvec3 reflection(0.0, -1.0 - 1.0 * 0.25, -3.0);
    m_window->selection().clear();
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, onScreen(reflection));
    EXPECT_EQ(m_window->selection().node(), teapot) << "clicking a reflection selects the real object";
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::AltModifier, onScreen(reflection));
    EXPECT_EQ(m_window->selection().node(), table) << "Alt+click selects the mirror itself";

    // The sky: nothing.
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, QPoint(viewport.width() / 2, 5));
    EXPECT_TRUE(m_window->selection().isEmpty());

    // Drag the teapot's X handle to the right: it moves along +X, as one undo step.
    m_window->selection().selectNode(teapot);
    viewport.setHandleMode(ui::HandleMode::Move);
    ASSERT_TRUE(waitForFrames(*m_window));
    const auto handle = viewport.handlePoint(0);
    ASSERT_TRUE(handle);
    const int before = m_window->undoStack().count();
    const double x0 = m_window->scene().findNode(teapot)->data().transform.translate.x;
    const QPoint start = handle->toPoint();
    QTest::mousePress(&viewport, Qt::LeftButton, Qt::NoModifier, start);
    for (int dx = 10; dx <= 60; dx += 10) {
        QMouseEvent move(QEvent::MouseMove, QPointF(start + QPoint(dx, 0)),
                         viewport.mapToGlobal(QPointF(start + QPoint(dx, 0))), Qt::NoButton, Qt::LeftButton,
                         Qt::NoModifier);
        QCoreApplication::sendEvent(&viewport, &move);
    }
    QTest::mouseRelease(&viewport, Qt::LeftButton, Qt::NoModifier, start + QPoint(60, 0));
    const auto& moved = m_window->scene().findNode(teapot)->data().transform;
    EXPECT_GT(moved.translate.x, x0 + 0.1);
    EXPECT_NEAR(moved.translate.y, -1.0, 1e-9) << "only along X";
    EXPECT_EQ(m_window->undoStack().count(), before + 1);
    EXPECT_EQ(m_window->undoStack().undoText().toStdString(), "Move \u201cTeapot\u201d");
    m_window->undoStack().undo();
    EXPECT_DOUBLE_EQ(m_window->scene().findNode(teapot)->data().transform.translate.x, x0);

    // Rotate and scale handles exist too.
    viewport.setHandleMode(ui::HandleMode::Scale);
    EXPECT_TRUE(viewport.handlePoint(1));
    viewport.setHandleMode(ui::HandleMode::Rotate);
    EXPECT_TRUE(viewport.handlePoint(2));
    viewport.setHandleMode(ui::HandleMode::Select);
    EXPECT_FALSE(viewport.handlePoint(0));
}

TEST_F(EditorWorkflow, CtrlClickInTheTreeSelectsSeveralNodesThatDeleteAndDuplicateAsOneStep) {
    openTeapot();
    ui::SceneTreeModel& tree = m_window->sceneTreeModel();
    view::Selection& selection = m_window->selection();
    QUndoStack& undo = m_window->undoStack();
    const NodeId teapot = *nodeNamed("Teapot");
    const NodeId table = *nodeNamed("Table");
    const NodeId light = *nodeNamed("Light");

    clickRow(tree.indexOf(teapot));
    clickRow(tree.indexOf(light), Qt::ControlModifier);
    EXPECT_EQ(selection.nodes(), (Ids{teapot, light}));
    EXPECT_EQ(selection.node(), light) << "the last one clicked is current";
    EXPECT_NE(m_window->inspector().editor(QStringLiteral("light.intensity")), nullptr)
        << "the inspector shows the current node";
    // Ctrl+click again takes a node out; Shift+click selects a range.
    clickRow(tree.indexOf(teapot), Qt::ControlModifier);
    EXPECT_EQ(selection.nodes(), Ids{light});
    clickRow(tree.indexOf(light));
    clickRow(tree.indexOf(teapot), Qt::ShiftModifier); // Teapot, Table, Light
    EXPECT_EQ(selection.nodes().size(), 3u);
    EXPECT_EQ(selection.node(), teapot);

    // The camera row is selected alone, and left out when nodes are added to it.
    clickRow(tree.cameraIndex(), Qt::ControlModifier);
    EXPECT_TRUE(selection.isCamera());
    EXPECT_EQ(treeView()->selectionModel()->selectedIndexes().size(), 1);
    clickRow(tree.indexOf(table), Qt::ControlModifier);
    EXPECT_FALSE(selection.isCamera());
    EXPECT_EQ(selection.nodes(), Ids{table});
    EXPECT_EQ(treeSelection(), Ids{table});

    // The tree follows a selection made elsewhere.
    selection.setNodes({teapot, light}, teapot);
    EXPECT_EQ(treeSelection(), (Ids{teapot, light}));
    EXPECT_EQ(tree.nodeId(treeView()->currentIndex()), teapot);

    // Delete both: one undo step; one undo brings both back.
    const int steps = undo.count();
    trigger("actionDelete");
    QCoreApplication::processEvents(); // the selection lets go of removed nodes once the command is done
    EXPECT_FALSE(m_window->scene().findNode(teapot));
    EXPECT_FALSE(m_window->scene().findNode(light));
    EXPECT_EQ(tree.rowCount(), 2);
    EXPECT_TRUE(selection.isEmpty());
    EXPECT_EQ(undo.count(), steps + 1);
    EXPECT_EQ(undo.undoText().toStdString(), "Delete 2 nodes");
    undo.undo();
    EXPECT_TRUE(m_window->scene().findNode(teapot));
    EXPECT_TRUE(m_window->scene().findNode(light));
    EXPECT_EQ(m_window->scene().indexOf(teapot), 0);
    EXPECT_EQ(m_window->scene().indexOf(light), 2);
    EXPECT_EQ(tree.rowCount(), 4);

    // Duplicate both: the copies are selected, right after their originals; one step to undo and redo.
    selection.setNodes({teapot, light}, teapot);
    trigger("actionDuplicate");
    EXPECT_EQ(undo.undoText().toStdString(), "Duplicate 2 nodes");
    EXPECT_EQ(undo.count(), steps + 1);
    const Ids copies = selection.nodes();
    ASSERT_EQ(copies.size(), 2u);
    EXPECT_EQ(m_window->scene().findNode(copies[0])->name(), "Light 2");
    EXPECT_EQ(m_window->scene().findNode(copies[1])->name(), "Teapot 2");
    EXPECT_EQ(selection.node(), copies[1]) << "the copy of the current node is current";
    EXPECT_EQ(m_window->scene().indexOf(copies[1]), m_window->scene().indexOf(teapot) + 1);
    EXPECT_EQ(m_window->scene().indexOf(copies[0]), m_window->scene().indexOf(light) + 1);
    EXPECT_EQ(tree.rowCount(), 6);
    EXPECT_EQ(treeSelection().size(), 2u);
    undo.undo();
    QCoreApplication::processEvents();
    EXPECT_FALSE(m_window->scene().findNode(copies[0]));
    EXPECT_FALSE(m_window->scene().findNode(copies[1]));
    EXPECT_TRUE(selection.isEmpty());
    EXPECT_EQ(tree.rowCount(), 4);
    undo.redo();
    EXPECT_TRUE(m_window->scene().findNode(copies[0]) && m_window->scene().findNode(copies[1]));
    EXPECT_EQ(tree.rowCount(), 6);
    undo.undo();

    // A node under a selected ancestor goes with the ancestor: one delete, not two.
    undo.push(new document::MoveNodeCommand(m_window->scene(), light, teapot, 0));
    selection.setNodes({light, teapot});
    trigger("actionDelete");
    EXPECT_EQ(undo.undoText().toStdString(), "Delete \u201cTeapot\u201d");
    EXPECT_FALSE(m_window->scene().findNode(light));
    undo.undo();
    EXPECT_EQ(m_window->scene().parentOf(light), teapot);

    // Dragging several rows: refused onto a dragged node or into one's subtree.
    const Layout beforeDrags = layout();
    std::unique_ptr<QMimeData> potAndTable(tree.mimeData({tree.indexOf(table), tree.indexOf(teapot)}));
    EXPECT_FALSE(tree.canDropMimeData(potAndTable.get(), Qt::MoveAction, -1, 0, tree.indexOf(light)));
    EXPECT_FALSE(tree.canDropMimeData(potAndTable.get(), Qt::MoveAction, -1, 0, tree.indexOf(table)));
    EXPECT_FALSE(tree.dropMimeData(potAndTable.get(), Qt::MoveAction, -1, 0, tree.indexOf(light)));
    EXPECT_EQ(layout(), beforeDrags);
    EXPECT_TRUE(tree.canDropMimeData(potAndTable.get(), Qt::MoveAction, 3, 0, {}));
    // A node under a dragged ancestor goes with it: one node moves, with the single-node text.
    std::unique_ptr<QMimeData> potAndLight(tree.mimeData({tree.indexOf(light), tree.indexOf(teapot)}));
    ASSERT_TRUE(tree.dropMimeData(potAndLight.get(), Qt::MoveAction, 3, 0, {})); // after the table
    EXPECT_EQ(m_window->scene().indexOf(table), 0);
    EXPECT_EQ(m_window->scene().indexOf(teapot), 1);
    EXPECT_EQ(m_window->scene().parentOf(light), teapot);
    EXPECT_EQ(undo.undoText().toStdString(), "Move \u201cTeapot\u201d");
    undo.undo();
    EXPECT_EQ(layout(), beforeDrags);
    undo.undo(); // the light back to the top level: Teapot, Table, Light
    const Layout flat = layout();

    // Two nodes onto a third: its children, in tree order whatever the order of the dragged rows, as one
    // undo step; they stay selected.
    selection.setNodes({light, table});
    const int dragSteps = undo.index();
    std::unique_ptr<QMimeData> tableAndLight(tree.mimeData({tree.indexOf(light), tree.indexOf(table)}));
    ASSERT_TRUE(tree.canDropMimeData(tableAndLight.get(), Qt::MoveAction, -1, 0, tree.indexOf(teapot)));
    ASSERT_TRUE(tree.dropMimeData(tableAndLight.get(), Qt::MoveAction, -1, 0, tree.indexOf(teapot)));
    const Layout underPot = layout();
    EXPECT_EQ(m_window->scene().parentOf(table), teapot);
    EXPECT_EQ(m_window->scene().parentOf(light), teapot);
    EXPECT_EQ(m_window->scene().indexOf(table), 0);
    EXPECT_EQ(m_window->scene().indexOf(light), 1);
    EXPECT_EQ(tree.rowCount(), 2);
    EXPECT_EQ(undo.index(), dragSteps + 1);
    EXPECT_EQ(undo.undoText().toStdString(), "Move 2 nodes");
    QCoreApplication::processEvents(); // the selection lets go of nodes still gone after a command
    EXPECT_EQ(selection.nodes(), (Ids{light, table}));
    EXPECT_EQ(treeSelection(), (Ids{table, light}));
    undo.undo();
    EXPECT_EQ(layout(), flat) << "one undo puts both back exactly";
    undo.redo();
    EXPECT_EQ(layout(), underPot);
    undo.undo();

    // Two nodes onto the top level at a row: together there, in tree order. Taking the teapot out from above
    // the drop row shifts the rows after it.
    std::unique_ptr<QMimeData> potAndLight2(tree.mimeData({tree.indexOf(light), tree.indexOf(teapot)}));
    ASSERT_TRUE(tree.dropMimeData(potAndLight2.get(), Qt::MoveAction, 3, 0, {})); // before the light
    EXPECT_EQ(layout(), (Layout{{table, speculum::scene::kNoNode, 0},
                                {teapot, speculum::scene::kNoNode, 1},
                                {light, speculum::scene::kNoNode, 2}}));
    EXPECT_EQ(undo.undoText().toStdString(), "Move 2 nodes");
    undo.undo();
    EXPECT_EQ(layout(), flat);
    std::unique_ptr<QMimeData> lightAndTable(tree.mimeData({tree.indexOf(light), tree.indexOf(table)}));
    ASSERT_TRUE(tree.dropMimeData(lightAndTable.get(), Qt::MoveAction, 1, 0, {})); // at the top
    EXPECT_EQ(layout(), (Layout{{table, speculum::scene::kNoNode, 0},
                                {light, speculum::scene::kNoNode, 1},
                                {teapot, speculum::scene::kNoNode, 2}}));
    undo.undo();
    EXPECT_EQ(layout(), flat);
    ASSERT_TRUE(tree.dropMimeData(potAndTable.get(), Qt::MoveAction, 4, 0, {})); // at the end
    const Layout atEnd{{light, speculum::scene::kNoNode, 0},
                       {teapot, speculum::scene::kNoNode, 1},
                       {table, speculum::scene::kNoNode, 2}};
    EXPECT_EQ(layout(), atEnd);
    undo.undo();
    EXPECT_EQ(layout(), flat);
    undo.redo();
    EXPECT_EQ(layout(), atEnd);
    undo.undo();
    // Dropped where they already are: nothing changes, and no empty undo step (the redo stays).
    EXPECT_FALSE(tree.dropMimeData(potAndTable.get(), Qt::MoveAction, 1, 0, {}));
    EXPECT_EQ(layout(), flat);
    EXPECT_EQ(undo.index(), dragSteps);
    EXPECT_TRUE(undo.canRedo());

    // Select All: every node, children too.
    trigger("actionSelectAll");
    EXPECT_EQ(selection.nodes().size(), 3u);
    EXPECT_EQ(treeSelection().size(), 3u);
    // Ctrl+A in the tree too, from the camera row: the nodes, without the camera.
    selection.selectCamera();
    treeView()->setFocus();
    QTest::keyClick(treeView(), Qt::Key_A, Qt::ControlModifier);
    EXPECT_FALSE(selection.isCamera());
    EXPECT_EQ(selection.nodes().size(), 3u);
}

TEST_F(EditorWorkflow, CtrlClickInTheViewportAddsAndRemovesAndHandleDragsActOnTheWholeSelection) {
    openTeapot();
    ui::Viewport& viewport = m_window->viewport();
    view::Selection& selection = m_window->selection();
    const NodeId teapot = *nodeNamed("Teapot");
    const NodeId table = *nodeNamed("Table");
    const NodeId light = *nodeNamed("Light");
    const glm::dvec3 body(0.0, -1.0 + 1.0 * 0.25, -3.0);
    const glm::dvec3 reflection(0.0, -1.0 - 1.0 * 0.25, -3.0);
    const glm::dvec3 lamp(
        speculum::scene::worldMatrices(m_window->scene(), viewport.lastFrameTime()).at(light)[3]);

    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, onScreen(body));
    EXPECT_EQ(selection.nodes(), Ids{teapot});
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::ControlModifier, onScreen(lamp));
    EXPECT_EQ(selection.nodes(), (Ids{teapot, light}));
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::ControlModifier | Qt::AltModifier, onScreen(reflection));
    EXPECT_EQ(selection.nodes(), (Ids{teapot, light, table})) << "Ctrl+Alt+click adds the mirror itself";
    EXPECT_EQ(selection.node(), table);
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::ControlModifier, onScreen(body));
    EXPECT_EQ(selection.nodes(), (Ids{light, table})) << "Ctrl+click on a selected node takes it out";
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::ControlModifier, QPoint(viewport.width() / 2, 5));
    EXPECT_EQ(selection.nodes(), (Ids{light, table})) << "Ctrl+click on nothing keeps the selection";
    ASSERT_TRUE(waitForFrames(*m_window)); // outlines of both drawn without trouble

    // Handles sit on the current node; dragging them acts on the whole selection, as one undo step.
    selection.setNodes({table, teapot}, teapot);
    viewport.setHandleMode(ui::HandleMode::Move);
    ASSERT_TRUE(waitForFrames(*m_window));
    // For a person to look at: both outlined (the teapot brighter), both rows selected, handles on the
    // teapot.
    EXPECT_TRUE(
        m_window->grab().save(QString::fromStdString(speculum::testDataPath("editor-multiselect.png"))));
    auto transformOf = [&](NodeId id) { return m_window->scene().findNode(id)->data().transform; };
    // Drags from a handle point to the right in several mouse moves.
    auto dragRight = [&](QPointF handle, int pixels) {
        const QPoint start = handle.toPoint();
        QTest::mousePress(&viewport, Qt::LeftButton, Qt::NoModifier, start);
        for (int dx = 10; dx <= pixels; dx += 10) {
            QMouseEvent move(QEvent::MouseMove, QPointF(start + QPoint(dx, 0)),
                             viewport.mapToGlobal(QPointF(start + QPoint(dx, 0))), Qt::NoButton,
                             Qt::LeftButton, Qt::NoModifier);
            QCoreApplication::sendEvent(&viewport, &move);
        }
        QTest::mouseRelease(&viewport, Qt::LeftButton, Qt::NoModifier, start + QPoint(pixels, 0));
    };
    const speculum::scene::Transform teapot0 = transformOf(teapot), table0 = transformOf(table);
    const int steps = m_window->undoStack().count();

    // Move: both by the same world displacement (both are top-level nodes, so also the same translate
    // change).
    auto handle = viewport.handlePoint(0);
    ASSERT_TRUE(handle);
    dragRight(*handle, 40);
    const glm::dvec3 teapotMoved = transformOf(teapot).translate - teapot0.translate;
    const glm::dvec3 tableMoved = transformOf(table).translate - table0.translate;
    EXPECT_GT(teapotMoved.x, 0.05);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(tableMoved[i], teapotMoved[i], 1e-9) << "axis " << i;
    }
    EXPECT_EQ(selection.nodes(), (Ids{table, teapot})) << "a handle drag keeps the selection";
    EXPECT_EQ(m_window->undoStack().count(), steps + 1) << "the whole drag is one step";
    EXPECT_EQ(m_window->undoStack().undoText().toStdString(), "Move 2 nodes");
    m_window->undoStack().undo();
    EXPECT_EQ(transformOf(teapot), teapot0);
    EXPECT_EQ(transformOf(table), table0);
    m_window->undoStack().redo();
    EXPECT_NEAR(transformOf(teapot).translate.x, teapot0.translate.x + teapotMoved.x, 1e-12);
    EXPECT_NEAR(transformOf(table).translate.x, table0.translate.x + tableMoved.x, 1e-12);
    m_window->undoStack().undo();

    // Rotate: both turn by the same Euler-angle change, each about its own origin (translates unchanged).
    viewport.setHandleMode(ui::HandleMode::Rotate);
    ASSERT_TRUE(waitForFrames(*m_window));
    handle = viewport.handlePoint(2);
    ASSERT_TRUE(handle);
    dragRight(*handle, 40);
    const glm::dvec3 teapotTurned = transformOf(teapot).rotate - teapot0.rotate;
    const glm::dvec3 tableTurned = transformOf(table).rotate - table0.rotate;
    EXPECT_GT(glm::length(teapotTurned), 1.0);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(tableTurned[i], teapotTurned[i], 1e-9) << "axis " << i;
    }
    EXPECT_EQ(transformOf(table).translate, table0.translate);
    EXPECT_EQ(m_window->undoStack().count(), steps + 1);
    EXPECT_EQ(m_window->undoStack().undoText().toStdString(), "Rotate 2 nodes");
    m_window->undoStack().undo();
    EXPECT_EQ(transformOf(teapot), teapot0);
    EXPECT_EQ(transformOf(table), table0);

    // Scale: each axis of both multiplied by the same factor (the teapot starts at 0.25, the table at 1).
    viewport.setHandleMode(ui::HandleMode::Scale);
    ASSERT_TRUE(waitForFrames(*m_window));
    handle = viewport.handlePoint(0);
    ASSERT_TRUE(handle);
    dragRight(*handle, 40);
    const glm::dvec3 teapotFactor = transformOf(teapot).scale / teapot0.scale;
    const glm::dvec3 tableFactor = transformOf(table).scale / table0.scale;
    EXPECT_GT(std::max({teapotFactor.x, teapotFactor.y, teapotFactor.z}), 1.05);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(tableFactor[i], teapotFactor[i], 1e-9) << "axis " << i;
    }
    EXPECT_EQ(m_window->undoStack().undoText().toStdString(), "Scale 2 nodes");
    m_window->undoStack().undo();
    EXPECT_EQ(transformOf(teapot), teapot0);
    EXPECT_EQ(transformOf(table), table0);
    EXPECT_EQ(m_window->undoStack().count(), steps + 1) << "undone steps stay redoable";

    // Esc during a drag puts every node back.
    viewport.setHandleMode(ui::HandleMode::Move);
    ASSERT_TRUE(waitForFrames(*m_window));
    handle = viewport.handlePoint(0);
    ASSERT_TRUE(handle);
    QTest::mousePress(&viewport, Qt::LeftButton, Qt::NoModifier, handle->toPoint());
    QMouseEvent move(QEvent::MouseMove, *handle + QPointF(30, 0),
                     viewport.mapToGlobal(*handle + QPointF(30, 0)), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QCoreApplication::sendEvent(&viewport, &move);
    EXPECT_NE(transformOf(table), table0);
    QTest::keyClick(&viewport, Qt::Key_Escape);
    QTest::mouseRelease(&viewport, Qt::LeftButton, Qt::NoModifier, (*handle + QPointF(30, 0)).toPoint());
    EXPECT_EQ(transformOf(teapot), teapot0);
    EXPECT_EQ(transformOf(table), table0);

    // Plain click selects only what is under the cursor; on nothing, nothing.
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, onScreen(lamp));
    EXPECT_EQ(selection.nodes(), Ids{light});
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, QPoint(viewport.width() / 2, 5));
    EXPECT_TRUE(selection.isEmpty());
}

// A model in parts: a click selects the model (the top of the hierarchy), a second click the part under
// the mouse, as Blender, Godot and Unity pick the object before its pieces.
TEST_F(EditorWorkflow, AClickSelectsTheModelFirstAndASecondClickThePart) {
    QTemporaryDir dir;
    const QString path =
        writeFileIn(dir, QStringLiteral("parts.speculum.json"), R"({"format": "speculum-scene", "version": 1,
          "camera": {"position": [0, 1, 5], "target": [0, 0.5, 0], "up": [0, 1, 0], "fovY": 50, "near": 0.1,
                     "far": 50},
          "nodes": [{"name": "Model", "children": [
            {"name": "Body", "transform": {"translate": [0, 0.5, 0], "scale": [0.5, 0.5, 0.5]}, "children": [
              {"name": "Knob", "transform": {"translate": [0, 2.6, 0], "scale": [0.3, 0.3, 0.3]},
               "mesh": {"builtin": "sphere"}}],
             "mesh": {"builtin": "box"}}]}]})");
    ASSERT_FALSE(path.isEmpty());
    ASSERT_TRUE(m_window->openProjectFile(path).ok());
    ASSERT_TRUE(waitForFrames(*m_window));
    ui::Viewport& viewport = m_window->viewport();
    auto named = [&](const std::string& name) {
        NodeId found = scene::kNoNode;
        m_window->scene().forEachNode([&](const scene::Node& n) {
            if (n.name() == name) {
                found = n.id();
            }
        });
        return found;
    };
    auto click = [&](glm::dvec3 at) {
        QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, onScreen(at));
        return m_window->selection().node();
    };
    const glm::dvec3 knob(0.0, 1.8, 0.0), body(0.2, 0.5, 0.5); // the knob stands on the body
    EXPECT_EQ(click(knob), named("Model")) << "the model first";
    EXPECT_EQ(click(knob), named("Body")) << "then one level deeper";
    EXPECT_EQ(click(knob), named("Knob")) << "down to the part under the mouse";
    EXPECT_EQ(click(knob), named("Knob")) << "and there it stays";
    EXPECT_EQ(click(body), named("Model")) << "another part: the model again";
    EXPECT_EQ(click(body), named("Body"));
    QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, QPoint(5, 5)); // the sky
    EXPECT_EQ(click(body), named("Model")) << "from nothing selected, the model again";
}

// H hides the selection, Alt+H shows everything again, the tick in the scene tree hides or shows one node:
// each one undo step, and a hidden node leaves the viewport's frame.
TEST_F(EditorWorkflow, HideAndShowFromTheKeysAndTheTree) {
    openTeapot();
    scene::Scene& scene = m_window->scene();
    NodeId teapot = scene::kNoNode;
    scene.forEachNode([&](const scene::Node& n) {
        if (n.name() == "Teapot") {
            teapot = n.id();
        }
    });
    ASSERT_NE(teapot, scene::kNoNode);
    auto drawnItems = [&] {
        ui::Viewport& viewport = m_window->viewport();
        const int before = viewport.framesRendered();
        viewport.update();
        EXPECT_TRUE(waitFor([&] { return viewport.framesRendered() > before; }, 30000));
        return viewport.lastReport().plan.passes.front().details.objects;
    };
    const std::size_t all = drawnItems();
    m_window->selection().selectNode(teapot);
    const int steps = m_window->undoStack().count();
    trigger("actionHideSelected");
    EXPECT_TRUE(scene.findNode(teapot)->data().hidden);
    EXPECT_EQ(m_window->undoStack().undoText(), QStringLiteral("Hide “Teapot”"));
    EXPECT_LT(drawnItems(), all) << "not drawn";
    ui::SceneTreeModel& tree = m_window->sceneTreeModel();
    const QModelIndex row = tree.indexOf(teapot);
    EXPECT_EQ(tree.data(row, Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
    trigger("actionShowAll");
    EXPECT_FALSE(scene.findNode(teapot)->data().hidden);
    EXPECT_EQ(drawnItems(), all);
    ASSERT_TRUE(tree.setData(row, Qt::Unchecked, Qt::CheckStateRole)) << "the tick hides it";
    EXPECT_TRUE(scene.findNode(teapot)->data().hidden);
    EXPECT_EQ(m_window->undoStack().count(), steps + 3);
    m_window->undoStack().undo();
    EXPECT_FALSE(scene.findNode(teapot)->data().hidden);
}

// Copy and paste through the clipboard, the viewport's right-click menu, and the undo history, as a
// Blender user reaches for them.
TEST_F(EditorWorkflow, CopyPasteTheRightClickMenuAndTheUndoHistory) {
    openTeapot();
    scene::Scene& scene = m_window->scene();
    NodeId teapot = scene::kNoNode;
    scene.forEachNode([&](const scene::Node& n) {
        if (n.data().mesh && teapot == scene::kNoNode) {
            teapot = n.id();
        }
    });
    ASSERT_NE(teapot, scene::kNoNode);
    const std::string name = scene.findNode(teapot)->name();
    m_window->selection().selectNode(teapot);
    const int steps = m_window->undoStack().count();
    trigger("actionCopy");
    EXPECT_EQ(m_window->undoStack().count(), steps) << "copying is no edit";
    EXPECT_TRUE(
        QGuiApplication::clipboard()->mimeData()->hasFormat(QStringLiteral("application/x-speculum-nodes")));
    EXPECT_TRUE(QGuiApplication::clipboard()->text().contains(QString::fromStdString(name)));
    trigger("actionPaste");
    ASSERT_EQ(m_window->undoStack().count(), steps + 1);
    const NodeId pasted = m_window->selection().node();
    ASSERT_NE(pasted, teapot) << "the pasted copy is selected";
    EXPECT_EQ(scene.findNode(pasted)->name(), name + " 2");
    EXPECT_EQ(scene.findNode(pasted)->data().transform, scene.findNode(teapot)->data().transform);
    // Cut: copied and deleted as one step; pasting brings it back.
    trigger("actionCut");
    EXPECT_EQ(scene.findNode(pasted), nullptr);
    trigger("actionPaste");
    EXPECT_EQ(m_window->undoStack().count(), steps + 3);

    // The right-click menu holds the Add menu and the Edit commands for the selection.
    QStringList items;
    QObject::connect(m_window.get(), &MainWindow::viewportMenuShown, m_window.get(), [&](QMenu* menu) {
        for (QAction* a : menu->actions()) {
            if (!a->isSeparator()) {
                items << (a->menu() ? a->menu()->objectName() : a->objectName());
            }
        }
        QTimer::singleShot(0, menu, &QMenu::close);
    });
    ui::Viewport& viewport = m_window->viewport();
    emit viewport.customContextMenuRequested(QPoint(viewport.width() / 2, viewport.height() / 2));
    for (const char* expected : {"addMenu", "actionDuplicate", "actionCopy", "actionPaste", "actionDelete",
                                 "actionFrameSelected", "actionHandleMove"}) {
        EXPECT_TRUE(items.contains(QString::fromLatin1(expected))) << expected;
    }

    // The undo history names every step; choosing one goes back to it.
    auto* history = m_window->findChild<QUndoView*>(QStringLiteral("undoHistory"));
    ASSERT_NE(history, nullptr);
    EXPECT_EQ(history->stack(), &m_window->undoStack());
    EXPECT_EQ(history->model()->rowCount(), m_window->undoStack().count() + 1) << "and the opened state";
    history->setCurrentIndex(history->model()->index(steps, 0));
    EXPECT_EQ(m_window->undoStack().index(), steps);
    EXPECT_EQ(scene.findNode(pasted), nullptr) << "back before the paste";
}

TEST_F(EditorWorkflow, ImportsDroppedModelsAndOffersRecoveredWork) {
    m_window->newProject();
    const QString box = QStringLiteral("/usr/share/assimp/models/OBJ/box.obj");
    if (!QFile::exists(box)) {
        GTEST_SKIP() << "assimp-testmodels not installed";
    }
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(box)});
    // As Qt delivers a drag: enter (which makes the window the drop target), then drop.
    QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(m_window.get(), &enter);
    EXPECT_TRUE(enter.isAccepted()) << "model files are accepted";
    QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(m_window.get(), &drop);
    EXPECT_TRUE(m_window->isImporting()) << "the file is read on a worker";
    ASSERT_TRUE(waitFor([&] { return !m_window->isImporting(); }));
    ASSERT_EQ(m_window->scene().topLevelNodes().size(), 3u) << "the floor, the sun and the model";
    const speculum::scene::Node& root = *m_window->scene().topLevelNodes().back();
    EXPECT_EQ(root.data().name, "box");
    std::vector<std::string> files; // the parts under the model's root draw the dropped file
    m_window->scene().forEachNode([&](const speculum::scene::Node& n) {
        if (n.data().mesh && m_window->scene().isAncestor(root.id(), n.id())) {
            files.push_back(n.data().mesh->file);
        }
    });
    ASSERT_FALSE(files.empty());
    EXPECT_EQ(files.front(), box.toStdString());
    EXPECT_FALSE(
        m_window->importModelFile(QStringLiteral("/usr/share/assimp/models/invalid/empty.obj")).ok());

    // The unsaved document goes to a recovery file; a later editor restores it, marked modified.
    QTemporaryDir dir;
    m_window->setRecoveryStore(
        speculum::scene::RecoveryStore(dir.path(), 4194303 + 99)); // as if this process died
    ASSERT_TRUE(m_window->autosaveNow().ok());
    const auto data = m_window->scene().toData();
    m_window->setRecoveryStore(
        speculum::scene::RecoveryStore(dir.path(), QCoreApplication::applicationPid()));
    m_window->undoStack().setClean();
    m_window->newProject();
    const auto orphans = m_window->recoveryStore().orphans();
    ASSERT_EQ(orphans.size(), 1u);
    ASSERT_TRUE(m_window->restoreRecovery(orphans.front()).ok());
    EXPECT_TRUE(m_window->scene().toData() == data);
    EXPECT_TRUE(m_window->isModified());
    EXPECT_EQ(m_window->windowHandle()->title(), QStringLiteral("Untitled* — speculum"));
    m_window->newProject();
    EXPECT_TRUE(m_window->recoveryStore().orphans().empty());

    // glTF export through the window.
    const QString gltf = QDir(dir.path()).filePath(QStringLiteral("scene.glb"));
    ASSERT_TRUE(m_window->exportGltfFile(gltf).ok());
    EXPECT_TRUE(QFile::exists(gltf));
}

} // namespace

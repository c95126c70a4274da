// The handle-drag state machine without a widget: mouse positions in, undoable edits out. A drag is one
// undo step; Esc (cancel) puts every node back and leaves the undo stack and its clean state as they were.
#include "editor/ui/HandleDrag.hpp"

#include "editor/document/Commands.hpp"
#include "editor/ui/SnapSettings.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/model/NodeMath.hpp"
#include "scene/model/Scene.hpp"

#include <QString>
#include <QUndoStack>
#include <cmath>
#include <gtest/gtest.h>
#include <string>

namespace speculum::ui {
namespace {

using scene::NodeId;
using State = HandleDrag::State;

class HandleDragTest : public ::testing::Test {
protected:
    void SetUp() override {
        scene::SceneData data;
        scene::NodeTree a, b;
        a.data.name = "A";
        b.data.name = "B";
        b.data.transform.translate = {1.5, 0.0, -0.5};
        data.nodes = {a, b};
        data.camera.position = {0.0, 2.0, 6.0};
        data.camera.target = {0.0, 0.0, 0.0};
        scene.reset(data);
        a_ = scene.topLevelNodes()[0]->id();
        b_ = scene.topLevelNodes()[1]->id();
        // Something saved already, so the drag starts above a clean state with history below it.
        scene::NodeData first = scene.findNode(b_)->data();
        first.transform.rotate.y = 30.0;
        stack.push(new document::SetNodeDataCommand(scene, b_, first));
        stack.setClean();
        startA = scene.findNode(a_)->data();
        startB = scene.findNode(b_)->data();
    }

    // The handles on node A as the viewport draws them: a 800×600 view through the scene's camera.
    Gizmo gizmo(HandleMode mode) const {
        Gizmo g;
        const ScreenProjection projection(scene.camera(), QSizeF(800, 600));
        g.setUp(mode, projection, glm::dmat4(1.0), scene::localMatrix(scene.findNode(a_)->data().transform));
        return g;
    }
    // A point on the x handle, where a user grabs it.
    static QPointF grip(const Gizmo& g) {
        const auto& line = g.axes()[0].line;
        return line.front() + (line.back() - line.front()) * 0.9;
    }

    scene::Scene scene;
    QUndoStack stack;
    NodeId a_ = 0, b_ = 0;
    scene::NodeData startA, startB;
};

TEST_F(HandleDragTest, PressMoveReleaseIsOneUndoStep) {
    HandleDrag drag(scene, stack);
    EXPECT_EQ(drag.state(), State::Idle);
    const Gizmo g = gizmo(HandleMode::Move);
    ASSERT_TRUE(g.isValid());
    const QPointF p = grip(g);
    ASSERT_EQ(g.hitTest(p), 0);
    ASSERT_TRUE(drag.press(g, 0, p, a_, {a_, b_}, 0.0));
    EXPECT_EQ(drag.state(), State::Pressed);
    EXPECT_TRUE(drag.isActive());
    EXPECT_EQ(drag.axis(), 0);
    drag.move(p); // not moved yet
    EXPECT_EQ(drag.state(), State::Pressed);
    EXPECT_EQ(stack.count(), 1);
    for (int dx = 10; dx <= 40; dx += 10) {
        drag.move(p + QPointF(dx, 0));
    }
    EXPECT_EQ(drag.state(), State::Dragging);
    const glm::dvec3 movedA = scene.findNode(a_)->data().transform.translate - startA.transform.translate;
    const glm::dvec3 movedB = scene.findNode(b_)->data().transform.translate - startB.transform.translate;
    EXPECT_GT(movedA.x, 0.05);
    EXPECT_NEAR(movedB.x, movedA.x, 1e-12) << "the other selected node follows";
    EXPECT_EQ(stack.count(), 2) << "the whole drag is one step";
    EXPECT_EQ(stack.undoText().toStdString(), "Move 2 nodes");
    EXPECT_FALSE(stack.isClean());
    drag.release();
    EXPECT_EQ(drag.state(), State::Committed);
    EXPECT_FALSE(drag.isActive());
    stack.undo();
    EXPECT_EQ(scene.findNode(a_)->data(), startA);
    EXPECT_EQ(scene.findNode(b_)->data(), startB);
    EXPECT_TRUE(stack.isClean());
    stack.redo();
    EXPECT_NEAR(scene.findNode(a_)->data().transform.translate.x - startA.transform.translate.x, movedA.x,
                1e-12);
}

TEST_F(HandleDragTest, CancelRestoresEveryNodeAndLeavesNoStep) {
    for (HandleMode mode : {HandleMode::Move, HandleMode::Rotate, HandleMode::Scale}) {
        HandleDrag drag(scene, stack);
        const Gizmo g = gizmo(mode);
        ASSERT_TRUE(g.isValid());
        const QPointF p = mode == HandleMode::Rotate ? g.axes()[1].line[8] : grip(g);
        const int axis = mode == HandleMode::Rotate ? 1 : 0;
        ASSERT_TRUE(drag.press(g, axis, p, a_, {a_, b_}, 0.0));
        drag.move(p + QPointF(25, 15));
        drag.move(p + QPointF(40, 20));
        ASSERT_NE(scene.findNode(a_)->data(), startA) << int(mode);
        ASSERT_EQ(stack.count(), 2) << int(mode);
        drag.cancel();
        EXPECT_EQ(drag.state(), State::Cancelled) << int(mode);
        EXPECT_EQ(scene.findNode(a_)->data(), startA) << int(mode);
        EXPECT_EQ(scene.findNode(b_)->data(), startB) << int(mode);
        EXPECT_EQ(stack.count(), 1) << int(mode) << ": no step left";
        EXPECT_TRUE(stack.isClean()) << int(mode) << ": the document is not modified";
        drag.release(); // the button comes up after Esc: nothing more happens
        EXPECT_EQ(drag.state(), State::Cancelled);
        EXPECT_EQ(stack.count(), 1);
    }
}

TEST_F(HandleDragTest, APressWithoutMovingAndADragBackLeaveNoStep) {
    HandleDrag drag(scene, stack);
    const Gizmo g = gizmo(HandleMode::Move);
    const QPointF p = grip(g);
    ASSERT_TRUE(drag.press(g, 0, p, a_, {a_}, 0.0));
    drag.release();
    EXPECT_EQ(drag.state(), State::Idle) << "a press and release on a handle is nothing";
    drag.cancel();
    EXPECT_EQ(drag.state(), State::Idle) << "cancel when no drag is under way does nothing";
    EXPECT_EQ(stack.count(), 1);

    ASSERT_TRUE(drag.press(g, 0, p, a_, {a_}, 0.0));
    drag.cancel(); // Esc before the mouse moved
    EXPECT_EQ(drag.state(), State::Cancelled);
    EXPECT_EQ(stack.count(), 1);
    EXPECT_TRUE(stack.isClean());

    ASSERT_TRUE(drag.press(g, 0, p, a_, {a_}, 0.0));
    drag.move(p + QPointF(30, 0));
    drag.move(p);
    drag.release();
    EXPECT_EQ(drag.state(), State::Committed);
    EXPECT_EQ(scene.findNode(a_)->data(), startA);
    EXPECT_EQ(stack.count(), 1) << "a drag back to where it began is no step";
    EXPECT_TRUE(stack.isClean());
}

TEST_F(HandleDragTest, ARefusedPressStartsNothing) {
    HandleDrag drag(scene, stack);
    const Gizmo g = gizmo(HandleMode::Move);
    EXPECT_FALSE(drag.press(Gizmo{}, 0, grip(g), a_, {a_}, 0.0)) << "no handles";
    EXPECT_FALSE(drag.press(g, 3, grip(g), a_, {a_}, 0.0)) << "no such axis";
    EXPECT_FALSE(drag.press(g, 0, grip(g), NodeId(999), {a_}, 0.0)) << "no such node";
    EXPECT_FALSE(drag.press(g, 0, grip(g), a_, {a_, NodeId(999)}, 0.0)) << "a dragged node is gone";
    EXPECT_EQ(drag.state(), State::Idle);
    drag.move(grip(g) + QPointF(30, 0));
    EXPECT_EQ(scene.findNode(a_)->data(), startA);
    EXPECT_EQ(stack.count(), 1);
}

TEST_F(HandleDragTest, EachDragIsItsOwnStep) {
    HandleDrag drag(scene, stack);
    const Gizmo g = gizmo(HandleMode::Move);
    const QPointF p = grip(g);
    for (int i = 0; i < 2; ++i) {
        ASSERT_TRUE(drag.press(gizmo(HandleMode::Move), 0, grip(gizmo(HandleMode::Move)), a_, {a_}, 0.0));
        drag.move(grip(gizmo(HandleMode::Move)) + QPointF(20, 0));
        drag.release();
    }
    EXPECT_EQ(stack.count(), 3) << "two drags, two steps";
    // Cancelling a third drag takes back only that one.
    const scene::NodeData afterTwo = scene.findNode(a_)->data();
    ASSERT_TRUE(drag.press(g, 0, p, a_, {a_}, 0.0));
    drag.move(p + QPointF(50, 0));
    drag.cancel();
    EXPECT_EQ(scene.findNode(a_)->data(), afterTwo);
    EXPECT_EQ(stack.count(), 3);
}

} // namespace
} // namespace speculum::ui

namespace speculum::ui {
namespace {

// What a drag writes is what a pixel can mean, never the noise of the pixels' maths; Ctrl snaps it to the
// ground grid, to 15° and to scale factors in steps of 0.1.
TEST_F(HandleDragTest, DraggedValuesCarryNoNoiseAndCtrlSnapsThem) {
    const Gizmo move = gizmo(HandleMode::Move);
    const QPointF p = grip(move);
    const double grid = move.gridStep();
    ASSERT_GT(grid, 0.0);
    for (double dx : {7.0, 13.0, 29.0, 41.0}) {
        const double x = move.drag(startA, 0, p, p + QPointF(dx, 3.0)).transform.translate.x;
        EXPECT_NE(x, 0.0) << dx;
        EXPECT_NEAR(x, std::round(x / (grid * 1e-3)) * grid * 1e-3, 1e-12) << "on a thousandth of the grid";
        const double snapped =
            move.drag(startA, 0, p, p + QPointF(dx, 3.0), SnapSteps{}).transform.translate.x;
        EXPECT_NEAR(snapped, std::round(snapped / grid) * grid, 1e-12) << "on the grid's lines";
        EXPECT_NEAR(snapped, x, grid / 2 + 1e-9);
    }
    EXPECT_EQ(move.drag(startA, 0, p, p + QPointF(20.0, 0.0)).transform.translate.y,
              startA.transform.translate.y)
        << "what the drag does not change keeps its value";

    const Gizmo rotate = gizmo(HandleMode::Rotate);
    const QPointF r = rotate.axes()[1].line[rotate.axes()[1].line.size() / 4];
    const double turned = rotate.drag(startA, 1, r, r + QPointF(17.0, 9.0)).transform.rotate.y;
    EXPECT_NEAR(turned * 100.0, std::round(turned * 100.0), 1e-9) << "hundredths of a degree";
    const double snappedTurn =
        rotate.drag(startA, 1, r, r + QPointF(60.0, 40.0), SnapSteps{}).transform.rotate.y;
    EXPECT_NEAR(std::fmod(std::abs(snappedTurn), 15.0), 0.0, 1e-9) << snappedTurn;

    const Gizmo scale = gizmo(HandleMode::Scale);
    const QPointF s = grip(scale);
    const double grown = scale.drag(startA, 0, s, s + QPointF(23.0, 0.0)).transform.scale.x;
    EXPECT_EQ(grown, std::stod(QString::number(grown, 'g', 4).toStdString())) << "4 significant digits";
    const double snappedScale =
        scale.drag(startA, 0, s, s + QPointF(23.0, 0.0), SnapSteps{}).transform.scale.x;
    EXPECT_NEAR(snappedScale * 10.0, std::round(snappedScale * 10.0), 1e-9) << "a factor in steps of 0.1";
}

// Steps the user chose (View ▸ Snap Steps…) replace the defaults; a snapped value is the short decimal it
// means (3 × 0.1 is written 0.3, not 0.30000000000000004).
TEST_F(HandleDragTest, SnappedDragsUseTheChosenStepsAndWriteShortDecimals) {
    const SnapSteps steps{.move = 0.1, .rotate = 45.0, .scale = 0.25};
    const auto shortest = [](double v) { return std::stod(QString::number(v, 'g', 12).toStdString()); };
    const Gizmo move = gizmo(HandleMode::Move);
    const QPointF p = grip(move);
    for (double dx : {7.0, 13.0, 29.0, 41.0, 67.0}) {
        const double x = move.drag(startA, 0, p, p + QPointF(dx, 3.0), steps).transform.translate.x;
        EXPECT_NEAR(x * 10.0, std::round(x * 10.0), 1e-9) << "on the 0.1 lines";
        EXPECT_EQ(x, shortest(x)) << x;
    }
    const Gizmo rotate = gizmo(HandleMode::Rotate);
    const QPointF r = rotate.axes()[1].line[rotate.axes()[1].line.size() / 4];
    for (QPointF d : {QPointF(60.0, 40.0), QPointF(-90.0, 20.0), QPointF(5.0, 5.0)}) {
        const double turn = rotate.drag(startA, 1, r, r + d, steps).transform.rotate.y;
        EXPECT_NEAR(std::fmod(std::abs(turn), 45.0), 0.0, 1e-9) << turn;
    }
    const Gizmo scale = gizmo(HandleMode::Scale);
    const QPointF s = grip(scale);
    for (double dx : {23.0, 61.0, -40.0, -200.0}) {
        const double factor = scale.drag(startA, 0, s, s + QPointF(dx, 0.0), steps).transform.scale.x /
                              startA.transform.scale.x;
        EXPECT_NEAR(factor * 4.0, std::round(factor * 4.0), 1e-3) << "a factor in steps of 0.25";
        EXPECT_GE(factor, 0.25 - 1e-9) << "never zero";
    }
}

// Ctrl snaps; with "snap while dragging" on, Ctrl drags freely instead.
TEST(SnapSettings, CtrlInvertsTheSnapWhileDraggingChoice) {
    SnapSettings settings;
    settings.steps.rotate = 5.0;
    EXPECT_FALSE(settings.forDrag(false));
    ASSERT_TRUE(settings.forDrag(true));
    EXPECT_EQ(settings.forDrag(true)->rotate, 5.0);
    settings.always = true;
    ASSERT_TRUE(settings.forDrag(false));
    EXPECT_EQ(*settings.forDrag(false), settings.steps);
    EXPECT_FALSE(settings.forDrag(true));
}

// The centre of the scale handles scales the three axes together, by one factor.
TEST_F(HandleDragTest, TheScaleHandlesCentreScalesEvenly) {
    const Gizmo g = gizmo(HandleMode::Scale);
    ASSERT_EQ(g.hitTest(g.origin()), Gizmo::kUniformAxis);
    EXPECT_NE(gizmo(HandleMode::Move).hitTest(g.origin()), Gizmo::kUniformAxis) << "scale handles only";
    HandleDrag drag(scene, stack);
    ASSERT_TRUE(drag.press(g, Gizmo::kUniformAxis, g.origin(), a_, {a_}, 0.0));
    drag.move(g.origin() + QPointF(45.0, 0.0)); // half a handle to the right: 1.5 times the size
    drag.release();
    const glm::dvec3 scaled = scene.findNode(a_)->data().transform.scale;
    EXPECT_NEAR(scaled.x, 1.5, 1e-9);
    EXPECT_EQ(scaled.x, scaled.y);
    EXPECT_EQ(scaled.x, scaled.z);
    EXPECT_EQ(stack.undoText(), QStringLiteral("Scale \u201cA\u201d"));
}

} // namespace
} // namespace speculum::ui

// Esc during a handle drag, as a user does it in the viewport: the node is back where it was, the undo stack
// has no step more, and the document is not modified (no '*' in the title). A drag that ends where it
// began leaves no step either.
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QMouseEvent>
#include <QTest>
#include <QUndoStack>
#include <QWindow>
#include <gtest/gtest.h>

namespace {

using namespace speculum;
using namespace speculum::ui::test;
using speculum::scene::NodeId;

const QString kTeapotProject =
    QString::fromStdString(speculum::testSourcePath("resources/scenes/teapot.speculum.json"));

class HandleCancel : public ::testing::Test {
protected:
    void SetUp() override {
        m_window = std::make_unique<ui::MainWindow>();
        m_window->resize(1400, 850);
        m_window->show();
        ASSERT_TRUE(
            waitFor([&] { return m_window->windowHandle() && m_window->windowHandle()->isExposed(); }));
        m_window->clock().setPlaying(false);
        m_window->clock().setTime(0.0);
        auto status = m_window->openProjectFile(kTeapotProject);
        ASSERT_TRUE(status.ok()) << status.error();
        ASSERT_TRUE(waitForFrames(*m_window));
        ASSERT_TRUE(m_window->viewport().rendererError().isEmpty());
        m_window->scene().forEachNode([&](const speculum::scene::Node& node) {
            if (node.name() == "Teapot") {
                m_teapot = node.id();
            }
        });
        ASSERT_NE(m_teapot, speculum::scene::kNoNode);
        m_window->selection().selectNode(m_teapot);
        m_window->viewport().setHandleMode(ui::HandleMode::Move);
        ASSERT_TRUE(waitForFrames(*m_window));
    }

    void TearDown() override {
        if (m_window) {
            m_window->undoStack().setClean();
            m_window->newProject(); // nothing modified: no prompt on close
            m_window.reset();
        }
    }

    // The title as the window system shows it ("[*]" replaced by '*' when modified, by nothing otherwise).
    QString shownTitle() const { return m_window->windowHandle()->title(); }

    void moveMouse(QPointF to) {
        ui::Viewport& viewport = m_window->viewport();
        QMouseEvent move(QEvent::MouseMove, to, viewport.mapToGlobal(to), Qt::NoButton, Qt::LeftButton,
                         Qt::NoModifier);
        QCoreApplication::sendEvent(&viewport, &move);
    }

    speculum::scene::Transform teapotTransform() const {
        return m_window->scene().findNode(m_teapot)->data().transform;
    }

    std::unique_ptr<ui::MainWindow> m_window;
    NodeId m_teapot = speculum::scene::kNoNode;
};

TEST_F(HandleCancel, EscPutsTheNodeBackAndLeavesTheDocumentClean) {
    ui::Viewport& viewport = m_window->viewport();
    QUndoStack& undo = m_window->undoStack();
    ASSERT_TRUE(undo.isClean());
    ASSERT_FALSE(shownTitle().contains(QLatin1Char('*'))) << shownTitle().toStdString();
    const int steps = undo.count();
    const speculum::scene::Transform start = teapotTransform();

    const auto handle = viewport.handlePoint(0);
    ASSERT_TRUE(handle);
    QTest::mousePress(&viewport, Qt::LeftButton, Qt::NoModifier, handle->toPoint());
    for (int dx = 10; dx <= 50; dx += 10) {
        moveMouse(QPointF(handle->toPoint()) + QPointF(dx, 0));
    }
    ASSERT_NE(teapotTransform(), start) << "the drag moves the teapot";
    EXPECT_FALSE(undo.isClean());
    EXPECT_TRUE(m_window->isWindowModified());
    EXPECT_TRUE(shownTitle().contains(QLatin1Char('*')))
        << "modified while dragging: " << shownTitle().toStdString();

    QTest::keyClick(&viewport, Qt::Key_Escape);
    QTest::mouseRelease(&viewport, Qt::LeftButton, Qt::NoModifier, handle->toPoint() + QPoint(50, 0));
    EXPECT_EQ(teapotTransform(), start) << "back where it was";
    EXPECT_EQ(undo.count(), steps) << "no undo step left behind";
    EXPECT_TRUE(undo.isClean());
    EXPECT_FALSE(undo.canRedo());
    EXPECT_FALSE(m_window->isWindowModified());
    EXPECT_FALSE(shownTitle().contains(QLatin1Char('*'))) << shownTitle().toStdString();

    // The mouse moves on after Esc with the button still down: nothing follows it.
    moveMouse(QPointF(handle->toPoint()) + QPointF(80, 0));
    EXPECT_EQ(teapotTransform(), start);
    EXPECT_EQ(undo.count(), steps);
    ASSERT_TRUE(waitForFrames(*m_window)); // and the viewport keeps drawing
}

TEST_F(HandleCancel, ADragBackToItsStartLeavesNoStepAndARealDragStillUndoes) {
    ui::Viewport& viewport = m_window->viewport();
    QUndoStack& undo = m_window->undoStack();
    const int steps = undo.count();
    const speculum::scene::Transform start = teapotTransform();
    const auto handle = viewport.handlePoint(0);
    ASSERT_TRUE(handle);
    const QPoint grip = handle->toPoint();

    QTest::mousePress(&viewport, Qt::LeftButton, Qt::NoModifier, grip);
    moveMouse(QPointF(grip) + QPointF(40, 0));
    ASSERT_NE(teapotTransform(), start);
    moveMouse(QPointF(grip));
    QTest::mouseRelease(&viewport, Qt::LeftButton, Qt::NoModifier, grip);
    EXPECT_EQ(teapotTransform(), start);
    EXPECT_EQ(undo.count(), steps);
    EXPECT_TRUE(undo.isClean());
    EXPECT_FALSE(shownTitle().contains(QLatin1Char('*'))) << shownTitle().toStdString();

    QTest::mousePress(&viewport, Qt::LeftButton, Qt::NoModifier, grip);
    moveMouse(QPointF(grip) + QPointF(40, 0));
    QTest::mouseRelease(&viewport, Qt::LeftButton, Qt::NoModifier, grip + QPoint(40, 0));
    const speculum::scene::Transform moved = teapotTransform();
    ASSERT_NE(moved, start);
    EXPECT_EQ(undo.count(), steps + 1);
    EXPECT_EQ(undo.undoText().toStdString(), "Move \u201cTeapot\u201d");
    EXPECT_TRUE(shownTitle().contains(QLatin1Char('*')));
    undo.undo();
    EXPECT_EQ(teapotTransform(), start);
    EXPECT_TRUE(undo.isClean());
    undo.redo();
    EXPECT_EQ(teapotTransform(), moved);
}

} // namespace

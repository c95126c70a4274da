// Esc during a handle drag, as a user does it in the viewport: the node is back where it was, the undo stack
// has no step more, and the document is not modified (no '*' in the title). A drag that ends where it
// began leaves no step either. Snap steps chosen in their dialog are used by the next drag and remembered
// by the next editor.
#include "editor/ui/SnapSettings.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QAction>
#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QMouseEvent>
#include <QPushButton>
#include <QSettings>
#include <QTest>
#include <QUndoStack>
#include <QWindow>
#include <gtest/gtest.h>
#include <set>

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

    void moveMouse(QPointF to, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
        ui::Viewport& viewport = m_window->viewport();
        QMouseEvent move(QEvent::MouseMove, to, viewport.mapToGlobal(to), Qt::NoButton, Qt::LeftButton,
                         modifiers);
        QCoreApplication::sendEvent(&viewport, &move);
    }

    // Drags the teapot's x handle by each of `offsets` (pixels), one undo step each, with `modifiers` held
    // while it moves; the x positions it reached.
    std::vector<double> dragX(const std::vector<int>& offsets, Qt::KeyboardModifiers modifiers) {
        ui::Viewport& viewport = m_window->viewport();
        std::vector<double> reached;
        for (int dx : offsets) {
            const auto handle = viewport.handlePoint(0);
            if (!handle) {
                ADD_FAILURE() << "no move handle";
                break;
            }
            const QPoint grip = handle->toPoint();
            // Ctrl goes down once the handle is held (on the press it would add to the selection).
            QTest::mousePress(&viewport, Qt::LeftButton, Qt::NoModifier, grip);
            moveMouse(QPointF(grip) + QPointF(dx / 2, 0), modifiers);
            moveMouse(QPointF(grip) + QPointF(dx, 0), modifiers);
            QTest::mouseRelease(&viewport, Qt::LeftButton, modifiers, grip + QPoint(dx, 0));
            reached.push_back(teapotTransform().translate.x);
        }
        return reached;
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

TEST_F(HandleCancel, SnapStepsChosenInTheirDialogAreUsedAndRemembered) {
    QAction* stepsAction = m_window->findChild<QAction*>(QStringLiteral("actionSnapSteps"));
    ASSERT_TRUE(stepsAction);
    stepsAction->trigger();
    auto* dialog = m_window->findChild<ui::SnapSettingsDialog*>(QStringLiteral("snapSettingsDialog"));
    ASSERT_TRUE(dialog && dialog->isVisible());
    auto* move = dialog->findChild<QDoubleSpinBox*>(QStringLiteral("snap.move"));
    auto* rotate = dialog->findChild<QDoubleSpinBox*>(QStringLiteral("snap.rotate"));
    ASSERT_TRUE(move && rotate);
    EXPECT_EQ(move->text().toStdString(), "Grid spacing") << "the default step is the grid's";
    EXPECT_EQ(rotate->value(), 15.0);
    move->selectAll();
    QTest::keyClicks(move, QStringLiteral("0.5"));
    rotate->selectAll();
    QTest::keyClicks(rotate, QStringLiteral("45"));
    auto* buttons = dialog->findChild<QDialogButtonBox*>();
    ASSERT_TRUE(buttons);
    QTest::mouseClick(buttons->button(QDialogButtonBox::Ok), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return !m_window->findChild<ui::SnapSettingsDialog*>(); }));
    EXPECT_EQ(m_window->viewport().snapSettings().steps.move, 0.5);
    EXPECT_EQ(m_window->viewport().snapSettings().steps.rotate, 45.0);

    // Ctrl snaps the moves to the chosen step; without it they are free.
    const auto onHalves = [](double x) { return std::abs(x * 2.0 - std::round(x * 2.0)) < 1e-9; };
    const std::vector<int> offsets{43, 97, 58, 131};
    const auto moves = [](const std::vector<double>& xs) {
        return std::set<double>(xs.begin(), xs.end()).size();
    };
    int snapped = 0, free = 0;
    const std::vector<double> ctrlHeld = dragX(offsets, Qt::ControlModifier);
    for (double x : ctrlHeld) {
        snapped += onHalves(x);
    }
    for (double x : dragX(offsets, Qt::NoModifier)) {
        free += !onHalves(x);
    }
    EXPECT_GE(moves(ctrlHeld), 3u) << "the drags moved the teapot";
    EXPECT_EQ(snapped, int(offsets.size()));
    EXPECT_GT(free, 0);

    // Snap While Dragging: now a drag without Ctrl snaps, and Ctrl frees it.
    QAction* always = m_window->findChild<QAction*>(QStringLiteral("actionSnapAlways"));
    ASSERT_TRUE(always && always->isCheckable() && !always->isChecked());
    always->trigger();
    snapped = 0;
    free = 0;
    const std::vector<double> unheld = dragX(offsets, Qt::NoModifier);
    for (double x : unheld) {
        snapped += onHalves(x);
    }
    for (double x : dragX(offsets, Qt::ControlModifier)) {
        free += !onHalves(x);
    }
    EXPECT_GE(moves(unheld), 3u) << "the drags moved the teapot";
    EXPECT_EQ(snapped, int(offsets.size()));
    EXPECT_GT(free, 0);

    // The next editor starts with all of it, its menu item checked.
    m_window->undoStack().setClean();
    m_window->newProject();
    m_window.reset();
    ui::MainWindow next;
    EXPECT_EQ(next.viewport().snapSettings().steps.move, 0.5);
    EXPECT_EQ(next.viewport().snapSettings().steps.rotate, 45.0);
    EXPECT_TRUE(next.viewport().snapSettings().always);
    QAction* nextAlways = next.findChild<QAction*>(QStringLiteral("actionSnapAlways"));
    ASSERT_TRUE(nextAlways);
    EXPECT_TRUE(nextAlways->isChecked());
    // A remembered value no dialog can give (a hand-edited file) reads as the default.
    QSettings().setValue(QStringLiteral("snap/rotateStep"), -3.0);
    EXPECT_EQ(ui::SnapSettings::load().steps.rotate, 15.0);
    ui::SnapSettings{}.save(); // the tests after this one start from the defaults
}

} // namespace

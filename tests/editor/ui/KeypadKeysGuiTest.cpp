// The numeric keypad from a real X keyboard (XTEST on the test's own Xvfb), in both NumLock states: the
// views of Blender's keypad, the orbit and zoom steps, and the keys a keypad shares with Home, Delete and the
// arrows never doing what those do. A text field keeps the keypad's digits.
#include "editor/document/NodeFactory.hpp"
#include "editor/ui/SceneTreePanel.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "editor/view/ViewPresets.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/XKeyboard.hpp"

#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QKeyEvent>
#include <QLineEdit>
#include <QTreeView>
#include <QUndoStack>
#include <QWindow>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>
#include <vector>

namespace speculum::ui {
namespace {

using test::waitFor;

void runFor(int ms) {
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
}

// The keypad keys the application receives, as Qt made them from X's events: each press's
// shortcut-override step, which comes whether or not a shortcut then takes the key.
class KeypadRecorder : public QObject {
public:
    struct Press {
        int key;
        Qt::KeyboardModifiers modifiers;
    };
    std::vector<Press> presses;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::ShortcutOverride && watched == QApplication::focusObject()) {
            const auto* key = static_cast<QKeyEvent*>(event);
            if (key->modifiers() & Qt::KeypadModifier)
                presses.push_back({key->key(), key->modifiers()});
        }
        return false;
    }
};

class KeypadKeysTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(test::haveXKeyboard()) << "xdotool is missing: scripts/setup-deps installs it";
        m_window = test::mainWindowWithXFocus();
        ASSERT_NE(m_window, nullptr) << "the window is shown and has X's input focus";
        m_window->viewport().setFocus(Qt::OtherFocusReason);
        qApp->installEventFilter(&m_recorder); // after the window's filters: it sees each key first
        const QAction* rewind = action("actionRewind");
        ASSERT_NE(rewind, nullptr);
        QObject::connect(rewind, &QAction::triggered, [this] { ++m_rewinds; });
    }
    void TearDown() override {
        qApp->removeEventFilter(&m_recorder);
        if (m_window) {
            m_window->undoStack().setClean();
            m_window.reset();
        }
    }

    QAction* action(const char* name) { return m_window->findChild<QAction*>(QString::fromLatin1(name)); }
    const render::Camera& view() { return m_window->viewport().viewCamera(); }
    glm::dvec3 looking() { return glm::normalize(view().target - view().position); }

    // Presses `key` and waits until it has arrived; false (with the failure said) where it did not.
    bool press(const char* key) {
        const std::size_t before = m_recorder.presses.size();
        if (!test::pressXKeys({QString::fromLatin1(key)})) {
            ADD_FAILURE() << "xdotool could not press " << key;
            return false;
        }
        if (!waitFor([&] { return m_recorder.presses.size() > before; }, 10000)) {
            ADD_FAILURE() << key << " never arrived";
            return false;
        }
        runFor(50); // what the key does, done
        return true;
    }
    // The Qt key of the last keypad key that arrived.
    int lastKey() const { return m_recorder.presses.empty() ? 0 : m_recorder.presses.back().key; }
    // Whether the view looks from the preset's side.
    bool looksFrom(view::ViewPreset preset) {
        return glm::dot(looking(), view::presetDirection(preset)) > 0.999;
    }

    std::unique_ptr<MainWindow> m_window;
    KeypadRecorder m_recorder;
    int m_rewinds = 0;
};

TEST_F(KeypadKeysTest, TheViewKeysWorkWithNumLockOffAndOn) {
    // The harness itself: Home from the main block reaches the window and rewinds.
    ASSERT_TRUE(test::pressXKeys({QStringLiteral("Home")}));
    ASSERT_TRUE(waitFor([&] { return m_rewinds == 1; }, 10000)) << "a real key reaches the window";

    // NumLock off, as a new X server starts: keypad 7 arrives as Home (with the keypad modifier).
    ASSERT_TRUE(press("KP_Home"));
    EXPECT_EQ(lastKey(), Qt::Key_Home) << "X's NumLock-off keypad 7";
    EXPECT_TRUE(looksFrom(view::ViewPreset::Top)) << "NumLock off: keypad 7 is the top view";
    ASSERT_TRUE(press("KP_End"));
    EXPECT_TRUE(looksFrom(view::ViewPreset::Front));
    ASSERT_TRUE(press("KP_Next"));
    EXPECT_TRUE(looksFrom(view::ViewPreset::Right));
    ASSERT_TRUE(press("ctrl+KP_Home"));
    EXPECT_TRUE(looksFrom(view::ViewPreset::Bottom));
    EXPECT_EQ(m_rewinds, 1) << "the keypad's Home never rewinds the animation";

    // NumLock on: the digits.
    ASSERT_TRUE(test::pressXKeys({QStringLiteral("Num_Lock")}));
    ASSERT_TRUE(press("KP_7"));
    EXPECT_EQ(lastKey(), Qt::Key_7) << "X's NumLock-on keypad 7";
    EXPECT_TRUE(looksFrom(view::ViewPreset::Top)) << "NumLock on: keypad 7 is the top view";
    ASSERT_TRUE(press("KP_1"));
    EXPECT_TRUE(looksFrom(view::ViewPreset::Front));
    ASSERT_TRUE(press("ctrl+KP_3"));
    EXPECT_TRUE(looksFrom(view::ViewPreset::Left));
    ASSERT_TRUE(press("ctrl+KP_1"));
    EXPECT_TRUE(looksFrom(view::ViewPreset::Back));
    ASSERT_TRUE(test::pressXKeys({QStringLiteral("Num_Lock")})); // as it was
    EXPECT_EQ(m_rewinds, 1);
}

TEST_F(KeypadKeysTest, OrbitAndZoomStepAsInBlender) {
    ASSERT_TRUE(press("KP_End"));
    ASSERT_TRUE(looksFrom(view::ViewPreset::Front));
    const double distance = glm::length(view().target - view().position);
    glm::dvec3 before = looking();
    ASSERT_TRUE(press("KP_Left")); // keypad 4: the camera orbits 15° to its left
    EXPECT_NEAR(glm::dot(before, looking()), std::cos(glm::radians(15.0)), 1e-6);
    EXPECT_GT(looking().x, 0.2) << "moved to its left (−X, looking along −Z), it looks a little towards +X";
    ASSERT_TRUE(press("KP_Right"));
    EXPECT_TRUE(looksFrom(view::ViewPreset::Front)) << "keypad 6 turns it back";
    before = looking();
    ASSERT_TRUE(press("KP_Up")); // keypad 8: over the top
    EXPECT_NEAR(glm::dot(before, looking()), std::cos(glm::radians(15.0)), 1e-6);
    EXPECT_LT(looking().y, -0.2) << "from above, it looks down";
    ASSERT_TRUE(press("KP_Add"));
    EXPECT_NEAR(glm::length(view().target - view().position), distance * 0.85, 1e-6 * distance);
    ASSERT_TRUE(press("KP_Subtract"));
    EXPECT_NEAR(glm::length(view().target - view().position), distance, 1e-6 * distance);
}

TEST_F(KeypadKeysTest, TheKeypadPointFramesTheSelectionAndNeverDeletes) {
    ASSERT_TRUE(m_window->addNode(document::NewNodeKind::Teapot).ok());
    m_window->viewport().setFocus(Qt::OtherFocusReason);
    const std::size_t nodes = m_window->scene().topLevelNodes().size();
    const int steps = m_window->undoStack().count();
    ASSERT_TRUE(press("KP_End"));
    ASSERT_TRUE(press("KP_Subtract"));
    ASSERT_TRUE(press("KP_Subtract"));
    const render::Camera away = view();
    ASSERT_TRUE(press("KP_Delete")); // NumLock off: the keypad's decimal point arrives as Delete
    EXPECT_EQ(lastKey(), Qt::Key_Delete);
    EXPECT_EQ(m_window->scene().topLevelNodes().size(), nodes) << "the keypad's Delete deletes nothing";
    EXPECT_EQ(m_window->undoStack().count(), steps);
    const render::Camera framed = view();
    EXPECT_GT(glm::length(framed.position - away.position), 1e-6) << "the view moved";
    // What View ▸ Frame Selection does from the same view.
    m_window->viewport().setViewCamera(away);
    action("actionFrameSelected")->trigger();
    EXPECT_LT(glm::length(view().position - framed.position), 1e-9);
    EXPECT_LT(glm::length(view().target - framed.target), 1e-9);
}

TEST_F(KeypadKeysTest, ATextFieldTypesTheKeypadsDigits) {
    ASSERT_TRUE(m_window->addNode(document::NewNodeKind::Teapot).ok());
    QTreeView& tree = m_window->sceneTree().view();
    tree.setFocus(Qt::OtherFocusReason);
    tree.edit(tree.currentIndex()); // the rename field, as F2 opens it
    QLineEdit* field = nullptr;
    ASSERT_TRUE(waitFor([&] {
        field = qobject_cast<QLineEdit*>(QApplication::focusWidget());
        return field != nullptr;
    }));
    field->clear();
    const render::Camera camera = view();
    ASSERT_TRUE(test::pressXKeys({QStringLiteral("Num_Lock")}));
    ASSERT_TRUE(press("KP_7"));
    ASSERT_TRUE(press("KP_1"));
    ASSERT_TRUE(test::pressXKeys({QStringLiteral("Num_Lock")}));
    EXPECT_EQ(field->text(), QStringLiteral("71")) << "the field types the keypad's digits";
    EXPECT_EQ(view().position, camera.position) << "and the view stays";
    field->undo();
}

} // namespace
} // namespace speculum::ui

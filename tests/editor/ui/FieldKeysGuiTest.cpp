// The keyboard after a field, typed on a real X keyboard (XTEST on the test's own Xvfb): Enter commits a
// number or name field and hands the keyboard back, so the document's keys (Ctrl+Z, W/E/R, Delete) act
// again; Esc puts the field back and commits nothing; F2's rename editor hands it back the same way.
#include "editor/document/NodeFactory.hpp"
#include "editor/ui/Inspector.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/XKeyboard.hpp"

#include <QApplication>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLineEdit>
#include <QUndoStack>
#include <QWindow>
#include <gtest/gtest.h>

namespace speculum::ui {
namespace {

using test::waitFor;

class FieldKeysTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(test::haveXKeyboard()) << "xdotool is missing: scripts/setup-deps installs it";
        m_window = test::mainWindowWithXFocus();
        ASSERT_NE(m_window, nullptr) << "the window is shown and has X's input focus";
        ASSERT_TRUE(m_window->addNode(document::NewNodeKind::Teapot).ok());
        m_teapot = m_window->selection().node();
    }
    void TearDown() override {
        if (m_window) {
            m_window->undoStack().setClean();
            m_window.reset();
        }
    }

    // Types `keys` (xdotool names) and lets the window handle them.
    void type(const QStringList& keys) {
        ASSERT_TRUE(test::pressXKeys(keys)) << keys.join(QLatin1Char(' ')).toStdString();
        QElapsedTimer timer;
        timer.start();
        while (timer.elapsed() < 300)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    }
    // The inspector's field `name`, with focus and its text selected, as a click and Ctrl+A leave it.
    template <typename Field>
    Field* focusField(const char* name) {
        auto* field = m_window->inspector().findChild<Field*>(QString::fromLatin1(name));
        if (!field)
            return nullptr;
        field->setFocus(Qt::MouseFocusReason);
        if (!waitFor([&] { return QApplication::focusWidget() == field; }, 10000))
            return nullptr;
        field->selectAll();
        return field;
    }
    const scene::Node& teapot() { return *m_window->scene().findNode(m_teapot); }
    bool viewportHasFocus() { return QApplication::focusWidget() == &m_window->viewport(); }

    std::unique_ptr<MainWindow> m_window;
    scene::NodeId m_teapot{};
};

TEST_F(FieldKeysTest, EnterCommitsANumberAndTheDocumentKeysWorkAgain) {
    const double x = teapot().data().transform.translate.x;
    const int steps = m_window->undoStack().count();
    ASSERT_NE(focusField<QDoubleSpinBox>("transform.translate.x"), nullptr);
    type({QStringLiteral("2"), QStringLiteral("period"), QStringLiteral("5"), QStringLiteral("Return")});
    EXPECT_DOUBLE_EQ(teapot().data().transform.translate.x, 2.5) << "Enter commits";
    EXPECT_EQ(m_window->undoStack().count(), steps + 1);
    EXPECT_TRUE(viewportHasFocus()) << "and hands the keyboard back";
    type({QStringLiteral("e")});
    EXPECT_EQ(m_window->viewport().handleMode(), HandleMode::Rotate) << "E switches the handles";
    type({QStringLiteral("ctrl+z")});
    EXPECT_DOUBLE_EQ(teapot().data().transform.translate.x, x) << "Ctrl+Z undoes the edit";
}

TEST_F(FieldKeysTest, EscPutsTheFieldBackAndCommitsNothing) {
    const double x = teapot().data().transform.translate.x;
    const int steps = m_window->undoStack().count();
    auto* field = focusField<QDoubleSpinBox>("transform.translate.x");
    ASSERT_NE(field, nullptr);
    const QString shown = field->text();
    type({QStringLiteral("9"), QStringLiteral("Escape")});
    EXPECT_EQ(field->text(), shown) << "the field shows the document's value again";
    EXPECT_DOUBLE_EQ(teapot().data().transform.translate.x, x);
    EXPECT_TRUE(viewportHasFocus());
    EXPECT_EQ(m_window->undoStack().count(), steps) << "nothing committed, on Esc or on leaving";

    auto* name = focusField<QLineEdit>("node.name");
    ASSERT_NE(name, nullptr);
    const std::string before = teapot().name();
    type({QStringLiteral("Z"), QStringLiteral("Escape")});
    EXPECT_EQ(name->text().toStdString(), before);
    EXPECT_EQ(teapot().name(), before);
    EXPECT_EQ(m_window->undoStack().count(), steps);
    EXPECT_TRUE(viewportHasFocus());
}

TEST_F(FieldKeysTest, ARenameWithF2AndEnterHandsTheKeyboardBack) {
    m_window->viewport().setFocus(Qt::OtherFocusReason);
    ASSERT_TRUE(waitFor([&] { return viewportHasFocus(); }));
    type({QStringLiteral("F2")});
    ASSERT_TRUE(waitFor([&] { return qobject_cast<QLineEdit*>(QApplication::focusWidget()) != nullptr; }))
        << "F2 opens the rename field";
    qobject_cast<QLineEdit*>(QApplication::focusWidget())->selectAll();
    type({QStringLiteral("P"), QStringLiteral("o"), QStringLiteral("t"), QStringLiteral("Return")});
    EXPECT_EQ(teapot().name(), "Pot");
    EXPECT_TRUE(waitFor([&] { return viewportHasFocus(); }, 5000)) << "Enter hands the keyboard back";
    const std::size_t nodes = m_window->scene().topLevelNodes().size();
    type({QStringLiteral("Delete")});
    EXPECT_EQ(m_window->scene().topLevelNodes().size(), nodes - 1) << "Delete deletes the node";
    type({QStringLiteral("ctrl+z")});
    EXPECT_EQ(m_window->scene().topLevelNodes().size(), nodes) << "Ctrl+Z brings it back";
}

} // namespace
} // namespace speculum::ui

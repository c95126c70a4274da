// The timeline's slider scrubs the animation, follows the clock while playing, and the
// clock starts over at 0, paused, when a project is opened or a new one made.
#include "editor/ui/TimeSlider.hpp"
#include "editor/view/AnimationClock.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QAction>
#include <QSlider>
#include <QTest>
#include <QToolBar>
#include <QUndoStack>
#include <QWindow>
#include <gtest/gtest.h>

namespace {

using namespace speculum;
using namespace speculum::ui::test;

const QString kChromeProject =
    QString::fromStdString(speculum::testSourcePath("resources/scenes/chrome.speculum.json"));
const QString kTeapotProject =
    QString::fromStdString(speculum::testSourcePath("resources/scenes/teapot.speculum.json"));

class TimeSliderTest : public ::testing::Test {
protected:
    void SetUp() override {
        m_window = std::make_unique<ui::MainWindow>();
        m_window->resize(1400, 850);
        m_window->show();
        ASSERT_TRUE(
            waitFor([&] { return m_window->windowHandle() && m_window->windowHandle()->isExposed(); }));
        m_slider = m_window->findChild<ui::TimeSlider*>(QStringLiteral("timeSlider"));
        ASSERT_NE(m_slider, nullptr);
        ASSERT_TRUE(m_slider->isVisible()) << "the timeline shows by default";
    }

    void TearDown() override {
        if (m_window) {
            m_window->undoStack().setClean();
            m_window->newProject();
            m_window.reset();
        }
    }

    void open(const QString& path) {
        auto status = m_window->openProjectFile(path);
        ASSERT_TRUE(status.ok()) << status.error();
        ASSERT_TRUE(waitForFrames(*m_window, 1));
    }

    std::unique_ptr<ui::MainWindow> m_window;
    ui::TimeSlider* m_slider = nullptr;
};

TEST_F(TimeSliderTest, SpansOneLoopOfTheAnimation) {
    open(kTeapotProject); // a bounce every 2 s, an orbit every 6 s: back where it started after 6 s
    EXPECT_DOUBLE_EQ(m_slider->duration(), 6.0);
    EXPECT_DOUBLE_EQ(m_window->clock().loopSeconds(), 6.0);
    open(kChromeProject);
    EXPECT_DOUBLE_EQ(m_slider->duration(), 10.0) << "nothing moves: a plain 10 s timeline";
    EXPECT_TRUE(m_slider->slider()->toolTip().contains(QStringLiteral("nothing")));
}

TEST_F(TimeSliderTest, PlayingMovesItAndPausingHoldsIt) {
    open(kTeapotProject);
    EXPECT_EQ(m_slider->slider()->value(), 0);
    EXPECT_EQ(m_slider->readout(), QStringLiteral("t = 0.00 s"));
    QAction* play = m_window->action(QStringLiteral("actionPlay"));
    EXPECT_EQ(play->text(), QStringLiteral("&Play Animation"));
    play->trigger();
    ASSERT_TRUE(m_window->clock().isPlaying());
    EXPECT_EQ(play->text(), QStringLiteral("&Pause Animation")) << "the button says what it does next";
    EXPECT_TRUE(play->isChecked());
    EXPECT_TRUE(waitFor([&] { return m_slider->shownTime() >= 0.3; }, 10000));
    EXPECT_NE(m_slider->readout(), QStringLiteral("t = 0.00 s"));
    play->trigger();
    ASSERT_FALSE(m_window->clock().isPlaying());
    EXPECT_EQ(play->text(), QStringLiteral("&Play Animation"));
    const int held = m_slider->slider()->value();
    QTest::qWait(300);
    EXPECT_EQ(m_slider->slider()->value(), held);
    EXPECT_NEAR(m_slider->shownTime(), m_window->clock().time(), 0.001);
}

TEST_F(TimeSliderTest, MovingItSetsTheClockAndTheViewportShowsThatTime) {
    open(kTeapotProject);
    const int before = m_window->viewport().framesRendered();
    m_slider->slider()->setValue(1500); // as a drag or a click along it does
    EXPECT_DOUBLE_EQ(m_window->clock().time(), 1.5);
    EXPECT_EQ(m_slider->readout(), QStringLiteral("t = 1.50 s"));
    ASSERT_TRUE(waitFor([&] { return m_window->viewport().framesRendered() > before; }));
    EXPECT_DOUBLE_EQ(m_window->viewport().lastFrameTime(), 1.5);
    EXPECT_FALSE(m_window->isModified()) << "time is not part of the document";
    EXPECT_EQ(m_window->undoStack().count(), 0);

    // With the mouse: a drag of the handle to the far right end shows the loop's end.
    QSlider* bar = m_slider->slider();
    bar->setValue(0);
    const QPoint handle(4, bar->height() / 2);
    QTest::mousePress(bar, Qt::LeftButton, Qt::NoModifier, handle);
    QTest::mouseMove(bar, QPoint(bar->width() / 2, bar->height() / 2));
    QTest::mouseMove(bar, QPoint(bar->width() + 40, bar->height() / 2));
    QTest::mouseRelease(bar, Qt::LeftButton, Qt::NoModifier, QPoint(bar->width() + 40, bar->height() / 2));
    EXPECT_NEAR(m_window->clock().time(), 6.0, 0.05);
}

TEST_F(TimeSliderTest, OpeningOrNewStartsTheClockOverPaused) {
    open(kTeapotProject);
    m_window->clock().setTime(2.5);
    m_window->clock().setPlaying(true);
    open(kChromeProject);
    EXPECT_FALSE(m_window->clock().isPlaying());
    EXPECT_DOUBLE_EQ(m_window->clock().time(), 0.0);
    EXPECT_EQ(m_slider->slider()->value(), 0);
    EXPECT_FALSE(m_window->action(QStringLiteral("actionPlay"))->isChecked());

    m_window->clock().setTime(4.0);
    m_window->clock().setPlaying(true);
    m_window->newProject();
    EXPECT_FALSE(m_window->clock().isPlaying());
    EXPECT_DOUBLE_EQ(m_window->clock().time(), 0.0);
    EXPECT_EQ(m_slider->readout(), QStringLiteral("t = 0.00 s"));
}

} // namespace

// The editor draws only when what it shows changes. A static demo left alone draws no frame for
// seconds, even with the clock running; an edit, an undo, a time jump, navigation and a resize each draw
// and then stop; an animated scene that plays keeps drawing until paused.
#include "editor/document/Commands.hpp"
#include "editor/ui/CoarseLevelJobs.hpp"
#include "editor/view/AnimationClock.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QTemporaryDir>
#include <QUndoStack>
#include <QWheelEvent>
#include <QWindow>
#include <gtest/gtest.h>

namespace {

using namespace speculum;
using namespace speculum::ui::test;

const QString kChromeProject =
    QString::fromStdString(speculum::testSourcePath("resources/scenes/chrome.speculum.json"));
const QString kTeapotProject =
    QString::fromStdString(speculum::testSourcePath("resources/scenes/teapot.speculum.json"));

constexpr int kIdleMs = 2500;  // "several seconds without input"
constexpr int kSettleMs = 600; // after the last frame a change asked for, before counting idle frames

class IdleRedraw : public ::testing::Test {
protected:
    void SetUp() override {
        m_window = std::make_unique<ui::MainWindow>();
        m_window->resize(1400, 850);
        m_window->show();
        ASSERT_TRUE(
            waitFor([&] { return m_window->windowHandle() && m_window->windowHandle()->isExposed(); }));
    }

    void TearDown() override {
        if (m_window) {
            m_window->undoStack().setClean();
            m_window->newProject();
            m_window.reset();
        }
    }

    ui::Viewport& viewport() { return m_window->viewport(); }

    void open(const QString& path) {
        auto status = m_window->openProjectFile(path);
        ASSERT_TRUE(status.ok()) << status.error();
        ASSERT_TRUE(waitForFrames(*m_window, 1)) << "the viewport did not draw";
        ASSERT_TRUE(viewport().rendererError().isEmpty()) << viewport().rendererError().toStdString();
        settle();
    }

    // Runs the event loop for `ms` without input and returns the frames drawn meanwhile.
    int framesOver(int ms) {
        const int before = viewport().framesRendered();
        QElapsedTimer timer;
        timer.start();
        while (timer.elapsed() < ms) {
            QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
            QThread::msleep(5);
        }
        return viewport().framesRendered() - before;
    }

    // Lets what a change asked for be drawn (models read in, the frame itself).
    void settle() {
        ASSERT_TRUE(waitFor([&] { return !viewport().modelsLoading(); }));
        framesOver(kSettleMs);
    }

    // After a change: at least one frame comes, then none over the idle time.
    void expectDrawsThenStops(const char* what) {
        const int before = viewport().framesRendered();
        EXPECT_TRUE(waitFor([&] { return viewport().framesRendered() > before; }, 30000))
            << what << ": no frame was drawn";
        framesOver(kSettleMs);
        EXPECT_EQ(framesOver(kIdleMs), 0) << what << ": frames kept coming";
    }

    std::unique_ptr<ui::MainWindow> m_window;
};

// A big mesh seen in a mirror: the frames draw it whole while a worker builds its simplified level (the GUI
// thread never waits seconds for it), then one more frame draws it at that level, and the view rests.
TEST_F(IdleRedraw, ABigMeshInAMirrorIsSimplifiedOnAWorkerThenDrawnOnceMore) {
    QTemporaryDir dir;
    // A teapot of 32 patches × 64 × 64 × 2 = 262 144 triangles, above a floor mirror.
    const QString path =
        writeFileIn(dir, QStringLiteral("big.speculum.json"), R"({"format": "speculum-scene", "version": 1,
          "camera": {"position": [0, 1.5, 4], "target": [0, 0, 0], "fovY": 50, "near": 0.1, "far": 50},
          "nodes": [
            {"name": "Teapot", "transform": {"translate": [0, 0.3, 0], "scale": [0.3, 0.3, 0.3]},
             "mesh": {"builtin": "teapot", "tessellation": 64}},
            {"name": "Floor", "mirror": {"size": [4, 4]}},
            {"name": "Light", "transform": {"translate": [1, 3, 2]}, "light": {"type": "point"}}]})");
    ASSERT_FALSE(path.isEmpty());
    bool drawnWholeMeanwhile = false;
    const QMetaObject::Connection watch = QObject::connect(
        &viewport(), &ui::Viewport::frameRendered, [&](const render::FrameReport& report, double) {
            for (const render::PlannedPass& pass : report.plan.passes)
                for (const render::ReflectedMesh& mesh : pass.details.bigMeshes)
                    drawnWholeMeanwhile = drawnWholeMeanwhile || (mesh.name == "Teapot" && mesh.simplifying);
        });
    auto status = m_window->openProjectFile(path);
    ASSERT_TRUE(status.ok()) << status.error();
    EXPECT_TRUE(waitFor([&] { return !viewport().lastReport().plan.coarseItems.empty(); }, 60000))
        << "the mirror never drew the teapot's simplified level";
    QObject::disconnect(watch);
    EXPECT_TRUE(drawnWholeMeanwhile) << "a frame waited for the level instead of drawing the teapot whole";
    EXPECT_EQ(viewport().coarseLevelJobs().pending(), 0);
    framesOver(kSettleMs);
    EXPECT_EQ(framesOver(kIdleMs), 0) << "with the level drawn, the view rests";
}

TEST_F(IdleRedraw, AStaticDemoDrawsNothingWhileLeftAlone) {
    open(kChromeProject);
    EXPECT_FALSE(m_window->clock().isPlaying()) << "opening a project does not start playback";
    EXPECT_FALSE(viewport().isAnimating());
    EXPECT_EQ(framesOver(kIdleMs), 0);
}

TEST_F(IdleRedraw, AStaticDemoDrawsNothingEvenWhileTheClockRuns) {
    open(kChromeProject);
    m_window->clock().setPlaying(true); // what start-up used to do
    framesOver(kSettleMs);              // play/pause is a time change: one frame
    EXPECT_FALSE(viewport().isAnimating()) << "nothing in the chrome demo moves";
    EXPECT_EQ(framesOver(kIdleMs), 0);
    m_window->clock().setPlaying(false);
}

TEST_F(IdleRedraw, AnEditAndItsUndoEachDrawThenStop) {
    open(kChromeProject);
    const speculum::scene::Node* first = m_window->scene().topLevelNodes().front().get();
    speculum::scene::NodeData data = first->data();
    data.transform.translate.x += 0.25;
    ASSERT_TRUE(document::pushEdit(m_window->undoStack(),
                                   new document::SetNodeDataCommand(m_window->scene(), first->id(), data)));
    expectDrawsThenStops("an edit");
    m_window->undoStack().undo();
    expectDrawsThenStops("an undo");
}

TEST_F(IdleRedraw, ATimeJumpNavigationAndAResizeEachDrawThenStop) {
    open(kChromeProject);
    m_window->clock().setTime(1.5);
    expectDrawsThenStops("a time jump");

    const QPointF centre(viewport().width() / 2.0, viewport().height() / 2.0);
    QWheelEvent wheel(centre, viewport().mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(&viewport(), &wheel);
    expectDrawsThenStops("a zoom");

    m_window->resize(1300, 800);
    expectDrawsThenStops("a resize");
}

TEST_F(IdleRedraw, AnAnimatedSceneKeepsDrawingWhilePlayingAndStopsWhenPaused) {
    open(kTeapotProject);
    EXPECT_FALSE(m_window->clock().isPlaying()) << "opening a project does not start playback";
    EXPECT_EQ(framesOver(1000), 0) << "paused: nothing moves";

    m_window->clock().setPlaying(true);
    EXPECT_TRUE(viewport().isAnimating());
    framesOver(300);
    const double startedAt = viewport().lastFrameTime();
    EXPECT_GE(framesOver(1500), 5) << "the bouncing teapot is drawn again and again";
    EXPECT_GT(viewport().lastFrameTime(), startedAt) << "each frame shows a later time";

    m_window->clock().setPlaying(false);
    EXPECT_FALSE(viewport().isAnimating());
    framesOver(kSettleMs);
    EXPECT_EQ(framesOver(kIdleMs), 0) << "paused again";
}

TEST_F(IdleRedraw, RemovingTheLastAnimationStopsTheFrames) {
    open(kTeapotProject);
    m_window->clock().setPlaying(true);
    ASSERT_TRUE(viewport().isAnimating());
    // Clears every node's animation, one undo step each: the scene becomes static while it plays.
    std::vector<std::pair<speculum::scene::NodeId, speculum::scene::NodeData>> animated;
    m_window->scene().forEachNode([&](const speculum::scene::Node& node) {
        if (node.data().animation) {
            animated.emplace_back(node.id(), node.data());
        }
    });
    ASSERT_FALSE(animated.empty());
    for (auto& [id, data] : animated) {
        data.animation.reset();
        document::pushEdit(m_window->undoStack(),
                           new document::SetNodeDataCommand(m_window->scene(), id, data));
    }
    EXPECT_FALSE(viewport().isAnimating());
    framesOver(kSettleMs);
    EXPECT_EQ(framesOver(kIdleMs), 0);
    m_window->undoStack().undo(); // one animation back: frames again
    EXPECT_TRUE(viewport().isAnimating());
    m_window->clock().setPlaying(false);
}

} // namespace

// In the viewport: adaptive resolution while navigating or dragging a handle
// (frames drawn reduced and scaled up, then one full frame once the view rests, equal to a frame drawn
// without adaptive resolution), the view presets and guides actions, the vertical orbit's direction, and
// a saved editor view placed after the reset of a newly opened document.
#include "editor/ui/ViewPresetActions.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "editor/view/ViewPresets.hpp"
#include "scene/evaluate/Snapshot.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QMouseEvent>
#include <QUndoStack>
#include <QWheelEvent>
#include <QWindow>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <optional>

namespace {

using namespace speculum;
using namespace speculum::ui::test;

const QString kChromeProject =
    QString::fromStdString(speculum::testSourcePath("resources/scenes/chrome.speculum.json"));
const QString kMirrorsProject =
    QString::fromStdString(speculum::testSourcePath("resources/scenes/mirrors.speculum.json"));

void sendMouse(ui::Viewport& viewport, QEvent::Type type, QPointF at, Qt::MouseButton button,
               Qt::MouseButtons buttons, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
    QMouseEvent event(type, at, viewport.mapToGlobal(at), button, buttons, modifiers);
    QCoreApplication::sendEvent(&viewport, &event);
}

void runFor(int ms) {
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < ms) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        QThread::msleep(2);
    }
}

// What one frame was, seen from inside it (frameRendered is emitted in paintGL, so grabFramebuffer()
// there reads the frame just drawn instead of drawing another).
struct Frame {
    double scale = 1.0;
    bool reduced = false;
    bool interacting = false;
    QSize drawn;
    QImage image;
};

class AdaptiveResolution : public ::testing::Test {
protected:
    void SetUp() override {
        m_window = std::make_unique<ui::MainWindow>();
        m_window->resize(1100, 700);
        m_window->show();
        ASSERT_TRUE(
            waitFor([&] { return m_window->windowHandle() && m_window->windowHandle()->isExposed(); }));
        QObject::connect(&viewport(), &ui::Viewport::frameRendered, &viewport(), [this] {
            Frame f;
            f.scale = viewport().lastFrameScale();
            f.reduced = viewport().lastFrameReduced();
            f.interacting = viewport().isInteracting();
            f.drawn = viewport().lastFrameDrawnSize();
            if (m_grab) {
                f.image = viewport().grabFramebuffer();
            }
            m_frames.push_back(std::move(f));
        });
    }

    void TearDown() override {
        if (m_window) {
            m_window->undoStack().setClean();
            m_window->newProject();
            m_window.reset();
        }
    }

    ui::Viewport& viewport() { return m_window->viewport(); }

    QSize deviceSize() {
        const qreal dpr = viewport().devicePixelRatioF();
        return {qRound(viewport().width() * dpr), qRound(viewport().height() * dpr)};
    }

    void open(const QString& path) {
        auto status = m_window->openProjectFile(path);
        ASSERT_TRUE(status.ok()) << status.error();
        m_window->clock().setPlaying(false);
        ASSERT_TRUE(waitForFrames(*m_window, 1));
        ASSERT_TRUE(viewport().rendererError().isEmpty()) << viewport().rendererError().toStdString();
        runFor(ui::Viewport::kRestMs + 200);
        m_frames.clear();
    }

    // One mouse move of a drag and the frame it causes.
    void moveAndDraw(QPointF at, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
        const int target = viewport().framesRendered() + 1;
        sendMouse(viewport(), QEvent::MouseMove, at, Qt::NoButton, Qt::LeftButton, modifiers);
        ASSERT_TRUE(waitFor([&] { return viewport().framesRendered() >= target; }, 30000));
    }

    // An orbit drag of `steps` moves from the centre; the button is still down at the end.
    void orbitDrag(int steps) {
        const QPointF centre(viewport().width() / 2.0, viewport().height() / 2.0);
        sendMouse(viewport(), QEvent::MouseButtonPress, centre, Qt::LeftButton, Qt::LeftButton);
        for (int i = 1; i <= steps; ++i) {
            moveAndDraw(centre + QPointF(12.0 * i, 5.0 * i));
        }
        m_dragEnd = centre + QPointF(12.0 * steps, 5.0 * steps);
    }
    void release() {
        sendMouse(viewport(), QEvent::MouseButtonRelease, m_dragEnd, Qt::LeftButton, Qt::NoButton);
    }

    // Waits for the view to rest and returns the frames drawn meanwhile.
    std::vector<Frame> rest() {
        const std::size_t before = m_frames.size();
        runFor(ui::Viewport::kRestMs + 600);
        return {m_frames.begin() + std::ptrdiff_t(before), m_frames.end()};
    }

    std::unique_ptr<ui::MainWindow> m_window;
    std::vector<Frame> m_frames;
    bool m_grab = false;
    QPointF m_dragEnd;
};

// View ▸ Show Screen-Space Sources: the screen-space demo's floor, drawn in the colours of where its
// reflection comes from (pure green where the trace meets the image), and a legend; off, none of them.
TEST_F(AdaptiveResolution, ShowScreenSpaceSourcesColoursTheTracedFloor) {
    open(QString::fromStdString(speculum::testSourcePath("resources/scenes/screen-space.speculum.json")));
    QAction* sources = m_window->findChild<QAction*>(QStringLiteral("viewShowScreenSpaceSources"));
    ASSERT_NE(sources, nullptr);
    ASSERT_TRUE(sources->isCheckable());
    EXPECT_FALSE(sources->isChecked()) << "off when the editor starts";
    m_grab = true;
    auto greenAfterAFrame = [&] {
        const int target = viewport().framesRendered() + 1;
        viewport().update();
        EXPECT_TRUE(waitFor([&] { return viewport().framesRendered() >= target; }, 30000));
        runFor(ui::Viewport::kRestMs + 200);
        const QImage image = m_frames.back().image;
        int green = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QRgb c = image.pixel(x, y);
                green += qGreen(c) > 240 && qRed(c) < 20 && qBlue(c) < 20 ? 1 : 0;
            }
        return std::pair{green, image.width() * image.height()};
    };
    sources->setChecked(true);
    EXPECT_TRUE(viewport().screenSpaceSourcesVisible());
    const auto [on, pixels] = greenAfterAFrame();
    EXPECT_GT(on, pixels / 20) << "the floor's pixels that meet the image";
    sources->setChecked(false);
    const auto [off, unused] = greenAfterAFrame();
    EXPECT_EQ(off, 0);
}

TEST_F(AdaptiveResolution, ADragIsDrawnReducedAndTheViewAtRestInFullEqualToAFrameWithoutIt) {
    open(kChromeProject);
    ASSERT_TRUE(viewport().adaptiveResolution()) << "on by default";
    // A budget no frame meets: the preview goes down to its floor of a quarter.
    viewport().setPreviewFrameBudget(0.01);
    m_grab = true;
    orbitDrag(6);
    ASSERT_EQ(m_frames.size(), 6u);
    const QSize full = deviceSize();
    for (const Frame& f : m_frames) {
        EXPECT_TRUE(f.interacting);
        EXPECT_TRUE(f.reduced);
        EXPECT_DOUBLE_EQ(f.scale, ui::Viewport::kMinPreviewScale);
        EXPECT_EQ(f.drawn, QSize(qRound(full.width() * 0.25), qRound(full.height() * 0.25)));
        EXPECT_EQ(f.image.size(), full) << "scaled up to the whole widget";
    }
    const QImage preview = m_frames.back().image;
    release();

    const std::vector<Frame> after = rest();
    ASSERT_EQ(after.size(), 1u) << "one full frame once the view rests, then nothing";
    EXPECT_FALSE(after[0].interacting);
    EXPECT_FALSE(after[0].reduced);
    EXPECT_DOUBLE_EQ(after[0].scale, 1.0);
    EXPECT_EQ(after[0].drawn, full);
    EXPECT_FALSE(viewport().lastFrameReduced());

    // The same view without adaptive resolution.
    viewport().setAdaptiveResolution(false);
    const int target = viewport().framesRendered() + 1;
    viewport().update();
    ASSERT_TRUE(waitFor([&] { return viewport().framesRendered() >= target; }));
    ASSERT_FALSE(m_frames.empty());
    const QImage reference = m_frames.back().image;
    const ImageDifference exact = compareImages(after[0].image, reference);
    EXPECT_EQ(exact.maximum, 0) << "the frame at rest is the full frame (mean difference " << exact.mean
                                << ")";

    // The preview is the same picture at a quarter of the resolution: close on average, nothing wild.
    const ImageDifference approximate = compareImages(preview, reference);
    EXPECT_LT(approximate.mean, 8.0) << "the preview is not the same picture";
}

TEST_F(AdaptiveResolution, AFastFrameNeedsNoPreviewAndNoExtraFrame) {
    open(kChromeProject);
    viewport().setPreviewFrameBudget(1e6); // every frame meets it
    orbitDrag(4);
    release();
    for (const Frame& f : m_frames) {
        EXPECT_FALSE(f.reduced);
        EXPECT_EQ(f.drawn, deviceSize());
    }
    EXPECT_TRUE(rest().empty()) << "what is shown is already the full frame";
}

TEST_F(AdaptiveResolution, OffEveryFrameIsFull) {
    open(kMirrorsProject);
    viewport().setAdaptiveResolution(false);
    viewport().setPreviewFrameBudget(0.01);
    orbitDrag(3);
    release();
    for (const Frame& f : m_frames) {
        EXPECT_FALSE(f.reduced);
        EXPECT_EQ(f.drawn, deviceSize());
    }
    EXPECT_TRUE(rest().empty());
}

TEST_F(AdaptiveResolution, WhenAQuarterIsStillTooSlowMirrorsNestLessDeepUntilTheViewRests) {
    open(kMirrorsProject);
    ASSERT_EQ(m_window->scene().settings().mirrorDepth, 4);
    viewport().setPreviewFrameBudget(0.01); // every frame over it: the floor, then fewer mirror levels
    orbitDrag(8);
    const render::FrameReport preview = viewport().lastReport();
    EXPECT_DOUBLE_EQ(viewport().lastFrameScale(), ui::Viewport::kMinPreviewScale);
    EXPECT_EQ(viewport().lastFrameLevel().mirrorDepthCut, 3) << "down to one level, not below";
    for (const render::MirrorView& view : preview.plan.views) {
        EXPECT_LE(view.depth, 1) << "only mirrors seen directly";
    }
    release();
    const std::vector<Frame> after = rest();
    ASSERT_EQ(after.size(), 1u);
    EXPECT_FALSE(after[0].reduced);
    const std::size_t restMirrors = viewport().lastReport().countRan(render::PassKind::Mirror);
    EXPECT_GT(restMirrors, preview.countRan(render::PassKind::Mirror)) << "the rest frame nests deeper";

    viewport().setAdaptiveResolution(false);
    const int target = viewport().framesRendered() + 1;
    viewport().update();
    ASSERT_TRUE(waitFor([&] { return viewport().framesRendered() >= target; }));
    EXPECT_EQ(viewport().lastReport().countRan(render::PassKind::Mirror), restMirrors)
        << "as deep as without adaptive resolution";
}

TEST_F(AdaptiveResolution, TheWheelAndAHandleDragPreviewToo) {
    open(kChromeProject);
    viewport().setPreviewFrameBudget(0.01);
    const QPointF centre(viewport().width() / 2.0, viewport().height() / 2.0);
    QWheelEvent wheel(centre, viewport().mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    const int target = viewport().framesRendered() + 1;
    QCoreApplication::sendEvent(&viewport(), &wheel);
    ASSERT_TRUE(waitFor([&] { return viewport().framesRendered() >= target; }));
    EXPECT_TRUE(m_frames.back().reduced) << "a zoom step is navigation";
    const std::vector<Frame> afterWheel = rest();
    ASSERT_EQ(afterWheel.size(), 1u);
    EXPECT_FALSE(afterWheel[0].reduced);

    // The first top-level node with a mesh, and its move handle.
    std::optional<speculum::scene::NodeId> node;
    for (const auto& n : m_window->scene().topLevelNodes()) {
        if (n->data().mesh) {
            node = n->id();
            break;
        }
    }
    ASSERT_TRUE(node.has_value());
    m_window->selection().selectNode(*node);
    viewport().setHandleMode(ui::HandleMode::Move);
    ASSERT_TRUE(waitForFrames(*m_window, 1));
    runFor(ui::Viewport::kRestMs + 200);
    const auto handle = viewport().handlePoint(0);
    ASSERT_TRUE(handle.has_value());
    m_frames.clear();
    const int steps = m_window->undoStack().count();
    sendMouse(viewport(), QEvent::MouseButtonPress, *handle, Qt::LeftButton, Qt::LeftButton);
    for (int i = 1; i <= 3; ++i) {
        moveAndDraw(*handle + QPointF(10.0 * i, 0.0));
    }
    const std::vector<render::ShadowPlan> dragShadows = viewport().lastReport().plan.shadows;
    sendMouse(viewport(), QEvent::MouseButtonRelease, *handle + QPointF(30.0, 0.0), Qt::LeftButton,
              Qt::NoButton);
    EXPECT_EQ(m_window->undoStack().count(), steps + 1) << "the drag moved the node";
    for (const Frame& f : m_frames) {
        EXPECT_TRUE(f.reduced);
    }
    const std::vector<Frame> afterDrag = rest();
    ASSERT_FALSE(afterDrag.empty());
    EXPECT_FALSE(afterDrag.back().reduced);
    // The dragged node's shadow is drawn again each frame: at a quarter of the size (never under 256²)
    // while previewing, whole at rest.
    const std::vector<render::ShadowPlan>& restShadows = viewport().lastReport().plan.shadows;
    ASSERT_FALSE(dragShadows.empty()) << "the chrome demo's light casts shadows";
    ASSERT_EQ(dragShadows.size(), restShadows.size());
    for (std::size_t i = 0; i < restShadows.size(); ++i) {
        EXPECT_EQ(dragShadows[i].mapSize,
                  std::min(restShadows[i].mapSize, std::max(256, restShadows[i].mapSize / 4)));
        EXPECT_TRUE(restShadows[i].render) << "drawn again at its own size";
    }
    m_window->undoStack().undo();
}

// ---- a viewport in a window of its own: the actions View ▸ Presets and Show Guides add to a window ----

class ViewportActions : public ::testing::Test {
protected:
    void SetUp() override {
        m_clock = std::make_unique<view::AnimationClock>();
        m_viewport = new ui::Viewport(m_scene, m_meshes, *m_clock, &m_host);
        m_host.resize(640, 400);
        m_viewport->resize(640, 400);
        ui::addViewPresetActions(m_host, nullptr, *m_viewport);
        m_host.show();
        ASSERT_TRUE(waitFor([&] { return m_host.windowHandle() && m_host.windowHandle()->isExposed(); }));
        ASSERT_TRUE(waitFor([&] { return m_viewport->framesRendered() > 0; }));
    }

    QAction* action(const char* name) { return m_host.findChild<QAction*>(QString::fromLatin1(name)); }

    glm::dvec3 looking() const {
        const render::Camera& c = m_viewport->viewCamera();
        return glm::normalize(c.target - c.position);
    }

    speculum::scene::Scene m_scene;
    speculum::scene::MeshLibrary m_meshes;
    std::unique_ptr<view::AnimationClock> m_clock;
    QWidget m_host;
    ui::Viewport* m_viewport = nullptr;
};

TEST_F(ViewportActions, NumpadKeysTurnTheViewAroundItsTarget) {
    const glm::dvec3 target = m_viewport->viewCamera().target;
    struct Case {
        const char* name;
        int key;
        Qt::KeyboardModifiers modifiers;
        view::ViewPreset preset;
    };
    const Case cases[] = {
        {"viewRight", Qt::Key_3, Qt::KeypadModifier, view::ViewPreset::Right},
        {"viewTop", Qt::Key_7, Qt::KeypadModifier, view::ViewPreset::Top},
        {"viewBottom", Qt::Key_7, Qt::KeypadModifier | Qt::ControlModifier, view::ViewPreset::Bottom},
        {"viewLeft", Qt::Key_3, Qt::KeypadModifier | Qt::ControlModifier, view::ViewPreset::Left},
        {"viewBack", Qt::Key_1, Qt::KeypadModifier | Qt::ControlModifier, view::ViewPreset::Back},
        {"viewFront", Qt::Key_1, Qt::KeypadModifier, view::ViewPreset::Front},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        QAction* a = action(c.name);
        ASSERT_NE(a, nullptr);
        EXPECT_EQ(a->shortcut(), QKeySequence(int(c.modifiers) | c.key));
        const int frames = m_viewport->framesRendered();
        a->trigger(); // what the shortcut does (a key event's routing to the window is Qt's)
        EXPECT_GT(glm::dot(looking(), view::presetDirection(c.preset)), 0.999);
        EXPECT_NEAR(glm::length(m_viewport->viewCamera().target - target), 0.0, 1e-9) << "same pivot";
        EXPECT_TRUE(waitFor([&] { return m_viewport->framesRendered() > frames; }, 30000)) << "drawn";
    }
    EXPECT_TRUE(m_scene.camera() == speculum::scene::CameraData{}) << "the scene camera is not edited";
}

TEST_F(ViewportActions, ShowGuidesTogglesTheGuides) {
    QAction* guides = action("viewShowGuides");
    ASSERT_NE(guides, nullptr);
    ASSERT_TRUE(guides->isCheckable());
    EXPECT_EQ(guides->isChecked(), m_viewport->guidesVisible());
    guides->setChecked(true);
    EXPECT_TRUE(m_viewport->guidesVisible());
    action("viewTop")->trigger(); // looking down at the ground grid
    auto guidesPasses = [&] { return m_viewport->lastReport().countRan(render::PassKind::Guides); };
    ASSERT_TRUE(waitFor([&] { return guidesPasses() == 1u; }, 30000)) << "the grid is drawn in the frame";
    guides->setChecked(false);
    EXPECT_FALSE(m_viewport->guidesVisible());
    EXPECT_TRUE(waitFor([&] { return guidesPasses() == 0u; }, 30000)) << "a frame without them follows";
    guides->setChecked(true);
    EXPECT_TRUE(waitFor([&] { return guidesPasses() == 1u; }, 30000));
}

// ---- the guides in the window: a grid line never crosses an opaque object standing in front of it ----

// A tall red box on the ground, no floor, seen from the scene camera, which looks past it (the pivot mark
// is beside the box): the ground grid lies behind and around the box.
constexpr const char* kBoxOnGroundProject = R"({
  "format": "speculum-scene", "version": 1,
  "settings": {"background": [0.02, 0.02, 0.03], "mirrorDepth": 1, "ambient": 0.6},
  "camera": {"position": [0, 1.4, 5], "target": [0.9, 0.5, 0], "up": [0, 1, 0], "fovY": 50, "near": 0.1,
             "far": 60},
  "nodes": [
    {"name": "Box", "transform": {"translate": [0, 0.9, -0.5], "rotate": [0, 0, 0], "scale": [0.6, 0.9, 0.6]},
     "mesh": {"builtin": "box", "tessellation": 1},
     "material": {"color": [0.9, 0.05, 0.05], "ambient": 1, "diffuse": 1, "specular": 0, "shininess": 8,
                  "emission": [0, 0, 0]}}
  ]
})";

bool isBoxRed(QRgb c) {
    return qRed(c) > 120 && qGreen(c) < qRed(c) / 2 && qBlue(c) < qRed(c) / 2;
}

// Pixels well inside the box: red, and red for two pixels around (no anti-aliased edge).
std::vector<QPoint> insideBox(const QImage& image) {
    std::vector<QPoint> inside;
    for (int y = 2; y < image.height() - 2; ++y)
        for (int x = 2; x < image.width() - 2; ++x) {
            bool all = true;
            for (int dy = -2; dy <= 2 && all; ++dy)
                for (int dx = -2; dx <= 2 && all; ++dx)
                    all = isBoxRed(image.pixel(x + dx, y + dy));
            if (all)
                inside.push_back({x, y});
        }
    return inside;
}

int channelDifference(QRgb a, QRgb b) {
    return std::max(
        {std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)), std::abs(qBlue(a) - qBlue(b))});
}

TEST_F(AdaptiveResolution, AGridLineNeverCrossesAnOpaqueObjectInFrontOfIt) {
    const QString folder = QDir::temp().filePath(QStringLiteral("speculum-guides-test"));
    QDir(folder).removeRecursively();
    ASSERT_TRUE(QDir().mkpath(folder));
    const QString path = QDir(folder).filePath(QStringLiteral("box.speculum.json"));
    {
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(kBoxOnGroundProject);
    }
    open(path);
    auto screenshot = [&](bool guides) {
        viewport().setGuidesVisible(guides);
        const int frames = viewport().framesRendered();
        viewport().update();
        EXPECT_TRUE(waitFor([&] { return viewport().framesRendered() > frames; }, 30000));
        runFor(100);
        return m_window->grab(QRect(viewport().mapTo(m_window.get(), QPoint(0, 0)), viewport().size()))
            .toImage()
            .convertToFormat(QImage::Format_RGB32);
    };
    const QImage without = screenshot(false);
    const QImage with = screenshot(true);
    ASSERT_EQ(without.size(), with.size());
    const std::vector<QPoint> box = insideBox(without);
    ASSERT_GT(box.size(), 1000u) << "the box is on screen";
    int crossing = 0;
    for (const QPoint& p : box)
        crossing += channelDifference(without.pixel(p), with.pixel(p)) > 2 ? 1 : 0;
    EXPECT_EQ(crossing, 0) << "pixels of the box that a guide changed";
    int grid = 0;
    for (int y = 0; y < with.height(); ++y)
        for (int x = 0; x < with.width(); ++x)
            grid += channelDifference(without.pixel(x, y), with.pixel(x, y)) > 8 ? 1 : 0;
    EXPECT_GT(grid, 1000) << "the grid shows around the box";
    QDir(folder).removeRecursively();
}

TEST_F(ViewportActions, VerticalOrbitFollowsTheMouseUnlessInverted) {
    const QPointF centre(m_viewport->width() / 2.0, m_viewport->height() / 2.0);
    auto dragDown = [&] {
        m_viewport->resetView();
        const double before = m_viewport->viewCamera().position.y;
        sendMouse(*m_viewport, QEvent::MouseButtonPress, centre, Qt::LeftButton, Qt::LeftButton);
        sendMouse(*m_viewport, QEvent::MouseMove, centre + QPointF(0.0, 10.0), Qt::NoButton, Qt::LeftButton);
        sendMouse(*m_viewport, QEvent::MouseMove, centre + QPointF(0.0, 40.0), Qt::NoButton, Qt::LeftButton);
        sendMouse(*m_viewport, QEvent::MouseButtonRelease, centre + QPointF(0.0, 40.0), Qt::LeftButton,
                  Qt::NoButton);
        return m_viewport->viewCamera().position.y - before;
    };
    EXPECT_FALSE(m_viewport->invertsVerticalOrbit());
    EXPECT_GT(dragDown(), 0.0) << "dragging down raises the camera, as in Blender";
    m_viewport->setInvertVerticalOrbit(true);
    EXPECT_LT(dragDown(), 0.0) << "inverted";
    m_viewport->setInvertVerticalOrbit(false);
}

TEST_F(ViewportActions, ASavedViewIsPlacedAfterTheResetOfANewDocument) {
    // A caller that puts the document's saved editor view back, connected after the viewport exists.
    const glm::dvec3 position(2.0, 3.0, 4.0), target(0.0, 0.5, 0.0);
    int resets = 0;
    QObject::connect(m_viewport, &ui::Viewport::viewReset, m_viewport, [&] {
        ++resets;
        m_viewport->placeView(position, target);
    });
    speculum::scene::SceneData data;
    data.camera.position = {0.0, 1.0, 9.0};
    m_scene.reset(std::move(data));
    EXPECT_EQ(resets, 1);
    const auto [p, t] = m_viewport->viewPositionTarget();
    EXPECT_EQ(p, position);
    EXPECT_EQ(t, target);
    EXPECT_EQ(m_viewport->viewCamera().up, m_viewport->sceneCamera().up);

    // A caller connected to Scene::sceneReset itself, after the viewport: its placement stays too.
    QObject::connect(&m_scene, &speculum::scene::Scene::sceneReset, m_viewport, [&] {
        m_viewport->placeView({5.0, 5.0, 5.0}, {0.0, 0.0, 0.0});
    });
    m_scene.reset(speculum::scene::SceneData{});
    EXPECT_EQ(m_viewport->viewPositionTarget().first, glm::dvec3(5.0, 5.0, 5.0));
    // Double-click still goes back to the scene camera.
    m_viewport->resetView();
    EXPECT_EQ(m_viewport->viewPositionTarget().first, m_viewport->sceneCamera().position);
}

} // namespace

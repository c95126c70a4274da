// The editor window on the reference project: it opens, the viewport draws the teapot on the marble table
// where the scene's camera puts them, edits mark the title as modified and undo clears it, and a broken
// file leaves the open document alone.
#include "editor/document/Commands.hpp"
#include "editor/document/NewScene.hpp"
#include "editor/ui/AppIdentity.hpp"
#include "editor/ui/MainWindow.hpp"
#include "editor/ui/Viewport.hpp"
#include "editor/view/AnimationClock.hpp"
#include "scene/model/Scene.hpp"
#include "support/TestPaths.hpp"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QMouseEvent>
#include <QPixmap>
#include <QTemporaryDir>
#include <QThread>
#include <QUndoStack>
#include <QWindow>
#include <cmath>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <optional>

namespace {

using speculum::scene::NodeId;
using speculum::ui::MainWindow;

const QString kTeapotProject =
    QString::fromStdString(speculum::testSourcePath("resources/scenes/teapot.speculum.json"));

bool waitFor(const std::function<bool()>& condition, int timeoutMs = 60000) {
    QElapsedTimer timer;
    timer.start();
    while (!condition()) {
        if (timer.elapsed() > timeoutMs) {
            return false;
        }
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        QThread::msleep(2);
    }
    return true;
}

// Waits until the viewport has drawn at least `frames` more frames than now.
bool waitForFrames(MainWindow& window, int frames = 2) {
    const int target = window.viewport().framesRendered() + frames;
    return waitFor([&] {
        window.viewport().update(); // paused: the viewport only draws on demand
        return window.viewport().framesRendered() >= target;
    });
}

double srgbEncode(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

struct Rgb {
    double r = 0, g = 0, b = 0;
    double luminance() const { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }
    double distance(const Rgb& o) const {
        return std::max({std::abs(r - o.r), std::abs(g - o.g), std::abs(b - o.b)});
    }
};

Rgb pixel(const QImage& image, QPoint p) {
    const QRgb c = image.pixel(p);
    return {double(qRed(c)), double(qGreen(c)), double(qBlue(c))};
}

// Mean colour of a small square around p (clamped to the image).
Rgb patch(const QImage& image, QPoint p, int radius = 3) {
    Rgb sum;
    int n = 0;
    for (int y = p.y() - radius; y <= p.y() + radius; ++y) {
        for (int x = p.x() - radius; x <= p.x() + radius; ++x) {
            if (image.rect().contains(x, y)) {
                const Rgb c = pixel(image, {x, y});
                sum.r += c.r, sum.g += c.g, sum.b += c.b;
                ++n;
            }
        }
    }
    return n ? Rgb{sum.r / n, sum.g / n, sum.b / n} : Rgb{};
}

class MainWindowTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(QFile::exists(kTeapotProject)) << kTeapotProject.toStdString();
        m_window = std::make_unique<MainWindow>();
        // Wide enough that the viewport between the docks keeps the aspect these checks assume (~1000×650).
        m_window->resize(1600, 760);
        m_window->show();
        ASSERT_TRUE(
            waitFor([&] { return m_window->windowHandle() && m_window->windowHandle()->isExposed(); }));
        // A still frame: the teapot rests on the table at t = 0.
        m_window->clock().setPlaying(false);
        m_window->clock().setTime(0.0);
    }

    void TearDown() override {
        if (m_window) {
            m_window->undoStack().setClean(); // no unsaved-changes prompt on close
            m_window.reset();
        }
    }

    void openTeapot() {
        auto status = m_window->openProjectFile(kTeapotProject);
        ASSERT_TRUE(status.ok()) << status.error();
        ASSERT_TRUE(waitForFrames(*m_window)) << "the viewport did not draw";
        ASSERT_TRUE(m_window->viewport().rendererError().isEmpty())
            << m_window->viewport().rendererError().toStdString();
    }

    QImage frame() { return m_window->viewport().grabFramebuffer().convertToFormat(QImage::Format_RGB32); }

    std::optional<NodeId> nodeNamed(const std::string& name) {
        std::optional<NodeId> found;
        m_window->scene().forEachNode([&](const speculum::scene::Node& node) {
            if (node.name() == name && !found) {
                found = node.id();
            }
        });
        return found;
    }

    // Where a world point lands in the framebuffer, with the document's camera (the viewport shows it
    // until the user navigates).
    QPoint project(const glm::dvec3& world, const QSize& size) {
        const auto& cam = m_window->scene().camera();
        const glm::dmat4 view = glm::lookAt(cam.position, cam.target, cam.up);
        const glm::dmat4 proj =
            glm::perspective(glm::radians(cam.fovY), double(size.width()) / size.height(), cam.near, cam.far);
        const glm::dvec4 clip = proj * view * glm::dvec4(world, 1.0);
        const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
        return {int(std::lround((ndc.x * 0.5 + 0.5) * size.width())),
                int(std::lround((0.5 - ndc.y * 0.5) * size.height()))};
    }

    Rgb background() {
        const auto& bg = m_window->scene().settings().background;
        return {255.0 * srgbEncode(bg.r), 255.0 * srgbEncode(bg.g), 255.0 * srgbEncode(bg.b)};
    }

    std::unique_ptr<MainWindow> m_window;
};

TEST_F(MainWindowTest, DrawsTheTeapotOnTheMarbleTable) {
    openTeapot();
    EXPECT_EQ(m_window->scene().topLevelNodes().size(), 3u);

    const QImage image = frame();
    ASSERT_FALSE(image.isNull());
    const Rgb bg = background();
    const QSize size = image.size();

    // Let people look at it.
    const QString shot = QString::fromStdString(speculum::testDataPath("editor-teapot.png"));
    EXPECT_TRUE(m_window->grab().save(shot)) << shot.toStdString();
    image.save(QString::fromStdString(speculum::testDataPath("editor-teapot-viewport.png")));

    // The sky above everything is the scene's background colour (sRGB-encoded by the renderer).
    for (double fx : {0.05, 0.5, 0.95}) {
        const Rgb c = patch(image, {int(fx * size.width()), int(0.08 * size.height())});
        EXPECT_LT(c.distance(bg), 6.0) << "top at x=" << fx << ": " << c.r << "," << c.g << "," << c.b;
    }

    int nonBackground = 0;
    for (int y = 0; y < size.height(); y += 4) {
        for (int x = 0; x < size.width(); x += 4) {
            nonBackground += pixel(image, {x, y}).distance(bg) > 12.0;
        }
    }
    const double coverage = double(nonBackground) / ((size.height() / 4) * (size.width() / 4));
    EXPECT_GT(coverage, 0.08) << "almost nothing but background was drawn";
    EXPECT_LT(coverage, 0.9) << "the background is missing";

    // The teapot: points along its body's axis (local y 0.6..1.8 of Newell's teapot, 0.25 scale) differ
    // from the background, while at the same height far to the side there is only background.
    const auto teapot = nodeNamed("Teapot");
    ASSERT_TRUE(teapot);
    const auto& tf = m_window->scene().findNode(*teapot)->data().transform;
    int teapotHits = 0, teapotSamples = 0;
    for (double localY = 0.6; localY <= 1.8; localY += 0.1) {
        const QPoint p = project(tf.translate + glm::dvec3(0.0, localY * tf.scale.y, 0.0), size);
        ASSERT_TRUE(image.rect().contains(p));
        ++teapotSamples;
        teapotHits += patch(image, p, 1).distance(bg) > 20.0;
        const Rgb side = patch(image, {int(0.04 * size.width()), p.y()});
        EXPECT_LT(side.distance(bg), 6.0) << "left edge at row " << p.y();
    }
    EXPECT_GE(teapotHits, teapotSamples * 9 / 10) << "teapot body missing at the projected position";

    // The table: marble in front of the teapot is brightly lit, much brighter than the background; just in
    // front of its near edge there is background again.
    const auto table = nodeNamed("Table");
    ASSERT_TRUE(table);
    const auto& tableData = m_window->scene().findNode(*table)->data();
    const auto& tt = tableData.transform;
    // The table is a mirror rectangle (or a [-1,1]² plane): its half extents, scaled.
    const glm::dvec2 half = tableData.mirror ? tableData.mirror->size * 0.5 : glm::dvec2(1.0);
    const glm::dvec3 extent(half.x * tt.scale.x, 0.0, half.y * tt.scale.z);
    // Sample the front half, left and right of the centre line.
    for (double fx : {-0.5, 0.0, 0.5}) {
        const glm::dvec3 onTable = tt.translate + glm::dvec3(fx * extent.x, 0.0, 0.7 * extent.z);
        const QPoint p = project(onTable, size);
        ASSERT_TRUE(image.rect().contains(p));
        const Rgb c = patch(image, p, 4);
        EXPECT_GT(c.luminance(), 110.0) << "table at x=" << fx << ": " << c.r << "," << c.g << "," << c.b;
        EXPECT_GT(c.luminance(), bg.luminance() + 50.0);
    }
    const QPoint beyond = project(tt.translate + glm::dvec3(0.0, 0.0, 1.15 * extent.z), size);
    if (image.rect().contains(beyond)) {
        EXPECT_LT(patch(image, beyond, 2).distance(bg), 6.0) << "in front of the table";
    }

    // The status bar reports the frame.
    EXPECT_GE(m_window->viewport().lastReport().cpuMs, 0.0);
}

TEST_F(MainWindowTest, UndoableEditMarksTitleAndUndoClearsIt) {
    openTeapot();
    QWindow* handle = m_window->windowHandle();
    ASSERT_NE(handle, nullptr);
    EXPECT_EQ(handle->title(), QStringLiteral("teapot.speculum.json — speculum"));
    EXPECT_FALSE(m_window->isWindowModified());

    const auto teapot = nodeNamed("Teapot");
    ASSERT_TRUE(teapot);
    const glm::dvec3 tf = m_window->scene().findNode(*teapot)->data().transform.translate;
    const double scaleY = m_window->scene().findNode(*teapot)->data().transform.scale.y;
    // The teapot's body where it is now: the viewport can change size between frames (the docks and the
    // status bar re-layout when the title or messages change), so project with the current size.
    auto bodyPatch = [&] {
        const QImage image = frame();
        return patch(image, project(tf + glm::dvec3(0.0, 1.2 * scaleY, 0.0), image.size()), 2);
    };
    ASSERT_TRUE(waitForFrames(*m_window));
    const Rgb before = bodyPatch();

    auto data = m_window->scene().findNode(*teapot)->data();
    ASSERT_TRUE(data.material);
    data.material->color = {1.0, 0.05, 0.05};
    m_window->undoStack().push(new speculum::document::SetNodeDataCommand(m_window->scene(), *teapot, data,
                                                                          QStringLiteral("Colour")));

    EXPECT_TRUE(m_window->isWindowModified());
    EXPECT_EQ(handle->title(), QStringLiteral("teapot.speculum.json* — speculum"));
    ASSERT_TRUE(waitForFrames(*m_window));
    const Rgb red = bodyPatch();
    EXPECT_GT(red.r - red.g, 40.0) << "the edit did not reach the viewport: " << red.r << "," << red.g;

    m_window->undoStack().undo();
    EXPECT_FALSE(m_window->isWindowModified());
    EXPECT_EQ(handle->title(), QStringLiteral("teapot.speculum.json — speculum"));
    ASSERT_TRUE(waitForFrames(*m_window));
    const Rgb after = bodyPatch();
    EXPECT_LT(after.distance(before), 4.0) << "undo did not restore the picture";
}

// A reflector whose map would take minutes a frame on this software renderer (2048², pre-filtered with
// 1024 samples, redrawn every frame: about 90 s) does not hold the window: the first frame comes at once,
// the map drawn smaller, and the editor says so and by how much.
TEST_F(MainWindowTest, ACostlyMapIsDrawnSmallerWhileEditingAndSaysSo) {
    const QString chrome = QFileInfo(kTeapotProject).absolutePath() + QStringLiteral("/chrome.speculum.json");
    ASSERT_TRUE(m_window->openProjectFile(chrome).ok());
    speculum::scene::SceneSettings settings = m_window->scene().settings();
    settings.prefilterSamples = 1024;
    m_window->scene().setSettings(settings);
    const auto ball = nodeNamed("Chrome ball");
    ASSERT_TRUE(ball.has_value());
    speculum::scene::NodeData data = m_window->scene().findNode(*ball)->data();
    data.reflector->resolution = 2048;
    data.reflector->roughness = 0.5;
    data.reflector->update = speculum::render::ReflectorUpdate::Always;
    m_window->scene().setNodeData(*ball, data);

    QElapsedTimer clock;
    clock.start();
    ASSERT_TRUE(waitForFrames(*m_window, 1));
    EXPECT_LT(clock.elapsed(), 30000) << "the first frame did not wait for the whole map";
    const speculum::render::FrameReport& report = m_window->viewport().lastReport();
    EXPECT_LT(report.plan.reflectorResolution(0), 2048);
    bool said = false;
    for (const std::string& w : report.warnings) {
        said =
            said || (w.find("while editing") != std::string::npos && w.find("roughly") != std::string::npos);
    }
    EXPECT_TRUE(said) << "the editor says the map is drawn smaller, and what the full one would cost";
}

TEST_F(MainWindowTest, BrokenFileKeepsTheOpenDocument) {
    openTeapot();
    const auto dataBefore = m_window->scene().toData();
    const QString pathBefore = m_window->scene().projectPath();
    const QString titleBefore = m_window->windowHandle()->title();

    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    struct Case {
        const char* file;
        QByteArray contents;
        const char* mentions; // what the error must name
    };
    const Case cases[] = {
        {"bad-size.speculum.json",
         R"({"format": "speculum-scene", "version": 1,
             "nodes": [ {"name": "Ok"}, {"name": "Mirror", "mirror": {"size": [1]}} ]})",
         "nodes[1].mirror.size"},
        {"truncated.speculum.json", R"({"format": "speculum-scene", "version": 1, "nodes": [)", ""},
        {"missing.speculum.json", {}, ""},
    };
    for (const Case& c : cases) {
        const QString path = dir.filePath(QString::fromLatin1(c.file));
        if (!c.contents.isNull()) {
            QFile f(path);
            ASSERT_TRUE(f.open(QIODevice::WriteOnly));
            f.write(c.contents);
        }
        auto status = m_window->openProjectFile(path);
        ASSERT_FALSE(status.ok()) << c.file;
        EXPECT_FALSE(status.error().empty()) << c.file;
        EXPECT_NE(status.error().find(c.mentions), std::string::npos) << c.file << ": " << status.error();

        EXPECT_TRUE(m_window->scene().toData() == dataBefore) << c.file << " changed the open document";
        EXPECT_EQ(m_window->scene().projectPath(), pathBefore);
        EXPECT_EQ(m_window->windowHandle()->title(), titleBefore);
        EXPECT_TRUE(m_window->logLines().back().contains(QString::fromStdString(status.error())));
    }
    // Still drawing.
    EXPECT_TRUE(waitForFrames(*m_window));
}

TEST_F(MainWindowTest, NewAndSaveAs) {
    openTeapot();
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString copy = dir.filePath(QStringLiteral("copy.speculum.json"));
    auto saved = m_window->saveProjectFile(copy);
    ASSERT_TRUE(saved.ok()) << saved.error();
    EXPECT_EQ(m_window->windowHandle()->title(), QStringLiteral("copy.speculum.json — speculum"));

    m_window->newProject();
    EXPECT_TRUE(m_window->scene().toData() == speculum::document::newSceneData())
        << "a floor, a sun, a raised camera";
    EXPECT_FALSE(m_window->isWindowModified());
    EXPECT_EQ(m_window->undoStack().count(), 0);
    EXPECT_EQ(m_window->windowHandle()->title(), QStringLiteral("Untitled — speculum"));
    ASSERT_TRUE(waitForFrames(*m_window));

    auto reopened = m_window->openProjectFile(copy);
    ASSERT_TRUE(reopened.ok()) << reopened.error();
    EXPECT_EQ(m_window->scene().topLevelNodes().size(), 3u);
}

// File ▸ Open Example… opens the dialog in the example projects' folder: here, run from the build folder,
// the source tree's (installed, <prefix>/share/speculum/scenes; tests/install checks that layout).
TEST_F(MainWindowTest, OpenExampleFindsTheExampleProjects) {
    QAction* openExample = m_window->findChild<QAction*>(QStringLiteral("actionOpenExample"));
    ASSERT_NE(openExample, nullptr);
    EXPECT_EQ(openExample->text(), QStringLiteral("Open &Example…"));
    const QString folder = speculum::ui::examplesFolder();
    ASSERT_FALSE(folder.isEmpty());
    for (const char* demo : {"teapot", "mirrors", "chrome", "models"}) {
        EXPECT_TRUE(QFile::exists(folder + QStringLiteral("/%1.speculum.json").arg(QLatin1String(demo))))
            << demo;
    }
    EXPECT_FALSE(speculum::ui::applicationIcon().isNull()) << "a window icon, installed or not";
    EXPECT_FALSE(speculum::ui::applicationIcon().pixmap(64).isNull());
}

TEST_F(MainWindowTest, PlayingAnimatesWithoutBeingAsked) {
    openTeapot();
    const int start = m_window->viewport().framesRendered();
    m_window->clock().setPlaying(true);
    // No update() calls here: the viewport's own timer must keep drawing while the clock runs.
    ASSERT_TRUE(waitFor([&] { return m_window->viewport().framesRendered() >= start + 4; }));
    const double t1 = m_window->viewport().lastFrameTime();
    ASSERT_TRUE(waitFor([&] { return m_window->viewport().lastFrameTime() > t1; }));
    EXPECT_GT(m_window->viewport().lastFrameTime(), 0.0);

    m_window->clock().setPlaying(false);
    const double paused = m_window->clock().time();
    ASSERT_TRUE(waitForFrames(*m_window));
    EXPECT_DOUBLE_EQ(m_window->viewport().lastFrameTime(), paused);
}

TEST_F(MainWindowTest, MouseOrbitMovesOnlyTheView) {
    openTeapot();
    const auto cameraBefore = m_window->scene().camera();
    const QImage before = frame();

    speculum::ui::Viewport& viewport = m_window->viewport();
    const QPointF from(viewport.width() * 0.5, viewport.height() * 0.5);
    const QPointF to = from + QPointF(viewport.width() * 0.2, 0.0);
    QMouseEvent press(QEvent::MouseButtonPress, from, viewport.mapToGlobal(from), Qt::LeftButton,
                      Qt::LeftButton, Qt::NoModifier);
    QMouseEvent move(QEvent::MouseMove, to, viewport.mapToGlobal(to), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QMouseEvent release(QEvent::MouseButtonRelease, to, viewport.mapToGlobal(to), Qt::LeftButton,
                        Qt::NoButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&viewport, &press);
    QCoreApplication::sendEvent(&viewport, &move);
    QCoreApplication::sendEvent(&viewport, &release);
    ASSERT_TRUE(waitForFrames(*m_window));
    const QImage orbited = frame();

    int changed = 0;
    for (int y = 0; y < before.height(); y += 4) {
        for (int x = 0; x < before.width(); x += 4) {
            changed += pixel(before, {x, y}).distance(pixel(orbited, {x, y})) > 20.0;
        }
    }
    EXPECT_GT(changed, 200) << "the view did not move";
    EXPECT_TRUE(m_window->scene().camera() == cameraBefore) << "navigation changed the document";
    EXPECT_TRUE(m_window->undoStack().isClean());
    EXPECT_FALSE(m_window->isWindowModified());

    viewport.resetView();
    ASSERT_TRUE(waitForFrames(*m_window));
    const QImage reset = frame();
    EXPECT_LT(patch(reset, {reset.width() / 2, reset.height() / 2}, 20)
                  .distance(patch(before, {before.width() / 2, before.height() / 2}, 20)),
              2.0);
}

} // namespace

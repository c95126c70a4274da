// What the editor shows and writes: an inspector edit reaches the viewport's pixels, the render passes
// panel lists the live plan, Export Still writes the same pixels as `speculum render` (and, with the exact
// reference, as `speculum render --reference`) for the same file and settings (and a cancel writes
// nothing), the dialog states its time, and pictures of the window with each demo scene.
#include "editor/ui/ExportStillDialog.hpp"
#include "editor/ui/Gizmo.hpp"
#include "editor/ui/Inspector.hpp"
#include "editor/ui/PropertyEditors.hpp"
#include "editor/ui/RenderPassesPanel.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <OpenImageIO/imageio.h>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QScreen>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QWindow>
#include <algorithm>
#include <gtest/gtest.h>
#include <map>
#include <optional>

namespace {

using namespace speculum;
using namespace speculum::ui::test;
using speculum::scene::NodeId;
using ui::MainWindow;

const QString kScenes = QString::fromStdString(speculum::testSourcePath("resources/scenes"));
const QString kTeapotProject = kScenes + QStringLiteral("/teapot.speculum.json");
const QString kFacingBallsProject = kScenes + QStringLiteral("/facing-balls.speculum.json");

class EditorOutput : public ::testing::Test {
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
            m_window->newProject();
            m_window.reset();
        }
    }

    void open(const QString& path) {
        auto status = m_window->openProjectFile(path);
        ASSERT_TRUE(status.ok()) << status.error();
        ASSERT_TRUE(waitForFrames(*m_window));
        ASSERT_TRUE(m_window->viewport().rendererError().isEmpty());
    }

    std::optional<NodeId> nodeNamed(const std::string& name) {
        std::optional<NodeId> found;
        m_window->scene().forEachNode([&](const speculum::scene::Node& node) {
            if (node.name() == name && !found) {
                found = node.id();
            }
        });
        return found;
    }

    QImage frame() { return m_window->viewport().grabFramebuffer().convertToFormat(QImage::Format_RGB32); }

    QPoint onFramebuffer(const glm::dvec3& world, QSize size) {
        ui::ScreenProjection projection(m_window->viewport().viewCamera(), QSizeF(size));
        const auto p = projection.project(world);
        EXPECT_TRUE(p.has_value());
        return p ? p->toPoint() : QPoint();
    }

    std::unique_ptr<MainWindow> m_window;
};

TEST_F(EditorOutput, AnInspectorEditChangesTheViewport) {
    open(kTeapotProject);
    const NodeId teapot = *nodeNamed("Teapot");
    m_window->selection().selectNode(teapot);
    ASSERT_TRUE(waitForFrames(*m_window));
    const QImage before = frame();
    const QPoint body = onFramebuffer({0.0, -1.0 + 1.2 * 0.25, -3.0}, before.size());
    const Rgb grey = patch(before, body, 2);

    ui::PropertyEditor* color = m_window->inspector().editor(QStringLiteral("material.color"));
    ASSERT_NE(color, nullptr);
    color->findChild<QDoubleSpinBox*>(QStringLiteral("material.color.g"))->setValue(0.05);
    color->findChild<QDoubleSpinBox*>(QStringLiteral("material.color.b"))->setValue(0.05);
    color->findChild<QDoubleSpinBox*>(QStringLiteral("material.color.r"))->setValue(1.0);
    EXPECT_EQ(m_window->scene().findNode(teapot)->data().material->color, glm::dvec3(1.0, 0.05, 0.05));
    ASSERT_TRUE(waitForFrames(*m_window));
    const Rgb red = patch(frame(), body, 2);
    EXPECT_GT(red.r - red.g, 40.0) << "grey " << grey.r << "," << grey.g << " → " << red.r << "," << red.g;
    EXPECT_LT(grey.r - grey.g, 10.0);

    // The shininess slider: a darker or brighter highlight, and emission lifts the whole body.
    color = m_window->inspector().editor(QStringLiteral("material.emission"));
    color->findChild<QDoubleSpinBox*>(QStringLiteral("material.emission.b"))->setValue(1.0);
    ASSERT_TRUE(waitForFrames(*m_window));
    const Rgb glowing = patch(frame(), body, 2);
    EXPECT_GT(glowing.b, red.b + 60.0);
}

TEST_F(EditorOutput, RenderPassesPanelShowsTheLivePlan) {
    open(kTeapotProject);
    // A moment later the light has moved on its orbit: its shadow map is drawn again in the next frame
    // (and reused by the frames after it, while nothing moves).
    std::vector<render::FrameReport> reports;
    const auto connection =
        QObject::connect(&m_window->viewport(), &ui::Viewport::frameRendered,
                         [&](const render::FrameReport& r, double) { reports.push_back(r); });
    m_window->clock().setTime(0.5);
    ASSERT_TRUE(waitForFrames(*m_window));
    QObject::disconnect(connection);
    ASSERT_FALSE(reports.empty());
    const render::FrameReport report = reports.front();
    ASSERT_FALSE(report.ran.empty());
    m_window->passesPanel().showReportNow(report);
    QTreeWidget& tree = m_window->passesPanel().tree();
    ASSERT_EQ(tree.topLevelItemCount(), 2);
    EXPECT_TRUE(tree.headerItem()->toolTip(2).contains(QStringLiteral("software renderer")))
        << "the GPU column says what its times mean without a graphics card";
    // The passes that ran, in order, each with the plan's reason and what running it found.
    QTreeWidgetItem* passes = tree.topLevelItem(0);
    ASSERT_EQ(passes->childCount(), int(report.ran.size()));
    bool sawShadow = false, sawMain = false;
    for (int i = 0; i < passes->childCount(); ++i) {
        const QTreeWidgetItem* item = passes->child(i);
        const render::PassRun& run = report.ran[std::size_t(i)];
        EXPECT_FALSE(item->text(3).isEmpty()) << "every pass says why it ran";
        EXPECT_EQ(item->text(3).toStdString(), report.reason(run));
        EXPECT_EQ(item->text(1).toStdString(), report.planned(run).target);
        sawShadow |= item->text(0) == QStringLiteral("shadow") && item->text(1) == QStringLiteral("Light");
        sawMain |= item->text(0) == QStringLiteral("main");
    }
    EXPECT_TRUE(sawShadow);
    EXPECT_TRUE(sawMain);
    EXPECT_EQ(tree.topLevelItem(1)->childCount(), int(report.skipped.size()));

    // Turning the light's shadows off removes its shadow pass from the live plan.
    m_window->selection().selectNode(*nodeNamed("Light"));
    ASSERT_TRUE(m_window->inspector().applyValue(QStringLiteral("light.shadows"), false).ok());
    reports.clear();
    const auto again = QObject::connect(&m_window->viewport(), &ui::Viewport::frameRendered,
                                        [&](const render::FrameReport& r, double) { reports.push_back(r); });
    m_window->clock().setTime(1.0);
    ASSERT_TRUE(waitForFrames(*m_window));
    QObject::disconnect(again);
    ASSERT_FALSE(reports.empty());
    m_window->passesPanel().showReportNow(reports.front());
    for (int i = 0; i < tree.topLevelItem(0)->childCount(); ++i) {
        EXPECT_NE(tree.topLevelItem(0)->child(i)->text(0), QStringLiteral("shadow"));
    }
}

// Several reflectors with bounces: the panel groups the maps of each bounce, one row per reflector in it.
TEST_F(EditorOutput, RenderPassesPanelGroupsTheMapsPerBounce) {
    std::vector<render::FrameReport> reports;
    const auto connection =
        QObject::connect(&m_window->viewport(), &ui::Viewport::frameRendered,
                         [&](const render::FrameReport& r, double) { reports.push_back(r); });
    open(kFacingBallsProject);
    ASSERT_TRUE(waitForFrames(*m_window));
    QObject::disconnect(connection);
    const auto drawsMaps = [](const render::FrameReport& r) {
        return r.countRan(render::PassKind::Envmap) > 0;
    };
    const auto withMaps = std::find_if(reports.begin(), reports.end(), drawsMaps);
    ASSERT_NE(withMaps, reports.end()) << "the first frame draws the maps";
    m_window->passesPanel().showReportNow(*withMaps);
    QTreeWidget& tree = m_window->passesPanel().tree();
    QTreeWidgetItem* passes = tree.topLevelItem(0);
    std::vector<QString> groups;
    for (int i = 0; i < passes->childCount(); ++i) {
        QTreeWidgetItem* row = passes->child(i);
        if (!row->text(0).startsWith(QStringLiteral("maps, bounce")))
            continue;
        groups.push_back(row->text(0));
        ASSERT_EQ(row->childCount(), 3) << row->text(0).toStdString();
        EXPECT_EQ(row->child(0)->text(1), QStringLiteral("Left ball"));
        EXPECT_EQ(row->child(1)->text(1), QStringLiteral("Right ball"));
        EXPECT_EQ(row->child(2)->text(1), QStringLiteral("Satin ball"));
        EXPECT_EQ(row->child(0)->text(0), QStringLiteral("envmap"));
    }
    const std::vector<QString> expected = {QStringLiteral("maps, bounce 0"), QStringLiteral("maps, bounce 1"),
                                           QStringLiteral("maps, bounce 2")};
    EXPECT_EQ(groups, expected);
}

TEST_F(EditorOutput, ExportStillMatchesTheCommandLine) {
    open(kTeapotProject);
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString editorPng = dir.filePath(QStringLiteral("editor.png"));
    const QString cliPng = dir.filePath(QStringLiteral("cli.png"));
    speculum::scene::StillExportSettings settings;
    settings.width = 320;
    settings.height = 180;
    settings.ssaa = 2;
    int calls = 0;
    auto exported = m_window->exportStillFile(editorPng, settings, [&](double, const std::string&) {
        ++calls;
        return true;
    });
    ASSERT_TRUE(exported.ok()) << exported.error();
    EXPECT_GE(calls, 4) << "progress for every sample";
    EXPECT_EQ(exported->still.samples, 4);

    QProcess cli;
    cli.start(QString::fromStdString(speculum::testCliBinary()),
              {QStringLiteral("render"), kTeapotProject, QStringLiteral("-o"), cliPng,
               QStringLiteral("--size"), QStringLiteral("320x180"), QStringLiteral("--ssaa"),
               QStringLiteral("2")});
    ASSERT_TRUE(cli.waitForFinished(120000));
    ASSERT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();

    const QImage a(editorPng), b(cliPng);
    ASSERT_FALSE(a.isNull());
    ASSERT_FALSE(b.isNull());
    ASSERT_EQ(a.size(), QSize(320, 180));
    const ImageDifference d = compareImages(a, b);
    // The same renderer code on the same kind of GL (llvmpipe through GLX here, EGL for the CLI).
    EXPECT_LE(d.maximum, 2) << "mean difference " << d.mean;
    EXPECT_LT(d.mean, 0.05);
    // Let people compare.
    QFile::remove(QString::fromStdString(speculum::testDataPath("editor-export-still.png")));
    QFile::copy(editorPng, QString::fromStdString(speculum::testDataPath("editor-export-still.png")));

    // A cancelled export writes nothing.
    const QString cancelled = dir.filePath(QStringLiteral("cancelled.png"));
    auto stopped =
        m_window->exportStillFile(cancelled, settings, [](double, const std::string&) { return false; });
    ASSERT_FALSE(stopped.ok());
    EXPECT_NE(stopped.error().find("cancel"), std::string::npos) << stopped.error();
    EXPECT_FALSE(QFile::exists(cancelled));
    // Bad settings are refused before any work.
    EXPECT_FALSE(m_window->exportStillFile(dir.filePath(QStringLiteral("still.bmpx")), settings).ok());
    // The viewport still draws afterwards.
    EXPECT_TRUE(waitForFrames(*m_window));
}

// The attributes stored in a still (what stillMetadata wrote), as text, without the render time: the one
// that may differ between two runs.
std::map<std::string, std::string> stillAttributes(const QString& path) {
    std::map<std::string, std::string> out;
    auto input = OIIO::ImageInput::open(path.toStdString());
    if (!input)
        return out;
    for (const OIIO::ParamValue& p : input->spec().extra_attribs)
        if (p.name().string().rfind("speculum:", 0) == 0 || p.name() == "Software" ||
            p.name() == "ImageDescription")
            out[p.name().string()] = p.get_string();
    out.erase("speculum:renderTimeMs");
    return out;
}

// The exact reference from Export Still is `speculum render --reference`'s: one function draws and writes
// both, so on a scene with rough mirrors, at a samples count other than the default, the pixels are the
// same bytes and the files carry the same attributes (the noise figure included).
TEST_F(EditorOutput, ExactReferenceExportMatchesTheCommandLine) {
    const QString project = kScenes + QStringLiteral("/glossy.speculum.json");
    open(project);
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString editorPng = dir.filePath(QStringLiteral("editor-reference.png"));
    const QString cliPng = dir.filePath(QStringLiteral("cli-reference.png"));
    speculum::scene::StillExportSettings settings;
    settings.width = 48;
    settings.height = 32;
    settings.reference = true;
    settings.samples = 3;
    double last = -1.0;
    std::string stage;
    auto exported =
        m_window->exportStillFile(editorPng, settings, [&](double fraction, const std::string& s) {
            last = fraction;
            stage = s;
            return true;
        });
    ASSERT_TRUE(exported.ok()) << exported.error();
    EXPECT_EQ(last, 1.0) << "progress up to the end";
    EXPECT_NE(stage.find("reference"), std::string::npos) << stage;
    ASSERT_TRUE(exported->trace);
    EXPECT_EQ(exported->trace->paths, 3) << "the samples setting reaches the tracer";
    EXPECT_GT(exported->trace->glossyPixels, 0) << "the scene's rough mirrors are in view";

    QProcess cli;
    cli.start(QString::fromStdString(speculum::testCliBinary()),
              {QStringLiteral("render"), project, QStringLiteral("-o"), cliPng, QStringLiteral("--size"),
               QStringLiteral("48x32"), QStringLiteral("--reference"), QStringLiteral("--samples"),
               QStringLiteral("3")});
    ASSERT_TRUE(cli.waitForFinished(120000));
    ASSERT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();

    const QImage a(editorPng), b(cliPng);
    ASSERT_FALSE(a.isNull());
    ASSERT_FALSE(b.isNull());
    ASSERT_EQ(a.size(), QSize(48, 32));
    ASSERT_EQ(b.size(), QSize(48, 32));
    const ImageDifference d = compareImages(a, b);
    EXPECT_EQ(d.maximum, 0) << "mean difference " << d.mean;

    const auto editorText = stillAttributes(editorPng), cliText = stillAttributes(cliPng);
    EXPECT_EQ(editorText, cliText);
    EXPECT_TRUE(editorText.count("speculum:noiseRms")) << "the noise figure is written";
    EXPECT_TRUE(editorText.count("speculum:glossyPixels"));
    EXPECT_NE(editorText.at("speculum:settings").find("3 paths"), std::string::npos)
        << editorText.at("speculum:settings");

    // Cancelled, it writes nothing.
    const QString cancelled = dir.filePath(QStringLiteral("cancelled-reference.png"));
    auto stopped =
        m_window->exportStillFile(cancelled, settings, [](double, const std::string&) { return false; });
    ASSERT_FALSE(stopped.ok());
    EXPECT_FALSE(QFile::exists(cancelled));
    EXPECT_TRUE(waitForFrames(*m_window));
}

// Export Still offers the exact tracer, and its time is the scene's start unless the user picks the time
// slider's; the dialog says which.
TEST_F(EditorOutput, ExportStillDialogOffersTheTracerAndStatesItsTime) {
    ui::ExportStillDialog dialog(QStringLiteral("/tmp/still.png"), 1.5, m_window.get());
    auto* reference = dialog.findChild<QCheckBox*>(QStringLiteral("stillReference"));
    ASSERT_NE(reference, nullptr);
    EXPECT_TRUE(reference->isEnabled());
    auto* samples = dialog.findChild<QSpinBox*>(QStringLiteral("stillSamples"));
    ASSERT_NE(samples, nullptr);
    EXPECT_FALSE(samples->isEnabled()) << "paths are the tracer's setting";
    reference->setChecked(true);
    EXPECT_TRUE(dialog.settings().reference);
    EXPECT_TRUE(samples->isEnabled());
    EXPECT_EQ(dialog.settings().samples, 16) << "the CLI's default";
    samples->setValue(64);
    EXPECT_EQ(dialog.settings().samples, 64);

    EXPECT_EQ(dialog.settings().time, 0.0);
    EXPECT_TRUE(dialog.timeNote().contains(QStringLiteral("t = 0.000 s, its start")))
        << dialog.timeNote().toStdString();
    EXPECT_TRUE(dialog.timeNote().contains(QStringLiteral("1.500"))) << "names the slider's time too";
    auto* source = dialog.findChild<QComboBox*>(QStringLiteral("stillTimeSource"));
    ASSERT_NE(source, nullptr);
    emit source->activated(1); // the user picks "Time slider"
    EXPECT_EQ(dialog.settings().time, 1.5);
    EXPECT_EQ(source->currentIndex(), 1);
    EXPECT_TRUE(dialog.timeNote().contains(QStringLiteral("t = 1.500 s, the time slider's time")))
        << dialog.timeNote().toStdString();
    dialog.findChild<QDoubleSpinBox*>(QStringLiteral("stillTime"))->setValue(2.25);
    EXPECT_EQ(source->currentIndex(), 2);
    EXPECT_TRUE(dialog.timeNote().contains(QStringLiteral("2.250"))) << dialog.timeNote().toStdString();
}

// The viewport's texture is 8-bit sRGB and the frame is drawn straight into it (no copy): what the window
// shows, as Qt composes that texture on screen, must be the bytes the frame wrote, not a decoded, darker
// version of them.
TEST_F(EditorOutput, TheFrameDrawnIntoTheViewportShowsOnScreenAsWritten) {
    open(kScenes + QStringLiteral("/chrome.speculum.json"));
    ASSERT_TRUE(waitForFrames(*m_window));
    const render::FrameReport& report = m_window->viewport().lastReport();
    EXPECT_TRUE(report.plan.cameraBufferIsOutput) << "chrome has no blend that needs the half-float buffer";
    EXPECT_EQ(report.countRan(render::PassKind::Composite), 0u);
    const QImage written = frame();
    QCoreApplication::processEvents();
    const QImage shown = m_window->windowHandle()
                             ->screen()
                             ->grabWindow(m_window->winId())
                             .toImage()
                             .convertToFormat(QImage::Format_RGB32);
    ASSERT_FALSE(shown.isNull());
    const QPoint origin = m_window->viewport().mapTo(m_window.get(), QPoint(0, 0));
    const double scale = written.width() / double(m_window->viewport().width());
    // Away from the overlay (axis gizmo, pivot mark), which is drawn over the frame on screen only.
    for (const QPointF at : {QPointF(0.2, 0.8), QPointF(0.8, 0.6), QPointF(0.5, 0.15), QPointF(0.3, 0.45)}) {
        const QPoint inViewport(int(at.x() * m_window->viewport().width()),
                                int(at.y() * m_window->viewport().height()));
        const Rgb w = patch(written, QPoint(int(inViewport.x() * scale), int(inViewport.y() * scale)), 2);
        const Rgb s = patch(shown, origin + inViewport, 2);
        EXPECT_LE(w.distance(s), 3.0) << "at " << at.x() << "," << at.y() << ": written " << w.r << "," << w.g
                                      << "," << w.b << ", shown " << s.r << "," << s.g << "," << s.b;
    }
}

TEST_F(EditorOutput, ScreenshotsOfEachDemoScene) {
    const QStringList scenes = QDir(kScenes).entryList({QStringLiteral("*.speculum.json")}, QDir::Files);
    ASSERT_FALSE(scenes.isEmpty());
    for (const QString& name : scenes) {
        open(QDir(kScenes).filePath(name));
        // Select the first mesh so the inspector and the handles show, as a user would see it.
        m_window->scene().forEachNode([&](const speculum::scene::Node& node) {
            if (node.data().mesh && m_window->selection().isEmpty()) {
                m_window->selection().selectNode(node.id());
            }
        });
        ASSERT_TRUE(waitForFrames(*m_window, 3));
        const QPixmap shot = m_window->grab();
        const QString stem = name.section(QLatin1Char('.'), 0, 0);
        const QString path = QString::fromStdString(speculum::testDataPath("editor-window-%1.png")).arg(stem);
        ASSERT_TRUE(shot.save(path)) << path.toStdString();
        std::printf("screenshot: %s\n", qPrintable(path));
        // Not a blank window: the viewport area has many colours.
        const QImage image = frame();
        const Rgb corner = patch(image, {5, 5}, 2);
        int different = 0;
        for (int y = 0; y < image.height(); y += 8) {
            for (int x = 0; x < image.width(); x += 8) {
                different += patch(image, {x, y}, 0).distance(corner) > 20.0;
            }
        }
        EXPECT_GT(different, 50) << name.toStdString();
        m_window->selection().clear();
    }
}

} // namespace

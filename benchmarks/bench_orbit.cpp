// Frame rate of the editor's viewport while the view is orbited: each demo opened in a
// MainWindow at its default size, a left-button drag around the view for about 3 s, with adaptive
// resolution (previews at a reduced resolution while navigating) and without it. One step = one mouse move
// and the frame it causes, as the editor sees a drag whose mouse moves come faster than its frames. The
// mirrors and chrome demos must orbit at 20 fps or more with adaptive resolution (2-core llvmpipe).
// Run: scripts/with-display build/release/benchmarks/speculum_bench_orbit [--seconds S] [--size WxH]
//      [--handle] [--no-overlay] [--no-guides] [--verbose] [--screenshot DIR] [PROJECT…]
// --handle drags the move handle of the first node with a mesh instead (the same targets); --screenshot
// saves the window at the end of each adaptive drag (a preview) and once it has rested.
#include "BenchViewport.hpp"
#include "editor/ui/Editor.hpp"
#include "editor/ui/MainWindow.hpp"
#include "editor/ui/Viewport.hpp"
#include "editor/view/AnimationClock.hpp"
#include "editor/view/Selection.hpp"
#include "scene/model/Scene.hpp"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QMouseEvent>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QWindow>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace speculum;
using bench::sendMouse;
using bench::waitForFrame;

constexpr double kTargetFps = 20.0;

void runFor(int ms) {
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

struct Orbit {
    bool ok = false;
    double fps = 0.0;
    double meanScale = 1.0;   // of the frames drawn during the drag
    double meanDrawMs = 0.0;  // paintGL's drawing, per frame
    double fullFrameMs = 0.0; // the frame after the drag (at full quality)
    int frames = 0;
    bool restFull = true; // the frame after the drag was drawn at full resolution
    std::string lastDrag; // --verbose: the last frame of the drag, pass by pass
};

// The passes of a frame with their CPU times (llvmpipe draws on the CPU: GPU timer queries say little).
std::string describe(const ui::Viewport& viewport) {
    const render::FrameReport& report = viewport.lastReport();
    std::map<std::string, std::pair<int, double>> byKind;
    for (const render::PassRun& run : report.ran) {
        auto& [count, ms] = byKind[std::string(render::toString(report.planned(run).kind))];
        ++count;
        ms += run.cpuMs;
    }
    std::string text = "    last drag frame: " + std::to_string(report.drawnWidth) + "x" +
                       std::to_string(report.drawnHeight) + ", mirror levels cut " +
                       std::to_string(viewport.lastFrameLevel().mirrorDepthCut) + ", renderer " +
                       std::to_string(report.cpuMs) + " ms of " + std::to_string(viewport.lastFrameMs()) +
                       " ms drawing:";
    for (const auto& [kind, entry] : byKind) {
        text += " " + kind + " " + std::to_string(entry.first) + "x " + std::to_string(entry.second) + " ms;";
    }
    return text;
}

// Presses at `start` and drags along path(step), one move per frame, for `seconds`.
QString g_screenshots; // --screenshot DIR: the window at the end of each adaptive drag and at rest
QString g_shotName;

void screenshot(const QString& suffix) {
    if (g_screenshots.isEmpty() || g_shotName.isEmpty()) {
        return;
    }
    for (QWidget* top : QApplication::topLevelWidgets()) {
        if (auto* window = qobject_cast<ui::MainWindow*>(top)) {
            window->grab().save(g_screenshots + QStringLiteral("/") + g_shotName + suffix);
        }
    }
}

Orbit drag(ui::Viewport& viewport, double seconds, QPointF start, const std::function<QPointF(int)>& path) {
    Orbit o;
    const QPointF centre = start;
    sendMouse(viewport, QEvent::MouseButtonPress, centre, Qt::LeftButton, Qt::LeftButton);
    double scaleSum = 0.0, drawSum = 0.0;
    QElapsedTimer clock;
    clock.start();
    int step = 0;
    while (clock.elapsed() < seconds * 1000.0) {
        ++step;
        const QPointF at = path(step);
        const int target = viewport.framesRendered() + 1;
        sendMouse(viewport, QEvent::MouseMove, at, Qt::NoButton, Qt::LeftButton);
        if (!waitForFrame(viewport, target)) {
            sendMouse(viewport, QEvent::MouseButtonRelease, at, Qt::LeftButton, Qt::NoButton);
            return o;
        }
        scaleSum += viewport.lastFrameScale();
        o.lastDrag = describe(viewport);
        drawSum += viewport.lastFrameMs();
        ++o.frames;
    }
    const double elapsed = double(clock.nsecsElapsed()) * 1e-9;
    screenshot(QStringLiteral("-drag.png"));
    sendMouse(viewport, QEvent::MouseButtonRelease, centre, Qt::LeftButton, Qt::NoButton);
    o.fps = o.frames / elapsed;
    o.meanScale = o.frames ? scaleSum / o.frames : 1.0;
    o.meanDrawMs = o.frames ? drawSum / o.frames : 0.0;
    // Resting: one full-quality frame follows when the drag was previewed.
    const int before = viewport.framesRendered();
    runFor(ui::Viewport::kRestMs + 150);
    if (viewport.framesRendered() == before) {
        viewport.update(); // no preview was drawn: time a full frame anyway
    }
    waitForFrame(viewport, before + 1);
    o.fullFrameMs = viewport.lastFrameMs();
    o.restFull = viewport.lastFrameScale() == 1.0 && !viewport.lastFrameReduced();
    screenshot(QStringLiteral("-rest.png"));
    o.ok = o.frames > 0;
    return o;
}

// Drags from the centre back and forth, about 45° either way around the scene and a little up and down
// (a drag across the full height turns 180°), at most 12 px a step: a few degrees a frame, as a hand
// drags, with the scene in view all along.
Orbit orbit(ui::Viewport& viewport, double seconds) {
    const QPointF centre(viewport.width() / 2.0, viewport.height() / 2.0);
    const double across = viewport.height() * 0.25, upDown = viewport.height() * 0.06;
    return drag(viewport, seconds, centre, [=](int step) {
        const double a = step * 12.0 / across;
        return centre + QPointF(across * std::sin(a), upDown * std::sin(a * 1.7));
    });
}

// Drags the move handle of the first top-level node with a mesh back and forth along its X axis (every
// move an edit: the document changes each frame, shadows and the environment map with it).
Orbit dragHandle(ui::MainWindow& window, double seconds) {
    ui::Viewport& viewport = window.viewport();
    for (const auto& node : window.scene().topLevelNodes()) {
        if (node->data().mesh) {
            window.selection().selectNode(node->id());
            break;
        }
    }
    viewport.setHandleMode(ui::HandleMode::Move);
    viewport.update();
    waitForFrame(viewport, viewport.framesRendered() + 1);
    const auto handle = viewport.handlePoint(0);
    if (!handle) {
        return {};
    }
    const QPointF start = *handle;
    const int steps = window.undoStack().count();
    Orbit o = drag(viewport, seconds, start,
                   [start](int step) { return start + QPointF(60.0 * std::sin(step * 0.3), 0.0); });
    if (window.undoStack().count() > steps) {
        window.undoStack().undo();
    }
    window.selection().clear();
    return o;
}

struct Options {
    double seconds = 3.0;
    QSize size; // empty: the window's default size
    bool overlay = true, guides = true, verbose = false, handle = false;
    std::vector<QString> projects; // empty: the demos the target is about
};

Options parseOptions(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--seconds" && i + 1 < argc) {
            o.seconds = std::atof(argv[++i]);
        } else if (arg == "--no-overlay") {
            o.overlay = false; // what the handles, guides and labels cost
        } else if (arg == "--handle") {
            o.handle = true; // drag a move handle instead of orbiting
        } else if (arg == "--screenshot" && i + 1 < argc) {
            g_screenshots = QString::fromLocal8Bit(argv[++i]);
        } else if (arg == "--verbose") {
            o.verbose = true;
        } else if (arg == "--no-guides") {
            o.guides = false;
        } else if (arg == "--size" && i + 1 < argc) {
            int w = 0, h = 0;
            if (std::sscanf(argv[++i], "%dx%d", &w, &h) == 2 && w > 0 && h > 0) {
                o.size = QSize(w, h);
            }
        } else {
            o.projects.push_back(QString::fromLocal8Bit(argv[i]));
        }
    }
    if (o.projects.empty()) {
        for (const char* name : {"mirrors", "chrome", "models"}) {
            o.projects.push_back(QStringLiteral(SPECULUM_SOURCE_DIR "/resources/scenes/%1.speculum.json")
                                     .arg(QString::fromLatin1(name)));
        }
    }
    return o;
}

// The main window, shown and exposed, its viewport with the overlay and guides as asked.
std::unique_ptr<ui::MainWindow> openWindow(const Options& options) {
    auto window = std::make_unique<ui::MainWindow>();
    if (options.size.isValid()) {
        window->resize(options.size);
    }
    window->show();
    QElapsedTimer exposing;
    exposing.start();
    while (!(window->windowHandle() && window->windowHandle()->isExposed()) && exposing.elapsed() < 10000) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    }
    ui::Viewport& viewport = window->viewport();
    if (QWidget* o = viewport.findChild<QWidget*>(QStringLiteral("viewportOverlay")); o && !options.overlay) {
        o->hide();
    }
    viewport.setGuidesVisible(options.guides);
    runFor(300);
    return window;
}

enum class Verdict { Met, Missed, RendererFailed };

// Opens one project and drags in it with and without adaptive resolution; prints its row.
Verdict measureProject(ui::MainWindow& window, const QString& project, const Options& options) {
    ui::Viewport& viewport = window.viewport();
    const std::string name = QFileInfo(project).fileName().toStdString();
    if (auto opened = window.openProjectFile(project); !opened.ok()) {
        std::printf("%-24s error: %s\n", name.c_str(), opened.error().c_str());
        return Verdict::Missed;
    }
    window.clock().setPlaying(false);
    window.clock().setTime(0.0);
    viewport.waitForModels();
    viewport.update();
    waitForFrame(viewport, viewport.framesRendered() + 2);
    if (!viewport.rendererError().isEmpty()) {
        std::printf("%-24s error: %s\n", name.c_str(), viewport.rendererError().toStdString().c_str());
        return Verdict::RendererFailed;
    }
    const auto measure = [&](bool adaptiveResolution) {
        viewport.setAdaptiveResolution(adaptiveResolution);
        viewport.resetView();
        waitForFrame(viewport, viewport.framesRendered() + 1);
        return options.handle ? dragHandle(window, options.seconds) : orbit(viewport, options.seconds);
    };
    g_shotName = QFileInfo(project).completeBaseName().section(QLatin1Char('.'), 0, 0);
    const Orbit adaptive = measure(true);
    g_shotName.clear();
    const Orbit full = measure(false);
    viewport.setAdaptiveResolution(true);
    if (!adaptive.ok || !full.ok) {
        std::printf("%-24s error: the viewport stopped drawing\n", name.c_str());
        return Verdict::Missed;
    }
    const bool required = name.rfind("mirrors", 0) == 0 || name.rfind("chrome", 0) == 0;
    const bool met = adaptive.fps >= kTargetFps;
    std::printf("%-24s %9.1f %9.1f %8.2f %10.1f %10.1f %12s%s\n", name.c_str(), adaptive.fps, full.fps,
                adaptive.meanScale, adaptive.meanDrawMs, adaptive.fullFrameMs,
                adaptive.restFull ? "full" : "NOT FULL", required && !met ? "  UNDER 20 FPS" : "");
    if (options.verbose) {
        std::printf("%s\n%s\n", adaptive.lastDrag.c_str(), full.lastDrag.c_str());
    }
    return adaptive.restFull && (!required || met) ? Verdict::Met : Verdict::Missed;
}

} // namespace

int main(int argc, char** argv) {
    // Settings of its own: the window opens at its default size, with no layout of the user's.
    QTemporaryDir home;
    for (const char* variable : {"XDG_DATA_HOME", "XDG_CONFIG_HOME", "XDG_CACHE_HOME", "XDG_STATE_HOME"}) {
        qputenv(variable, QFile::encodeName(home.filePath(QString::fromLatin1(variable))));
    }
    ui::installDefaultSurfaceFormat();
    QApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("speculum-bench-orbit"));

    const Options options = parseOptions(argc, argv);
    std::unique_ptr<ui::MainWindow> window = openWindow(options);
    ui::Viewport& viewport = window->viewport();
    const qreal dpr = viewport.devicePixelRatioF();
    std::printf("%s of %.0f s in the viewport of a %dx%d window (viewport %dx%d device pixels); fps "
                "with and without adaptive resolution (preview budget %.0f ms a frame)\n",
                options.handle ? "move-handle drag" : "orbit drag", options.seconds, window->width(),
                window->height(), qRound(viewport.width() * dpr), qRound(viewport.height() * dpr),
                viewport.previewFrameBudget());
    std::printf("%-24s %9s %9s %8s %10s %10s %12s\n", "project", "fps", "fps(full)", "scale", "draw ms",
                "full ms", "rest frame");
    bool pass = true;
    for (const QString& project : options.projects) {
        const Verdict verdict = measureProject(*window, project, options);
        if (verdict == Verdict::RendererFailed) {
            return 1;
        }
        pass = pass && verdict == Verdict::Met;
    }
    window->undoStack().setClean();
    window->newProject();
    window.reset();
    std::printf("%s\n", pass ? "target met: mirrors and chrome orbit at 20 fps or more, full frames at rest"
                             : "target NOT met");
    return pass ? 0 : 1;
}

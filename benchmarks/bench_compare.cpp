// "Compare with exact" at its default quality (480 px wide, auto refinement) on every demo, in the editor:
// the time from the click until the result stands, the paths per rough pixel it reached and the noise
// the exact image has left. The default must finish within 20 s on two cores for every demo (30 s with
// the margin of a loaded machine is the failure line).
// Run: scripts/with-display build/release/benchmarks/speculum_bench_compare [PROJECT…]
#include "BenchViewport.hpp"
#include "editor/ui/AccuracyPanel.hpp"
#include "editor/ui/MainWindow.hpp"
#include "editor/ui/Viewport.hpp"
#include "editor/view/AnimationClock.hpp"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QTimer>
#include <QUndoStack>
#include <cstdio>

namespace {

using namespace speculum;

constexpr double kTargetSeconds = 20.0;
constexpr double kFailSeconds = 30.0;

bool waitUntilCompared(ui::AccuracyPanel& panel, int timeoutMs) {
    QElapsedTimer clock;
    clock.start();
    while (panel.comparing() && clock.elapsed() < timeoutMs) {
        QEventLoop loop;
        QTimer::singleShot(20, &loop, &QEventLoop::quit);
        loop.exec();
    }
    return !panel.comparing();
}

// One demo: opened, drawn, compared at the panel's defaults; prints its row. False when it failed or took
// longer than the failure line.
bool measure(ui::MainWindow& window, const QString& project) {
    const std::string name = QFileInfo(project).fileName().toStdString();
    if (auto opened = window.openProjectFile(project); !opened.ok()) {
        std::printf("%-24s error: %s\n", name.c_str(), opened.error().c_str());
        return false;
    }
    window.clock().setPlaying(false);
    ui::Viewport& viewport = window.viewport();
    viewport.waitForModels();
    viewport.update();
    bench::waitForFrame(viewport, viewport.framesRendered() + 2);
    ui::AccuracyPanel& panel = window.accuracyPanel();
    QElapsedTimer clock;
    clock.start();
    panel.compareWithExact();
    const bool done = waitUntilCompared(panel, 600000);
    const double seconds = clock.elapsed() / 1000.0;
    const auto& result = panel.lastComparison();
    if (!done || !result) {
        std::printf("%-24s error: no result after %.1f s\n", name.c_str(), seconds);
        return false;
    }
    std::printf("%-24s %9.1f %6d %10d %12.4f %9.2f%s\n", name.c_str(), seconds, result->paths,
                result->roughPixels, result->noiseRms, result->psnr,
                seconds > kFailSeconds     ? "  TOO SLOW"
                : seconds > kTargetSeconds ? "  over the 20 s target"
                                           : "");
    return seconds <= kFailSeconds;
}

} // namespace

int main(int argc, char** argv) {
    QApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("speculum-bench-compare"));
    QStringList projects = app.arguments().mid(1);
    if (projects.isEmpty()) {
        for (const char* demo : {"teapot", "mirrors", "chrome", "glossy", "models"}) {
            projects << QStringLiteral(SPECULUM_SOURCE_DIR "/resources/scenes/%1.speculum.json").arg(demo);
        }
    }
    ui::MainWindow window;
    window.resize(1280, 800);
    window.show();
    QEventLoop settle;
    QTimer::singleShot(500, &settle, &QEventLoop::quit);
    settle.exec();
    std::printf("%-24s %9s %6s %10s %12s %9s\n", "project", "seconds", "paths", "rough px", "noise (RMS)",
                "PSNR dB");
    bool pass = true;
    for (const QString& project : projects) {
        pass = measure(window, project) && pass;
    }
    window.undoStack().setClean();
    return pass ? 0 : 1;
}

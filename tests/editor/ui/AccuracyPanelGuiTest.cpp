// The Accuracy dock on the chrome-ball demo: Compare with exact measures the current view against the
// tracer and shows finite numbers and an error map (also over the viewport); a cancelled comparison leaves
// the last numbers alone; a bench results.json loads into the chart, and clicking a point gives the
// document that configuration's settings in one undo step that undo takes back. Run sweep runs the bench's
// sweep in-process: points fill the chart while it runs, the report's findings show when it is done,
// Cancel stops it within about a second and leaves the chart as it was, and the document never changes.
// The compared images show side by side and in a flip view; chart points label themselves on hover; clear()
// (New, Open) forgets it all.
#include "editor/ui/AccuracyPanel.hpp"
#include "editor/ui/CompareView.hpp"
#include "editor/ui/ExactComparison.hpp"
#include "editor/ui/SweepChart.hpp"
#include "scene/model/Scene.hpp"
#include "support/GuiTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QAction>
#include <QChart>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QGraphicsScene>
#include <QGraphicsTextItem>
#include <QLabel>
#include <QMouseEvent>
#include <QProgressBar>
#include <QPushButton>
#include <QScatterSeries>
#include <QScrollArea>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>
#include <QWheelEvent>
#include <gtest/gtest.h>
#include <map>
#include <set>

namespace speculum::ui {
namespace {

using test::waitFor;
using test::waitForFrames;

const QString kChrome =
    QString::fromStdString(speculum::testSourcePath("resources/scenes/chrome.speculum.json"));
const QString kGlossy =
    QString::fromStdString(speculum::testSourcePath("resources/scenes/glossy.speculum.json"));

// Configurations of a sweep on the chrome scene in the layout `speculum bench` writes: its own, a coarse
// tennis-ball map with shallower mirrors and a sharper PCF kernel (the one the test clicks), and a few more.
const char* kResults = R"({
  "format": "speculum-bench", "version": 1, "scene": "chrome.speculum.json", "size": "480x270",
  "results": [
    {"id": "scene", "family": "scene", "label": "scene", "series": "scene", "reference": "scene",
     "sceneSetting": true,
     "settings": {"map": "cube", "resolution": 256, "fill": "resampled", "parallax": "off",
                  "mirrorDepth": 3, "pcf": 5},
     "gpuMs": 4.0, "cpuMs": 6.0, "memoryBytes": 1000, "rmse": 0.02, "psnr": 34.0,
     "psnrMirrors": null, "psnrReflector": 30.0},
    {"id": "envmap-tennis-ball-direct-64", "family": "envmap", "label": "64", "series": "tennis-ball direct",
     "reference": "scene", "sceneSetting": false,
     "settings": {"map": "tennis-ball", "resolution": 64, "fill": "direct", "parallax": "off",
                  "mirrorDepth": 2, "pcf": 3},
     "gpuMs": 2.0, "cpuMs": 3.0, "memoryBytes": 500, "rmse": 0.04, "psnr": 28.0,
     "psnrMirrors": null, "psnrReflector": 22.0},
    {"id": "envmap-cube-64", "family": "envmap", "label": "64", "series": "cube", "reference": "scene",
     "sceneSetting": false,
     "settings": {"map": "cube", "resolution": 64, "fill": "resampled", "parallax": "off",
                  "mirrorDepth": 3, "pcf": 5},
     "gpuMs": 3.0, "cpuMs": 4.5, "memoryBytes": 700, "rmse": 0.03, "psnr": 31.0,
     "psnrMirrors": null, "psnrReflector": 26.0},
    {"id": "mirror-depth-1", "family": "mirror-depth", "label": "1", "series": "depth", "reference": "deep-mirrors",
     "sceneSetting": false,
     "settings": {"map": "cube", "resolution": 256, "fill": "resampled", "parallax": "off",
                  "mirrorDepth": 1, "pcf": 5},
     "gpuMs": 3.5, "cpuMs": 5.0, "memoryBytes": 1000, "rmse": 0.025, "psnr": 32.5,
     "psnrMirrors": null, "psnrReflector": 29.0},
    {"id": "shadows-pcf-1", "family": "shadows", "label": "pcf 1", "series": "pcf", "reference": "hard-shadows",
     "sceneSetting": false,
     "settings": {"map": "cube", "resolution": 256, "fill": "resampled", "parallax": "off",
                  "mirrorDepth": 3, "pcf": 1},
     "gpuMs": 3.8, "cpuMs": 5.5, "memoryBytes": 1000, "rmse": 0.03, "psnr": 30.5,
     "psnrMirrors": null, "psnrReflector": 30.0}
  ]
})";

// A point of a later version's sweep, whose one setting this version does not know.
const char* kUnknownSettingResults = R"({
  "format": "speculum-bench", "version": 1, "scene": "chrome.speculum.json", "size": "480x270",
  "results": [
    {"id": "future-1", "family": "envmap", "label": "future", "series": "future", "reference": "scene",
     "sceneSetting": false, "settings": {"futureSetting": "on"},
     "gpuMs": 2.0, "cpuMs": 3.0, "memoryBytes": 500, "rmse": 0.04, "psnr": 28.0,
     "psnrMirrors": null, "psnrReflector": 22.0}
  ]
})";

QString writeResults(const QTemporaryDir& dir, const char* results = kResults) {
    const QString path = dir.filePath(QStringLiteral("results.json"));
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::WriteOnly));
    file.write(results);
    return path;
}

// A floor, a box and one shadowed light: the sweep has the scene and the PCF family only (five
// configurations, two references), seconds on a software rasterizer.
const char* kTinyScene = R"({
  "format": "speculum-scene", "version": 1,
  "settings": {"background": [0.2, 0.2, 0.25], "mirrorDepth": 1, "ambient": 0.2},
  "camera": {"position": [0, 2, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fovY": 50, "near": 0.1, "far": 30},
  "nodes": [
    {"name": "Floor", "transform": {"scale": [4, 1, 4]}, "mesh": {"builtin": "plane"}},
    {"name": "Box", "transform": {"translate": [0, 0.5, 0], "scale": [0.5, 0.5, 0.5]}, "mesh": {"builtin": "box"}},
    {"name": "Light", "transform": {"translate": [1, 4, 2]},
     "light": {"type": "point", "shadows": {"mapSize": 256, "pcf": 3}}}
  ]
})";

const scene::ReflectorComponent* reflectorOf(const scene::Scene& scene) {
    const scene::ReflectorComponent* found = nullptr;
    scene.forEachNode([&](const scene::Node& node) {
        if (node.data().reflector && !found) {
            found = &*node.data().reflector;
        }
    });
    return found;
}

class AccuracyPanelTest : public ::testing::Test {
protected:
    void SetUp() override {
        m_window = std::make_unique<MainWindow>();
        m_window->resize(1400, 900);
        m_window->show();
        ASSERT_TRUE(m_window->openProjectFile(kChrome).ok());
        m_dock = m_window->findChild<QDockWidget*>(QStringLiteral("accuracyDock"));
        ASSERT_NE(m_dock, nullptr);
        // The View menu toggles it like the other docks.
        m_dock->toggleViewAction()->trigger();
        m_dock->raise();
        ASSERT_TRUE(m_dock->isVisible());
        ASSERT_TRUE(waitForFrames(*m_window, 2));
    }

    AccuracyPanel& panel() { return m_window->accuracyPanel(); }
    QString text(const char* name) { return panel().findChild<QLabel*>(QString::fromLatin1(name))->text(); }

    std::unique_ptr<MainWindow> m_window;
    QDockWidget* m_dock = nullptr;
};

TEST_F(AccuracyPanelTest, CompareWithExactShowsFiniteNumbersAndAnErrorMap) {
    EXPECT_EQ(text("accuracyPsnr"), QStringLiteral("—"));
    panel().setPreviewWidth(160);
    panel().findChild<QPushButton*>(QStringLiteral("compareExact"))->click();
    ASSERT_TRUE(waitFor([&] { return !panel().comparing(); }, 180000));
    ASSERT_TRUE(panel().lastComparison().has_value()) << text("accuracyStatus").toStdString();
    const ComparisonResult& r = *panel().lastComparison();
    EXPECT_EQ(r.width, 160);
    EXPECT_GT(r.height, 0);
    EXPECT_TRUE(std::isfinite(r.rmse));
    EXPECT_GE(r.rmse, 0.0);
    EXPECT_LT(r.rmse, 0.5); // the same scene both ways: far from random
    EXPECT_TRUE(std::isfinite(r.psnr));
    EXPECT_GT(r.psnr, 10.0);
    ASSERT_TRUE(r.psnrReflector.has_value()); // the chrome ball is in view
    EXPECT_TRUE(std::isfinite(*r.psnrReflector));
    EXPECT_GT(r.rasterCpuMs, 0.0);
    EXPECT_GT(r.traceMs, 0.0);
    // The numbers are on screen.
    EXPECT_TRUE(text("accuracyPsnr").endsWith(QStringLiteral(" dB"))) << text("accuracyPsnr").toStdString();
    EXPECT_TRUE(text("accuracyPsnrReflector").endsWith(QStringLiteral(" dB")));
    EXPECT_NE(text("accuracyRmse"), QStringLiteral("—"));
    EXPECT_TRUE(text("accuracyTraceMs").endsWith(QStringLiteral(" ms")));
    EXPECT_TRUE(text("accuracyRasterMs").contains(QStringLiteral("ms")));
    // The error map: the frame's size, not all black (some pixel differs), shown in the panel.
    EXPECT_EQ(r.errorMap.size(), QSize(r.width, r.height));
    const QImage map = r.errorMap.convertToFormat(QImage::Format_RGB32);
    int lit = 0;
    for (int y = 0; y < map.height(); ++y) {
        for (int x = 0; x < map.width(); ++x) {
            lit += qGray(map.pixel(x, y)) > 20;
        }
    }
    EXPECT_GT(lit, 0);
    EXPECT_FALSE(panel().findChild<QLabel*>(QStringLiteral("accuracyErrorMap"))->pixmap().isNull());
    // Over the viewport on request.
    auto* overlay = panel().findChild<QCheckBox*>(QStringLiteral("accuracyOverlay"));
    ASSERT_TRUE(overlay->isEnabled());
    overlay->setChecked(true);
    auto* over = m_window->viewport().findChild<QWidget*>(QStringLiteral("errorMapOverlay"));
    ASSERT_NE(over, nullptr);
    EXPECT_TRUE(over->isVisible());
    EXPECT_EQ(over->size(), m_window->viewport().size());
    // The chart of a sweep too, for the picture.
    QTemporaryDir dir;
    ASSERT_TRUE(panel().loadSweepFile(writeResults(dir)).ok());
    ASSERT_TRUE(waitForFrames(*m_window, 2));
    const QString shot = QString::fromStdString(speculum::testDataPath("editor-accuracy-panel.png"));
    ASSERT_TRUE(m_window->grab().save(shot));
    std::printf("screenshot: %s\n", qPrintable(shot));

    // A cancelled comparison keeps the last numbers and says so.
    const double psnr = r.psnr;
    panel().setPreviewWidth(1200);
    panel().compareWithExact();
    panel().cancelComparison();
    ASSERT_TRUE(waitFor([&] { return !panel().comparing(); }, 180000));
    EXPECT_EQ(text("accuracyStatus"), QStringLiteral("Cancelled."));
    EXPECT_EQ(panel().lastComparison()->psnr, psnr);
}

TEST_F(AccuracyPanelTest, ClickingASweepPointAppliesItsSettingsAsOneUndoStep) {
    QTemporaryDir dir;
    const QString path = writeResults(dir);

    EXPECT_FALSE(panel().loadSweepFile(dir.filePath(QStringLiteral("missing.json"))).ok());
    ASSERT_TRUE(panel().loadSweepFile(path).ok());
    SweepChart& chart = panel().chart();
    EXPECT_EQ(chart.seriesCount(), 4); // one per family: scene, envmap, mirror-depth, shadows
    const scene::SceneData before = m_window->scene().toData();
    ASSERT_NE(reflectorOf(m_window->scene()), nullptr);
    EXPECT_EQ(reflectorOf(m_window->scene())->map, scene::ReflectorMap::Cube);

    // A real mouse click on the envmap point.
    QScatterSeries* envmap = nullptr;
    for (QAbstractSeries* s : chart.chart()->series()) {
        if (s->name() == QStringLiteral("envmap")) {
            envmap = qobject_cast<QScatterSeries*>(s);
        }
    }
    ASSERT_NE(envmap, nullptr);
    QApplication::processEvents();
    const QPoint at = chart.mapFromScene(chart.chart()->mapToPosition(QPointF(2.0, 28.0), envmap));
    QTest::mouseClick(chart.viewport(), Qt::LeftButton, {}, at);
    ASSERT_TRUE(waitFor([&] { return m_window->undoStack().count() == 1; }, 5000))
        << "the click at " << at.x() << "," << at.y() << " applied nothing";

    const auto* reflector = reflectorOf(m_window->scene());
    EXPECT_EQ(reflector->map, scene::ReflectorMap::TennisBall);
    EXPECT_EQ(reflector->resolution, 64);
    EXPECT_EQ(reflector->fill, scene::ReflectorFill::Direct);
    EXPECT_EQ(m_window->scene().settings().mirrorDepth, 2);
    int pcf = 0;
    m_window->scene().forEachNode([&](const scene::Node& node) {
        if (node.data().light && node.data().light->shadows) {
            pcf = node.data().light->shadows->pcf;
        }
    });
    EXPECT_EQ(pcf, 3);
    // The Edit menu names the change; undo takes it all back in one step.
    EXPECT_TRUE(m_window->undoStack().undoText().startsWith(QStringLiteral("Apply Sweep Setting envmap 64")))
        << m_window->undoStack().undoText().toStdString();
    m_window->undoStack().undo();
    EXPECT_EQ(m_window->scene().toData(), before);
    m_window->undoStack().redo();
    EXPECT_EQ(reflectorOf(m_window->scene())->map, scene::ReflectorMap::TennisBall);

    // Settings the scene cannot take are named, the rest still applied.
    m_window->undoStack().undo();
    const QString message = panel().applyRecord(0);
    EXPECT_TRUE(message.contains(QStringLiteral("Not applied")) == false) << message.toStdString();
    EXPECT_TRUE(message.contains(QStringLiteral("the document already has these settings")))
        << message.toStdString();
    EXPECT_EQ(m_window->scene().toData(), before); // the scene's own settings: nothing to change
}

// A point none of whose settings the document can take says so, and names them; it never claims the
// document already had them.
TEST_F(AccuracyPanelTest, APointThatAppliesNothingSaysWhy) {
    QTemporaryDir dir;
    ASSERT_TRUE(panel().loadSweepFile(writeResults(dir, kUnknownSettingResults)).ok());
    const int steps = m_window->undoStack().count();
    const QString message = panel().applyRecord(0);
    EXPECT_EQ(message,
              QStringLiteral("envmap future: nothing applied. Not applied: futureSetting = on: this version "
                             "does not know the setting."));
    EXPECT_EQ(m_window->undoStack().count(), steps);
}

TEST_F(AccuracyPanelTest, RunSweepFillsTheChartAsItGoesAndShowsTheFindings) {
    QTemporaryDir dir;
    const QString scene = dir.filePath(QStringLiteral("tiny.speculum.json"));
    {
        QFile file(scene);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(kTinyScene);
    }
    ASSERT_TRUE(m_window->openProjectFile(scene).ok());
    ASSERT_TRUE(waitForFrames(*m_window, 2));
    const scene::SceneData before = m_window->scene().toData();
    ASSERT_EQ(m_window->undoStack().count(), 0);

    panel().findChild<QPushButton*>(QStringLiteral("runSweep"))->click();
    ASSERT_TRUE(panel().sweeping());
    EXPECT_FALSE(panel().findChild<QPushButton*>(QStringLiteral("runSweep"))->isEnabled());
    EXPECT_TRUE(panel().findChild<QPushButton*>(QStringLiteral("cancelSweep"))->isEnabled());
    EXPECT_TRUE(panel().findChild<QProgressBar*>(QStringLiteral("sweepProgress"))->isVisible());
    // Points arrive before the sweep is done (the timing rounds come after every point is measured).
    int seenWhileRunning = 0;
    QString statusWhileRunning;
    ASSERT_TRUE(waitFor(
        [&] {
            if (panel().sweeping() && panel().chart().pointCount() > 0 && seenWhileRunning == 0) {
                seenWhileRunning = panel().chart().pointCount();
                statusWhileRunning = text("sweepStatus");
            }
            return !panel().sweeping();
        },
        300000));
    EXPECT_GT(seenWhileRunning, 0) << "no point in the chart before the sweep finished";
    EXPECT_TRUE(statusWhileRunning.contains(QStringLiteral(" of "))) << statusWhileRunning.toStdString();
    EXPECT_TRUE(text("sweepMessage").startsWith(QStringLiteral("5 configurations of tiny.speculum.json")))
        << text("sweepMessage").toStdString();
    EXPECT_EQ(panel().chart().pointCount(), 5);
    EXPECT_EQ(panel().chart().seriesCount(), 2); // scene, shadows
    const auto& records = panel().chart().results().records;
    ASSERT_EQ(records.size(), 5u);
    for (const auto& r : records) {
        EXPECT_TRUE(std::isfinite(r.psnr)) << r.config.id;
        EXPECT_GT(r.cpuMs, 0.0) << r.config.id;
    }
    // The report's findings, in plain words, in the panel.
    const QString findings = panel().findingsText();
    EXPECT_TRUE(findings.contains(QStringLiteral("Shadow filtering"))) << findings.toStdString();
    EXPECT_TRUE(findings.contains(QStringLiteral("Best: **pcf "))) << findings.toStdString();
    EXPECT_TRUE(findings.contains(QStringLiteral("Cheapest within 1 dB of the best")))
        << findings.toStdString();
    EXPECT_TRUE(panel().findChild<QWidget*>(QStringLiteral("sweepFindingsScroll"))->isVisible());
    EXPECT_FALSE(panel().findChild<QProgressBar*>(QStringLiteral("sweepProgress"))->isVisible());
    // The sweep measured the document; it changed nothing in it.
    EXPECT_EQ(m_window->undoStack().count(), 0);
    EXPECT_TRUE(m_window->undoStack().isClean());
    EXPECT_EQ(m_window->scene().toData(), before);
    // Its points apply like a loaded run's: pcf 1 is one undo step.
    int pcf1 = -1;
    for (std::size_t i = 0; i < records.size(); ++i) {
        if (records[i].config.id == "pcf-1") {
            pcf1 = int(i);
        }
    }
    ASSERT_GE(pcf1, 0);
    panel().applyRecord(pcf1);
    EXPECT_EQ(m_window->undoStack().count(), 1);
}

TEST_F(AccuracyPanelTest, CancelStopsTheSweepAndLeavesEverythingAsItWas) {
    QTemporaryDir dir;
    ASSERT_TRUE(panel().loadSweepFile(writeResults(dir)).ok());
    const int pointsBefore = panel().chart().pointCount();
    ASSERT_EQ(pointsBefore, 5);
    const scene::SceneData before = m_window->scene().toData();

    panel().runSweep(true);
    ASSERT_TRUE(panel().sweeping());
    // Cancel in the middle: once the tracer has started (or points come in).
    ASSERT_TRUE(waitFor(
        [&] {
            return text("sweepStatus").contains(QStringLiteral("%")) || panel().chart().pointCount() > 0 ||
                   !panel().sweeping();
        },
        120000));
    ASSERT_TRUE(panel().sweeping()) << "the chrome sweep ended before it could be cancelled";
    QElapsedTimer stopping;
    stopping.start();
    panel().findChild<QPushButton*>(QStringLiteral("cancelSweep"))->click();
    ASSERT_TRUE(waitFor([&] { return !panel().sweeping(); }, 30000));
    const qint64 ms = stopping.elapsed();
    std::printf("the sweep stopped %lld ms after Cancel\n", static_cast<long long>(ms));
    EXPECT_LT(ms, 2000) << "Cancel should stop the sweep within about a second";
    // Idle again, the chart as it was, the document untouched.
    EXPECT_EQ(text("sweepMessage"), QStringLiteral("Sweep cancelled; nothing changed."));
    EXPECT_TRUE(panel().findChild<QPushButton*>(QStringLiteral("runSweep"))->isEnabled());
    EXPECT_FALSE(panel().findChild<QPushButton*>(QStringLiteral("cancelSweep"))->isEnabled());
    EXPECT_FALSE(panel().findChild<QProgressBar*>(QStringLiteral("sweepProgress"))->isVisible());
    EXPECT_EQ(panel().chart().pointCount(), pointsBefore);
    EXPECT_TRUE(panel().findingsText().isEmpty());
    EXPECT_EQ(m_window->undoStack().count(), 0);
    EXPECT_EQ(m_window->scene().toData(), before);
}

// What the numbers measured is on screen: the exact image, the raster image and the error map side by
// side, and a flip view in which the Flip button (or a click on the image) alternates exact and raster.
// The glossy demo's rough mirror: the exact image is refined level by level, each shown as it is done with
// the noise it has left, after an estimate of the whole; the images have a still's aspect whatever the
// viewport's shape.
TEST_F(AccuracyPanelTest, TheExactImageIsRefinedProgressivelyWithItsNoiseAndTimeLeft) {
    ASSERT_TRUE(m_window->openProjectFile(kGlossy).ok());
    ASSERT_TRUE(waitForFrames(*m_window, 2));
    ExactComparison* comparison = panel().findChild<ExactComparison*>();
    ASSERT_NE(comparison, nullptr);
    std::vector<double> estimates;
    std::vector<ComparisonResult> levels;
    std::vector<double> secondsLeft;
    int lastLevel = 64;
    QObject::connect(comparison, &ExactComparison::estimated, comparison, [&](double seconds, int paths) {
        EXPECT_TRUE(levels.empty()) << "the estimate comes before the first level";
        EXPECT_EQ(paths, lastLevel);
        estimates.push_back(seconds);
    });
    QObject::connect(comparison, &ExactComparison::progress, comparison,
                     [&](double, int, double left) { secondsLeft.push_back(left); });
    QObject::connect(comparison, &ExactComparison::refined, comparison, [&](const ComparisonResult& r) {
        levels.push_back(r);
        EXPECT_TRUE(panel().comparing()) << "a level shown while the next is traced";
        EXPECT_EQ(text("accuracyPsnr"), QStringLiteral("%1 dB").arg(r.psnr, 0, 'f', 2)) << "shown at once";
    });
    QObject::connect(comparison, &ExactComparison::finished, comparison,
                     [&](const ComparisonResult& r) { levels.push_back(r); });
    panel().setPreviewWidth(96);
    panel().setPaths(64);
    panel().compareWithExact();
    ASSERT_TRUE(waitFor([&] { return !panel().comparing(); }, 180000));
    ASSERT_EQ(estimates.size(), 1u);
    EXPECT_GT(estimates.front(), 0.0);
    ASSERT_EQ(levels.size(), 3u) << text("accuracyStatus").toStdString();
    const int expectedPaths[] = {4, 16, 64};
    for (std::size_t i = 0; i < levels.size(); ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(levels[i].paths, expectedPaths[i]);
        EXPECT_EQ(levels[i].final, i + 1 == levels.size());
        EXPECT_EQ(levels[i].width, 96);
        EXPECT_EQ(levels[i].height, 54) << "a still's aspect, not the viewport's";
        EXPECT_GT(levels[i].roughPixels, 0) << "the rough mirror is in view";
        EXPECT_TRUE(std::isfinite(levels[i].psnr));
        if (i > 0) {
            // Four times the paths: about half the noise.
            EXPECT_LT(levels[i].noiseRms, levels[i - 1].noiseRms * 0.7);
            EXPECT_GT(levels[i].noiseRms, levels[i - 1].noiseRms * 0.3);
        }
    }
    EXPECT_FALSE(secondsLeft.empty());
    for (double left : secondsLeft)
        EXPECT_TRUE(std::isfinite(left) && left >= 0.0) << left;
    EXPECT_EQ(panel().lastComparison()->paths, 64);
    EXPECT_TRUE(text("accuracyNoise").contains(QStringLiteral("at 64 paths per rough pixel")))
        << text("accuracyNoise").toStdString();

    // Cancel while refining: the last level done stands, and nothing is lost.
    levels.clear();
    lastLevel = 256;
    panel().setPaths(256);
    panel().setPreviewWidth(160);
    QObject::connect(comparison, &ExactComparison::refined, comparison, [&] { panel().cancelComparison(); });
    panel().compareWithExact();
    ASSERT_TRUE(waitFor([&] { return !panel().comparing(); }, 180000));
    // (A level the worker finished while the cancel was on its way is shown too.)
    ASSERT_GE(levels.size(), 2u) << "a level, then the result it stands as";
    const ComparisonResult& stands = levels.back();
    EXPECT_TRUE(stands.final);
    EXPECT_EQ(stands.paths, levels[levels.size() - 2].paths) << "the last level shown";
    EXPECT_LT(stands.paths, 256) << "stopped before the end";
    EXPECT_EQ(panel().lastComparison()->paths, stands.paths);
    EXPECT_EQ(panel().lastComparison()->width, 160);
}

// A scene with nothing rough in view is exact at the first level: no refinement, and it says so.
TEST_F(AccuracyPanelTest, AViewWithNothingRoughIsExactAtOnce) {
    int refinements = 0;
    QObject::connect(panel().findChild<ExactComparison*>(), &ExactComparison::refined, &panel(),
                     [&] { ++refinements; });
    panel().setPreviewWidth(96);
    panel().setPaths(256);
    panel().compareWithExact();
    ASSERT_TRUE(waitFor([&] { return !panel().comparing(); }, 180000));
    ASSERT_TRUE(panel().lastComparison().has_value());
    EXPECT_EQ(refinements, 0);
    EXPECT_EQ(panel().lastComparison()->roughPixels, 0);
    EXPECT_EQ(panel().lastComparison()->noiseRms, 0.0);
    EXPECT_TRUE(text("accuracyNoise").startsWith(QStringLiteral("none")))
        << text("accuracyNoise").toStdString();
}

TEST_F(AccuracyPanelTest, TheImagesShowSideBySideAndTheFlipViewAlternates) {
    EXPECT_TRUE(panel().explanationText().contains(QStringLiteral("above 40 dB")))
        << panel().explanationText().toStdString();
    EXPECT_TRUE(panel().explanationText().contains(QStringLiteral("below 30 dB")));
    panel().setPreviewWidth(120);
    panel().compareWithExact();
    ASSERT_TRUE(waitFor([&] { return !panel().comparing(); }, 180000));
    ASSERT_TRUE(panel().lastComparison().has_value()) << text("accuracyStatus").toStdString();
    const ComparisonResult& r = *panel().lastComparison();
    ASSERT_EQ(r.reference.size(), QSize(r.width, r.height));
    ASSERT_EQ(r.raster.size(), QSize(r.width, r.height));
    EXPECT_NE(r.reference, r.raster) << "the raster frame is an approximation: some pixel differs";

    auto tile = [&](const char* name) { return panel().findChild<ImageTile*>(QString::fromLatin1(name)); };
    ImageTile* reference = tile("accuracyReference");
    ImageTile* raster = tile("accuracyRaster");
    ImageTile* errorMap = tile("accuracyErrorMap");
    ImageTile* flipView = tile("accuracyFlipView");
    ASSERT_TRUE(reference && raster && errorMap && flipView);
    EXPECT_EQ(reference->image(), r.reference);
    EXPECT_EQ(raster->image(), r.raster);
    EXPECT_EQ(errorMap->image(), r.errorMap);
    for (ImageTile* t : {reference, raster, errorMap}) {
        EXPECT_TRUE(t->isVisible()) << t->objectName().toStdString();
        EXPECT_GT(t->width(), 40) << t->objectName().toStdString();
        // Three across the dock, none cut off at its right edge.
        EXPECT_LE(t->mapTo(m_dock, QPoint(t->width(), 0)).x(), m_dock->width())
            << t->objectName().toStdString();
    }
    EXPECT_FALSE(flipView->isVisible());
    // The three side by side: left to right, on one row.
    EXPECT_LT(reference->mapTo(&panel(), QPoint()).x(), raster->mapTo(&panel(), QPoint()).x());
    EXPECT_LT(raster->mapTo(&panel(), QPoint()).x(), errorMap->mapTo(&panel(), QPoint()).x());
    EXPECT_EQ(reference->mapTo(&panel(), QPoint()).y(), errorMap->mapTo(&panel(), QPoint()).y());
    const QString shots = qEnvironmentVariable("SPECULUM_SHOTS_DIR");
    if (!shots.isEmpty()) {
        QApplication::processEvents();
        EXPECT_TRUE(m_dock->grab().save(shots + QStringLiteral("/accuracy-side-by-side.png")));
    }

    // The flip view: one image, the exact one first.
    auto* mode = panel().findChild<QComboBox*>(QStringLiteral("accuracyImageMode"));
    ASSERT_NE(mode, nullptr);
    mode->setCurrentIndex(1);
    QApplication::processEvents();
    EXPECT_TRUE(flipView->isVisible());
    EXPECT_FALSE(reference->isVisible());
    EXPECT_GE(flipView->height(), std::min(r.height, 200)) << "larger than a tile";
    EXPECT_LE(flipView->mapTo(m_dock, QPoint(flipView->width(), 0)).x(), m_dock->width());
    auto* flip = panel().findChild<QPushButton*>(QStringLiteral("accuracyFlipButton"));
    ASSERT_NE(flip, nullptr);
    ASSERT_TRUE(flip->isVisible());
    EXPECT_TRUE(panel().flipShowsReference());
    EXPECT_EQ(flipView->image(), r.reference);
    EXPECT_TRUE(text("accuracyFlipCaption").startsWith(QStringLiteral("Exact")))
        << text("accuracyFlipCaption").toStdString();
    if (!shots.isEmpty()) {
        QApplication::processEvents();
        EXPECT_TRUE(m_dock->grab().save(shots + QStringLiteral("/accuracy-flip-exact.png")));
    }
    QTest::mouseClick(flip, Qt::LeftButton);
    EXPECT_FALSE(panel().flipShowsReference());
    EXPECT_EQ(flipView->image(), r.raster);
    EXPECT_EQ(flipView->pixmap().toImage().convertToFormat(QImage::Format_RGB32),
              r.raster.convertToFormat(QImage::Format_RGB32));
    EXPECT_TRUE(text("accuracyFlipCaption").startsWith(QStringLiteral("Raster")));
    if (!shots.isEmpty()) {
        QApplication::processEvents();
        EXPECT_TRUE(m_dock->grab().save(shots + QStringLiteral("/accuracy-flip-raster.png")));
    }
    // A click on the image flips back.
    QTest::mouseClick(flipView, Qt::LeftButton, {}, flipView->rect().center());
    EXPECT_TRUE(panel().flipShowsReference());
    EXPECT_EQ(flipView->image(), r.reference);
    // Nothing of this touched the document.
    EXPECT_EQ(m_window->undoStack().count(), 0);
    panel().setImageMode(AccuracyPanel::ImageMode::SideBySide);
    EXPECT_TRUE(reference->isVisible());
    EXPECT_FALSE(flip->isVisible());
}

// Beside RMSE and PSNR the comparison shows the PSNR's interval, MAE, SSIM and FLIP, and the FLIP map; the
// zoomable view swipes between exact and raster (the wheel zooms about the pointer, the line drags, the
// image pans, a double-click fits) or shows them side by side; the overlay shows either map.
TEST_F(AccuracyPanelTest, PerceptualFiguresTheFlipMapAndTheZoomableSwipeView) {
    panel().setPreviewWidth(120);
    panel().compareWithExact();
    ASSERT_TRUE(waitFor([&] { return !panel().comparing(); }, 180000));
    ASSERT_TRUE(panel().lastComparison().has_value()) << text("accuracyStatus").toStdString();
    const ComparisonResult& r = *panel().lastComparison();
    EXPECT_GT(r.flip, 0.0);
    EXPECT_LT(r.flip, 1.0);
    EXPECT_GT(r.hdrFlip, 0.0);
    EXPECT_GT(r.ssim, 0.0);
    EXPECT_LT(r.ssim, 1.0);
    EXPECT_GT(r.mae, 0.0);
    EXPECT_EQ(text("accuracyFlip"),
              QStringLiteral("%1 · %2").arg(r.flip, 0, 'f', 4).arg(r.hdrFlip, 0, 'f', 4));
    EXPECT_EQ(text("accuracySsim"), QString::number(r.ssim, 'f', 4));
    EXPECT_EQ(text("accuracyMae"), QString::number(r.mae, 'f', 4));
    EXPECT_TRUE(text("accuracyPsnrInterval").startsWith(QStringLiteral("exact")))
        << "the chrome demo has nothing rough: " << text("accuracyPsnrInterval").toStdString();
    EXPECT_TRUE(panel().explanationText().contains(QStringLiteral("FLIP")));
    ASSERT_EQ(r.flipMap.size(), QSize(r.width, r.height));
    auto* flipMap = panel().findChild<ImageTile*>(QStringLiteral("accuracyFlipMap"));
    ASSERT_NE(flipMap, nullptr);
    EXPECT_EQ(flipMap->image(), r.flipMap);
    EXPECT_TRUE(flipMap->isVisible());

    // The overlay: the error map, or the FLIP map.
    auto* overlay = m_window->findChild<QWidget*>(QStringLiteral("errorMapOverlay"));
    ASSERT_NE(overlay, nullptr);
    auto overlayImage = [&] { return overlay->grab().toImage(); };
    panel().findChild<QCheckBox*>(QStringLiteral("accuracyOverlay"))->setChecked(true);
    QApplication::processEvents();
    const QImage withErrorMap = overlayImage();
    panel().setOverlayMap(AccuracyPanel::OverlayMap::Flip);
    QApplication::processEvents();
    EXPECT_NE(overlayImage(), withErrorMap) << "the FLIP map is drawn instead";

    // The swipe view: both images, split at the middle.
    panel().setImageMode(AccuracyPanel::ImageMode::Swipe);
    QApplication::processEvents();
    CompareView& view = panel().compareView();
    ASSERT_TRUE(view.isVisible());
    EXPECT_FALSE(flipMap->isVisible());
    EXPECT_EQ(view.layoutMode(), CompareView::Layout::Swipe);
    EXPECT_EQ(view.zoom(), 1.0);
    EXPECT_DOUBLE_EQ(view.divider(), 0.5);
    // Drag the swipe line (at the middle while the image fits) to the right: more of the exact image shows.
    const QPoint onLine(view.rect().center().x(), view.height() / 2);
    QTest::mousePress(&view, Qt::LeftButton, {}, onLine);
    QTest::mouseMove(&view, onLine + QPoint(30, 0));
    QTest::mouseRelease(&view, Qt::LeftButton, {}, onLine + QPoint(30, 0));
    EXPECT_GT(view.divider(), 0.5) << "the line follows the drag";
    const QImage fitted = view.grab().toImage();
    // Zoom about a point left of the centre: the image point under it stays under it.
    const QPoint anchor = view.rect().center() - QPoint(view.width() / 6, 0);
    const QPointF before = view.imagePointAt(anchor);
    QWheelEvent wheel(anchor, view.mapToGlobal(anchor), QPoint(), QPoint(0, 240), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(&view, &wheel);
    EXPECT_NEAR(view.zoom(), 1.5625, 1e-9) << "two steps of 1.25";
    EXPECT_NEAR(view.imagePointAt(anchor).x(), before.x(), 1e-6);
    EXPECT_NEAR(view.imagePointAt(anchor).y(), before.y(), 1e-6);
    EXPECT_NE(view.grab().toImage(), fitted) << "the zoom shows";
    // Drag elsewhere pans: the point under the pointer moves with it.
    const QPoint from(view.width() / 5, view.height() / 3);
    const QPointF under = view.imagePointAt(from);
    QTest::mousePress(&view, Qt::LeftButton, {}, from);
    QTest::mouseMove(&view, from + QPoint(20, 10));
    QTest::mouseRelease(&view, Qt::LeftButton, {}, from + QPoint(20, 10));
    EXPECT_NEAR(view.imagePointAt(from + QPoint(20, 10)).x(), under.x(), 0.5);
    // (Sent as an event: QTest's own double-click leaves its click timing to the next test's moves.)
    QMouseEvent doubleClick(QEvent::MouseButtonDblClick, QPointF(from), view.mapToGlobal(QPointF(from)),
                            Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(&view, &doubleClick);
    EXPECT_EQ(view.zoom(), 1.0) << "a double-click fits the image again";
    const QString shots = qEnvironmentVariable("SPECULUM_SHOTS_DIR");
    if (!shots.isEmpty()) {
        view.setZoom(4.0, view.rect().center());
        QApplication::processEvents();
        EXPECT_TRUE(m_dock->grab().save(shots + QStringLiteral("/accuracy-swipe.png")));
    }
    // Exact beside raster, zoomable: two panes.
    panel().setImageMode(AccuracyPanel::ImageMode::ZoomSideBySide);
    QApplication::processEvents();
    EXPECT_EQ(view.layoutMode(), CompareView::Layout::SideBySide);
    EXPECT_TRUE(view.isVisible());
    if (!shots.isEmpty()) {
        QApplication::processEvents();
        EXPECT_TRUE(m_dock->grab().save(shots + QStringLiteral("/accuracy-zoom-side-by-side.png")));
    }
    EXPECT_EQ(m_window->undoStack().count(), 0) << "looking changes nothing in the document";
}

// clear() (what New and Open do) empties the images, the numbers and the chart.
TEST_F(AccuracyPanelTest, ClearEmptiesTheImagesTheNumbersAndTheChart) {
    panel().setPreviewWidth(64);
    panel().compareWithExact();
    ASSERT_TRUE(waitFor([&] { return !panel().comparing(); }, 180000));
    ASSERT_TRUE(panel().lastComparison().has_value()) << text("accuracyStatus").toStdString();
    QTemporaryDir dir;
    ASSERT_TRUE(panel().loadSweepFile(writeResults(dir)).ok());
    auto* overlay = panel().findChild<QCheckBox*>(QStringLiteral("accuracyOverlay"));
    overlay->setChecked(true);
    const QStringList tiles{QStringLiteral("accuracyReference"), QStringLiteral("accuracyRaster"),
                            QStringLiteral("accuracyErrorMap"), QStringLiteral("accuracyFlipView")};
    for (const QString& name : tiles) {
        EXPECT_FALSE(panel().findChild<ImageTile*>(name)->image().isNull()) << name.toStdString();
    }

    panel().clear();
    EXPECT_FALSE(panel().lastComparison().has_value());
    for (const QString& name : tiles) {
        auto* tile = panel().findChild<ImageTile*>(name);
        EXPECT_TRUE(tile->image().isNull()) << name.toStdString();
        EXPECT_TRUE(tile->pixmap().isNull()) << name.toStdString();
    }
    EXPECT_FALSE(panel().findChild<QWidget*>(QStringLiteral("accuracyImages"))->isVisible());
    for (const char* name : {"accuracyPsnr", "accuracyRmse", "accuracyPsnrReflector", "accuracyTraceMs"}) {
        EXPECT_EQ(text(name), QStringLiteral("—")) << name;
    }
    EXPECT_EQ(panel().chart().pointCount(), 0);
    EXPECT_FALSE(overlay->isChecked());
    EXPECT_FALSE(overlay->isEnabled());
    EXPECT_FALSE(m_window->viewport().findChild<QWidget*>(QStringLiteral("errorMapOverlay"))->isVisible());

    // Opening a project clears it too (the main window's File ▸ Open path).
    ASSERT_TRUE(panel().loadSweepFile(writeResults(dir)).ok());
    ASSERT_GT(panel().chart().pointCount(), 0);
    ASSERT_TRUE(m_window->openProjectFile(kChrome).ok());
    QApplication::processEvents();
    EXPECT_EQ(panel().chart().pointCount(), 0);
}

// Resting the pointer on a chart point labels it with its configuration, its settings, its frame time
// and its PSNR; moving off takes the label away.
// Each family has a colour and a marker of its own, the same in every run; the time axis keeps its title
// from the empty chart to the filled one.
TEST_F(AccuracyPanelTest, FamiliesHaveDistinctColoursAndMarkersAndTheAxisTitleStays) {
    SweepChart& chart = panel().chart();
    auto timeAxisTitle = [&] {
        const auto axes = chart.chart()->axes(Qt::Horizontal);
        return axes.isEmpty() ? QString() : axes.front()->titleText();
    };
    chart.setResults({});
    const QString emptyTitle = timeAxisTitle();
    QTemporaryDir dir;
    ASSERT_TRUE(panel().loadSweepFile(writeResults(dir)).ok());
    EXPECT_EQ(timeAxisTitle(), emptyTitle);
    std::map<QString, std::pair<QRgb, int>> styles;
    for (QAbstractSeries* s : chart.chart()->series()) {
        auto* scatter = qobject_cast<QScatterSeries*>(s);
        if (scatter && scatter->name() != QStringLiteral("applied")) {
            styles[scatter->name()] = {scatter->color().rgb(), int(scatter->markerShape())};
        }
    }
    ASSERT_GE(styles.size(), 4u) << "scene, envmap, mirror-depth, shadows";
    std::set<QRgb> colours;
    std::set<int> shapes;
    for (const auto& [family, style] : styles) {
        EXPECT_TRUE(colours.insert(style.first).second) << family.toStdString() << ": a colour of its own";
        shapes.insert(style.second);
    }
    EXPECT_GE(shapes.size(), 4u) << "markers differ too, for a reader who cannot tell the colours apart";
    // Loaded again, the families keep their looks.
    ASSERT_TRUE(panel().loadSweepFile(writeResults(dir)).ok());
    for (QAbstractSeries* s : chart.chart()->series()) {
        auto* scatter = qobject_cast<QScatterSeries*>(s);
        if (scatter && styles.count(scatter->name())) {
            EXPECT_EQ(scatter->color().rgb(), styles[scatter->name()].first);
        }
    }
}

TEST_F(AccuracyPanelTest, AChartPointShowsItsSettingsTimeAndPsnrOnHover) {
    QTemporaryDir dir;
    ASSERT_TRUE(panel().loadSweepFile(writeResults(dir)).ok());
    SweepChart& chart = panel().chart();
    QScatterSeries* envmap = nullptr;
    for (QAbstractSeries* s : chart.chart()->series()) {
        if (s->name() == QStringLiteral("envmap")) {
            envmap = qobject_cast<QScatterSeries*>(s);
        }
    }
    ASSERT_NE(envmap, nullptr);
    // The chart sits under the comparison's figures: scrolled to, as a user would.
    auto* scroll = panel().findChild<QScrollArea*>(QStringLiteral("accuracyScroll"));
    ASSERT_NE(scroll, nullptr);
    scroll->ensureWidgetVisible(&chart);
    ASSERT_TRUE(waitForFrames(*m_window, 1));
    QApplication::processEvents();
    EXPECT_TRUE(chart.hoverText().isEmpty());
    const QPoint at = chart.mapFromScene(chart.chart()->mapToPosition(QPointF(2.0, 28.0), envmap));
    QTest::mouseMove(chart.viewport(), at + QPoint(20, 20));
    QTest::mouseMove(chart.viewport(), at);
    ASSERT_TRUE(waitFor([&] { return !chart.hoverText().isEmpty(); }, 3000))
        << "no label at " << at.x() << "," << at.y();
    const QString label = chart.hoverText();
    EXPECT_TRUE(label.startsWith(QStringLiteral("envmap 64"))) << label.toStdString();
    EXPECT_TRUE(label.contains(QStringLiteral("2.00 ms GPU")))
        << "which clock timed it: " << label.toStdString();
    EXPECT_TRUE(label.contains(QStringLiteral("PSNR 28.00 dB"))) << label.toStdString();
    EXPECT_TRUE(label.contains(QStringLiteral("map tennis-ball"))) << label.toStdString();
    EXPECT_TRUE(label.contains(QStringLiteral("resolution 64"))) << label.toStdString();
    EXPECT_TRUE(label.contains(QStringLiteral("fill direct"))) << label.toStdString();
    // Drawn in the chart, beside the point.
    bool shown = false;
    for (QGraphicsItem* item : chart.scene()->items()) {
        if (auto* textItem = dynamic_cast<QGraphicsTextItem*>(item)) {
            shown |= textItem->isVisible() && textItem->toPlainText() == label;
        }
    }
    EXPECT_TRUE(shown);
    EXPECT_EQ(chart.pointLabel(1), label) << "the label of results record 1";
    const QString shots = qEnvironmentVariable("SPECULUM_SHOTS_DIR");
    if (!shots.isEmpty()) {
        QApplication::processEvents();
        EXPECT_TRUE(m_dock->grab().save(shots + QStringLiteral("/accuracy-chart-hover.png")));
    }
    // Off the point, no label.
    QTest::mouseMove(chart.viewport(),
                     chart.mapFromScene(chart.chart()->plotArea().topLeft()) + QPoint(3, 3));
    ASSERT_TRUE(waitFor([&] { return chart.hoverText().isEmpty(); }, 3000));
    EXPECT_EQ(chart.pointLabel(99), QString());
}

// Pictures of the panel during and after a quick sweep of the chrome demo, when SPECULUM_SHOTS_DIR names
// a folder for them (minutes on a software rasterizer, so not part of the usual run).
TEST_F(AccuracyPanelTest, ScreenshotsOfAChromeSweep) {
    const QString shots = qEnvironmentVariable("SPECULUM_SHOTS_DIR");
    if (shots.isEmpty()) {
        GTEST_SKIP() << "set SPECULUM_SHOTS_DIR to take the screenshots";
    }
    m_window->resize(1600, 1000);
    panel().runSweep(true);
    ASSERT_TRUE(waitFor([&] { return panel().chart().pointCount() >= 12 || !panel().sweeping(); }, 600000));
    ASSERT_TRUE(panel().sweeping());
    QApplication::processEvents();
    ASSERT_TRUE(m_dock->grab().save(shots + QStringLiteral("/accuracy-during.png")));
    ASSERT_TRUE(waitFor([&] { return !panel().sweeping(); }, 1200000));
    ASSERT_FALSE(panel().findingsText().isEmpty()) << text("sweepMessage").toStdString();
    QApplication::processEvents();
    ASSERT_TRUE(m_dock->grab().save(shots + QStringLiteral("/accuracy-after.png")));
    ASSERT_TRUE(m_window->grab().save(shots + QStringLiteral("/accuracy-window.png")));
}

} // namespace
} // namespace speculum::ui

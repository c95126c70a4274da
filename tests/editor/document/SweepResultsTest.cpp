// Reading a bench results.json and giving a document one configuration's settings: the Pareto front the
// Accuracy chart draws and the parallax proxy it applies (both the accuracy library's), a results.json
// the bench writes read back into the same records, the errors a broken file gives, and an applied record
// that is one undo step and names the settings the scene has no place for.
#include "editor/document/SweepResults.hpp"

#include "accuracy/Analysis.hpp"
#include "render/mesh/Primitives.hpp"
#include "scene/model/Scene.hpp"
#include "scene/project/ProjectFile.hpp"
#include "support/DocumentTestSupport.hpp"
#include "support/TestPaths.hpp"

#include <QUndoStack>
#include <gtest/gtest.h>
#include <optional>

namespace speculum::document {
namespace {

accuracy::Record record(double ms, double psnr) {
    accuracy::Record r;
    r.config.family = accuracy::Family::Envmap;
    r.gpuMs = ms;
    r.psnr = psnr;
    return r;
}

// The chart's front is the library's: frame time against whole-frame PSNR across every record.
TEST(SweepResults, ParetoFrontKeepsWhatNothingFasterBeats) {
    const std::vector<accuracy::Record> records = {record(1, 20), record(2, 25), record(3, 22),
                                                   record(4, 30), record(4, 28), record(0.5, 18)};
    EXPECT_EQ(accuracy::paretoFront(records), (std::vector<std::size_t>{5, 0, 1, 3}));
    EXPECT_TRUE(accuracy::paretoFront(std::vector<accuracy::Record>{}).empty());
}

// What the bench writes is what the editor reads: one record type, through results.json and back.
TEST(SweepResults, WhatTheBenchWritesTheEditorReads) {
    const auto folder = test::freshTestFolder();
    const std::string path = (folder / "results.json").string();
    accuracy::RunInfo run;
    run.scene = "chrome.speculum.json";
    run.width = 480;
    run.height = 270;
    std::vector<accuracy::Record> records = {record(2.5, 31.0), record(3.5, 33.0)};
    records[0].config.id = "envmap-cube-64";
    records[0].config.label = "64";
    records[0].config.series = "cube";
    records[0].settings = {{"map", "cube"}, {"resolution", "64"}, {"parallax", "on"}};
    records[1].config.family = accuracy::Family::Scene;
    records[1].sceneSetting = true;
    records[1].gpuMs = -1.0;
    records[1].cpuMs = 7.25;
    records[1].psnrReflector = 29.5;
    ASSERT_TRUE(accuracy::writeJson(path, run, records).ok());
    auto loaded = loadSweepResults(QString::fromStdString(path));
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_EQ(loaded->size(), "480x270");
    ASSERT_EQ(loaded->records.size(), 2u);
    EXPECT_EQ(loaded->records[0].settings, records[0].settings);
    EXPECT_EQ(loaded->records[0].config.id, "envmap-cube-64");
    EXPECT_DOUBLE_EQ(accuracy::frameMs(loaded->records[0]), 2.5);
    EXPECT_DOUBLE_EQ(accuracy::frameMs(loaded->records[1]), 7.25);
    EXPECT_EQ(loaded->records[1].psnrReflector, std::optional<double>(29.5));
    EXPECT_EQ(accuracy::paretoFront(loaded->records), accuracy::paretoFront(records));
}

// "Parallax on" for a reflector without a proxy of its own is the sweep's box around the scene.
TEST(SweepResults, TheParallaxProxyIsTheSweeps) {
    render::FrameInput frame;
    const auto box = std::make_shared<const render::MeshData>(render::makeBox());
    frame.items.push_back({"Room", glm::dmat4(glm::dmat3(5.0)), box, {}, true});
    render::Reflector ball;
    ball.mesh = std::make_shared<const render::MeshData>(render::makeSphere(8));
    ball.world = glm::dmat4(glm::dmat3(0.5));
    frame.reflectors = {ball};
    const accuracy::SceneTraits traits = accuracy::sceneTraits(frame, std::nullopt);
    ASSERT_TRUE(traits.proxyMakesSense);
    const auto proxy = sweepParallaxProxy(frame);
    ASSERT_TRUE(proxy.has_value());
    EXPECT_EQ(proxy->shape, scene::ParallaxShape::Box);
    ASSERT_TRUE(traits.proxy);
    EXPECT_EQ(proxy->min, traits.proxy->min);
    EXPECT_EQ(proxy->max, traits.proxy->max);
    // Outside the room there is nothing around the ball for a box to stand for.
    frame.reflectors[0].world[3] = glm::dvec4(0.0, 40.0, 0.0, 1.0);
    EXPECT_FALSE(sweepParallaxProxy(frame).has_value());
}

TEST(SweepResults, BrokenFilesSayWhatIsWrong) {
    const auto folder = test::freshTestFolder();
    const QString path = test::qpath(folder / "results.json");
    test::writeBytes(path, R"({"format": "speculum-scene"})");
    auto wrong = loadSweepResults(path);
    ASSERT_FALSE(wrong.ok());
    EXPECT_NE(wrong.error().find("results.json: not a speculum bench result"), std::string::npos)
        << wrong.error();
    test::writeBytes(
        path, R"({"format": "speculum-bench", "results": [{"family": "scene", "cpuMs": 1, "rmse": 0}]})");
    auto missing = loadSweepResults(path);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("results[0].psnr: expected a number"), std::string::npos)
        << missing.error();
    EXPECT_FALSE(loadSweepResults(test::qpath(folder / "none.json")).ok());
}

TEST(SweepResults, AppliedSettingsAreOneUndoStepAndNameWhatDoesNotApply) {
    scene::Scene scene;
    std::vector<std::string> warnings;
    ASSERT_TRUE(scene::openProject(scene, test::demoScenePath(), warnings)
                    .ok()); // teapot, marble mirror, no reflector
    const scene::SceneData before = scene.toData();
    QUndoStack stack;
    auto application = applySweepSettings(scene,
                                          {{"map", "cube"},
                                           {"technique", "texture"},
                                           {"mirrorDepth", "1"},
                                           {"tessellation", "4"},
                                           {"reflectedDetail", "full"}},
                                          QStringLiteral("Apply Sweep Setting mirror-technique texture"));
    ASSERT_TRUE(application.command);
    ASSERT_EQ(application.skipped.size(), 1);
    EXPECT_EQ(application.skipped.front(), QStringLiteral("map = cube: the scene has no curved reflector"));
    stack.push(application.command.release());
    EXPECT_EQ(stack.count(), 1);
    EXPECT_EQ(stack.undoText(), QStringLiteral("Apply Sweep Setting mirror-technique texture"));
    EXPECT_EQ(scene.settings().mirrorDepth, 1);
    EXPECT_FALSE(scene.settings().simplifyReflections);
    int mirrors = 0, teapots = 0;
    scene.forEachNode([&](const scene::Node& node) {
        if (node.data().mirror) {
            ++mirrors;
            EXPECT_EQ(node.data().mirror->technique, scene::MirrorTechnique::Texture);
        }
        if (node.data().mesh && node.data().mesh->builtin == scene::BuiltinMesh::Teapot) {
            ++teapots;
            EXPECT_EQ(node.data().mesh->tessellation, 4);
        }
    });
    EXPECT_GT(mirrors, 0);
    EXPECT_GT(teapots, 0);
    stack.undo();
    EXPECT_EQ(scene.toData(), before);

    // Nothing to change: no command.
    auto same = applySweepSettings(scene, {{"mirrorDepth", std::to_string(scene.settings().mirrorDepth)}},
                                   QStringLiteral("same"));
    EXPECT_FALSE(same.command);
    EXPECT_TRUE(same.skipped.isEmpty());
}

// A point of the glossy family is a roughness and a filter ("footprint 16 taps", "mip", "prefilter 64
// samples"): applied from the Accuracy panel, it sets the scene's rough mirrors to that roughness and the
// settings to that filter, in one undo step, and undo gives the scene back.
TEST(SweepResults, AGlossyPointAppliesItsRoughnessAndFilter) {
    scene::Scene scene;
    std::vector<std::string> warnings;
    ASSERT_TRUE(scene::openProject(
                    scene,
                    QString::fromStdString(speculum::testSourcePath("resources/scenes/glossy.speculum.json")),
                    warnings)
                    .ok());
    const scene::SceneData before = scene.toData();
    auto footprint = applySweepSettings(scene, {{"roughness", "0.5"}, {"glossy", "footprint 4 taps"}},
                                        QStringLiteral("Apply Sweep Setting glossy-footprint-4-0.5"));
    ASSERT_TRUE(footprint.command);
    EXPECT_TRUE(footprint.skipped.isEmpty()) << footprint.skipped.join(QStringLiteral("; ")).toStdString();
    QUndoStack stack;
    stack.push(footprint.command.release());
    EXPECT_EQ(scene.settings().glossyFilter, render::GlossyFilter::Footprint);
    EXPECT_EQ(scene.settings().glossyTaps, 4);
    int rough = 0;
    scene.forEachNode([&](const scene::Node& node) {
        const auto& mirror = node.data().mirror;
        if (mirror && mirror->roughness > 0.0) {
            ++rough;
            EXPECT_EQ(mirror->roughness, 0.5) << node.data().name;
        }
    });
    EXPECT_GT(rough, 0) << "the glossy demo has rough mirrors";
    stack.undo();
    EXPECT_EQ(scene.toData(), before);

    auto mip = applySweepSettings(scene, {{"glossy", "mip"}}, QStringLiteral("mip"));
    ASSERT_TRUE(mip.command);
    stack.push(mip.command.release());
    EXPECT_EQ(scene.settings().glossyFilter, render::GlossyFilter::Mip);

    auto broken = applySweepSettings(scene, {{"glossy", "footprint many taps"}}, QStringLiteral("broken"));
    EXPECT_FALSE(broken.command);
    ASSERT_EQ(broken.skipped.size(), 1);
    EXPECT_TRUE(broken.skipped.front().startsWith(QStringLiteral("glossy = footprint many taps: ")))
        << broken.skipped.front().toStdString();
}

// The shadows family's kernel is a field of every shadowed light's shadow map.
TEST(SweepResults, AShadowPointSetsEveryShadowedLightsKernel) {
    scene::Scene scene;
    std::vector<std::string> warnings;
    ASSERT_TRUE(scene::openProject(
                    scene,
                    QString::fromStdString(speculum::testSourcePath("resources/scenes/chrome.speculum.json")),
                    warnings)
                    .ok());
    auto application = applySweepSettings(scene, {{"pcf", "7"}}, QStringLiteral("Apply Sweep Setting pcf 7"));
    EXPECT_TRUE(application.skipped.isEmpty())
        << application.skipped.join(QStringLiteral("; ")).toStdString();
    ASSERT_TRUE(application.command);
    QUndoStack stack;
    stack.push(application.command.release());
    int shadowed = 0;
    scene.forEachNode([&](const scene::Node& node) {
        if (node.data().light && node.data().light->shadows) {
            ++shadowed;
            EXPECT_EQ(node.data().light->shadows->pcf, 7);
        }
    });
    EXPECT_GT(shadowed, 0);
}

TEST(SweepResults, SettingsThatCancelOutGiveNoCommand) {
    scene::Scene scene;
    std::vector<std::string> warnings;
    ASSERT_TRUE(scene::openProject(scene, test::demoScenePath(), warnings).ok());
    std::optional<scene::MirrorTechnique> current;
    scene.forEachNode([&](const scene::Node& node) {
        if (node.data().mirror && !current)
            current = node.data().mirror->technique;
    });
    ASSERT_TRUE(current);
    const scene::MirrorTechnique other = *current == scene::MirrorTechnique::Stencil
                                             ? scene::MirrorTechnique::Texture
                                             : scene::MirrorTechnique::Stencil;
    // A later key edits the mirrors back to what they hold: nothing changes, so nothing is pushed.
    auto application = applySweepSettings(
        scene,
        {{"technique", std::string(render::names::fileName(render::names::kMirrorTechniques, other))},
         {"technique", std::string(render::names::fileName(render::names::kMirrorTechniques, *current))}},
        QStringLiteral("cancelled"));
    EXPECT_FALSE(application.command);
    EXPECT_EQ(application.applied.size(), 2);

    const std::string depth = std::to_string(scene.settings().mirrorDepth);
    const std::string otherDepth = std::to_string((scene.settings().mirrorDepth + 1) % 16);
    auto depths = applySweepSettings(scene, {{"mirrorDepth", otherDepth}, {"mirrorDepth", depth}},
                                     QStringLiteral("cancelled depth"));
    EXPECT_FALSE(depths.command);
    auto last = applySweepSettings(scene, {{"mirrorDepth", depth}, {"mirrorDepth", otherDepth}},
                                   QStringLiteral("last wins"));
    ASSERT_TRUE(last.command);
    last.command->redo();
    EXPECT_EQ(std::to_string(scene.settings().mirrorDepth), otherDepth);
}

} // namespace
} // namespace speculum::document

// Reading a bench results.json and giving a document one configuration's settings: the Pareto front the
// Accuracy chart draws, the errors a broken file gives, and an applied record that is one undo step and
// names the settings the scene has no place for.
#include "DocumentTestSupport.hpp"
#include "editor/document/ProjectFile.hpp"
#include "editor/document/Scene.hpp"
#include "editor/document/SweepResults.hpp"

#include <QUndoStack>
#include <gtest/gtest.h>

namespace speculum::document {
namespace {

SweepRecord record(double ms, double psnr) {
    SweepRecord r;
    r.family = QStringLiteral("envmap");
    r.gpuMs = ms;
    r.psnr = psnr;
    return r;
}

TEST(SweepResults, ParetoFrontKeepsWhatNothingFasterBeats) {
    const std::vector<SweepRecord> records = {record(1, 20), record(2, 25), record(3, 22),
                                              record(4, 30), record(4, 28), record(0.5, 18)};
    EXPECT_EQ(paretoFront(records), (std::vector<std::size_t>{5, 0, 1, 3}));
    EXPECT_TRUE(paretoFront({}).empty());
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
    Scene scene;
    std::vector<std::string> warnings;
    ASSERT_TRUE(
        openProject(scene, test::demoScenePath(), warnings).ok()); // teapot, marble mirror, no reflector
    const SceneData before = scene.toData();
    QUndoStack stack;
    auto application = applySweepSettings(scene,
                                          {{QStringLiteral("map"), QStringLiteral("cube")},
                                           {QStringLiteral("technique"), QStringLiteral("texture")},
                                           {QStringLiteral("mirrorDepth"), QStringLiteral("1")},
                                           {QStringLiteral("tessellation"), QStringLiteral("4")}},
                                          QStringLiteral("Apply Sweep Setting mirror-technique texture"));
    ASSERT_TRUE(application.command);
    ASSERT_EQ(application.skipped.size(), 1);
    EXPECT_EQ(application.skipped.front(), QStringLiteral("map = cube: the scene has no curved reflector"));
    stack.push(application.command.release());
    EXPECT_EQ(stack.count(), 1);
    EXPECT_EQ(stack.undoText(), QStringLiteral("Apply Sweep Setting mirror-technique texture"));
    EXPECT_EQ(scene.settings().mirrorDepth, 1);
    int mirrors = 0, teapots = 0;
    scene.forEachNode([&](const Node& node) {
        if (node.data().mirror) {
            ++mirrors;
            EXPECT_EQ(node.data().mirror->technique, MirrorTechnique::Texture);
        }
        if (node.data().mesh && node.data().mesh->builtin == BuiltinMesh::Teapot) {
            ++teapots;
            EXPECT_EQ(node.data().mesh->tessellation, 4);
        }
    });
    EXPECT_GT(mirrors, 0);
    EXPECT_GT(teapots, 0);
    stack.undo();
    EXPECT_EQ(scene.toData(), before);

    // Nothing to change: no command.
    auto same = applySweepSettings(
        scene, {{QStringLiteral("mirrorDepth"), QString::number(scene.settings().mirrorDepth)}},
        QStringLiteral("same"));
    EXPECT_FALSE(same.command);
    EXPECT_TRUE(same.skipped.isEmpty());
}

} // namespace
} // namespace speculum::document

// `speculum time` as a user runs it: frame-time statistics that hang together, the camera buffer the
// frames used, the passes a static frame reuses and an animated one redraws, and bad input refused.
#include "CliRun.hpp"
#include "support/TestPaths.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <gtest/gtest.h>
#include <map>
#include <string>

namespace {

using speculum::test::CliRun;
using speculum::test::runSpeculum;

std::string scene(const std::string& path) {
    return speculum::testSourcePath(path);
}

QJsonObject timeJson(const std::string& arguments) {
    const CliRun run = runSpeculum("time " + arguments + " --json");
    EXPECT_EQ(run.status, 0) << run.err;
    const QJsonDocument json = QJsonDocument::fromJson(QByteArray::fromStdString(run.out));
    EXPECT_TRUE(json.isObject()) << run.out;
    return json.object();
}

// Kind → runs per frame, from the JSON's passes.
std::map<std::string, double> runsPerFrame(const QJsonObject& o) {
    std::map<std::string, double> runs;
    for (const QJsonValue& p : o["passes"].toArray())
        runs[p["kind"].toString().toStdString()] = p["runsPerFrame"].toDouble();
    return runs;
}

TEST(TimeCommand, ReportsConsistentFrameTimesAndTheShareOfEachPass) {
    const QJsonObject o =
        timeJson(scene("benchmarks/scenes/ball.speculum.json") + " --frames 7 --size 160x90");
    EXPECT_EQ(o["frames"].toInt(), 7);
    EXPECT_EQ(o["size"].toString(), "160x90");
    EXPECT_EQ(o["frameMs"].toArray().size(), 7);
    const double median = o["medianMs"].toDouble();
    EXPECT_GT(o["minMs"].toDouble(), 0.0);
    EXPECT_LE(o["minMs"].toDouble(), median);
    EXPECT_LE(median, o["maxMs"].toDouble());
    EXPECT_NEAR(o["fps"].toDouble(), 1000.0 / median, 1e-6);
    EXPECT_EQ(o["cameraBuffer"].toString(), "srgb8") << "no mirror: nothing needs the half-float buffer";
    const auto runs = runsPerFrame(o);
    EXPECT_EQ(runs.at("main"), 1.0);
    // The target is like the editor's viewport (sRGB, with depth and stencil): the frame is drawn into it.
    EXPECT_TRUE(o["drawnIntoOutput"].toBool());
    EXPECT_EQ(runs.count("composite"), 0u) << "no copy into the output";
    EXPECT_NE(o["compositeReason"].toString().indexOf("composite pass not needed"), -1)
        << o["compositeReason"].toString().toStdString();
    double shares = 0.0;
    for (const QJsonValue& p : o["passes"].toArray())
        shares += p["share"].toDouble();
    if (o["gpuMsPerFrame"].toDouble() > 0.0) {
        EXPECT_NEAR(shares, 1.0, 1e-6);
    }
}

TEST(TimeCommand, AStaticSceneReusesItsShadowMapAndAnAnimatedOneRedrawsIt) {
    const std::string teapot = scene("resources/scenes/teapot.speculum.json") + " --frames 3 --size 160x90";
    const auto still = runsPerFrame(timeJson(teapot));
    EXPECT_EQ(still.count("shadow"), 0u) << "drawn in the warm-up, reused in every timed frame";
    const QJsonObject animated = timeJson(teapot + " --animated");
    EXPECT_TRUE(animated["animated"].toBool());
    EXPECT_EQ(runsPerFrame(animated).at("shadow"), 1.0) << "the light orbits: a new map each frame";
    EXPECT_EQ(animated["cameraBuffer"].toString(), "srgb8")
        << "the marble table is a stencil mirror without Fresnel: its reflection is drawn pre-weighted";
    EXPECT_TRUE(animated["drawnIntoOutput"].toBool());
}

TEST(TimeCommand, HalfFloatTimesTheCompositePath) {
    const QJsonObject o =
        timeJson(scene("benchmarks/scenes/ball.speculum.json") + " --frames 2 --size 64x64 --half-float");
    EXPECT_EQ(o["cameraBuffer"].toString(), "half-float");
    EXPECT_FALSE(o["drawnIntoOutput"].toBool());
    EXPECT_EQ(runsPerFrame(o).at("composite"), 1.0) << "the half-float buffer is resolved into the output";
}

TEST(TimeCommand, TheTextReportNamesTheFigures) {
    const CliRun run = runSpeculum("time " + scene("benchmarks/scenes/room-1-mirror.speculum.json") +
                                   " --frames 2 --size 96x54");
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.out.find("room-1-mirror.speculum.json at 96x54, static, 2 frames"), std::string::npos)
        << run.out;
    EXPECT_NE(run.out.find("frame: median "), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("camera buffer: srgb8"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("mirror"), std::string::npos) << run.out;
}

TEST(TimeCommand, BadInputIsOneLineAndANonZeroExit) {
    const std::string ball = scene("benchmarks/scenes/ball.speculum.json");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"time " + ball + " --frames 0", "--frames: '0' is out of range (1..100000)"},
        {"time " + ball + " --frames many", "--frames: expected a whole number, got 'many'"},
        {"time " + ball + " --ssaa 2", "time: unknown option '--ssaa'"},
        {"time", "time: missing PROJECT file"},
        {"tiem " + ball, "did you mean 'time'?"},
        {"time /nonexistent/x.speculum.json", "x.speculum.json"},
    };
    for (const auto& [arguments, expected] : cases) {
        const CliRun run = runSpeculum(arguments);
        EXPECT_NE(run.status, 0) << arguments;
        EXPECT_NE(run.err.find(expected), std::string::npos) << arguments << "\n" << run.err;
        EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << "one line: " << run.err;
        EXPECT_TRUE(run.out.empty()) << run.out;
    }
}

} // namespace

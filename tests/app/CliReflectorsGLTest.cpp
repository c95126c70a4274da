// `speculum explain` on the facing-balls demo (three balls over a floor mirror, reflectorBounces 2): every
// map pass per reflector and bounce with its reason, in order, the maps' mirror passes, and the skips; a
// second identical frame reuses every map.
#include "CliRun.hpp"
#include "support/TestPaths.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace {

namespace test = speculum::test;
using test::CliRun;

std::string facingBalls() {
    return speculum::testSourcePath("resources/scenes/facing-balls.speculum.json");
}

QJsonObject explained(const std::string& arguments) {
    const CliRun run = test::runSpeculum("explain " + facingBalls() + " --size 160x90 --json " + arguments);
    EXPECT_EQ(run.status, 0) << run.err;
    return QJsonDocument::fromJson(QByteArray::fromStdString(run.out)).object();
}

TEST(CliReflectors, ExplainListsEveryMapPassPerReflectorAndBounce) {
    const QJsonObject root = explained("");
    std::vector<std::pair<std::string, int>> maps;
    for (const auto& value : root["passes"].toArray()) {
        const QJsonObject pass = value.toObject();
        if (pass["kind"].toString() != "envmap")
            continue;
        maps.emplace_back(pass["target"].toString().toStdString(), pass["bounce"].toInt());
        const std::string reason = pass["reason"].toString().toStdString();
        const int bounce = pass["bounce"].toInt();
        EXPECT_NE(reason.find("bounce " + std::to_string(bounce) + " of 2"), std::string::npos) << reason;
        EXPECT_EQ(pass["code"].toString(), bounce == 0 ? "envmap-first-map" : "envmap-bounce") << reason;
    }
    const std::vector<std::pair<std::string, int>> expected = {
        {"Left ball", 0},  {"Right ball", 0}, {"Satin ball", 0}, {"Left ball", 1}, {"Right ball", 1},
        {"Satin ball", 1}, {"Left ball", 2},  {"Right ball", 2}, {"Satin ball", 2}};
    EXPECT_EQ(maps, expected);
    // Each map's own mirror passes (the floor mirror in its faces), with the bounce they were drawn at.
    const QJsonArray envmaps = root["envmaps"].toArray();
    ASSERT_EQ(envmaps.size(), 9);
    for (qsizetype i = 0; i < envmaps.size(); ++i) {
        const QJsonObject map = envmaps[i].toObject();
        EXPECT_EQ(map["target"].toString().toStdString(), expected[static_cast<std::size_t>(i)].first);
        EXPECT_EQ(map["bounce"].toInt(), expected[static_cast<std::size_t>(i)].second);
        EXPECT_FALSE(map["passes"].toArray().isEmpty()) << "the floor mirror reflects in every map";
    }
    EXPECT_EQ(root["envmapMirrors"].toObject(), envmaps[0].toObject()) << "the first map, as before";
    // The satin ball is rough: one pre-filter, after its last bounce.
    int prefilters = 0;
    for (const auto& value : root["passes"].toArray())
        prefilters += value.toObject()["kind"].toString() == "prefilter" ? 1 : 0;
    EXPECT_EQ(prefilters, 1);
}

TEST(CliReflectors, ASecondStaticFrameReusesEveryMap) {
    const QJsonObject root = explained("--frame 2");
    for (const auto& value : root["passes"].toArray())
        EXPECT_NE(value.toObject()["kind"].toString(), "envmap");
    int unchanged = 0;
    for (const auto& value : root["skipped"].toArray())
        unchanged += value.toObject()["code"].toString() == "envmap-unchanged" ? 1 : 0;
    EXPECT_EQ(unchanged, 3) << "one skip per reflector";
}

TEST(CliReflectors, TextListsTheMapsOfEachBounce) {
    const CliRun run = test::runSpeculum("explain " + facingBalls() + " --size 160x90");
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_NE(run.out.find("Inside the environment map of Right ball (drawn by its envmap pass, bounce 2)"),
              std::string::npos)
        << run.out;
}

} // namespace
